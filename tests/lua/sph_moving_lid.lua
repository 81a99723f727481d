-- A lid of fixed SPH particles driven from Lua (s:add{fixed = true, velocity = function(t)}) drags a
-- syrup layer into Couette flow: after one L^2/nu the profile is the line 0 .. 10 mm/s within 0.3
-- mm/s; a spinning paddle takes omega and pivot; the errors name what is wrong.
local h = require "hearth"
-- a spinning paddle (omega about z in 2D, a pivot) keeps its size
local p = h.scene { dim = 2, dx = 0.004, box = { { 0, 0 }, { 0.2, 0.2 } }, solver = "sph", gravity = { 0, 0 } }
local m = h.material("newtonian", { density = 1000, bulk = 1e4, viscosity = 0.1 })
p:add { shape = h.box({ 0.06, 0.096 }, { 0.14, 0.104 }), material = m, ppc = 1, jitter = 0, fixed = true,
  omega = 2, pivot = { 0.1, 0.1 } }
p:step(20)
local ok, e = pcall(p.add, p, { shape = h.box({ 0, 0 }, { 0.02, 0.02 }), material = m, omega = 2 })
assert(not ok and e:find("fixed = true"), "omega on a free body: " .. tostring(e))
ok, e = pcall(p.add, p, { shape = h.box({ 0, 0 }, { 0.02, 0.02 }), material = m, fixed = true, velocity = "fast" })
assert(not ok and e:find("velocity"), "a bad velocity: " .. tostring(e))
local q = h.scene { dim = 2, dx = 0.01, box = { { 0, 0 }, { 0.2, 0.2 } } }
ok, e = pcall(q.add, q, { shape = h.box({ 0.05, 0.05 }, { 0.1, 0.1 }), material = h.material("elastic", { density = 1000 }),
  fixed = true, velocity = { 0.1, 0 } })
assert(not ok and e:find("collider"), "MPM refuses a moving fixed body: " .. tostring(e))
local bad = h.scene { dim = 2, dx = 0.004, box = { { 0, 0 }, { 0.2, 0.2 } }, solver = "sph" }
bad:add { shape = h.box({ 0.06, 0.096 }, { 0.14, 0.104 }), material = m, fixed = true,
  velocity = function(t) if t > 0 then error("lid jammed") end return { 0, 0 } end }
ok, e = pcall(bad.step, bad, 2)
assert(not ok and e:find("body motion function") and e:find("lid jammed"), "an error in the motion function surfaces: " .. tostring(e))

-- last, so the run that hearth run finishes with is this scene's
local s = h.scene { dim = 2, dx = 0.002, box = { { 0, 0 }, { 0.024, 0.032 } }, solver = "sph", gravity = { 0, 0 },
  sph = { periodic_x = true } }
local syrup = h.material("newtonian", { density = 1000, bulk = 1e3, viscosity = 10 })
s:add { shape = h.box({ 0, 0 }, { 0.024, 0.006 }), material = syrup, ppc = 1, jitter = 0, fixed = true }
s:add { shape = h.box({ 0, 0.026 }, { 0.024, 0.032 }), material = syrup, ppc = 1, jitter = 0, fixed = true,
  velocity = function(t) return { math.min(1, t / 0.01) * 0.01, 0 } end }
s:add { shape = h.box({ 0, 0.006 }, { 0.024, 0.026 }), material = syrup, ppc = 1, jitter = 0 }
s:run { until_t = 0.04 }
local u = s:line("velocity_x", { 0.012, 0.007 }, { 0.012, 0.025 }, 5)
for i, ui in ipairs(u) do
  local y = 0.001 + (i - 1) * 0.0045 -- height above the floor's surface
  local want = 0.01 * y / 0.02
  assert(math.abs(ui - want) < 3e-4, ("moving lid: u = %.5f m/s at y = %.4f m, want %.5f"):format(ui, y, want))
end
print(("moving lid: u (mm/s) %.2f %.2f %.2f %.2f %.2f"):format(u[1] * 1e3, u[2] * 1e3, u[3] * 1e3, u[4] * 1e3, u[5] * 1e3))

print("sph moving lid ok")

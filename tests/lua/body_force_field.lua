-- s:body_force: a column on a slip floor (nu = 0: uniaxial stress) under no
-- gravity but a body force that grows linearly with height, f_y = -a (y - floor) / H.
-- Static stress: sigma_yy(y) = -rho a / (2 H) (L^2 - (y - floor)^2), L the column's
-- height (a uniform force a would give -rho a (L - (y - floor)): 4/3 of it at
-- mid-height). Two resolutions; then a bad return value and a Lua error are named.
local h = require "hearth"
local rho, a, E, H, W, floor = 1000, 10, 1e6, 0.3, 0.4, 0.1
local function column(n)
  local dx = 1 / n
  local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 1, 1 } }, gravity = { 0, 0 }, damping = 300 }
  local m = h.material("elastic", { E = E, nu = 0, density = rho })
  s:collider { shape = h.plane({ 0, floor }, { 0, 1 }), mode = "slip" }
  s:add { shape = h.box({ 0.5 - W / 2, floor }, { 0.5 + W / 2, floor + H }), material = m, ppc = 4, jitter = 0 }
  local calls = 0
  s:body_force(function(x, y, z, t)
    calls = calls + 1
    return 0, -a * (y - floor) / H
  end)
  local st = s:run { until_t = 0.5, until_rest = 1e-5 }
  local r = s:particles { fields = { "x" } }
  local top = -math.huge
  for i = 1, r.n do top = math.max(top, r.x[3 * i - 1]) end
  local L = top + 0.25 * dx - floor -- particles sit a quarter cell (ppc 4) inside the surface
  local err = {}
  for k, f in ipairs { 0.25, 0.5, 0.75 } do
    local y = floor + f * L
    local exact = -rho * a / (2 * H) * (L * L - (y - floor) ^ 2)
    err[k] = s:probe("stress_yy", { 0.5, y }) / exact - 1
  end
  print(("dx 1/%d: at rest %s at t %.4g s (%d steps, %.0f calls a step); sigma_yy / closed form - 1 at 0.25 0.5 0.75 "
    .. "of the height: %+.4f %+.4f %+.4f"):format(n, tostring(st.at_rest), st.t, st.step, calls / st.step, err[1],
    err[2], err[3]))
  assert(st.at_rest, "the damped column did not come to rest")
  return err
end
local e32, e64 = column(32), column(64)
for k = 1, 3 do
  assert(math.abs(e32[k]) < 0.01 and math.abs(e64[k]) < 0.005, "stress off the closed form of the varying force")
end
-- bad values and errors are named, with where and when
local function one()
  local s = h.scene { dim = 2, dx = 1 / 16, gravity = { 0, 0 } }
  s:add { shape = h.box({ 0.4, 0.4 }, { 0.6, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
  return s
end
local s = one()
s:body_force(function(x, y, z, t) return "up" end)
local ok, e = pcall(s.step, s, 1)
assert(not ok and e:find("s:body_force function at (", 1, true) and e:find("returned string", 1, true), e)
s = one()
s:body_force(function(x, y, z, t) error("no force here") end)
ok, e = pcall(s.step, s, 1)
assert(not ok and e:find("s:body_force function:", 1, true) and e:find("no force here", 1, true), e)
-- nil removes it
s = one()
s:body_force(function() return 5, 0 end)
s:body_force(nil)
s:step(5)
local r = s:particles { fields = { "v" } }
assert(r.v[1] == 0, "s:body_force(nil) should remove the force")
ok, e = pcall(s.body_force, s, 3)
assert(not ok and e:find("expected a function", 1, true), e)
print("body_force_field ok")

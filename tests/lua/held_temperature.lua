-- fixed_temperature on colliders and bodies: what it holds, what it refuses, and a checkpoint keeps it
local h = require "hearth"
local function fails(fn, want)
  local ok, e = pcall(fn)
  assert(not ok, "expected an error containing: " .. want)
  assert(tostring(e):find(want, 1, true), ("'%s' not in: %s"):format(want, tostring(e)))
end
local s = h.scene { dim = 2, dx = 1 / 50, gravity = { 0, 0 } }
local m = h.material("elastic", { E = 1e4, density = 1000, conductivity = 1, specific_heat = 1 })
local floor = h.plane({ 0, 0.1 }, { 0, 1 })
fails(function() s:collider { shape = floor, fixed_temperature = true } end, "needs temperature")
fails(function() s:collider { shape = floor, temperature = 100, fixed_temperature = true, beta = 50 } end,
  "a finite beta contradicts it")
fails(function() s:add { shape = h.box({ 0.2, 0.1 }, { 0.4, 0.2 }), material = m, fixed_temperature = true } end,
  "needs temperature")
s:collider { shape = floor, temperature = 100, beta = math.huge } -- the same as fixed_temperature = true
s:add { shape = h.box({ 0.2, 0.1 }, { 0.4, 0.2 }), material = m, temperature = 20, fixed = true, jitter = 0 }
s:add { shape = h.box({ 0.6, 0.3 }, { 0.7, 0.4 }), material = m, temperature = 150, fixed = true, fixed_temperature = true }
s:run { until_t = 0.05 }
local held = s:particles { fields = { "temperature" } }
s:save("held.ck")
local r = h.load("held.ck")
r:run { until_t = 0.1 }
s:run { until_t = 0.1 }
assert(r:hash() == s:hash(), "a restored scene holds the same temperatures")
local bottom = s:probe("temperature", { 0.3, 0.105 })
assert(bottom > 50 and bottom <= 100, "the slab's bottom warms toward the held 100 degC: " .. bottom)
local hb = s:probe("temperature", { 0.65, 0.35 })
assert(math.abs(hb - 150) < 1e-9, "the held block keeps 150 degC: " .. hb)
assert(held.n > 0)
local sph = h.scene { dim = 2, dx = 1 / 50, solver = "sph" }
local ms = h.material("elastic", { E = 1e4, density = 1000, conductivity = 1, specific_heat = 1 })
fails(function() sph:collider { shape = floor, temperature = 100, fixed_temperature = true } end, "needs the MPM solver")
fails(function()
  sph:add { shape = h.box({ 0.2, 0.1 }, { 0.4, 0.2 }), material = ms, temperature = 150, fixed_temperature = true }
end, "held on the MPM grid")
print("held_temperature ok")

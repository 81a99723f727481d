-- wet colliders (held or Robin) and a humid oven from Lua: the keys reach the
-- core, water moves the way they say, and bad values are refused with units
local h = require "hearth"
local function fails(fn, want)
  local ok, e = pcall(fn)
  assert(not ok, "expected an error containing: " .. want)
  assert(tostring(e):find(want, 1, true), ("'%s' not in: %s"):format(want, tostring(e)))
end
local plane = h.plane({ 0, 0.2 }, { 0, 1 })
fails(function() h.scene { oven = { saturation = 1.5 } } end, "oven.saturation = 1.5; valid range [0, 1]")
local s0 = h.scene { dim = 2 }
fails(function() s0:collider { shape = plane, beta_water = 0.1 } end, "beta_water needs saturation")
fails(function() s0:collider { shape = plane, saturation = 0.5, beta_water = -1 } end, "beta_water = -1; valid range")

-- one box each: held at 0.9, exchanging toward 0.9, drying toward humid air at 0.3
local function box(opts, collider, evap)
  local s = h.scene(opts)
  local m = h.material("elastic", { E = 1e5, density = 1000, water_diffusivity = 1e-6, evaporation = evap or 0 })
  if collider then collider.shape = plane; s:collider(collider) end
  s:add { shape = h.box({ 0.3, 0.2 }, { 0.7, 0.4 }), material = m, saturation = 0.6, fixed = true }
  local w0 = s:stats().water_mass
  s:run { until_t = 20 }
  return s:stats().water_mass - w0, s
end
local held = box({ dim = 2, dx = 1 / 64, gravity = { 0, 0 } }, { saturation = 0.9 })
local robin = box({ dim = 2, dx = 1 / 64, gravity = { 0, 0 } }, { saturation = 0.9, beta_water = 0.05 })
local humid, s = box({ dim = 2, dx = 1 / 64, gravity = { 0, 0 }, oven = { saturation = 0.3 } }, nil, 1e-3)
local dry = box({ dim = 2, dx = 1 / 64, gravity = { 0, 0 } }, nil, 1e-3)
print(("taken up: held %.4g, Robin %.4g kg/m; lost: humid air %.4g, dry air %.4g kg/m"):format(held, robin, -humid, -dry))
assert(held > robin and robin > 0, "a held face passes more water than a weak exchange, and both pass some")
assert(humid < 0 and dry < humid, "humid air dries the box more slowly than dry air")
-- evaporation is linear in s - s_amb: (0.6 - 0.3) / 0.6 of the dry loss, to the profile's curvature
assert(math.abs(humid / dry - 0.5) < 0.05, ("humid / dry loss %.4f, expected about 0.5"):format(humid / dry))
assert(s:settings()["oven.saturation"] == 0.3, "s:settings() reports oven.saturation")
print("wet_boundaries ok")

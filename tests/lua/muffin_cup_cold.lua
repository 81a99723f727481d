-- h.recipes.muffin_cup hands a preset oven's cold tin to its cup (pan_start_temperature and pan_warm_time become the
-- collider's start_temperature and warm_time, colliders.h): the batter on the floor of a cup that warms from 20 degC
-- is cooler, early on, than in a cup at the oven's temperature from the start, and an oven without the two numbers
-- (the paper presets') makes the cup of before, the same bits. Bars set before the first run (as warming_tray.lua's).
local h = require "hearth"
local function scene(oven)
  local s = h.scene { dim = 2, dx = 1 / 200, gravity = { 0, 0 }, box = { { 0, 0 }, { 0.08, 0.06 } } }
  local m = h.material("elastic", { E = 1e4, density = 1000, conductivity = 1, specific_heat = 1 })
  h.recipes.muffin_cup(s, { dim = 2, x = 0.04, base = 0.01, radius = 0.02, height = 0.03, wall = 0.004, fill = 0.02,
    material = m, oven = oven, mode = "slip", ppc = 4 })
  return s
end
local hot = { pan_temperature = 120, pan_beta = 50, dough_temperature = 20 }
local cold = { pan_temperature = 120, pan_beta = 50, dough_temperature = 20, pan_start_temperature = 20,
  pan_warm_time = 0.05 }
local a, b = scene(cold), scene(hot)
a:run { until_t = 0.1 }
b:run { until_t = 0.1 }
local tc, th = a:probe("temperature", { 0.04, 0.0125 }), b:probe("temperature", { 0.04, 0.0125 })
print(("batter on the cup's floor at 0.1 s: tin warming from 20 degC %.3f, tin at 120 degC from the start %.3f")
  :format(tc, th))
assert(tc > 20 and tc < th - 1, "the cold tin heats the batter later")
-- the paper presets' ovens carry no cold start: the cup is a plain heated collider, as before
local plain = h.scene { dim = 2, dx = 1 / 200, gravity = { 0, 0 }, box = { { 0, 0 }, { 0.08, 0.06 } } }
plain:collider { shape = h.cup({ 0.04, 0.01 }, { 0, 1 }, 0.02, 0.03, 0.004, 0.004), mode = "slip", friction = 0.3,
  temperature = 120, beta = 50 }
plain:add { shape = h.box({ 0.02, 0.01 }, { 0.06, 0.03 }), material = h.material("elastic", { E = 1e4, density = 1000,
  conductivity = 1, specific_heat = 1 }), temperature = 20, ppc = 4 }
plain:run { until_t = 0.1 }
assert(plain:hash() == b:hash(), "a cup without pan_start_temperature is the hot cup of before")
print("muffin_cup_cold ok")

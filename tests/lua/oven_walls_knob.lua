-- tests/lua_test.sh oven_walls_set_knobs: a scene whose oven has no walls; --set oven.wall_temperature and
-- oven.emissivity give it some. Prints the oven's settings.
local h = require "hearth"
local s = h.scene { oven = { temperature = 180, beta = 30 } }
local g = s:settings()
print(("oven %g %g walls %s %g scale %g"):format(g["oven.temperature"], g["oven.beta"],
  g["oven.wall_temperature"] and ("%g"):format(g["oven.wall_temperature"]) or "nil", g["oven.emissivity"], g["oven.radiation_scale"]))

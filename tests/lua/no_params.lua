-- lua_set_overrides: a scene that declares no parameters.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
s:add { shape = h.box({ 0.4, 0.4 }, { 0.6, 0.5 }),
  material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
s:run { until_t = 0.001 }
print("ran")

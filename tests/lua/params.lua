-- lua_set_overrides: scene parameters and --set.
local h = require "hearth"
local P = h.params { height = 0.3, label = "a", sizes = { 1, 2 } }
print(("height=%s type=%s"):format(tostring(P.height), math.type(P.height) or type(P.height)))
print("label=" .. P.label)
print(("sizes=%s n=%d"):format(table.concat(P.sizes, "/"), #P.sizes))
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
s:add { shape = h.box({ 0.4, P.height }, { 0.6, P.height + 0.1 }),
  material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
print(("filled_at_0.35=%s"):format(tostring(s:probe("density", { 0.5, 0.35 }) > 0)))
s:run { until_t = 0.001 }

-- s:run{csv = ...}'s columns say their units (#18, helper userfix7; tests/lua_test.sh run_csv_columns_say_units):
-- a small warm block falling for two frames, in 2D or 3D, probed for a field with a unit and a dimensionless one.
local h = require "hearth"
local P = h.params { dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" } }
local d3 = P.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
local s = h.scene { dim = P.dim, dx = 0.05, box = { v(0, 0, 0), v(1, 1, 0.5) } }
s:add { shape = h.box(v(0.3, 0.3, 0.1), v(0.6, 0.6, 0.4)), temperature = 40,
  material = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000 }) }
local at = v(0.45, 0.45, 0.25)
s:run { until_t = 0.01, every = 0.005, csv = "series.csv",
  probes = { { "speed", at }, { "temperature", at }, { "J", at } } }

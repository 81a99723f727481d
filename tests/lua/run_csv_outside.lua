-- run_csv_probe_outside_empty (#18, helper userview4): s:run{csv = ...}'s probe at a point no material fills leaves
-- its cell empty ("not measured"), as the shipped scenes' CSVs do; one inside the block reads a number
local h = require "hearth"
local s = h.scene { dim = 2, dx = 0.05, box = { { 0, 0 }, { 1, 1 } } }
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), temperature = 40,
  material = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000 }) }
s:run { until_t = 0.01, every = 0.005, csv = "series.csv",
  probes = { { "temperature", { 0.45, 0.45 } }, { "temperature", { 0.9, 0.9 } } } }

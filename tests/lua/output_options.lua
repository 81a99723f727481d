-- output_options_did_you_mean: one misspelt output option per run (--set which=NAME).
local h = require "hearth"
local P = h.params { which = "none" }
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
s:add { shape = h.box({ 0.4, 0.4 }, { 0.6, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
local w = P.which
if w == "png" then
  s:png("speed", "a.png", { widht = 200 })
elseif w == "run_png" then
  s:run { until_t = 0.001, png = { feild = "speed" } }
elseif w == "probes" then
  s:run { until_t = 0.001, csv = "a.csv", probes = { { "speed", { 0.5, 0.5 }, pont = { 0.1, 0.1 } } } }
elseif w == "csv" then
  s:run { until_t = 0.001, csv = { path = "a.csv" } }
elseif w == "run" then
  s:run { until_t = 0.001, evry = 0.0005 }
end
print("done " .. w)

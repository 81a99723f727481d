-- params_number_*: a scene's numeric parameters declared with their range (h.number) and --set.
local h = require "hearth"
local P = h.params { dx = h.number { 0.005, above = 0, max = 0.05, unit = "m", what = "the grid spacing" },
  cups = h.number { 3, min = 1, max = 12, integer = true, what = "muffin cups in a row" },
  vent = h.number { 5, min = 0, unit = "m/s", what = "the CO2 vent velocity", also = { [-1] = "the preset's" } },
  height = 0.3,
  ovens = h.number { { 190, 150 }, list = true, min = -273.15, max = 5000, unit = "degC", what = "the ovens" } }
print(("dx=%g cups=%g vent=%g height=%g ovens=%s"):format(P.dx, P.cups, P.vent, P.height, table.concat(P.ovens, ",")))

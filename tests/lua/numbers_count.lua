-- params_number_list_count_refused, set_long_value_cut: a list with at most a count of numbers (h.number's max_count).
local h = require "hearth"
local P = h.params { sizes = h.number { { 1, 2 }, list = true, max_count = 3, min = 0, max = 1e6, unit = "mm",
  what = "the cookies' sizes" }, dx = h.number { 0.005, above = 0, unit = "m", what = "the grid spacing" } }
print(("sizes=%s"):format(table.concat(P.sizes, ",")))

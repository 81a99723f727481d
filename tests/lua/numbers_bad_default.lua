-- params_number_bad_default_refused: the scene author's default lies outside its own range.
local h = require "hearth"
local P = h.params { cups = h.number { 0, min = 1, max = 12, integer = true, what = "muffin cups in a row" } }
print("ran with cups=" .. P.cups)

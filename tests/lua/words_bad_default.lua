-- params_word_bad_default_refused: a default that is not one of its words is the scene author's mistake.
local h = require "hearth"
local P = h.params { tray = h.choice { "stiky", separate = "slides out with friction", sticky = "held where it touched" } }
print("ran with tray=" .. P.tray)

-- params_word_*: a scene's word-valued parameters (h.choice) and --set.
local h = require "hearth"
local P = h.params { height = 0.3,
  tray = h.choice { "separate", separate = "slides out with friction", sticky = "held where it touched" },
  only = h.choice { "", [""] = "both", raw = "the raw one alone", roasted = "the roasted one alone" },
  wall = h.choice("slip", h.contact_words) }
print(("tray=%s only=[%s] wall=%s"):format(P.tray, P.only, P.wall))

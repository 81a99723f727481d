-- params_word_passed_through_refused: a wrapper that runs words.lua (--set scene=...) with its own parameters,
-- a superset of the scene's, and a tray default of its own that words.lua does not take.
local h = require "hearth"
local P = h.params { scene = "words.lua", height = 0.3, tray = "glue", only = "", wall = "slip" }
h.pass_params(P)
dofile(P.scene)

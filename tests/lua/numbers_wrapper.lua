-- params_number_passed_through_refused: a wrapper that runs numbers.lua (--set scene=...) with its own
-- parameters, plain numbers, a superset of the scene's; its cups default (0) is one numbers.lua does not take.
local h = require "hearth"
local P = h.params { scene = "numbers.lua", dx = 0.01, cups = 0, vent = 5, height = 0.3 }
h.pass_params(P)
dofile(P.scene)

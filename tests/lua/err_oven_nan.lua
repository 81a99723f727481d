local h = require "hearth"
local s = h.scene { dim = 2, dx = 0.01, box = { { 0, 0 }, { 0.1, 0.1 } } }
s:oven(0 / 0, 30)

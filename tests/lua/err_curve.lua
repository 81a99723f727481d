local h = require "hearth"
local c = h.curve { { 100, 1e4 }, { 50, 2e4 } }

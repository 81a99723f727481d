local h = require "hearth"
local m = h.material("elastic", { Ee = 1 })

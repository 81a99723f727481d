local h = require "hearth"
local m = h.material("newtonian", { density = 1e9, bulk = 1e5, viscosity = 1 })

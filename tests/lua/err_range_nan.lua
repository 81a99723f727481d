local h = require "hearth"
local m = h.material("elastic", { E = 1e4, nu = 0 / 0, density = 1000 })

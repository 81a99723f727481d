local h = require "hearth"
local m = h.material("no_such_plugin_xyz", { density = 1000 })

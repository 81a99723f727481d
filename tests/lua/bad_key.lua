-- lua_error_unknown_key: a misspelt h.scene field (line 3).
local h = require "hearth"
local s = h.scene { dxx = 0.01 }

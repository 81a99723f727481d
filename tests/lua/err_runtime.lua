local h = require "hearth"
local function helper(t)
  return t.missing_function(1)
end
helper({})

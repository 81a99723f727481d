local h = require "hearth"
local k = -1 -- as a scene's own check of a --set value
if k <= 0 then error(("k = %g: must be > 0"):format(k)) end

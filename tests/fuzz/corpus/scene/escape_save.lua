local h = require "hearth"
local s = h.scene{dim = 2, box = {{0, 0}, {0.1, 0.1}}, dx = 0.01, seed = 1}
s:save("../escape_save.ck")

local h = require "hearth"
h.scene{dim = 2, box = {{0, 0}, {0/0, 1}}, dx = -1}

local h = require "hearth"
local s = h.scene{dim = 2, box = {{0, 0}, {0.1, 0.2}}, dx = 0.01, seed = 1}
local m = h.material("elastic", {E = 5e4, nu = 0.3, density = 4061})
s:add{material = m, shape = h.box({0.03, 0.03}, {0.07, 6.16}), ppc = 2}
s:collider{shape = h.plane({0,02}, {0, 1}), mode = "separate", friction = 0.3}
s:step(5)
s:run{until_t = 0.004}

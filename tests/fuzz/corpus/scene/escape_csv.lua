local h = require "hearth"
local s = h.scene{dim = 2, box = {{0, 0}, {0.1, 0.1}}, dx = 0.01, seed = 1}
local m = h.material("elastic", {E = 1e4, nu = 0.3, density = 1000})
s:add{material = m, shape = h.box({0.03, 0.03}, {0.06, 0.06}), ppc = 2}
s:run{until_t = 0.001, csv = "../escape_csv.csv"}

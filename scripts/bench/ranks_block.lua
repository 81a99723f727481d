-- ranks_block.lua: the 3D elastic block of tests/mpi/elastic_block.lua at a
-- chosen resolution and width, for scripts/bench/ranks_instructions.sh. width scales the
-- block along x (weak scaling: width = ranks keeps particles per rank fixed).
local h = require "hearth"
local P = h.params { cells = 32, width = 1, steps = 50 }
local L = 0.1 * P.width
local s = h.scene { dim = 3, dx = 1 / P.cells, box = { { 0, 0, 0 }, { 0.2 + 2 * L + 0.2, 1, 0.5 } }, wall = "slip" }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.2, 0.15, 0.15 }, { 0.2 + 2 * L, 0.35, 0.35 }), material = jelly, ppc = 4, velocity = { 0.5, -1, 0.2 } }
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }
s:step(P.steps)
print(("particles %d steps %d"):format(s:stats().particles, s:stats().step))

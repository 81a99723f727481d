-- mpi_collider_matches_one_rank: a plate moving under a Lua velocity function
-- presses a soft block on a sticky floor (scripts/scenes/press.lua, coarser),
-- and a grip holds the block's left end: moving, sticky (its mirrors in P2G,
-- its held nodes) and grip colliders, 150 steps; state.csv as elastic_block.lua's.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 1, 0.6 } } }
local dough = h.material("elastic", { E = 2e4, nu = 0.35, density = 1100 })
s:add { shape = h.box({ 0.3, 0.05 }, { 0.7, 0.2 }), material = dough, ppc = 4 }
s:collider { shape = h.plane({ 0, 0.05 }, { 0, 1 }), mode = "sticky" }
s:collider { shape = h.box({ 0.25, 0.04 }, { 0.34, 0.21 }), mode = "grip" }
s:collider { shape = h.box({ 0.4, 0.22 }, { 0.8, 0.26 }), mode = "sticky",
  velocity = function(t) return t < 0.1 and { 0, -0.4 } or { 0.1, 0 } end }
s:step(150)
local r = s:particles { fields = { "id", "x", "v", "J" } }
local lines = {}
for i = 1, r.n do
  lines[#lines + 1] = ("%d,%.17g,%.17g,%.17g,%.17g,%.17g"):format(r.id[i], r.x[3 * i - 2], r.x[3 * i - 1], r.v[3 * i - 2],
    r.v[3 * i - 1], r.J[i])
end
h.write("state.csv", table.concat(lines, "\n") .. "\n")
s:png("von_mises", "press.png")
print(("steps %d particles %d t %.6g hash %s"):format(s:stats().step, s:stats().particles, s:stats().t, s:hash()))

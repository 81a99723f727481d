-- mpi_rebalance_matches_one_rank: a bar resting on the floor at the left of a
-- box 2 m long and a heavier block thrown to the right over it, 250 steps:
-- the particle count per block layer shifts, so the slab cuts move at each
-- rebalance (every 50 steps), some by more than one slab. Every particle's id,
-- x, v and J to state.csv for tests/mpi_test.sh.
local h = require "hearth"
local P = h.params { steps = 250 }
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 2, 0.5 } }, wall = "slip", cfl = 0.9 }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.1, 0.1 }, { 0.5, 0.15 }), material = jelly, ppc = 4 }
s:add { shape = h.box({ 0.1, 0.25 }, { 0.4, 0.45 }), material = jelly, ppc = 4, velocity = { 6, 0 } }
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate" }
s:step(P.steps)
local r = s:particles { fields = { "id", "x", "v", "J" } }
local lines = {}
for i = 1, r.n do
  lines[#lines + 1] = ("%d,%.17g,%.17g,%.17g,%.17g,%.17g"):format(r.id[i], r.x[3 * i - 2], r.x[3 * i - 1], r.v[3 * i - 2],
    r.v[3 * i - 1], r.J[i])
end
h.write("state.csv", table.concat(lines, "\n") .. "\n")
local st = s:stats()
print(("steps %d particles %d t %.6g kinetic %.17g hash %s"):format(st.step, st.particles, st.t, st.kinetic, s:hash()))

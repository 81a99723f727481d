-- mpi_wall_column_matches_one_rank: a jelly column standing against the
-- box's far wall along the slab axis (x = 2 m, end node 128 at dx = 1/64,
-- alone in block layer 32), warming in an oven. 2 of its 5 cells lie in
-- block layer 30, so at 2 ranks the cut falls at layer 31: rank 0 holds the
-- column's first two cells and, as its upper halo, layer 31, but not the end
-- node, which the surface search's domain-wall test (boundary.c) reads for
-- the cells within three nodes of the wall (issue #21's second field halo
-- gap). heat = "explicit" or "implicit"; 60 steps; state.csv as
-- heat_traffic.lua's.
local h = require "hearth"
local P = h.params { steps = 60, heat = "explicit" }
local dx = 1 / 64
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 2, 0.5 } }, wall = "slip", oven = { temperature = 200, beta = 40 },
  heat = P.heat }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000, specific_heat = 3000, conductivity = 5 })
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }
s:add { shape = h.box({ 122 * dx, 0.1 }, { 127 * dx, 0.4 }), material = jelly, ppc = 4, temperature = 20 }
s:step(P.steps)
local r = s:particles { fields = { "id", "x", "v", "temperature" } }
local lines = {}
for i = 1, r.n do
  lines[#lines + 1] = ("%d,%.17g,%.17g,%.17g,%.17g,%.17g"):format(r.id[i], r.x[3 * i - 2], r.x[3 * i - 1], r.v[3 * i - 2], r.v[3 * i - 1],
    r.temperature[i])
end
h.write("state.csv", table.concat(lines, "\n") .. "\n")
local st = s:stats()
print(("steps %d particles %d kinetic %.17g heat %.17g cg %d"):format(st.step, st.particles, st.kinetic, st.heat_energy,
  st.cg_iterations))

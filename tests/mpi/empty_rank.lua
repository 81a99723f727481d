-- mpi_empty_rank_* and mpi_rank_empties_mid_run_*: a short jelly block at the
-- left end of a box 2 m long (block layers of 4 cells, 0.0625 m; the block
-- spans layers 1-3). At 4 ranks every slab keeps at least one layer, so the
-- cuts leave at least one rank (the right end's) with no particle for the
-- whole run: issue #21's empty rank. vx = 0: the block drops onto the floor
-- and rests there; vx > 0: thrown along the box, its particles leave the
-- left ranks' slabs between the rebalances (every 50 steps), so a rank
-- empties mid-run and another fills. heat = "none", "explicit" or
-- "implicit" (an oven). Every particle's id, x, v, J and temperature to
-- state.csv for tests/mpi_test.sh.
local h = require "hearth"
local P = h.params { steps = 100, heat = "none", vx = 0 }
local def = { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 2, 0.5 } }, wall = "slip", cfl = 0.9 }
if P.heat ~= "none" then def.oven, def.heat = { temperature = 200, beta = 40 }, P.heat end
local s = h.scene(def)
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000, specific_heat = 3000, conductivity = 5 })
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate" }
s:add { shape = h.box({ 0.08, 0.12 }, { 0.22, 0.3 }), material = jelly, ppc = 4, velocity = { P.vx, -0.5 },
  temperature = P.heat ~= "none" and 20 or nil }
s:step(P.steps)
local r = s:particles { fields = P.heat ~= "none" and { "id", "x", "v", "J", "temperature" } or { "id", "x", "v", "J" } }
local lines = {}
for i = 1, r.n do
  lines[#lines + 1] = ("%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g"):format(r.id[i], r.x[3 * i - 2], r.x[3 * i - 1], r.v[3 * i - 2],
    r.v[3 * i - 1], r.J[i], r.temperature and r.temperature[i] or 0)
end
h.write("state.csv", table.concat(lines, "\n") .. "\n")
local st = s:stats()
print(("steps %d particles %d t %.6g kinetic %.17g heat %.17g hash %s"):format(st.step, st.particles, st.t, st.kinetic,
  st.heat_energy or 0, s:hash()))

-- mpi_heated_plate_across_slabs_matches_one_rank: a hot plate standing across
-- the slab axis (x, the box's long axis) between two jelly blocks of equal
-- size, so the ranks' cut falls at x = 1.0 (block layer 16 at dx = 1/64, 4
-- nodes a layer), three cells below the plate's right face (x = 1 + 3 dx). The
-- right block is seeded 3 cells into the plate: its first particles belong
-- to the rank below the cut, and their contact points (their feet on the
-- face, thermal.c's find_boundary) have B-spline stencils reaching node 68,
-- the second block layer past that rank's slab (issue #21's field halo gap).
-- heat = "explicit" or "implicit"; 60 steps; state.csv as heat_traffic.lua's. draw = 1: the plate goes in at
-- 20 degC and the blocks draw their heat from it (heat_capacity, area: colliders.h), each rank's contact points'
-- heat summed over the ranks (thermal.c's sheet_ledger), its temperature printed
-- (mpi_drawing_plate_across_slabs_matches_one_rank).
-- Before the contact points moved ranks the temperatures differed from one
-- process by 5.7e-7 at 2 and 4 ranks.
local h = require "hearth"
local P = h.params { steps = 60, heat = "explicit", draw = 0 }
local dx = 1 / 64
local face = 1.0 + 3 * dx
-- (with draw = 1 the fields step every step: their automatic cycle, a tenth of the heat's 37 s limit, would not
-- come in 60 steps, and the sheet draws only in a field step)
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 2, 0.5 } }, wall = "slip", heat = P.heat,
  field_steps = P.draw == 1 and 1 or nil }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000, specific_heat = 3000, conductivity = 5 })
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }
local plate = P.draw == 1 and { start_temperature = 20, warm_time = 0.02, heat_capacity = 2e3, area = 1 } or {}
plate.shape, plate.mode, plate.temperature = h.box({ 0.96, 0 }, { face, 0.5 }), "separate", 150
local pid = s:collider(plate)
s:add { shape = h.box({ 0.41, 0.1 }, { 0.96, 0.3 }), material = jelly, ppc = 4, temperature = 20 }
s:add { shape = h.box({ 1.0, 0.1 }, { 1.55, 0.3 }), material = jelly, ppc = 4, temperature = 20 }
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
if P.draw == 1 then
  local c = s:collider_heat(pid)
  print(("plate %.17g degC drawn %.17g oven_in %.17g"):format(c.temperature, c.drawn, c.oven_in))
end

-- mpi_heat_halo_traffic_bounded: tests/mpi/traffic.lua's elastic bar of
-- length len (m) along a box 2 m long (slabs along x), here warming in an
-- oven (heat with the air surface, explicit or implicit), 100 steps.
-- tests/mpi_test.sh runs it at two lengths (twice the particles) and reads
-- each rank's bytes.
local h = require "hearth"
local P = h.params { len = 0.6, steps = 100, heat = "explicit", state = 0 }
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 2, 0.5 } }, wall = "slip", oven = { temperature = 200, beta = 40 },
  heat = P.heat }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000, specific_heat = 3000, conductivity = 5 })
s:add { shape = h.box({ 0.2, 0.15 }, { 0.2 + P.len, 0.35 }), material = jelly, ppc = 4, velocity = { 0.5, -1 }, temperature = 20 }
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }
s:step(P.steps)
if P.state == 1 then -- every particle's id, x, v and temperature to state.csv (17 digits), for tests/mpi_compare.py
  local r = s:particles { fields = { "id", "x", "v", "temperature" } }
  local lines = {}
  for i = 1, r.n do
    lines[#lines + 1] = ("%d,%.17g,%.17g,%.17g,%.17g,%.17g"):format(r.id[i], r.x[3 * i - 2], r.x[3 * i - 1], r.v[3 * i - 2], r.v[3 * i - 1],
      r.temperature[i])
  end
  h.write("state.csv", table.concat(lines, "\n") .. "\n")
end
local st = s:stats()
print(("steps %d particles %d kinetic %.17g heat %.17g cg %d"):format(st.step, st.particles, st.kinetic, st.heat_energy,
  st.cg_iterations))

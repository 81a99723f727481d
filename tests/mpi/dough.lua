-- mpi_dough_matches_one_rank: a bread dough with every field live (heat with
-- the oven's surface, water and evaporation with latent heat, CO2), sagging
-- on a tray, 100 steps; every particle's id, x, v, temperature, saturation
-- and J to state.csv (17 digits) for tests/mpi_test.sh. The dough is seeded on the tray (its lowest row a
-- half-spacing over it, glued from the first step); it started 2 mm higher (0.75 dx in 2D) while a sticky
-- tray grabbed what came within a cell and a half, and fell once the tray held only what touched it (helper glue,
-- docs/validation.md "A sticky face holds what touched it"). dim = 3: the same
-- dough 0.02 m deep on a tray 0.04 m deep (mpi_dough_3d_matches_one_rank).
-- tray, tray_beta: the tray's temperature (degC) and Robin coefficient (W/(m2 K); 0: the collider's
-- default); a hot tray boils and dries the bottom row (mpi_dough_boils_matches_one_rank).
local h = require "hearth"
local P = h.params { steps = 100, heat = "explicit", dim = 2, tray = 180, tray_beta = 0, ambient = 0 }
local three = P.dim == 3
local s = h.scene { dim = P.dim, dx = three and 0.006 or 0.004,
  box = three and { { 0, 0, 0 }, { 0.12, 0.08, 0.04 } } or { { 0, 0 }, { 0.12, 0.08 } },
  oven = { temperature = 200, beta = 40 }, latent_heat = true, heat = P.heat, dt_max = 2e-3 }
local d = h.library.dough.bread
d.specific_heat, d.conductivity = 2800, 0.5
d.dry_conductivity, d.dry_specific_heat = 0, 0 -- its own real-unit conductivity and specific heat, one for wet
-- and dry, as when this was written
d.water_diffusivity, d.evaporation = 5e-8 / 373.15, 3e-5
-- its gas as when this was written (eq. 13 as printed, porosity 0.1, the paper bread's CO2), unless ambient (Pa)
-- puts the pores' gas at the atmosphere as the preset now does (gas.h, gas_tau_ambient; mpi_dough_matches_one_rank):
-- the gas's stiffness shortens the step, so a case of a fixed step count would cover less of its bake (the hot
-- tray's cases would no longer boil or dry), and the 450 degC tray heats the bottom row past 70 degC in a few steps
if P.ambient > 0 then
  d.ambient_pressure = P.ambient
else
  d.ambient_pressure, d.porosity = 0, 0.1
  d.gas_rate = 0.03 / 600 * 0.4 * 2.5 / 1500 * h.library.oven.bread.time_scale
end
s:add { shape = three and h.box({ 0.02, 0.0102, 0.01 }, { 0.10, 0.0482, 0.03 }) or h.box({ 0.02, 0.010 }, { 0.10, 0.048 }), material = h.material("cam_clay_dough", d), temperature = 25,
  saturation = 0.4 }
s:collider { shape = h.plane({ 0, 0.01, 0 }, { 0, 1, 0 }), mode = "sticky", temperature = P.tray,
  beta = P.tray_beta > 0 and P.tray_beta or nil }
s:step(P.steps)
local r = s:particles { fields = { "id", "x", "v", "temperature", "saturation", "J" } }
local lines = {}
for i = 1, r.n do
  lines[#lines + 1] = ("%d,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g"):format(r.id[i], r.x[3 * i - 2],
    r.x[3 * i - 1], r.x[3 * i], r.v[3 * i - 2], r.v[3 * i - 1], r.v[3 * i], r.temperature[i], r.saturation[i], r.J[i])
end
h.write("state.csv", table.concat(lines, "\n") .. "\n")
local st = s:stats()
print(("steps %d particles %d t %.6g kinetic %.17g heat %.17g hash %s"):format(st.step, st.particles, st.t, st.kinetic,
  st.heat_energy, s:hash()))
-- the sums stats() adds over the particles (over the ranks on slabs), and the last CG solve's iterations
print(("sums heat %.17g water %.17g lost %.17g gas %.17g oven %.17g cg %d"):format(st.heat_energy, st.water_mass,
  st.water_lost, st.gas, st.oven_heat_in, st.cg_iterations))

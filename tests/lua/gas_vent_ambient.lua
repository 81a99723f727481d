-- gas_vent with the atmosphere (fields/gas.c, issue #18, helper cookiecool): with ambient_pressure an open
-- surface pore vents toward the CO2 n* at which it stands at p_a, dn^g/dt = -h S_p / V_p (n^g - n*), not to
-- n^g = 0. A dry disc whose pores hold air put in at reference_temperature 40 degC and kept at 0 degC (oven and
-- body): the air alone stands at p_a 273.15 / 313.15, a gauge pressure of -12.9 kPa, and eq. 14's bell at 40
-- degC, 20 K wide, makes a trace of CO2 (e^-4 of alpha). Open pores (n^p_0 0.8 >= vent_porosity 0.7) at the
-- surface, after ~20 of their decay times 1 / k (k = h S_p / V_p ~ 400 1/s), must read a gauge pressure within
-- 1% of that vacuum of 0 (air has come in); four cells in, the pores stay at the vacuum less the trace (within 1%).
-- Vented to n^g = 0, as before the change, the surface would keep the vacuum. The disc is stiff (E 1e8 Pa), so
-- J stays ~1.
local h = require "hearth"
local dx, R, hv = 0.01, 0.08, 2
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.3, 0.3 } }, gravity = { 0, 0 },
  oven = { temperature = 0, beta = 10 }, gas_vent = hv, vent_porosity = 0.7 }
local pa, T0 = 101325, 40
local mat = h.material("cam_clay_dough", { E = 1e8, nu = 0.3, tau_y = 1e8, eta = 0, density = 500, porosity = 0.8,
  gas_rate = 1e-9, reaction_temperature = 40, reaction_width = 20, expansion = 0, ambient_pressure = pa,
  reference_temperature = T0 })
s:add { shape = h.disc({ 0.15, 0.15 }, R), material = mat, ppc = 4, jitter = 0, temperature = 0 }
local vac = pa * 273.15 / (T0 + 273.15) - pa
s:run { until_t = 0.05 }
local r = s:particles { fields = { "x", "gas_pressure", "J", "temperature" } }
-- the surface: the outermost ring of the lattice (within a quarter cell of the disc's edge); inside: four cells in
-- (boundary.c's surface share S_p reaches ~3 cells into the disc, from its smoothed fraction's level sets)
local surf, inner, worst_surf, worst_in, jdev, tdev = 0, 0, 0, 0, 0, 0
for p = 1, r.n do
  jdev = math.max(jdev, math.abs(r.J[p] - 1))
  tdev = math.max(tdev, math.abs(r.temperature[p]))
  local d = math.sqrt((r.x[3 * p - 2] - 0.15) ^ 2 + (r.x[3 * p - 1] - 0.15) ^ 2)
  if d > R - dx / 4 then
    surf = surf + 1
    worst_surf = math.max(worst_surf, math.abs(r.gas_pressure[p] / vac))
  elseif d < R - 4 * dx then
    inner = inner + 1
    worst_in = math.max(worst_in, math.abs(r.gas_pressure[p] / vac - 1))
  end
end
print(("gas_vent_ambient: %d particles, %d in the outer ring, %d four cells in, t %.3f s; the air's vacuum %.1f Pa; surface |p / vacuum| "
  .. "worst %.2e (bound 1e-2); inside |p / vacuum - 1| worst %.2e (bound 1e-2); |J - 1| <= %.1e, |T| <= %.1e degC")
  :format(r.n, surf, inner, s:_time(), vac, worst_surf, worst_in, jdev, tdev))
if surf > 0 and inner > 0 and worst_surf <= 1e-2 and worst_in <= 1e-2 then print("gas_vent_ambient ok") end

-- gas_vent (fields/gas.c): an air-boundary particle whose pores are open
-- (gas porosity >= vent_porosity) loses its CO2 at dn^g/dt = -h S_p / V_p n^g
-- while it makes it at a = alpha^g R0 (at theta = theta_r, no heat flowing:
-- the block and the oven air at theta_r). Per step, n <- (n + a dt) e^{-k dt},
-- k = h S_p / V_p, so after j steps n_j = C (1 - r^j), r = e^{-k dt}: a
-- geometric approach to C ~ a / k. From each surface particle's n^g after j,
-- 2j and 3j steps this checks, with numbers the test computes itself:
--  (1) the exponential: q = n_2j / n_j - 1 (= r^j) predicts n_3j = n_j (1 + q + q^2);
--  (2) the rate: k_p = -ln q / (j dt); sum_p k_p V_p / h is the surface the
--      loss went through, and must be the disc's perimeter 2 pi R, R from the
--      placed particles' area (boundary.c's area, which heat and evaporation
--      use, within 1%: it measures the smoothed volume fraction's level sets,
--      which round a square's corners, so a disc);
--  (3) inside, and everywhere in a disc whose pores are closed (n^p_0 0.5 <
--      0.7), n^g = a t exactly: nothing leaves.
-- The gas is kept tiny (n^g R theta ~ 1e-3 Pa against E 1e5 Pa), so the block
-- stays put (J - 1 ~ 1e-8) and S_p, V_p are constant.
local h = require "hearth"
local P = h.params { closed = false }
local dx, R, Tr, hv, dt = 0.01, 0.08, 40, 0.02, 2e-4
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.3, 0.3 } }, gravity = { 0, 0 }, dt_max = dt,
  oven = { temperature = Tr, beta = 10 }, gas_vent = hv, vent_porosity = 0.7 }
local n0, rho, alpha = P.closed and 0.5 or 0.8, 500, 1e-8
local mat = h.material("cam_clay_dough", { E = 1e5, nu = 0.3, tau_y = 1e6, eta = 0, density = rho, porosity = n0,
  gas_rate = alpha, reaction_temperature = Tr, reaction_width = 20, expansion = 0 })
s:add { shape = h.disc({ 0.15, 0.15 }, R), material = mat, ppc = 4, jitter = 0, temperature = Tr }
local area = s:volume() -- the placed particles' area (J = 1)
local a = alpha * rho
local j = 400
local samples = {}
for k = 1, 3 do
  s:step(j)
  samples[k] = s:particles { fields = { "id", "gas", "J", "boundary" } }
end
local t = { s:_time() / 3, 2 * s:_time() / 3, s:_time() }
local dts = t[1] / j
print(("gas_vent: %d particles, %d steps of %.3e s per sample (dt_max %.1e), a = %.3e mol/(m^3 s), h = %g m/s, "
  .. "n^p_0 %g"):format(samples[1].n, j, dts, dt, a, hv, n0))
local byid = {}
for k = 1, 3 do
  for p = 1, samples[k].n do
    local id = samples[k].id[p]
    byid[id] = byid[id] or {}
    byid[id][k] = { n = samples[k].gas[p], J = samples[k].J[p], b = samples[k].boundary[p] }
  end
end
local V0 = area / samples[1].n
local perim = 2 * math.pi * math.sqrt(area / math.pi)
local worst_exp, worst_inside, surf, nvent, jdev = 0, 0, 0, 0, 0
for _, r in pairs(byid) do
  for k = 1, 3 do jdev = math.max(jdev, math.abs(r[k].J - 1)) end
  local free = a * t[3] -- what the particle made
  if r[3].n < free * (1 - 1e-9) then -- it lost gas: vented
    nvent = nvent + 1
    local q = r[2].n / r[1].n - 1
    local pred = r[1].n * (1 + q + q * q)
    worst_exp = math.max(worst_exp, math.abs(pred / r[3].n - 1))
    local kp = -math.log(q) / (j * dts)
    surf = surf + kp * V0 * r[3].J / hv
  else
    for k = 1, 3 do worst_inside = math.max(worst_inside, math.abs(r[k].n / (a * t[k]) - 1)) end
  end
end
print(("gas_vent: %d particles vented; exponential n_3j against n_j (1 + q + q^2): worst %.2e (bound 1e-6); "
  .. "surface sum k_p V_p / h = %.6f m against 2 pi R = %.6f m (%.3f%%, bound 1%%); the rest n^g = a t to %.2e "
  .. "(bound 1e-9); |J - 1| <= %.1e"):format(nvent, worst_exp, surf, perim, 100 * math.abs(surf / perim - 1),
  worst_inside, jdev))
local ok
if P.closed then ok = nvent == 0 and worst_inside <= 1e-9
else ok = nvent > 0 and worst_exp <= 1e-6 and math.abs(surf / perim - 1) <= 0.01 and worst_inside <= 1e-9 end
-- a checkpoint holds gas_vent and vent_porosity (format version 5's DEF section): the restored
-- scene vents as the saved one, bit for bit
s:save("vent.ck")
local r = h.load("vent.ck")
local rs = r:settings()
s:step(50)
r:step(50)
print(("gas_vent: restored gas_vent %g, vent_porosity %g; 50 steps on: hash %s saved, %s restored"):format(rs.gas_vent,
  rs.vent_porosity, s:hash(), r:hash()))
if rs.gas_vent ~= hv or rs.vent_porosity ~= 0.7 or s:hash() ~= r:hash() then
  ok = false; print("gas_vent: the checkpoint did not carry the venting")
end
if ok then print("gas_vent ok") end

-- crumb_plateau_ladder.lua: tests/unit_latent.c's latent_heat_crumb_plateau
-- slab at three resolutions, for docs/validation.md ("Crumb plateau (#18)").
--   hearth run scripts/validation/crumb_plateau_ladder.lua --quiet [--set finest=0.0005]
-- A pinned 60 x 20 mm slab of proofed bread dough (rho 484 kg/m^3, c 2700
-- J/(kg K), kappa 0.51 W/(m K), saturation 0.218 of 1000 kg/m^3: 218 kg of
-- water a cubic metre) at 20 degC in a 200 degC oven, beta 40 W/(m^2 K), with
-- latent heat and boiling at 100 degC; no surface evaporation, next to no
-- water diffusion, so the water leaves by boiling alone. Measured: when the
-- centre, which holds 100 degC while wet, has lost half its water (checked
-- every 10 s), against a 1D enthalpy-method reference of the half thickness
-- (cells boiling as water_boil does) and the closed form of the unit test.
-- Observed order: log2 of successive errors' ratio.
local h = require "hearth"
local P = h.params { finest = 0.0005 }
local RHO, C, K, S0, H, BETA, TOV = 484, 2700, 0.51, 0.218, 0.01, 40, 200
local L = 2.26e6

local function fd(n) -- the 1D reference (front_fd in tests/unit_latent.c)
  local dx = H / n
  local dt, w0 = 0.2 * RHO * C * dx * dx / K, S0 * 1000
  local T, W, q, t = {}, {}, {}, 0
  for i = 1, n do T[i], W[i] = 20, w0 end
  while W[n] > 0.5 * w0 do
    q[1] = (TOV - T[1]) / (1 / BETA + 0.5 * dx / K)
    for i = 2, n do q[i] = K * (T[i - 1] - T[i]) / dx end
    q[n + 1] = 0
    for i = 1, n do
      T[i] = T[i] + dt * (q[i] - q[i + 1]) / (RHO * C * dx)
      if T[i] > 100 and W[i] > 0 then
        local e = RHO * C * (T[i] - 100) / L
        if e < W[i] then W[i], T[i] = W[i] - e, 100 else T[i], W[i] = T[i] - W[i] * L / (RHO * C), 0 end
      end
    end
    t = t + dt
  end
  return t
end

local function slab(dx)
  local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.1, 0.06 } }, gravity = { 0, 0 },
    oven = { temperature = TOV, beta = BETA }, latent_heat = true }
  local m = h.material("elastic", { E = 1e4, density = RHO, specific_heat = C, conductivity = K,
    water_diffusivity = 1e-15, evaporation = 0 })
  s:add { shape = h.box({ 0.02, 0.02 }, { 0.08, 0.04 }), material = m, temperature = 20, saturation = S0, fixed = true,
    jitter = 0 }
  local t, plateau_lo, plateau_hi, hot = 0, math.huge, -math.huge, false
  while true do
    t = t + 10
    s:run { until_t = t }
    local Tc, sc = s:probe("temperature", { 0.05, 0.03 }), s:probe("saturation", { 0.05, 0.03 })
    if sc < 0.5 * S0 then return t, plateau_lo, plateau_hi end
    if Tc > 99 then hot = true end
    if hot then plateau_lo, plateau_hi = math.min(plateau_lo, Tc), math.max(plateau_hi, Tc) end
    if t > 5000 then return 0 / 0, plateau_lo, plateau_hi end
  end
end

local t_ref = fd(100)
print(("1D reference (100 cells across the half thickness): the centre is half dry at %.0f s"):format(t_ref))
print("dx (mm) | centre half dry (s) | error vs 1D | order | plateau (degC)")
local prev
local dx = 0.002
while dx >= P.finest * 0.999 do
  local t, lo, hi = slab(dx)
  local err = (t - t_ref) / t_ref
  local order = prev and math.log(math.abs(prev / err)) / math.log(2) or 0 / 0
  print(("%7.2f | %19.0f | %+10.1f%% | %5.2f | %.2f .. %.2f"):format(1000 * dx, t, 100 * err, order, lo, hi))
  prev, dx = err, dx / 2
end

-- Three hot particles alone in the air (no oven, no colliders, no gravity), of
-- the s'more preset with the marshmallow's molten yield stress and the preset's
-- expansion 2 Pa/K, on explicit heat: a cheap copy of the particles that ran off
-- the cracker in marshmallow.lua and blew up (docs/validation.md, "A lone hot
-- particle"). Their thermal pressure outweighs the molten yield stress, so they
-- swell without bound (J past 1e30); conduction's quadrature volume J V_0 then
-- outran forward Euler's step and the temperature went to +-1e94 by step 266.
-- Bound checked (a maximum principle with the expansion's work): conduction
-- and FLIP create no new extremes, and the only other heat is eq. 9's
-- -theta c lambda div v, which integrates to theta J^(-c lambda / (rho c)): J
-- within double range (|ln J| <= 709.8) moves theta by at most that factor.
local h = require "hearth"
local P = h.params { steps = 400, every = 20 }
local dx = 0.002
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.16, 0.08 } }, gravity = { 0, 0 }, guard = "stop" }
local smore, D = h.library.paper.smore, require "hearth.dough"
local ty = D.paper.smore.yield
smore.tau_y = h.curve { { D.THETA[1], ty * D.TAU_SHAPE[1] }, { D.THETA[2], ty * D.TAU_SHAPE[2] },
  { D.THETA[3], ty * D.TAU_SHAPE[3] }, { 100, ty * D.TAU_SHAPE[3] }, { 150, ty * D.TAU_SHAPE[4] }, irreversible = true }
smore.expansion = 2
local mat = h.material("cam_clay_dough", smore)
local T0 = { 90, 60, 80 }
for k = 1, 3 do
  local x = 0.08 + (k - 1) * dx
  s:add { shape = h.box({ x, 0.04 }, { x + dx, 0.04 + dx }), material = mat, ppc = 1, jitter = 0, temperature = T0[k] }
end
local K = 273.15
local f = math.exp(709.8 * smore.expansion / (D.paper.smore.density * D.paper.smore.specific_heat))
local lo, hi = (60 + K) / f - K, (90 + K) * f - K
local done, tmin, tmax, jmax, msg = 0, math.huge, -math.huge, 0, nil
while done < P.steps do
  local ok, e = pcall(s.step, s, P.every)
  done = done + P.every
  local r = s:particles { fields = { "temperature", "J" } }
  for i = 1, r.n do
    local T = r.temperature[i]
    if not (T >= tmin) then tmin = T end
    if not (T <= tmax) then tmax = T end
    if r.J[i] > jmax then jmax = r.J[i] end
  end
  if not ok then msg = type(e) == "table" and e.message or tostring(e); break end
end
s:_state().ran = true
print(("lone_hot_particles: steps %d, T in [%.6g, %.6g] degC (bound [%.4g, %.4g]), J max %.4g"):format(
  s:stats().step, tmin, tmax, lo, hi, jmax))
if msg then print("lone_hot_particles: stopped: " .. msg) end
if tmin >= lo and tmax <= hi then print("lone_hot_particles ok") end

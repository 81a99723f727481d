-- One lone particle of the s'more preset with the marshmallow's molten yield
-- stress (60 Pa at 90 degC), at the preset's expansion c lambda = 2 Pa/K, with
-- no collider or gravity (issue #18). Eq. 10's thermal term added as a
-- pressure after the law's yield swelled such a particle without end (J past
-- 1e30 in marshmallow.lua); as a thermal strain (core/sim/material.h,
-- material_thermal_split) it must stop where linear thermoelasticity puts it:
-- tau = C:(eps - alpha dT I) is free when the volume strain is 3 alpha dT, and
-- eq. 10's c lambda is 3 K alpha (Gonzalez & Stuart 2008), so
--   ln J_th = c lambda (T - T_ref) / K,   K = lambda + 2/3 mu = E / (3 (1 - 2 nu)),
-- computed here from the preset's numbers, not by the code under test.
-- Modes (--set mode=...), each asserting its own bound:
--  free3d  3D, the particle starts at 90 degC, compaction = 0, overdamped: a free
--          particle expands isotropically, so J = J_th for any yield stress (within 1%).
--  compact3d  the same with the law's default compaction 0.5: the first step's
--          sudden strain presses the particle past its compressive yield
--          (eq. 12: tau_y / sqrt(M(n)) < c lambda dT) and it compacts, at most
--          by the cap J^P >= 1 - 0.5 n^p_0, so ln J is in
--          [ln J_th + ln(1 - 0.5 n^p_0), ln J_th].
--  oven2d  2D (plane strain, J the area ratio), heated from T_ref to 90 degC by
--          an oven over ~0.1 s (quasi-static): the in-plane strain of a plane
--          strain body with a thermal strain is c lambda dT / (lambda + mu) when
--          it stays elastic and c lambda dT / K when its out-of-plane stress has
--          yielded away, so ln J is in [c lambda dT / (lambda + mu), c lambda dT / K].
-- One particle, so no conduction; eq. 9's cooling under expansion moves T by a
-- factor J^(-c lambda / (rho c)) = 1 - 1e-7 here.
local h = require "hearth"
local P = h.params { mode = "free3d", steps = 3000, every = 100, damping = 0 }
local modes = { free3d = { dim = 3, T0 = 90, compaction = 0, damping = 5000 },
  compact3d = { dim = 3, T0 = 90, compaction = 0.5, damping = 50 }, oven2d = { dim = 2, compaction = 0.5, oven = 90, damping = 50 } }
local M = modes[P.mode] or error("--set mode=" .. tostring(P.mode) .. ": one of free3d, compact3d, oven2d")
local dx = 0.004
local d3 = M.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
-- damping settles the particle's elastic ringing (no other loss acts on it); it moves no equilibrium. free3d's
-- 5000 1/s is overdamped, so the sudden strain neither rings past the yield in tension nor (compaction 0)
-- compacts: the expansion is quasi-static, the closed form's case (at 50 1/s it rang to ln J 1.59 ln J_th)
local s = h.scene { dim = M.dim, dx = dx, box = { v(0, 0, 0), v(0.08, 0.08, 0.08) }, gravity = v(0, 0, 0), guard = "stop",
  damping = P.damping > 0 and P.damping or M.damping, oven = M.oven and { temperature = M.oven, beta = 20000 } or nil }
local smore, D = h.library.paper.smore, require "hearth.dough"
local ty = D.paper.smore.yield
smore.tau_y = h.curve { { D.THETA[1], ty * D.TAU_SHAPE[1] }, { D.THETA[2], ty * D.TAU_SHAPE[2] },
  { D.THETA[3], ty * D.TAU_SHAPE[3] }, { 100, ty * D.TAU_SHAPE[3] }, { 150, ty * D.TAU_SHAPE[4] }, irreversible = true }
smore.expansion = 2
smore.compaction = M.compaction
local mat = h.material("cam_clay_dough", smore)
local Tref = smore.reference_temperature or 0
local x = 0.04
s:add { shape = h.box(v(x, x, x), v(x + dx, x + dx, x + dx)), material = mat, ppc = 1, jitter = 0,
  temperature = M.T0 or Tref }
-- the preset's E and nu (cam_clay_dough's defaults where it gives none: nu 0.3, porosity n^p_0 0.1)
local E, nu, n0 = smore.E, smore.nu or 0.3, smore.porosity or 0.1
local K = E / (3 * (1 - 2 * nu))
local mu, lam = E / (2 * (1 + nu)), E * nu / ((1 + nu) * (1 - 2 * nu))
local done, jmin, jmax, msg, r = 0, math.huge, 0, nil, nil
while done < P.steps do
  local ok, e = pcall(s.step, s, P.every)
  done = done + P.every
  if not ok then msg = type(e) == "table" and e.message or tostring(e); break end
  r = s:particles { fields = { "temperature", "J" } }
  if done > 2 * P.steps / 3 then jmin, jmax = math.min(jmin, r.J[1]), math.max(jmax, r.J[1]) end -- where it settled
end
s:_state().ran = true
local T = r and r.temperature[1] or 0 / 0
local eth = smore.expansion * (T - Tref) / K
local lo, hi
if P.mode == "free3d" then lo, hi = 0.99 * eth, 1.01 * eth
elseif P.mode == "compact3d" then lo, hi = eth + math.log(1 - M.compaction * n0), 1.01 * eth
else lo, hi = smore.expansion * (T - Tref) / (lam + mu), 1.01 * eth end
print(("lone_molten %s: dim %d, %d steps, T %.6g degC, K %.6g Pa: thermal strain J_th = exp(c lambda dT / K) = %.6f "
  .. "(ln %.5g); J over the last third [%.6f, %.6f] (ln %.5g .. %.5g, ratio to ln J_th %.4f); bound ln J in [%.5g, %.5g]")
  :format(P.mode, M.dim, s:stats().step, T, K, math.exp(eth), eth, jmin, jmax, math.log(jmin), math.log(jmax),
    math.log(jmax) / eth, lo, hi))
if msg then print("lone_molten: stopped: " .. msg) end
if not msg and math.abs(T - 90) < 0.5 and math.log(jmin) >= lo and math.log(jmax) <= hi then print("lone_molten ok") end

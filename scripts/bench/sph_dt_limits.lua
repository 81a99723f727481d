-- Which stable-dt limit binds on the SPH dam break (scripts/bench/sph_dam_break.lua's
-- scene), step by step: the CFL limit cfl dx / (speed + sound speed) from the last
-- step's report (sph_stable_dt, core/sim/solver/sph_dt.c) against the dt taken. A step
-- whose dt is more than 1% below it was set by the viscous, force or heat limit (or a
-- rollback); the CFL-bound ones are within 1% (the speeds move a little within a step).
-- Prints the share of CFL-bound steps, the smallest dt over the CFL limit, the steps
-- and the mean dt to t_end.
--   hearth run scripts/bench/sph_dt_limits.lua --set dx=0.004 --set t_end=0.6
local h = require "hearth"
local P = h.params { dx = 0.004, t_end = 0.6 }
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 1.2, 0.6 } }, solver = "sph", wall = "slip",
  sph = { av_beta = 1, xsph0 = 0.05 } }
local water = h.material("newtonian", { density = 1000, bulk = 2e5, viscosity = 1e-3 })
s:add { shape = h.box({ 0, 0 }, { 0.2, 0.4 }), material = water, ppc = 1, jitter = 0 }
s:step(1)
local steps, bound, worst, t0 = 0, 0, math.huge, s:stats().t
while s:stats().t < P.t_end do
  local st = s:stats()
  local cfl_dt = st.cfl * P.dx / (st.max_speed + st.wave_speed)
  s:step(1)
  local ratio = s:stats().dt / cfl_dt
  steps = steps + 1
  if ratio > 0.99 then bound = bound + 1 end
  if ratio < worst then worst = ratio end
end
local st = s:stats()
print(("dx %g, %d particles, t %.3f s: %d steps, %.1f%% at the CFL limit (cfl %g), smallest dt / CFL limit %.3f, " ..
  "mean dt %.3g s, %d rollbacks, fastest %.2f m/s, sound speed %.2f m/s"):format(P.dx, st.particles, st.t, steps,
  100 * bound / steps, st.cfl, worst, (st.t - t0) / steps, st.rollbacks, st.max_speed, st.wave_speed))

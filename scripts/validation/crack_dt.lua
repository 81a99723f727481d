-- crack_dt.lua: bread.lua (by default its plain loaf, only = 1) with the scene's
-- time step set from outside, for docs/validation.md ("The crack over the time
-- step (#18, helper crackdt)"): does the unscored loaf's crack converge in dt?
-- It runs scripts/scenes/baking/bread.lua itself (same loaves, same measures,
-- same bread.csv, read by tests/bread_claims.py), with h.scene's settings
-- changed by:
--   cfl     the CFL number (core/sim/settings.c "cfl", default 0.5). It scales
--           only the mechanical limit cfl dx / (speed + wave speed): the
--           explicit heat and water limits (thermal_dt_limit, water_dt_limit)
--           cap dt on their own, unscaled (core/sim/solver/mpm.c, mpm_stable_dt)
--   dt_max  the largest step (s; 0: none); below every limit it makes the step
--           uniform, the same in every run of the same dt_max
--   transfer  the scene's transfer ("apic", the default, or "pic": the affine
--           part dropped, a dissipative transfer, to see how the answer moves
--           with the transfer's own loss per step)
--   field_steps  the fields' clock (core/sim/fields/field_clock.c: 0, the
--           default, lets heat and water skip steps while the cycle stays
--           within 0.1 of their explicit limit, which happens only at the
--           smallest steps; 1 carries them every step, single rate)
--   hearth run scripts/validation/crack_dt.lua --quiet [--set dx=0.004] [--set dt_max=2e-5] [--set only=0] ...
-- from any folder (the scene is found beside this script: h.scene_path; or --set bread=PATH to bread.lua).
-- Besides bread.csv's row, every frame prints the steps so far, the step's dt,
-- the two mechanical speeds and the fields' explicit limit, so the table can
-- say which limit set the step, and the scene's totals of water, CO2 and heat
-- and the plain loaf's damage summed over its particles (smooth measures, to
-- read an order in dt where the crack is a threshold's); the end prints the step count and the dt
-- seen at the frames (smallest, largest) and the mean step.
local h = require "hearth"
local P = h.params { dim = 2, dx = 0.005, until_t = 2.5, frames = 5, slit_depth = 0.02, slit_width = 0.01, only = 1,
  cfl = 0.5, dt_max = 0, transfer = h.choice { "apic", apic = "APIC (the scene setting's default)", pic = "PIC: no affine part, dissipative" }, field_steps = 0,
  bread = h.scene_path("../scenes/baking/bread.lua") }

-- bread.lua's own h.params sees the values parsed here (it declares a subset of these names)
h.pass_params(P)

local scene = h.scene
h.scene = function(o)
  o.cfl, o.dt_max, o.transfer, o.field_steps = P.cfl, P.dt_max, P.transfer, P.field_steps
  local s = scene(o)
  local methods = getmetatable(s).__index
  local run = methods.run
  methods.run = function(self, r)
    local on_frame, lo, hi = r.on_frame, math.huge, 0
    r.on_frame = function(f)
      on_frame(f)
      local st = self:stats()
      -- the plain loaf's damage (x < 0.14 m): its sum and its count past the crack band's peak (0.5) and at 1
      local p, dsum, dhalf, done = self:particles { fields = { "x", "damage" } }, 0, 0, 0
      for k = 1, p.n do
        if p.x[3 * k - 2] < 0.14 then
          local d = p.damage[k]
          dsum, dhalf, done = dsum + d, dhalf + (d >= 0.5 and 1 or 0), done + (d >= 1 and 1 or 0)
        end
      end
      print(("t %.3f  plain loaf damage: sum %.6g, %d particles >= 0.5, %d cracked"):format(st.t, dsum, dhalf, done))
      if st.step > 0 then lo, hi = math.min(lo, st.dt), math.max(hi, st.dt) end
      print(("t %.3f  step %d  dt %.4g s  speed %.4g  wave %.4g m/s  mechanical limit %.4g s  field limit %.4g s  "
        .. "water %.8g kg  gas %.8g mol  heat %.8g J"):format(st.t, st.step, st.dt, st.max_speed, st.wave_speed,
        P.cfl * P.dx / (st.max_speed + st.wave_speed), st.field_limit, st.water_mass, st.gas, st.heat_energy))
    end
    local out = run(self, r)
    local st = self:stats()
    print(("crack_dt: cfl %g dt_max %g dx %g only %d: %d steps, mean dt %.4g s, dt at frames %.4g .. %.4g s"):format(
      P.cfl, P.dt_max, P.dx, P.only, st.step, st.t / st.step, lo, hi))
    return out
  end
  return s
end

dofile(P.bread)

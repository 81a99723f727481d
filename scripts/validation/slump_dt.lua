-- slump_dt.lua: bread.lua's plain loaf with no oven, for docs/validation.md
-- ("The crack over the time step (#18, helper crackdt)" and "A damped dough
-- over the time step (helper doughdamp)"): does the loaf's slump under
-- gravity converge in dt? The same shape (h.recipes.loaf_shape), tray and
-- dough (h.library.paper.bread) as bread.lua. No oven is not the mechanics
-- alone: the preset's water evaporates at the ambient and its skin stiffens
-- as it dries, and its gas builds (`sealed` below takes both out). The step
-- fixed by dt_max (uniform when below the CFL limit, with field_steps = 1):
--   dt_max    the step (s)
--   transfer  "apic" (the scene default) or "pic" (the affine part dropped:
--             the transfer's own loss per step, larger)
--   material  "dough" (the preset) or "elastic" (the preset's E, nu and
--             density, no yield: is the transfer alone dt-convergent?)
--   damping   the core's grid velocity damping c (1/s, core/sim/settings.c;
--             0 = off): a drag on the absolute velocity, not a material's
--   field_steps  the fields' clock (0, the default: heat and water may skip
--             steps and the clock's landings shorten some, so dt_max 5e-5 s
--             and less is not uniform; 1: every step, uniform). The preset
--             carries its water and temperature, oven or not
--   sealed    1: the preset's evaporation and gas rate set to 0, so no skin
--             dries (its E and tau_y rise x100 as it does) and no gas
--             builds: the mechanics alone (0, the default: as the preset)
--   hearth run scripts/validation/slump_dt.lua --quiet [--set dx=0.005] [--set dt_max=1e-4] ...
-- Prints per frame the top of the loaf on its axis (mm above the tray), the
-- highest particle, the centroid's height and the kinetic energy.
local h = require "hearth"
local P = h.params { dx = 0.005, dt_max = 1e-4, until_t = 0.5, frames = 4, transfer = h.choice { "apic", apic = "APIC (the scene setting's default)", pic = "PIC: no affine part, dissipative" },
  material = h.choice { "dough", dough = "h.library.paper.bread's dough (cam_clay_dough)",
    elastic = "an elastic body of the dough's E, nu and density" }, damping = 0,
  field_steps = 0, sealed = 0 }
local TRAY, WIDTH, BODY, X0 = 0.02, 0.08, 0.03, 0.07 -- bread.lua's plain loaf
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.14, 0.14 } }, name = "slump", dt_max = P.dt_max,
  transfer = P.transfer, damping = P.damping, field_steps = P.field_steps }
h.recipes.tray(s, TRAY)
local prm = h.library.paper.bread
if P.sealed == 1 then -- a copy: the library's preset stays as it is
  local q = {}
  for k, v in pairs(prm) do q[k] = v end
  q.evaporation, q.gas_rate, prm = 0, 0, q
end
local mat = P.material == "elastic" and h.material("elastic", { E = prm.E, nu = prm.nu, density = prm.density })
  or h.material("cam_clay_dough", prm)
s:add { shape = h.recipes.loaf_shape(2, X0, TRAY, WIDTH, BODY), material = mat, ppc = 4 }
s:run { until_t = P.until_t, every = P.until_t / P.frames, on_frame = function(f)
  local p, top, yc, m = s:particles { fields = { "x" } }, -math.huge, 0, 0
  for k = 1, p.n do
    top = math.max(top, p.x[3 * k - 1])
    yc = yc + p.x[3 * k - 1]
  end
  local st = s:stats()
  print(("slump_dt %s %s damping %g sealed %d dx %g dt_max %g: t %.3f  steps %d  axis top %.4f mm  "
    .. "highest %.4f mm  centroid %.5f mm  kinetic %.6g J"):format(P.material, P.transfer, P.damping, P.sealed,
    P.dx, P.dt_max, f.t, st.step, 1e3 * h.recipes.height(s, X0, TRAY, 0.14, 2000), 1e3 * (top - TRAY),
    1e3 * (yc / p.n - TRAY), st.kinetic))
  print(("slump_dt   water %.6g kg, lost %.6g kg, gas %.4g"):format(st.water_mass, st.water_lost, st.gas))
end }

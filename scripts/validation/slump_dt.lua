-- slump_dt.lua: bread.lua's plain loaf with the mechanics alone (no oven: no
-- heat, water or gas), for docs/validation.md ("The crack over the time step
-- (#18, helper crackdt)"): does the loaf's slump under gravity converge in dt?
-- The same shape (h.recipes.loaf_shape), tray and dough (h.library.paper.bread
-- at its raw dough temperature's reference: no temperature field) as bread.lua;
-- the step fixed by dt_max (uniform when below the CFL limit):
--   dt_max    the step (s)
--   transfer  "apic" (the scene default) or "pic" (the affine part dropped:
--             the transfer's own loss per step, larger)
--   material  "dough" (the preset) or "elastic" (the preset's E, nu and
--             density, no yield: is the transfer alone dt-convergent?)
--   hearth run scripts/validation/slump_dt.lua --quiet [--set dx=0.005] [--set dt_max=1e-4] ...
-- Prints per frame the top of the loaf on its axis (mm above the tray), the
-- highest particle, the centroid's height and the kinetic energy.
local h = require "hearth"
local P = h.params { dx = 0.005, dt_max = 1e-4, until_t = 0.5, frames = 4, transfer = "apic", material = "dough" }
local TRAY, WIDTH, BODY, X0 = 0.02, 0.08, 0.03, 0.07 -- bread.lua's plain loaf
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.14, 0.14 } }, name = "slump", dt_max = P.dt_max,
  transfer = P.transfer }
h.recipes.tray(s, TRAY)
local prm = h.library.paper.bread
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
  print(("slump_dt %s %s dx %g dt_max %g: t %.3f  steps %d  axis top %.4f mm  highest %.4f mm  centroid %.5f mm  kinetic %.6g J")
    :format(P.material, P.transfer, P.dx, P.dt_max, f.t, st.step, 1e3 * h.recipes.height(s, X0, TRAY, 0.14, 2000),
      1e3 * (top - TRAY), 1e3 * (yc / p.n - TRAY), st.kinetic))
end }

-- Viscosity funnel with the SPH solver (Rodriguez-Arenas 2011 Fig. 3.15-3.16).
--   hearth run scripts/scenes/sph/funnel.lua [--set viscosity=50]
-- A block of Newtonian fluid falls into a funnel (two capsule colliders) and
-- runs out of its neck. The thesis compares nu = 1 with nu = 1e5 in its
-- animation units; here viscosity is in Pa s and the explicit viscous step
-- (dt <= 0.125 rho h^2 / mu) makes very high values slow, so compare e.g.
-- --set viscosity=0.5 with --set viscosity=50. Writes outflow.csv: the share
-- of a line at y = 0.05 m (below the neck) covered by fluid, over time (t_s, s).
local h = require "hearth"
-- newtonian's range of viscosity: [0, 1e6] Pa s
local P = h.params { viscosity = h.number { 0.5, min = 0, max = 1e6, unit = "Pa s", what = "the fluid's viscosity" },
  dx = h.number { 0.005, above = 0, unit = "m", what = "the grid spacing" } }

local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.4, 0.5 } }, solver = "sph",
  sph = { av_beta = 1, xsph0 = 0.05, alpha_c = 0.1, beta_c = 0.9 } }
local fluid = h.material("newtonian", { density = 1000, bulk = 4e4, viscosity = P.viscosity })
s:add { shape = h.box({ 0.12, 0.32 }, { 0.28, 0.46 }), material = fluid, ppc = 1, jitter = 0 }
local neck = 0.02
s:collider { shape = h.capsule({ 0.02, 0.3 }, { 0.2 - neck, 0.18 }, 0.006), mode = "slip" }
s:collider { shape = h.capsule({ 0.38, 0.3 }, { 0.2 + neck, 0.18 }, 0.006), mode = "slip" }

local n = s:stats().particles
local rows = { "t_s,pool_share" }
s:run { until_t = 1.0, every = 0.05, png = { field = "speed", path = "frames/speed_%04d.png" },
  on_frame = function(f)
    local below = 0
    local line = s:line("density", { 0, 0.05 }, { 0.4, 0.05 }, 101)
    for _, d in ipairs(line) do if d == d then below = below + 1 end end
    rows[#rows + 1] = ("%.3f,%.4f"):format(f.t, below / 101)
    h.write("outflow.csv", table.concat(rows, "\n") .. "\n")
  end }
print(("funnel, viscosity %g Pa s: t = %.2f s, %d particles"):format(P.viscosity, s:stats().t, n))

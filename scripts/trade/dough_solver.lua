-- One maxwell_sph dough slab in a 180 degC oven for 0.5 s, under the solver
-- the trade's `solver` knob picks (the scene of scripts/scenes/sph/compare_mpm_sph.lua,
-- one solver per run):
--   hearth trade scripts/trade/dough_solver.lua --metric height --knob dx=0.008,0.004 --knob solver=mpm,sph
local h = require "hearth"
local P = h.params { t_end = 0.5, solver = h.choice { "mpm", mpm = "the MPM solver", sph = "the SPH solver" } } -- the knob sets this parameter, so the SPH options follow it
local sph = P.solver == "sph"
local s = h.scene { dim = 2, dx = 0.004, box = { { 0, 0 }, { 0.3, 0.15 } }, solver = P.solver,
  oven = { temperature = 180, beta = 20 },
  sph = sph and { heat_ext = 6.1, heat_int = 0.5, av_beta = 1, xsph0 = 0.05 } or nil }
local dough = h.material("maxwell_sph", { density = 1100, bulk = 3e4, mu_e = 2e3, lambda = 2, viscosity = 20,
  conductivity = 0.5, specific_heat = 2500 })
s:add { shape = h.box({ 0.1, 0.01 }, { 0.2, 0.06 }), material = dough, jitter = 0, temperature = 26, ppc = sph and 1 or 4 }
s:collider { shape = h.plane({ 0, 0.01 }, { 0, 1 }), mode = "slip", friction = 0.3 }
s:run { until_t = P.t_end }

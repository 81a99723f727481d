-- The heat slab: a pinned square of half-width L in an oven, heated through
-- Robin faces with Biot number beta L / kappa = 1 (as in tests/unit_heat.c).
-- The exact centre temperature is the product of two slab series solutions:
--   T(0, 0, Fo) = T_oven - (T_oven - T_0) theta(Bi = 1, x = 0, Fo)^2,
-- theta(1, 0, 0.5) = 0.772526383 (Fourier number Fo = kappa t / (rho c L^2)),
-- so at Fo = 0.5 the centre is at 60.3202987 degC.
--   hearth trade scripts/trade/heat_slab.lua --metric centre_temperature \
--     --knob dx=0.004,0.002,0.001 --knob heat=explicit,implicit \
--     --reference analytic:60.3202987
local h = require "hearth"
local P = h.params { Fo = 0.5 }

local L, kappa, rho, c, beta = 0.02, 1.0, 1000, 1000, 50 -- beta L / kappa = 1
local s = h.scene { dim = 2, dx = L / 10, box = { { -0.032, -0.032 }, { 0.032, 0.032 } }, gravity = { 0, 0 },
  oven = { temperature = 120, beta = beta } }
local slab = h.material("elastic", { E = 1e-2, density = rho, conductivity = kappa, specific_heat = c })
s:add { shape = h.box({ -L, -L }, { L, L }), material = slab, ppc = 4, jitter = 0, temperature = 20, fixed = true }
s:run { until_t = P.Fo * rho * c * L * L / kappa }

-- muffin_heat_slab.lua: is the heat through the muffin's top the same over dx? (#18, helper muffin4;
-- docs/validation.md "The muffin's tear: the heat under the crown")
-- A 2D slab 48 mm deep with the muffin preset's heat (density 500, specific heat 20, conductivity 0.5:
-- h.library.paper.muffin, TUNE's kappa in lua/hearth/dough.lua) and its oven (105 degC, beta 75), on the
-- box's floor (no heat through it) and against its side walls, so the heat comes in through the top alone:
-- a semi-infinite solid with a Robin surface, whose closed form (Carslaw & Jaeger 1959, §2.7 eq. (1)) is
--   T(z, t) = T_oven [erfc(z / 2 sqrt(D t)) - exp(H z + H^2 D t) erfc(z / 2 sqrt(D t) + H sqrt(D t))],
-- H = beta / kappa, D = kappa / (rho c); its heat taken in per unit area, rho c int_0^inf T dz, is
-- Q(t) = rho c T_oven [2 sqrt(D t / pi) - (1 - exp(H^2 D t) erfc(H sqrt(D t))) / H]. 48 mm is deep enough to
-- stand for the half-space to 1 s (sqrt(D t) = 7 mm).
-- An elastic material (no gas, no water: the heat alone). Per frame it prints the particles' heat per unit
-- area (the middle half of the slab's width) over Q, and the top particle's temperature against the closed
-- form at its depth (the grid's sample of a boundary layer about one cell thick at 4 mm).
--   hearth run scripts/validation/muffin_heat_slab.lua --quiet [--set dx=0.003] [--set until_t=1]
local h = require "hearth"
local P = h.params { dx = 0.004, until_t = 1.0, frames = 4 }
local RHO, C, KAPPA, T_OVEN, BETA = 500, 20, 0.5, 105, 75
local W, DEPTH = 0.072, 0.048 -- whole cells at dx 4, 3, 2 and 1.5 mm
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { W, DEPTH + 0.03 } }, gravity = { 0, 0 },
  oven = { temperature = T_OVEN, beta = BETA }, name = "muffin_heat_slab" }
local m = h.material("elastic", { E = 4e4, nu = 0.3, density = RHO, specific_heat = C, conductivity = KAPPA })
-- the slab fills the box's floor and sides (material against a domain wall takes no heat through it)
local y0, top = P.dx, P.dx + DEPTH
s:add { shape = h.box({ P.dx, y0 }, { W - P.dx, top }), material = m, temperature = 0, ppc = 4 }
local Dm, H = KAPPA / (RHO * C), BETA / KAPPA

-- erfc to a relative error below 1.2e-7 (Numerical Recipes' erfcc, Chebyshev fit)
local function erfc(x)
  local t = 1 / (1 + 0.5 * math.abs(x))
  local y = t * math.exp(-x * x - 1.26551223 + t * (1.00002368 + t * (0.37409196 + t * (0.09678418 + t * (-0.18628806 +
    t * (0.27886807 + t * (-1.13520398 + t * (1.48851587 + t * (-0.82215223 + t * 0.17087277)))))))))
  return x >= 0 and y or 2 - y
end
local function exact(z, t)
  local r = math.sqrt(Dm * t)
  return T_OVEN * (erfc(z / (2 * r)) - math.exp(H * z + H * H * Dm * t) * erfc(z / (2 * r) + H * r))
end
local function heat_in(t) -- J/m^2 (header)
  local r = math.sqrt(Dm * t)
  return RHO * C * T_OVEN * (2 * r / math.sqrt(math.pi) - (1 - math.exp(H * H * Dm * t) * erfc(H * r)) / H)
end

s:run { until_t = P.until_t, every = P.until_t / P.frames, on_frame = function(f)
  if f.t == 0 then return end
  local q = s:particles { fields = { "x", "temperature" } }
  local mass = RHO * P.dx * P.dx / 4 -- 2 x 2 particles a cell (ppc 4), all whole cells
  local e, ytop, Ttop = 0, -math.huge, 0
  for k = 1, q.n do
    local x, y = q.x[3 * k - 2], q.x[3 * k - 1]
    if math.abs(x - W / 2) < W / 4 then
      e = e + mass * C * q.temperature[k]
      if y > ytop then ytop, Ttop = y, q.temperature[k] end
    end
  end
  local z = P.dx / 4 -- the top particle's depth as seeded (2 x 2 a cell)
  print(("dx %.1f mm, t %.3f s: heat in per area %.4f of the closed form; top particle %.1f degC, closed form at "
    .. "its depth (%.2f mm) %.1f degC, at the surface %.1f"):format(P.dx * 1e3, f.t, e / (W / 2) / heat_in(f.t), Ttop,
    z * 1e3, exact(z, f.t), exact(0, f.t)))
end }

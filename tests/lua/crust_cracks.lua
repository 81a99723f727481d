-- A dry, stiff crust over a crumb that expands (issue #18): does it crack?
-- A 8 x 3 cm slab of cam_clay_dough (E 5e3 Pa, tau_y 200 Pa, no pore cap)
-- on a sticky tray, water K theta = 2e-4 m^2/s and evaporation 2
-- kg/(m^2 s K) (a time lapse: the top ~4 mm dries in 0.3 s). Its E and
-- tau_y follow a moisture curve, x F at X/X0 <= 0.65, x1 at >= 0.85,
-- irreversible. At t = 0.3 s the oven goes from 20 to 120 degC (beta 1000
-- W/(m^2 K), Table 2's fast heat: c 20 J/(kg K), kappa 30 W/(m K)) and the
-- thermal expansion c lambda = 10 Pa/K swells the soft crumb under the
-- crust that does not swell as much (pores capped at 0.6, as the muffin's).
-- Run with F = 30 (a dried crust) and F = 1 (the same dough without dry
-- stiffening or embrittlement). What it shows (docs/validation.md, "Crust
-- (#18)"): the dried crust cracks at its crown (damage 1) by ~0.55 s. The
-- crumb ran away under eq. 10's expansion through the crack while that was a
-- pressure after the yield; as a thermal strain (core/sim/material.h) it
-- swells by ln J_th = 10 x 100 / K = 0.24 and stops ("Eq. 10 as a thermal
-- strain" in docs/validation.md).
-- The crack measure (the same as bread.lua's for the unscored loaf): the top
-- surface of the intact material, the highest particle with damage below 1
-- in each column of width dx (a fully damaged particle carries no tension:
-- a band of them is the crack, and cracked crust heaped in the V is debris,
-- not the surface; crack band model, Bazant & Oh 1983); a column is
-- open when it lies at least 0.1 of the body's height below the lower of the
-- highest columns within 4 cells on either side; a crack is a run of at
-- least 2 open columns. Prints "crack W cells, depth D" for each run.
local h = require "hearth"
local P = h.params { dx = 0.004, F = 30, cl = 10, ef = 1, ef_dry = 0.02, rule = 0 }
local dx = P.dx
local x0, x1, floor, H, s0 = 0.02, 0.10, 0.01, 0.03, 0.4
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.12, 0.08 } }, oven = { temperature = 20, beta = 0 }, name = "crust_cracks" }
local dry = h.curve { { 0.65, P.F }, { 0.85, 1 }, of = "moisture", irreversible = true }
-- The strain to fracture (the law's damage, plugins/cam_clay_dough.c): a wet dough's cell walls part
-- only at Hencky strains ~1 (P.ef), far past its yield strain tau_y / E ~ 0.04, so it flows and
-- never cracks; a glassy crust breaks at a few per cent (P.ef_dry, 0.02), before it yields. It
-- follows the same moisture points as the stiffening; F = 1, the dough without the dry crust's
-- stiffening, keeps the wet value too.
local ef = P.F > 1 and P.ef * h.curve { { 0.65, P.ef_dry / P.ef }, { 0.85, 1 }, of = "moisture", irreversible = true } or P.ef
local m = h.material("cam_clay_dough", { E = 5e3 * dry, nu = 0.3, density = 500, tau_y = 200 * dry, eta = 0,
  fracture_strain = ef, fracture_stretch = P.rule,
  specific_heat = 20, conductivity = 30, expansion = P.cl, reference_temperature = 20, porosity = 0.1, max_porosity = 0.6,
  water_diffusivity = 2e-4 / 293.15, evaporation = 2 })
s:collider { shape = h.plane({ 0, floor }, { 0, 1 }), mode = "sticky" }
s:add { shape = h.box({ x0, floor }, { x1, floor + H }), material = m, temperature = 20, saturation = s0 }

local K = 4 -- cells either side that a crack is measured against
local function crack()
  local r = s:particles { fields = { "x", "damage" } }
  local xl, top = x0 - 10 * dx, {}
  local nc = math.floor((x1 - x0) / dx + 0.5) + 20
  for c = 1, nc do top[c] = -math.huge end
  for i = 1, r.n do
    local c = math.floor((r.x[3 * i - 2] - xl) / dx) + 1
    if c >= 1 and c <= nc and r.damage[i] < 1 then top[c] = math.max(top[c], r.x[3 * i - 1]) end
  end
  local a, b, hmax = nil, nil, 0
  for c = 1, nc do if top[c] > -math.huge then a = a or c; b = c; hmax = math.max(hmax, top[c] - floor) end end
  local best, bestd, run, rund = 0, 0, 0, 0
  for c = a, b do
    local l, rr = -math.huge, -math.huge
    for k = math.max(a, c - K), c - 1 do l = math.max(l, top[k]) end
    for k = c + 1, math.min(b, c + K) do rr = math.max(rr, top[k]) end
    local depth = math.min(l, rr) - math.max(top[c], floor)
    if depth >= 0.1 * hmax then run, rund = run + 1, math.max(rund, depth) else run, rund = 0, 0 end
    if run > best or (run == best and rund > bestd) then best, bestd = run, rund end
  end
  return best, bestd, hmax
end

s:run { until_t = 0.3 }
local r = s:particles { fields = { "x", "saturation", "J" } }
local crust, n = 0, 0
for i = 1, r.n do
  if r.x[3 * i - 1] > floor + H - 0.004 then crust, n = crust + r.saturation[i] * r.J[i] / s0, n + 1 end
end
print(("dx %g mm, F %g: dried 0.3 s, top 4 mm X/X0 %.3f"):format(dx * 1e3, P.F, crust / n))
s:oven(120, 1000)
local w, d, hm
for k = 1, 2 do
  s:run { until_t = 0.3 + 0.2 * k }
  w, d, hm = crack()
  local q, nc = s:particles { fields = { "damage" } }, 0
  for i = 1, q.n do if q.damage[i] >= 1 then nc = nc + 1 end end
  print(("dx %g mm, F %g: t %.1f s height %.2f mm, widest opening %d cells, depth %.2f mm (%.3f of the height), %d cracked particles")
    :format(dx * 1e3, P.F, s:stats().t, hm * 1e3, w, d * 1e3, d / hm, nc))
end
if P.F > 1 then
  s:png("saturation", "crust_cracks.png")
  s:png("damage", "crust_cracks_damage.png", { kind = "particles", range = { 0, 1 } })
end
print(("crust_cracks result: dx %g F %g height %.2f mm opening %d cells depth %.3f"):format(dx * 1e3, P.F, hm * 1e3, w, d / hm))

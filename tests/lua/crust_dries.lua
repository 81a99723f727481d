-- The surface dries first (issue #18): a bread loaf (h.library.dough.bread
-- with a real dough's heat, c = 2800 J/(kg K), kappa = 0.5 W/(m K), and
-- water: effective diffusivity K theta = 5e-8 m^2/s, evaporation 3e-5
-- kg/(m^2 s K)), pinned (the mechanics play no part), 8 x 4 cm in a 200 degC
-- oven for 20 minutes, evaporation taking its latent heat (real heat
-- capacities: the crumb stays near 100 degC while the surface climbs). The mean moisture ratio X/X0 of the top 4 mm (the
-- crust-to-be) and of the centre (8 mm around mid-height), mid-loaf (2 cm
-- wide), printed over the bake. The top must lose water faster than the
-- centre all along, and end below 0.7 with the centre above 0.97.
local h = require "hearth"
local P = h.params { dx = 0.004, until_t = 1200 }
local dx = P.dx
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.12, 0.08 } }, gravity = { 0, 0 },
  oven = { temperature = 200, beta = 40 }, latent_heat = true }
local d = h.library.dough.bread
d.specific_heat, d.conductivity = 2800, 0.5
d.dry_conductivity, d.dry_specific_heat = 0, 0 -- its own real-unit conductivity and specific heat, one for wet
-- and dry, as when this was written
d.water_diffusivity, d.evaporation = 5e-8 / 373.15, 3e-5
local y1, s0 = 0.06, 0.4
s:add { shape = h.box({ 0.02, 0.02 }, { 0.10, y1 }), material = h.material("cam_clay_dough", d), temperature = 25,
  saturation = s0, fixed = true, jitter = 0 }
local function layers()
  local r = s:particles { fields = { "x", "saturation" } }
  local a, na, c, nc = 0, 0, 0, 0
  for i = 1, r.n do
    local x, y = r.x[3 * i - 2], r.x[3 * i - 1]
    if math.abs(x - 0.06) < 0.01 then
      if y > y1 - 0.004 then a, na = a + r.saturation[i], na + 1 end
      if math.abs(y - 0.04) < 0.004 then c, nc = c + r.saturation[i], nc + 1 end
    end
  end
  return a / na / s0, c / nc / s0 -- pinned: J = 1, so s/s0 is the moisture ratio
end
local top, centre
for k = 1, 6 do
  s:run { until_t = P.until_t * k / 6 }
  top, centre = layers()
  print(("dx %g mm  t %5.0f s  top 4 mm X/X0 %.4f  centre %.4f  (surface %.1f degC, centre %.1f degC)"):format(dx * 1e3,
    s:stats().t, top, centre, s:probe("temperature", { 0.06, y1 - dx / 4 }), s:probe("temperature", { 0.06, 0.04 })))
  assert(1 - top > 5 * (1 - centre), "the top does not lose water five times faster than the centre")
end
assert(top < 0.7 and centre > 0.97, ("the end of the bake: top %.4f (< 0.7), centre %.4f (> 0.97)"):format(top, centre))
print(("crust_dries ok: dx %g mm, after %g s top %.4f centre %.4f"):format(dx * 1e3, P.until_t, top, centre))

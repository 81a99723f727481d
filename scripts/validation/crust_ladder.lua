-- crust_ladder.lua: tests/lua/crust_dries.lua's loaf at three resolutions, for
-- docs/validation.md ("Crust (#18)").
--   hearth run scripts/validation/crust_ladder.lua --quiet
-- An 8 x 4 cm loaf of bread dough (h.library.dough.bread with c 2800 J/(kg K),
-- kappa 0.5 W/(m K); water K theta = 5e-8 m^2/s, evaporation 3e-5
-- kg/(m^2 s K), saturation 0.4), pinned, 20 minutes in a 200 degC oven (beta
-- 40 W/(m^2 K)), latent heat on. The mean moisture ratio X/X0 of the top
-- 4 mm and of the centre 8 mm, mid-loaf (2 cm wide), after 10 and 20
-- minutes. Observed order: log2 of successive differences' ratio.
local h = require "hearth"
local function loaf(dx)
  local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.12, 0.08 } }, gravity = { 0, 0 },
    oven = { temperature = 200, beta = 40 }, latent_heat = true }
  local d = h.library.dough.bread
  d.specific_heat, d.conductivity = 2800, 0.5
  d.dry_conductivity, d.dry_specific_heat = 0, 0 -- its own real-unit conductivity and specific heat, one for wet
  -- and dry, as when this was written
  d.water_diffusivity, d.evaporation = 5e-8 / 373.15, 3e-5
  s:add { shape = h.box({ 0.02, 0.02 }, { 0.10, 0.06 }), material = h.material("cam_clay_dough", d), temperature = 25,
    saturation = 0.4, fixed = true, jitter = 0 }
  local out = {}
  for k, t in ipairs { 600, 1200 } do
    s:run { until_t = t }
    local r = s:particles { fields = { "x", "saturation" } }
    local a, na, c, nc = 0, 0, 0, 0
    for i = 1, r.n do
      local x, y = r.x[3 * i - 2], r.x[3 * i - 1]
      if math.abs(x - 0.06) < 0.01 then
        if y > 0.056 then a, na = a + r.saturation[i], na + 1 end
        if math.abs(y - 0.04) < 0.004 then c, nc = c + r.saturation[i], nc + 1 end
      end
    end
    out[2 * k - 1], out[2 * k] = a / na / 0.4, c / nc / 0.4
  end
  return out
end
local names = { "top, 10 min", "centre, 10 min", "top, 20 min", "centre, 20 min" }
local rows = {}
for i, dx in ipairs { 0.004, 0.002, 0.001 } do rows[i] = loaf(dx) end
print("dx (mm)   " .. table.concat(names, " | "))
for i, dx in ipairs { 4, 2, 1 } do
  print(("%-9g %s"):format(dx, table.concat({ ("%.4f"):format(rows[i][1]), ("%.4f"):format(rows[i][2]),
    ("%.4f"):format(rows[i][3]), ("%.4f"):format(rows[i][4]) }, " | ")))
end
local ord = {}
for k = 1, 4 do
  local d1, d2 = rows[1][k] - rows[2][k], rows[2][k] - rows[3][k]
  ord[k] = ("%.2f"):format(math.log(math.abs(d1 / d2), 2))
end
print("order     " .. table.concat(ord, " | "))

-- browning_ladder.lua: tests/unit_browning.c's browning_surface_not_crumb
-- loaf at four resolutions, for docs/validation.md ("Browning (#18)").
--   hearth run scripts/validation/browning_ladder.lua --quiet
-- A 10 cm square of bread dough (kappa 0.4 W/(m K), rho 500 kg/m^3, c 2800
-- J/(kg K)) baked 20 minutes in an oven at 250 degC, beta 40 W/(m^2 K), its
-- heat and browning both run S = 600 times fast (c / S, browning_scale S:
-- 2 s simulated). Measured on the vertical centre line: the index at 2.5 and
-- 10 mm under the top face (s:probe, the particles' B-spline average), the
-- centre's, and the crust's depth (where the index falls to 0.3, linear
-- between the line's 401 samples). Observed order: log2 of successive
-- differences' ratio.
local h = require "hearth"
local S, L, c = 600, 0.1, 0.1
local function loaf(dx)
  local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.2, 0.2 } }, gravity = { 0, 0 },
    oven = { temperature = 250, beta = 40 }, browning = true, browning_scale = S }
  local dough = h.material("elastic", { E = 1e4, density = 500, conductivity = 0.4, specific_heat = 2800 / S })
  s:add { shape = h.box({ c - L / 2, c - L / 2 }, { c + L / 2, c + L / 2 }), material = dough, temperature = 20,
    fixed = true, jitter = 0 }
  s:run { until_t = 1200 / S }
  local top = c + L / 2
  local n = 401
  local line = s:line("browning", { c, top }, { c, c }, n)
  local depth = 0 / 0
  for k = 1, n - 1 do
    local a, b = line[k], line[k + 1]
    if a == a and b == b and a >= 0.3 and b < 0.3 then
      depth = (k - 1 + (a - 0.3) / (a - b)) * (L / 2) / (n - 1)
      break
    end
  end
  return { dx = dx, b25 = s:probe("browning", { c, top - 0.0025 }), b10 = s:probe("browning", { c, top - 0.010 }),
    centre = s:probe("browning", { c, c }), depth = depth, T = s:probe("temperature", { c, top - 0.0025 }),
    n = s:stats().particles }
end
local rows = {}
print("| dx (mm) | particles | index 2.5 mm in | index 10 mm in | centre | crust depth (index 0.3, mm) | T 2.5 mm in (degC) |")
print("|---|---|---|---|---|---|---|")
for k, dx in ipairs { 0.01, 0.005, 0.0025, 0.00125 } do
  local r = loaf(dx)
  rows[k] = r
  print(("| %g | %d | %.4f | %.4f | %.2e | %.2f | %.1f |"):format(1000 * dx, r.n, r.b25, r.b10, r.centre, 1000 * r.depth, r.T))
end
for _, q in ipairs { "b25", "b10", "depth" } do
  local o = {}
  for k = 1, #rows - 2 do
    o[#o + 1] = ("%.2f"):format(math.log(math.abs(rows[k][q] - rows[k + 1][q]) / math.abs(rows[k + 1][q] - rows[k + 2][q]), 2))
  end
  print(("observed order of %s: %s"):format(q, table.concat(o, ", ")))
end

-- browning_picture_shows_crust: s:png("browning", path) with no kind draws the crust in the colour its particles carry
-- (#18, helper userfix9; userview4's item 6: a slice averaged the one-particle crust with the crumb under it and the
-- air above, so the physical pancake's and loaf's browning.png drew them pale while their lines gave the top
-- 0.247 / 0.153). docs/lua.md's browning example, shortened: a 10 cm block of real dough at 250 degC, 20 real minutes
-- at a time scale of 600 (Zanoni et al. 1995's kinetics, fields/browning.c), on a coarse 10 mm grid so it runs in
-- well under a second. Prints the picture's geometry, the top particle on the centre line and the browning colour map
-- (h.colormap) at t = 0, 0.01, ..., 1 for tests/png_pixel.py to read the picture's colour back as a browning.
local h = require "hearth"
local S = 600
local dx = 0.01
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.2, 0.2 } }, gravity = { 0, 0 },
  oven = { temperature = 250, beta = 40 }, browning = true, browning_scale = S }
local dough = h.material("elastic", { E = 1e4, density = 500, conductivity = 0.4, specific_heat = 2800 / S })
s:add { shape = h.box({ 0.05, 0.05 }, { 0.15, 0.15 }), material = dough, temperature = 20, fixed = true, jitter = 0 }
s:run { until_t = 1200 / S }
local r = s:particles { fields = { "x", "browning" } }
local top, tx, ty = nil, 0, -1
for i = 1, r.n do -- the highest particle nearest the centre line x = 0.1 (a column of them: the lattice's)
  local x, y = r.x[3 * i - 2], r.x[3 * i - 1] -- x has three components in 2D too
  if math.abs(x - 0.1) < dx / 2 and y > ty then top, tx, ty = r.browning[i], x, y end
end
local _, info = s:png("browning", "browning.png")
print(("top particle x %.5f y %.5f browning %.4f"):format(tx, ty, top))
-- the top particle's centre in the picture's pixels (its plot's area and the metres it shows): its own disc there
local a, lo, hi = info.area, info.view_lo, info.view_hi
print(("pixel %.2f %.2f"):format(a[1] + (tx - lo[1]) / (hi[1] - lo[1]) * a[3], a[2] + (hi[2] - ty) / (hi[2] - lo[2]) * a[4]))
local map = {}
for k = 0, 100 do map[#map + 1] = table.concat({ h.colormap("browning", k / 100) }, ",") end
print("map " .. table.concat(map, " "))

-- browning_3d_picture_shows_cut: a 3D s:png("browning", path) with no kind or depth draws a slab about the middle
-- plane, so its crumb is pale inside a brown ring, as a loaf cut in half (Ding Fig. 18's halves) (#18, helper
-- userfix11; userfix9's Left: a 3D particle picture is a projection seen along -z, so browning.png showed the front
-- face's crust, brown all over). tests/lua/browning_picture.lua's block of real dough at 250 degC for 20 real minutes,
-- in 3D, fixed, at two spacings (12.5 and 10 mm: 4096 and 8000 particles). For each, prints the picture's title
-- and, for two points of its plane, the particle the picture should draw there (of those within the slab, the
-- nearest in x and y, the largest z on top, as render.c draws far to near) and that point's pixel: the block's
-- centre and the top of its centre column; then the browning colour map for tests/png_pixel.py.
local h = require "hearth"
local S = 600
for _, dx in ipairs { 0.0125, 0.01 } do
  local s = h.scene { dim = 3, dx = dx, box = { { 0, 0, 0 }, { 0.2, 0.2, 0.2 } }, gravity = { 0, 0, 0 },
    oven = { temperature = 250, beta = 40 }, browning = true, browning_scale = S }
  local dough = h.material("elastic", { E = 1e4, density = 500, conductivity = 0.4, specific_heat = 2800 / S })
  s:add { shape = h.box({ 0.05, 0.05, 0.05 }, { 0.15, 0.15, 0.15 }), material = dough, temperature = 20, fixed = true,
    jitter = 0 }
  s:run { until_t = 1200 / S }
  local r = s:particles { fields = { "x", "browning" } }
  local name = ("browning_%g.png"):format(dx * 1000)
  local _, info = s:png("browning", name)
  print(("picture %s title %s"):format(name, info.title))
  local half = dx -- the slab the scene's default draws: 2 dx thick about z = 0.1 (lua/lua_output.c)
  -- the particle drawn at (tx, ty): within the slab, nearest in x and y, the largest z of those
  local function drawn_at(tx, ty)
    local best, bd, bz = nil, math.huge, -math.huge
    for i = 1, r.n do
      local x, y, z = r.x[3 * i - 2], r.x[3 * i - 1], r.x[3 * i]
      if math.abs(z - 0.1) <= half then
        local d = (x - tx) ^ 2 + (y - ty) ^ 2
        if d < bd - 1e-12 or (d < bd + 1e-12 and z > bz) then best, bd, bz = i, math.min(d, bd), z end
      end
    end
    return best
  end
  local a, lo, hi = info.area, info.view_lo, info.view_hi
  local function show(what, i)
    local x, y = r.x[3 * i - 2], r.x[3 * i - 1]
    print(("%s %g browning %.4f pixel %.2f %.2f"):format(what, dx, r.browning[i],
      a[1] + (x - lo[1]) / (hi[1] - lo[1]) * a[3], a[2] + (hi[2] - y) / (hi[2] - lo[2]) * a[4]))
  end
  local c = drawn_at(0.1, 0.1)
  show("centre", c)
  local top = drawn_at(r.x[3 * c - 2], 0.2) -- the centre particle's column, at its top
  show("top", top)
end
local map = {}
for k = 0, 100 do map[#map + 1] = table.concat({ h.colormap("browning", k / 100) }, ",") end
print("map " .. table.concat(map, " "))

-- Bread (Ding et al. 2019, Fig. 15): three loaves of the same dough baked side
-- by side, one intact, one with a slit scored on top, one with two.
--   hearth run scripts/scenes/baking/bread.lua [--set dim=3] [--set until_t=4]
-- Writes, under hearth-out/bread/: heat_%04d.png (temperature) and
-- bread.csv: per frame (t_s, the simulated time: Table 2's animation units),
-- each loaf's height and each slit's gap width (the
-- open width of the cut, measured across it halfway up its lower wall), each
-- loaf's area (2D, m^2) or volume (3D, m^3): the sum of V0 J over its
-- particles (area_plain_m2, area_one_slit_m2, area_two_slits_m2 in 2D; volume_plain_m3, volume_one_slit_m3 and
-- volume_two_slits_m3 in 3D: #18, helper userfix7, where one name had held both without a unit; --params and the
-- run's first lines say it too); and the plain loaf's top crack: the deepest notch in the top of
-- its intact material (crack_depth_m: how far the top of a one-cell column
-- lies below the lower of the highest tops within 15 mm (whole cells) to its left and to
-- its right) and the notch's width (crack_width_m: the run of columns around
-- it deeper than half that), over the loaf's middle 80%. A column's top is
-- its highest particle whose damage is below 1: a fully damaged particle
-- carries no tension (plugins/cam_clay_dough.c), so a band of them is the
-- crack itself, as in the crack band model (Bazant & Oh 1983, Mater. Constr.
-- 16:155), and the cracked crust that heaps in the opening is debris, not
-- its surface (docs/validation.md, Crust (#18)); and (#18) the plain loaf's
-- water: X/X0 (its water over the water it was given, saturation x J / s_0) of
-- its top particle on the loaf's axis and of the particle nearest the crumb's
-- centre (on the axis, 35 mm above the tray), and its count of cracked
-- particles (damage 1); and top_arc_m, the length of the plain loaf's top skin
-- followed as material (the particles on top of its crown's middle 80% at the
-- start, by id): its growth is the stretch the rise puts on the crust. The dough carries water (lua/hearth/dough.lua, WATER:
-- rates x600, so 2.5 s stand for a 25 minute bake); at the end it writes
-- damage.png and browning.png (in 3D the particles within dx of the middle plane, z = 0.06 m: a cut's crust ring).
-- The tray: tray = "separate" (default; a greased tray or baking paper: the foot may slide, friction 0.4, and
-- lift) or "sticky" (a bare tray the dough sticks to: the contact holds the foot where it touched, in tension
-- too), as loaf_physical.lua's (docs/validation.md, "The loaf's foot on its tray (#18, helper loaffoot)").
-- cracked, the plain loaf's count of cracked particles, has no unit (tests/scene_csv.py's unit rule):
-- bread.csv has no unit: cracked
local h = require "hearth"
local P = h.params { dim = h.number { 2, min = 2, max = 3, integer = true,
    what = "the space's dimensions (bread.csv's loaf sizes: area_*_m2 in 2D, volume_*_m3 in 3D)" },
  dx = h.number { 0.005, above = 0, unit = "m", what = "the grid spacing" },
  until_t = h.number { 2.5, above = 0, unit = "s", what = "the bake's simulated time" },
  frames = h.number { 5, min = 1, integer = true, unit = "frames", what = "PNG frames over the bake" },
  -- a slit is cut down from the round top (BODY + WIDTH / 2 = 70 mm above the tray): at most to the tray
  slit_depth = h.number { 0.02, min = 0, below = 0.07, unit = "m", what = "the slits' depth below the loaf's top" },
  slit_width = h.number { 0.01, above = 0, below = 0.08, unit = "m",
    what = "the slits' width; the loaf is 80 mm wide" },
  only = h.number { 0, min = 0, max = 3, integer = true,
    what = "the one loaf to bake (1: plain, 2: one slit, 3: two; 0: all)" },
  dx_min_3d = h.number { 0.008, min = 0, unit = "m", what = "the finest grid spacing in 3D (0: no floor)" },
  tray = h.choice { "separate",
    separate = "friction 0.4: the foot slides out, as on a greased or papered tray",
    sticky = "the foot held where it touched, as on a bare tray the dough has wetted" } }
local d3 = P.dim == 3
-- 3D keeps dx at least dx_min_3d (8 mm: a loaf in minutes); lower it to measure finer (docs/validation.md,
-- "bread.lua in 3D"); the validation wrappers that hand this scene their own params (crack_heat.lua) leave it unset
local dx = h.dx_3d(P.dx, P.dx_min_3d or 0.008, d3) -- says so when it raises dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local oven = h.library.paper_oven.bread
print(("bread.lua: h.library.paper.bread, animation units (Ding Table 2): heat runs in seconds, not minutes; water %g times fast; its %g degC oven does not brown the crust (for a "
  .. "browning crust: loaf_physical.lua; its base browns, its top stays pale)")
  :format(oven.water_time_scale, oven.temperature))
local TRAY, WIDTH, BODY, SPACING = 0.02, 0.08, 0.03, 0.14 -- m: tray, loaf width, straight part, loaf spacing
local zc, ZW = 0.06, 0.06 -- 3D: loaves are extruded along z over +-ZW/2
local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(3 * SPACING, 0.14, 0.12) },
  oven = { temperature = oven.temperature, beta = oven.beta }, name = "bread", browning = true,
  browning_scale = oven.water_time_scale, time_units = "animation" }
h.recipes.tray(s, TRAY, { temperature = oven.pan_temperature, beta = oven.pan_beta, mode = P.tray })
local dough = h.material("cam_clay_dough", h.library.paper.bread)

-- a loaf: a box with a round top (2D), extruded in 3D; slits are thin boxes cut from the top
local loaves = {
  { x = 0.5 * SPACING, slits = {} },
  { x = 1.5 * SPACING, slits = { 0 } },
  { x = 2.5 * SPACING, slits = { -0.018, 0.018 } },
}
local top0 = TRAY + BODY + WIDTH / 2
for i, L in ipairs(loaves) do
  if P.only > 0 and i ~= P.only then goto next end -- --set only=2: bake just that loaf (the tests do)
  local shape = h.recipes.loaf_shape(P.dim, L.x, TRAY, WIDTH, BODY, zc, ZW) -- shared with tear_open.lua
  for _, off in ipairs(L.slits) do
    shape = shape - h.box(v(L.x + off - P.slit_width / 2, top0 - P.slit_depth, 0), v(L.x + off + P.slit_width / 2,
      top0 + 0.01, 0.12))
  end
  s:add { shape = shape, material = dough, temperature = oven.dough_temperature, saturation = oven.saturation,
    ppc = d3 and 8 or 4 }
  ::next::
end

-- height of the material above the tray on the vertical line at x
local function height(x)
  local n = 1000
  local d = s:line("density", v(x, TRAY, zc), v(x, 0.14, zc), n + 1)
  local top = 0
  for k, val in ipairs(d) do if val == val then top = (k - 1) * (0.14 - TRAY) / n end end
  return top
end
-- the gap of a slit at x0: the empty run around x0 on a horizontal line halfway up the slit's lower wall, between
-- its floor (the material's top at x0) and the loaf's top beside the slit. The line had been a third of the slit
-- depth below that top, which at the two-slit loaf's slits, off its crown, lay at the slits' floor (y 69.8 mm
-- against the floor at 70): each slit read open or shut by the jitter of its floor's particles (bread.csv's first
-- row 2.70 and 0 mm; #18, helpers userview4, userfix8)
local function gap(x0)
  local y = TRAY + (height(x0) + math.min(height(x0 - 0.012), height(x0 + 0.012))) / 2
  local n, span = 400, 0.03
  local d = s:line("density", v(x0 - span, y, zc), v(x0 + span, y, zc), n + 1)
  local mid = n // 2 + 1
  if d[mid] == d[mid] then return 0 end -- closed: material at the slit's centre
  local lo, hi = mid, mid
  while lo > 1 and d[lo - 1] ~= d[lo - 1] do lo = lo - 1 end
  while hi < n + 1 and d[hi + 1] ~= d[hi + 1] do hi = hi + 1 end
  return (hi - lo + 2) * 2 * span / n
end

-- each loaf's area (volume in 3D): V0 J summed over the particles within half a spacing of its centre;
-- every particle starts with the same V0 (one dx and ppc), read at the start as volume / count
local v0
local function areas()
  local p = s:particles { fields = { "x", "J" } }
  v0 = v0 or s:volume() / p.n
  local a = { 0, 0, 0 }
  for k = 1, p.n do
    local i = math.floor(p.x[3 * k - 2] / SPACING) + 1
    if a[i] then a[i] = a[i] + v0 * p.J[k] end
  end
  return a
end
-- the plain loaf's top crack (header): notch depth and width on the top of its intact material
local function crack(x0)
  local p = s:particles { fields = { "x", "damage" } }
  local lo, n, w = x0 - 0.4 * WIDTH, math.floor(0.8 * WIDTH / dx + 0.5), math.floor(0.015 / dx + 0.5)
  local top = {} -- per one-cell column: the highest intact particle above the tray; an empty column is open to the tray
  for k = 1, n do top[k] = 0 end
  for k = 1, p.n do
    local c = math.floor((p.x[3 * k - 2] - lo) / dx) + 1
    if c >= 1 and c <= n and p.damage[k] < 1 and (not d3 or math.abs(p.x[3 * k] - zc) < dx / 2) then
      top[c] = math.max(top[c], p.x[3 * k - 1] - TRAY)
    end
  end
  local depth = {}
  for k = 1, n do
    local l, r = 0, 0
    for j = math.max(1, k - w), k do l = math.max(l, top[j]) end
    for j = k, math.min(n, k + w) do r = math.max(r, top[j]) end
    depth[k] = math.min(l, r) - top[k]
  end
  local kmax = 1
  for k = 2, n do if depth[k] > depth[kmax] then kmax = k end end
  local d = depth[kmax]
  if not (d > 0) then return 0, 0 end
  local a, b = kmax, kmax
  while a > 1 and depth[a - 1] > d / 2 do a = a - 1 end
  while b < n and depth[b + 1] > d / 2 do b = b + 1 end
  return d, (b - a + 1) * dx
end

-- the plain loaf's water (header): X/X0 of its top particle and its crumb's centre, and its cracked particles
local function water(x0)
  local p = s:particles { fields = { "x", "saturation", "J", "damage" } }
  local top, ctr, nc, yc = nil, nil, 0, TRAY + 0.035
  for k = 1, p.n do
    local x, y = p.x[3 * k - 2], p.x[3 * k - 1]
    if math.abs(x - x0) < SPACING / 2 and p.damage[k] >= 1 then nc = nc + 1 end
    if math.abs(x - x0) < dx / 2 and (not d3 or math.abs(p.x[3 * k] - zc) < dx / 2) then
      if not top or y > p.x[3 * top - 1] then top = k end
      if not ctr or math.abs(y - yc) < math.abs(p.x[3 * ctr - 1] - yc) then ctr = k end
    end
  end
  if not top then return 0, 0, nc end
  local s0 = oven.saturation
  return p.saturation[top] * p.J[top] / s0, p.saturation[ctr] * p.J[ctr] / s0, nc
end

-- the plain loaf's top skin, followed as material (header, top_arc_m): the highest particle of each one-cell
-- column over the crown's middle 80% at the start, by id; its length is the polyline through them in their
-- starting order, so its growth is the tangential stretch the rise puts on the skin
local skin
local function top_arc(x0)
  local p = s:particles { fields = { "id", "x" } }
  if not skin then
    local lo, n = x0 - 0.4 * WIDTH, math.floor(0.8 * WIDTH / dx + 0.5)
    local best = {}
    for k = 1, p.n do
      local c = math.floor((p.x[3 * k - 2] - lo) / dx) + 1
      if c >= 1 and c <= n and (not d3 or math.abs(p.x[3 * k] - zc) < dx / 2) and
        (not best[c] or p.x[3 * k - 1] > p.x[3 * best[c] - 1]) then best[c] = k end
    end
    skin = {}
    for c = 1, n do if best[c] then skin[#skin + 1] = p.id[best[c]] end end
  end
  local at = {}
  for k = 1, p.n do at[p.id[k]] = k end
  local len, prev = 0, nil
  for _, id in ipairs(skin) do
    local k = at[id]
    if k then
      if prev then len = len + math.sqrt((p.x[3 * k - 2] - p.x[3 * prev - 2]) ^ 2 + (p.x[3 * k - 1] - p.x[3 * prev - 1]) ^ 2) end
      prev = k
    end
  end
  return len
end

-- each loaf's size says its unit in its name: an area in 2D, a volume in 3D (tests/bread_claims.py reads either)
local size = d3 and "volume_%s_m3" or "area_%s_m2"
local rows = { "t_s,height_plain_m,height_one_slit_m,height_two_slits_m,gap_one_slit_m,gap_two_slits_left_m,gap_two_slits_right_m,"
  .. size:format("plain") .. "," .. size:format("one_slit") .. "," .. size:format("two_slits")
  .. ",crack_depth_m,crack_width_m,moisture_top,moisture_centre,cracked,top_arc_m" }
print(("bread.csv: %s is each loaf's V0 J summed, %s"):format(size:format("*"), d3 and "a volume in m^3 (3D)"
  or "in m^2 (2D)"))
print(rows[1]) -- the rows each frame prints below are bread.csv's: its header first, so they read as columns
-- the frames' titles say which loaf lies where and whose seconds they are (#18, helper userview3: "t = 2.5 s" alone
-- read as two and a half seconds of a real bake)
local label = (P.only == 0 and "plain, one slit, two slits" or ({ "plain loaf", "one slit", "two slits" })[P.only])
  .. "; Table 2's animation units"
s:run { until_t = P.until_t, every = P.until_t / P.frames,
  png = { field = "temperature", path = "heat_%04d.png", label = label },
  on_frame = function(f)
    local r = { ("%.3f"):format(f.t) }
    for _, L in ipairs(loaves) do
      r[#r + 1] = ("%.5f"):format(height(L.x + (#L.slits == 1 and 0.02 or 0)))
    end
    r[#r + 1] = ("%.5f"):format(gap(loaves[2].x))
    r[#r + 1] = ("%.5f"):format(gap(loaves[3].x + loaves[3].slits[1]))
    r[#r + 1] = ("%.5f"):format(gap(loaves[3].x + loaves[3].slits[2]))
    for _, a in ipairs(areas()) do r[#r + 1] = ("%.6g"):format(a) end
    local cd, cw = crack(loaves[1].x)
    r[#r + 1] = ("%.5f"):format(cd)
    r[#r + 1] = ("%.5f"):format(cw)
    local top, ctr, nc = 0, 0, 0
    if P.only <= 1 then top, ctr, nc = water(loaves[1].x) end
    r[#r + 1] = ("%.4f"):format(top)
    r[#r + 1] = ("%.4f"):format(ctr)
    r[#r + 1] = ("%d"):format(nc)
    r[#r + 1] = ("%.5f"):format(P.only <= 1 and top_arc(loaves[1].x) or 0)
    rows[#rows + 1] = table.concat(r, ",")
    h.write("bread.csv", table.concat(rows, "\n") .. "\n")
    print(rows[#rows])
  end,
  -- for ParaView (open vtu/bread.pvd: the time axis, temperature, stress, ids) and Blender (ply/)
  vtu = { path = "vtu/bread_%04d.vtu" },
  ply = { path = "ply/bread_%04d.ply", color = "temperature", colormap = "inferno" } }
s:png("damage", "damage.png", { kind = "particles", range = { 0, 1 }, label = label })
s:png("browning", "browning.png", { label = label })

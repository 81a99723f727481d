-- Muffin tray (Ding et al. 2019, Fig. 2): batter in heated cups rises into a dome.
--   hearth run scripts/scenes/baking/muffins.lua [--set dim=3] [--set cups=3] [--set ppc=9] [--set preset=physical]
-- preset: "paper" (the default: h.library.paper.muffin, Table 2's animation units, 3 s) or "physical"
-- (h.library.dough.muffin: a batter's measured density, heat capacity and conductivity, its rates 60 times fast,
-- latent heat and boiling on; 22 s stand for a 22 minute bake, and the frames' titles give the real time). The
-- physical batter has no crust fracture, so it domes and does not tear: its tear columns read the top of all of
-- its particles. until_t = 0 bakes the preset's own time.
-- (ppc: particles a cell, 0 = 4 in 2D and 8 in 3D; the risen crumb, J up to 2.25 at the preset's pore cap,
-- keeps ~1.8 of 4 a cell, and at dx 4 mm its crown parts along a column of particles: a numerical
-- fracture that 9 a cell does not show, docs/validation.md "The muffin's tear: the heat under the crown,
-- and particles a cell")
-- Writes, under hearth-out/muffins/: heat_%04d.png (temperature) and
-- muffins.csv: per frame (t_s, the simulated time; the physical preset adds
-- its real time, t_real_s) and cup, the top of the batter at the cup's centre
-- above the rim, its centre's height above its edge, the curvature of
-- its top (negative = domed), and its deepest tear (#18): over the one-cell
-- bins of the top of its intact material (particles with damage below 1; see
-- tops) across the cup, how far a bin's top lies below the lower of
-- the highest tops on its left and on its right (tear_depth), and the width
-- of the run of bins around it deeper than half that (tear_width, m); and
-- (#18) the first cup's water: X/X0 (water over the water given, saturation x
-- J / s_0) of its top particle on the cup's axis and of the particle nearest
-- the batter's centre (on the axis, fill / 2 above the floor), and its count
-- of cracked particles (damage 1). The batter carries water (lua/hearth/dough.lua,
-- WATER: rates x600); at the end it writes damage.png and browning.png (in 3D the particles within dx of the
-- middle plane, z = 0.04 m, through the cups' axes: a cut's crust ring, not the front face's crust).
-- How it domes: the tin heats the batter from its walls and floor (the
-- muffin preset's kappa gives a Biot number of ~7, see lua/hearth/dough.lua),
-- so the batter there passes gelatinisation (tau_y x20, frozen) while the
-- centre is still soft and making CO2; the centre rises, the set rim stays.
-- The batter stays soft up to 55 degC (lua/hearth/dough.lua, MUFFIN_SET).
-- Measured (2D, one cup, 1.5 s): dx 4 mm, centre 12.34 mm above the edge, top
-- curvature -5.8 1/m (the crown's tear flattens the fit), the centre's top from
-- 9.2 mm below the rim to 7.3 mm above it (claim_muffin_domes); dx 3 mm 17.70
-- mm, domed at 1 s (-45 1/m) but +6.3 1/m at 1.5 s, its crown torn flat at both
-- shoulders (claim_muffin_domes_fine, an expected failure). Its top dries before the rise but stays leathery until it sets (the
-- preset's heat-set, lua/hearth/dough.lua HEAT_SET), and its crown then tears:
-- 4.70 mm deep and 8 mm wide at 4 mm (claim_muffin_top_tears); at 3 mm 3.85 mm,
-- short of the claim (docs/validation.md "The muffin's tear: the heat-set"); the
-- 4 mm notch is a V the crown opens by flow, which finer grids do not open, and
-- from 3.5 mm down the notch is 2.9-3.9 mm ("The muffin's tear over dx"); that V
-- is the risen crumb parting along a column of particles at 4 a cell: at 9 a
-- cell (ppc) the notch is 1.52 mm at 4 mm and 0.31 mm at 3 mm (helper muffin4). With
-- bread's set (stiffening from 35 degC) the top stayed 4.4 mm below the rim
-- (dome 4.14 mm); with Table 2's kappa (an isothermal batter; gas x0.1) the
-- same cup ended dished: centre 1.2 mm below the edge, curvature +5 1/m.
-- cracked_1, the first cup's count of cracked particles, has no unit (tests/scene_csv.py's unit rule):
-- muffins.csv has no unit: cracked_1
local h = require "hearth"
local P = h.params { dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" },
  dx = h.number { 0.004, above = 0, unit = "m", what = "the grid spacing" },
  until_t = h.number { 0, min = 0, unit = "s", what = "the bake's simulated time (0: the preset's own)" },
  frames = h.number { 6, min = 1, integer = true, unit = "frames", what = "PNG frames over the run" },
  -- at most a dozen, as cookies' ovens and pull_twist's doughs: each cup widens the box (1e300 had been refused by
  -- the box's cell count, naming no parameter)
  cups = h.number { 3, min = 1, max = 12, integer = true, what = "muffin cups in a row" },
  -- the batter's depth above the cup's inner floor (12 mm up), at most to the box's top (100 mm)
  fill = h.number { 0.022, above = 0, below = 0.088, unit = "m", what = "the batter's depth in its cup" },
  -- s:add's range of ppc: 1 to 1000 (lua/hearth/init.lua)
  ppc = h.number { 0, min = 0, max = 1000, integer = true, what = "particles per cell (0: 4 in 2D, 8 in 3D)" },
  wall_mode = h.choice("slip", h.contact_words), -- the cup's walls and floor
  preset = h.choice { "paper", paper = "h.library.paper.muffin: Ding Table 2, animation units",
    physical = "h.library.dough.muffin: a real batter's properties, its bake in real minutes mapped" } }
local d3 = P.dim == 3
local dx = h.dx_3d(P.dx, 0.006, d3) -- says so when it raises dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local physical = P.preset == "physical"
local oven = physical and h.library.oven.muffin or h.library.paper_oven.muffin
local S = physical and oven.time_scale or nil -- the physical preset's rates run S times fast: t_real = S t
local until_t = P.until_t > 0 and P.until_t or physical and oven.bake_time or 3
if physical then
  print(("muffins.lua: h.library.dough.muffin, %s; bake %.0f min in %.1f s"):format(oven.units, until_t * S / 60, until_t))
else
  print(("muffins.lua: h.library.paper.muffin, animation units (Ding Table 2): heat runs in seconds, not minutes; water %g times fast; its %g degC oven does not brown the crust ("
    .. "--set preset=physical browns it where the cup touches it; its top stays pale, as loaf_physical.lua's)")
    :format(oven.water_time_scale, oven.temperature))
end
-- m: the cups' inner floor, inner radius, wall height above the floor, wall and floor thickness, cup spacing
local BASE, R, CUP_H, WALL, SPACING = 0.012, 0.025, 0.03, 0.004, 0.08
local W = SPACING * P.cups
local zc = 0.04
local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(W, 0.1, 0.08) },
  oven = { temperature = oven.temperature, beta = oven.beta, wall_temperature = oven.wall_temperature,
    emissivity = oven.emissivity, radiation_scale = oven.radiation_scale }, name = "muffins", browning = true,
  browning_scale = physical and oven.browning_scale or oven.water_time_scale, latent_heat = physical and oven.latent_heat,
  boiling_point = physical and oven.boiling_point or nil, gas_vent = physical and oven.gas_vent or nil,
  vent_porosity = physical and oven.vent_porosity or nil, time_scale = S,
  time_units = physical and "real" or "animation" }
local batter = h.material("cam_clay_dough", physical and h.library.dough.muffin or h.library.paper.muffin)
-- the paper batter's dried skin cracks (its damage field); the physical one has no fracture law
local cracks = not physical
local xs, tins = {}, {}
for i = 1, P.cups do
  -- cup centres on grid nodes: both walls then sit alike on the grid and the
  -- batter's top is symmetric (off-node, one side's top climbed its wall)
  xs[i] = math.floor((i - 0.5) * SPACING / dx + 0.5) * dx
  -- the cup, its inner floor at BASE, and the batter filling it (h.recipes.muffin_cup, shared with tear_open.lua)
  tins[i] = h.recipes.muffin_cup(s, { dim = P.dim, x = xs[i], base = BASE, radius = R, height = CUP_H, wall = WALL, fill = P.fill,
    zc = zc, material = batter, oven = oven, mode = P.wall_mode, ppc = P.ppc > 0 and P.ppc or d3 and 8 or 4 })
end
local RIM = BASE + CUP_H

-- The top of each cup's batter from its particles: in bins one cell wide
-- across the cup (in 3D on the slab |z - zc| < dx/2), the highest particle;
-- with `intact`, the highest whose damage is below 1 (the tear's measure, as
-- bread.lua's crack: a band of fully damaged particles is the tear itself,
-- and cracked crust heaped in it is debris, not the top).
local function tops(intact)
  local q = s:particles { fields = cracks and { "x", "damage" } or { "x" } }
  local x = q.x
  local t = {}
  for i = 1, P.cups do t[i] = {} end
  for p = 0, q.n - 1 do
    local px, py, pz = x[3 * p + 1], x[3 * p + 2], x[3 * p + 3]
    if (not d3 or math.abs(pz - zc) < dx / 2) and not (intact and cracks and q.damage[p + 1] >= 1) then
      local i = math.floor(px / SPACING) + 1
      if xs[i] and math.abs(px - xs[i]) <= R then
        local b = math.floor((px - xs[i]) / dx + 0.5)
        if not t[i][b] or py > t[i][b] then t[i][b] = py end
      end
    end
  end
  return t
end
-- centre: mean top over |u| <= R/4; edge: over |u| >= 3R/4 (the batter at the
-- walls); curvature: 2a of the least-squares y = a u^2 + b u + c over |u| <= 0.6 R
local function measure(top)
  local c, nc, e, ne, pts = 0, 0, 0, 0, {}
  for b, y in pairs(top) do
    local u = b * dx
    if math.abs(u) <= R / 4 then c, nc = c + y, nc + 1 end
    if math.abs(u) >= 3 * R / 4 then e, ne = e + y, ne + 1 end
    if math.abs(u) <= 0.6 * R then pts[#pts + 1] = { u, y } end
  end
  local a = h.parabola(pts)
  if nc == 0 or ne == 0 or a ~= a then return 0 / 0, 0 / 0, 0 / 0 end
  return c / nc, c / nc - e / ne, 2 * a
end

-- the deepest tear of a cup's top (header): its depth and width (m)
local function tear(top)
  local lo, hi = math.huge, -math.huge
  for b in pairs(top) do lo, hi = math.min(lo, b), math.max(hi, b) end
  if lo > hi then return 0, 0 end
  local left, right, depth = {}, {}, {}
  for b = lo, hi do left[b] = math.max(left[b - 1] or -math.huge, top[b] or -math.huge) end
  for b = hi, lo, -1 do right[b] = math.max(right[b + 1] or -math.huge, top[b] or -math.huge) end
  local bmax, dmax = lo, 0
  for b = lo, hi do
    depth[b] = math.min(left[b], right[b]) - (top[b] or BASE) -- an empty bin is a gap down to the floor
    if depth[b] > dmax then bmax, dmax = b, depth[b] end
  end
  if dmax <= 0 then return 0, 0 end
  local a, z = bmax, bmax
  while a > lo and depth[a - 1] > dmax / 2 do a = a - 1 end
  while z < hi and depth[z + 1] > dmax / 2 do z = z + 1 end
  return dmax, (z - a + 1) * dx
end

-- the first cup's water (header): X/X0 of its top particle and its centre, and its cracked particles
local function water()
  local p = s:particles { fields = cracks and { "x", "saturation", "J", "damage" } or { "x", "saturation", "J" } }
  local top, ctr, nc, yc = nil, nil, 0, BASE + P.fill / 2
  for k = 1, p.n do
    local x, y = p.x[3 * k - 2], p.x[3 * k - 1]
    if cracks and math.abs(x - xs[1]) <= R and p.damage[k] >= 1 then nc = nc + 1 end
    if math.abs(x - xs[1]) < dx / 2 and (not d3 or math.abs(p.x[3 * k] - zc) < dx / 2) then
      if not top or y > p.x[3 * top - 1] then top = k end
      if not ctr or math.abs(y - yc) < math.abs(p.x[3 * ctr - 1] - yc) then ctr = k end
    end
  end
  if not top then return 0, 0, nc end
  return p.saturation[top] * p.J[top] / oven.saturation, p.saturation[ctr] * p.J[ctr] / oven.saturation, nc
end

local head = { "t_s" }
for i = 1, P.cups do
  head[#head + 1] = ("top_above_rim_%d_m,centre_above_edge_%d_m,top_curvature_%d_1_per_m,tear_depth_%d_m,tear_width_%d_m")
    :format(i, i, i, i, i)
end
head[#head + 1] = "moisture_top_1,moisture_centre_1,cracked_1"
-- t_s is the simulated time: the paper preset's Table 2 animation units, the physical preset's S times fast, whose
-- real time t_real_s = S t_s comes last (pancake.lua's and lava_cake.lua's columns)
if physical then head[#head + 1] = "t_real_s" end
local rows = { table.concat(head, ",") }
print(rows[1]) -- the rows each frame prints below are muffins.csv's: its header first, so they read as columns
-- the frames' title: what they show and, for the paper preset, that their seconds are Table 2's animation units
-- (a frame read alone said "t = 3 s"; bread.lua's and pancake.lua's said so already; #18, helper userview4)
local label = ("%d muffin%s, oven %g °C%s"):format(P.cups, P.cups == 1 and "" or "s", oven.temperature,
  physical and "" or "; Table 2's animation units")
s:run { until_t = until_t, every = until_t / P.frames,
  png = { field = "temperature", path = "heat_%04d.png", time_scale = S, label = label },
  on_frame = function(f)
    local r = { ("%.3f"):format(f.t) }
    local t, ti = tops(false), tops(true)
    for i = 1, P.cups do
      local c, ce, k = measure(t[i])
      local td, tw = tear(ti[i])
      r[#r + 1] = ("%.5f,%.5f,%.3f,%.5f,%.5f"):format(c - RIM, ce, k, td, tw)
    end
    r[#r + 1] = ("%.4f,%.4f,%d"):format(water())
    if physical then r[#r + 1] = ("%.1f"):format(S * f.t) end
    rows[#rows + 1] = table.concat(r, ",")
    h.write("muffins.csv", table.concat(rows, "\n") .. "\n")
    print(rows[#rows])
  end }
if cracks then s:png("damage", "damage.png", { kind = "particles", range = { 0, 1 }, label = label }) end
s:png("browning", "browning.png", { time_scale = S, label = label })
local tin = s:collider_heat(tins[1])
if physical and tin.oven_in > 0 then -- the tin the batter drew its heat from (colliders.h)
  print(("muffins.lua: the first cup's tin at %.1f min %.1f degC; it gave the batter %.0f J of the oven's %.0f (J%s)")
    :format(s:stats().t * S / 60, tin.temperature, tin.drawn, tin.oven_in, d3 and "" or " per metre of depth"))
end

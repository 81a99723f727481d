-- Torn open after baking (Ding et al. 2019, Fig. 2 right: "a muffin torn open to reveal a fully cooked
-- interior"; Fig. 16: "tearing of the bread after baking"): one muffin (muffins.lua's cup and preset) or one
-- loaf (bread.lua's plain loaf and preset) is baked as those scenes bake it, taken out (the oven off, its cup or
-- tray taken away) and held by its outer thirds, which are pulled straight apart until it parts.
--   hearth run scripts/scenes/baking/tear_open.lua [--set food=muffin|bread] [--set raw=true] [--set dx=...]
--   [--set bake=...] (s; 0 = the food's own: muffin 3, muffins.lua's whole bake; bread 2.5, bread.lua's)
--   [--set speed=0.05] (m/s, each grip) [--set pull=0.4] (s) [--set frames=20] (frames over the pull)
--   [--set two_field=true] (the scene's two velocity fields where a crack runs, Homel & Herbold 2017,
--   core/sim/solver/mpm_two_field.c: a crack's sides part instead of moving as one; off by default for both
--   foods, as muffins.lua and bread.lua bake, so the bake here is theirs; with it the muffin parts into two clean
--   halves, the loaf parts later, measured below)
-- raw = true pulls the same shape unbaked: the dough as it goes into the oven, at its own temperature, gripped
-- and pulled at t = 0 alike.
-- The pull: both grips move straight apart (x), not up or about a hinge. A hand tearing a muffin also bends the
-- halves open from the top, but a hinge stretches the top most and the base least, so what parts first depends
-- on the bending arm as much as on the crumb; a straight pull loads the whole section alike, the way pull_twist.lua
-- (Fig. 6) loads its strips, so the baked and the raw dough are compared at the same stretch.
-- The grips (colliders of mode "grip": they carry the particles inside them) hold everything outside the middle
-- third of the food's raw width (x < xc - w/6 and x > xc + w/6, the full height): the free span between them is
-- 17 mm (muffin, w = 50 mm) or 27 mm (loaf, w = 80 mm). (With the middle half free, 25 and 40 mm, the loaf's
-- whole middle sheared off at the grips and fell under its own weight.)
-- Writes, under hearth-out/tear_open/: heat_%04d.png (temperature) and damage_%04d.png at the end of the bake
-- and every fifth frame of the pull and its last, browning.png at the end (3D: a slab 2 dx thick about the middle
-- plane), and tear_open.csv, per frame
-- (t_s, the simulated time, s):
--   separation_m: how far the grips have moved apart (0 through the bake);
--   neck_m: the thinnest section between the grips: over one-cell columns from a cell inside each grip's face,
--     the height of the one-cell rows that hold an intact particle (damage below 1: a fully cracked particle
--     carries no tension, plugins/cam_clay_dough.c); 0 = a column with no intact particle, torn through;
--   pieces: the pieces of intact material: one-cell bins holding an intact particle joined to their eight
--     neighbours, counting the components that hold at least 5% of the intact particles (smaller ones are crumbs);
--   face_particles, face_peak_min_degC, face_peak_max_degC: the particles on the faces the pull opened (in the
--     free span, with an empty bin among their eight neighbours now, and none at the start of the pull: they were
--     inside), and the lowest and highest peak temperature they reached (each particle's highest temperature over
--     the frames, a lower bound on its true peak, since the frames sample it);
--   cracked: particles with damage 1;
--   force_mid_N_per_m: the pull's tension through the middle: sigma_xx V summed over the particles in the
--     one-cell column at the food's centre, over dx (N per metre of depth, 2D);
--   free_cracked_fraction: of the particles in the free span at the take-out, the share cracked now (a crumbling
--     band cracks most of it, two faces a few cells each);
--   largest_piece_share: the largest component of intact bins' particles over all the particles (two clean halves
--     near 0.5 less their cracked faces; crumbs and a fallen strip lower it);
--   crack_from_face_m: where the pull cracks: the median, over the free span's particles it has cracked (not those
--     the bake cracked), of their distance now to the nearer grip face (empty until it cracks one);
--   bodies, loose_share: pieces, over every particle's bins (cracked or not): two halves with their torn faces on
--     them and a clean gap are two bodies, crumbs between the halves bridge them into one; loose_share: the
--     particles outside the bodies (crumbs fallen clear).
-- 2D only: the measures are over columns and bins of the plane.
-- Measured (frames every 2 mm of separation; one field / two; docs/validation.md "Torn open after baking"):
--   baked muffin (3 s), dx 4 / 3 mm, two fields (--set two_field=true): two pieces by 10 / 4 mm of separation (one field:
--     4 / 4), 49 / 100 cracked at 40 mm (one field 68 / 130), 52 / 58% of the free span cracked (71 / 74%), the
--     largest piece 42 / 40% of the particles (38 / 38%); the faces' particles all reached 81.7 / 81.1 degC and more
--     (one field 81.2 / 80.2; the batter sets from 55 degC); raw (raw = true, nothing cracks, the same either way):
--     two pieces at 32 mm / not within 40. The tear starts at the top of the middle (4 mm) and runs down it: two
--     halves each with a rough cracked face 2-4 cells deep and a clean gap between them (two bodies from 20 mm on,
--     0.4 / 0.2% loose); with one field the cracked band's sides share their nodes, so the free crumb between the
--     halves falls as crumbs instead (bridging the halves into one body at 3 of 11 frames at 4 mm; 4.0% loose at 3).
--   baked loaf (2.5 s), dx 5 / 4 mm, one field: two pieces by 8 / 8 mm (neck 0 by 14 / 10 mm), 109 /
--     247 cracked at 40 mm; its faces all reached 81.2 degC (the crumb sets at 70; the loaf heats evenly, Biot 0.04);
--     tension through the middle at most 57 / 51 N/m; raw: two pieces at 24 / 26 mm, at most 39 / 37 N/m. It tears
--     at both grips' faces (a grip's edge is a stress raiser, as a hand's fingers are), starting at their feet (5 mm),
--     and its middle strip hangs on one half (one field, 5 mm) or falls free (three pieces). Two fields clean its
--     faces (94 / 173 cracked) but part it only by 12 / 20 mm, which the raw dough's 24 / 26 mm no longer doubles
--     at 4 mm (the contrast claim_raw_dough_stretches_before_tearing_fine asks, with one field).
-- Cost (CPU, --threads 1, a shared 2-core machine): muffin 13 / 17 s at 4 mm, 50 / 65 s at 3 mm (one field / two);
-- loaf 7 / 8 s at 5 mm, 13 / 17 s at 4 mm; a raw pull 1-3 s.
-- cracked, the count of cracked particles, has no unit (tests/scene_csv.py's unit rule):
-- tear_open.csv has no unit: cracked
-- An empty cell is "not measured" (pancake.lua's rule, read by tests/scene_csv.py): the torn faces' peaks before the
-- pull has opened a face, where it cracks before it has cracked anything:
-- tear_open.csv may leave empty (not measured): face_peak_min_degC, face_peak_max_degC, crack_from_face_m
local h = require "hearth"
-- the pull's and the run's numbers, each with its valid range (0 for dx, bake and ppc: the food's own)
local P = h.params { dim = h.number { 2, min = 2, max = 2, integer = true,
    what = "the space's dimensions; the tear is measured over the plane's columns" },
  raw = h.flag { false, what = "pull the food unbaked, at its own temperature, in place of the baked one" },
  food = h.choice { "muffin", muffin = "a muffin's batter in its cup (h.library.paper.muffin)",
    bread = "a loaf of bread dough on its tray (h.library.paper.bread)" },
  dx = h.number { 0, min = 1e-4, max = 0.02, unit = "m", what = "the grid spacing", also = { [0] = "the food's own" } },
  bake = h.number { 0, min = 0, max = 100, unit = "s", what = "the bake before the pull (0: the food's own)" },
  speed = h.number { 0.05, above = 0, max = 10, unit = "m/s", what = "the grips' speed" },
  pull = h.number { 0.4, above = 0, max = 100, unit = "s", what = "the pull's time" },
  frames = h.number { 20, min = 1, max = 10000, integer = true, what = "PNG frames over the pull" },
  ppc = h.number { 0, min = 0, max = 64, integer = true, what = "particles per cell (0: 4)" },
  two_field = h.flag { false, what = "two velocity fields where a crack runs (Homel & Herbold 2017), so its sides part" } }
local muffin = P.food == "muffin"
local dx = P.dx > 0 and P.dx or muffin and 0.004 or 0.005 -- the food's own scene's dx
local bake = P.raw and 0 or P.bake > 0 and P.bake or muffin and 3 or 2.5
-- the frames' title: which food, baked or raw, and that the seconds are Table 2's animation units (#18, helper
-- userview4: the frames said their time alone)
local label = ("%s %s; Table 2's animation units"):format(P.raw and "raw" or "baked", P.food)
local oven = h.library.paper_oven[P.food]
print(("tear_open.lua: h.library.paper.%s, animation units (Ding Table 2): heat runs in seconds, not minutes; water %g "
  .. "times fast; %s"):format(P.food, oven.water_time_scale,
  P.raw and "raw (not baked)" or ("baked %g s"):format(bake)))

-- the food: muffins.lua's cup (its inner floor, radius, wall height, wall; 22 mm of batter), bread.lua's loaf
local W, H = muffin and 0.14 or 0.24, muffin and 0.1 or 0.14
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { W, H } },
  oven = not P.raw and { temperature = oven.temperature, beta = oven.beta } or nil, name = "tear_open",
  browning = true, browning_scale = oven.water_time_scale, two_field = P.two_field, time_units = "animation" }
local material = h.material("cam_clay_dough", h.library.paper[P.food])
local xc = math.floor(W / 2 / dx + 0.5) * dx -- on a grid node, as muffins.lua's cups
local BASE, R, FLOOR -- m: the food's floor, half its raw width, how far below BASE its support reaches
local support
if muffin then
  BASE, R, FLOOR = 0.012, 0.025, 0.004
  support = h.recipes.muffin_cup(s, { dim = 2, x = xc, base = BASE, radius = R, height = 0.03, wall = FLOOR,
    fill = 0.022, material = material, oven = oven, mode = "slip", ppc = P.ppc > 0 and P.ppc or 4 })
else
  BASE, R, FLOOR = 0.02, 0.04, 0.01
  support = h.recipes.tray(s, BASE, { temperature = oven.pan_temperature, beta = oven.pan_beta })
  s:add { shape = h.recipes.loaf_shape(2, xc, BASE, 2 * R, 0.03), material = material,
    temperature = oven.dough_temperature, saturation = oven.saturation, ppc = P.ppc > 0 and P.ppc or 4 }
end
local FACE = R / 3 -- the grips' inner faces at xc -+ FACE: each holds its side's outer third of the raw width

-- one-cell bins of the particles (damage below 1 with `intact`), keyed i * 2^20 + j
local function key(x, y) return math.floor(x / dx) * 1048576 + math.floor(y / dx) end
local function occupancy(p, intact)
  local occ = {}
  for k = 1, p.n do
    if not intact or p.damage[k] < 1 then
      local c = key(p.x[3 * k - 2], p.x[3 * k - 1])
      occ[c] = (occ[c] or 0) + 1
    end
  end
  return occ
end
local function inside(occ, x, y) -- all eight neighbours of the bin at x, y hold a particle
  local c = key(x, y)
  for di = -1, 1 do
    for dj = -1, 1 do if not occ[c + di * 1048576 + dj] then return false end end
  end
  return true
end

local t0, peak, was_inside, v0 = nil, {}, nil, nil
local was_free, was_cracked, nfree -- by id at the take-out: in the free span; cracked already (by the bake)
local function separation(t) return t0 and 2 * P.speed * math.max(0, t - t0) or 0 end

local function measure(t)
  local p = s:particles { fields = { "id", "x", "temperature", "damage", "stress", "J" } }
  v0 = v0 or s:volume() / p.n -- every particle starts with the same volume (one dx, one ppc)
  for k = 1, p.n do
    local id, T = p.id[k], p.temperature[k]
    if not peak[id] or T > peak[id] then peak[id] = T end
  end
  local all, intact = occupancy(p, false), occupancy(p, true)
  local a, b = xc - FACE - separation(t) / 2 + dx, xc + FACE + separation(t) / 2 - dx -- the free span, a cell in
  -- the neck: per one-cell column over [a, b], the intact rows
  local rows, c0, c1 = {}, math.floor(a / dx), math.floor(b / dx)
  for c = c0, c1 do rows[c] = 0 end
  for kk in pairs(intact) do
    local c = kk // 1048576
    if rows[c] then rows[c] = rows[c] + 1 end
  end
  local neck = math.huge
  for c = c0, c1 do neck = math.min(neck, rows[c] * dx) end
  -- pieces: components of the intact bins (eight neighbours), those with >= 5% of the intact particles; bodies:
  -- the same over every particle's bins (cracked or not), those with >= 5% of all: a cracked face still on its
  -- half is part of that half's body, crumbs between the halves bridge them into one, and loose: the share of the
  -- particles outside the bodies (crumbs fallen away)
  local function components(occ)
    local seen, sizes, total = {}, {}, 0
    for _, n in pairs(occ) do total = total + n end
    for start in pairs(occ) do
      if not seen[start] then
        local stack, size = { start }, 0
        seen[start] = true
        while #stack > 0 do
          local q = table.remove(stack)
          size = size + occ[q]
          for di = -1, 1 do
            for dj = -1, 1 do
              local r = q + di * 1048576 + dj
              if occ[r] and not seen[r] then seen[r] = true; stack[#stack + 1] = r end
            end
          end
        end
        sizes[#sizes + 1] = size
      end
    end
    local count, largest, held = 0, 0, 0
    for _, n in ipairs(sizes) do
      if n >= 0.05 * total then count, held = count + 1, held + n end
      largest = math.max(largest, n)
    end
    return count, largest, total > 0 and 1 - held / total or 0
  end
  local pieces, largest = components(intact)
  local bodies, _, loose = components(all)
  -- the faces the pull opened, their particles' peak temperatures; the cracked; the force through the middle
  -- and where the pull cracks the free span: the share of its particles cracked now (a crumbling band cracks most
  -- of it, two faces a few cells each), and how far from the nearer grip face the particles it cracked lie now
  -- (the median; those the bake had cracked left out: the pull's tear, not the crust's)
  local nf, tlo, thi, cracked, force = 0, math.huge, -math.huge, 0, 0
  local free_cracked, from_face = 0, {}
  local left, right = xc - FACE - separation(t) / 2, xc + FACE + separation(t) / 2 -- the grips' faces now
  for k = 1, p.n do
    local x, y, id = p.x[3 * k - 2], p.x[3 * k - 1], p.id[k]
    if p.damage[k] >= 1 then
      cracked = cracked + 1
      if was_free and was_free[id] then
        free_cracked = free_cracked + 1
        if not was_cracked[id] then from_face[#from_face + 1] = math.min(x - left, right - x) end
      end
    end
    if was_inside and was_inside[id] and x > a and x < b and not inside(all, x, y) then
      nf, tlo, thi = nf + 1, math.min(tlo, peak[id]), math.max(thi, peak[id])
    end
    if math.abs(x - xc) < dx / 2 then force = force + p.stress[9 * k - 8] * v0 * p.J[k] / dx end
  end
  table.sort(from_face)
  local median = #from_face > 0 and (from_face[(#from_face + 1) // 2] + from_face[#from_face // 2 + 1]) / 2 or 0 / 0
  return p, all, neck, pieces, nf, tlo, thi, cracked, force, nfree and free_cracked / nfree or 0,
    largest / p.n, median, bodies, loose
end

-- out of the oven: the oven off (no air exchange: the food keeps its heat through the tear), the cup or tray
-- taken away, the grips on the outer thirds, moving apart
local function take_out(sc)
  local p, all = measure(sc:stats().t)
  was_inside = {}
  was_free, was_cracked, nfree = {}, {}, 0
  for k = 1, p.n do
    local x, id = p.x[3 * k - 2], p.id[k]
    was_inside[id] = inside(all, x, p.x[3 * k - 1])
    if math.abs(x - xc) < FACE then was_free[id], nfree = true, nfree + 1 end
    was_cracked[id] = p.damage[k] >= 1
  end
  t0 = sc:stats().t
  if not P.raw then sc:oven(nil) end
  sc:move(support, { 0, -1 }) -- out of the scene
  local lo, hi = BASE - FLOOR - dx, H + 1
  sc:collider { shape = h.box({ xc - 3 * R, lo }, { xc - FACE, hi }), mode = "grip", velocity = { -P.speed, 0 } }
  sc:collider { shape = h.box({ xc + FACE, lo }, { xc + 3 * R, hi }), mode = "grip", velocity = { P.speed, 0 } }
end
s:at(bake, take_out)

local rows = { "t_s,separation_m,neck_m,pieces,face_particles,face_peak_min_degC,face_peak_max_degC,cracked,"
  .. "force_mid_N_per_m,free_cracked_fraction,largest_piece_share,crack_from_face_m,bodies,loose_share" }
local every = P.pull / P.frames
local frame = 0
local parted -- the separation at the first frame torn through (two pieces or more)
s:run { until_t = bake + P.pull, every = every, on_frame = function(f)
  local _, _, neck, pieces, nf, tlo, thi, cracked, force, free_cracked, largest, from_face, bodies, loose =
    measure(f.t)
  local sep = separation(f.t)
  if t0 and not parted and pieces >= 2 then parted = sep end
  -- a value not measured (no torn face yet, nothing the pull cracked) is an empty cell, as pancake.csv's (it was
  -- "nan"; #18, helper userview4)
  local function cell(fmt, x) return x == x and fmt:format(x) or "" end
  rows[#rows + 1] = ("%.4f,%.5f,%.5f,%d,%d,%s,%s,%d,%.4g,%.4f,%.4f,%s,%d,%.4f"):format(f.t, sep, neck, pieces, nf,
    cell("%.2f", nf > 0 and tlo or 0 / 0), cell("%.2f", nf > 0 and thi or 0 / 0), cracked, force, free_cracked, largest,
    cell("%.5f", from_face), bodies, loose)
  h.write("tear_open.csv", table.concat(rows, "\n") .. "\n")
  if t0 and f.t >= t0 - 1e-9 then
    if frame % 5 == 0 or f.t >= bake + P.pull - 1e-9 then -- and the pull's last frame, the food torn
      f:png("temperature", "heat_%04d.png", { kind = "particles", label = label })
      f:png("damage", "damage_%04d.png", { kind = "particles", range = { 0, 1 }, label = label })
    end
    frame = frame + 1
  end
end }
s:png("browning", "browning.png", { label = label })
print(("%s%s: %s"):format(P.raw and "raw " or "baked ", P.food, parted and
  ("torn through at %.1f mm of separation"):format(parted * 1e3) or
  ("not torn through after %.1f mm of separation"):format(separation(bake + P.pull) * 1e3)))

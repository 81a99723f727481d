-- Pancake (Ding et al. 2019, Fig. 11): batter poured from a spout that moves
-- across a hot pan (a heated collider: Table 2's conductive theta and beta),
-- cooked from below, then flipped by an event once its bottom has set, i.e.
-- once the bottom's temperature has passed the gelatinisation point of the
-- preset's Fig. 8 curves (lua/hearth/dough.lua, theta_4 = 70 degC), where
-- tau_y jumps x20 for good.
-- The flip: a spatula (a thin heated plate set flush into the pan under the
-- batter) turns half a circle about a pivot beside the pancake, 8 mm above
-- the pan (about the pancake's height), so the pancake is laid upside down
-- next to where it cooked; the spatula is then withdrawn. The turn starts and
-- ends at rest, as a wrist's does (the minimum-jerk profile, Flash & Hogan
-- 1985); --set turn=constant is the old turn, at pi / spin from its first step
-- to its last, which tore the set sheet in two under the spatula (below).
--   hearth run scripts/scenes/baking/pancake.lua [--set dim=3]
--   [--set spatula=sticky|slip|separate] [--set spin=0.5] (s for the half turn) [--set turn=smooth|constant]
--   [--set particles=1] (every particle to particles_%04d.csv each frame)
--   [--set flip_dt=0] (a dt cap during the turn) [--set gas=0.1] [--set porosity=-1]
--   [--set pan=200] (degC) [--set set_at=70] (the bottom temperature that triggers the flip, degC)
--   [--set preset=paper|physical] [--set flip_at=120] (physical: the flip's real time, s) [--set width=800] (px)
-- preset: "paper" (the default: h.library.paper.pancake, Table 2's animation units, 2 s, flipped once the
-- bottom passes set_at) or "physical" (h.library.dough.pancake: a 54% water batter, lua/hearth/dough_physical.lua,
-- with latent heat, boiling and browning on, on a 190 degC griddle under 25 degC air; heat and water run 60
-- times fast, so 3.5 s stand for 3.5 minutes and the frames' titles give the real time; flipped at 2 real
-- minutes, the recipes' time, whatever its bottom reads). The mechanics is not scaled: the pour (0.4 s) spans
-- 24 s of the real heat history and the turn (0.5 s) 30 s.
-- The physical pancake (2D, helper pancake; docs/validation.md "The physical pancake"): at dx 2 mm its middle
-- climbs to 71.1 degC by the flip and (old turn: its torn landing put a 100 degC particle there) holds at 100.0 degC
-- after it while it keeps 0.98 of its water (with today's smooth turn it reaches 80.6-81.9 degC, by the frame count: below); the face on
-- the pan browns 0.180 (fields/browning.c's 0..1) by the flip while the top stays at 0.000; 9.7 mm thick before
-- the flip, and 66% of the batter's water is left at 3.5 min (it boils off the pan faces). At 1.5 mm: 71.0 degC
-- by the flip, 94.1 at the end (0.97 of its water), browning 0.166 / 0.000 (these with the old turn,
-- --set turn=constant; with the smooth turn its middle climbs to 80.6 degC by 3.5 min at 2 mm, 90.2 at 1.5 mm, and
-- its second face browns 0.098 / 0.001, with the old turn 0.0001 / 0.083). Why 80.6-81.9 at 2 mm (helper
-- pancakeheat, docs/validation.md "The pancake's middle at 2 mm"): strands of the raw side drip onto the pan while
-- the sheet hangs, and at 2 mm one lies under the centre line; the set sheet lands on it and stays 1.3 dx above the
-- pan there (the grid couples the two a cell apart: tests/contact/pebble.lua), so the middle heats through that one
-- particle. The paper preset's pancake reads 167.9
-- degC at its pan face and top alike at 2 s (156.8 with the smooth turn). The flipped sheet's raw side drops off
-- the set layer as loose particles while it hangs, so its second face meets the pan unevenly. Not the time
-- mapping's runny batter (its viscosity is
-- 1/60 of the real one) alone: with the real viscosity it lands as ragged. Likely (docs/validation.md, "The
-- physical pancake"): far past its yield stress the plugin's batter flows at ~mu (tau_y / q)^2, ~1% of mu here.
-- Status: the pour, the cooking and the flip work (2D, dx 2 mm: the bottom
-- passes 70 degC at t = 0.58 s, measured at commit 76ac79a; 0.82 s when this
-- was first written; the spatula lifts the pancake ~8 cm and lays
-- it down right of the pivot, where it finishes cooking on its other face).
-- The flip (helper pancakeflip, docs/validation.md "The pancake's flip lands whole"; 2D, dx 2 mm / 1.5 mm): with
-- the smooth turn the sheet stays one piece (1.5 dx links) in every frame and lands whole, no hole, 1.20x / 1.29x
-- its length before the flip. The old turn's jump to 6.3 rad/s in one step, and its dead stop, tore it in two
-- under the spatula at 130-150 degrees (the largest piece 0.54 / 0.52 of the batter); the pieces joined where they
-- landed, 1.48x / 1.69x as long. The set sheet (tau_y 40 Pa, Table 2's 2 Pa x 20) hangs at its limit: rho g h =
-- 29 Pa at its median 5.9 mm, 53 Pa at its thickest folds (10.9 mm; the pour piles a folded ribbon, thickness
-- cv 0.38 before the flip). Left: the landing still stretches it, by 1.20x at 2 mm (1.28x with the pivot 14 mm
-- above the pan instead of 8: not the blade's far end meeting the pan early), and the physical preset's raw side
-- (below 55 degC at 2 minutes) still drips off in strands while it hangs (the largest piece 0.85 at 2 mm, and a
-- hole 3 dx wide in the landed sheet). The turn used to stop (det F <= 0 at ~120 degrees):
-- the core's thermal expansion stress grew as J^2 with the plastic dilation
-- of the warm batter (Cam-clay yields in tension), which fed itself; it now
-- takes the elastic J^E (core/sim/solver/mpm.c). The guard also no longer calls the
-- energy the spatula gives a runaway (core/sim/solver/guard.c).
-- Writes, under hearth-out/pancake/: heat_%04d.png (temperature, the whole box: the flip lifts it ~8 cm), pan_%04d.png
-- (the same frames' close-up on the pancake: 0.12 m of the pan around it, 30 mm high; picture option region) and
-- pancake.csv: over time, the temperature of the pancake's face on the pan and
-- of its top face, whether it has been flipped, and the batter's mean height above the pan and mean x;
-- flip.csv: the flip time and the bottom's temperature then; landed.csv: every particle at the end (the time, id,
-- position, J, temperature; tests/pancake_landed_measure.py reads its pieces and holes). With preset=physical,
-- pancake.csv also has the real time, the middle particle's temperature and the water it holds (of the raw
-- batter's), the browning of the
-- lowest (on the pan) and highest particle on the centre line, and the water left of what was poured; and
-- browning.png (3D: a slab 2 dx thick about the middle plane) and saturation.png at the end (the close-up's region),
-- and profile.csv: the particles within dx/2 of
-- the centre line at the end, from the pan up (height, temperature, water held, browning).
-- An empty cell is "not measured": while no batter lies on the pan at the centre (the pour, the flip) nothing is read
-- on the centre line. tests/baking/scenes.sh (baking_scene_*) reads the next line and accepts empty cells in its
-- columns alone:
-- pancake.csv may leave empty (not measured): bottom_temperature_degC, top_temperature_degC, thickness_m,
--   middle_temperature_degC, middle_water_held, bottom_browning, top_browning
-- flip.csv may leave empty (not measured): bottom_temperature_at_flip_degC
-- Columns that are counts, flags or ratios of the scene's own say no unit (tests/scene_csv.py's unit rule; #18,
-- helper userfix7): flipped is 1 once the spatula has turned the sheet; middle_water_held and water_held the water a
-- particle holds over the raw batter's (saturation x J / the preset's); water_left the pancake's water over the raw
-- batter's.
-- pancake.csv has no unit: flipped, middle_water_held, water_left
-- profile.csv has no unit: water_held
local h = require "hearth"
local THETA_SET = require("hearth.dough").THETA[4] -- gelatinisation, degC
local P = h.params { dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" },
  dx = h.number { 0.002, above = 0, unit = "m", what = "the grid spacing" },
  until_t = h.number { 0, min = 0, unit = "s",
    what = "the run's simulated time (0: the preset's own: paper 2 s, physical its 3.5 real minutes)" },
  frames = h.number { 20, min = 1, integer = true, unit = "frames", what = "PNG frames over the run" },
  width = h.number { 800, min = 64, max = 8192, integer = true, unit = "px",
    what = "the PNG frames' width (the pancake is a quarter of the pan's)" },
  pour = h.number { 0.4, above = 0, unit = "s", what = "the pour's time" },
  spin = h.number { 0.5, above = 0, unit = "s", what = "the spatula's half turn" },
  gas = h.number { 0.1, min = 0, what = "a factor on the batter's CO2 rate" },
  flip_dt = h.number { 0, min = 0, unit = "s", what = "a cap on the time step through the flip (0: none)" },
  -- the material's range of an initial gas porosity: [1e-06, 0.99] (cam_clay_dough)
  porosity = h.number { -1, min = 1e-6, max = 0.99, what = "the batter's initial gas porosity",
    also = { [-1] = "the preset's" } },
  spatula = h.choice("sticky", h.contact_words),
  pan = h.number { -1000, min = -273.15, unit = "degC", what = "the pan's temperature",
    also = { [-1000] = "the preset's (paper 200, physical 190)" } },
  set_at = h.number { THETA_SET, min = -273.15, unit = "degC",
    what = "the bottom's temperature that flips it (preset paper)" },
  flip_at = h.number { 0, min = 0, unit = "s",
    what = "the real time of the flip (preset physical; 0: the preset's 2 min)" },
  particles = h.number { 0, min = 0, max = 1, integer = true,
    what = "1: also every particle (the time, id, position, J, temperature) to particles_%04d.csv at each frame" },
  turn = h.choice { "smooth", smooth = "the spatula's turn starts and ends at rest (a wrist's minimum-jerk turn)",
    constant = "the turn at pi / spin from its first step to its last (the scene before helper pancakeflip)" },
  preset = h.choice { "paper", paper = "h.library.paper.pancake: Ding Table 2, animation units",
    physical = "h.library.dough.pancake: a real batter's properties, its minutes on the griddle mapped" } }
local d3 = P.dim == 3
local dx = h.dx_3d(P.dx, 0.004, d3) -- says so when it raises dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local physical = P.preset == "physical"
local oven = physical and h.library.oven.pancake or h.library.paper_oven.pancake
local S = physical and oven.time_scale or nil -- the physical preset's rates run S times fast: t_real = S t
local until_t = P.until_t > 0 and P.until_t or physical and oven.bake_time or 2
local pan_T = P.pan > -1000 and P.pan or oven.pan_temperature
if P.flip_at > 0 and not physical then
  error("pancake.lua: --set flip_at is the physical preset's (a real time); the paper preset flips at set_at", 0)
end
local flip_real = physical and (P.flip_at > 0 and P.flip_at or oven.flip_time * S) or nil
if physical then
  print(("pancake.lua: h.library.dough.pancake, %s; griddle %g degC, flip at %.1f min, %.1f min in %.2f s")
    :format(oven.units, pan_T, flip_real / 60, until_t * S / 60, until_t))
else
  print("pancake.lua: h.library.paper.pancake, animation units (Ding Table 2): heat runs in seconds, not minutes")
end
local W, PAN, zc = 0.32, 0.01, 0.05         -- m: pan width, pan top height, depth centre (3D)
local X0, X1 = 0.045, 0.105                 -- m: the spout's path
local SPOUT_W, SPOUT_Y, SPEED = 0.008, PAN + 0.025, 0.15 -- m, m, m/s: spout width, exit height, batter speed
local XP, HALF = 0.165, 0.008               -- m: spatula pivot x, its height above the pan (~ the pancake's)
-- the physical preset: the kitchen's air above (its "oven"), latent heat and boiling, browning
local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(W, 0.18, 0.1) }, gravity = v(0, -9.81, 0),
  name = "pancake", oven = physical and { temperature = oven.temperature, beta = oven.beta,
    wall_temperature = oven.wall_temperature, emissivity = oven.emissivity, radiation_scale = oven.radiation_scale } or nil,
  latent_heat = physical and oven.latent_heat or nil, boiling_point = physical and oven.boiling_point or nil,
  browning = physical or nil, browning_scale = physical and oven.browning_scale or nil, time_scale = S,
  time_units = physical and "real" or "animation" }
s:collider { shape = h.box(v(-1, -1, -1), v(W + 1, PAN, 1)), mode = "separate", friction = 0.5,
  temperature = pan_T, beta = oven.pan_beta }
-- the spatula: flush with the pan's top under where the batter lands
-- (sticky: the batter wets it, so the pancake turns over with it and does
-- not slide off first, as it did on a "separate" spatula at 60 degrees)
local spatula = s:collider { shape = h.box(v(0.02, PAN - 0.004, zc - 0.05), v(XP, PAN, zc + 0.05)), mode = P.spatula,
  friction = 1, pivot = v(XP, PAN + HALF, zc), temperature = pan_T, beta = oven.pan_beta }

-- The spout: a row of batter one lattice spacing high leaves it every
-- spacing / SPEED seconds, at the spout's position then (as h.recipes.nozzle,
-- which holds its slot still).
-- Gas x0.1, as the lava cake preset (lua/hearth/dough.lua): at
-- the preset's rate this 2 Pa batter tears while it passes theta_r (the
-- guard stopped the run at t = 0.59 s, kinetic energy x18).
local d = physical and h.library.dough.pancake or h.library.paper.pancake
d.gas_rate = d.gas_rate * P.gas
if P.porosity >= 0 then d.porosity = P.porosity end
local batter = h.material("cam_clay_dough", d)
local ppc = d3 and 8 or 4
local hp = dx / math.floor((d3 and ppc ^ (1 / 3) or math.sqrt(ppc)) + 0.5)
local period = hp / SPEED
for k = 0, math.floor(P.pour / period) - 1 do
  local t = k * period
  s:at(t, function(sc)
    local x = X0 + (X1 - X0) * t / P.pour
    local y = math.floor(SPOUT_Y / hp + 0.5) * hp
    sc:add { shape = h.box(v(x - SPOUT_W / 2, y, zc - SPOUT_W / 2), v(x + SPOUT_W / 2, y + hp, zc + SPOUT_W / 2)),
      material = batter, temperature = oven.dough_temperature, ppc = ppc, jitter = 0, velocity = v(0, -SPEED, 0) }
  end)
end

-- the pancake's faces at x: its top along a vertical density line, and the
-- temperatures 0.75 dx inside the bottom and the top face
local flipped, flip_t, flip_T = false, nil, nil
local function centre() return flipped and 2 * XP - (X0 + X1) / 2 or (X0 + X1) / 2 end
local function faces()
  local x, n = centre(), 400
  local d = s:line("density", v(x, PAN, zc), v(x, PAN + 0.04, zc), n + 1)
  local lo, hi
  for k, val in ipairs(d) do if val == val then lo = lo or k; hi = k end end
  if not lo then return 0 / 0, 0 / 0, 0 end
  local ylo, yhi = PAN + (lo - 1) * 0.04 / n, PAN + (hi - 1) * 0.04 / n
  return s:probe("temperature", v(x, ylo + 0.75 * dx, zc)), s:probe("temperature", v(x, yhi - 0.75 * dx, zc)), yhi - ylo
end

-- the flip event: checked every 10 ms once the pour is over
local TURN_STEPS = 100 -- the smooth turn's rate is set this many times
-- the frames' title (s:run below): the pan, whether the pancake was flipped, and the paper preset's units
local png
local function pan_label()
  return ("pancake on a %g °C pan%s%s"):format(pan_T, flipped and ", flipped" or "",
    physical and "" or "; Table 2's animation units")
end
local function flip(sc)
  flipped, flip_t = true, sc:stats().t
  if png then png.label = pan_label() end
  if P.flip_dt > 0 then sc:set_dt(nil, P.flip_dt) end
  h.write("flip.csv", ("flip_time_s,bottom_temperature_at_flip_degC\n%.3f,%s\n"):format(flip_t,
    flip_T and ("%.2f"):format(flip_T) or ""))
  local function omega(w) return d3 and { 0, 0, -w } or -w end
  if P.turn == "constant" then
    sc:collider_velocity(spatula, v(0, 0, 0), omega(math.pi / P.spin))
  else
    -- a wrist's turn: the minimum-jerk profile of a human point-to-point movement (Flash & Hogan 1985, J.
    -- Neurosci. 5:1688, eq. 2), theta(s) = pi (10 s^3 - 15 s^4 + 6 s^5) over s = (t - flip_t) / spin, from rest
    -- to rest; the old turn jumped to pi / spin in one step and stopped dead. Set every TURN_STEPS-th of the turn
    -- to the mean rate over that part, so the turn is exactly half a circle.
    local function theta(x) return math.pi * x ^ 3 * (10 - 15 * x + 6 * x * x) end
    for k = 0, TURN_STEPS - 1 do
      sc:at(flip_t + k * P.spin / TURN_STEPS, function(sc2)
        sc2:collider_velocity(spatula, v(0, 0, 0),
          omega((theta((k + 1) / TURN_STEPS) - theta(k / TURN_STEPS)) * TURN_STEPS / P.spin))
      end)
    end
  end
  -- turned over, the pancake hangs under the spatula just above the pan;
  -- the spatula is then withdrawn at once (moved out of the scene), and the
  -- pancake drops the last few millimetres onto its uncooked face
  sc:at(flip_t + P.spin, function(sc2)
    sc2:collider_velocity(spatula, v(0, 0, 0), 0)
    sc2:move(spatula, v(0, 1, 0))
  end)
end
local function watch(sc)
  local bottom = faces()
  if physical and sc:stats().t * S >= flip_real - 1e-9 then -- the physical preset flips at the recipe's time
    flip_T = bottom == bottom and bottom or nil -- flip.csv's cell is then empty: not measured
    flip(sc)
  elseif not physical and bottom == bottom and bottom > P.set_at then
    flip_T = bottom
    flip(sc)
  else
    sc:at(sc:stats().t + 0.01, watch)
  end
end
s:at(P.pour + 0.05, watch)

-- where the batter is: its mean height above the pan and mean x (the flip
-- lifts it, then lays it down right of the pivot)
local function mean_place()
  local X, sx, sy, n = s:positions(), 0, 0, 0
  for k = 1, #X, 3 do sx, sy, n = sx + X[k], sy + X[k + 1], n + 1 end
  if n == 0 then return 0 / 0, 0 / 0 end
  return sy / n - PAN, sx / n
end
-- the physical preset's inside, from particle values (a probe is the grid's B-spline average over three cells,
-- about the whole pancake's thickness): the particles within dx/2 of the centre line, the lowest (the pan face), the
-- highest (the top) and the one nearest the middle of the two; the middle's water held as a fraction of the raw
-- batter's (saturation x J over the preset's saturation, as muffins.lua's); their browning (fields/browning.c's 0..1)
local function inside()
  local r = s:particles { fields = { "x", "temperature", "saturation", "J", "browning" } }
  local x, lo, hi = centre(), nil, nil
  for k = 1, r.n do
    local px, py = r.x[3 * k - 2], r.x[3 * k - 1]
    if py > PAN and math.abs(px - x) < dx / 2 then
      if not lo or py < r.x[3 * lo - 1] then lo = k end
      if not hi or py > r.x[3 * hi - 1] then hi = k end
    end
  end
  if not lo then return nil end
  local ym, mid, dm = (r.x[3 * lo - 1] + r.x[3 * hi - 1]) / 2, nil, math.huge
  for k = 1, r.n do
    local dd = math.abs(r.x[3 * k - 2] - x) + math.abs(r.x[3 * k - 1] - ym)
    if r.x[3 * k - 1] > PAN and dd < dm then mid, dm = k, dd end
  end
  return { T = r.temperature[mid], held = r.saturation[mid] * r.J[mid] / oven.saturation,
    bottom_browning = r.browning[lo], top_browning = r.browning[hi], n = r.n }
end
-- the water left: the water the batter holds now over what the poured particles brought (each lattice particle's
-- volume hp^dim at the preset's saturation, 1000 kg/m^3 of water per unit saturation)
local function water_left(n) return s:stats().water_mass / (n * hp ^ (d3 and 3 or 2) * 1000 * oven.saturation) end

-- every particle (the time, its id, position, J, temperature) to a CSV: landed.csv at the end, for measuring the
-- landed sheet (tests/pancake_landed_measure.py: its pieces and holes), and with --set particles=1 particles_%04d.csv
-- each frame
local function write_particles(path)
  local r = s:particles { fields = { "id", "x", "J", "temperature" } }
  local lines, t = { "t_s,id,x_m,y_m,z_m,J,temperature_degC" }, s:stats().t
  for k = 1, r.n do
    lines[#lines + 1] = ("%.4f,%d,%.6f,%.6f,%.6f,%.5f,%.2f"):format(t, r.id[k], r.x[3 * k - 2], r.x[3 * k - 1],
      r.x[3 * k], r.J[k], r.temperature[k])
  end
  h.write(path, table.concat(lines, "\n") .. "\n")
end

local head = "t_s,bottom_temperature_degC,top_temperature_degC,thickness_m,flipped,mean_height_m,mean_x_m"
if physical then
  head = head .. ",t_real_s,middle_temperature_degC,middle_water_held,bottom_browning,top_browning,water_left"
end
local rows = { head }
-- the close-up (#18, helper userfix5; userview3's item 7: in the whole 0.32 x 0.18 m box a 10 mm pancake is 19 px
-- thick and its particles 2 px, a sliver): 0.12 m of the pan around the pancake (the landed sheet is ~9 cm long),
-- from 6 mm below the pan's face to 24 mm above it, about 5 px a millimetre at the default width; on the far side of
-- the pivot once flipped
local function close_region()
  local x = centre()
  return { { x - 0.06, PAN - 0.006 }, { x + 0.06, PAN + 0.024 } }
end
-- the title names the pan and, once turned, says so (#18, helper userview3: a frame said only its time, and the
-- paper preset's seconds are Table 2's animation units); the flip event turns it
png = { field = "temperature", path = "heat_%04d.png", time_scale = S, width = P.width,
  label = pan_label() }
s:run { until_t = until_t, every = until_t / P.frames, png = png,
  on_frame = function(f)
    if P.particles == 1 then write_particles(("particles_%04d.csv"):format(f.index)) end
    f:png("temperature", "pan_%04d.png", { kind = "particles", time_scale = S, width = P.width, label = pan_label(),
      region = close_region() })
    local bt, tt, th = faces()
    local my, mx = mean_place()
    if my == my then
      -- while no batter lies on the pan at the centre (the pour, mid-flip) the centre line's cells are empty: "not
      -- measured" (the header's list; -1 had read as a temperature, helper userview3's item 3)
      local ok = bt == bt and tt == tt
      local row = ("%.3f,%s,%s,%s,%d,%.5f,%.5f"):format(f.t, ok and ("%.2f"):format(bt) or "",
        ok and ("%.2f"):format(tt) or "", ok and ("%.5f"):format(th) or "", flipped and 1 or 0, my, mx)
      if physical then
        local m = ok and inside()
        row = row .. (m and (",%.1f,%.2f,%.4f,%.4f,%.4f"):format(f.t * S, m.T, m.held, m.bottom_browning,
          m.top_browning) or (",%.1f,,,,"):format(f.t * S))
          .. (",%.4f"):format(water_left(s:stats().particles)) -- the whole batter's, whatever lies at the centre
      end
      rows[#rows + 1] = row
      h.write("pancake.csv", table.concat(rows, "\n") .. "\n")
    end
  end }
local bt, tt, th = faces()
write_particles("landed.csv")
if physical then
  -- the profile through the pancake at the end: each particle within dx/2 of the centre line, from the pan up
  local r, prof = s:particles { fields = { "x", "temperature", "saturation", "J", "browning" } }, {}
  for k = 1, r.n do
    local px, py = r.x[3 * k - 2], r.x[3 * k - 1]
    if py > PAN and math.abs(px - centre()) < dx / 2 then
      prof[#prof + 1] = { py - PAN, r.temperature[k], r.saturation[k] * r.J[k] / oven.saturation, r.browning[k] }
    end
  end
  table.sort(prof, function(a, b) return a[1] < b[1] end)
  local lines = { "height_m,temperature_degC,water_held,browning" }
  for _, q in ipairs(prof) do lines[#lines + 1] = ("%.5f,%.2f,%.4f,%.4f"):format(table.unpack(q)) end
  h.write("profile.csv", table.concat(lines, "\n") .. "\n")
  s:png("browning", "browning.png",
    { time_scale = S, width = P.width, label = pan_label(), region = close_region() })
  s:png("saturation", "saturation.png",
    { time_scale = S, width = P.width, label = pan_label(), region = close_region() })
  local m = inside()
  print(((flip_t and ("flipped at %.1f min (t = %.3f s)"):format(flip_t * S / 60, flip_t) or "not flipped yet")
    .. "; after %.1f min: face on the pan %.1f degC, top %.1f degC (probes), middle "
    .. "%.1f degC holding %.2f of its water, browning pan face %.3f, top %.3f; thickness %.1f mm; %.1f%% of the water "
    .. "left"):format(s:stats().t * S / 60, bt, tt,
    m and m.T or 0 / 0, m and m.held or 0 / 0, m and m.bottom_browning or 0 / 0, m and m.top_browning or 0 / 0,
    1000 * th, m and 100 * water_left(m.n) or 0 / 0))
  return
end
print(flip_t and ("flipped at t = %.3f s (bottom %.1f degC > %g degC); at the end: face on the pan %.1f degC, "
  .. "top %.1f degC, "
  .. "thickness %.4f m"):format(flip_t, flip_T, P.set_at, bt, tt, th) or "not flipped yet (the bottom has not set)")

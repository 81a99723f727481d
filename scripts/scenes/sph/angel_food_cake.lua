-- Angel food cake baked, then left in its pan to collapse, with the SPH solver
-- (Rodriguez-Arenas 2011 Fig. 4.11).
--   hearth run scripts/scenes/sph/angel_food_cake.lua [--set bake=1.5 --set cool_to=25 --set bubble_share=0.4]
--     [--set xsph_cool=0.05 --set xsph_hot=0.3 --set water_activity=0.94 --set water=false]
-- A 2D section through a tube pan: batter on both sides of the central tube,
-- between the pan's walls. A share of its particles are bubble particles
-- (eq. 3.48-3.50; whisked egg white holds many). In the oven (oven, degC)
-- heat enters at the surface (eq. 3.42) and diffuses (eq. 3.45), and the
-- bubbles grow with their gas: an angel food cake rises on steam, its foam's
-- air cells expanded by the batter's water vapour as it nears its boiling
-- point ("cake expansion increases with increasing temperature of the batter
-- according to the gas laws and with increasing water vapor pressure from
-- the liquid", Matz 1992, Bakery Technology and Engineering; steam leavens as
-- the moisture heats, Gisslen, Professional Baking). So each bubble's rest
-- volume is its air's and steam's (sph.gas_law with sph.bubble_vapour = the
-- batter's water activity: eq. 3.49-3.50 in Kelvin with the thesis's eq.
-- 2.42-2.43, Fan et al.'s bubble), up to sph.bubble_vmax (4) where the cells
-- open; an open cell holds the oven's air and keeps its volume as it cools
-- (sph.bubble_stays_open). water_activity = 0.94: Norrish's equation (1966, J. Food Technol. 1:25,
-- K = 6.47 for sucrose) for the sugar syrup of a standard angel food batter
-- (12 egg whites, 360 g at 87.6% water (USDA SR egg white, raw), 298 g sugar,
-- 120 g cake flour at 14% moisture: 2.62 mol sucrose per kg of water); any
-- a_w from 0.85 to 0.95 brings a bubble to the cap between 92 and 95 degC
-- (0.85 rose 1.687x, 0.94 1.692x). water_activity = 0 is the thesis's dry
-- eq. 3.51, then eq. 3.52's kept density (the batter keeps the volume it
-- reached), which read in Kelvin grows a bubble only by T / T0 (1.48 at 170
-- degC): the thesis's own T / T0 is in degC (Table 4.1's 26 degC), 6.9 at 180.
-- At t = bake the cake comes out and is left upright in its pan (cool_to,
-- degC): the temperature falls, the steam in the cells still closed
-- condenses and their air contracts, and the structure, which only sets
-- while hot here (mu_e and viscosity follow the temperature through
-- h.curve), gives way. The thesis does the
-- same by hand (§4.5: rho_f raised, mu_e and lambda lowered after baking);
-- turning the pan over is what a baker does to stop it, not modelled.
-- Measured with the batter's water (the default since #18 helper sphcrumb, WATER below; docs/validation.md "The
-- angel food cake's crumb holds its water"): relative volume at its highest in the oven and at t = 3.5 s 1.688 and
-- 1.563 at dx 3 mm, 1.742 and 1.581 at 2 mm; as the bake ends the crumb band is 102.6 degC (101.0 at 2 mm), browned
-- 0.0058 (0.0073) and holds 0.78 (0.68) of its water, under a top band at 139 degC (142) browned 0.29 (0.36) and an
-- outer surface browned 0.34 (0.38) (claim_sph_angel_cake_crumb_pale[_fine]; the outer particles read at their
-- face's temperature, the oven's flux through the film since helper sphflux: before it 1.694 / 1.548, crumb 0.0074,
-- top band 0.34, outer 0.41 at 3 mm). The rest of
-- this note was measured without the water (--set water=false, the same bits as before it).
-- Measured (2D, #18 helper angelsteam, docs/validation.md "The angel food cake
-- rises on its steam"): relative volume (density slice) at its highest in the oven
-- and at t = 3.5 s: 1.692 and 1.526 at dx 3 mm, 1.743 and 1.604 at 2 mm (at 3 mm the
-- highest is at 0.5 s, 13 minutes in; the cake leaves the oven at 1.638)
-- (claim_sph_angel_cake_rises[_fine]: rises past 1.3x, loses part of it and
-- keeps part, no bubble past its gas, each side one piece: a bubble spot's
-- particles in the middle of the cavity their steam opened are its gas,
-- each as wide as its volume, helper angelpieces; no batter tears off).
-- With the cells closed as they cool, 1.692 / 0.902 and 1.743 / 0.884: the
-- cake fell below its batter. Dry (water_activity = 0): 1.205 and 0.993 at 3 mm,
-- 1.193 and 0.961 at 2 mm. The crumb stays the coolest band while it bakes
-- (bands.csv at 0.5 s: 106 degC against the top's 137 and the bottom's 123 at
-- 3 mm, 111 / 139 / 130 at 2 mm; dry 114 / 126 / 125, 116 / 128 / 126; with the
-- batter's water 95.0 / 102.0 / 101.3 and 94.9 / 102.6 / 100.5). Without water
-- no boiling plateau holds the crumb near 100 degC: the whole cake passes 150
-- degC by 1 s and browns (the crumb band 0.54 as the bake ends, at 166 degC). History of the dry cake: eq. 3.51
-- pushing for as long as a bubble heated (before sph.c's bubble_expands)
-- gave 2.33 and 1.87; with the oven's heat at the colour field's surface
-- particles (before sph_outer.c) 2.25 and 2.00; with the old asymmetric seed
-- 2.22 and 1.95, the right half 13.7 degC hotter than the left at 1 s;
-- before the time step counted the stiffness eq. 3.52 gives the batter
-- (sph.c, signal_speed) 2.05 and 1.61 and it needed the hot crust's larger
-- XSPH epsilon to stay stable (xsph_hot); with the printed form's heat (6e8,
-- 0.3x this) 1.95 and 1.72.
-- Writes volume.csv (relative volume over time, from a density slice, with
-- the mean temperature, and the mean temperatures of the particles left and
-- right of the tube's axis and their difference), bands.csv (the mean
-- temperatures of the top, crumb and bottom bands away from the pan's walls,
-- sph_cake_crumb_coolest, their batter's browning, the crumb band's saturation
-- and the outer surface's browning and saturation; both CSVs by simulated time t_s (s; named t before helper
-- userfix5) and, last, t_real_min, the frames' real minutes), particles_raw.csv, particles_baked.csv and
-- particles_end.csv (the particles after the first step, as the bake ends and
-- at until_t: tests/sph_cake_rise.py; a bubble's browning is an empty cell, #18 helper userfix10, where it had been
-- `nan`: it is gas) and browning and
-- temperature frames (the browning index of Zanoni et al. 1995 from
-- temperature history; browning_scale = 1600 lets the 1.5 s bake stand for
-- 40 minutes).
-- Heat: eq. 3.42 per unit area of surface (core/sim/solver/sph_heat.c),
-- k_h,ext = S h / c from a physical oven: h = 30 W/(m^2 K) (Baik et al. 1999,
-- J. Food Sci. 64:688: 20-48 W/(m^2 K) with radiation), c = 2800 J/(kg K) (a
-- cake batter, Choi & Okos; h.library.dough.muffin's) and S = 1600
-- (browning_scale): 1600 x 30 / 2800 = 17.1 kg/(m^2 s). (The thesis's printed
-- form had 6e8, 5.2 in these units at dx 3 mm and falling as dx^3.)
-- Units: viscosity and mu_e are scaled from Table 4.1 (animation units) as in
-- bread_roll.lua, so the 2D default runs in well under a minute.
-- Columns without a unit (tests/scene_csv.py's unit rule; #18, helper userfix7): phase, a word (baking or
-- cooling); bands.csv's B_* the bands' mean browning index and S_* their batter's mean saturation.
-- volume.csv has no unit: phase
-- bands.csv has no unit: B_top, B_crumb, B_bottom, S_crumb, B_outer, S_outer
-- particles_raw.csv may leave empty (not measured): browning
-- particles_baked.csv may leave empty (not measured): browning
-- particles_end.csv may leave empty (not measured): browning
local h = require "hearth"
-- oven: above the batter's 26 degC start (the bake heats it; the temperature frames span the two); foam: V_b0 of eq.
-- 3.50 in maxwell_sph's range [0, 100]; bubble_share: discs of 4 mm on a square pitch touch at pi / 4 (--set
-- bubble_share=0 had left no spots, and h.union's raw Lua error was all a user saw)
local P = h.params { dx = h.number { 0.003, above = 0, unit = "m", what = "the grid spacing" },
  oven = h.number { 180, above = 26, max = 5000, unit = "degC",
    what = "the oven's temperature, above the batter's 26 degC" },
  cool_to = h.number { 25, min = -273.15, max = 5000, unit = "degC", what = "the air it cools in after the bake" },
  -- simulated seconds, each 26.7 real minutes (S = 1600, below): --params had not said so, only the run's first line
  bake = h.number { 1.5, min = 0, unit = "s", what = "the bake's simulated time before it cools (1 s: 26.7 real min)" },
  until_t = h.number { 3.5, min = 0, unit = "s",
    what = "the run's simulated time (1 s: 26.7 real min; 0: the set-up alone, measured)" },
  bubble_share = h.number { 0.4, above = 0, max = math.pi / 4,
    what = "the share of the batter seeded as bubble particles" },
  foam = h.number { 1.0, min = 0, max = 100, what = "the batter's initial bubble volume V_b0 (eq. 3.50)" },
  xsph_cool = h.number { 0.05, min = 0, max = 1, what = "XSPH's epsilon in the cool batter (h.scene's range)" },
  xsph_hot = h.number { 0.3, min = 0, max = 1, what = "XSPH's epsilon in the hot batter (h.scene's range)" },
  water_activity = h.number { 0.94, min = 0, max = 0.99,
    what = "the batter's water activity a_w: its steam joins the bubbles' air (sph.gas_law, eq. 2.42-2.43; 0: the "
      .. "thesis's dry eq. 3.51-3.52)" },
  -- the batter's water (WATER below): true carries it, with latent_heat and boiling at 100 degC; false is the batter
  -- before #18 helper sphcrumb, which held none
  water = h.flag { true, what = "the batter carries its water: latent heat, boiling at 100 degC (false: the dry batter)" } }
-- what a run's seconds stand for (S = 1600, the scene's browning_scale and its heat_ext, below)
print(("angel_food_cake.lua: viscosity and mu_e scaled from Table 4.1's animation units; heat and browning 1600 times fast: "
  .. "the %g s bake stands for %.0f min, 1 s for %.1f min"):format(P.bake, P.bake * 1600 / 60, 1600 / 60))

local T0 = 26
-- The pan is mirror symmetric about x = 0.1 m, and its particles must be too
-- or the halves heat differently (#18: the right half ran 13.7 degC hotter
-- at 1 s, 6.5 degC at 0.1 s). The seeding lattice starts at the box's low
-- corner, (i + 1/2) dx, so it is its own mirror image about the box's centre
-- only when the box is a whole number of dx wide: the box is widened to
-- that about x = 0.1 (0.2 m was 66.7 spacings at dx 3 mm, which put the
-- left half's particles 1 mm further from the outer wall and 1 mm nearer
-- the tube than the right half's).
local cx = 0.1
local half = math.ceil(0.2 / P.dx - 1e-9) * P.dx / 2
local s = h.scene { dim = 2, dx = P.dx, box = { { cx - half, 0 }, { cx + half, 0.12 } }, solver = "sph",
  sph = { heat_ext = 17.1, heat_int = 0.5, av_beta = 1, xsph0 = P.xsph_cool, xsph_f = P.xsph_hot, xsph_T0 = T0, xsph_Tf = 120,
          bubble_T0 = T0, tension = true, alpha_c = 0.1, beta_c = 0.8,
          gas_law = P.water_activity > 0, bubble_vapour = P.water_activity, bubble_stays_open = P.water_activity > 0 },
  oven = { temperature = P.oven, beta = 0, radiation_scale = 1600 }, browning = true, browning_scale = 1600,
  latent_heat = P.water or nil, boiling_point = P.water and 100 or nil, time_scale = 1600 }

-- The crumb sets while hot and softens again as it cools (the structure of
-- an angel food cake left upright is not set enough to hold).
local props = {
  density = 600, bulk = 2e4, lambda = 0.5,
  viscosity = h.curve { { T0, 2 }, { 80, 4 }, { 110, 10 } },
  mu_e = h.curve { { T0, 20 }, { 80, 60 }, { 110, 1000 } },
}
-- WATER (#18, helper sphcrumb): the batter's water, as bread_roll.lua's --set crust=true gives its dough the
-- bread's. The recipe above (360 g egg white at 87.6% water, USDA SR; 298 g sugar; 120 g cake flour at 14%) holds
-- 332 g of water in 778 g, 42.7% wet basis; at the batter's 600 kg/m^3 that is s = 0.427 x 600 / 1000 = 0.256 of
-- rho_0^w (Ding et al. eq. 8). Its liquid diffusivity 2e-9 m^2/s and surface evaporation 1.2e-5 are the roll's
-- (h.library.dough.bread's, chosen within baking models' range: lua/hearth/dough_physical.lua), on this scene's
-- S = 1600; eq. 22's D = K theta s gives K = D / (373.15 s). Heat capacity by the mixture rule the roll's bread takes
-- (m c = m_s c_s + m_w c_w; Choi & Okos 1986 at 25 degC, the ASHRAE composition model), with the recipe's solids
-- (USDA SR egg white and cake flour: 88% carbohydrate, 11% protein, 0.4% fat, 0.6% ash of the solids):
-- c_s = 1641 J/(kg K); wet 2724 (2800 taken, the c the oven's heat_ext above is written with, 3% above, as the
-- bread's 2.7 against its 2.79), dried (m_s / m) c_s = 0.573 x 1641 = 941. Conductivity by the same model's
-- volume-weighted parallel sum (the ASHRAE rule the lava cake and pancake presets use) at this density: 0.222
-- W/(m K) wet, 0.071 with the water's volume turned to air (the dried particle keeps its volume): SPH's conduction
-- takes only their ratio, 0.32, on sph.heat_int (core/sim/solver/sph_heat.c). The bubbles share the batter's
-- parameters but hold no water (sph_water.c: a bubble is gas) and read as wet, so they conduct and hold heat as
-- before. Boiling at 100 degC, as the roll: the batter's 2.62 mol/kg of sucrose would raise it by 0.512 x 2.62 =
-- 1.3 K (ebullioscopy, ideal), not taken.
if P.water then
  local g, S, s0 = require("hearth.dough_physical").goods.bread, 1600, 0.256 -- the roll's bread: its D and evaporation
  props.saturation, props.water_diffusivity = s0, g.water_diffusivity_m2s / (373.15 * s0) * S
  props.evaporation = g.evaporation * S
  props.specific_heat, props.dry_specific_heat = 2800, 0.573 * 1641
  props.conductivity, props.dry_conductivity = 0.222, 0.071
end
local batter = h.material("maxwell_sph", props)
props.bubble = P.foam -- V_b0 of eq. 3.50 (the thesis sets 1; above about 1.3 the batter bursts at once)
local bubble = h.material("maxwell_sph", props)

-- the pan: floor, two outer walls and the central tube (slip; the thesis's
-- collider response, eq. 3.33)
local floor_y, top0 = 0.01, 0.045
s:collider { shape = h.plane({ 0, floor_y }, { 0, 1 }), mode = "slip" }
s:collider { shape = h.plane({ 0.02, 0 }, { 1, 0 }), mode = "slip" }
s:collider { shape = h.plane({ 0.18, 0 }, { -1, 0 }), mode = "slip" }
s:collider { shape = h.box({ 0.092, 0 }, { 0.108, 0.11 }), mode = "slip" }

-- batter on both sides of the tube; bubble particles in a regular pattern of
-- small discs through it (their share set by bubble_share), laid from each
-- outer wall inward so that the right side's are the left side's mirror
-- image (one pattern across the pan, 0.16 m = 14.3 pitches, left the right
-- wall's last column of spots cut and the tube's sides in different places
-- of the pattern)
local function side(x0, x1)
  return h.box({ x0, floor_y }, { x1, top0 })
end
local cake = h.union(side(0.02, 0.092), side(0.108, 0.18))
local spots, r = {}, 0.004
-- the discs of radius r on a square pitch hold pi r^2 / pitch^2 of the batter: at most pi / 4, where they touch
-- (bubble_share's range, h.params above)
local pitch = r * math.sqrt(math.pi / P.bubble_share)
for y = floor_y + pitch / 2, top0, pitch do
  for x = 0.02 + pitch / 2, cx, pitch do
    spots[#spots + 1] = h.disc({ x, y }, r)
    spots[#spots + 1] = h.disc({ 2 * cx - x, y }, r)
  end
end
local gas = h.union(table.unpack(spots))
s:add { shape = h.difference(cake, gas), material = batter, ppc = 1, jitter = 0, temperature = T0 }
s:add { shape = h.intersection(cake, gas), material = bubble, ppc = 1, jitter = 0, temperature = T0 }

-- relative volume: area of the material in a density slice (NaN is outside)
local res = { 200, 120 }
local function area()
  local rows = s:slice("density", { res = res })
  local n = 0
  for _, row in ipairs(rows) do for _, v in ipairs(row) do if v == v then n = n + 1 end end end
  return n * (2 * half / res[1]) * (0.12 / res[2])
end
local function mean_T()
  local T = s:slice("temperature", { res = { 50, 30 } })
  local sum, n = 0, 0
  for _, row in ipairs(T) do for _, v in ipairs(row) do if v == v then sum, n = sum + v, n + 1 end end end
  return n > 0 and sum / n or 0 / 0
end
-- mean temperature of the particles left and right of the pan's centre: a
-- symmetric pan heats both alike, to round-off (sph_cake_heats_mirror_symmetric)
local function halves_T()
  local p = s:particles { fields = { "x", "temperature" } }
  local sl, nl, sr, nr = 0, 0, 0, 0
  for i = 1, p.n do
    local T = p.temperature[i]
    if p.x[3 * i - 2] < cx then sl, nl = sl + T, nl + 1 else sr, nr = sr + T, nr + 1 end
  end
  return sl / nl, sr / nr
end
-- mean temperatures of three bands of the cake (#18: the crumb had run hotter than its crust, eq. 3.42's oven
-- heat entering rows inside the risen cake): the particles at least 10 mm from the pan's walls and tube, the
-- bottom band within 10 mm of the floor, the top band within 10 mm of the highest of them, the crumb band 10 mm
-- about their middle height (sph_cake_crumb_coolest); and the batter's (the bubbles are gas: NaN) mean browning
-- in each band, its mean saturation in the crumb band, and the mean browning and saturation of the batter on
-- the outer surface, where the oven's heat enters (the boundary flag, sph_outer.c; with water off its saturation
-- is NaN) (claim_sph_angel_cake_crumb_pale)
local function bands_T()
  local fields = { "x", "temperature", "browning", "boundary" }
  if P.water then fields[#fields + 1] = "saturation" end
  local p = s:particles { fields = fields }
  local inner, ytop = {}, floor_y
  local bo, so, no = 0, 0, 0
  for i = 1, p.n do
    local x, y = p.x[3 * i - 2], p.x[3 * i - 1]
    local d = math.min(math.abs(x - 0.02), math.abs(x - 0.18), math.abs(x - 0.092), math.abs(x - 0.108))
    if d >= 0.01 and (x < 0.092 or x > 0.108) then
      inner[#inner + 1] = i
      ytop = math.max(ytop, y)
    end
    local b = p.browning[i]
    if p.boundary[i] > 0 and b == b then
      bo, so, no = bo + b, so + (P.water and p.saturation[i] or 0 / 0), no + 1
    end
  end
  local mid, sum, cnt = 0.5 * (floor_y + ytop), { 0, 0, 0 }, { 0, 0, 0 }
  local bsum, bcnt, ssum = { 0, 0, 0 }, { 0, 0, 0 }, 0
  for _, i in ipairs(inner) do
    local y, T = p.x[3 * i - 1], p.temperature[i]
    local b = (y > ytop - 0.01 and 1) or (math.abs(y - mid) < 0.005 and 2) or (y < floor_y + 0.01 and 3) or nil
    if b then
      sum[b], cnt[b] = sum[b] + T, cnt[b] + 1
      local br = p.browning[i]
      if br == br then
        bsum[b], bcnt[b] = bsum[b] + br, bcnt[b] + 1
        if b == 2 then ssum = ssum + (P.water and p.saturation[i] or 0 / 0) end
      end
    end
  end
  return { T = { sum[1] / cnt[1], sum[2] / cnt[2], sum[3] / cnt[3] }, top = ytop,
           B = { bsum[1] / bcnt[1], bsum[2] / bcnt[2], bsum[3] / bcnt[3] }, S_crumb = ssum / bcnt[2],
           B_outer = bo / no, S_outer = so / no }
end
-- particle positions (x_m, y_m), temperatures (T_degC), own volumes J = det F, browning (NaN: a bubble particle), the
-- summed density, the pressure and the particle's id (SPH sorts its particles, so the rows' order changes: the
-- id follows a bubble from the bake's end to the cooled cake), for measures that do not go through the density
-- field (tests/sph_cake_rise.py: pieces, bubbles against their gas)
local function positions(path)
  local r = s:particles { fields = { "x", "temperature", "J", "browning", "density", "pressure", "id" } }
  local rows = { "x_m,y_m,T_degC,J,browning,density_kg_m3,pressure_Pa,id" }
  for i = 1, r.n do
    rows[#rows + 1] = ("%.6g,%.6g,%.3f,%.5g,%.4g,%.5g,%.5g,%d"):format(r.x[3 * i - 2], r.x[3 * i - 1],
      r.temperature[i], r.J[i], r.browning[i], r.density[i], r.pressure[i], r.id[i])
  end
  h.write(path, table.concat(rows, "\n") .. "\n")
end
s:step(1) -- the density slice needs one SPH step (before it the probe has no SPH density)
positions("particles_raw.csv")
local A0 = area()
-- t is the simulated time (s); t_real_min, last, the real minutes the frames' titles give (S = 1600): the CSVs had
-- the one clock and the frames the other (#18, helper userview3)
local csv = { "t_s,relative_volume,mean_temperature_degC,phase,T_left_degC,T_right_degC,T_right_minus_left_degC,t_real_min" }
local bands = { "t_s,T_top_degC,T_crumb_degC,T_bottom_degC,top_mm,B_top,B_crumb,B_bottom,S_crumb,B_outer,S_outer,t_real_min" }
local cooling, peak, peak_t, baked, baked_b = false, 1, 0, nil, nil
-- the frames' titles give the real time the scene's S = 1600 stands for, then the simulated seconds; browning
-- is drawn as a slice, as the temperature is: as particles, the bubbles (gas, no browning: NaN) drew as
-- dark grey discs, which on the browning map read as burnt spots through the crumb
-- The label says whether the cake is in the oven or cooling in its pan (#18, helper userview3: the cooling frames,
-- 26-93 min, read like the bake's); the run's browning frame is drawn before on_frame, the temperature frame in it,
-- both with the label of the state the frame shows, then the label turns when the cake comes out.
local png = { field = "browning", path = "frames/browning_%04d.png", time_scale = 1600, kind = "slice",
  label = ("angel food cake in the oven, %g °C"):format(P.oven) }
local function out_of_oven()
  png.label = ("angel food cake out of the oven, cooling at %g °C"):format(P.cool_to)
  positions("particles_baked.csv") -- the cake as it leaves the oven
  s:oven(P.cool_to, 0) -- out of the oven, left upright in its pan
  cooling = true
end
-- The cake comes out at the first frame at or past the bake (frames every 0.1 s from the first step's end). A run
-- whose frames end before that frame (--set bake=0.02 --set until_t=0.04) takes it out at the bake itself, where it
-- had stayed in the oven to the end and its line said "still in the oven" (#18, helpers userview4, userfix8);
-- the runs whose frames reach the bake keep their steps and bits.
local t0 = s:stats().t
if t0 + math.max(0, math.ceil((P.bake - 1e-9 - t0) / 0.1)) * 0.1 > P.until_t + 1e-9 then
  s:at(P.bake, function()
    out_of_oven()
    baked, baked_b = area() / A0, bands_T() -- the cake as the bake ends, where no frame falls
  end)
end
s:run { until_t = P.until_t, every = 0.1, png = png,
  on_frame = function(f)
    local label = png.label
    if not cooling and f.t >= P.bake - 1e-9 then out_of_oven() end
    local rv = area() / A0
    if not cooling and rv > peak then peak, peak_t = rv, f.t end
    local b = bands_T()
    if cooling and not baked then baked, baked_b = rv, b end -- the first frame out of the oven: the cake as the bake ends
    local TL, TR = halves_T()
    csv[#csv + 1] = ("%.4f,%.5f,%.2f,%s,%.4f,%.4f,%.3g,%.2f"):format(f.t, rv, mean_T(), cooling and "cooling" or "baking",
      TL, TR, TR - TL, f.t * 1600 / 60)
    h.write("volume.csv", table.concat(csv, "\n") .. "\n")
    bands[#bands + 1] = ("%.4f,%.3f,%.3f,%.3f,%.1f,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.2f"):format(f.t, b.T[1], b.T[2], b.T[3],
      b.top * 1e3, b.B[1], b.B[2], b.B[3], b.S_crumb, b.B_outer, b.S_outer, f.t * 1600 / 60)
    h.write("bands.csv", table.concat(bands, "\n") .. "\n")
    -- one range for the whole run: the default one follows the oven, which
    -- the cooling sets to cool_to, and then every frame saturated at 26 degC
    f:png("temperature", "frames/temperature_%04d.png", { range = { math.min(T0, P.cool_to), P.oven }, time_scale = 1600,
      label = label })
  end }
positions("particles_end.csv")
-- the highest volume in the oven (tests/sph_cake_test.sh reads it), when, and the volume as the bake ends: the
-- cake is highest about a third of the way into its bake and settles a little before it comes out
-- (a run that stops before the bake's end, --until under bake, says so: it had printed its last volume "as the bake
-- ends")
print(("angel food cake: relative volume %.3f at its highest in the oven (t = %.2f s, %.0f min; %s), "
  .. "%.3f at t = %.2f s, %.0f min (mean %.1f degC)"):format(peak, peak_t, peak_t * 1600 / 60,
  baked and ("%.3f as the bake ends"):format(baked) or ("still in the oven: the bake ends at %g s"):format(P.bake),
  area() / A0, s:stats().t, s:stats().t * 1600 / 60, mean_T())) -- both times in real minutes too (#18, userview4)
-- the crumb against the crust as the bake ends (bands.csv's row then; claim_sph_angel_cake_crumb_pale)
-- a saturation also as its share of the batter's start (WATER, 0.256): 0.19 alone had read as a dried crumb; without
-- the water, none (it had printed -nan)
local function sat(x) return P.water and ("%.4f (%.2f of its start)"):format(x, x / 0.256) or "none (water = false)" end
if baked_b then
  print(("angel food cake as the bake ends: crumb band %.1f degC, browning %.4f, saturation %s; top band %.1f degC, "
    .. "browning %.4f; outer surface's batter browning %.4f, saturation %s"):format(baked_b.T[2], baked_b.B[2],
    sat(baked_b.S_crumb), baked_b.T[1], baked_b.B[1], baked_b.B_outer, sat(baked_b.S_outer)))
end

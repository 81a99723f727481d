-- Angel food cake baked, then left in its pan to collapse, with the SPH solver
-- (Rodriguez-Arenas 2011 Fig. 4.11).
--   hearth run scripts/scenes/sph/angel_food_cake.lua [--set bake=1.5 --set cool_to=25 --set bubble_share=0.4]
--     [--set xsph_cool=0.05 --set xsph_hot=0.3]
-- A 2D section through a tube pan: batter on both sides of the central tube,
-- between the pan's walls. A share of its particles are bubble particles
-- (eq. 3.48-3.51; whisked egg white holds many). In the oven (oven, degC)
-- heat enters at the surface (eq. 3.42) and diffuses (eq. 3.45); the bubbles
-- expand while they heat and the batter keeps the volume it reached (eq.
-- 3.52). At t = bake the cake comes out and is left upright in its pan
-- (cool_to, degC): the temperature falls, the bubbles' gas contracts (the
-- ideal gas of eq. 3.51 in reverse raises their final density) and the
-- structure, which only sets while hot here (mu_e and viscosity follow the
-- temperature through h.curve), gives way: the cake loses part of the
-- volume it gained. The thesis does the same by hand (§4.5: rho_f raised,
-- mu_e and lambda lowered after baking); turning the pan over is what a baker
-- does to stop it, not modelled. Measured (2D default, the per-area heat
-- below on the cake's outer surface, sph_outer.c, and eq. 3.51 stopped where
-- a bubble reaches its gas's volume, sph.c's bubble_expands, #18 helper
-- deadbread): relative volume 1.205 at the end of baking (t = 1.5 s), 0.993
-- at t = 3.5 s (mean 28 degC): the 40% of bubble particles grow by their
-- gas's T / T0 (1.48 at 170 degC) and no further; the crumb is the coolest
-- band while it bakes (bands.csv at 0.5 s: 114 degC against the top's 126
-- and the bottom's 125 at dx 3 mm, 116 / 128 / 126 at 2 mm). Before the
-- stop, with eq. 3.51 pushing for as long as a bubble heated: 2.33 and 1.87
-- (mean 29 degC), the crumb band 104 degC against 137 and 132, though the
-- whole cake passes 150 degC by 1 s (no water, so no boiling plateau holds the
-- crumb near 100 degC, and the crumb browns); a few particles were thrown
-- onto the tube's top then (none now); the halves' mean temperatures agree
-- to 6e-12 degC throughout. Until the oven's heat entered at the outer surface (#18) it
-- entered at the colour field's surface particles, which in the risen cake
-- were batter rows inside it and not its top: 2.25 and 2.00 (mean 82 degC),
-- the crumb band 17 degC hotter than the top at 0.5 s, and the mean 16.6
-- degC apart between dx 3 and 2 mm. With the old asymmetric seed it was 2.22 and 1.95 (mean 78 degC), the right half
-- 13.7 degC hotter than the left at 1 s. Before the time step counted the
-- stiffness eq. 3.52 gives the batter (sph.c, signal_speed) it was 2.05 and
-- 1.61 (mean 63 degC), the cooled crumb full of holes, and the scene needed
-- the hot crust's larger XSPH epsilon to stay stable (xsph_hot; with 0.05
-- everywhere the guard stopped it at t = 0.03 s). With the printed form's
-- heat (6e8, 0.3x this) it was 1.95 and 1.72.
-- Writes volume.csv (relative volume over time, from a density slice, with
-- the mean temperature, and the mean temperatures of the particles left and
-- right of the tube's axis and their difference), bands.csv (the mean
-- temperatures of the top, crumb and bottom bands away from the pan's walls,
-- sph_cake_crumb_coolest) and browning and
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
local h = require "hearth"
-- oven: above the batter's 26 degC start (the bake heats it; the temperature frames span the two); foam: V_b0 of eq.
-- 3.50 in maxwell_sph's range [0, 100]; bubble_share: discs of 4 mm on a square pitch touch at pi / 4 (--set
-- bubble_share=0 had left no spots, and h.union's raw Lua error was all a user saw)
local P = h.params { dx = h.number { 0.003, above = 0, unit = "m", what = "the grid spacing" },
  oven = h.number { 180, above = 26, max = 5000, unit = "degC",
    what = "the oven's temperature, above the batter's 26 degC" },
  cool_to = h.number { 25, min = -273.15, max = 5000, unit = "degC", what = "the air it cools in after the bake" },
  bake = h.number { 1.5, min = 0, unit = "s", what = "the bake's time before it cools" },
  until_t = h.number { 3.5, min = 0, unit = "s", what = "the run's simulated time (0: the set-up alone, measured)" },
  bubble_share = h.number { 0.4, above = 0, max = math.pi / 4,
    what = "the share of the batter seeded as bubble particles" },
  foam = h.number { 1.0, min = 0, max = 100, what = "the batter's initial bubble volume V_b0 (eq. 3.50)" },
  xsph_cool = h.number { 0.05, min = 0, max = 1, what = "XSPH's epsilon in the cool batter (h.scene's range)" },
  xsph_hot = h.number { 0.3, min = 0, max = 1, what = "XSPH's epsilon in the hot batter (h.scene's range)" } }
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
          bubble_T0 = T0, tension = true, alpha_c = 0.1, beta_c = 0.8 },
  oven = { temperature = P.oven, beta = 0 }, browning = true, browning_scale = 1600 }

-- The crumb sets while hot and softens again as it cools (the structure of
-- an angel food cake left upright is not set enough to hold).
local props = {
  density = 600, bulk = 2e4, lambda = 0.5,
  viscosity = h.curve { { T0, 2 }, { 80, 4 }, { 110, 10 } },
  mu_e = h.curve { { T0, 20 }, { 80, 60 }, { 110, 1000 } },
}
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
-- about their middle height (sph_cake_crumb_coolest)
local function bands_T()
  local p = s:particles { fields = { "x", "temperature" } }
  local inner, ytop = {}, floor_y
  for i = 1, p.n do
    local x, y = p.x[3 * i - 2], p.x[3 * i - 1]
    local d = math.min(math.abs(x - 0.02), math.abs(x - 0.18), math.abs(x - 0.092), math.abs(x - 0.108))
    if d >= 0.01 and (x < 0.092 or x > 0.108) then
      inner[#inner + 1] = i
      ytop = math.max(ytop, y)
    end
  end
  local mid, sum, cnt = 0.5 * (floor_y + ytop), { 0, 0, 0 }, { 0, 0, 0 }
  for _, i in ipairs(inner) do
    local y, T = p.x[3 * i - 1], p.temperature[i]
    local b = (y > ytop - 0.01 and 1) or (math.abs(y - mid) < 0.005 and 2) or (y < floor_y + 0.01 and 3) or nil
    if b then sum[b], cnt[b] = sum[b] + T, cnt[b] + 1 end
  end
  return sum[1] / cnt[1], sum[2] / cnt[2], sum[3] / cnt[3], ytop
end
s:step(1) -- the density slice needs one SPH step (before it the probe has no SPH density)
local A0 = area()
local csv = { "t,relative_volume,mean_temperature_C,phase,T_left_C,T_right_C,T_right_minus_left_C" }
local bands = { "t,T_top_C,T_crumb_C,T_bottom_C,top_mm" }
local cooling, peak = false, 1
-- the frames' titles give the real time the scene's S = 1600 stands for, then the simulated seconds; browning
-- is drawn as a slice, as the temperature is: as particles, the bubbles (gas, no browning: NaN) drew as
-- dark grey discs, which on the browning map read as burnt spots through the crumb
s:run { until_t = P.until_t, every = 0.1, png = { field = "browning", path = "frames/browning_%04d.png", time_scale = 1600,
  kind = "slice" },
  on_frame = function(f)
    if not cooling and f.t >= P.bake - 1e-9 then
      s:oven(P.cool_to, 0) -- out of the oven, left upright in its pan
      cooling = true
    end
    local rv = area() / A0
    if not cooling then peak = math.max(peak, rv) end
    local TL, TR = halves_T()
    csv[#csv + 1] = ("%.4f,%.5f,%.2f,%s,%.4f,%.4f,%.3g"):format(f.t, rv, mean_T(), cooling and "cooling" or "baking",
      TL, TR, TR - TL)
    h.write("volume.csv", table.concat(csv, "\n") .. "\n")
    local Tt, Tc, Tb, yt = bands_T()
    bands[#bands + 1] = ("%.4f,%.3f,%.3f,%.3f,%.1f"):format(f.t, Tt, Tc, Tb, yt * 1e3)
    h.write("bands.csv", table.concat(bands, "\n") .. "\n")
    -- one range for the whole run: the default one follows the oven, which
    -- the cooling sets to cool_to, and then every frame saturated at 26 degC
    f:png("temperature", "frames/temperature_%04d.png", { range = { math.min(T0, P.cool_to), P.oven }, time_scale = 1600 })
  end }
print(("angel food cake: relative volume %.3f at the end of baking, %.3f at t = %.2f s (mean %.1f degC)"):format(
  peak, area() / A0, s:stats().t, mean_T()))

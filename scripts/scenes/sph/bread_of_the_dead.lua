-- Bread of the dead (pan de muerto) rising with the SPH solver (Rodriguez-Arenas
-- 2011 Fig. 4.12-4.13).
--   hearth run scripts/scenes/sph/bread_of_the_dead.lua [--set mu_e=2000 --set oven=180 --until 1.2 --set water=false]
-- A 2D section of the loaf: a round mass on a hot tray with bone-like dough
-- pieces laid over it (a capsule down each flank with a knuckle disc at each
-- end) and a ball on top in the centre. The body holds bubble particles
-- (eq. 3.48-3.51) that expand as heat enters at the surface (eq. 3.42) and
-- diffuses (eq. 3.45); the dough keeps the volume it reached (eq. 3.52). The
-- dough is smooth and elastic (maxwell_sph with a high mu_e and a long
-- relaxation time, eq. 3.20), so the toppings keep their shape and ride up on
-- the rising body instead of sinking into it. What keeps it together is
-- XSPH (eq. 3.34, 0.6 raw to 0.9 baked by eq. 4.4, the thesis's own
-- stiffening knob) and Monaghan's artificial stress (sph.artificial_stress,
-- 0.3) against the tensile instability of the stretched dough.
-- Measured with the dough's water (the default since #18 helper sphcrumb, WATER below) and the dough's own
-- conduction, heat_int = S kappa / c = 0.283 (since helper deadcrust; docs/validation.md "The bread of the dead's
-- crust is pale because its oven is"): at 1.2 s relative volume 1.038 (1.056 at dx 1.5 mm), ball top 56.5 mm
-- (57.0), one piece with no gap inside; its centre 82.2 degC (82.0), unbrowned, with all its water, under an outer
-- surface at 101.9 degC (105.5) browned 0.026 (0.038), saturation 0.154 (0.080), read at its face's temperature
-- with the oven's flux through the film (helper sphflux: before it, 104.1 (107.5) degC, 0.031 (0.043)): a pale crust
-- (claim_sph_bread_of_the_dead_crumb_pale[_fine]), as a 1D slab of the same dough in the same oven
-- (scripts/validation/dead_crust_slab.py: 105.5 degC, 0.03 at 30 min) is; golden (0.5,
-- claim_sph_bread_of_the_dead_crust_browns, an expected failure) needs a hotter oven's flux than h = 30 at 180 degC.
-- With the earlier heat_int 0.5 (kappa 0.90 W/(m K) on S; --set heat_int=0.5): relative volume 1.041 (1.062), centre
-- 94.9 degC (94.7), outer surface 102.1 degC (104.2) browned 0.020 (0.028). Without the water (--set water=false
-- --set heat_int=0.5, the same bits as before helper sphcrumb) the centre reads 118.8 degC, browned 0.044, the outer
-- surface 144.7 degC, 0.22. The rest of this note was measured without the water, with heat_int 0.5.
-- Measured (2D default, to t = 1.2 s; tests/sph_dead_measure.py reads the
-- particles_*.csv it writes): relative volume 1.067, ball top 57.5 mm above
-- the tray, one piece with no gap inside (claim_sph_bread_of_the_dead_one_piece),
-- the bones in place; the bubbles stand at their gas's volume (mean rho0 / rho
-- 1.342 against V_b(T) 1.343) (#18, helper deadbread, docs/validation.md "The
-- bread of the dead stays in one piece": eq. 3.51 now stops where the bubble
-- reaches its gas's volume, sph.c's bubble_expands, and the base squeezed on
-- the tray takes the oven's heat for its length, sph_outer.c's oshare). Before
-- that, with the heat on the body's outer surface (sph_outer.c, the tray's face
-- included): relative volume 1.532, ball top 73.0 mm; by 0.9 s the two lowest
-- knuckles had parted from the body (3 pieces) and by 1.1 s two slits of 13.5
-- raw particle areas had opened under the top ball, where the bubbles stood at
-- 1.44x their gas's volume (pushed for as long as they heated); the base's
-- middle on the hot tray read about 140 degC at 1.1 s, its squeezed bottom row
-- taking 1.7 faces of heat per face of base. With eq. 3.42 at the colour
-- field's surface particles (which missed that row) the base's middle read
-- about 90 degC in the 1.1 s frame. Before that: relative
-- volume 1.244, ball top 63.5 mm above the tray (62.5 mm at the start, 55.0
-- after settling; 1.230 and 63.0 mm before XSPH's pair epsilon and the time
-- step of eq. 3.52's stiffness, sph.c), bones in place, one piece, the crust near 160 degC and the
-- centre near 85 degC at 1.1 s. With the thesis's printed heat (4e8, a third
-- of the heat at this dx) it rose 1.013 by 1.2 s, ball top 55.5 mm, and stayed
-- one piece to 2.5 s (1.041); the variants below were measured with that heat.
-- Without artificial stress (--set artificial_stress=0) the rising
-- body splits along the bones into three lobes by t = 1.9 s (relative volume
-- 1.14, 1.24 at 2.5 s; part of that volume is the gaps). With the XSPH of
-- bread_roll.lua (--set xsph0=0.05 --set xsph_f=0.3) it shattered by 1 s
-- (before artificial stress); --set mu_e=20 slumps (ball top 20 mm).
-- Heat: eq. 3.42 per unit area of surface (core/sim/solver/sph_heat.c),
-- k_h,ext = S h / c from a physical oven: h = 30 W/(m^2 K) (Baik et al. 1999,
-- J. Food Sci. 64:688: 20-48 W/(m^2 K) with radiation), c = 2700 J/(kg K)
-- (bread dough, Choi & Okos; h.library.dough.bread's) and S = 1500
-- (browning_scale: 1.2 s for 30 minutes): 1500 x 30 / 2700 = 16.7 kg/(m^2 s).
-- (The thesis's printed form had 4e8, 1.0 in these units at dx 2 mm: the
-- numbers measured above were taken with it.)
-- Inside, eq. 3.45's k_h,int = kappa / c on the same S: 1500 x 0.51 / 2700 =
-- 0.283 kg/(m s) (bread dough's kappa and c, Zanoni et al. 1995 and Choi &
-- Okos, h.library.dough.bread's; the heat_int parameter). It was 0.5, kappa
-- 0.90 W/(m K) on S: 1.77x the dough's, so the surface took ~25 min instead of
-- ~15 to reach 100 degC in the 1D slab of scripts/validation/dead_crust_slab.py.
-- Writes volume.csv: relative volume (from a density slice), the height of
-- the top ball and of a bone knuckle above the tray, over time (t_s in simulated s and, last, t_real_min, the frames'
-- real minutes); and
-- particles_NNNN.csv (the raw loaf, then every frame) and particles_end.csv
-- (at until_t): x, y (m), T (degC), outer (1 where the oven's heat
-- enters, sph_outer.c), browning and saturation per particle.
-- outer, 1 on the loaf's outer surface (the boundary field, sph_outer.c), has no unit (tests/scene_csv.py's rule):
-- particles_NNNN.csv has no unit: outer
-- particles_end.csv has no unit: outer
-- A bubble is gas: its browning and saturation are empty cells, not measured (and the saturation of every particle
-- with --set water=false); they had been `nan` (#18, helper userfix10: h.write writes a NaN in a CSV as empty):
-- particles_NNNN.csv may leave empty (not measured): browning, saturation
-- particles_end.csv may leave empty (not measured): browning, saturation
local h = require "hearth"
-- the bread dough's physical properties (lua/hearth/dough_physical.lua: Zanoni et al. 1995, Choi & Okos) and the
-- scene's time scale S (browning_scale: 1.2 s for a 30-minute bake), which heat_ext, heat_int, the water and the
-- browning all share
local BREAD, S = require("hearth.dough_physical").goods.bread, 1500
-- mu_e, viscosity, lambda and vb0 (the bubble's V_b0, eq. 3.50) in maxwell_sph's ranges
local P = h.params { dx = h.number { 0.002, above = 0, unit = "m", what = "the grid spacing" },
  oven = h.number { 180, min = -273.15, max = 5000, unit = "degC", what = "the oven's temperature" },
  mu_e = h.number { 2000, min = 0.001, max = 10000000000.0, unit = "Pa", what = "the dough's elastic modulus mu_e" },
  viscosity = h.number { 5, min = 0, max = 1e6, unit = "Pa s", what = "the dough's viscosity" },
  lambda = h.number { 20, min = 1e-09, max = 1000000000.0, unit = "s", what = "the dough's relaxation time" },
  -- simulated seconds, each 25 real minutes (S = 1500, above): --params had not said so, only the run's first line
  until_t = h.number { 1.2, min = 0, unit = "s",
    what = "the run's simulated time (1 s: 25 real min; 0: the set-up alone, measured)" },
  vb0 = h.number { 1.0, min = 0, max = 100, what = "the bubbles' initial volume V_b0 (eq. 3.50)" },
  xsph0 = h.number { 0.6, min = 0, max = 1, what = "XSPH's epsilon in the raw dough (h.scene's range)" },
  xsph_f = h.number { 0.9, min = 0, max = 1, what = "XSPH's epsilon in the baked dough (h.scene's range)" },
  artificial_stress = h.number { 0.3, min = 0, max = 1,
    what = "Monaghan's epsilon against the tensile instability (h.scene's range)" },
  -- the dough's water (WATER below): true carries the bread dough's, with latent_heat and boiling at 100 degC;
  -- false is the dough before #18 helper sphcrumb, which held none
  water = h.flag { true, what = "the dough carries its water: latent heat, boiling at 100 degC (false: the dry dough)" },
  -- eq. 3.45's k_h,int = S kappa / c on the dough's own kappa and c (the HEAT note): 1500 x 0.51 / 2700 = 0.283;
  -- 0.5 was the scene's before #18 helper deadcrust (kappa 0.90 W/(m K) on S = 1500)
  heat_int = h.number { S * BREAD.conductivity / BREAD.specific_heat, min = 0, max = 1e6, unit = "kg/(m s)",
    what = "the dough's internal heat conduction k_h,int = S kappa / c (eq. 3.45)" },
  -- with --set oven.wall_temperature / oven.emissivity (radiating walls, docs/validation.md "An oven's hot walls"):
  -- the air's own coefficient, heat_ext = S h_c / c, the scene's h = 30 being an effective one with radiation in it
  h_c = h.number { 0, min = 0, unit = "W/(m^2 K)", what = "the oven air's coefficient in real time (0: heat_ext 16.7, h = 30)" } }
-- what a run's seconds stand for (S = 1500, the scene's browning_scale and its heat_ext, below)
print(("bread_of_the_dead.lua: heat (an oven's h = 30 W/(m^2 K)) and browning 1500 times fast: "
  .. "the %g s run stands for %.0f min, 1 s for %.0f min"):format(P.until_t, P.until_t * S / 60, S / 60))

local T0, tray = 26, 0.01
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.16, 0.12 } }, solver = "sph",
  sph = { heat_ext = P.h_c > 0 and S * P.h_c / BREAD.specific_heat or 16.7, heat_int = P.heat_int, av_beta = 1, xsph0 = P.xsph0, xsph_f = P.xsph_f, xsph_T0 = T0,
          xsph_Tf = 120,
          bubble_T0 = T0, tension = true, artificial_stress = P.artificial_stress },
  oven = { temperature = P.oven, beta = 0, radiation_scale = S }, -- walls (--set) radiate S times fast, as heat_ext
  browning = true, browning_scale = S, -- Zanoni et al. 1995 kinetics; 1.2 s stand for a 30-minute bake
  latent_heat = P.water or nil, boiling_point = P.water and 100 or nil, time_scale = S }

local props = { density = 1100, bulk = 2e4, lambda = P.lambda, viscosity = P.viscosity, mu_e = P.mu_e }
-- WATER (#18, helper sphcrumb): the dough is bread dough (its heat capacity above is h.library.dough.bread's), so
-- it carries that dough's water: 45% wet basis (lua/hearth/dough_physical.lua: Zanoni, Peri & Pierucci 1993), at
-- this scene's 1100 kg/m^3 s = 0.45 x 1100 / 1000 = 0.495 of rho_0^w (Ding et al. eq. 8); the bread's liquid
-- diffusivity 2e-9 m^2/s (eq. 22: K = D / (373.15 s)) and surface evaporation 1.2e-5, on this scene's S = 1500;
-- its dried crust's heat capacity by the mixture rule (m c = m_s c_s: 0.55 x 1650 = 907.5 J/(kg K), whose slope
-- (2700 - 907.5) x 1100 / 495 = 3983 J/(kg K) per kg of water is water's own c, as the rule asks) and conductivity
-- (Zanoni et al. 1995's measured crust against crumb, 0.23 of 0.51 W/(m K): SPH's conduction takes their ratio on
-- sph.heat_int, core/sim/solver/sph_heat.c). The bubbles share the parameters but hold no water (sph_water.c).
if P.water then
  local g, s0 = BREAD, 0.495
  props.saturation, props.water_diffusivity = s0, g.water_diffusivity_m2s / (373.15 * s0) * S
  props.evaporation = g.evaporation * S
  props.specific_heat, props.dry_specific_heat = g.specific_heat, g.dry_specific_heat
  props.conductivity, props.dry_conductivity = g.conductivity, g.dry_conductivity
end
local dough = h.material("maxwell_sph", props)
props.bubble = P.vb0 -- V_b0 of eq. 3.50
local bubble = h.material("maxwell_sph", props)

-- the body: a disc cut flat by the tray
local cx, R = 0.08, 0.03
local c = { cx, tray + 0.02 }
local body = h.intersection(h.disc(c, R), h.box({ 0, tray }, { 0.16, 0.12 }))
-- the bones: along each flank, just outside the body, a capsule with a knuckle
-- disc at each end; the ball sits on top in the centre
local function on_body(angle, out)
  return { c[1] + (R + out) * math.cos(angle), c[2] + (R + out) * math.sin(angle) }
end
local tb, kn = 0.0035, 0.0045 -- bone half-thickness, knuckle radius
local pieces = {}
for _, side in ipairs { -1, 1 } do
  local a0, a1 = math.pi / 2 + side * 0.45, math.pi / 2 + side * 1.25
  local p0, p1 = on_body(a0, tb), on_body(a1, tb)
  pieces[#pieces + 1] = h.capsule(p0, p1, tb)
  pieces[#pieces + 1] = h.disc(on_body(a0, kn), kn)
  pieces[#pieces + 1] = h.disc(on_body(a1, kn), kn)
end
local ball_r = 0.007
local ball = h.disc({ cx, c[2] + R + ball_r * 0.8 }, ball_r)
pieces[#pieces + 1] = ball
local toppings = h.difference(h.union(table.unpack(pieces)), body)

-- bubble particles spread through the body in small discs
local spots = {}
for j = -3, 3 do
  for i = -3, 3 do
    local x, y = c[1] + i * 0.008, c[2] + j * 0.008
    if (x - c[1]) ^ 2 + (y - c[2]) ^ 2 < (0.85 * R) ^ 2 and y > tray + 0.004 then
      spots[#spots + 1] = h.disc({ x, y }, 0.0025)
    end
  end
end
local gas = h.intersection(body, h.union(table.unpack(spots)))
s:add { shape = h.difference(body, gas), material = dough, ppc = 1, jitter = 0, temperature = T0 }
s:add { shape = gas, material = bubble, ppc = 1, jitter = 0, temperature = T0 }
s:add { shape = toppings, material = dough, ppc = 1, jitter = 0, temperature = T0 }
s:collider { shape = h.plane({ 0, tray }, { 0, 1 }), mode = "slip", temperature = P.oven, beta = 0 }

local res = { 160, 120 }
local function area()
  local rows = s:slice("density", { res = res })
  local n = 0
  for _, row in ipairs(rows) do for _, v in ipairs(row) do if v == v then n = n + 1 end end end
  return n * (0.16 / res[1]) * (0.12 / res[2])
end
-- top of the material above the tray along a vertical line at x
local function top_at(x)
  local col = s:line("density", { x, tray }, { x, 0.12 }, 221)
  local y = tray
  for i, d in ipairs(col) do if d == d then y = tray + (i - 1) * (0.12 - tray) / 220 end end
  return y - tray
end
local knuckle_x = on_body(math.pi / 2 + 1.25, kn)[1]
-- particle positions (x_m, y_m), temperatures (T_degC) and the outer-surface flag, for measures that do not go
-- through the density field (tests/sph_dead_measure.py's pieces and inner gaps; bread_roll.lua writes its own)
-- (and the browning and saturation: empty for a bubble, which is gas, and the saturation for every particle with the
-- water off; tests/sph_crumb_measure.py)
local function positions(path)
  local fields = { "x", "temperature", "boundary", "browning" }
  if P.water then fields[#fields + 1] = "saturation" end
  local r = s:particles { fields = fields }
  local x, T, b, rows = r.x, r.temperature, r.boundary, { "x_m,y_m,T_degC,outer,browning,saturation" }
  for i = 1, #T do
    rows[#rows + 1] = ("%.6g,%.6g,%.2f,%d,%.4g,%.4g"):format(x[3 * i - 2], x[3 * i - 1], T[i], b[i], r.browning[i],
      P.water and r.saturation[i] or 0 / 0)
  end
  h.write(path, table.concat(rows, "\n") .. "\n")
end
s:step(1) -- the density slice needs one SPH step (before it the probe has no SPH density)
local A0 = area()
-- t is the simulated time (s); t_real_min, last, the real minutes the frames' titles give (S = 1500)
local csv = { "t_s,relative_volume,ball_top_m,knuckle_top_m,t_real_min" }
positions("particles_0000.csv")
-- the frames' titles give the real time the scene's S = 1500 stands for, then the simulated seconds; browning
-- is drawn as a slice, as the temperature is: as particles, the bubbles (gas, no browning: NaN) drew as
-- dark grey discs, which on the browning map read as burnt spots through the crumb
-- the label names the bread and its oven (#18, helper userview3: a frame copied out said only its time)
local label = ("bread of the dead, oven %g °C"):format(P.oven)
s:run { until_t = P.until_t, every = 0.1, png = { field = "browning", path = "frames/browning_%04d.png", time_scale = S,
  kind = "slice", label = label },
  on_frame = function(f)
    csv[#csv + 1] = ("%.4f,%.5f,%.5f,%.5f,%.2f"):format(f.t, area() / A0, top_at(cx), top_at(knuckle_x), f.t * S / 60)
    h.write("volume.csv", table.concat(csv, "\n") .. "\n")
    f:png("temperature", "frames/temperature_%04d.png", { time_scale = S, label = label })
    positions(("particles_%04d.csv"):format(#csv - 1))
  end }
positions("particles_end.csv") -- the loaf at until_t (the frames stop one interval short of it)
-- the time in real minutes too, as the frames give it (#18, helper userview4: the first line alone said it)
print(("bread of the dead: relative volume %.3f, top ball %.4f m above the tray at t = %.2f s, %.0f min"):format(
  area() / A0, top_at(cx), s:stats().t, s:stats().t * S / 60))
-- the centre (particles within a fifth of the body's radius of the particles' centroid) against the outer surface
-- (the boundary flag, where the oven's heat enters, sph_outer.c): temperature, browning and saturation, the dough's
-- (a bubble is gas: no browning, no water, NaN)
do
  local fields = { "x", "temperature", "browning", "boundary" }
  if P.water then fields[#fields + 1] = "saturation" end
  local r = s:particles { fields = fields }
  local cxm, cym = 0, 0
  for i = 1, r.n do cxm, cym = cxm + r.x[3 * i - 2] / r.n, cym + r.x[3 * i - 1] / r.n end
  local acc = { centre = { 0, 0, 0, 0, 0 }, outer = { 0, 0, 0, 0, 0 } }
  for i = 1, r.n do
    local d = math.sqrt((r.x[3 * i - 2] - cxm) ^ 2 + (r.x[3 * i - 1] - cym) ^ 2)
    local a = r.boundary[i] > 0 and acc.outer or d < 0.2 * R and acc.centre or nil
    if a then
      a[1], a[2] = a[1] + 1, a[2] + r.temperature[i]
      local b = r.browning[i]
      if b == b then a[3], a[4], a[5] = a[3] + 1, a[4] + b, a[5] + (P.water and r.saturation[i] or 0 / 0) end
    end
  end
  for _, k in ipairs { "centre", "outer" } do
    local a = acc[k]
    print(("bread of the dead at t = %.2f s, %.0f min (water %s): %s %d particles (%d dough), %.1f degC, the dough's "
      .. "browning %.4f and saturation %.4f"):format(s:stats().t, s:stats().t * S / 60, tostring(P.water), k, a[1], a[3],
      a[2] / a[1], a[4] / a[3], a[5] / a[3]))
  end
end

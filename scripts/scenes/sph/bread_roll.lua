-- Bread roll rise with the SPH solver (Rodriguez-Arenas 2011 §4.2, Fig. 4.3-4.4).
--   hearth run scripts/scenes/sph/bread_roll.lua [--set bubbles=centre] [--until 3]
-- A 2D roll of Table 4.1 dough (maxwell_sph, h.library.sph.bread_roll) on a hot
-- tray in an oven. A quarter of its particles are bubble particles (eq. 3.48-3.50):
-- spread evenly in spots (bubbles=even, Fig. 4.4a-b), one by one among the
-- dough's (bubbles=dispersed) or gathered at the centre (bubbles=centre,
-- Fig. 4.4c-d). Heat enters at the surface (eq. 3.42) and
-- diffuses (eq. 3.45); the dough stiffens (eq. 4.1-4.3). How it holds together
-- and rises comes from the preset (#18, docs/validation.md "SPH bread roll"):
-- the thesis's Tait with its negative part (tension) and Monaghan's artificial
-- stress keep it one piece, and each bubble's rest density is the gas law's
-- rho0 / V_b(T) with the dough's water vapour (sph.gas_law, sph.bubble_vapour),
-- each bubble as stiff as its own gas, P_a - P_v (sph.gas_pressure = 101325):
-- the bubbles grow with their temperature, and only with it; the dough reads
-- a squeeze only as far as its own det F confirms it (sph.own_squeeze).
-- The preset's sph.hourglass = 0.5 damps the pairs' motion their velocity
-- gradient does not see: the roll no longer hops on its tray, and it stayed
-- whole in every run of an ensemble (4 at 2 mm to 3 s, 3 at 1.5 mm to 2 s);
-- --set hourglass=0 is the roll before it (at 2 mm it tore 2.02% at 2.4 s),
-- --set hourglass=1 tore the 1.5 mm roll 2.08% at 2.0 s (docs/validation.md
-- "Hourglass control for the roll's dough", "The hourglass control over an
-- ensemble").
-- --set shift=k moves the roll k spacings (k dx) along the tray: the same roll
-- on the same slip tray, each particle where it was relative to the roll,
-- only the arithmetic's round-off (and neighbour sums' order) differs. The
-- roll's cavities open and close by chance, so its runs at shift 1 and 2 are
-- an ensemble of one scene (docs/validation.md "The hourglass control over an
-- ensemble"); shift -1 seeds one more particle (a lattice point on the disc's
-- edge rounds the other way), so it is not the same roll. --set warm=1e-6
-- seeds the roll a microkelvin warmer: nothing a thermometer or the dough
-- would notice, but every temperature-dependent parameter moves by ~1e-8 of
-- itself from the first step, a larger seed of chance than round-off.
-- Measured (2D default, from the particles, tests/sph_roll_measure.py: the
-- dough with its closed gas cells, less what is torn): whole in every frame
-- to 2 s, 1.3x at 1.3 s and 1.435x at 1.9 s (1.5 mm alike), its crumb soft
-- until bread's set at 68-80 degC (the preset's mu_e, helper rollset); from
-- 1.6 s the ends of its base lift off the tray (4.5 mm at 1.9 s) as the set
-- crust rounds over bubbles that stay closed (docs/validation.md "The roll's
-- set"). With eq. 4.2 (--set mu_e_curve=table) the crumb set before 50 degC:
-- on its tray (largest gap 1.30 mm) but 1.14x ("The roll's base: its own
-- squeeze"). Before the gas
-- law's density summed rest volumes (sph.c sort_and_list) it tore at 0.5 s
-- (1.03x) along the films between bubble spots, which eq. 3.13's mass sum
-- read as stretched (docs/validation.md "The films' tension").
-- It stays where it was put (it drifted 2 cm right by 1.2 s before XSPH's
-- pair epsilon, sph.c phase_xsph). Its underside left the tray from 0.9 s
-- but for a foot, and the 1.5 mm roll slit from 0.5 s: eq. 3.13 read the
-- roll's outline and tray side as stretched, and Tait's tension made them a
-- skin (docs/validation.md "The roll's skin"). The preset's
-- sph.renormalised_density divides the sum by the part of the kernel the
-- dough fills: it sits flat on its tray, heats from it and rises more slowly
-- (1.22x at 1.5 s at 2 mm), whole (docs/validation.md "The roll's skin,
-- renormalised"). --set continuity=true (with --set renormalised=false) reads
-- each particle's own volume instead (with the B-stiff bubbles its films tore
-- from 1.6 s; with the own gas and eq. 4.2's early set it stayed whole and
-- flat on its tray but rose 1.14x); --set gas_pressure=0 gives the bubbles the dough's Tait B instead of
-- their gas's stiffness (2.9 kPa raw, 4.8e5 hot; the preset before rolltray:
-- 1.50x at 2 s, its base up to 6.07 mm off the tray; docs/validation.md "The
-- bubble's own gas", "The own gas as the preset"). --set dough_water=0.43
-- dissolves CO2 in the dough's water by Henry's law, which the heat drives
-- into the bubbles.
-- --set own_squeeze=false gives the rest-volume sum its squeeze back: from
-- 1.5 s the base arches off the tray between two feet, 2-4 mm, and the roll
-- rises 1.45x (docs/validation.md "Why the roll's base leaves its tray"): the
-- dough of its bottom rows reads the hot bubbles beside it as a squeeze and
-- holds 0.06-1.1 MPa, and the tray, a clip with no adhesion, can then carry
-- the roll's weight only over a contact W / p wide. (Two switches tried
-- for the base, a cap on the dough beside bubbles and vented open cells, are
-- deleted: "Both switches on"; so is a bubble that opens as its crumb sets:
-- "The roll's cells open at the set", and one that opens as the dough round
-- it sets: "The roll's cells open as their walls set".)
-- --set vent=true (sph.surface_vent) lets a bubble on the outer surface vent, as a crumb's cells that open to
-- the air (the flood fill's outer flag, less the tray side: a cell within its h of the tray is closed by it) lose
-- their gas: its gauge is 0 and the gas that left stays gone (sph_gas.c; docs/validation.md "Cells open to the air
-- vent"). Vented on the tray side too, the 2 mm roll's base cells lost half their gas and it tipped on its tray
-- (6.29 mm at 2 s); without it, 3.42 mm at 1.7 s and level, but with --set warm=0.3 the 2 mm roll tore its top
-- 2.51% at 2 s and the 1.5 mm roll 2.87% at a base spot open onto the gap under its lifted base ("The vented
-- roll rocked because its tray side vented"). Off by default, as measured there.
-- --set trace=true also writes trace_NNNN.csv beside each particles_NNNN.csv from 0001 on: every particle's id (the dough's
-- first, its bubbles' after: bubble ids from the count the run prints), position, velocity, temperature, pressure,
-- density, outer flag (the oven's heat enters there) and stress_yy, for scripts/validation/sph_roll_spots.py
-- (docs/validation.md "The 1.5 mm roll's tear traced"); the run's bits are the same. outer is a flag:
-- trace_NNNN.csv has no unit: outer
-- trace_NNNN.csv has no unit: gas_left (with vent=true: the share of a bubble's own gas still in its cell; NaN: dough)
-- Writes volume.csv (relative volume over time, from a density slice, and the
-- coolest particle's temperature; by simulated time t_s, s), particles_NNNN.csv (positions, for
-- tests/sph_roll_measure.py: particles_0000.csv is the raw roll before the run, and NNNN >= 1 the frame at
-- t = (NNNN - 1) x 0.1 s, volume.csv's row NNNN, whose pictures are frames/*_(NNNN - 1).png: particles_0004.csv and
-- trace_0004.csv go with temperature_0003.png, at 0.3 s) and browning frames: the crust's colour from each
-- particle's temperature history (Zanoni et al. 1995, the thesis's [89];
-- browning_scale = 400 lets the 3 s animation stand for a 20-minute bake).
-- Heat: eq. 3.42 per unit area of surface (core/sim/solver/sph_heat.c),
-- k_h,ext = S h / c from a physical oven: h = 30 W/(m^2 K) (an oven's
-- effective coefficient, radiation included, 20-48 W/(m^2 K) in Baik et al.
-- 1999, J. Food Sci. 64:688; h.library.oven.bread's), c = 2700 J/(kg K) (bread
-- dough, Choi & Okos composition model; h.library.dough.bread's) and the
-- scene's time scale S = 400 (browning_scale: the 3 s stand for 20 minutes),
-- so heat_ext = 400 x 30 / 2700 = 4.44 kg/(m^2 s) at any dx. (It was 1e9 in
-- the thesis's printed form, which at dx 2 mm is 2.55 in these units and went
-- as dx^3, so the finer roll stayed cool.) The tray heats through the same
-- coefficient. heat_int (0.2, kappa / c) is not rescaled: the same S on
-- bread's 0.51 W/(m K) would give 0.076. Tried with the oven's flux through
-- the film (helper sphflux): at 2 mm the roll rose 1.344x by 2 s and tore 2.1%
-- of its envelope at 2.7 s (claim_sph_bread_roll_one_piece_whole_bake's bar
-- 2%), where 0.2 stays whole to 3 s; so 0.2 stays (docs/validation.md "SPH's
-- oven heat enters at the face").
-- Scaling: Table 4.1's numbers are animation units. Taken as SI, the raw dough
-- (0.1 Pa s, mu_e 1 Pa) is water and the roll splashes, and the baked end
-- (5e3 Pa s) needs microsecond steps. So the viscosity is multiplied by
-- visc_scale (default 100) and capped at visc_cap (default 300 Pa s). mu_e is
-- the preset's in Pa (mu_e_curve = sourced): Table 4.1 x 100 while raw, set
-- over 68-80 degC where bread sets (McGee 2004), 1 MPa at 80 (lua/hearth/
-- sph_library.lua MU_E_SET; docs/validation.md "The roll's set"); --set
-- mu_e_curve=table gives eq. 4.2 of Table 4.1 x mue_scale (default 100), which
-- passes the gas's 20 kPa at 45.3 degC and held the roll at 1.14x. --set
-- visc_scale=1 --set mue_scale=1 --set visc_cap=1e9 --set mu_e_curve=table is
-- the table as printed.
-- --set crust=true gives the dough h.library.dough.bread's water (its 45% wet
-- basis, at this dough's 1100 kg/m^3 saturation s = 0.45 x 1100 / 1000 = 0.495
-- of rho_0^w, Ding et al. eq. 8, as bread_of_the_dead.lua's; its liquid
-- diffusivity 2e-9 m^2/s, eq. 22's K = D / (373.15 s), and surface evaporation
-- on the scene's S = 400),
-- latent_heat with boiling at 100 degC, and its dried crust's conductivity and
-- heat capacity (dry_conductivity 0.23 of 0.51 W/(m K): sph.heat_int x 0.45
-- where dried; dry_specific_heat 907.5 of 2700 J/(kg K); core/sim/solver/
-- sph_heat.c); --set dry=false keeps the water and drops the dried crust's two
-- parameters, for comparison. It prints the browning and saturation of the
-- outer rim (within 3 mm of the roll's outline) and of the centre (within a
-- fifth of the radius) at the end (docs/validation.md "SPH's dried crust"),
-- the dough's only: the bubbles are gas and hold no water (sph_water.c; their
-- material's default saturation 0.5 had read as 0.31 at the centre at 0.02 s,
-- "SPH's saturation at rest: the bubbles held water").
-- Before #18 (clamped pressure, eq. 3.51): the slumping roll tore at its base
-- by 0.3 s and split in two by 1 s; with tension and artificial stress the
-- top burst at 1.64 s (eq. 3.51 pushes by whatever volume it already gained).
local h = require "hearth"
local lib = h.library.sph.bread_roll
local sph = lib.sph
-- the sph.* numbers in h.scene's ranges (hearth help scene); radius: the roll sits on the tray at 10 mm in the
-- 0.12 m tall box
local P = h.params { dx = h.number { 0.002, above = 0, unit = "m", what = "the grid spacing" },
  oven = h.number { 180, min = -273.15, max = 5000, unit = "degC", what = "the oven's temperature" },
  visc_scale = h.number { 100, min = 0, what = "a factor on the dough's viscosity curve" },
  mue_scale = h.number { 100, above = 0, what = "a factor on eq. 4.2's mu_e (mu_e_curve=table)" },
  visc_cap = h.number { 300, min = 0, unit = "Pa s", what = "the cap on the scaled viscosity" },
  radius = h.number { 0.025, above = 0, max = 0.055, unit = "m", what = "the roll's radius" },
  xsph0 = h.number { 0.05, min = 0, max = 1, what = "XSPH's epsilon in the raw dough (h.scene's range)" },
  heat_ext = h.number { 4.44, min = 0, max = 1e6, what = "the oven's heat transfer to the surface (sph.heat_ext)" },
  artificial_stress = h.number { sph.artificial_stress, min = 0, max = 1,
    what = "Monaghan's epsilon against the tensile instability" },
  tension = h.flag { sph.tension, what = "Tait's negative part (eq. 3.17): the dough pulls back when stretched" },
  gas_law = h.flag { sph.gas_law, what = "a bubble's rest density follows its gas and vapour (eq. 3.49-3.50)" },
  vapour = h.number { sph.bubble_vapour, min = 0, max = 0.99, what = "the bubbles' vapour share (sph.bubble_vapour)" },
  vmax = h.number { sph.bubble_vmax or 4, min = 1, max = 100, what = "the bubbles' largest growth (sph.bubble_vmax)" },
  continuity = h.flag { sph.continuity_density or false, what = "Tait reads each particle's own volume, not the summed density (with renormalised=false)" },
  renormalised = h.flag { sph.renormalised_density or false,
    what = "the summed density divided by the kernel's share inside the body (no skin at the outline)" },
  gas_pressure = h.number { sph.gas_pressure or 0, min = 0, max = 1e7, unit = "Pa",
    what = "the bubbles' gas pressure (sph.gas_pressure)" },
  dough_water = h.number { sph.dough_water or 0, min = 0, max = 0.9, unit = "kg/kg",
    what = "CO2 dissolved in the dough's water (sph.dough_water)" },
  own_squeeze = h.flag { sph.own_squeeze or false, what = "Tait reads a squeeze only as far as its own det F confirms it" },
  hourglass = h.number { sph.hourglass or 0, min = 0, max = 100,
    what = "the hourglass control's coefficient (sph.hourglass)" },
  crust = h.flag { false, what = "the dough carries bread's water, boils at 100 degC and dries a crust" },
  dry = h.flag { true, what = "with crust: the dried crust's own conductivity and heat capacity" },
  trace = h.flag { false, what = "trace_NNNN.csv beside each particles_NNNN.csv: every particle's state by id" },
  vent = h.flag { sph.surface_vent or false,
    what = "a bubble on the outer surface vents: its gauge is 0 and the gas that left stays gone (sph.surface_vent)" },
  shift = h.number { 0, min = -5, max = 5, integer = true, what = "spacings the roll is moved along the tray (below)" },
  warm = h.number { 0, min = -50, max = 50, unit = "K", what = "how much warmer the roll is seeded (below)" },
  bubbles = h.choice { "even", even = "small bubbles spread evenly through the roll",
    centre = "one bubble at the centre, half the roll's radius",
    dispersed = "one bubble particle in four, each alone among dough particles (Fig. 4.4a)" },
  mu_e_curve = h.choice { "sourced", sourced = "mu_e as measured breads set (the preset's own: sph_library.lua)",
    table = "the thesis's eq. 4.2 as printed (.paper.mu_e), times mue_scale" } }
-- what a run's seconds stand for (S = 400, the scene's browning_scale and heat_ext's default, below)
print("bread_roll.lua: h.library.sph.bread_roll, its viscosity scaled from Table 4.1's animation units; heat (an "
  .. "oven's h = 30 W/(m^2 K)) and browning 400 times fast: the 3 s run stands for 20 min, 1 s for 6.7 min")

sph.heat_ext, sph.heat_int, sph.av_beta = P.heat_ext, 0.2, 1
sph.gas_law, sph.bubble_vapour, sph.bubble_vmax = P.gas_law, P.vapour, P.vmax
sph.artificial_stress, sph.tension = P.artificial_stress, P.tension
sph.continuity_density, sph.renormalised_density, sph.gas_pressure = P.continuity, P.renormalised, P.gas_pressure
sph.dough_water, sph.own_squeeze, sph.hourglass = P.dough_water, P.own_squeeze, P.hourglass
sph.surface_vent = P.vent -- the cells the air reaches vent (sph_gas.c; docs/validation.md "Cells open to the air")
sph.xsph0 = P.xsph0 -- eq. 4.4 at the raw end (Table 4.1: 0.05)
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.16, 0.12 } }, solver = "sph", sph = sph,
  oven = { temperature = P.oven, beta = 0, radiation_scale = 400 }, browning = true, browning_scale = 400, -- S: walls by --set
  latent_heat = P.crust or nil, boiling_point = P.crust and 100 or nil, time_scale = 400 }

local function scaled(c, k, cap)
  local pts = {}
  for i, p in ipairs(c) do pts[i] = { p[1], math.min(p[2] * k, cap or math.huge) } end
  return h.curve(pts)
end
local m = lib.material
m.viscosity = scaled(lib.material.viscosity, P.visc_scale, P.visc_cap)
if P.mu_e_curve == "table" then m.mu_e = scaled(lib.paper.mu_e, P.mue_scale) end
local bubble_m = {}
for k, v in pairs(m) do bubble_m[k] = v end
-- The crust's water (#18, helper userfix6): saturation is the water's volume over the particle's, s = W / (rho_0^w V)
-- (Ding et al. eq. 8; sph_water.c's V is the rest volume m / rho_0). h.library.dough.bread's 0.218 is 45% wet basis
-- in its crumb of 484 kg/m^3, a volume that holds its pores; this roll's dough particles are the dough between its
-- bubbles, 1100 kg/m^3, so the same 45% is 0.45 x 1100 / 1000 = 0.495 (0.218 there was 19.8%, while the dried
-- crust's heat capacity, 907.5 = 0.55 x 1650 J/(kg K), takes 45%: its slope (2700 - 907.5) x 1100 / 218 = 9045
-- J/(kg K) per kg of water, twice water's own; at 0.495 it is 3983, 5% under water's 4180 as the 2700 is 3% under
-- Choi and Okos's 2.79). bread_of_the_dead.lua's dough takes the same.
local WET_BASIS = 0.45
local s0 = P.crust and WET_BASIS * m.density / 1000 or nil
if P.crust then -- the bread's water and dried crust (lua/hearth/dough_physical.lua), on the scene's time scale
  local g = h.library.dough.bread
  m.specific_heat, m.conductivity = g.specific_heat, g.conductivity -- SPH reads only dry_conductivity / conductivity
  -- eq. 22: D = K theta s, so K = D / (373.15 s0) for the bread's D at 373 K; its evaporation, both on S = 400
  local raw = require("hearth.dough_physical").goods.bread -- the preset's own figures, before its S = 300
  m.water_diffusivity = raw.water_diffusivity_m2s / (373.15 * s0) * 400
  m.evaporation = raw.evaporation * 400
  if P.dry then m.dry_conductivity, m.dry_specific_heat = g.dry_conductivity, g.dry_specific_heat end
end
local dough = h.material("maxwell_sph", m)
bubble_m.bubble = 1
local bubble = h.material("maxwell_sph", bubble_m)

local c = { 0.08 + P.shift * P.dx, 0.01 + P.radius }
local roll = h.disc(c, P.radius)
local gas
if P.bubbles == "centre" then
  gas = h.disc(c, P.radius * 0.5)
elseif P.bubbles == "even" then
  local spots = {}
  for j = -2, 2 do
    for i = -2, 2 do
      local x, y = c[1] + i * P.radius * 0.36, c[2] + j * P.radius * 0.36
      if (x - c[1]) ^ 2 + (y - c[2]) ^ 2 < (0.85 * P.radius) ^ 2 then
        spots[#spots + 1] = h.disc({ x, y }, P.radius * 0.125)
      end
    end
  end
  gas = h.union(table.unpack(spots))
elseif P.bubbles == "dispersed" then
  -- one bubble particle in four, each on its own among dough particles (the
  -- particles sit at the cell centres ((i + 1/2) dx, (j + 1/2) dx); bubbles at
  -- even i and j): no two bubbles touch, so a film is never thinner than one
  -- dough particle however far the bubbles grow (Fig. 4.4a's bubbles are
  -- single particles among the dough's)
  local spots, d = {}, P.dx
  for j = math.floor((c[2] - P.radius) / d), math.ceil((c[2] + P.radius) / d) do
    for i = math.floor((c[1] - P.radius) / d), math.ceil((c[1] + P.radius) / d) do
      if i % 2 == 0 and j % 2 == 0 then spots[#spots + 1] = h.disc({ (i + 0.5) * d, (j + 0.5) * d }, 0.3 * d) end
    end
  end
  gas = h.union(table.unpack(spots))
end
s:add { shape = h.difference(roll, gas), material = dough, ppc = 1, jitter = 0, temperature = lib.table.T0 + P.warm,
  saturation = s0 }
local n_dough = #s:positions() // 3 -- ids 0 .. n_dough - 1: the dough's; the bubbles' follow (gas: no water)
if P.trace then
  print(("trace: the dough's particles are ids 0-%d, the bubbles' from %d"):format(n_dough - 1, n_dough))
  print("trace: trace_NNNN.csv (and particles_NNNN.csv) is the frame at t = (NNNN - 1) x 0.1 s, frames/*_(NNNN - 1).png")
end
if P.crust then -- the water the dough was given, read back from its particles, as a share of its mass
  local r = s:particles { fields = { "saturation" } }
  local lo, hi = math.huge, -math.huge
  for i = 1, n_dough do lo, hi = math.min(lo, r.saturation[i]), math.max(hi, r.saturation[i]) end
  print(("crust: the dough's water, saturation %.4f-%.4f of rho_w 1000 kg/m^3 in its %g kg/m^3: %.1f%% wet basis "
    .. "(h.library.dough.bread's, whose dried heat capacity takes %g%%)"):format(lo, hi, m.density,
    100 * hi * 1000 / m.density, 100 * WET_BASIS))
end
s:add { shape = h.intersection(roll, gas), material = bubble, ppc = 1, jitter = 0, temperature = lib.table.T0 + P.warm }
s:collider { shape = h.plane({ 0, 0.01 }, { 0, 1 }), mode = "slip", temperature = P.oven, beta = 0 }

-- relative volume: area of the material in a density slice (NaN is outside)
local function area()
  local rows = s:slice("density", { res = { 160, 120 } })
  local n = 0
  for _, r in ipairs(rows) do for _, v in ipairs(r) do if v == v then n = n + 1 end end end
  return n * (0.16 / 160) * (0.12 / 120)
end
local A0 = area()
local csv = { "t_s,relative_volume,coolest_T_degC" }
-- particle positions (x_m, y_m) for measures that do not go through the density field
-- (tests/sph_roll_measure.py: occupied area and connected pieces)
local function positions(path)
  local x, rows = s:positions(), { "x_m,y_m" }
  for i = 1, #x // 3 do rows[#rows + 1] = ("%.6g,%.6g"):format(x[3 * i - 2], x[3 * i - 1]) end
  h.write(path, table.concat(rows, "\n") .. "\n")
end
positions("particles_0000.csv")
-- the frames' titles give the real time the scene's S = 400 stands for, then the simulated seconds; browning
-- is drawn as a slice, as the temperature is: as particles, the bubbles (gas, no browning: NaN) drew as
-- dark grey discs, which on the browning map read as burnt spots through the crumb
s:run { until_t = 3, every = 0.1, png = { field = "browning", path = "frames/browning_%04d.png", time_scale = 400,
  kind = "slice" },
  on_frame = function(f)
    local T, cool = s:particles { fields = { "temperature" } }.temperature, math.huge
    for i = 1, #T do cool = math.min(cool, T[i]) end
    csv[#csv + 1] = ("%.4f,%.5f,%.2f"):format(f.t, area() / A0, cool)
    h.write("volume.csv", table.concat(csv, "\n") .. "\n")
    f:png("temperature", "frames/temperature_%04d.png", { time_scale = 400 })
    positions(("particles_%04d.csv"):format(#csv - 1))
    if P.trace then -- the particles' state by id (scripts/validation/sph_roll_spots.py reads it; helper rolltear)
      local fields = { "id", "x", "v", "temperature", "pressure", "density", "boundary", "stress_yy" }
      if P.vent then fields[#fields + 1] = "gas_left" end -- the share of a bubble's gas still in it (NaN: dough)
      local r = s:particles { fields = fields }
      local rows = { "id,x_m,y_m,vx_m_s,vy_m_s,T_degC,p_Pa,rho_kg_m3,outer,syy_Pa" .. (P.vent and ",gas_left" or "") }
      for i = 1, r.n do
        rows[#rows + 1] = ("%d,%.6g,%.6g,%.5g,%.5g,%.5g,%.6g,%.6g,%g,%.6g"):format(r.id[i], r.x[3 * i - 2],
          r.x[3 * i - 1], r.v[3 * i - 2], r.v[3 * i - 1], r.temperature[i], r.pressure[i], r.density[i], r.boundary[i],
          r.stress_yy[i]) .. (P.vent and (",%.6g"):format(r.gas_left[i]) or "")
      end
      h.write(("trace_%04d.csv"):format(#csv - 1), table.concat(rows, "\n") .. "\n")
    end
  end }
print(("bread roll (%s bubbles): relative volume %.3f at t = %.2f s"):format(P.bubbles, area() / A0, s:stats().t))
if P.crust then -- the rim against the centre: browning, saturation (the dough's), temperature
  local r = s:particles { fields = { "x", "browning", "saturation", "temperature", "id" } }
  local n, cx, cy = #r.browning, 0, 0
  local x = r.x
  for i = 1, n do cx, cy = cx + x[3 * i - 2] / n, cy + x[3 * i - 1] / n end
  local far = 0
  for i = 1, n do far = math.max(far, math.sqrt((x[3 * i - 2] - cx) ^ 2 + (x[3 * i - 1] - cy) ^ 2)) end
  local acc = { rim = { 0, 0, 0, 0 }, centre = { 0, 0, 0, 0 } }
  for i = 1, n do
    local d = math.sqrt((x[3 * i - 2] - cx) ^ 2 + (x[3 * i - 1] - cy) ^ 2)
    local a = d > far - 0.003 and acc.rim or d < 0.2 * P.radius and acc.centre or nil
    if a then
      a[1], a[4] = a[1] + 1, a[4] + r.temperature[i]
      if r.id[i] < n_dough then -- the dough's: bubbles are gas, with no water and no crust of their own
        a[2], a[3], a[5] = a[2] + r.browning[i], a[3] + r.saturation[i], (a[5] or 0) + 1
      end
    end
  end
  for _, k in ipairs { "rim", "centre" } do
    local a = acc[k]
    -- a coarse roll's centre can hold bubbles alone (3 mm: its four centre particles): no dough to read there
    local dough = (a[5] or 0) > 0 and ("dough's browning %.4f and saturation %.4f"):format(a[2] / a[5], a[3] / a[5])
      or "no dough particle there to read browning and saturation from"
    print(("crust (dry %s): %s %d particles (%d dough), %s, temperature %.1f degC"):format(
      tostring(P.dry), k, a[1], a[5] or 0, dough, a[4] / a[1]))
  end
end

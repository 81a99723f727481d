-- Cookies (Ding et al. 2019, Fig. 3): dough balls baked on a hot tray, a 3 x 3
-- grid of leavener (alpha^g in Table 2 units: 0.015, 0.0075, 0) x oven
-- temperature. Each oven is its own bake (the oven air is one temperature per
-- scene), with the three leaveners side by side on one tray.
--   hearth run scripts/scenes/baking/cookies.lua [--set dim=3] [--set ovens=150]
--   [--set baseline=true]   the Stomakhin et al. 2014 comparison of Fig. 17:
--                           the snow_plastic plugin (Stomakhin et al. 2013's
--                           law: fixed corotated, elastic stretch clamped to
--                           [1 - 2.5e-2, 1 + 7.5e-3], hardening xi = 10) with
--                           the cookie's E, nu, density and heat; no gas, no
--                           viscoplasticity and no thermal expansion (Ding et
--                           al. §2: neither Stomakhin et al. nor Gao et al.
--                           model expansion). Heat still flows.
--   [--set reaction_temperature=10 --set reaction_width=10 --set gas=3]
--                           the leavener's kinetics moved off Table 2 (theta_r, dtheta
--                           in degC; gas multiplies alpha^g), for docs/validation.md
--                           "The cookie's gas: when, where, and eq. 12"; not a preset.
--   [--set conductivity=1]  Table 2's kappa (30 W/(m K)); the scene's default
--                           0.01 is a real dough's (below, "The oven").
--   [--set tray_mode=sticky --set tray_friction=1
--    --set water=true --set soft_until=60 --set max_porosity=0.6]
--                           the levers of docs/validation.md "The cookie: tray,
--                           crust, conduction and 3D" (#18, session 28): the
--                           tray's contact (h.recipes.tray: separate, 0.4);
--                           water as bread's (dough.lua WATER: s_0 0.10 for a
--                           20 % wb cookie dough, so the surface dries and
--                           dough.lua's DRY curve stiffens it); bread's Fig. 8
--                           points (set at 70 degC) with tau_y and eta held at
--                           their 35 degC values up to soft_until degC (the
--                           levers of sessions 26-28, before the preset took its
--                           own set, dough.lua's COOKIE_SET); the plugin's pore
--                           cap. Not presets: the defaults are Table 2's cookie
--                           with a real dough's conductivity.
--   [--set preset=physical] h.library.dough.cookie (#18: a sugar-snap dough's density,
--                           heat capacity and conductivity, its rates 50 times fast, latent
--                           heat, boiling and browning on; 13.2 s stand for 11 minutes and the
--                           frames' titles give the real time) in each oven of --set ovens
--                           (h.library.oven.cookie's own bake is 190 degC); the same cookies,
--                           each leavener a scaling the preset's CO2 rate by a / 0.015. It also
--                           writes oven_<T>/browning.png (3D: a slab 2 dx thick about the middle
--                           plane) and prints each cookie's browning at its
--                           top, rim, base and centre. Measured (2D, dx 5 mm): the unleavened
--                           cookie barely spreads (its measured yield stress, 61.5 Pa in shear once
--                           the fat melts, holds its 17.5 mm: 62 -> 66 mm on the drawing sheet, raw.csv
--                           against cookies.csv; docs/validation.md "Does the physical cookie spread on
--                           the drawing sheet? (#18, helper cookiespread2)"); the soda's CO2 (0.069 mol/kg) comes
--                           in two shares, the NH4Cl one on a 60 degC bell before the 78 degC set
--                           and the leftover soda's at 100 degC, and the leavened cookie stands
--                           1.51x the unleavened at 190 degC (94 mm wide), 1.86x at 150, 1.97x at
--                           110 (41.0 against 20.8 mm, commit 80e63bd; 2.20x before each share stopped at
--                           its amount, below) (docs/validation.md "The physical cookie's two shares (#18, helper
--                           sodatwo)"; since open pores vent toward the atmosphere, not to a vacuum,
--                           the 150 and 110 degC cookies no longer shed pieces, and at 110 the most
--                           leavened is a foam of J ~3.5: "The physical cookie in the cooler ovens
--                           (#18, helper cookiecool)"; each share now stops at the formula's amount,
--                           0.042 mol/kg of the NH4Cl share and 0.027 of the soda, where the bell alone
--                           made 0.056 of the first at 110 degC: "A leavener runs out (#18, helper
--                           depletion)"). The leavener a scales both of the preset's shares (their
--                           rates and amounts) by a / 0.015, so 0.015 is the formula's. until_t = 0 bakes the preset's own time (paper 5 s).
--   [--set seed=2]        the particles' jitter (h.scene's seed, default 1): a
--                           new sampling of the same dough, to see a reading's
--                           noise (docs/validation.md, "Fig. 17: the top's
--                           curvature and its noise").
-- Writes, under hearth-out/cookies/: oven_<T>/heat_%04d.png (the heat
-- progress, Fig. 3's right column), raw.csv (each cookie's height and spread as placed, by the same probe) and
-- cookies.csv (final height, spread and
-- top curvature per cookie; negative curvature = domed; alone = 1 when no
-- other cookie reaches its slot, so its readings are its own; particles, and shed: how many of them lie
-- beyond two spacings of its largest piece, shed_swollen the same with the link stretched by J; see shed
-- below), series.csv (height
-- and spread over time). Two curvatures: top_curvature from the density
-- probe's top over the middle third of the spread (9 samples), and
-- top_curvature_particles from the highest particle in each one-cell bin,
-- a least-squares parabola over the middle 60% of the cookie's width
-- (h.top_curvature), and top_curvature_particles_se that fit's standard error.
-- Both read the top's change since the dough was placed (flat-topped, so its
-- curvature): the probe's heights less the raw dough's where the material
-- on top was placed, the particles' displacements since placing. Read from heights alone a static
-- flat top reads the seeding's jitter, +-3 1/m at dx 3.75 mm (#18 helper
-- fig17c, docs/validation.md "Fig. 17 at 3.75 mm: the jitter, read and removed").
-- What shaped the top with Table 2's heat and the 25 mm dough (measured, 2D, dx
-- 7.5 mm, 150 degC, before helper flat3; "The oven" below for now): the cold dough
-- (tau_y 20 Pa) cannot carry its own 25 mm (rho g H ~ 120 Pa); with eta the
-- full model slumps slowly, and once its fat has melted (35 degC) it spreads
-- soft until its gluten sets at 71-78 degC (dough.lua, COOKIE_SET), ~1.6 s;
-- the CO2 (Table 2: 40 +- 20 degC) is made while it is soft and puffs the
-- leavened cookie (area +73%) while the unleavened one spreads flatter
-- (docs/validation.md, "The cookie's set"). The baseline does not flow at all: its
-- weight strains it ~0.2%, inside the snow law's clamp, so it keeps the
-- placed dough's shape (a capsule: flat top, round ends) through the bake;
-- read from heights alone its top scattered within ~2 1/m of 0, either sign,
-- from one particle sampling (--set seed) to the next (docs/validation.md,
-- "Fig. 17: the top's curvature and its noise"); read as its change since
-- placing it is its elastic settling, -0.003 to -0.11 1/m.
-- The oven (issue #18, docs/validation.md "The unleavened cookie's top: a real
-- dough's heat"): Table 2's cookie conducts 30 W/(m K) with c 20 J/(kg K), so it
-- bakes evenly (Biot beta L / kappa = 25 x 0.00875 / 30 ~ 0.007) and spreads as a
-- puddle held by the tray, which domes (Huppert 1982). A real cookie dough
-- conducts 0.29-0.5 W/(m K) (0.35 from its composition by Choi & Okos, as
-- h.library.dough.cookie; 0.29-0.45 measured in unleavened doughs, Budzaki &
-- Seruga 2015, Int. J. Food Prop. 18:2300), so in a real oven (beta 20-48
-- W/(m^2 K), Baik et al. 1999, J. Food Sci. 64:688; Table 2's 25 and the tray's 35)
-- its Biot number is ~1: the base and rim set before the centre, the unleavened
-- dough sets flat on its set base and the leavened centre still rises inside a
-- set rim (Ding Fig. 17). conductivity = 0.01 (x Table 2's kappa: 0.3 W/(m K))
-- gives that Biot number; the heat then runs ~220x a real dough's (diffusivity
-- 3e-5 against 1.4e-7 m^2/s: a 15-minute bake in 4 s), and every cookie has set
-- (71-78 degC, COOKIE_SET) by ~3.5 s at 150 degC (centre 76-78 degC at 3 s, 95 at 4 s).
-- Columns without a unit (tests/scene_csv.py's unit rule; #18, helper userfix7): leavener, Table 2's alpha^g of the
-- cookie (animation units, a label: 0.015 the formula's); alone and shed, shed_swollen, a flag and counts (above).
-- cookies.csv has no unit: leavener, alone, shed, shed_swollen
-- series.csv has no unit: leavener
-- raw.csv has no unit: leavener
local h = require "hearth"
-- The levers that change Table 2's cookie (below, each where it acts), with their defaults: preset=paper's only.
local PAPER_LEVERS = { baseline = false, reaction_temperature = -1, reaction_width = -1, conductivity = 0.01,
  water = false, soft_until = -1, max_porosity = -1 }
-- each lever's valid range (h.number; -1: the preset's own value, as the scene reads it below) or what it switches
-- (h.flag)
local LEVER_RANGES = {
  baseline = h.flag { false, what = "Fig. 17's comparison: Stomakhin et al.'s snow law, no gas, no expansion" },
  water = h.flag { false, what = "the dough carries bread's water (s_0 0.10): its surface dries and stiffens" },
  reaction_temperature = h.number { -1, min = 0, unit = "degC", what = "the CO2 reaction's temperature",
    also = { [-1] = "the preset's" } },
  reaction_width = h.number { -1, above = 0, unit = "degC", what = "the CO2 reaction's width",
    also = { [-1] = "the preset's" } },
  conductivity = h.number { 0.01, above = 0, what = "a factor on Table 2's kappa" },
  -- Fig. 8's fat-melting and gelatinisation points
  soft_until = h.number { -1, above = 35, below = 70, unit = "degC", what = "the end of the soft spread",
    also = { [-1] = "Table 2's curve" } },
  max_porosity = h.number { -1, above = 0, below = 1,
    what = "the gas porosity's cap", also = { [-1] = "the preset's" } } }
local defaults = { dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" },
  dx = h.number { 0.005, above = 0, unit = "m", what = "the grid spacing" },
  until_t = h.number { 0, min = 0, unit = "s", what = "the bake's simulated time (0: the preset's own)" },
  frames = h.number { 5, min = 1, integer = true, unit = "frames", what = "PNG frames over the bake" },
  -- at most a dozen of each (muffins.lua's cups likewise): each oven is a bake and each leavener a cookie on every
  -- tray, so the cost grows with the count (a list of 10000 leaveners had laid a tray 10000 cookies wide)
  ovens = h.number { { 190, 150, 110 }, list = true, max_count = 12, min = -273.15, max = 5000, unit = "degC",
    what = "the ovens' temperatures, one bake each" },
  leaveners = h.number { { 0.015, 0.0075, 0 }, list = true, max_count = 12, min = 0,
    what = "the cookies' leaveners, side by side on each tray (0.015: the formula's)" },
  gas = h.number { 1, min = 0, what = "a factor on the CO2 rates (and the physical preset's amounts)" },
  tray_mode = h.choice("separate", h.contact_words),
  tray_friction = h.number { 0.4, min = 0, what = "the tray's Coulomb friction coefficient" },
  seed = h.number { 1, min = 0, integer = true, what = "the particles' seeding (0 acts as 1)" },
  -- vent: the scene setting gas_vent (below); -1: the preset's
  vent = h.number { -1, min = 0, unit = "m/s", what = "the CO2 vent velocity of open surface pores",
    also = { [-1] = "the preset's" } },
  preset = h.choice { "paper", paper = "h.library.paper.cookie: Ding Table 2, animation units",
    physical = "h.library.dough.cookie: a real sugar-snap dough's properties, its bake in real minutes mapped" } }
for k, v in pairs(PAPER_LEVERS) do defaults[k] = LEVER_RANGES[k] or v end
local P = h.params(defaults)
-- preset=physical (#18): h.library.dough.cookie and h.library.oven.cookie (lua/hearth/dough_physical.lua: each
-- number's source; its rates run S = 50 times fast, so the 11 minute bake at 190 degC takes 13.2 s), latent heat,
-- boiling and browning on. The same cookies: leavener a multiplies the preset's CO2 rates (both shares; cookies.csv's
-- gas_rate_mol_per_kg_s column is the first's, gas_rate) by a / 0.015, the
-- leavener its rate stands for (Table 2's cookie alpha^g), as the paper path's gas_rate is a x GAS_SCALE. The
-- PAPER_LEVERS are the paper preset's only; gas and the grid's words hold for both.
local physical = P.preset == "physical"
if physical then
  local levers = {}
  for k in pairs(PAPER_LEVERS) do levers[#levers + 1] = k end
  table.sort(levers) -- the first one set, named the same way every run
  for _, k in ipairs(levers) do
    if P[k] ~= PAPER_LEVERS[k] then
      h.refuse(("--set %s=%s: a lever on Table 2's cookie, for preset=paper only (the physical dough's numbers are "
        .. "its own, lua/hearth/dough_physical.lua)"):format(k, tostring(P[k])))
    end
  end
end
-- until_t 0: the preset's own bake (paper 5 s; physical h.library.oven.cookie.bake_time, 13.2 s for 11 minutes)
-- vent (m/s, the scene setting gas_vent; 0 = Ding et al.'s closed skin): a surface particle whose pores have
-- opened (gas porosity >= 0.7, vent_porosity) loses its CO2 to the oven air (core/sim/fields/gas.c). 5 m/s is
-- an open pore's ~0.02 m/s (CO2 diffusing out across a millimetre) at Table 2's heat, which bakes the cookie
-- ~250 times fast (a 10-minute bake in 2.5 s); any value past ~1 m/s vents an open pore within a few steps.
-- Without it the leavened cookie's top and rim swell past its crumb (issue #18, docs/validation.md "The
-- cookie's skin"). -1: the preset's, 5 m/s for paper and h.library.oven.cookie.gas_vent (0.02 m/s x S) for physical.
local d3 = P.dim == 3
local dx = h.dx_3d(P.dx, 0.01, d3) -- says so when it raises dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
local ovens, leaveners = P.ovens, P.leaveners

local oven = physical and h.library.oven.cookie or h.library.paper_oven.cookie
local S = physical and oven.time_scale or nil -- the physical preset's rates run S times fast: t_real = S t
local vent = P.vent ~= -1 and P.vent or physical and oven.gas_vent or 5
local until_t = P.until_t > 0 and P.until_t or physical and oven.bake_time or 5
-- the leavener the physical preset's CO2 rate stands for: Table 2's cookie alpha^g (h.library.paper.cookie's rate
-- is it x GAS_SCALE)
local A_PRESET = h.library.paper.cookie.gas_rate / h.library.dough_scale.gas
if physical then
  print(("cookies.lua: h.library.dough.cookie, %s; bake %.1f min in %.1f s; open surface pores vent CO2 at %g m/s")
    :format(oven.units, until_t * S / 60, until_t, vent))
else
  print(("cookies.lua: h.library.paper.cookie, animation units (Ding Table 2) with its conductivity x%g (1: Table 2's; "
    .. "0.01: a real dough's): heat runs in seconds, not minutes; open surface pores vent CO2 at %g m/s (--set vent=0: "
    .. "none)"):format(P.conductivity, vent))
end
-- m: tray height, cookie spacing, dough radius and height. Each cookie is read
-- in its own slot (SPACING wide, centred on it), so the slot must hold the
-- cookie's whole spread: at 0.12 m the leavened cookie (60 mm raw, 110-130 mm
-- baked, plane strain) reached the box's wall (its particles 1.6 cells from
-- it at dx 5 mm; the walls act on the two node layers nearest each face) and
-- its neighbour's slot, whose spread then read its rim (the unleavened
-- cookie: 102 mm for its own 83, #18). 0.18 m keeps each cookie's centre on a
-- grid node at dx 7.5, 5 and 3.75 mm, as 0.12 m did.
-- The dough: 60 mm wide and 17.5 mm thick (25 mm until #18 helper flat3). A real
-- cookie is a thin disc: AACC Method 10-50.05 rates sugar-snap cookies by their
-- spread factor W/T, ~8-10 baked, from dough sheeted and cut several times wider
-- than thick (a ~7 mm sheet cut 60 mm wide, as we recall the method; not checked
-- against its text). A 7 mm sheet is one cell at the claims' coarse dx 7.5 mm;
-- 17.5 mm is the thinnest of 15, 17.5 and 20 mm that every cookie claim reads at
-- 7.5 mm (at 15 mm, two cells, the measures read the baseline capsule's round ends
-- into its top: -45 1/m; at 20 mm the coarse probe read the unleavened top rounder
-- than the leavened in its one sampling; docs/validation.md "The unleavened
-- cookie's top: a real dough's heat"). With a real conductivity the 25 mm dough
-- baked to W/T 3.1 (73 / 23.5 mm at dx 5 mm), this one to 3.6 (66 / 18 mm).
local TRAY, SPACING, R, THICK = 0.02, 0.18, 0.03, 0.0175
local W = SPACING * #leaveners
local zc = 0.06

local rows = { "oven_degC,leavener,gas_rate_mol_per_kg_s,height_m,spread_m,top_curvature_1_per_m,top_curvature_particles_1_per_m,alone,top_curvature_particles_se_1_per_m,particles,shed,shed_swollen" }
-- series.csv's t_s is the simulated time (the paper preset's Table 2 animation units; the physical preset's S times
-- fast, whose real time t_real_s = S t_s comes last, as pancake.lua's and lava_cake.lua's)
local series = { "oven_degC,leavener,t_s,height_m,spread_m,centre_temperature_degC" .. (S and ",t_real_s" or "") }
-- raw.csv: each cookie's height and spread as placed, by the same probe as cookies.csv's (issue #18, helper
-- cookiespread: claim_cookie_physical_spreads compares the baked cookie with its raw dough at each dx)
local raw_rows = { "oven_degC,leavener,height_m,spread_m" }
for _, T in ipairs(ovens) do
  local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(W, 0.09, 0.12) },
    oven = { temperature = T, beta = oven.beta, wall_temperature = oven.wall_temperature,
      emissivity = oven.emissivity, radiation_scale = oven.radiation_scale }, gas_vent = vent, name = "cookies", seed = P.seed,
    browning = physical or nil, browning_scale = S, latent_heat = physical and oven.latent_heat or nil,
    boiling_point = physical and oven.boiling_point or nil, vent_porosity = physical and oven.vent_porosity or nil,
    time_scale = S, time_units = physical and "real" or "animation" }
  -- the physical preset's sheet goes in cold (oven.pan_start_temperature, pan_warm_time: dough_physical.lua) and the
  -- dough draws its heat from it (oven.pan_heat_capacity): the sheet is the box's floor, each cookie's 0.18 m share
  -- of it, a third under the dough (2D: per metre of depth; 3D: the box's 0.12 m deep)
  local tray = h.recipes.tray(s, TRAY, h.recipes.pan(oven, P.dim == 3 and W * 0.12 or W,
    { temperature = T, mode = P.tray_mode, friction = P.tray_friction }))
  local xs, first, gas_of = {}, {}, {} -- gas_of[i]: the physical cookie i's CO2 rate (mol/(kg s), S times fast); first[i]: cookie i's first particle id (ids run in the order s:add made them)
  for i, a in ipairs(leaveners) do
    local d = physical and h.library.dough.cookie or h.library.paper.cookie
    if physical then -- both of the preset's CO2 shares (its NH4Cl share is gas_rate_2, dough_physical.lua)
      d.gas_rate = d.gas_rate * a / A_PRESET * P.gas; gas_of[i] = d.gas_rate
      if d.gas_rate_2 then d.gas_rate_2 = d.gas_rate_2 * a / A_PRESET * P.gas end
      -- and each share's amount (its reactant: the leavener), the same factor
      if d.gas_amount then d.gas_amount = d.gas_amount * a / A_PRESET * P.gas end
      if d.gas_amount_2 then d.gas_amount_2 = d.gas_amount_2 * a / A_PRESET * P.gas end
    else d.gas_rate = a * h.library.dough_scale.gas * P.gas end
    if not physical then d.conductivity = d.conductivity * P.conductivity end
    local S0, WATER_S = 0.10, 600 -- the levers above: water as dough.lua's WATER (2e-7 m^2/s, 1.2e-3 kg/(m^2 s K), x600)
    if P.water then d.saturation, d.water_diffusivity, d.evaporation = S0, 2e-7 / (373.15 * S0) * WATER_S, 1.2e-3 * WATER_S end
    if P.soft_until ~= -1 then -- Table 2's cookie (tau_y 20 Pa, eta 500 x ETA_SCALE) with Fig. 8's 35 degC point held to soft_until
      local e = 500 * h.library.dough_scale.eta
      d.tau_y = h.curve { { 5, 20 }, { 20, 16 }, { 35, 6 }, { P.soft_until, 6 }, { 70, 400 }, irreversible = true }
      d.eta = h.curve { { 5, e }, { 20, 0.5 * e }, { 35, 0.1 * e }, { P.soft_until, 0.1 * e }, { 70, 0.05 * e }, irreversible = true }
    end
    if P.max_porosity > 0 then d.max_porosity = P.max_porosity end
    if P.reaction_temperature >= 0 then d.reaction_temperature = P.reaction_temperature end
    if P.reaction_width > 0 then d.reaction_width = P.reaction_width end
    -- the baseline: the cookie's E, nu, density and heat; the snow law's theta_c, theta_s, xi (plugin defaults)
    local mat = P.baseline and h.material("snow_plastic", { E = d.E, nu = d.nu, density = d.density,
      specific_heat = d.specific_heat, conductivity = d.conductivity, reference_temperature = d.reference_temperature })
      or h.material("cam_clay_dough", d)
    xs[i] = (i - 0.5) * SPACING
    first[i] = s:stats().particles
    s:add { shape = h.shapes.cookie(v(xs[i], TRAY + THICK / 2, zc), R, THICK), material = mat,
      temperature = oven.dough_temperature, saturation = physical and oven.saturation or P.water and S0 or nil, ppc = d3 and 8 or 4 }
  end
  first[#leaveners + 1] = s:stats().particles
  local function cookie_of(id) -- which cookie particle id belongs to
    for i = 1, #leaveners do if id < first[i + 1] then return i end end
  end
  -- alone: 1 when every particle of cookie i lies 2.5 cells or more inside
  -- its slot. A particle's mass reaches the grid nodes up to 1.5 cells away,
  -- so the cookie then touches neither the box's wall layers (the two nodes
  -- nearest each face) nor a node its neighbour touches (when that one is
  -- alone too), and the density line across its slot reads it only.
  local function alone(i)
    local r = s:particles { fields = { "id", "x" } }
    for p = 1, r.n do
      if cookie_of(r.id[p]) == i and math.abs(r.x[3 * p - 2] - xs[i]) > SPACING / 2 - 2.5 * dx then return 0 end
    end
    return 1
  end
  -- shed(i): is cookie i one piece? Its particles linked when within two seeded spacings (dx: s:add seeds ppc 4
  -- in 2D and 8 in 3D, dx/2 apart), the count outside the largest linked group (issue #18, helper cookiecool:
  -- the most leavened physical cookie shed 6-7% of its particles in the 150 and 110 degC ovens), and its
  -- particle count. A swollen foam's spacing (dx/2 sqrt(J) in 2D: 0.85 dx at J 2.9) comes near the link, so a
  -- lone interior particle can read as shed; a piece a baker would see is a group.
  -- shed(i, true): the same with the link stretched to each pair's swelling, dx max(J_a, J_b)^(1/dim) (cells of
  -- 2 dx, the link at most 2 dx): a foam whose spacing has grown past dx reads whole, a piece still apart; a
  -- reading made after the bar above was seen (cookies.csv's shed_swollen), not a bar.
  local function shed(i, swollen)
    local r = s:particles { fields = swollen and { "id", "x", "J" } or { "id", "x" } }
    local L = swollen and 2 * dx or dx
    local px, parent, cell, n = {}, {}, {}, 0
    local function find(a) while parent[a] ~= a do parent[a] = parent[parent[a]]; a = parent[a] end return a end
    local function key(a, b, c) return (a * 4096 + b) * 4096 + c end
    for p = 1, r.n do
      if cookie_of(r.id[p]) == i then
        n = n + 1
        px[n] = { r.x[3 * p - 2], r.x[3 * p - 1], d3 and r.x[3 * p] or 0,
          j = swollen and math.min(r.J[p] ^ (1 / (d3 and 3 or 2)), 2) or 1 }
        parent[n] = n
        local c = { math.floor(px[n][1] / L), math.floor(px[n][2] / L), math.floor(px[n][3] / L) }
        px[n].c = c
        local k = key(c[1], c[2], c[3])
        cell[k] = cell[k] or {}
        table.insert(cell[k], n)
      end
    end
    for a = 1, n do
      local c = px[a].c
      for ox = -1, 1 do for oy = -1, 1 do for oz = d3 and -1 or 0, d3 and 1 or 0 do
        for _, b in ipairs(cell[key(c[1] + ox, c[2] + oy, c[3] + oz)] or {}) do
          if b > a then
            local u, w, z = px[a][1] - px[b][1], px[a][2] - px[b][2], px[a][3] - px[b][3]
            local l = dx * math.max(px[a].j, px[b].j)
            if u * u + w * w + z * z <= l * l then parent[find(a)] = find(b) end
          end
        end
      end end end
    end
    local size, big = {}, 0
    for a = 1, n do local f = find(a); size[f] = (size[f] or 0) + 1; if size[f] > big then big = size[f] end end
    return n - big, n
  end
  -- line_h(x): the probe's height above the tray at x (in 3D on the plane z = zc): the highest of 1401
  -- samples up the line where the probe reads material, then bisected between it and the sample above to
  -- 12 halvings (0.05 mm / 4096). Why: the samples alone step by 0.05 mm, which scatters the nine-point
  -- curvature below by ~0.25 1/m whatever the top (docs/validation.md "Fig. 17 at 3.75 mm: the jitter, read
  -- and removed").
  local LINE_STEP = (0.09 - TRAY) / 1400
  local function line_h(x)
    local dd = s:line("density", v(x, TRAY, zc), v(x, 0.09, zc), 1401)
    local k0
    for k, val in ipairs(dd) do if val == val then k0 = k end end
    if not k0 then return 0 end
    local a, b = (k0 - 1) * LINE_STEP, k0 * LINE_STEP -- material at a, none at b
    if k0 == #dd then return a end
    for _ = 1, 12 do
      local m = (a + b) / 2
      local val = s:probe("density", v(x, TRAY + m, zc))
      if val == val then a = m else b = m end
    end
    return a
  end
  -- The raw dough's reading, the measures' zero (docs/validation.md "Fig. 17 at 3.75 mm: the jitter, read and
  -- removed"): the placed top is flat, so whatever curvature a measure reads on it is the seeding's jitter
  -- (s:add's particles sit up to a quarter of their spacing off the lattice), which a static cookie keeps
  -- through the bake. rest_x, rest_y: every particle's placed position, by id (rest_y is h.top_curvature's
  -- rest); raw_h[i]: the probe's height across cookie i's slot (every dx/8 over the middle third of the
  -- widest spread the slot holds, linear between), which the probe's curvature fit subtracts where the top
  -- material at each of its sample points was placed (measure below).
  local rest_y, rest_x, raw_h, RAW_STEP, RAW_HALF = {}, {}, {}, dx / 8, SPACING / 6
  do
    local r = s:particles { fields = { "id", "x" } }
    for p = 1, r.n do rest_x[r.id[p]], rest_y[r.id[p]] = r.x[3 * p - 2], r.x[3 * p - 1] end
    for i = 1, #leaveners do
      raw_h[i] = {}
      for j = -math.ceil(RAW_HALF / RAW_STEP) - 1, math.ceil(RAW_HALF / RAW_STEP) + 1 do raw_h[i][j] = line_h(xs[i] + j * RAW_STEP) end
    end
  end
  local function raw_at(i, u) -- the raw dough's probe height at xs[i] + u
    local f = u / RAW_STEP
    local j = math.floor(f)
    local a, b = raw_h[i][j], raw_h[i][j + 1]
    if not (a and b) then error(("cookies.lua: the raw profile ends at %g m from the centre; asked %g"):format(RAW_HALF, u)) end
    return a + (b - a) * (f - j)
  end
  local function measure(i)
    local c = d3 and { xs[i], zc } or { xs[i] }
    local hgt = line_h(c[1])
    local yb = TRAY + 1.5 * dx
    local dd = s:line("density", v(xs[i] - SPACING / 2, yb, zc), v(xs[i] + SPACING / 2, yb, zc), 241)
    local lo, hi
    for k, val in ipairs(dd) do if val == val then lo = lo or k; hi = k end end
    local spread = lo and (hi - lo) * SPACING / 240 or 0
    -- top curvature: a parabola through heights over the middle third of the spread, each less the raw
    -- dough's where the material on top there was placed (its change since the placed, flat top: the raw
    -- reading is the jitter's). Where it was placed, not the same x: the jitter moves with the particles, and
    -- at dx 7.5 mm the raw reading at the same x (an edge the spread cookie has left) scattered the
    -- unleavened against the leavened reading (docs/validation.md "Fig. 17 at 3.75 mm: ...")
    local n, S2, S4, T0, T2 = 9, 0, 0, 0, 0
    local S0 = n
    local r = s:particles { fields = { "id", "x" } }
    for k = 1, n do
      local u = (k - 5) / 4 * spread / 6
      -- where the top material at xs[i] + u was placed: the highest of the cookie's particles within dx/2 of it
      local top, x0 = -math.huge, xs[i] + u
      for p = 1, r.n do
        local px, py, pz = r.x[3 * p - 2], r.x[3 * p - 1], r.x[3 * p]
        if py > top and math.abs(px - xs[i] - u) < dx / 2 and (not d3 or math.abs(pz - zc) < dx / 2)
          and cookie_of(r.id[p]) == i then
          top, x0 = py, rest_x[r.id[p]] + (xs[i] + u - px)
        end
      end
      local y = line_h(xs[i] + u) - raw_at(i, x0 - xs[i])
      S2, S4, T0, T2 = S2 + u * u, S4 + u ^ 4, T0 + y, T2 + y * u * u
    end
    local a = (S0 * T2 - S2 * T0) / (S0 * S4 - S2 * S2)
    return hgt, spread, 2 * a
  end
  -- the top from the particles (h.top_curvature): the highest of cookie i's
  -- own particles (by id) in each one-cell bin across it (in 3D on the slab
  -- |z - zc| < dx/2), and 2a of the least-squares y = a u^2 + b u + c over the
  -- middle 60% of the cookie's width, with its standard error; each bin's top read as that particle's rise
  -- since it was placed (rest_y above), so the seeding's jitter cancels
  local function particle_curvature(i)
    return h.top_curvature(s, { keep = function(id) return cookie_of(id) == i end, origin = xs[i], bin = dx,
      fraction = 0.6, z = d3 and zc or nil, rest = rest_y })
  end
  for i, a in ipairs(leaveners) do
    local hgt, spread = measure(i)
    raw_rows[#raw_rows + 1] = ("%g,%g,%.5f,%.5f"):format(T, a, hgt, spread)
  end
  h.write("raw.csv", table.concat(raw_rows, "\n") .. "\n")
  -- the leaveners too, left to right as they lie on the tray, when they fit a title's 64 bytes (three cookies with
  -- nothing to say which is which)
  local lv = {}
  for i, a in ipairs(leaveners) do lv[i] = ("%g"):format(a) end
  -- and the paper preset's units (its frames said "t = 5 s" with no word that a second is Table 2's animation
  -- unit; #18, helper userview4): the order goes first, then the leaveners, when the 64 bytes run out
  local units = physical and "" or "; Table 2's animation units"
  local oven_label = ("oven %g °C, leaveners %s left to right%s"):format(T, table.concat(lv, ", "), units)
  if #oven_label > 64 then oven_label = ("oven %g °C, leaveners %s%s"):format(T, table.concat(lv, ", "), units) end
  if #oven_label > 64 then oven_label = ("oven %g °C%s"):format(T, units) end
  s:run { until_t = until_t, every = until_t / P.frames,
    -- one temperature range for every oven (the dough's start to the hottest oven), so their frames compare side
    -- by side; each oven's own run had grown its own range
    -- the title names the oven: a frame looked at alone (or copied out of oven_110/) says which bake it is
    png = { field = "temperature", path = ("oven_%g/heat_%%04d.png"):format(T), time_scale = S,
      range = { oven.dough_temperature, math.max(table.unpack(ovens)) }, label = oven_label },
    on_frame = function(f)
      for i, a in ipairs(leaveners) do
        local hgt, spread = measure(i)
        local tc = s:probe("temperature", v(xs[i], TRAY + 0.01, zc))
        series[#series + 1] = ("%g,%g,%.4f,%.5f,%.5f,%.2f"):format(T, a, f.t, hgt, spread, tc)
          .. (S and (",%.1f"):format(S * f.t) or "")
      end
      h.write("series.csv", table.concat(series, "\n") .. "\n")
    end }
  for i, a in ipairs(leaveners) do
    local hgt, spread, curv = measure(i)
    local pcurv, pse = particle_curvature(i)
    local one = alone(i)
    local off, count = shed(i)
    local off_swollen = shed(i, true)
    rows[#rows + 1] = ("%g,%g,%.3g,%.5f,%.5f,%.4f,%.4f,%d,%.4f,%d,%d,%d"):format(T, a, P.baseline and 0 or physical and gas_of[i] or a * h.library.dough_scale.gas,
      hgt, spread, curv, pcurv, one, pse, count, off, off_swollen)
    if one == 0 then
      print(("cookies.lua: warning: oven %g degC, leavener %g: the cookie reaches the edge of its slot (%.0f mm wide): "
        .. "it touches the box's wall or its neighbour, and its readings are not its own alone"):format(T, a, SPACING * 1e3))
    end
    -- the two curvatures with what each says (#18, helper userview3's item 5: the physical cookie's disagreed in sign
    -- and the line did not say which to read): the claims (tests/baking/cookie.sh) call a top domed when both read
    -- below 0, and take the particles' fit as unresolved when it lies within two of its standard errors of 0
    local pread = pse ~= pse and "no standard error" or math.abs(pcurv) < 2 * pse
      and "flat within noise, |k| < 2 standard errors" or pcurv < 0 and "domed" or "dented"
    print(("oven %g degC, leavener %g: height %.4f m, spread %.4f m; top curvature, below 0 domed (the claims need "
      .. "both): probe %+.3f 1/m, %s; particles %+.3f +- %.3f 1/m, %s; "
      .. "%d of its %d particles beyond two spacings of its largest piece (%d with the link stretched by J)"):format(T, a,
      hgt, spread, curv, curv < 0 and "domed" or curv > 0 and "dented" or "flat", pcurv, pse, pread,
      off, count, off_swollen))
  end
  h.write("cookies.csv", table.concat(rows, "\n") .. "\n")
  if physical then -- the crust's colour (Zanoni et al. 1995's index, 0..1): a picture, and per cookie a printed line
    -- the index's own 0..1; titled with its oven as the heat frames are (it had read 't = 11 min' alone)
    s:png("browning", ("oven_%g/browning.png"):format(T), { time_scale = S, range = { 0, 1 }, label = oven_label })
    local r = s:particles { fields = { "id", "x", "browning" } }
    for i, a in ipairs(leaveners) do
      -- top: the highest particle within dx/2 of the cookie's axis; rim: the one farthest from it; base: the lowest on
      -- the axis; centre: the nearest to the axis' midpoint between base and top
      local top, rim, base, ctr
      for p = 1, r.n do
        if cookie_of(r.id[p]) == i then
          local u, y = math.abs(r.x[3 * p - 2] - xs[i]), r.x[3 * p - 1]
          if not rim or u > math.abs(r.x[3 * rim - 2] - xs[i]) then rim = p end
          if u < dx / 2 and (not d3 or math.abs(r.x[3 * p] - zc) < dx / 2) then
            if not top or y > r.x[3 * top - 1] then top = p end
            if not base or y < r.x[3 * base - 1] then base = p end
          end
        end
      end
      if top then
        local ym = (r.x[3 * top - 1] + r.x[3 * base - 1]) / 2
        for p = 1, r.n do
          if cookie_of(r.id[p]) == i and (not ctr or math.abs(r.x[3 * p - 2] - xs[i]) + math.abs(r.x[3 * p - 1] - ym)
              < math.abs(r.x[3 * ctr - 2] - xs[i]) + math.abs(r.x[3 * ctr - 1] - ym)) then ctr = p end
        end
        print(("oven %g degC, leavener %g: browning top %.3f, rim %.3f, base %.3f, centre %.3f"):format(T, a,
          r.browning[top], r.browning[rim], r.browning[base], r.browning[ctr]))
      end
    end
  end
  local sheet = s:collider_heat(tray)
  if physical and sheet.oven_in > 0 then -- the sheet the dough drew its heat from (colliders.h)
    print(("oven %g degC: the sheet at %.1f min %.1f degC; it gave the dough %.0f J of the oven's %.0f (J%s)"):format(T,
      s:stats().t * S / 60, sheet.temperature, sheet.drawn, sheet.oven_in, d3 and "" or " per metre of depth"))
  end
end

-- hearth.dough: the baked goods of Ding et al. 2019 (Table 2, Fig. 8) as
-- presets for the cam_clay_dough plugin. Scenes use them through
--   h.material("cam_clay_dough", h.library.paper.cookie)   -- parameters and curves
--   h.library.paper_oven.cookie                                     -- oven, pan and dough temperatures
-- Each preset keeps Table 2's column as `paper` next to the numbers used.
--
-- Choices where Table 2 does not say (units, theta scale):
--  * Temperatures are degrees C: theta_0 (dough), ambient theta (oven air)
--    and conductive theta (tray or pan) are taken as printed. The oven's beta
--    is Table 2's ambient beta, the tray's beta its conductive beta, both in
--    W/(m^2 K).
--  * E, density, specific heat and kappa are SI as printed. Specific heat 20
--    J/(kg K) and kappa 30-250 W/(m K) are ~1/100 and ~100x a real dough's:
--    the paper's scaling, which bakes a cookie in seconds of simulated time;
--    kept, because it is what makes the scenes affordable.
--  * tau_y(theta) follows Fig. 8's shape with Table 2's "yield surface" value
--    y as the fridge value: x1 at theta_1 = 5 degC (fridge), x0.8 at
--    theta_2 = 20 degC (room), x0.3 at theta_3 = 35 degC (fat melts), x20 at
--    theta_4 = 70 degC (starch gelatinises), constant beyond, irreversible
--    (the core evaluates it at the highest temperature a particle reached,
--    so a set cookie stays set).
--  * COOKIE_SET (issue #18; SET below): the cookie's Fig. 8 temperatures are a
--    sugar-snap dough's, not bread's. Ding et al. give theta_1..theta_4 as
--    "typical temperature ranges" whose "actual values vary among the
--    different examples"; read as bread's (x0.3 at 35 degC rising linearly
--    to x20 at 70 degC) the cookie stiffened from 35 degC (x6.6 by 38 degC)
--    and every pore froze at ~38 degC, 0.9 s into the bake, with 41% of its
--    CO2 made (docs/validation.md, "The cookie's CO2 traced"). A real cookie
--    dough does the opposite: its fat melts between 10 and 50 degC
--    (Chevallier, Colonna, Della Valle & Lourdin 2000, J. Cereal Sci. 31:241,
--    DSC and DMTA of biscuit doughs) and it spreads while soft; its diameter
--    grows linearly and then "suddenly became fixed" about halfway through the
--    bake (5.1-5.8 min of 10-11: Miller & Hoseney 1997, Cereal Chem. 74:330);
--    the set is the gluten's glass transition (Doescher, Hoseney & Milliken
--    1987, Cereal Chem. 64:158), measured in cookie dough at 71 degC (hard
--    wheat flour) and 78 degC (soft wheat flour, a cookie's) and correlated
--    with the set time at r = 0.97-0.99 (Miller, Hoseney & Morris 1996, J.
--    Thermal Anal. 47:1329); sucrose and the low water raise the starch's
--    gelatinisation so far that "little if any of it gelatinizes" (Pareyt,
--    Brijs & Delcour 2009, J. Agric. Food Chem. 57:7814, who find the set
--    in the gluten's cross-linking, delayed by sucrose), so there is no
--    60-70 degC starch set. So the cookie's curves keep Fig. 8's values and shape (x1,
--    x0.8, x0.3, x20 on tau_y; x1, x0.5, x0.1, x0.05 on eta) at its own
--    temperatures: 5, 20, 35 degC as Fig. 8, the melted value held to 71
--    degC, and set by 78 degC (the two flours' glass transitions, the sudden
--    set's width). Baked biscuit is ~2/3 gas (bulk density 1.26 -> 0.42
--    g/cm^3, Chevallier et al. 2000, J. Agric. Food Chem. 48:1322), so no
--    pore cap is needed below that. Measured: docs/validation.md, "The
--    cookie's set (#18, session 30)".
--  * MUFFIN_SET (issue #18; SET below): a cake batter stays fluid until its
--    starch gelatinises. Read as bread's (x0.3 at 35 degC rising linearly to
--    x20 at 70 degC) the muffin's batter stiffened from 35 degC (x29 by 50
--    degC, where the CO2 rate of eq. 11 peaks at 40): its top skin became a
--    lid at 45-60 degC and its centre stopped rising at 1.2 s of muffins.lua
--    at 40-45 degC, half its CO2 still to come, the top 5 mm below the rim
--    (docs/validation.md, "The muffin's set"). Measured batters do not stiffen
--    there: a cake batter's viscosity falls as it heats and rises sharply
--    only when its starch gelatinises, and the sugar sets that onset (Shelke,
--    Faubion & Hoseney 1990, Cereal Chem. 67:575, batter viscometry in an
--    oven; sucrose raises starch gelatinisation: Spies & Hoseney 1982,
--    Cereal Chem. 59:128). Wheat starch in excess water starts to gelatinise
--    near 55-60 degC (DSC onset; our reading of the common textbook range, not
--    checked against one paper), and sugar only raises it, so 55 is the low
--    end. So the muffin's curves keep Fig. 8's values and shape, the melted
--    value held from 35 to 55 degC, set at Fig. 8's 70 degC (bread's). The
--    set crumb's stretch to fracture (SET) ramps over the same 55-70 degC.
--  * eta: g = f^2/2 with f in Pa^2 (eq. 12, §6.5) makes eta a Pa^3 s
--    quantity. Table 2's eta taken in those units returns to the surface
--    within one step at the scenes' steps (rate-independent), so nothing
--    spreads over time. eta here is ETA_SCALE = 4000 times Table 2's value at
--    the fridge point, then Fig. 8's non-increasing shape: x1, x0.5, x0.1 and
--    x0.05 at theta_1..theta_4, irreversible. The cookie's 500 -> 2e6 Pa^3 s
--    makes a 2.5 cm dough ball spread over ~1 s, the time the oven takes to
--    set it, so the oven temperature decides how far it spreads (§7.2).
--  * alpha^g: the core integrates dn^g/dt = alpha^g R0 exp(-((theta -
--    theta_r)/dtheta)^2) in mol/m^3 with the SI gas constant. Table 2's
--    alpha^g in mol/(kg s) would build ~1e5 Pa of CO2 pressure against a
--    dough that yields at tens of Pa, and blow it apart. gas_rate here is
--    GAS_SCALE = 1/600 of Table 2's value (cookie: 0.015 -> 2.5e-5), which
--    gives pressures of a few tau_y: the dough rises, and sets before it
--    tears. (At 1/300 the cookie in a 110 degC oven tears: the porous dough
--    weakens in tension as n^p grows, eq. 12, so an unset dough that keeps
--    making gas runs away.)
--  * Per good (TUNE below), where Table 2 taken as above fails in SI at
--    kitchen size: bread's tau_y x10 (200 Pa at the fridge point), because
--    a 7 cm loaf under gravity loads its base with rho g H ~ 340 Pa and at
--    20 Pa it spreads into a puddle before the oven sets it. Lava cake gas
--    x0.1: a batter with tau_y = 1-2 Pa tears within 0.5 s at 1/600 (the
--    runaway described above).
--  * Rise (#18): a good's tau_y factor k multiplies its eta by k^2. The law's
--    flow rate is (f / eta) df/dtau with f in Pa^2, so in simple shear at a
--    stress near tau_y its viscosity is ~eta / (12 tau_y^2): eta (Pa^3 s)
--    is a viscosity times a squared stress. Raising tau_y by k with eta
--    kept made the dough k^2 more fluid. Bread's x10 without this spread the
--    loaf under its own weight in ~1 s of a 2.5 s bake (71.6 -> 55.5 mm; with
--    it 79.3 mm, area +40%: docs/validation.md "Rise (#18)"), and bread's old
--    gas x0.4 (against the runaway, seen at 3.5 s) is no longer needed. The
--    muffin (tau x10) carries it too; its dome is unchanged (5.51 mm).
--  * Muffin (TUNE: kappa x0.005, tau x10, gas x2.5, max_porosity 0.6), so that it rises into
--    the dome of Fig. 2, measured by scripts/scenes/baking/muffins.lua
--    (2D, dx 4 mm, one 50 mm cup with 22 mm of batter):
--    - kappa 0.5 W/(m K), a real batter's, for Table 2's 100. The dome
--      needs the batter to set at the tin's walls and floor while its
--      centre still rises with gas. With kappa 100 at kitchen size the
--      Biot number beta R / kappa = 150 x 0.025 / 100 = 0.04: the batter
--      heats evenly (wall, floor and centre within 1 degC: 29 degC at
--      0.25 s) and sets everywhere at once at ~0.75 s, flat. With 0.5 the
--      Biot number is 7.5: walls and floor pass 70 degC while the centre is
--      still below 40 degC.
--    - tau_y x10, as bread's (20 Pa at the fridge point, 6 Pa when the fat
--      melts, 400 Pa set): the set crumb must hold the CO2. By eq. 12 a
--      layer of porosity n yields in tension at tau_y / sqrt(M(n)), so it
--      holds a gas content n^g R theta of at most ~0.385 tau_y (the largest
--      n / sqrt(M(n)), near n = 0.45); Table 2's 40 Pa set value tore at
--      1.3-1.7 s under ~110 Pa of gas (kinetic energy x15).
--    - gas x2.5 (alpha^g / 240): at x0.1 the pressure peaked at 58 Pa, below
--      the batter's own weight at the floor (rho g h ~ 110 Pa), and nothing
--      rose. Centre above edge (kappa, tau and cap as here, 2D, dx 4 mm,
--      one cup, edge = the top at the walls): gas x2 3.5 mm, x2.5 5.0 mm,
--      x3 6.1 mm; the scene's measure at x2.5: 5.5 mm (claim_muffin_domes).
--    - max_porosity 0.6 (a plugin parameter, not in the paper; see the
--      header of plugins/cam_clay_dough.c): past n^p ~ 0.45 a layer holding
--      more gas than ~0.385 tau_y inflates without end, and without the cap
--      the rising batter tore (guard: a particle at 300 m/s) at dx 3 mm by
--      0.83 s and at dx 4 mm with gas x3. Baked muffin crumb is about 60%
--      gas, so pores stop growing plastically there. Since the porosity is
--      the gas volume fraction 1 - (1 - n^p_0) / J^P (core/sim/fields/gas.h;
--      issue #18, helper vent) the cap sits at J^P 2.25, a crumb 60% gas; with
--      the linear J^P - 1 + n^p_0 it sat at J^P 1.5, 40% gas. Dome 4.14 ->
--      5.66 mm (claim_muffin_domes).
--  * nu (not in Table 2) 0.3; initial porosity n^p_0 0.1; thermal expansion
--    c lambda (not in Table 2) 0.1 Pa/K from the dough's start temperature,
--    2 Pa/K for the marshmallow (its visible swelling, §7.2).
--  * latent_heat = false in every oven (the scene switch h.scene{latent_heat =
--    ...}, issue #18): with Table 2's c = 20 J/(kg K) a particle that loses
--    1% of its mass as water would cool by 0.01 L / c = 1130 K (L = 2.26
--    MJ/kg), so the latent sink belongs only to presets in real heat
--    capacities; a scene passes `latent_heat = oven.latent_heat`.
--  * Table 2's dx and dt are the paper's 3D resolutions; the scenes pick
--    their own (coarser) dx, and dt follows the CFL limit.
--  * DRY (issue #18, not in Ding et al.): a crust is its dough dried past the
--    glass transition. Roos (1995, Phase Transitions in Foods, ch. 5-6):
--    water plasticises starch and gluten, and through the glass transition
--    the modulus falls ~3 decades (glassy ~1e9 Pa, rubbery ~1e6 Pa); bread
--    crust is glassy (crisp) below ~13-15 % water wet basis at room
--    temperature (van Nieuwenhuijzen, Primo-Martin et al. 2008, J. Agric.
--    Food Chem. 56, 6432: the crust's water content sets the transition), and
--    a baked crust holds a few % water against the crumb's ~45 % (Vanin, Lucas
--    & Trystram 2009, Trends Food Sci. Technol. 20, 333). E and tau_y get a
--    factor over water content X (kg water / kg solids, dry basis): x100 at
--    X = 0.05 (a baked crust, 5 % wb), x10 at X = 0.16 (14 % wb, Tg at room
--    temperature), x1 at X = 0.41 (29 % wb, rubbery), log-linear between
--    (two more points). 100, not Roos's 1000: E sets the wave speed, so the
--    step shrinks as sqrt(E) (x10 steps, not x32) where a crust forms. The
--    core takes the curve over the moisture ratio X/X_0 (h.curve{of =
--    "moisture"}), X_0 the raw dough's: bread 0.82 (45 % wb), muffin batter
--    0.67 (40 %), cookie dough 0.25 (20 %), typical recipe values; each
--    factor is divided by its value at X_0, so a raw dough keeps Table 2's
--    numbers, and a scene without water (X/X_0 = 1) is unchanged.
--    Irreversible: a dried crust stays crisp when crumb water returns.
--  * WATER (issue #18, not in Table 2; Ding et al. §3.2 model moisture but
--    Table 2 gives no water numbers): the bread and the muffin carry water, so
--    their surface dries and stiffens (DRY) and turns brittle over a moist
--    crumb. Each number below and its source:
--    - water content: the raw dough's X_0 above (bread 0.82 kg/kg dry basis,
--      45 % wet basis; muffin batter 0.67, 40 % wb), as the saturation of
--      eq. 8 at Table 2's density: s_0 = x_w rho / rho_w = 0.45 x 500 / 1000
--      = 0.225 (bread), 0.40 x 500 / 1000 = 0.20 (muffin).
--    - time: Table 2's heat has no single real time scale (its kappa / (rho
--      c) is 2.6e4 times a real crumb's diffusivity, its beta / (rho c) 430
--      times a real oven's), so water takes the bake's own: bread.lua's 2.5 s
--      stand for a 25 minute bake and muffins.lua's 1.5-3 s for a 20 minute
--      one, WATER_S = 600 (water rates x600, as h.library.dough's time_scale).
--      Checked against the heat's own clock: bread.lua's crumb sets (60-70
--      degC, where a loaf stops rising) at 1.45-1.8 s, and a real loaf's oven
--      spring lasts its first 10-15 minutes (P. Reinhart 1991, Brother
--      Juniper's Bread Book; J. Hamelman 2004, Bread), which gives 330-620:
--      x600 is at the top of that, so a faster water clock has no footing
--      (docs/validation.md, "The crack measure and the crust's timing").
--    - diffusivity: 2e-7 m^2/s real (x600: 1.2e-4 m^2/s in the scene), the
--      effective moisture diffusivity of a baking crumb where evaporation and
--      condensation of vapour through the pores, not liquid flow, carry the
--      water out (Thorvaldsson & Janestad 1999, J. Food Eng. 40:167, model
--      the two apart); 2e-7 is our choice of its order, 100 times
--      dough_physical's liquid 2e-9, and it stands for the evaporation front
--      the animation units cannot have (latent heat off below): the dried
--      layer then spans a cell at dx 4-5 mm. Eq. 22's K = D / (theta s_0),
--      theta = 373.15 K, as dough_physical.
--    - evaporation beta^w: 1.2e-3 kg/(m^2 s K) real (x WATER_S), calibrated,
--      not measured: the value that brings bread.lua's top particle at dx 5
--      mm to X ~ 0.19 kg/kg by the end of the bake, a baked crust's few %
--      (Vanin et al. 2009 above) averaged with the crumb over a 5 mm cell,
--      and past the glass transition's 0.16 within a cell. dough_physical's
--      1.2e-5 (a wet surface's ~1 g/(m^2 s), the heat-limited rate beta (T_oven
--      - 100) / L of a real oven) left the top at X/X_0 0.67 here: a real
--      crust is 2-3 mm, dried by an evaporation front under it, and a cell of
--      5 mm has to dry through instead; so this is ~100x a real surface's
--      rate, the price of a crust the grid resolves.
--    Measured (bread.lua's plain loaf, dx 5 mm, 2.5 s): the top particle ends
--    at X/X_0 0.23, the centre at 0.92 (docs/validation.md, "Crust (#18)").
--  * FRACTURE (issue #18): the stretch rule (fracture_stretch = 1,
--    plugins/cam_clay_dough.c's "crust fracture"): a point cracks when the
--    stretch it takes along its elastic strain, each step over its fracture
--    strain at the time, sums to 1, so the drying itself cracks nothing and
--    the rise's stretch of a dried skin does. The stretch to fracture over
--    water content X: 0.02 once dried to X = 0.16 kg/kg (glassy: van
--    Nieuwenhuijzen et al. 2008 above put the crust's crispness transition at
--    this water content; 0.02, a few per cent, is our order of magnitude, not
--    a measured crust value), 1 at X = 0.41 (rubbery: a dough's cell walls
--    part at Hencky strains of order 1, van Vliet et al. 1992, J. Texture
--    Stud. 23:439), log-linear between (a glass transition moves a modulus
--    by decades, Roos 1995 above, and the strain to failure with it), and
--    100 at the raw dough's X_0, linear above 0.41: the rule counts plastic
--    flow, and a raw dough flows (its pores grow) without parting; at 1 the
--    loaf's wet crumb cracked by its own slump (279 particles by 0.5 s).
--    Irreversible. Measured crusts that fit this: sensory crispness is lost
--    between water activity 0.55 and 0.70 ("Relations between sensorial
--    crispness and molecular mobility of model bread crust and its main
--    components as measured by PTA, DSC and NMR"; from an abstract, authors
--    and journal not checked), and crusts baked with more steam fail at lower force
--    (Altamirano-Fortoul, Le-Bail, Chevallier & Rosell 2012, J. Food Eng.
--    108:128): no source found gives a crust's strain to fracture over its
--    water, so the numbers between the two ends are ours.
--  * SET (issue #18, session 30): the set crumb breaks too. Past the set
--    (Fig. 8's 70 degC, where tau_y is x20) a crumb is a solid foam, not a
--    dough that flows: the plugin's fracture_strain_set (cam_clay_dough.c,
--    "the set crumb"; the stretch rule takes the smaller of it and the
--    water's) is 100 (never) up to 35 degC and 0.15 from 70 degC, linear
--    between, over the highest temperature reached (irreversible), on the
--    same points as tau_y's set (the muffin's: 55 to 70 degC, MUFFIN_SET). 0.15 is inside the range measured on baked
--    crumb pulled apart, 0.05-0.36 (4-30 mm of break elongation on 83 mm
--    specimens: "Some tensile characteristics of bread crumb", J. Texture
--    Stud. 25:299, 1994; from its abstract, authors not checked). Without it
--    the crack in the bread's crust stopped a particle deep, in a crumb that
--    flowed. Measured (bread.lua's plain loaf, only = 1, 2.5 s): at 4 mm a
--    crown crack 8.05 mm deep and 8 mm wide (3.27 mm and 4 mm without),
--    14 cracked particles; the result moves with the value: 0.1 gives 19.7
--    mm and 4 mm wide, 0.2 8.1 mm and 4 mm, 0.05 cracks the whole set crumb
--    (hundreds of particles; the guard stops the run), 0.3 changes nothing.
--    Where the crust does not crack (5 mm) nothing changes, and nor in the
--    muffin, whose crown stops stretching as it sets (docs/validation.md,
--    Crust (#18), "The set crumb"; before MUFFIN_SET).
--  * BAND (issue #18, helper tear): the crack band of cam_clay_dough.c ("the
--    crack band", Bazant & Oh 1983): past its stretch to fracture a point
--    softens over the further stretch crack_opening / crack_band, so a crack
--    that starts takes the load off its neighbours and the energy it takes
--    per area does not depend on dx. crack_band = 0 here: h.material's
--    register gives it the scene's cell size (lua/hearth/init.lua). The
--    opening w_c = 2 G_f / f_t = 0.06 mm from the only brittle food foam we
--    found measured for both: potato crisps, work of fracture ~45 J/m^2 and
--    strength ~1.5 MPa ("Fracture properties of potato crisps", Int. J. Food
--    Sci. Technol. 2007, doi 10.1111/j.1365-2621.2007.01531.x; from its
--    abstract, authors not checked). Vincent 2004 (Eng. Fail. Anal. 11:695)
--    puts crisp foods' work of fracture near 1 J/m^2 and other foods' at
--    1-500, so this is an estimate for bread crust, not a measurement of it.
--    An opening, not G_f, because the presets' stresses are animation-scaled
--    and a length is not. Measured (helper tear): the bread's 4 mm crack 9.96
--    -> 8.05 mm deep (still >= 0.1 of the loaf's height); the muffin's top
--    still cracks as a band (39 particles at 4 mm, tear notch 0.04 mm): its
--    skin, at X/X0 0.5-0.6, is only ~2x as stiff as the batter it is fixed
--    to (DRY), so a crack relieves the skin only within about its own
--    thickness (a film cracking on a compliant substrate cracks at a spacing
--    of a few thicknesses: Hutchinson & Suo 1992, Adv. Appl. Mech. 29:63),
--    one particle here. Since helper crackband the band softens from its
--    peak over w_c / h - eps_f, so a crack takes G_f per area only in a cell
--    h < w_c / eps_f: 3 mm for the driest skin (eps_f 0.02), 0.4 mm for the
--    set crumb (SET's 0.15). In a larger cell the point drops at its peak as
--    without a band: the plain loaf at 4 mm is back to 9.96 mm
--    (docs/validation.md, "Is the crack band mesh-objective?").
--  * HEAT_SET (issue #18, helper crisp): drying alone does not make a crust
--    brittle; a film that dries before the heat has set its starch and
--    gluten is leathery (cam_clay_dough.c's "the heat-set", with its
--    sources). The muffin's fracture_unset (the plugin's parameter) falls
--    from 1 to 0 over its set (MUFFIN_SET's 55 to 70 degC, the points of
--    fracture_strain_set), irreversible: its water's brittleness counts in
--    proportion to the set. Why: the preset's evaporation (WATER, ~100x a real
--    surface's) dries the top to X/X0 0.5 by 0.5 s while it is at 30-40 degC
--    and the rise is still to come (0.5-1.3 s), and the rise then stretched
--    every particle of that brittle skin alike: it crackled as a band (39
--    particles at 4 mm, no tear). With the heat-set the skin stretches
--    unharmed until its crown passes 55-70 degC at 1.0-1.25 s, and the crown
--    then tears (claim_muffin_top_tears: 4.70 mm deep and 8 mm wide at 4 mm;
--    docs/validation.md "The muffin's tear: the heat-set").
--    Not the bread's: Table 2's bread heats evenly (Biot 0.04), so its crust
--    passes 35-70 degC with the crumb, at the end of the rise, and a crust
--    that waits for the set has no rise left to crack it: the 4 mm crown crack
--    went from 8.05 to 0.38 mm deep with it (5 mm: 0.25 mm, unchanged), and
--    with a real Biot number (crack_heat.lua conductivity 0.0234) it still
--    did not crack the 5 mm top (0.29 mm; 25 particles cracked elsewhere).
local ETA_SCALE, GAS_SCALE = 4000, 1 / 600
local DRY_X = { 0.05, 0.10, 0.16, 0.25, 0.41 }  -- water content, kg/kg dry basis
local DRY_F = { 100, 37, 10, 4.6, 1 }           -- E and tau_y factor (Roos 1995's glass transition, capped at 100)
local DRY_X0 = { bread = 0.82, muffin = 0.67, cookie = 0.25 } -- the raw dough's water content (dry basis)
-- water of the goods that bake a crust (WATER above): s_0, real diffusivity (m^2/s), beta^w (kg/(m^2 s K))
local WATER_S = 600
local WATER = { bread = { saturation = 0.225, diffusivity = 2e-7, evaporation = 1.2e-3 },
  muffin = { saturation = 0.20, diffusivity = 2e-7, evaporation = 1.2e-3 } }
-- stretch to fracture over water content (FRACTURE): glassy, leathery, rubbery, and the raw dough (never)
local FRACTURE_X, FRACTURE_DRY, FRACTURE_WET = { 0.16, 0.41 }, 0.02, 100
local CRACK_OPENING = 6e-5 -- the crack band's opening w_c = 2 G_f / f_t, m (BAND above): a crisp food foam's
local HEAT_SET = { muffin = true } -- the goods whose water's brittleness waits for the set (HEAT_SET above)
local FRACTURE_SET = 0.15 -- the set crumb's stretch to fracture (SET below), from 100 at Fig. 8's 35 degC to this at 70
local THETA = { 5, 20, 35, 70 }            -- Fig. 8: fridge, room, fat melting, gelatinisation (degC)
local TAU_SHAPE = { 1, 0.8, 0.3, 20 }      -- Fig. 8 left, relative to Table 2's value
local ETA_SHAPE = { 1, 0.5, 0.1, 0.05 }    -- Fig. 8 right, relative to ETA_SCALE x Table 2's value
-- a good whose Fig. 8 temperatures differ (COOKIE_SET, MUFFIN_SET above): its points and shapes replace THETA, TAU_SHAPE,
-- ETA_SHAPE
local SET = { cookie = { theta = { 5, 20, 35, 71, 78 }, tau = { 1, 0.8, 0.3, 0.3, 20 }, eta = { 1, 0.5, 0.1, 0.1, 0.05 } },
  muffin = { theta = { 5, 20, 35, 55, 70 }, tau = { 1, 0.8, 0.3, 0.3, 20 }, eta = { 1, 0.5, 0.1, 0.1, 0.05 } } }

-- Table 2, one column per good (N/A as nil).
local paper = {
  bread = { E = 2e3, density = 500, specific_heat = 20, kappa = 100, yield = 20, eta = 500, theta0 = 1,
    ambient_theta = 100, ambient_beta = 100, conductive_theta = 100, conductive_beta = 150, alpha_g = 0.03,
    theta_r = 40, dtheta = 20, dx = 0.01, dt = 4e-3 },
  cookie = { E = 4e4, density = 500, specific_heat = 20, kappa = 30, yield = 20, eta = 500, theta0 = 0,
    ambient_theta = 150, ambient_beta = 25, conductive_theta = 150, conductive_beta = 35, alpha_g = 0.015,
    theta_r = 40, dtheta = 20, dx = 0.0051, dt = 3e-4 },
  pancake = { E = 4e4, density = 500, specific_heat = 20, kappa = 200, yield = 2, eta = 50, theta0 = 0,
    ambient_theta = nil, ambient_beta = nil, conductive_theta = 200, conductive_beta = 70, alpha_g = 0.02,
    theta_r = 30, dtheta = 20, dx = 0.016, dt = 5e-4 },
  muffin = { E = 4e4, density = 500, specific_heat = 20, kappa = 100, yield = 2, eta = 10, theta0 = 0,
    ambient_theta = 105, ambient_beta = 75, conductive_theta = 105, conductive_beta = 150, alpha_g = 0.03,
    theta_r = 40, dtheta = 20, dx = 0.008, dt = 2e-4 },
  lava_cake = { E = 2e3, density = 500, specific_heat = 20, kappa = 250, yield = 1, eta = 10, theta0 = 0,
    ambient_theta = 100, ambient_beta = 110, conductive_theta = 100, conductive_beta = 110, alpha_g = 0.025,
    theta_r = 20, dtheta = 10, dx = 0.0075, dt = 4e-4 },
  smore = { E = 4e4, density = 500, specific_heat = 200, kappa = 150, yield = 200, eta = 60, theta0 = 0,
    ambient_theta = 400, ambient_beta = 120, conductive_theta = 400, conductive_beta = 360, alpha_g = nil,
    theta_r = nil, dtheta = nil, dx = 0.003, dt = 2e-4 },
}

-- per-good factors on top of the global ones (see the header)
local TUNE = { bread = { tau = 10 }, muffin = { kappa = 0.005, tau = 10, gas = 2.5, max_porosity = 0.6 }, lava_cake = { gas = 0.1 } }

local D = { paper = paper, TUNE = TUNE, SET = SET, WATER = WATER, WATER_S = WATER_S, DRY_X = DRY_X, DRY_F = DRY_F, DRY_X0 = DRY_X0, ETA_SCALE = ETA_SCALE, GAS_SCALE = GAS_SCALE, THETA = THETA, TAU_SHAPE = TAU_SHAPE,
  ETA_SHAPE = ETA_SHAPE }

local function curve(base, shape, theta)
  local pts = { irreversible = true }
  for i, T in ipairs(theta or THETA) do pts[i] = { T, base * shape[i] } end
  return pts
end

--- The preset of one good: plain parameters, curve point lists (for h.curve), and its oven.
function D.preset(name)
  local c = paper[name]
  if not c then return nil end
  local tune = TUNE[name] or {}
  local params = {
    E = c.E, nu = 0.3, density = c.density,
    specific_heat = c.specific_heat, conductivity = c.kappa * (tune.kappa or 1),
    gas_rate = c.alpha_g and c.alpha_g * GAS_SCALE * (tune.gas or 1) or 0,
    reaction_temperature = c.theta_r or 40, reaction_width = c.dtheta or 20,
    porosity = 0.1, max_porosity = tune.max_porosity,
    expansion = name == "smore" and 2 or 0.1, reference_temperature = c.theta0,
  }
  -- eta carries the square of the tau_y factor (header, "Rise"): eta / tau_y^2 is the dough's viscosity
  local tau = tune.tau or 1
  local set = SET[name] or { theta = THETA, tau = TAU_SHAPE, eta = ETA_SHAPE }
  local curves = { tau_y = curve(c.yield * tau, set.tau, set.theta),
    eta = curve(c.eta * ETA_SCALE * tau * tau, set.eta, set.theta) }
  local dry -- factor points {X/X0, f(X)/f(X0)} for E and tau_y (DRY above)
  if DRY_X0[name] then
    local X0, f0 = DRY_X0[name], 1
    for i = 2, #DRY_X do -- f at X0, log-linear as the points
      if X0 <= DRY_X[i] then
        f0 = DRY_F[i - 1] * (DRY_F[i] / DRY_F[i - 1]) ^ ((X0 - DRY_X[i - 1]) / (DRY_X[i] - DRY_X[i - 1])); break
      end
    end
    local pts = { irreversible = true, of = "moisture" }
    for i, X in ipairs(DRY_X) do if X < X0 then pts[#pts + 1] = { X / X0, DRY_F[i] / f0 } end end
    if X0 <= DRY_X[#DRY_X] then pts[#pts + 1] = { 1, 1 } end -- a cookie dough is drier than the last point
    dry = { E = pts, tau_y = pts }
  end
  local w = WATER[name]
  if w then -- WATER and FRACTURE above
    params.saturation = w.saturation
    params.water_diffusivity = w.diffusivity / (373.15 * w.saturation) * WATER_S
    params.evaporation = w.evaporation * WATER_S
    params.fracture_strain = FRACTURE_WET
    params.fracture_stretch = 1
    params.crack_opening, params.crack_band = CRACK_OPENING, 0 -- BAND: 0 = the scene's cell (lua/hearth/init.lua)
    local X0 = DRY_X0[name]
    local ef, n = { irreversible = true, of = "moisture" }, 5 -- log-linear from FRACTURE_DRY to 1 over FRACTURE_X, n steps
    for i = 0, n do
      local X = FRACTURE_X[1] + (FRACTURE_X[2] - FRACTURE_X[1]) * i / n
      ef[#ef + 1] = { X / X0, FRACTURE_DRY ^ (1 - i / n) / FRACTURE_WET }
    end
    ef[#ef + 1] = { 1, 1 }
    dry.fracture_strain = ef
    -- SET: the set crumb's, over the highest temperature reached, on Fig. 8's set points (as tau_y's)
    local nt = #set.theta -- the set's last two points: where tau_y leaves its melted value, and the set
    curves.fracture_strain_set = { { set.theta[nt - 1], FRACTURE_WET }, { set.theta[nt], FRACTURE_SET }, irreversible = true }
    -- HEAT_SET: the water's brittleness in proportion to the set, over the same points
    if HEAT_SET[name] then curves.fracture_unset = { { set.theta[nt - 1], 1 }, { set.theta[nt], 0 }, irreversible = true } end
  end
  local oven = { temperature = c.ambient_theta, beta = c.ambient_beta, pan_temperature = c.conductive_theta,
    pan_beta = c.conductive_beta, dough_temperature = c.theta0, latent_heat = false,
    saturation = w and w.saturation, water_time_scale = w and WATER_S }
  return params, curves, oven, dry
end

return D

-- hearth.dough_physical: doughs in physical units (issue #18, "presets say
-- their units"), for the cam_clay_dough plugin:
--   h.material("cam_clay_dough", h.library.dough.bread)   -- parameters and curves
--   h.library.oven.bread                                     -- oven, pan, dough and the time scale
-- Ding et al.'s Table 2 goods, in the animation units hearth used before, are
-- h.library.paper.<name> and h.library.paper_oven.<name> (lua/hearth/dough.lua).
--
-- Every number below carries its source. Where a value is measured we say so;
-- where it is predicted from the composition (Choi & Okos 1986, the method of
-- the ASHRAE Handbook - Refrigeration, chapter "Thermal properties of foods")
-- or chosen within a reported range, we say that instead.
--
-- ---- the time scale S -----------------------------------------------------
-- A real bake takes 20-30 minutes; the dough's elastic waves limit the MPM
-- step to ~3e-4 s at dx 5 mm, so a bake in real time would take millions of
-- steps. The presets therefore run every transport RATE S times fast and
-- keep every capacity: conductivity, the oven's and the pan's beta, the
-- water diffusivity, the surface evaporation beta^w and the CO2 rate are
-- multiplied by S, and the scene runs 1/S of the real time. Heat and water
-- then follow exactly the real history in t_real = S t (divide eq. 9 and 22
-- by S: nothing else changes; density, specific heat, water content and
-- L = 2.26 MJ/kg are capacities and stay). Browning's rate is scaled alike
-- (oven.browning_scale = S). The mechanics keeps its elasticity (its waves
-- are not part of the bake: the dough is quasi-static) and divides its
-- viscosity by S, so a viscous slump under its own weight, time eta / (rho g
-- H), keeps its ratio to the bake's time. oven.time_scale = S and
-- oven.bake_time (s, simulated) say it; a scene reports t_real = S t.
--
-- ---- viscosity in the plugin's units ----------------------------------------
-- cam_clay_dough's eta penalises f = M p^2 + q^2 - tau_y^2 (Pa^2) and is in
-- Pa^3 s (plugins/cam_clay_dough.c). Just past the yield surface f ~ 2 tau_y
-- (q - tau_y), and the plastic rate is ~ (dt / eta) f q per step, so a
-- Newtonian overstress viscosity mu (Pa s) is eta = 2 tau_y^2 mu. The curve
-- of eta below is that, point by point, at each point's tau_y.
--
-- ---- water --------------------------------------------------------------
-- hearth's water is the saturation s of rho_0^w = 1000 kg/m^3 (Ding et al.
-- eq. 8): water mass per volume = 1000 s. A dough of density rho and water
-- mass fraction x_w (wet basis) has s = x_w rho / 1000.
local D = {}

local THETA = { 5, 20, 35, 70 }            -- Fig. 8's points (degC): fridge, room, fat melting, gelatinisation
local TAU_SHAPE = { 1, 0.8, 0.3, 20 }      -- Fig. 8 left, as the paper presets (dough.lua): the set crumb is 20x
local MU_SHAPE = { 1, 0.5, 0.1, 0.05 }     -- Fig. 8 right, relative to the measured viscosity at the first point

-- per good: the numbers and their sources
D.goods = {
  bread = {
    -- proofed wheat dough: porosity eps = 50% (a dough proofed to twice its volume)
    -- density: Zanoni et al. 1995 (J. Food Eng. 26:497, "Determination of the thermal diffusivity of bread as a function
    -- of porosity"), measured crumb rho = 979 - 9.90 eps (eps in %): 484 kg/m^3
    density = 484,
    -- specific heat: Choi & Okos composition model (ASHRAE) for 45% water, 55% solids (mostly starch): 2.7 kJ/(kg K);
    -- the order of the measured doughs Rask 1989 (J. Food Eng. 9:167) reviews
    specific_heat = 2700,
    -- conductivity: kappa = alpha rho c with Zanoni et al. 1995's measured crumb diffusivity
    -- alpha = exp(0.01 eps - 15.25) = 3.9e-7 m^2/s at eps = 50%: 0.51 W/(m K)
    conductivity = 0.51,
    -- dried, the crust conducts less (issue #18; core parameter dry_conductivity, kappa linear in the water left):
    -- kappa = alpha rho c with Zanoni et al. 1995's measured crust correlations at the same eps = 50%,
    -- alpha = exp(0.0062 eps - 15.30) = 3.09e-7 m^2/s and rho = 895 - 9.0 eps = 445 kg/m^3, and c = 1.65 kJ/(kg K)
    -- (Choi & Okos, ASHRAE, for the dry solids: 85% carbohydrate, 12% protein, 2% fat, 1% ash, at 25 degC):
    -- 0.23 W/(m K), 0.44 of the wet crumb's. (A bread model's dry and wet values, 0.18 and 0.37 W/(m K), have
    -- about the same ratio: techMathGroup/breadBakingFoam, compEffProps.H.)
    dry_conductivity = 0.23,
    -- dried, the crust holds less heat (issue #18; core parameter dry_specific_heat, per kg of the dough's mass, linear
    -- in the water left): the water it lost took its heat capacity with it. A particle's mass stays the dough's, and
    -- the mixture rule m c = m_s c_s + m_w c_w with no water left gives c = (m_s / m) c_s = 0.55 x 1.65 kJ/(kg K) (45%
    -- water, the solids' c_s from Choi & Okos as above): 907.5 J/(kg K), a third of the dough's. (The same rule with
    -- c_w = 4.18 kJ/(kg K) gives the wet dough 2.79 kJ/(kg K), 3% above the 2.7 taken.)
    dry_specific_heat = 0.55 * 1650,
    -- water: 45% wet basis (a lean bread dough's; Zanoni, Peri & Pierucci 1993, J. Food Eng. 19:383, bake doughs of
    -- about this), s = 0.45 x 484 / 1000
    saturation = 0.218,
    -- liquid water diffusivity in crumb: chosen 2e-9 m^2/s within the 1e-10..1e-8 m^2/s range of baking models
    -- (e.g. Zanoni, Pierucci & Peri 1994, J. Food Eng. 23:321); eq. 22's D = K theta s gives K = D / (373 s)
    water_diffusivity_m2s = 2e-9,
    -- surface evaporation: chosen so a wet surface (s = 0.218, 373 K) loses ~1 g/(m^2 s) before it boils;
    -- the boiling front (core, boiling_point) carries most of the water. With latent_heat (these ovens') the rate
    -- is this at 373 K and falls with the vapour pressure below it (core/sim/fields/water.h, #18's wet bulb)
    evaporation = 1.2e-5,
    -- rheology: E = 3 G' with G' ~ 1e4 Pa (small-strain moduli 1e3-1e4 Pa, Dobraszczyk & Morgenstern 2003, J. Cereal
    -- Sci. 38:229); creep (overstress) viscosity 1e5 Pa s (the 1e4-1e6 Pa s of the same review); yield stress 200 Pa
    -- at the fridge point (a stiff dough holds a 7 cm loaf, rho g H ~ 330 Pa, once it is a few degrees warmer and
    -- sets at 70 degC: Fig. 8's shape)
    E = 3e4, nu = 0.3, tau_y = 200, mu = 1e5,
    -- the pores' gas: a proofed dough's cells hold gas at about the atmosphere's pressure and what moves the dough is
    -- their overpressure (Fan, Mitchell & Blanshard 1999, J. Food Eng. 41:69, "A model for the oven rise of dough
    -- during baking"), so eq. 13 is taken over the atmosphere (core parameter ambient_pressure, p_a = 101325 Pa;
    -- core/sim/fields/gas.h, gas_tau_ambient): the pores start with air and water vapour at p_a, and heating,
    -- the vapour and the CO2 swell them (the oven rise). Porosity 0.5: the gas fraction of this density's dough
    -- proofed to twice its volume (above). Before, eq. 13 read the whole pores' gas (no atmosphere), so a real
    -- yeast's CO2 stood for 1e5 Pa against a dough that yields at 1e2 Pa and the rate was cut to the paper
    -- bread's, 2.2e-8 mol/(kg s) with porosity 0.1: the loaf did not rise (docs/gallery/crumb_plateau.md).
    -- The cells open to the air (the set crumb turns from a foam to a sponge) at 70 degC, where this preset's crumb
    -- sets (Fig. 8's 70 degC, tau_y x20): pore opening is measured at 71-81 degC (Zhang et al. 2025, Foods 14:1649;
    -- as core/sim/fields/gas.c's venting cites), and from there the gas holds no pressure (core parameter
    -- open_temperature). At 75 degC the set skeleton held the vapour's swelling between 70 and 75 degC in the layer
    -- over the hot base, which bent the dried base up at its edges (5 mm off the tray at dx 5 mm) and tore it at
    -- 2.5 mm (docs/validation.md, "The physical loaf's oven spring"). Once the tray held only where the dough
    -- touches it (mpm_touch.c), 76 degC kept the base down but burst one flank of the 2.5 mm loaf and not the 5 mm
    -- one ("A body rests on what it touches", the opening temperature asked again): 70 stays.
    ambient_pressure = 101325, open_temperature = 70,
    -- CO2: the order a proof retains: doubling this dough's volume (0.5 of it gas) in about an hour at 30 degC is
    -- p V / (R T) = 101325 x (0.5 / 484) / (8.314 x 303) = 0.042 mol/kg per hour, 1.15e-5 mol/(kg s) (a proof's
    -- usual hour; the preset's own 50% porosity), at the bell's 30 degC: the peak rate 1.15e-5 / exp(-(10/20)^2).
    -- The yeast's optimum is 32-40 degC (bakemag.com, "The science of fermentation"): theta_r = 40 degC, width 20 K
    -- (Ding et al.'s bell), so it dies away past ~60 degC.
    gas_rate = 1.15e-5 / math.exp(-0.25), reaction_temperature = 40, reaction_width = 20, porosity = 0.5,
    expansion = 0.1, dough_temperature = 25,
    -- oven: 200 degC, beta 30 W/(m^2 K) (effective coefficients, radiation included, 20-48 W/(m^2 K) in Baik et al.
    -- 1999, J. Food Sci. 64:688); pan: a tray at the oven's temperature through ~100 W/(m^2 K) contact
    oven_temperature = 200, oven_beta = 30, pan_temperature = 200, pan_beta = 100,
    -- the tray goes into the oven with the dough on it, at the room's 20 degC, and warms as a lumped sheet drawn on by
    -- the dough, as the cookie's (#18, helper userfix7; before, it stood at 200 degC from the first step): the same
    -- 1 mm aluminium baking sheet, 2700 kg/m^3 x 900 J/(kg K) x 0.001 m = 2430 J/(m^2 K) (handbook values, helper
    -- lead's "A tray that goes in cold"), heated on both faces by the oven's 30 W/(m^2 K): 2430 / 60 = 40 s real
    -- (docs/validation.md, "The sheet gives the food its heat (#18, helper traydraw)"; loaf_physical.lua gives its area)
    pan_start_temperature = 20, pan_warm_time_real = 40, pan_heat_capacity = 2430,
    time_scale = 300, bake_time_real = 1500,
  },
  cookie = {
    -- sugar-snap cookie dough of an assumed composition: 18% water, 20% fat, 55% carbohydrate, 7% protein;
    -- density 1200 kg/m^3 from the constituents' (carbohydrate and protein ~1.5, water 1.0, fat 0.92 g/cm^3) with
    -- ~15% air (estimated, not measured)
    density = 1200,
    -- specific heat and conductivity: Choi & Okos composition model (ASHRAE) for that composition at 25 degC
    specific_heat = 2150, conductivity = 0.35,
    saturation = 0.216,                        -- 0.18 x 1200 / 1000
    water_diffusivity_m2s = 1e-9,              -- chosen, as bread's, lower for the denser dough
    evaporation = 1.2e-5,
    -- rheology: E = 1e5 Pa and viscosity 1e5 Pa s are guesses (short doughs stiffer than bread dough, G' 1e4-1e5 Pa,
    -- Dobraszczyk & Morgenstern 2003's range for doughs). The yield stress is measured (issue #18, helper cookieyield):
    -- cookie doughs of soft wheat flour, sugar, water and olive oil, by shear rheometry, yield at 50.22-72.80 Pa (In,
    -- Jeong & Min 2022, Food Sci. Biotechnol. 31:807, abstract: the printable formulations; G' 7165-12590 Pa; the
    -- same doughs with butter and egg in place of the oil and water yield higher). Their fat is liquid, as this
    -- dough's is once it has melted, so the midpoint, 61.5 Pa, is taken as the melted plateau (COOKIE_SET's x0.3,
    -- 35-71 degC). A shear yield stress s is q = sqrt(3) s on this plugin's von Mises surface (plugins/
    -- cam_clay_dough.c, eq. 12 as the pores close): 106.5 Pa melted, so 106.5 / 0.3 = 355 Pa at the fridge's x1 (284
    -- at room, the solid fat's x0.8 / x0.3 = 2.7 over the oil dough's, as the butter doughs' higher yield). The
    -- abstract gives neither the measurement's temperature nor the doughs' water; the range's ends give 290-420 Pa.
    -- Was 500, a guess, under which the unleavened cookie did not spread (docs/validation.md, "The physical
    -- cookie's yield stress").
    E = 1e5, nu = 0.3, tau_y = 355, mu = 1e5,
    -- CO2: a sugar-snap cookie's soda (issue #18, helper sodacookie). The formula: the micro sugar-snap cookie of
    -- AACC Method 10-52 as the Wheat Marketing Center's "Wheat and Flour Testing Methods" (wheatflourbook.org, 2008;
    -- "Sugar Snap Cookie") gives it: flour 40 g (14% moisture), sugar 24 g, shortening 12 g, nonfat dry milk 1.2 g,
    -- NaHCO3 0.40 g dry plus 0.32 g in solution, NH4Cl 0.20 g and salt 0.18 g in solution, water 0.3-2.1 mL more;
    -- baked 11 minutes at 205 degC. The soda, 0.72 / 84.01 = 8.57 mmol, meets an acid salt, NH4Cl 0.20 / 53.49 = 3.74
    -- mmol: NaHCO3 + NH4Cl -> NaCl + NH3 + H2O + CO2 gives one CO2 per NH4Cl, 3.74 mmol; the soda left over, 4.83
    -- mmol, has no acid and decomposes by heat alone, 2 NaHCO3 -> Na2CO3 + H2O + CO2, half a mole each: 2.42 mmol.
    -- 6.16 mmol CO2 in all (the NH3, 3.74 mmol more gas, is taken to stay in the dough's water, uncounted: eq. 12
    -- carries one gas). The dough's mass: 78.3 g of ingredients, the solutions' water not given there; at this
    -- preset's 18% water (flour's 5.6 g included) it is 72.7 / 0.82 = 88.7 g, so 6.16 / 88.7 = 0.069 mol/kg (0.078
    -- at 78.6 g, the solutions holding no water and 0.3 mL added). Every mole assumes the soda reacts whole in the bake.
    -- When: a soda is heat-triggered, not a yeast's 40 degC bell. NaHCO3 decomposes gradually from 80-100 degC and
    -- faster toward 200 (en.wikipedia.org "Sodium bicarbonate", thermal decomposition; no dough DSC found here), and
    -- the NH4Cl reaction runs as the dough heats and its NH3 and CO2 leave. Ding et al.'s eq. 14 bell is what the
    -- plugin has: centre theta_r = 100 degC (the top of that range and the dough's boiling plateau), width 20 K, so
    -- the rate is e^-1 of its peak at 80 degC, 2% at 60 and 1e-7 in the 20 degC raw dough. The bell falls again past
    -- 100 degC where a real soda's rate keeps rising; only the crust passes 100. Eq. 14 has no depletion of its own, so
    -- the rate was set from the amount (since helper depletion the amount also caps it, below): the one bell's peak rate (before the two shares below) was 0.069 mol/kg over the 229 s the bell integrates to along the dough's
    -- centre temperature in this preset's 190 degC, 11 minute bake (cookies.lua --set preset=physical, dx 5 mm,
    -- series.csv, 22 frames, with this preset's earlier gas: 20 degC to 100 at 11 minutes): 0.069 / 229 = 3.0e-4
    -- mol/(kg s) (under the gas law below the centre reads 216 s, 0.065 mol/kg). The hotter outer dough makes more
    -- than the centre, the crust past 100 degC less.
    -- The gas law: bread's, eq. 13 over the atmosphere (ambient_pressure; the bread entry above says why). With eq.
    -- 13 as printed (the pores' whole gas, porosity 0.1) this amount stopped the bake at 49 s of 11 minutes: the
    -- stability guard, 13.9 kPa of CO2 in a hot particle whose stress had gone to 0 (docs/validation.md, "The physical
    -- cookie's soda"). Porosity 0.15: the ~15% air of the density above, which this law fills at p_a. The cells
    -- open where the dough has set, 78 degC (COOKIE_SET's end, within the 71-81 degC of pore opening Zhang et al.
    -- 2025 measure in bread, as bread's open_temperature takes its set): at 95 the leavened cookie spread to 130 mm
    -- and dished, and at 100 the pores' vapour reaches p_a and both cookies burst.
    -- Two shares (issue #18, helper sodatwo; docs/validation.md "The physical cookie's two shares"): the two
    -- reactions above are two sources, so each takes its own eq. 14 bell (the core's second share, gas_rate_2), its
    -- centre and width fixed from sources before any run with them. The NH4Cl share, 3.74 mmol / 88.7 g = 0.0422
    -- mol/kg, is in effect dissolved ammonium bicarbonate (NH4+ and HCO3- in the dough's water): it releases slowly at
    -- room temperature and rapidly above ~40 degC (Church & Dwight's ammonium bicarbonate sheet, ahperformance.com),
    -- "more noticeable" at ~60 degC, "a very short time" at oven temperature (LibreTexts, Chemistry of Cooking 5.7),
    -- from 60 degC (ammoniumbicarbonate.com); measured in solution, it leaves over tens of minutes at 50 degC (an
    -- NH3-CO2-H2O solution lost ~90% of its solutes in 90 min at 50 degC under 0.35 bar: Kolliopoulos &
    -- Papangelakis 2019, Ind. Eng. Chem. Res. 58:12247, abstract; HCO3- falls sharply in the first 30 min at 50-90
    -- degC, faster when hotter: Liu, Zhang & Liu 2017, Chin. J. Process Eng. 17:123, abstract), too slowly for an
    -- 11 minute bake below ~50. The solid salt decomposes from ~75 degC (DSC, Resentera et al. 2025, Ind. Eng.
    -- Chem. Res., abstract), but in this dough it is dissolved. Centre 60 degC (where the sources agree the release
    -- is under way), width 20 K: e^-1 of the peak at 40 (the sheet's "rapidly") and at 80, 2% in the 20 degC raw
    -- dough (its slow room-temperature loss). Eq. 14 has no depletion of its own: the bell's fall past 60 stood for
    -- the share running out, as the solution's rate falls once its HCO3- is spent (gas_amount_2 below now ends it). The leftover soda, 2.42 / 88.7 = 0.0273
    -- mol/kg, keeps the one bell's 100 degC, 20 K (the bicarbonate-carbonate equilibrium; no source found for
    -- another). Each peak rate is the share's amount over the time its bell integrates to along the dough centre's
    -- temperature in this preset's 190 degC bake before the shares (main's binary at 5cac4e3, cookies.lua --set
    -- preset=physical --set ovens=190 --set leaveners=0.015 --set frames=66, series.csv, erf per 10 s frame): 265 s
    -- for 60/20 (89% of it before the 78 degC set), 220 s for 100/20 (9% before it). Was one bell, 0.069 / 229 at
    -- 100 degC, 20 K, under which the leavened cookie stood 1.07x the unleavened at 190 degC; with the two shares
    -- 1.55x at dx 5 mm, 1.81x at 3.75 (Ding §7.3's bar 1.3x; claim_cookie_physical_leavened_taller).
    -- Each share is a finite amount (issue #18, helper depletion; the core's gas_amount and gas_amount_2, gas.h's
    -- gas_share_capped): the formula's moles above, 2.42 / 88.7 = 0.0273 mol/kg of the soda and 3.74 / 88.7 =
    -- 0.0422 of the NH4Cl share, one CO2 per NaHCO3 (NaHCO3 + NH4Cl -> NaCl + NH3 + CO2 + H2O for the NH4Cl share;
    -- the leftover soda's CO2 from its acid-free decomposition as "When the physical cookie's soda releases its CO2"
    -- counts it). Without them a dough held near 60 degC made the NH4Cl share's bell for ever: 0.056 mol/kg in the
    -- 110 degC oven (docs/validation.md "The physical cookie in the cooler ovens"). The amounts are not time-scaled.
    gas_rate = 2.42 / 88.7 / 220, reaction_temperature = 100, reaction_width = 20, gas_amount = 2.42 / 88.7,
    gas_rate_2 = 3.74 / 88.7 / 265, reaction_temperature_2 = 60, reaction_width_2 = 20, gas_amount_2 = 3.74 / 88.7,
    porosity = 0.15,
    ambient_pressure = 101325, open_temperature = 78,
    expansion = 0.1, dough_temperature = 20,
    -- the set: a sugar-snap dough's gluten glass transition at 71-78 degC, no starch gelatinisation (lua/hearth/dough.lua,
    -- COOKIE_SET, the same curve as h.library.paper.cookie's)
    curve = "cookie",
    oven_temperature = 190, oven_beta = 30, pan_temperature = 190, pan_beta = 100,
    -- the sheet goes into the oven with the dough on it, at the room's 20 degC, and warms as a lumped sheet (its Biot
    -- number ~1e-4): a 1 mm aluminium sheet (2700 kg/m^3 x 900 J/(kg K) x 0.001 m = 2430 J/(m^2 K), handbook values)
    -- heated on both faces by the oven's 30 W/(m^2 K) reaches it with a time constant of 2430 / 60 = 40 s (the oven's side
    -- alone: the dough's draw comes on top). Before, the sheet stood at 190 degC from the first step
    -- (docs/validation.md, "A tray that goes in cold"). pan_heat_capacity, that same 2430 J/(m^2 K): the heat the
    -- dough draws through pan_beta comes out of the sheet (colliders.h's heat_capacity; cookies.lua gives the sheet's
    -- area; docs/validation.md, "The sheet gives the food its heat (#18, helper traydraw)")
    pan_start_temperature = 20, pan_warm_time_real = 40, pan_heat_capacity = 2430,
    time_scale = 50, bake_time_real = 660,
  },
  muffin = {
    -- cake batter, 38% water: density 800 kg/m^3 (an aerated batter), specific heat 2.8 kJ/(kg K) and
    -- conductivity 0.25 W/(m K): predicted by the Choi & Okos composition model (ASHRAE), not checked here against a
    -- measurement (Baik et al.'s cake baking studies in tunnel ovens, 1999-2001, are where to look)
    density = 800, specific_heat = 2800, conductivity = 0.25,
    saturation = 0.304,                        -- 0.38 x 800 / 1000
    water_diffusivity_m2s = 2e-9, evaporation = 1.2e-5,
    -- a batter flows: E 1e4, yield 20 Pa, viscosity 1e2 Pa s (batters are 1-100 Pa s fluids; chosen at the top, so
    -- it stands in its cup while it heats), soft to 55 degC and set by 70 degC (lua/hearth/dough.lua, MUFFIN_SET,
    -- the same curve as h.library.paper.muffin's: a batter thickens only at starch gelatinisation)
    E = 1e4, nu = 0.3, tau_y = 20, mu = 100, max_porosity = 0.6, curve = "muffin",
    -- CO2 as bread's: the gas the paper muffin's rate makes in muffins.lua's 3 s, spread over the real bake
    gas_rate = 0.03 / 600 * 2.5 * 3 / 1320, reaction_temperature = 40, reaction_width = 20, porosity = 0.1,
    expansion = 0.1, dough_temperature = 20,
    oven_temperature = 180, oven_beta = 30, pan_temperature = 180, pan_beta = 100,
    -- the tin goes into the oven with the batter in it, at the room's 20 degC, and warms as a lumped sheet (Biot
    -- 30 x 0.0007 / 60.5 = 3.5e-4): a steel muffin tin of 22 to 24 gauge (0.79 to 0.61 mm; 0.7 mm taken), plain
    -- carbon steel's 7854 kg/m^3 x 434 J/(kg K) (Incropera & DeWitt, Fundamentals of Heat and Mass Transfer, Table
    -- A.1) x 0.0007 m = 2386 J/(m^2 K), heated on its outer face only (the batter covers the inner one) by the oven's
    -- 30 W/(m^2 K): 2386 / 30 = 80 s (69 to 90 s over the two gauges; an aluminium tin of 1 mm, 2440 J/(m^2 K), 81 s).
    -- A paper liner between holds ~50 g/m^2 x 1.3 kJ/(kg K) = 65 J/(m^2 K), 3% of the tin's: left out. 80 s is the oven's
    -- side alone: the batter's draw comes on top. Before, the tin stood at 180 degC from the first step
    -- (docs/validation.md, "The muffin tin and the lava cake's mould go in cold"). pan_heat_capacity, that same 2386
    -- J/(m^2 K): the batter's heat comes out of the tin (h.recipes.muffin_cup gives the cup's area; docs/validation.md,
    -- "The sheet gives the food its heat (#18, helper traydraw)")
    pan_start_temperature = 20, pan_warm_time_real = 80, pan_heat_capacity = 2386,
    time_scale = 60, bake_time_real = 1320,
  },
  pancake = {
    -- American pancake batter (issue #18, helper pancake). Not the muffin's: a pancake batter holds ~54% water where
    -- the muffin's cake batter holds 38%, and it is a denser, barely aerated liquid. The composition: Eames, Khaw &
    -- Bouremel, "How to make the perfect pancake" (Mathematics Today, IMA), whose American pancake has a baker's ratio
    -- (milk to flour by mass) of ~100: 200 g milk (87.5% water), 200 g flour (14% water), one 55 g egg (75% water):
    -- 244 g water in 455 g, 54% wet basis (two eggs: 54.5%), within the 50-55% the brief asks.
    -- density: its airless constituents (water 1.0, flour solids ~1.45 g/cm^3) give 1170 kg/m^3; with ~10% of gas
    -- (the porosity below; a stirred batter's bubbles, estimated, not measured) 1050 kg/m^3
    density = 1050,
    -- specific heat: Choi & Okos composition model (ASHRAE), per kg of batter 0.54 water (4.18 kJ/(kg K)), 0.34
    -- carbohydrate (1.55), 0.07 protein (2.0), 0.04 fat (1.98), 0.01 ash (1.1): 3.0 kJ/(kg K)
    specific_heat = 3000,
    -- conductivity: the same model's volume-weighted parallel sum (water 0.61, carbohydrate 0.20, protein and fat
    -- 0.18, ash 0.33 W/(m K)) gives 0.46 W/(m K) for the airless batter; with 10% air (0.026) 0.41. Predicted, not
    -- measured; no dried-crust value is taken (no measurement found for a pancake's crust: dry_conductivity unset)
    conductivity = 0.41,
    -- dried, it holds less heat: the mixture rule as bread's (m c = m_s c_s, the solids' c_s = 1.65 kJ/(kg K) from
    -- the composition above), 0.46 x 1650 J/(kg K)
    dry_specific_heat = 0.46 * 1650,
    saturation = 0.567,                        -- 0.54 x 1050 / 1000
    -- liquid water diffusivity and surface evaporation: the muffin's (bread's liquid 2e-9 m^2/s, chosen within
    -- the 1e-10..1e-8 m^2/s range of baking models; the boiling front carries most of the water)
    water_diffusivity_m2s = 2e-9, evaporation = 1.2e-5,
    -- rheology and its set: E 1e4 Pa, 1e2 Pa s and the set (MUFFIN_SET: soft to 55 degC, x20 by 70 degC at starch
    -- gelatinisation) are the muffin batter's (batters are 1-100 Pa s fluids; no pancake batter rheometry found
    -- here). The yield stress is the pancake's own, from the shape recipes give it: about a quarter cup (59 mL) of
    -- batter a pancake ("a little less than 1/4 cup of batter will make a decent pancake", gist.github.com/willb/
    -- 170844) and 4-inch pancakes ("about fourteen 4-inch cakes", pastebin.com/qB56Nt3S), a disc 7.3 mm deep over
    -- R = 50.8 mm. A yield-stress puddle stops spreading when its height is H = sqrt(2 s R / (rho g)) (the
    -- lubrication shape h(x)^2 = 2 s (R - x) / (rho g)), so its shear yield stress is s = rho g H^2 / (2 R) = 5.4 Pa
    -- at the room's 20 degC; on this plugin's von Mises surface q = sqrt(3) s = 9.4 Pa (as the cookie's), x0.8 of
    -- the fridge point's on MUFFIN_SET: 11.7 Pa. The spread sets first where the pan sets the batter, so the
    -- batter's own yield stress is at most this. (Was the muffin's 20 Pa in the first runs: 10.6 mm thick before
    -- the flip at dx 2 mm, 9.7 mm with 11.7.)
    E = 1e4, nu = 0.3, tau_y = 11.7, mu = 100, max_porosity = 0.6, curve = "muffin",
    -- no CO2: the baking powder's rise is left out (gas_rate 0; the porosity the batter's stirred-in bubbles)
    gas_rate = 0, reaction_temperature = 60, reaction_width = 20, porosity = 0.1,
    expansion = 0.1, dough_temperature = 20,
    -- the griddle: 175-190 degC (350-375 degF) is the range cooking guides give for pancakes (e.g. whatis.eokultv.com,
    -- "griddle temperature guide"): 190. The contact: no measured batter-to-griddle coefficient was found here, so it
    -- is the conductance of the greased pan's oil film, k / delta: a teaspoon of oil (5 mL) over a 25 cm pan (0.049
    -- m^2) is 0.1 mm thick, vegetable oil conducts 0.17 W/(m K): 1700 W/(m^2 K). An upper bound: it leaves out the
    -- steam under the boiling face and the pan's own cooling where the batter lands (the pan here stays at 190 degC).
    -- The other presets' tray, 100 W/(m^2 K), boiled the pan face for minutes and browned it 0.0004 by the flip at
    -- dx 4 mm (docs/validation.md, "The physical pancake"). The air above: kitchen air at 25 degC, free convection
    -- 10 W/(m^2 K) (free convection in gases is 2-25 W/(m^2 K): Incropera & DeWitt, Table 1.1)
    oven_temperature = 25, oven_beta = 10, pan_temperature = 190, pan_beta = 1700,
    -- cooked 2 min on its first side, then flipped: recipes flip once bubbles open on the top and the edges look set
    -- (whatis.eokultv.com's guide), "until browned on the bottom, about 3 minutes" on a low heat (github.com/
    -- dpapathanasiou/recipes, mini chocolate chip pancakes); 2 min at this griddle's 190 degC, and 1.5 min on the
    -- second side: 3.5 min in 3.5 s
    time_scale = 60, bake_time_real = 210, flip_time_real = 120,
  },
  lava_cake = {
    -- Chocolate fondant (lava cake) batter (issue #18, helper lavaphys). The recipe: F. Cloake, "How to cook the
    -- perfect chocolate fondants" (The Guardian, Word of Mouth, 10 Feb 2011), for two: 60 g butter, 60 g dark
    -- chocolate, one egg and one yolk, 60 g caster sugar, a tablespoon of flour; baked 12 minutes at 200 degC on a
    -- hot tray (14 from the fridge), rested 30 s and turned out. Its composition, with an egg's 50 g (76% water,
    -- 12.5% protein, 10% fat), a yolk's 18 g (52%, 16%, 27%), butter 16% water and 81% fat, 70% dark chocolate ~1%
    -- water, ~40% fat, ~8% protein, ~46% carbohydrate, flour 9 g at 14% water (USDA-style tables; our reading, not
    -- one table): 257 g holding 23% water, 32% fat, 6% protein, 37% carbohydrate (mostly the sugar), 1% ash.
    -- No leavener: its air is the whisked eggs' (porosity 0.1, estimated as the pancake's: not measured).
    -- density: Choi & Okos's constituent densities at 20 degC (ASHRAE; water 998, fat 917, protein 1320,
    -- carbohydrate 1593, ash 2418 kg/m^3) give 1161 kg/m^3 for the airless batter; with 10% air 1045
    density = 1045,
    -- specific heat: Choi & Okos at 20 degC (water 4.18, fat 2.01, protein 2.03, carbohydrate 1.59, ash 1.13
    -- kJ/(kg K)), mass-weighted: 2.33 kJ/(kg K). The fat's melting heat (butter, cocoa butter at 20-35 degC) is left out
    specific_heat = 2330,
    -- conductivity: the same model's volume-weighted parallel sum (water 0.604, fat 0.175, protein 0.202,
    -- carbohydrate 0.228, ash 0.357 W/(m K) at 20 degC over volume fractions 0.27, 0.41, 0.05, 0.27, 0.005): 0.306
    -- W/(m K) airless, 0.28 with 10% air (0.026). Predicted, not measured; alpha = 1.15e-7 m^2/s
    conductivity = 0.28,
    -- dried, it holds less heat: the mixture rule as bread's (m c = m_s c_s), the solids' c_s = 1.77 kJ/(kg K) from
    -- the composition above, per kg of batter 0.77 x 1771 J/(kg K)
    dry_specific_heat = 0.77 * 1771,
    saturation = 0.240,                        -- 0.23 x 1045 / 1000
    -- liquid water diffusivity and surface evaporation: the muffin's (chosen, as bread's)
    water_diffusivity_m2s = 2e-9, evaporation = 1.2e-5,
    -- rheology of the raw batter: the muffin batter's E 1e4 Pa, viscosity 100 Pa s and yield 20 Pa at the fridge
    -- point (batters are 1-100 Pa s fluids; no fondant batter rheometry was found here). Melted (x0.3 from 35 degC,
    -- where butter and cocoa butter have melted) it yields at 6 Pa and flows at 10 Pa s, below molten chocolate's
    -- own (a Bingham 36 Pa and 8.7 Pa s for a milk chocolate, J. Rheol. 62:1187, 2018, "From elastic deformation
    -- to flow in tempered chocolate", abstract; Casson 29 Pa and 6.1 Pa s for a dark one, NETZSCH's glossary
    -- "Casson analysis"), which the batter dilutes with melted butter, egg and sugar.
    E = 1e4, nu = 0.3, tau_y = 20, mu = 100,
    -- the set: egg proteins, not starch (the batter holds a tablespoon of flour in 257 g). Egg white begins to
    -- thicken at 63 degC (ovotransferrin), yolk sets at 70 and whole egg "sets around 73 degC" (H. McGee 2004, On
    -- Food and Cooking, ch. 2, "egg-protein coagulation"); added sugar raises these, by an amount not given there,
    -- so McGee's plain-egg numbers are taken: the melted value held to 63 degC, set by 73. The set value: an
    -- open-cell foam collapses at ~0.05 of its modulus (Gibson & Ashby 1997, Cellular Solids, sigma_el ~ 0.05 E*),
    -- and sponge cake's measured elastic moduli are 1e3-1e4 Pa (J. Home Econ. Jpn. 38(12):1063, 1987, 1e4-1e5
    -- dyn/cm^2; the moduli rose with more butter and less egg, and a fondant is butter-rich): 0.05 x 1e4 = 500 Pa
    -- at this batter's E, x25 the fridge point's 20. (Both chosen at 07:05 UTC on this helper's day, before any run
    -- of this preset.) The cake stands on this choice: at 4 mm a set of 250 Pa kept 77% of its height but its foot
    -- ran 12 mm, 150 Pa 58%, 50 Pa (0.05 x the range's 1e3) 37% (docs/validation.md "The physical lava cake").
    set = { theta = { 5, 20, 35, 63, 73 }, tau = { 1, 0.8, 0.3, 0.3, 25 }, eta = { 1, 0.5, 0.1, 0.1, 0.05 } },
    gas_rate = 0, reaction_temperature = 60, reaction_width = 20, porosity = 0.1,
    expansion = 0.1, dough_temperature = 20,
    -- the oven: Cloake's 200 degC, beta 30 W/(m^2 K) (bread's: Baik et al. 1999). The mould: a metal pudding mould on
    -- a hot tray, taken at the oven's temperature through the other presets' 100 W/(m^2 K) contact. The batter from
    -- the room (20 degC: baked at once), so the egg set lies (73 - 20) / (200 - 20) = 29% of the way to the oven
    oven_temperature = 200, oven_beta = 30, pan_temperature = 200, pan_beta = 100,
    -- the mould's wall goes into the oven with the batter in it, at the room's 20 degC, and warms as a lumped sheet
    -- (Biot 30 x 0.0007 / 237 ~ 1e-4): a spun aluminium pudding (dariole) mould, its wall 0.7 mm (taken: no measured
    -- gauge here), 2702 kg/m^3 x 903 J/(kg K) (Incropera & DeWitt, Table A.1) x 0.0007 m = 1708 J/(m^2 K), heated on
    -- its outer face only by the oven's 30 W/(m^2 K): 1708 / 30 = 57 s. Its floor stands on the recipe's hot tray:
    -- through a ~0.1 mm air gap (0.035 W/(m K) / 1e-4 m ~ 350 W/(m^2 K)) it takes the tray's temperature in
    -- 1708 / 350 ~ 5 s, so lava_cake.lua keeps the floor at 200 degC and gives these two numbers to the wall only.
    -- A ceramic ramekin would not be a lumped sheet: a 4.5 mm wall of 2000 x 900 J/(m^3 K) holds 8100 J/(m^2 K)
    -- (270 s through the oven's face) and its Biot number with the batter's 100 W/(m^2 K) drawing on its inner face
    -- is (30 + 100) x 0.0045 / 1.5 = 0.39; the batter would take much of that heat, and across the wall: one
    -- lumped temperature is not fair there (docs/validation.md, "The muffin tin and the lava cake's mould go in cold"). pan_heat_capacity,
    -- that same 1708 J/(m^2 K): the batter's heat comes out of the wall (lava_cake.lua gives the wall's area; docs/
    -- validation.md, "The sheet gives the food its heat (#18, helper traydraw)")
    pan_start_temperature = 20, pan_warm_time_real = 57, pan_heat_capacity = 1708,
    -- 12 real minutes in 12 s (the muffin's and the pancake's S = 60): the scene's 0.4 s lift stands for 24 s of
    -- the heat history, about the recipe's 30 s rest
    time_scale = 60, bake_time_real = 720,
    -- the cake: one of Cloake's two, 257 g / 2 of batter at 1045 kg/m^3, 123 mL (m^3 here). The recipe's 12 minutes
    -- are for this size: a cake of Fig. 4's scene size (lava_cake.lua's 40 mm across, 30 mm high: 38 mL in 3D) set
    -- through at 2 and 4 mm by 11.5 minutes (docs/validation.md "The physical lava cake")
    portion = 257e-3 / 2 / 1045,
  },
}

local function curve(points, theta)
  local pts = { irreversible = true }
  for i, T in ipairs(theta) do pts[i] = { T, points(i) } end
  return pts
end

--- The physical preset of one good: plugin parameters, curve point lists (for h.curve), and its oven.
function D.preset(name)
  local g = D.goods[name]
  if not g then return nil end
  local S = g.time_scale
  local params = {
    E = g.E, nu = g.nu, density = g.density, specific_heat = g.specific_heat, dry_specific_heat = g.dry_specific_heat,
    conductivity = g.conductivity * S, dry_conductivity = g.dry_conductivity and g.dry_conductivity * S,
    -- eq. 22: D = K theta s at the boiling point and the dough's saturation
    water_diffusivity = g.water_diffusivity_m2s / (373.15 * g.saturation) * S,
    evaporation = g.evaporation * S, saturation = g.saturation,
    gas_rate = g.gas_rate * S, reaction_temperature = g.reaction_temperature, reaction_width = g.reaction_width,
    gas_rate_2 = g.gas_rate_2 and g.gas_rate_2 * S, reaction_temperature_2 = g.reaction_temperature_2,
    reaction_width_2 = g.reaction_width_2,
    gas_amount = g.gas_amount, gas_amount_2 = g.gas_amount_2, -- moles per kg: no time in them, not scaled by S
    porosity = g.porosity, max_porosity = g.max_porosity, expansion = g.expansion,
    ambient_pressure = g.ambient_pressure, open_temperature = g.open_temperature,
    reference_temperature = g.dough_temperature,
  }
  -- Fig. 8's points, a named set (the cookie's, lua/hearth/dough.lua's SET) or the good's own (g.set)
  local set = g.set or g.curve and require("hearth.dough").SET[g.curve]
  local theta, ts, ms = set and set.theta or THETA, set and set.tau or TAU_SHAPE, set and set.eta or MU_SHAPE
  local curves = {
    tau_y = curve(function(i) return g.tau_y * ts[i] end, theta),
    eta = curve(function(i) local t = g.tau_y * ts[i]; return 2 * t * t * g.mu * ms[i] / S end, theta),
  }
  -- the oven's radiating walls (core setting oven.wall_temperature, oven.emissivity; fields/thermal.h): no preset
  -- has them (no measured wall temperature for these ovens was found, docs/validation.md "An oven's hot walls"), so
  -- wall_temperature and emissivity stay nil (g.oven_wall_temperature, g.oven_emissivity if a good gives them); the
  -- scale is S, as beta's, for a scene that sets walls (--set oven.wall_temperature=... oven.emissivity=...)
  local oven = { temperature = g.oven_temperature, beta = g.oven_beta * S, pan_temperature = g.pan_temperature,
    wall_temperature = g.oven_wall_temperature, emissivity = g.oven_emissivity, radiation_scale = S,
    pan_beta = g.pan_beta * S, dough_temperature = g.dough_temperature, saturation = g.saturation,
    pan_start_temperature = g.pan_start_temperature, pan_warm_time = g.pan_warm_time_real and g.pan_warm_time_real / S,
    -- the sheet's own heat capacity per area (J/(m^2 K)), real: the scene's time runs S times fast through beta and
    -- the conductivity (x S), so the sheet's C over the scaled coefficients keeps its scaled time constant
    pan_heat_capacity = g.pan_heat_capacity,
    latent_heat = true, boiling_point = 100, browning_scale = S, time_scale = S, bake_time = g.bake_time_real / S,
    flip_time = g.flip_time_real and g.flip_time_real / S, portion = g.portion,
    -- open surface pores vent their CO2 (scene settings gas_vent, vent_porosity; core/sim/fields/gas.c): an open
    -- pore's CO2 diffuses into the air across ~1 mm, D / delta = 1.6e-5 m^2/s (CO2 in air near room temperature;
    -- ~3e-5 at 200 degC) / 1e-3 m ~ 0.02 m/s in real time, S times fast here; the pores open past a gas fraction of
    -- 0.7, where a foam's cells press into one another (spheres pack at 0.64-0.74)
    gas_vent = 0.02 * S, vent_porosity = 0.7,
    units = ("physical, heat and water %g times fast (t_real = %g t)"):format(S, S) }
  return params, curves, oven
end

D.THETA, D.TAU_SHAPE, D.MU_SHAPE = THETA, TAU_SHAPE, MU_SHAPE
return D

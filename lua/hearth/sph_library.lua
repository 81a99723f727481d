-- hearth.sph_library: presets from Rodriguez-Arenas 2011 (SPH baking thesis).
-- Loaded by init.lua as h.library.sph; called with h so it can build curves.
--
-- h.library.sph.bread_roll: Table 4.1 (solidification parameters) for the
-- maxwell_sph plugin, a fresh table on every access:
--   .material  parameters for h.material("maxwell_sph", ...):
--              mu_e      in Pa: the dough's set as measured bread sets (MU_E_SET below;
--                        the thesis's eq. 4.2 is .paper.mu_e)
--              viscosity eq. 4.1 through (T0, mu0), (Tc, muc), (Tf, muf)
--              C_lambda  eq. 4.3 (the arctan law is a parameter mode of the plugin)
--   .sph       for h.scene{solver = "sph", sph = ...}: the XSPH tuner of eq. 4.4
--              (linear from eps0 at T0 to eps_f at Tf; eps_f is 0.5 as in the text of
--              §4.3: Table 4.1 prints 5, XSPH above 1 overshoots and the core refuses
--              it), and how the dough holds together and rises (#18):
--                tension = true, the thesis's Tait (eq. 3.17) with its negative part:
--                  clamped, a dough has no cohesion and a slumping roll tears at its
--                  stretched base before it has warmed;
--                artificial_stress = 0.5 (Monaghan 2000) against the tensile
--                  instability tension brings (tension alone explodes by 0.7 s; at
--                  0.3 the dough films between the risen bubbles pair up and tear
--                  at 1.4 s, docs/validation.md "SPH bread roll (#18)");
--                gas_law = true: a bubble's rest density rho0 / V_b(T) (eq. 3.49-3.50
--                  in Kelvin), so the rise follows the temperature and is bounded by
--                  it (eq. 3.51 pushes by whatever it already gained: the top burst);
--                bubble_vapour = 0.95: the dough's water activity, the usual figure
--                  for bread (Czuchajowska, Pomeranz & Jeffers 1989, Cereal Chem. 66,
--                  128-132, measure a_w of doughs and crumb): the vapour of eq.
--                  2.42-2.43 joins the bubbles' gas, which is what makes dough rise
--                  well beyond a dry gas's T/T0 (1.5x at 180 degC);
--                renormalised_density = true: Tait reads the summed density over the
--                  part of the kernel the dough fills (Ferrand et al. 2013's gamma),
--                  so the outline and the tray side read no false stretch: without
--                  it their tension was a skin that beaded the roll off its tray and
--                  slit the finer roll (docs/validation.md "The roll's skin,
--                  renormalised");
--                gas_pressure = 101325: each bubble is as stiff as its own gas,
--                  P_a - P_v(T) (eq. 2.42-2.43 with 3.49-3.50 exactly), not the
--                  dough's Tait B, which is a 34th of it raw and 5x it hot: with B the
--                  crust's bubbles pushed up to 4.7x their gas near the boiling point
--                  (docs/validation.md "The bubble's own gas");
--                own_squeeze = true: the dough's Tait reads a squeeze only as far as
--                  its own det F confirms it (the sum's stretch stays): the sum over
--                  rest volumes read the dough beside hot bubbles the set crumb holds
--                  back as squeezed (to 1.1 MPa at 2 s), which arched the base off
--                  its tray and pushed the roll past 1.3x; without it the base stays
--                  on the tray (with eq. 4.2's early set the roll rose 1.14x, the gas
--                  volume reached before the crumb set; with MU_E_SET 1.43x, and the
--                  base's ends lift from 1.6 s: docs/validation.md "The roll's base:
--                  its own squeeze", "The roll's set").
--                hourglass = 0.5 (core/sim/solver/sph_hourglass.c): damps the pairs'
--                  motion eq. 3.27's gradient does not describe, with half eq. 3.19's
--                  pair viscosity. Chosen over an ensemble of the same roll, not one
--                  run (the roll is deterministic, but a microkelvin's warmth or a
--                  move along the tray changes which cavity opens): at 0.5 the roll
--                  stayed whole in all 4 runs at 2 mm to 3 s (at most 0.36, 1.81,
--                  0.89, 1.71% of the outline torn; the bar is 2%) and all 3 at 1.5 mm
--                  to 2 s (1.14, 1.33, 1.29%), rising 1.431-1.440x; with 0 (before)
--                  the 2 mm roll tore 2.02% at 2.4 s in the claims' run, with 1 the
--                  1.5 mm roll tore 2.08% at 2.0 s. The margin at 2 mm is thin (1.81%),
--                  and the base still lifts 5.9-6.3 mm by 2 s (docs/validation.md "The
--                  hourglass control over an ensemble").
--   .paper     eq. 4.2 as printed, mu_e through (T0, mu_e0), (Tc, mu_ec), (Tf, mu_ef) of
--              Table 4.1 (animation units; the scene scales it by 100 with --set
--              mu_e_curve=table).
--   .table     the raw Table 4.1 numbers.
-- MU_E_SET (#18, helper rollset): eq. 4.2 is not a measured law. The thesis (§4.3)
-- gives mu_e "the same rate of change given by the viscosity changes" of Fan et
-- al. "due to the lack of experimental data": linear from mu_ec at Tc = 45 degC to
-- mu_ef at 120, a 5000-fold rise linear in T. Scaled by 100 (the roll's scene),
-- that passes the bubbles' 10-20 kPa of gas at 45.3 degC and is 1.3 MPa at 65: the
-- crumb set before 50 degC and held the roll at 1.14x (docs/validation.md "The
-- roll's base: its own squeeze"). A bread dough sets later: oven spring stops
-- when the interior reaches 68-80 degC, where the gluten cross-links and the
-- starch gelatinises (H. McGee 2004, On Food and Cooking, "mid-baking: from foam
-- to sponge"); wheat starch begins to gelatinise and the loaf's expansion slows
-- at 60-70 degC, and the structure is formed by 70-80 (J. Hamelman 2004, Bread,
-- his table of baking temperatures). So the curve here keeps Table 4.1 x 100 up
-- to Tc (100 Pa raw, 1 kPa at 45 degC: the soft dough the roll's slump and tray
-- were measured with; a dough's small-strain G' of 1-10 kPa at 1 Hz,
-- Dobraszczyk & Morgenstern 2003, J. Cereal Sci. 38:229, is its plateau, and
-- they note that such tests are not at breadmaking's long times), holds it to 68
-- degC, rises log-linearly over McGee's 68-80 degC (points every 3 degC, three
-- figures) to a set crumb's cell-wall modulus at 80, and joins Table 4.1 x 100 at
-- Tf (5 MPa at 120 degC, the drying crust). The set value: bread crumb's Young's
-- modulus is ~50 kPa at small strain (7-8 kPa in tension; the review of Scanlon &
-- Zghal 2001, Food Res. Int. 34:841, as its text reads online), and an open-cell
-- foam's modulus is its wall's times the squared relative density (Gibson &
-- Ashby 1988): at 75-85% porosity (crumb) the wall's E is 0.8-2.2 MPa, mu_e =
-- 2 G = 2 E / 3 = 0.5-1.5 MPa; 1 MPa taken. Measured: docs/validation.md "The roll's
-- set: the crumb sets where bread does (#18, helper rollset)".
-- Difference from the thesis: eq. 4.1 and 4.2 extrapolate linearly beyond T0
-- and Tf; hearth's curves are constant beyond their end points.
-- The thesis's values are scaled for animation (its units are not SI
-- rheometry); bulk modulus and density are hearth's choices for a dough.
return function(h)
  local T41 = { T0 = 26, Tc = 45, Tf = 120, mu0 = 0.1, muc = 1, muf = 5e3, mue0 = 1, muec = 10, muef = 5e4,
                C_lambda = 450, eps0 = 0.05, epsf = 5 }
  -- MU_E_SET above: (degC, Pa); soft to 68 degC, log-linear to 1 MPa at 80 (1e3 x 1000^(k/4)), then Table 4.1 x 100
  local MU_E_SET = { { 26, 100 }, { 45, 1e3 }, { 68, 1e3 }, { 71, 5620 }, { 74, 31600 }, { 77, 178000 }, { 80, 1e6 },
                     { 120, 5e6 } }
  local presets = {
    bread_roll = function()
      local t = T41
      return {
        paper = { mu_e = h.curve { { t.T0, t.mue0 }, { t.Tc, t.muec }, { t.Tf, t.muef } } },
        material = {
          mu_e = h.curve(MU_E_SET),
          viscosity = h.curve { { t.T0, t.mu0 }, { t.Tc, t.muc }, { t.Tf, t.muf } },
          C_lambda = t.C_lambda, density = 1100, bulk = 2e4,
        },
        -- eps_f: §4.3's text value 0.5, not Table 4.1's 5 (XSPH overshoots above 1; the core refuses it)
        sph = { xsph0 = t.eps0, xsph_f = 0.5, xsph_T0 = t.T0, xsph_Tf = t.Tf, tension = true, artificial_stress = 0.5,
                gas_law = true, bubble_vapour = 0.95, bubble_T0 = t.T0, renormalised_density = true,
                gas_pressure = 101325, own_squeeze = true, hourglass = 0.5 },
        table = (function() local c = {} for k, v in pairs(t) do c[k] = v end return c end)(),
      }
    end,
  }
  local names = {}
  for k in pairs(presets) do names[#names + 1] = k end
  table.sort(names)
  return setmetatable({}, {
    __index = function(_, name)
      local f = presets[name]
      if not f then
        error(("h.library.sph: no preset '%s' (valid: %s)"):format(tostring(name), table.concat(names, ", ")), 2)
      end
      return f()
    end,
  })
end

-- hearth.sph_library: presets from Rodriguez-Arenas 2011 (SPH baking thesis).
-- Loaded by init.lua as h.library.sph; called with h so it can build curves.
--
-- h.library.sph.bread_roll: Table 4.1 (solidification parameters) for the
-- maxwell_sph plugin, a fresh table on every access:
--   .material  parameters for h.material("maxwell_sph", ...):
--              mu_e      eq. 4.2 through (T0, mu_e0), (Tc, mu_ec), (Tf, mu_ef)
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
--                  on the tray and the roll rises 1.14x, the gas volume reached before
--                  the crumb sets (docs/validation.md "The roll's base: its own
--                  squeeze").
--   .table     the raw Table 4.1 numbers.
-- Difference from the thesis: eq. 4.1 and 4.2 extrapolate linearly beyond T0
-- and Tf; hearth's curves are constant beyond their end points.
-- The thesis's values are scaled for animation (its units are not SI
-- rheometry); bulk modulus and density are hearth's choices for a dough.
return function(h)
  local T41 = { T0 = 26, Tc = 45, Tf = 120, mu0 = 0.1, muc = 1, muf = 5e3, mue0 = 1, muec = 10, muef = 5e4,
                C_lambda = 450, eps0 = 0.05, epsf = 5 }
  local presets = {
    bread_roll = function()
      local t = T41
      return {
        material = {
          mu_e = h.curve { { t.T0, t.mue0 }, { t.Tc, t.muec }, { t.Tf, t.muef } },
          viscosity = h.curve { { t.T0, t.mu0 }, { t.Tc, t.muc }, { t.Tf, t.muf } },
          C_lambda = t.C_lambda, density = 1100, bulk = 2e4,
        },
        -- eps_f: §4.3's text value 0.5, not Table 4.1's 5 (XSPH overshoots above 1; the core refuses it)
        sph = { xsph0 = t.eps0, xsph_f = 0.5, xsph_T0 = t.T0, xsph_Tf = t.Tf, tension = true, artificial_stress = 0.5,
                gas_law = true, bubble_vapour = 0.95, bubble_T0 = t.T0, renormalised_density = true,
                gas_pressure = 101325, own_squeeze = true },
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

-- loaf_open.lua: scripts/scenes/baking/loaf_physical.lua (the physical loaf, h.library.dough.bread, on its tray)
-- with the pores' opening temperature set from outside, for docs/validation.md ("The cells open over their measured
-- range (#18, helper openrange)"): which opening temperature lets the loaf rise without tearing, at which dx?
--   open   the material's open_temperature (degC; the preset's 70): the cells open and the gas stops pushing
--          there (core/sim/fields/gas.h, gas_tau_ambient). With the openrange branch's experiment commit the
--          cells open over [open, open + 10 K] instead of at once (a hard-coded width, that commit only).
--   hearth run scripts/validation/loaf_open.lua --quiet [--set dx=0.0025] [--set open=72] [--out DIR]
-- from the source root (or --set loaf=PATH to loaf_physical.lua). It writes what loaf_physical.lua writes
-- (loaf.csv: the area, height and base_gap_m per real minute; temperature_%04d.png; browning.png): look at the
-- frames, a torn flank or crown shows there and in no single number.
local h = require "hearth"
local P = h.params { dx = 0.005, frames = 25, latent = true, until_real = 0, tray = "separate", open = 70,
  loaf = "scripts/scenes/baking/loaf_physical.lua" }

-- loaf_physical.lua's own h.params sees the values parsed here (it declares a subset of these names)
h.pass_params(P)

-- the loaf's material: the preset with its open_temperature replaced (only a material with ambient_pressure reads it)
local material = h.material
h.material = function(plugin, params)
  if params.ambient_pressure then
    local q = {}
    for k, v in pairs(params) do q[k] = v end
    q.open_temperature = P.open
    params = q
  end
  return material(plugin, params)
end

dofile(P.loaf)

-- loaf_water.lua: scripts/scenes/baking/loaf_physical.lua (the physical loaf, h.library.dough.bread, on its tray)
-- with the dough's surface evaporation beta^w and liquid water diffusivity D multiplied from outside, for
-- docs/validation.md ("When does the loaf's crust dry? (#18, helper crustdry)"): does the top's colour at 25 min
-- move when its surface dries sooner or later? What-ifs only: the preset's numbers stay.
--   evap   multiplies the preset's evaporation (beta^w 1.2e-5 kg/(m^2 s K) in real time, "chosen" in
--          lua/hearth/dough_physical.lua); the heat and mass transfer analogy at the oven's convective part gives
--          4-8 times it (docs/validation.md, the section above)
--   diff   multiplies the preset's water diffusivity (2e-9 m^2/s at 373 K and s0, chosen within 1e-10..1e-8)
--   hearth run scripts/validation/loaf_water.lua --quiet [--set dx=0.0025] [--set evap=8] [--set diff=0.1] [--out DIR]
-- from the source root (or --set loaf=PATH to loaf_physical.lua). It writes what loaf_physical.lua writes.
local h = require "hearth"
local P = h.params { dx = 0.005, frames = 25, latent = true, until_real = 0, tray = "separate", h_c = 0, evap = 1,
  diff = 1, loaf = "scripts/scenes/baking/loaf_physical.lua" }

-- loaf_physical.lua's own h.params sees the values parsed here (it declares a subset of these names)
h.pass_params(P)

-- the loaf's material: the preset with its evaporation and diffusivity scaled (the dough is the one material with
-- ambient_pressure in that scene; the tray is a collider)
local material = h.material
h.material = function(plugin, params)
  if params.ambient_pressure then
    local q = {}
    for k, v in pairs(params) do q[k] = v end
    q.evaporation = params.evaporation * P.evap
    q.water_diffusivity = params.water_diffusivity * P.diff
    params = q
  end
  return material(plugin, params)
end

dofile(P.loaf)

-- loaf_whatif.lua: scripts/scenes/baking/loaf_physical.lua (the physical loaf, h.library.dough.bread, on its tray)
-- with one of the dough preset's numbers changed from outside, for docs/validation.md's what-ifs. The preset's
-- numbers stay; each knob's default is the preset's.
--   open   the material's open_temperature (degC; the preset's 70): the cells open and the gas stops pushing
--          there (core/sim/fields/gas.h, gas_tau_ambient): which opening temperature lets the loaf rise without
--          tearing, at which dx? ("The cells open over their measured range (#18, helper openrange)")
--   evap   multiplies the preset's evaporation (beta^w 1.2e-5 kg/(m^2 s K) in real time, "chosen" in
--          lua/hearth/dough_physical.lua; the heat and mass transfer analogy at the oven's convective part gives
--          4-8 times it), and
--   diff   multiplies the preset's water diffusivity (2e-9 m^2/s at 373 K and s0, chosen within 1e-10..1e-8): does
--          the top's colour at 25 min move when its surface dries sooner or later? ("When does the loaf's crust
--          dry, against measurements? (#18, helper crustdry)")
--   hearth run scripts/validation/loaf_whatif.lua --quiet [--set dx=0.0025] [--set open=72] [--set evap=8]
--     [--set diff=0.1] [--out DIR]
-- from any folder (the scene is found beside this script: h.scene_path; or --set loaf=PATH to loaf_physical.lua). It
-- writes what loaf_physical.lua writes (loaf.csv: the area, height and base_gap_m per real minute;
-- temperature_%04d.png; browning.png: look at the frames, a torn flank or crown shows there and in no single
-- number), and at the end prints the loaf's axis column (particles within dx/2 of it, from the top down): each one's
-- depth under the top particle, saturation and browning, and where the moisture ratio X = s / s0 first reaches 0.5
-- (the dried layer).
local h = require "hearth"
local P = h.params { dx = 0.005, frames = 25, latent = true, until_real = 0, tray = "separate", open = 70, h_c = 0,
  evap = 1, diff = 1, loaf = h.scene_path("../scenes/baking/loaf_physical.lua") }

-- loaf_physical.lua's own h.params sees the values parsed here (it declares a subset of these names)
h.pass_params(P)

-- the loaf's material: the preset with the knobs applied (the dough is the one material with ambient_pressure in
-- that scene; the tray is a collider)
local material = h.material
h.material = function(plugin, params)
  if params.ambient_pressure then
    local q = {}
    for k, v in pairs(params) do q[k] = v end
    q.open_temperature = P.open
    q.evaporation = params.evaporation * P.evap
    q.water_diffusivity = params.water_diffusivity * P.diff
    params = q
  end
  return material(plugin, params)
end

-- the scene loaf_physical.lua makes, to read its particles at the end
local scene, made = h.scene, nil
h.scene = function(...)
  made = scene(...)
  return made
end

dofile(P.loaf)

-- the dried layer on the axis column (helper crustdry)

local r, X0, s0, col = made:particles { fields = { "x", "saturation", "browning" } }, 0.07, 0.218, {}
for i = 1, r.n do
  if math.abs(r.x[3 * i - 2] - X0) < P.dx / 2 then col[#col + 1] = { r.x[3 * i - 1], r.saturation[i], r.browning[i] } end
end
table.sort(col, function(a, b) return a[1] > b[1] end)
local top, half = col[1][1], nil
for k = 2, #col do
  if col[k][2] >= 0.5 * s0 and not half then -- X = 0.5 between this particle and the one above, linearly
    local a, b = col[k - 1], col[k]
    half = top - (a[1] + (0.5 * s0 - a[2]) / (b[2] - a[2]) * (b[1] - a[1]))
  end
end
print(("axis column at the end, dx %g m: X = 0.5 at %s mm under the top particle"):format(P.dx,
  half and ("%.2f"):format(half * 1e3) or "(none)"))
for k = 1, math.min(14, #col) do
  print(("  %.2f mm under the top particle: saturation %.4f, browning %.4f"):format((top - col[k][1]) * 1e3, col[k][2],
    col[k][3]))
end

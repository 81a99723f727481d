-- Drying an apple slice (Ding et al. §7.1, Figs. 9 and 13): wet flesh under a
-- thin, drier and stiffer skin, at constant temperature on a tray. Water
-- diffuses to the surface and evaporates; as it goes, the water pressure
-- (eq. 14) pulls the flesh in and the slice shrinks and curls.
--   hearth run scripts/scenes/drying.lua [--set momentum=1] [--set duration=3]
-- The rates are a time lapse: drying that takes hours is compressed into
-- seconds (evaporation and diffusivity scaled up together), so a run stays
-- under a minute while the elastic waves are still resolved.
-- Writes frames of saturation and drying.csv (time, water left, area).
local h = require "hearth"
local P = h.params {
  momentum = h.number { 0, min = 0, max = 1, integer = true, what = "the water's own momentum (1: on, 0: off)" },
  duration = h.number { 3, above = 0, unit = "s", what = "the run's simulated time" },
  temperature = h.number { 60, min = -273.15, max = 5000, unit = "degC",
    what = "the oven air's (and the slice's start)" } }

local s = h.scene { dim = 2, dx = 1 / 500, box = { { 0, 0 }, { 0.1, 0.04 } }, gravity = { 0, -9.81 },
  oven = { temperature = P.temperature, beta = 20 }, water_momentum = P.momentum == 1 }
local common = { nu = 0.3, density = 1050, conductivity = 0.5, specific_heat = 3600, evaporation = 0.4 / 333 }
local function with(t) for k, v in pairs(common) do t[k] = t[k] or v end return t end
-- flesh: wet and soft; skin: drier, stiffer, and water crosses it slowly
local flesh = h.material("elastic", with { E = 3e4, water_diffusivity = 3e-6 / 333, water_stiffness = 8e4 })
local skin = h.material("elastic", with { E = 3e5, water_diffusivity = 3e-7 / 333, water_stiffness = 8e4 })
s:add { shape = h.box({ 0.02, 0.012 }, { 0.08, 0.020 }), material = flesh, saturation = 0.85, temperature = P.temperature }
s:add { shape = h.box({ 0.02, 0.020 }, { 0.08, 0.022 }), material = skin, saturation = 0.3, temperature = P.temperature }
s:collider { shape = h.plane({ 0, 0.012 }, { 0, 1 }), mode = "sticky" }

local w0 = s:stats().water_mass
local rows = { "t_s,water_fraction,area_m2,water_lost_kg_per_m" }
s:run { until_t = P.duration, every = P.duration / 30, png = { field = "saturation", path = "frames/sat_%04d.png" },
  on_frame = function(f)
    local st = f.scene:stats()
    rows[#rows + 1] = ("%.4f,%.6f,%.8g,%.6g"):format(f.t, st.water_mass / w0, f.scene:volume(), st.water_lost)
    h.write("drying.csv", table.concat(rows, "\n") .. "\n")
  end }
local st = s:stats()
print(("dried to %.1f%% of its water; area %.4g m^2 (momentum coupling %s)"):format(100 * st.water_mass / w0,
  s:volume(), P.momentum == 1 and "on" or "off"))

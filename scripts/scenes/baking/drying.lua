-- Dehydrating an apple slice (Ding et al. 2019 §7.1, Figs. 9 and 13): wet
-- cam_clay_dough flesh (high saturation) under a thin skin that holds little
-- water, dried at one constant temperature on a rack. Water diffuses to the
-- air boundary and evaporates (eq. 14's flux); the water pressure
-- -c (s - s0) I pulls the flesh in, so the slice shrinks, and where the
-- shrinking strain passes the yield surface it stays (the wrinkles).
--   hearth run scripts/scenes/baking/drying.lua [--set dim=3] [--set until_t=12]
-- What it shows (2D, dx 2.5 mm, measured at commit d59d707, #18): by the default 2 s 11.9% of the water is gone and
-- 9.4% of the area, a flat slab whose skin grows wetter from the flesh (saturation 0.32 -> 0.47); by 12 s (30 s of
-- CPU) 52.5% is gone and 32% of the area, the slice shrunk to a low ridge with a notch or two in its top, but
-- no wrinkles as Ding's Figs. 9 and 13 show (docs/validation.md, "The shipped scenes as a user meets them").
-- Rates are a time lapse (as scripts/scenes/drying.lua): hours of drying in
-- seconds, diffusivity and evaporation scaled up together.
-- --set latent_heat=true takes L = 2.26 MJ/kg from the heat of the water that
-- evaporates (issue #18). The time lapse scales evaporation, not heat, so the
-- sink is ~500x the oven's beta (L x evaporation = 1e4 W/(m^2 K) against 20):
-- the slice falls far below the air's temperature; docs/validation.md ("Latent
-- heat of evaporation (#18)") has the numbers. Off by default for that reason.
-- Writes, under hearth-out/drying/: sat_%04d.png (saturation) and drying.csv
-- (time, water fraction left, volume by s:volume(): volume_m2 in 2D, volume_m3 in 3D, and
-- temperature (degC) and saturation at the skin's top and the flesh's centre).
local h = require "hearth"
local P = h.params { dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" },
  dx = h.number { 0.0025, above = 0, unit = "m", what = "the grid spacing" },
  until_t = h.number { 2, above = 0, unit = "s", what = "the run's simulated time" },
  frames = h.number { 20, min = 1, integer = true, unit = "frames", what = "PNG frames over the run" },
  temperature = h.number { 60, min = -273.15, max = 5000, unit = "degC",
    what = "the oven air's (and the slab's start)" },
  latent_heat = h.flag { false,
    what = "evaporation takes L = 2.26 MJ/kg from the slice's heat (the time lapse makes it ~500x the oven's)" } }
local d3 = P.dim == 3
local dx = h.dx_3d(P.dx, 0.004, d3) -- says so when it raises dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local L, H, SKIN, RACK, zc = 0.06, 0.008, 0.002, 0.012, 0.03 -- m: slice length, flesh height, skin, rack height
local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(0.1, 0.04, 0.06) },
  oven = { temperature = P.temperature, beta = 20 }, latent_heat = P.latent_heat, name = "drying" }
-- The flesh: an apple's density and heat, a stiff, strong dough (the cell
-- walls) that yields once drying strains it well past the elastic range.
local function apple(E, tau, D)
  return h.material("cam_clay_dough", {
    E = E, nu = 0.3, density = 1050, specific_heat = 3600, conductivity = 0.5,
    tau_y = tau, eta = 0, gas_rate = 0, porosity = 0.1, expansion = 0, reference_temperature = P.temperature,
    water_diffusivity = D, evaporation = 1.5 / 333, water_stiffness = 8e4 })
end
local flesh = apple(3e4, 2e3, 1e-5 / 333)
local skin = apple(3e5, 2e4, 1e-6 / 333) -- tougher, and water crosses it slowly
local x0, x1 = 0.02, 0.02 + L
local zlo, zhi = zc - L / 2, zc + L / 2
s:add { shape = h.box(v(x0, RACK, zlo), v(x1, RACK + H, zhi)), material = flesh, saturation = 0.85,
  temperature = P.temperature, ppc = d3 and 8 or 4 }
s:add { shape = h.box(v(x0, RACK + H, zlo), v(x1, RACK + H + SKIN, zhi)), material = skin, saturation = 0.3,
  temperature = P.temperature, ppc = d3 and 8 or 4 }
s:collider { shape = h.plane(v(0, RACK, 0), v(0, 1, 0)), mode = "sticky" }

local w0 = s:stats().water_mass
-- the skin's top (half a particle spacing in) and the flesh's centre, mid-slice. The slice shrinks as it dries
-- (its top falls ~2 mm by 12 s), so the top is found each frame: the highest point with material on the mid-slice
-- line (a fixed point there read the air, NaN, once the slice fell below it)
local xm, centre = (x0 + x1) / 2, v((x0 + x1) / 2, RACK + H / 2, zc)
local function top()
  local n, y0, y1 = 200, RACK, RACK + H + SKIN + dx
  local col = s:line("saturation", v(xm, y0, zc), v(xm, y1, zc), n + 1)
  local y = RACK + H + SKIN
  for i = n + 1, 1, -1 do
    if col[i] == col[i] then y = y0 + (i - 1) * (y1 - y0) / n; break end
  end
  return v(xm, y - dx / 4, zc)
end
local function probes()
  local p = top()
  return s:probe("temperature", p), s:probe("saturation", p), s:probe("temperature", centre),
    s:probe("saturation", centre)
end
-- the columns' units in their names: volume_m2 in 2D (m^2 per metre of depth), volume_m3 in 3D; saturations are 0..1
local rows = { ("t_s,water_fraction,%s,top_T_degC,top_saturation,centre_T_degC,centre_saturation"):format(d3 and "volume_m3" or "volume_m2") }
-- the title says what its seconds are: water's rates are a time lapse (scaled up together by a factor the header
-- does not name, so no time_scale), heat's are an apple's own
s:run { until_t = P.until_t, every = P.until_t / P.frames, png = { field = "saturation", path = "sat_%04d.png",
    label = "time lapse: drying's hours in seconds; heat in real time" },
  on_frame = function(f)
    local st = f.scene:stats()
    rows[#rows + 1] = ("%.4f,%.6f,%.8g,%.3f,%.4f,%.3f,%.4f"):format(f.t, st.water_mass / w0, f.scene:volume(), probes())
    h.write("drying.csv", table.concat(rows, "\n") .. "\n")
  end }
local st = s:stats()
print(("%.1f%% of its water left (%.1f%% evaporated); volume %.4g %s"):format(100 * st.water_mass / w0,
  100 - 100 * st.water_mass / w0, s:volume(), d3 and "m^3" or "m^2"))
print(("latent_heat = %s: skin top %.1f degC at saturation %.3f, flesh centre %.1f degC at saturation %.3f")
  :format(tostring(P.latent_heat), probes()))

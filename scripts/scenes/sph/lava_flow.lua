-- Lava-like flow down a slope with a temperature-dependent XSPH tuner, with
-- the SPH solver (Rodriguez-Arenas 2011 Fig. 3.17).
--   hearth run scripts/scenes/sph/lava_flow.lua [--set xsph_cold=0.05 --set cooling=1.2]
-- A block of hot lava-like fluid (newtonian, its viscosity rising as it cools
-- through h.curve) is released at the top of a slope in cold air. Surface
-- particles lose heat to the air (eq. 3.42 per unit area, the oven here being
-- the air; cooling = h / c in kg/(m^2 s), animation-scaled: 8 is the thesis's
-- printed form with 2e8 at dx 5 mm, 2e8 dx^3 / pi) and
-- the heat diffuses (eq. 3.45). XSPH (eq. 3.34) smooths each particle's
-- velocity toward its neighbours' with a tuner linear in temperature (eq.
-- 4.4): small while hot (the lava runs), large once cold (it moves as a
-- crust and stalls). --set xsph_cold=0.05 (the hot value everywhere) shows the
-- flow without the tuner.
-- Writes front.csv: the position of the flow front along the slope (its
-- farthest particle), the mean temperature of the particles' rows in a
-- temperature slice, over time (t_s, s); and temperature frames.
local h = require "hearth"
-- the viscosity curve runs from T_air through 600 degC to T_hot, so T_air lies below 600 and T_hot above it
local P = h.params { dx = h.number { 0.005, above = 0, unit = "m", what = "the grid spacing" },
  T_hot = h.number { 1100, above = 600, max = 5000, unit = "degC", what = "the lava's eruption temperature" },
  T_air = h.number { 20, min = -273.15, below = 600, unit = "degC", what = "the air's temperature" },
  xsph_hot = h.number { 0.05, min = 0, max = 1, what = "XSPH's epsilon in the hot lava (h.scene's range)" },
  xsph_cold = h.number { 0.9, min = 0, max = 1, what = "XSPH's epsilon in the cold lava (h.scene's range)" },
  cooling = h.number { 8, min = 0, max = 1e6, what = "the air's heat transfer to the surface (sph.heat_ext)" },
  until_t = h.number { 3.0, min = 0, unit = "s", what = "the run's simulated time (0: the set-up alone, measured)" } }

local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.8, 0.3 } }, solver = "sph",
  sph = { heat_ext = P.cooling, heat_int = 2, av_beta = 1, alpha_c = 0.1, beta_c = 0.9,
          -- eq. 4.4: epsilon from xsph0 at xsph_T0 to xsph_f at xsph_Tf (held beyond)
          xsph0 = P.xsph_cold, xsph_T0 = P.T_air, xsph_f = P.xsph_hot, xsph_Tf = P.T_hot },
  oven = { temperature = P.T_air, beta = 0 } }
local lava = h.material("newtonian", {
  density = 2500, bulk = 1e5,
  viscosity = h.curve { { P.T_air, 20 }, { 600, 5 }, { P.T_hot, 1 } },
})

-- the slope: a plane through (0, 0.2) falling to (0.8, 0.04)
local p0, p1 = { 0, 0.2 }, { 0.8, 0.04 }
local tx, ty = p1[1] - p0[1], p1[2] - p0[2]
local len = math.sqrt(tx * tx + ty * ty)
tx, ty = tx / len, ty / len
s:collider { shape = h.plane(p0, { -ty, tx }), mode = "slip" }
-- the lava: a block resting on the top of the slope
local block = h.box({ 0.01, 0.0 }, { 0.11, 0.26 })
s:add { shape = h.difference(block, h.plane(p0, { -ty, tx })), material = lava, ppc = 1, jitter = 0,
  temperature = P.T_hot }

-- the front: the farthest particle along the slope, measured from its top
local function front()
  local x, far = s:positions(), -math.huge
  for i = 1, #x, 3 do
    local d = (x[i] - p0[1]) * tx + (x[i + 1] - p0[2]) * ty
    if d > far then far = d end
  end
  return far
end
local function mean_T()
  local T = s:slice("temperature", { res = { 80, 30 } })
  local sum, n = 0, 0
  for _, row in ipairs(T) do for _, v in ipairs(row) do if v == v then sum, n = sum + v, n + 1 end end end
  return n > 0 and sum / n or 0 / 0
end
local csv = { "t_s,front_m,mean_temperature_degC" }
s:run { until_t = P.until_t, every = 0.1, png = { field = "temperature", path = "frames/temperature_%04d.png" },
  on_frame = function(f)
    csv[#csv + 1] = ("%.4f,%.5f,%.1f"):format(f.t, front(), mean_T())
    h.write("front.csv", table.concat(csv, "\n") .. "\n")
  end }
print(("lava flow: front %.3f m down the slope at t = %.2f s (mean %.0f degC)"):format(front(), s:stats().t, mean_T()))

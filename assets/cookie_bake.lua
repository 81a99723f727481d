-- The scene `hearth` opens when it is given none: one cookie of Ding et al.'s
-- dough (Table 2, h.library.paper.cookie) baking on a hot tray in a 180 degC
-- oven. The left view shows temperature, the right saturation.
--   at the prompt:  s:oven(220)    hotter air
--                   s:run{until_t = 20}
local h = require "hearth"
local oven = h.library.paper_oven.cookie
print("cookie_bake.lua: h.library.paper.cookie, animation units (Ding Table 2): heat runs in seconds, not minutes")
local TRAY = 0.02
local s = h.scene { dim = 2, dx = 1 / 250, box = { { 0, 0 }, { 0.16, 0.09 } },
  oven = { temperature = 180, beta = oven.beta }, name = "cookie", time_units = "animation" }
h.recipes.tray(s, TRAY, { temperature = 180, beta = oven.pan_beta })
local d = h.library.paper.cookie
d.gas_rate = 0.0075 * h.library.dough_scale.gas
-- a little water, so the saturation view has something to show as the surface dries
d.water_diffusivity, d.evaporation, d.saturation = 2e-8, 2e-6, 0.4
s:add { shape = h.shapes.cookie({ 0.08, TRAY + 0.0125 }, 0.03, 0.025), material = h.material("cam_clay_dough", d),
  temperature = oven.dough_temperature }
cookie = s -- a global, so the prompt can reach it as `cookie` or `s`
s:run { until_t = 30, every = 0.5, csv = "cookie.csv", probes = { { "temperature", { 0.08, TRAY + 0.01 } } } }

-- The scene `hearth` opens when it is given none: one cookie of Ding et al.'s
-- dough (Table 2, h.library.paper.cookie) baking on a hot tray in a 180 degC
-- oven. The left view shows temperature, the right saturation (the cookie's water, below: what is chosen and why).
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
-- Water (Ding Table 2 gives the cookie none; #18, helper userfix10: these had been invented, 2e-8, 2e-6 and 0.4 "so
-- the saturation view has something to show"): the physical cookie's (h.library.dough.cookie, dough_physical.lua:
-- diffusivity 1e-9 m^2/s chosen within baking models' 1e-10..1e-8, evaporation 1.2e-5 kg/(m^2 s K) for a wet
-- surface's ~1 g/(m^2 s)) on a water clock as lua/hearth/dough.lua's WATER_S maps bread's (2.5 s for 25 min): the
-- paper cookie's 5 s bake (cookies.lua) for the physical one's 11 minutes, W = 132. The saturation is the paper
-- cookie's own raw water, X_0 = 0.25 kg/kg dry basis (20 % wet basis: dough.lua's DRY_X0, which its drying curves
-- divide by) at Table 2's density, eq. 8: s_0 = 0.20 x 500 / 1000 = 0.10.
local real, real_oven = h.library.dough.cookie, h.library.oven.cookie
local W = real_oven.bake_time * real_oven.time_scale / 5 -- real seconds per simulated second, for the water
d.saturation = 0.20 * 500 / 1000
-- eq. 22's K = D / (theta s_0): the preset's K back to its real D (x its s_0 / its time_scale), then over this s_0 x W
d.water_diffusivity = real.water_diffusivity * real.saturation / d.saturation * W / real_oven.time_scale
d.evaporation = real.evaporation * W / real_oven.time_scale
print(("cookie_bake.lua: its water h.library.dough.cookie's, %g times fast (the paper's 5 s bake for the real %g "
  .. "minutes), saturation %g (20 %% wet basis)"):format(W, real_oven.bake_time * real_oven.time_scale / 60,
  d.saturation))
s:add { shape = h.shapes.cookie({ 0.08, TRAY + 0.0125 }, 0.03, 0.025), material = h.material("cam_clay_dough", d),
  temperature = oven.dough_temperature }
cookie = s -- a global, so the prompt can reach it as `cookie` or `s`
s:run { until_t = 30, every = 0.5, csv = "cookie.csv", probes = { { "temperature", { 0.08, TRAY + 0.01 } } } }

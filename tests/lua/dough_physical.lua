-- The physical dough presets (h.library.dough / h.library.oven, issue #18) and
-- the paper's (h.library.paper / h.library.paper_oven) from a scene.
local h = require "hearth"
for _, name in ipairs { "bread", "cookie", "muffin" } do
  local d, o = h.library.dough[name], h.library.oven[name]
  local S = o.time_scale
  assert(S > 1 and o.bake_time * S >= 600, name .. ": a time scale and a bake of ten minutes or more in real time")
  assert(o.latent_heat == true and o.boiling_point == 100 and o.browning_scale == S, name .. ": latent heat and boiling on")
  assert(o.units:find("physical"), name .. ": the oven says its units")
  -- real heat capacities and densities, only rates scaled
  assert(d.specific_heat >= 2000 and d.specific_heat <= 3000, name .. ": a dough's specific heat, J/(kg K)")
  assert(d.density >= 400 and d.density <= 1300, name .. ": a dough's density")
  local k = d.conductivity / S
  assert(k >= 0.2 and k <= 0.6, name .. ": a dough's conductivity once the time scale is taken out: " .. k)
  assert(o.beta / S >= 20 and o.beta / S <= 48, name .. ": an oven's beta (Baik et al. 1999: 20-48 W/(m^2 K))")
  -- water content: 15-45% of the mass
  local xw = 1000 * d.saturation / d.density
  assert(xw > 0.15 and xw < 0.46, name .. ": water mass fraction " .. xw)
  -- eta = 2 tau_y^2 mu / S at each point of Fig. 8
  local ty, eta = d.tau_y, d.eta
  -- the cookie's set at 71-78 degC, the muffin batter's at 55-70 (lua/hearth/dough.lua, COOKIE_SET, MUFFIN_SET):
  -- both hold the melted value to their set's start; bread keeps Fig. 8's four points
  local np = name == "bread" and 4 or 5
  assert(ty.irreversible and eta.irreversible and #ty == np and #eta == np, name .. ": Fig. 8's curves")
  assert(ty[np][1] == (name == "cookie" and 78 or 70) and ty[np][2] == 20 * ty[1][2], name .. ": sets x20")
  if np == 5 then
    assert(ty[4][1] == (name == "cookie" and 71 or 55) and ty[4][2] == ty[3][2], name .. ": soft until its set starts")
  end
  local mu1 = eta[1][2] * S / (2 * ty[1][2] ^ 2)
  assert(mu1 >= 100 and mu1 <= 1e6, name .. ": the viscosity behind eta, Pa s: " .. mu1)
  h.material("cam_clay_dough", d) -- passes the plugin's schema
end
-- the pancake (helper pancake): a batter of 50-55% water on a 180-200 degC griddle under room air, flipped at 1.5-3
-- real minutes (the brief's ranges; the sources in lua/hearth/dough_physical.lua), on the muffin's set
do
  local d, o = h.library.dough.pancake, h.library.oven.pancake
  local S = o.time_scale
  local xw = 1000 * d.saturation / d.density
  assert(xw >= 0.50 and xw <= 0.55, "pancake: water mass fraction " .. xw)
  assert(o.latent_heat == true and o.boiling_point == 100 and o.browning_scale == S, "pancake: latent heat and boiling on")
  assert(o.pan_temperature >= 180 and o.pan_temperature <= 200 and o.temperature <= 30, "pancake: a griddle under room air")
  assert(o.flip_time * S >= 90 and o.flip_time * S <= 180 and o.flip_time < o.bake_time, "pancake: the flip's real time")
  assert(d.specific_heat >= 2000 and d.specific_heat <= 4200 and d.conductivity / S >= 0.2 and d.conductivity / S <= 0.6,
    "pancake: a batter's heat capacity and conductivity")
  assert(#d.tau_y == 5 and d.tau_y[5][1] == 70 and d.tau_y[4][1] == 55, "pancake: the muffin batter's set (MUFFIN_SET)")
  h.material("cam_clay_dough", d) -- passes the plugin's schema
end
-- the lava cake (helper lavaphys): a chocolate fondant batter in a 200-220 degC oven for 10-15 real minutes (recipes'
-- ranges), egg-set between 62 and 80 degC (the brief's range of egg proteins) to at least the 62 Pa a 28 mm cake
-- needs ("The lava cake stands"), from a batter at the room's or the fridge's temperature; its portion a ramekin's
do
  local d, o = h.library.dough.lava_cake, h.library.oven.lava_cake
  local S = o.time_scale
  local xw = 1000 * d.saturation / d.density
  assert(xw >= 0.15 and xw <= 0.35, "lava_cake: water mass fraction " .. xw)
  assert(o.latent_heat == true and o.boiling_point == 100 and o.browning_scale == S, "lava_cake: latent heat and boiling on")
  assert(o.temperature >= 200 and o.temperature <= 220 and o.pan_temperature == o.temperature, "lava_cake: the oven")
  assert(o.bake_time * S >= 600 and o.bake_time * S <= 900, "lava_cake: the bake's real time " .. o.bake_time * S)
  assert(o.dough_temperature >= 4 and o.dough_temperature <= 25, "lava_cake: a batter from the fridge or the room")
  assert(o.portion >= 50e-6 and o.portion <= 250e-6, "lava_cake: a ramekin's portion, m^3: " .. o.portion)
  assert(d.specific_heat >= 2000 and d.specific_heat <= 3000 and d.conductivity / S >= 0.2 and d.conductivity / S <= 0.6,
    "lava_cake: a batter's heat capacity and conductivity")
  local ty = d.tau_y
  assert(#ty == 5 and ty[4][1] >= 62 and ty[5][1] <= 80 and ty[4][1] < ty[5][1], "lava_cake: the egg's set temperatures")
  assert(ty[4][2] == ty[3][2] and ty[5][2] >= 62, "lava_cake: melted until the set starts, set to >= 62 Pa")
  h.material("cam_clay_dough", d) -- passes the plugin's schema
end
-- the paper presets keep Table 2's animation units and say so
local p, po = h.library.paper.bread, h.library.paper_oven.bread
assert(p.specific_heat == 20 and po.latent_heat == false, "h.library.paper: Table 2 verbatim (c = 20 J/(kg K)), latent heat off")
local ok, e = pcall(function() return h.library.dough.smore end)
assert(not ok and e:find("no preset 'smore'") and e:find("bread, cookie, lava_cake, muffin, pancake"),
  "physical presets list their names: " .. tostring(e))
ok, e = pcall(function() return h.library.paper.cooky end)
assert(not ok and e:find("did you mean 'cookie'"), "nearest paper preset: " .. tostring(e))
-- a physical scene takes its oven as given
local o = h.library.oven.bread
local s = h.scene { dim = 2, dx = 0.005, box = { { 0, 0 }, { 0.12, 0.08 } }, latent_heat = o.latent_heat,
  boiling_point = o.boiling_point, browning = true, browning_scale = o.browning_scale,
  oven = { temperature = o.temperature, beta = o.beta } }
s:add { shape = h.box({ 0.03, 0.015 }, { 0.09, 0.045 }), material = h.material("cam_clay_dough", h.library.dough.bread),
  temperature = o.dough_temperature }
s:step(20)
print("dough physical ok")

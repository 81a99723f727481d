-- The dough presets (Ding et al. Table 2, Fig. 8) from a scene.
local h = require "hearth"
-- Table 2's numbers, typed here from the paper: E, kappa, yield, eta, alpha^g, ambient theta
local T2 = { bread = { 2e3, 100, 20, 500, 0.03, 100 }, cookie = { 4e4, 30, 20, 500, 0.015, 150 },
  pancake = { 4e4, 200, 2, 50, 0.02, nil }, muffin = { 4e4, 100, 2, 10, 0.03, 105 },
  lava_cake = { 2e3, 250, 1, 10, 0.025, 100 }, smore = { 4e4, 150, 200, 60, nil, 400 } }
for name, t in pairs(T2) do
  local d, o = h.library.paper[name], h.library.paper_oven[name]
  local kk = name == "muffin" and 0.005 or 1 -- the muffin's documented kappa factor (a real batter's 0.5 W/(m K))
  local E = type(d.E) == "table" and d.E.base or d.E -- a product with its moisture factor (issue #18)
  assert(E == t[1] and d.conductivity == kk * t[2] and d.density == 500, name .. ": E, kappa, density from Table 2")
  assert(d.max_porosity == (name == "muffin" and 0.6 or nil), name .. ": the pore cap only where documented")
  -- Fig. 8: tau_y at the fridge point is Table 2's value, dips while fat melts, sets x20 at gelatinisation
  local ty = d.tau_y
  local k = (name == "bread" or name == "muffin") and 10 or 1 -- bread's and muffin's documented tau_y factor
  local np = #(rawget(ty, "base") or ty) -- the curve's points (under a moisture factor's product)
  assert(ty.irreversible and ty[1][2] == k * t[3] and ty[3][2] < ty[2][2] and ty[2][2] < ty[1][2]
    and ty[np][2] == 20 * k * t[3], name .. ": tau_y curve shape")
  if name == "cookie" then -- dough.lua's COOKIE_SET: melted from 35 degC, held soft to 71 degC, set by 78 degC
    assert(np == 5 and ty[3][1] == 35 and ty[4][1] == 71 and ty[4][2] == ty[3][2] and ty[5][1] == 78,
      "cookie: soft from 35 to 71 degC, set by 78 degC (Miller et al. 1996's glass transition)")
  elseif name == "muffin" then -- dough.lua's MUFFIN_SET: melted from 35 degC, held soft to 55 degC, set by 70 degC
    assert(np == 5 and ty[3][1] == 35 and ty[4][1] == 55 and ty[4][2] == ty[3][2] and ty[5][1] == 70,
      "muffin: soft from 35 to 55 degC (the batter's starch onset), set by 70 degC")
  else
    assert(np == 4 and ty[3][1] == 35 and ty[4][1] == 70, name .. ": Fig. 8's points at 35 and 70 degC")
  end
  -- issue #18: E and tau_y of the doughs that bake a crust stiffen as they dry (dough.lua's DRY), x1 when raw
  local dry = ({ bread = 100, muffin = 100, cookie = 100 / 4.6 })[name]
  if dry then
    local f, g = d.E.factor, d.tau_y.factor
    for i = 1, #f do assert(g[i][1] == f[i][1] and g[i][2] == f[i][2], name .. ": tau_y dries as E") end
    assert(#g == #f and f.moisture and f.irreversible and f[#f][1] <= 1 and f[#f][2] == 1
      and math.abs(f[1][2] - dry) < 1e-9 * dry, name .. ": dry factor " .. f[1][2] .. ", expected " .. dry)
    for i = 2, #f do assert(f[i][2] < f[i - 1][2], name .. ": the factor falls as the crust holds more water") end
  end
  -- issue #18 (dough.lua's WATER, FRACTURE): the bread and the muffin carry water (their raw X_0 as s_0 at
  -- Table 2's density), and a stretch to fracture (the stretch rule, fracture_stretch 1) of 100 raw, 1 at X = 0.41
  -- kg/kg (rubbery), falling log-linearly to 0.02 once dried to X = 0.16 kg/kg (glassy); no other good
  local wat = ({ bread = 0.45 * 500 / 1000, muffin = 0.40 * 500 / 1000 })[name]
  if wat then
    assert(math.abs(d.saturation - wat) < 1e-12 and o.saturation == d.saturation, name .. ": s_0 " .. tostring(d.saturation))
    assert(d.water_diffusivity > 0 and d.evaporation > 0 and o.water_time_scale == 600, name .. ": water live, x600")
    local fs, f = d.fracture_strain, d.fracture_strain.factor
    assert(fs.base == 100 and d.fracture_stretch == 1 and f.moisture and f.irreversible and
      math.abs(fs.base * f[1][2] - 0.02) < 1e-12 and f[#f][1] == 1 and f[#f][2] == 1,
      name .. ": brittle when dry, never cracks raw, by the stretch rule")
    for i = 2, #f do assert(f[i][2] > f[i - 1][2], name .. ": the stretch to fracture grows with water") end
    local X0 = ({ bread = 0.82, muffin = 0.67 })[name]
    assert(math.abs(f[1][1] * X0 - 0.16) < 1e-12, name .. ": glassy at X = 0.16 kg/kg")
    assert(math.abs(f[#f - 1][1] * X0 - 0.41) < 1e-12 and math.abs(fs.base * f[#f - 1][2] - 1) < 1e-12,
      name .. ": rubbery (1) at X = 0.41 kg/kg")
    -- dough.lua's SET: the set crumb's stretch to fracture, 100 (never) where tau_y leaves its melted value (Fig.
    -- 8's 35 degC; the muffin's 55, MUFFIN_SET), 0.15 from its 70 degC set
    local st, t0 = d.fracture_strain_set, name == "muffin" and 55 or 35
    assert(st and not st.moisture and st.irreversible and #st == 2 and st[1][1] == t0 and st[1][2] == 100 and
      st[2][1] == 70 and st[2][2] == 0.15, name .. ": the set crumb breaks at 0.15 from 70 degC")
    -- dough.lua's HEAT_SET: the muffin's water brittleness waits for its set (1 raw at 55 degC, 0 set at 70,
    -- irreversible); the bread's does not (its crust sets with its crumb: dough.lua says why)
    local un = d.fracture_unset
    if name == "muffin" then
      assert(un and not un.moisture and un.irreversible and #un == 2 and un[1][1] == 55 and un[1][2] == 1 and
        un[2][1] == 70 and un[2][2] == 0, name .. ": the skin is leathery until it sets (55 to 70 degC)")
    else
      assert(un == nil, name .. ": no heat-set gate")
    end
  else
    assert(d.saturation == nil and d.fracture_strain == nil and d.fracture_strain_set == nil and o.saturation == nil,
      name .. ": no water, no fracture")
  end
  local eta = d.eta
  -- eta carries tau_y's factor squared (lua/hearth/dough.lua, "Rise"): the viscosity eta / tau_y^2 stays Table 2's
  assert(eta.irreversible and eta[1][2] == 4000 * k * k * t[4], name .. ": eta scale")
  for i = 2, #eta do assert(eta[i][2] <= eta[i - 1][2], name .. ": eta non-increasing") end
  local g = ({ muffin = 2.5, lava_cake = 0.1 })[name] or 1 -- the documented gas factors
  assert(math.abs(d.gas_rate - g * (t[5] or 0) / 600) <= 1e-15, name .. ": gas_rate = alpha^g / 600")
  assert(o.temperature == t[6], name .. ": oven temperature")
  assert(o.latent_heat == false, name .. ": Table 2's animation units keep the latent sink off")
  h.material("cam_clay_dough", d) -- every point of every curve passes the plugin's schema
end
local ok, e = pcall(function() return h.library.paper.cooky end)
assert(not ok and e:find("did you mean 'cookie'"), "nearest preset name: " .. tostring(e))
-- a copy per lookup: changing one does not change the library
local a = h.library.paper.cookie
a.E = 1
assert(h.library.paper.cookie.E.base == 4e4, "fresh copy")
-- a cookie bakes a few steps with every field live
local o = h.library.paper_oven.cookie
local s = h.scene { dim = 2, dx = 0.005, box = { { 0, 0 }, { 0.12, 0.06 } }, oven = { temperature = o.temperature, beta = o.beta } }
s:add { shape = h.shapes.cookie({ 0.06, 0.0325 }, 0.03, 0.025), material = h.material("cam_clay_dough", h.library.paper.cookie),
  temperature = o.dough_temperature }
h.recipes.tray(s, 0.02, { temperature = o.pan_temperature, beta = o.pan_beta })
s:step(20)
local por = s:probe("porosity", { 0.06, 0.03 })
assert(por > 0 and por < 1, "porosity live: " .. tostring(por))
print("dough library ok")

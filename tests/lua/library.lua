-- The sauce library and h.mix from a scene.
local h = require "hearth"
local mayo, honey = h.library.sauce.mayo, h.library.sauce.honey_b
assert(mayo.sigma_y == 70.8 and mayo.eta == 30.5 and mayo.h == 0.442, "mayo from Table 1")
local ok, e = pcall(function() return h.library.sauce.mayonaise end)
assert(not ok and e:find("did you mean 'mayo") , "nearest sauce name: " .. tostring(e))
local same = h.mix { { mayo, 0.3 }, { mayo, 0.7 } }
assert(math.abs(same.eta - mayo.eta) < 1e-12 * mayo.eta and math.abs(same.h - mayo.h) < 1e-12, "identity law")
local only = h.mix { { mayo, 1 }, { honey, 0 } }
assert(only.eta == mayo.eta and only.sigma_y == mayo.sigma_y, "zero law")
local half = h.mix { { mayo, 0.5 }, { honey, 0.5 } }
print(("mayo/honey_b 50:50: h %.3f, eta %.3f Pa s^h, sigma_y %.3f Pa"):format(half.h, half.eta, half.sigma_y))
local s = h.scene { dim = 2, dx = 1 / 64 }
local m = h.material("von_mises_sauce", half)
s:add { shape = h.disc({ 0.5, 0.5 }, 0.1), material = m }
s:step(5)
print("library ok")

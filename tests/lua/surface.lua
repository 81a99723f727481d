-- recipes_surface_below_a_gap: h.recipes.surface reads the top of the lowest material on a vertical line, not a body
-- above a gap (h.recipes.height's highest); a block 0.2 m tall on y0 = 0.1 and a blob from 0.5 to 0.6 above it
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 1, 1 } }, gravity = { 0, 0 } }
local m = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.4, 0.1 }, { 0.6, 0.3 }), material = m, fixed = true, jitter = 0 }
s:add { shape = h.box({ 0.45, 0.5 }, { 0.55, 0.6 }), material = m, fixed = true, jitter = 0 }
print(("height=%.4f surface=%.4f"):format(h.recipes.height(s, 0.5, 0.1, 0.9, 800), h.recipes.surface(s, 0.5, 0.1, 0.9, 800)))
-- nothing on the line: 0, as h.recipes.height
print(("empty=%.4f"):format(h.recipes.surface(s, 0.2, 0.1, 0.9, 800)))
s:run { until_t = 0 } -- nothing to simulate (hearth run would otherwise run a scene it built)

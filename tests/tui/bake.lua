-- tui tests: a small 2D scene with an oven, so temperature is a live field
-- and s:oven(...) at the prompt changes what the status bar shows.
local h = require "hearth"
s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 0.75 } }, oven = { temperature = 180, beta = 25 } }
dough = h.material("elastic", { E = 2e4, nu = 0.3, density = 500, conductivity = 0.4, specific_heat = 2500 })
s:add { shape = h.box({ 0.3, 0.1 }, { 0.7, 0.3 }), material = dough, temperature = 20 }
s:collider { shape = h.plane({ 0, 0.08 }, { 0, 1 }), mode = "separate", friction = 0.3 }
greeting = "hello from bake"

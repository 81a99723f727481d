local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
s:add { shape = h.box({ 0.4, 0.4 }, { 0.6, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
print("speed", s:probe("speed", { 0.5, 0.5 }))
print("temperature", s:probe("temperature", { 0.5, 0.5 }))

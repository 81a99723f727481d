-- tui tests: bake.lua's block in a scene whose rates run 300 times fast (a physical preset's oven.time_scale), so the
-- status line gives the real time as the scene's frames do (tui_status_says_scene_clock).
local h = require "hearth"
s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 0.75 } }, oven = { temperature = 180, beta = 25 },
  time_scale = 300 }
dough = h.material("elastic", { E = 2e4, nu = 0.3, density = 500, conductivity = 0.4, specific_heat = 2500 })
s:add { shape = h.box({ 0.3, 0.1 }, { 0.7, 0.3 }), material = dough, temperature = 20 }
s:collider { shape = h.plane({ 0, 0.08 }, { 0, 1 }), mode = "separate", friction = 0.3 }

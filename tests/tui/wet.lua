-- tui tests: a small 2D bread dough holding water in an oven, so more fields
-- are live (saturation, water, browning, ...) than the probe panel has rows
-- at 80x24: the panel must scroll to show them all.
local h = require "hearth"
s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 0.75 } }, oven = { temperature = 180, beta = 25 } }
local d = h.library.dough.bread
d.water_diffusivity, d.evaporation = 5e-8 / 373.15, 3e-5
s:add { shape = h.box({ 0.3, 0.1 }, { 0.7, 0.3 }), material = h.material("cam_clay_dough", d), temperature = 20,
  saturation = 0.4 }
s:collider { shape = h.plane({ 0, 0.08 }, { 0, 1 }), mode = "separate", friction = 0.3 }

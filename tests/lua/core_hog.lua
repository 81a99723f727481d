-- sandbox_core_memory: adds block after block of particles, as a scene with a
-- list parameter of 5000 doughs would: the core's memory grows, not Lua's.
-- --set blocks=48 --set tall=10: the particles' estimate (60 MB) fits under a
-- 64M ceiling, but the 10 m tall box's grid tables (~15 MB) hold part of it:
-- refused up front. --set blocks=40 --set tall=10: the estimate fits beside
-- the tables, and the first step's sort and grid blocks are refused.
local h = require "hearth"
local P = h.params { blocks = h.number { 100, min = 1, max = 100, integer = true, what = "blocks of 8000 particles" },
  tall = h.number { 0.1, min = 0.1, max = 10, unit = "m", what = "the box's height" } }
local s = h.scene { dim = 2, dx = 0.002, box = { { 0, 0 }, { 10, P.tall } } }
local dough = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 })
for i = 0, P.blocks - 1 do -- 0.1 x 0.08 m at 4 per cell: 8000 particles each (100: 8e5, ~125 MB)
  s:add { shape = h.box({ 0.1 * i, 0.01 }, { 0.1 * i + 0.1, 0.09 }), material = dough, ppc = 4 }
end
s:step(1)
print("unreachable")

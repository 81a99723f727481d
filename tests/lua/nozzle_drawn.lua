-- A nozzle (h.recipes.nozzle) alone in a box: its walls are a collider, drawn
-- in the frames as the other colliders are, and they leave the stream as it
-- was without them. --set walls=false leaves them out; the scene writes the
-- particle positions at the end to positions.txt for the comparison.
local h = require "hearth"
local P = h.params { walls = true }
local s = h.scene { dim = 2, dx = 0.005, box = { { 0, 0 }, { 0.2, 0.2 } } }
h.recipes.nozzle(s, { x = 0.1, y = 0.15, width = 0.02, speed = 0.3, dx = 0.005, to = 0.15, walls = P.walls,
  material = h.material("newtonian", { viscosity = 1, density = 1000 }) })
s:run { until_t = 0.15, every = 0.15, png = { field = "speed", path = "f_%04d.png", width = 400, height = 400 } }
local x, out = s:positions(), {}
for i = 1, #x do out[i] = ("%.17g"):format(x[i]) end
h.write("positions.txt", table.concat(out, "\n") .. "\n")

-- A 8 x 3 cm elastic block split across the periodic seam of a box periodic in x (half of it at each end),
-- released at rest `lift` cells above the domain's separate floor, under gravity for t seconds (#18, helper
-- traygap's open question: the touch test reads the particle blocks at block coordinate -1 inside the box only,
-- so does a node by the seam still see the particles that touch the floor on the far side?). The block is elastic,
-- not dough: periodic axes carry no heat yet. Prints one line:
--   result lowest=<dx> seam=<dx> hp=<dx>
-- the lowest particle's height above the floor's face, overall and within 6 mm of the seam, and the half-spacing.
local h = require "hearth"
local P = h.params { dx = 0.005, lift = 1.0, t = 0.4 }
local core = require("hearth.core")
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.14, 0.14 } }, name = "seam", wall = "separate",
  periodic_x = true }
local floor_y = P.dx -- the floor's face: one cell inside the box (G2P keeps particles there)
local y0 = floor_y + P.lift * P.dx
s:add { shape = core.box({ -0.01, y0 }, { 0.03, y0 + 0.03 }) + core.box({ 0.11, y0 }, { 0.15, y0 + 0.03 }),
  material = h.material("elastic", { E = 3e4, nu = 0.3, density = 500 }) }
s:run { until_t = P.t }
local r = s:particles { fields = { "x" } }
local low, seam = math.huge, math.huge
for i = 1, r.n do
  local x, y = r.x[3 * i - 2], r.x[3 * i - 1]
  low = math.min(low, y)
  if x < 0.006 or x > 0.134 then seam = math.min(seam, y) end
end
print(("result lowest=%.4f seam=%.4f hp=%.4f"):format((low - floor_y) / P.dx, (seam - floor_y) / P.dx, 0.25))

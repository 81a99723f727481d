-- Cookie cutter: dough shaped by a PNG mask (assets/masks/gingerbread.png),
-- dropped onto a tray. --set mask=star for the star, --set dim=3 for an extruded cookie.
local h = require "hearth"
local P = h.params { mask = h.choice { "gingerbread", gingerbread = "assets/masks/gingerbread.png: a gingerbread man",
  star = "assets/masks/star.png: a five-pointed star" },
  dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" },
  -- 3D: the cutter's extrusion about the box's middle depth (0.2 m deep)
  thickness = h.number { 0.02, above = 0, below = 0.2, unit = "m", what = "the cutter's thickness in 3D" } }
local d3 = P.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local s = h.scene { dim = P.dim, dx = d3 and 1 / 64 or 1 / 128, box = { v(0, 0, 0), v(0.5, 0.5, 0.2) } }
local dough = h.material("elastic", { E = 5e4, nu = 0.3, density = 1200 })
local cutter = h.mask("../../assets/masks/" .. P.mask .. ".png", { 0.15, 0.12 }, { 0.35, 0.37 })
if d3 then cutter = h.extrude(cutter, 0.1 - P.thickness / 2, 0.1 + P.thickness / 2) end
s:add { shape = cutter, material = dough, ppc = d3 and 8 or 4 }
s:collider { shape = h.plane(v(0, 0.05, 0), v(0, 1, 0)), mode = "separate", friction = 0.4 }
s:run { until_t = 0.4, every = 0.05, png = { field = "speed", path = "frames/cookie_%04d.png", kind = "particles" } }
print(("cookie: %d particles"):format(s:stats().particles))

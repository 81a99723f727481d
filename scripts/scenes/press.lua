-- A moving collider presses a soft block: a plate comes down, holds, and lifts.
--   hearth run scripts/scenes/press.lua [--set depth=0.05] [--set dim=3]
local h = require "hearth"
-- the block stands 0.15 m tall on the floor at 0.05 m; elastic's range of E: [0.01, 1e12] Pa
local P = h.params {
  depth = h.number { 0.06, min = 0, below = 0.15, unit = "m", what = "how far the plate presses into the block" },
  speed = h.number { 0.2, above = 0, unit = "m/s", what = "the plate's speed" },
  stiffness = h.number { 2e4, min = 0.01, max = 1e12, unit = "Pa", what = "the dough's Young's modulus" },
  dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" } }
local d3 = P.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local s = h.scene { dim = P.dim, dx = d3 and 1 / 40 or 1 / 80, box = { v(0, 0, 0), v(1, 0.6, 0.5) } }
local dough = h.material("elastic", { E = P.stiffness, nu = 0.35, density = 1100 })
s:add { shape = h.box(v(0.4, 0.05, 0.15), v(0.6, 0.2, 0.35)), material = dough }
s:collider { shape = h.plane(v(0, 0.05, 0), v(0, 1, 0)), mode = "sticky" }

-- the plate starts 2 cm above the block and moves with a velocity function of time
local travel = (0.02 + P.depth) / P.speed
local plate = s:collider { shape = h.box(v(0.3, 0.22, 0.05), v(0.7, 0.26, 0.45)), mode = "sticky",
  velocity = function(t)
    if t < travel then return v(0, -P.speed, 0) end
    if t < travel + 0.2 then return v(0, 0, 0) end
    return v(0, P.speed, 0)
  end }

local function top() -- the block's highest particle along its centre line
  local ys = s:line("density", v(0.5, 0.05, 0.25), v(0.5, 0.3, 0.25), 101)
  local y = 0
  for i, dd in ipairs(ys) do if dd == dd then y = 0.05 + (i - 1) * 0.25 / 100 end end
  return y
end
local rows = { "t_s,top_m" }
s:run { until_t = travel + 0.5, every = 0.05, png = { field = "von_mises", path = "frames/q_%04d.png" },
  on_frame = function(f)
    rows[#rows + 1] = ("%.4f,%.4f"):format(f.t, top())
    h.write("top.csv", table.concat(rows, "\n") .. "\n")
  end }
print(("pressed to %.3f m at the deepest; top now at %.3f m"):format(0.2 - P.depth, top()))

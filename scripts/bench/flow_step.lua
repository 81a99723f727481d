-- A block thrown across the box (6 m/s sideways, 3 m/s down, fully jittered), so particles
-- cross grid blocks every step and the sort reorders them: the bookkeeping's
-- share of a step where the material flows (scripts/bench/report.sh counts
-- it at one and two threads; `hearth bench`'s block starts at rest, and its
-- particles hardly change blocks in 40 steps).
--   hearth run scripts/bench/flow_step.lua --quiet [--set dim=2] [--set cells=256] [--set steps=4]
local h = require "hearth"
local P = h.params { dim = 2, cells = 256, steps = 4 }
local d3 = P.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
local s = h.scene { dim = P.dim, dx = 1 / P.cells, box = { v(0, 0, 0), v(1, 1, 1) }, wall = "slip", seed = 7,
  dt_max = 1e-4 * 64 / P.cells }
local el = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000 })
s:add { shape = h.box(v(0.1, 0.3, 0.3), v(0.5, 0.7, 0.7)), material = el, ppc = d3 and 8 or 4, velocity = v(6, -3, 0), jitter = 1 }
s:step(P.steps)
print("particles=" .. s:stats().particles)

-- plugin_point_dim_filled: hearth_point.dim and hearth_block.dim (<hearth/material.h> rule 8) are the
-- scene's dimension. tests/plugins/point_fields.c's point_dim fails its stress (code 3) when a point
-- reports another dimension than its parameter `dim`; lua_test.sh runs this at dim 2 and 3, expecting
-- each, batched and with HEARTH_PLUGIN_NO_BATCH=1, and under SPH (--set solver=sph).
local h = require "hearth"
local P = h.params { dim = 2, expect = 2, solver = "mpm" }
local d3 = P.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
local s = h.scene { dim = P.dim, dx = 1 / 16, box = { v(0, 0, 0), v(1, 1, 1) }, solver = P.solver }
s:add { shape = h.box(v(0.3, 0.3, 0.3), v(0.6, 0.6, 0.6)), material = h.material("point_dim", { dim = P.expect }) }
s:step(3)
print("stepped " .. s:stats().particles)

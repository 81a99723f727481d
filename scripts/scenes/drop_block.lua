-- An elastic block dropped onto a plane: the simplest complete scene.
--   hearth run scripts/scenes/drop_block.lua [--set height=0.4] [--set stiffness=2e4]
local h = require "hearth"
-- the 0.2 m block's bottom in the 1 m box; elastic's range of E: [0.01, 1e12] Pa
local P = h.params {
  height = h.number { 0.35, min = 0, max = 0.8, unit = "m", what = "the block's bottom above the floor" },
  stiffness = h.number { 5e4, min = 0.01, max = 1e12, unit = "Pa", what = "the jelly's Young's modulus" },
  dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" } }

local s = h.scene { dim = P.dim, dx = 1 / 64, box = { { 0, 0, 0 }, { 1, 1, 0.5 } }, wall = "slip" }
local jelly = h.material("elastic", { E = P.stiffness, nu = 0.3, density = 1000 })
local half = P.dim == 3 and 0.1 or nil
local block = P.dim == 3 and h.box({ 0.4, P.height, 0.15 }, { 0.6, P.height + 0.2, 0.35 })
                         or h.box({ 0.4, P.height }, { 0.6, P.height + 0.2 })
s:add { shape = block, material = jelly, ppc = 4 }
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }

s:run { until_t = 1.0, every = 0.1, csv = "height.csv", probes = { { "speed", { 0.5, 0.2 } } },
  png = { field = "speed", path = "frames/speed_%04d.png" } }
-- a 2D scene's mass is per metre of depth, and so is its energy (height.csv's kinetic_J_per_m)
print(("after the drop: t = %.2f s, kinetic energy %.3g %s"):format(s:stats().t, s:stats().kinetic,
  P.dim == 2 and "J per metre of depth" or "J"))

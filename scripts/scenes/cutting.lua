-- Cutting: a block of dough rests on a board; at t = 0.2 s a knife removes a
-- thin slab (a removal event), and the two halves are pushed apart.
--   hearth run scripts/scenes/cutting.lua [--set gap=0.01]
local h = require "hearth"
-- the knife's slab is cut from the 0.4 m block's middle
local P = h.params {
  gap = h.number { 0.01, above = 0, below = 0.4, unit = "m", what = "the width of the slab the knife removes" },
  at = h.number { 0.2, min = 0, unit = "s", what = "the cut's time" } }

local s = h.scene { dim = 2, dx = 1 / 100, box = { { 0, 0 }, { 1, 0.5 } } }
local dough = h.material("elastic", { E = 3e4, nu = 0.3, density = 1100 })
local left = s:add { shape = h.box({ 0.3, 0.06 }, { 0.5, 0.16 }), material = dough }
local right = s:add { shape = h.box({ 0.5, 0.06 }, { 0.7, 0.16 }), material = dough }
s:collider { shape = h.plane({ 0, 0.06 }, { 0, 1 }), mode = "separate", friction = 0.5 }

s:at(P.at, function(sc)
  local n = sc:cut(h.box({ 0.5 - P.gap / 2, 0 }, { 0.5 + P.gap / 2, 0.5 }))
  print(("t = %.3f s: the knife removed %d particles"):format(sc:stats().t, n))
  sc:push(left, { -0.2, 0 })
  sc:push(right, { 0.2, 0 })
end)
s:run { until_t = 0.6, every = 0.05, png = { field = "speed", path = "frames/speed_%04d.png" } }
print(("left piece %d particles, right piece %d particles"):format(s:body_particles(left), s:body_particles(right)))

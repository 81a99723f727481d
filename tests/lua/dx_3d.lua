-- dx_3d_floor_said: h.dx_3d raises dx to a scene's 3D floor and says so; in 2D, or at or above the floor, dx passes.
local h = require "hearth"
local P = h.params { dx = h.number { 0.002, above = 0, unit = "m", what = "the grid spacing" },
  dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" } }
print(("dx used: %g"):format(h.dx_3d(P.dx, 0.004, P.dim == 3)))

-- A viscous dam break in 2D: a column of syrup-like fluid collapses along a tray.
--   hearth run scripts/scenes/dam_break.lua [--set viscosity=5] [--set dx=0.005]
-- The front position (the right-most particle) is written to front.csv (t_s, s; front_m).
local h = require "hearth"
-- the column stands at (0.02, 0.02) in the 1.2 x 0.6 m box; newtonian's range of viscosity: [0, 1e6] Pa s
local P = h.params { viscosity = h.number { 2.0, min = 0, max = 1e6, unit = "Pa s", what = "the syrup's viscosity" },
  dx = h.number { 1 / 100, above = 0, unit = "m", what = "the grid spacing" },
  width = h.number { 0.2, above = 0, max = 1.18, unit = "m", what = "the column's width" },
  height = h.number { 0.4, above = 0, max = 0.58, unit = "m", what = "the column's height" } }

local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 1.2, 0.6 } }, wall = "slip" }
local syrup = h.material("newtonian", { density = 1300, bulk = 1e5, viscosity = P.viscosity })
s:add { shape = h.box({ 0.02, 0.02 }, { 0.02 + P.width, 0.02 + P.height }), material = syrup, ppc = 4 }

local rows = { "t_s,front_m" }
local function front()
  local xs = s:line("density", { 0, 0.03 }, { 1.2, 0.03 }, 241)
  local x = 0
  for i, d in ipairs(xs) do if d == d then x = (i - 1) * 1.2 / 240 end end -- NaN is outside the fluid
  return x
end
s:run { until_t = 0.6, every = 0.05, png = { field = "speed", path = "frames/speed_%04d.png" },
  on_frame = function(f)
    rows[#rows + 1] = ("%.4f,%.4f"):format(f.t, front())
    h.write("front.csv", table.concat(rows, "\n") .. "\n")
  end }
print(("front at t = %.2f s: x = %.3f m"):format(s:stats().t, front()))

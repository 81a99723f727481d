-- Sauce poured onto a steak (Nagasawa et al. 2019, section 6.5, Fig. 14), in
-- 2D: a nozzle above a steak on a plate pours a sauce that lands, spreads
-- over the steak and runs down its sides.
--   hearth run scripts/scenes/sauces/steak.lua [--set sauce=bbq] [--set sauce=mix --set blend=linear]
-- sauce: a library name (pork_cutlet, bbq, ...) or "mix", the half-and-half
-- pork cutlet / BBQ sauce mixture of Fig. 14, blended as `blend` says.
-- spread.csv: how far the sauce reaches over the steak's top to the left
-- and right of the pour point over time, the area that ran off onto the plate, and the
-- sauce's height above the steak's top at the pour point (the pile's top).
local h = require "hearth"
local P = h.params { blend = h.choice("nonlinear", h.blend_words),
  sauce = h.choice("mix", h.library.sauce_words(), { mix = "half pork cutlet, half BBQ sauce (Fig. 14), blended as blend "
    .. "says" }), dx = h.number { 0.0025, above = 0, unit = "m", what = "the grid spacing" },
  speed = h.number { 0.2, above = 0, unit = "m/s", what = "the pour's speed at the nozzle's exit" },
  width = h.number { 0.02, above = 0, unit = "m", what = "the nozzle's slot width" },
  drop = h.number { 0.006, min = 0, unit = "m", what = "the nozzle exit's height above the steak" },
  pour = h.number { 0.4, above = 0, unit = "s", what = "the pour's time" },
  until_t = h.number { 1.0, min = 0, unit = "s", what = "the run's simulated time (0: the set-up alone, measured)" },
  every = h.number { 0.05, above = 0, unit = "s", what = "the time between frames" },
  png = h.flag { true, what = "PNG frames of the speed in frames/" } }

local material
if P.sauce == "mix" then
  material = h.mix { { h.library.sauce.pork_cutlet, 0.5 }, { h.library.sauce.bbq, 0.5 } }
else
  material = h.material("von_mises_sauce", h.library.sauce[P.sauce])
end
local W, H = 0.2, 0.12
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { W, H } }, blend = P.blend, name = "steak" }
local plate_y, sx0, sx1, stop = 0.01, 0.04, 0.16, 0.035 -- the steak: 12 cm long, 2.5 cm thick
s:collider { shape = h.plane({ 0, plate_y }, { 0, 1 }), mode = "sticky" }
s:collider { shape = h.shapes.rounded_box({ sx0, plate_y - 0.005 }, { sx1, stop }, 0.008), mode = "sticky" }
local x_pour = 0.085 -- a little left of the middle, as a cook pours
-- a wide slot close above the steak: a free-falling stream thins as it speeds
-- up, and a stream under two cells wide loses its continuum in MPM
h.recipes.nozzle(s, { x = x_pour, y = stop + P.drop, width = P.width, speed = P.speed, material = material, dx = P.dx,
  to = P.pour })

local function spread()
  local y = stop + 1.5 * P.dx
  local right = h.recipes.reach(s, { x_pour, y }, { 1, 0 }, sx1 - x_pour, P.dx / 2)
  local left = h.recipes.reach(s, { x_pour, y }, { -1, 0 }, x_pour - sx0, P.dx / 2)
  -- run-off: material on the plate beside the steak (a slice, low band)
  local nx, ny = math.floor(W / P.dx), math.floor(H / P.dx)
  local rows = s:slice("density", { axis = "z", res = { nx, ny } })
  local n = 0
  for j, row in ipairs(rows) do
    if (j - 0.5) * H / ny < plate_y + 0.01 then
      for i, v in ipairs(row) do
        local x = (i - 0.5) * W / nx
        if v == v and (x < sx0 - 2 * P.dx or x > sx1 + 2 * P.dx) then n = n + 1 end
      end
    end
  end
  local height = h.recipes.surface(s, x_pour, stop, H, math.floor((H - stop) / (P.dx / 2)))
  return left, right, n * (W / nx) * (H / ny), height
end

local rows = { "t_s,left_m,right_m,runoff_m2,height_m" }
local l, r, ro, ht = 0, 0, 0, 0
s:run { until_t = P.until_t, every = P.every,
  png = P.png and { field = "speed", path = "frames/speed_%04d.png" } or nil,
  on_frame = function(f)
    l, r, ro, ht = spread()
    rows[#rows + 1] = ("%.4f,%.4f,%.4f,%.6g,%.4f"):format(f.t, l, r, ro, ht)
    h.write("spread.csv", table.concat(rows, "\n") .. "\n")
  end }
print(("steak (%s, %s) at t = %.2f s: sauce reaches %.3f m left and %.3f m right of the pour; %.3g m^2 ran off"):format(
  P.sauce, P.blend, s:stats().t, l, r, ro))

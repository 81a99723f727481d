-- Honey-mustard-mayo: mixtures of three sauces (Nagasawa et al. 2019, Fig. 11),
-- each composition from its own nozzle onto its own slanted plate, side by
-- side in 2D, the geometry of nozzle.lua. Every mixture's parameters come
-- from the three constituents alone (a blend of blends, eq. 18 with K = 3).
--   hearth run scripts/scenes/sauces/ternary.lua [--set blend=linear]
-- Lanes, left to right (mayo : mustard : honey): the three pure sauces, the
-- three half-and-half pairs, and the centre of the triangle (1/3 each).
-- front.csv: distance down the slope of each lane's farthest material over time.
local h = require "hearth"
local P = h.params { blend = h.choice("nonlinear", h.blend_words),
  dx = h.number { 0.0025, above = 0, unit = "m", what = "the grid spacing" },
  angle = h.number { 45, min = 0, below = 90, unit = "degrees", what = "the plate's slope" },
  speed = h.number { 0.2, above = 0, unit = "m/s", what = "the extrusion speed at the nozzle's exit" },
  width = h.number { 0.01, above = 0, unit = "m", what = "the nozzle's slot width" },
  drop = h.number { 0.02, min = 0, unit = "m", what = "the nozzle exit's height above the plate" },
  emit = h.number { 0.6, above = 0, unit = "s", what = "the extrusion's time" },
  until_t = h.number { 1.0, min = 0, unit = "s", what = "the run's simulated time (0: the set-up alone, measured)" },
  -- the reach along the plate runs lane - 0.03 m - dx
  lane = h.number { 0.22, above = 0.03, unit = "m", what = "a lane's width" },
  every = h.number { 0.05, above = 0, unit = "s", what = "the time between frames" },
  png = h.flag { true, what = "PNG frames of the speed in frames/" } }

local L = h.library.sauce
local sauces = { L.mayo, L.mustard, L.honey }
local third = 1 / 3
local comps = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 }, { 0.5, 0.5, 0 }, { 0.5, 0, 0.5 }, { 0, 0.5, 0.5 },
  { third, third, third } }
local names = { "my", "ms", "ho", "my_ms", "my_ho", "ms_ho", "centre" }

local th = math.rad(P.angle)
local c, sn = math.cos(th), math.sin(th)
local height = P.lane * math.tan(th) + P.drop + 0.04
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { #comps * P.lane, height } }, blend = P.blend,
  name = "ternary" }
local top = height - 0.04 - P.drop
local lanes = {}
for i, w in ipairs(comps) do
  local X = (i - 1) * P.lane
  local xn = X + 0.03
  s:collider { shape = h.plane({ xn, top }, { sn, c }) * h.box({ X + P.dx, -1 }, { X + P.lane - P.dx, height + 1 }),
    mode = "sticky" }
  local mix = h.mix { { sauces[1], w[1] }, { sauces[2], w[2] }, { sauces[3], w[3] } }
  h.recipes.nozzle(s, { x = xn, y = height - 0.04, width = P.width, speed = P.speed, material = mix, dx = P.dx,
    to = P.emit })
  lanes[i] = { xn = xn, mix = mix }
end

local function front(ln)
  local off = 1.5 * P.dx
  return h.recipes.reach(s, { ln.xn + off * sn, top + off * c }, { c, -sn }, (P.lane - 0.03 - P.dx) / c, P.dx / 2)
end

local rows = { "t_s,front_" .. table.concat(names, "_m,front_") .. "_m" } -- each front in m
local last = {}
s:run { until_t = P.until_t, every = P.every,
  png = P.png and { field = "speed", path = "frames/speed_%04d.png", width = 1600 } or nil,
  on_frame = function(f)
    local r = { ("%.4f"):format(f.t) }
    for i, ln in ipairs(lanes) do
      last[i] = front(ln)
      r[#r + 1] = ("%.4f"):format(last[i])
    end
    rows[#rows + 1] = table.concat(r, ",")
    h.write("front.csv", table.concat(rows, "\n") .. "\n")
  end }
local out = {}
for i, ln in ipairs(lanes) do
  out[#out + 1] = ("%s %.3f m (h %.2f, eta %.3g, sigma_y %.3g)"):format(names[i], last[i], ln.mix.h, ln.mix.eta,
    ln.mix.sigma_y)
end
print(("honey-mustard-mayo, %s blend, fronts at t = %.2f s:\n  %s"):format(P.blend, s:stats().t,
  table.concat(out, "\n  ")))

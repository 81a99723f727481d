-- Nozzle extrusion onto a slanted plate (Nagasawa et al. 2019, section 6.1,
-- Fig. 8): two library sauces mixed in several ratios, each extruded from its
-- own nozzle onto its own slanted plate, side by side in one 2D scene
-- (plane strain: a nozzle that is a slot, a plate that is a long ramp).
--   hearth run scripts/scenes/sauces/nozzle.lua                        (mayo/honey, Fig. 1)
--   hearth run scripts/scenes/sauces/nozzle.lua --set pair=mayo:pork_cutlet     (Fig. 9)
--   hearth run scripts/scenes/sauces/nozzle.lua --set pair=honey:oyster         (Fig. 10)
--   ... --set blend=linear   or   --set blend=labels   (the paper's comparisons, Figs. 1b, 1c)
-- Lane i holds the mixture ratios[i] : (1 - ratios[i]) of the pair's first and
-- second sauce. The key measure, front.csv, is the distance down the slope
-- (from the point under the nozzle) of the farthest material of each lane
-- over time. Frames go to frames/speed_%04d.png.
local h = require "hearth"
local P = h.params {
  pair = "mayo:honey", ratios = "0,0.25,0.5,0.75,1", blend = h.choice("nonlinear", h.blend_words),
  dx = h.number { 0.0025, above = 0, unit = "m", what = "the grid spacing" }, -- 4 cells across the nozzle
  angle = h.number { 45, min = 0, below = 90, unit = "degrees", what = "the plate's slope" },
  speed = h.number { 0.2, above = 0, unit = "m/s", what = "the extrusion speed at the nozzle's exit" },
  width = h.number { 0.01, above = 0, unit = "m", what = "the nozzle's slot width" },
  drop = h.number { 0.02, min = 0, unit = "m", what = "the nozzle exit's height above the plate" },
  emit = h.number { 0.6, above = 0, unit = "s", what = "the extrusion's time" },
  until_t = h.number { 1.0, min = 0, unit = "s", what = "the run's simulated time (0: the set-up alone, measured)" },
  lane = h.number { 0.16, above = 0, unit = "m", what = "a lane's width" },
  every = h.number { 0.05, above = 0, unit = "s", what = "the time between frames" },
  -- scales kappa and mu (the paper's 1e6 and 1e5 Pa, section 4.6); von_mises_sauce's range of kappa: [1, 1e12] Pa
  stiffness = h.number { 1, min = 1e-6, max = 1e6, what = "a factor on the sauces' kappa and mu" },
  png = h.flag { true, what = "PNG frames of the speed in frames/" },
}

local a, b = P.pair:match("^([%w_]+):([%w_]+)$")
if not a then error("--set pair=A:B, e.g. mayo:honey; got " .. P.pair, 0) end
local A, B = h.library.sauce[a], h.library.sauce[b]
local ratios = {}
for r in P.ratios:gmatch("[^,]+") do
  local v = tonumber(r)
  if not v or v < 0 or v > 1 then error("--set ratios: comma-separated numbers in [0, 1]; got " .. P.ratios, 0) end
  ratios[#ratios + 1] = v
end
if #ratios < 1 or #ratios > 8 then error("--set ratios: 1 to 8 ratios", 0) end

local th = math.rad(P.angle)
local c, sn = math.cos(th), math.sin(th)
local nl = #ratios
local height = P.lane * math.tan(th) + P.drop + 0.04
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { nl * P.lane, height } }, gravity = { 0, -9.81 },
  blend = P.blend, name = "nozzle" }

local lanes = {}
for i, r in ipairs(ratios) do
  local X = (i - 1) * P.lane
  local top = height - 0.04 - P.drop -- plate height under the nozzle
  local xn = X + 0.03                -- nozzle centre
  -- the plate: everything below the line through (xn, top) sloping down to the right, within the lane
  local plate = h.plane({ xn, top }, { sn, c }) * h.box({ X + P.dx, -1 }, { X + P.lane - P.dx, height + 1 })
  s:collider { shape = plate, mode = "sticky" } -- sauce wets the plate: no slip
  local mix = h.mix { { A, r }, { B, 1 - r } }
  mix.kappa, mix.mu = 1e6 * P.stiffness, 1e5 * P.stiffness
  lanes[i] = { ratio = r, xn = xn, top = top, material = mix }
end

for _, L in ipairs(lanes) do
  h.recipes.nozzle(s, { x = L.xn, y = height - 0.04, width = P.width, speed = P.speed, material = L.material,
    dx = P.dx, to = P.emit })
end

-- Front: how far the material reaches along a line parallel to the plate,
-- 1.5 dx above it, from under the nozzle to the lane's end.
local function front(L)
  local off = 1.5 * P.dx
  return h.recipes.reach(s, { L.xn + off * sn, L.top + off * c }, { c, -sn }, (P.lane - 0.03 - P.dx) / c, P.dx / 2)
end

-- for hearth trade: the front of the middle lane (the 50:50 mix by default) at the end
h.metric("front", function() return front(lanes[(#lanes + 1) // 2]) end)

local head = { "t_s" }
for _, L in ipairs(lanes) do head[#head + 1] = ("front_%g_m"):format(L.ratio) end -- each front in m
local rows = { table.concat(head, ",") }
local last = {}
s:run { until_t = P.until_t, every = P.every,
  png = P.png and { field = "speed", path = "frames/speed_%04d.png", width = 1200 } or nil,
  on_frame = function(f)
    local r = { ("%.4f"):format(f.t) }
    for i, L in ipairs(lanes) do
      last[i] = front(L)
      r[#r + 1] = ("%.4f"):format(last[i])
    end
    rows[#rows + 1] = table.concat(r, ",")
    h.write("front.csv", table.concat(rows, "\n") .. "\n")
  end }
local out = {}
for i, L in ipairs(lanes) do out[#out + 1] = ("%g:%g %.3f m"):format(L.ratio, 1 - L.ratio, last[i]) end
print(("%s, %s blend, fronts at t = %.2f s: %s"):format(P.pair, P.blend, s:stats().t, table.concat(out, ", ")))

-- A celery dip (Nagasawa et al. 2019, section 6.3, Fig. 12), in 2D: a stick
-- of celery goes down into a bowl of sauce, rests, and comes back up with
-- some sauce on it.
--   hearth run scripts/scenes/sauces/celery_dip.lua [--set sauce=mustard] [--set sauce=mix --set blend=linear]
-- sauce: a library name (mayo, mustard, ...) or "mix", the half-and-half
-- mayo/mustard mixture of Fig. 12, blended as `blend` says.
-- dip.csv over time: the height of the sauce's surface on the dip's centre
-- line (the hole the celery leaves: a sauce with a yield stress keeps it, a
-- thin one levels), and the area of sauce (m^2 per m of depth) above the
-- bowl's initial level (what the celery pushes up and lifts out). The sauce
-- wets the celery only through its sticky contact, which since commit
-- e062372 is glue (a particle that touched it stays held, in tension too), so
-- the lifted celery pulls a column of sauce up; no surface tension.
local h = require "hearth"
local P = h.params { blend = h.choice("nonlinear", h.blend_words),
  sauce = h.choice("mix", h.library.sauce_words(), { mix = "half mayo, half mustard (Fig. 12), blended as blend says" }),
  dx = h.number { 0.003, above = 0, unit = "m", what = "the grid spacing" },
  speed = h.number { 0.1, above = 0, unit = "m/s", what = "the celery's speed" },
  depth = h.number { 0.025, min = 0, unit = "m", what = "how deep the celery dips below the sauce's top" },
  rest = h.number { 0.2, min = 0, unit = "s", what = "the celery's rest at the bottom" },
  until_t = h.number { 1.2, min = 0, unit = "s", what = "the run's simulated time (0: the set-up alone, measured)" },
  every = h.number { 0.05, above = 0, unit = "s", what = "the time between frames" },
  png = h.flag { true, what = "PNG frames of the speed in frames/" } }

local material
if P.sauce == "mix" then
  material = h.mix { { h.library.sauce.mayo, 0.5 }, { h.library.sauce.mustard, 0.5 } }
else
  material = h.material("von_mises_sauce", h.library.sauce[P.sauce])
end
local W, H = 0.12, 0.16
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { W, H } }, blend = P.blend, name = "celery_dip" }
-- the bowl: a U of inner half-width 4 cm, 4 cm deep, walls 4 mm, sauce 3 cm deep
local base, r_in, level = 0.01, 0.04, 0.04
s:collider { shape = h.container({ W / 2, base }, { 0, 1 }, r_in, 0.045, 0.004, 0.006), mode = "sticky" }
s:add { shape = h.box({ W / 2 - r_in + P.dx / 2, base }, { W / 2 + r_in - P.dx / 2, level }), material = material,
  ppc = 4 }
-- the celery: a rounded stick 1 cm wide whose tip starts 1 cm above the sauce;
-- down `depth` into the sauce, a rest, then up and out
local tip0 = level + 0.01
local down = (0.01 + P.depth) / P.speed
local celery = s:collider { shape = h.capsule({ W / 2, tip0 + 0.005 }, { W / 2, tip0 + 0.2 }, 0.005), mode = "sticky",
  velocity = function(t)
    if t < down then return { 0, -P.speed } end
    if t < down + P.rest then return { 0, 0 } end
    return { 0, P.speed }
  end }

-- sauce above the level: samples of a density slice above level + 2 dx
local nx, ny = math.floor(W / P.dx), math.floor(H / P.dx)
local function lifted()
  local rows = s:slice("density", { axis = "z", res = { nx, ny } })
  local n = 0
  for j, row in ipairs(rows) do
    local y = (j - 0.5) * H / ny
    if y > level + 2 * P.dx then
      for _, v in ipairs(row) do if v == v then n = n + 1 end end
    end
  end
  return n * (W / nx) * (H / ny)
end

local rows = { "t_s,centre_height_m,lifted_m2" }
local last, centre = 0, 0
s:run { until_t = P.until_t, every = P.every,
  png = P.png and { field = "speed", path = "frames/speed_%04d.png" } or nil,
  on_frame = function(f)
    last = lifted()
    -- the surface: the top of the sauce in the bowl on the centre line, not the drops on the lifted celery above a
    -- gap, which h.recipes.height (the highest material) had read as it: 0.0711 m at 1.2 s for a bath ~25 mm deep
    -- (#18, helper userview4)
    centre = h.recipes.surface(s, W / 2, base, H - 0.01, 400)
    rows[#rows + 1] = ("%.4f,%.5f,%.6g"):format(f.t, centre, last)
    h.write("dip.csv", table.concat(rows, "\n") .. "\n")
  end }
print(("celery dip (%s, %s) at t = %.2f s: sauce surface %.4f m above the bowl floor at the dip (%.4f m at the start); %.3g m^2 above the initial level"):format(
  P.sauce, P.blend, s:stats().t, centre, level - base, last))

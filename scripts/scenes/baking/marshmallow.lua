-- Marshmallow (Ding et al. 2019, Figs. 5 and 18): a s'more. Two marshmallows,
-- each in its own scene so that only one meets the fire: the roasted one is
-- held in Table 2's s'more flame (ambient 400 degC, beta 120 W/(m^2 K): heat
-- from all round, as a marshmallow turned on its stick over a fire gets it),
-- so its skin dries into a stiff, brittle crust while its inside melts; the
-- raw one is held as long in room air. Each is then laid on its lower cracker
-- and pressed by the upper one: the roasted crust breaks and the molten inside
-- oozes out (Fig. 18), the raw one squashes whole (the control).
--   hearth run scripts/scenes/baking/marshmallow.lua [--set dim=3] [--set roast=0.9]
-- Changed (issue #18, helper ooze4): until then the right one roasted on a
-- hot element under its cracker (Table 2's conductive theta and beta) for
-- 0.5 s, in one scene with the raw one, and both were pressed 6 mm. Heated from below
-- only, the marshmallow heated evenly (Biot number 0.06), formed no crust and
-- slumped, molten, before the crackers reached it (docs/validation.md, "The
-- marshmallow's ooze (#18)"). Now:
--  * The roast: `roast` s (0.9) in Table 2's s'more ambient (the paper's own
--    numbers for this good), in dry air (oven saturation 0), held in place (no
--    gravity: the stick holds it; the crackers wait away from it, since a
--    collider within two cells of a surface is contact, not air, for the
--    heat), so the crust forms on every face. 0.9 s is an estimate: the time
--    in which Table 2's flame dries the skin ~3 mm deep (two cells) while the
--    centre passes the gelatin's melt (35 degC) and stays under the sugar's
--    hard crack (150 degC); in Table 2's animation units it stands for a
--    roast of a minute or two.
--  * The press: the crackers close at `speed` each (10 mm/s) for `press`
--    seconds (1 s), 20 mm, squeezing the 25 mm marshmallow to ~12 mm: a s'more
--    pressed firmly, our estimate (no source gives a press depth). The scene
--    refuses a press that would leave the marshmallow less than a fifth of its
--    height (the crackers start 29 mm apart). Unchecked, 15 mm/s for 1 s
--    closed them through each other and the guard stopped the run.
--  * The crackers hold what touches them (`mode` sticky; `--set mode=slip`
--    for Coulomb `friction` 0.5, as before): a graham cracker is rough and
--    porous, and the sugar sticks to it (it is what holds a s'more together).
--    Squeezed between sticking plates a soft body spreads as a fountain flow:
--    its middle runs ahead of the faces held on the plates and feeds the
--    front (Engmann, Servais & Burbidge 2005, J. Non-Newtonian Fluid Mech.
--    132, 1: squeeze flow with and without slip), so the inside reaches the
--    front through the broken crust. With slip crackers the crust is pushed
--    out whole ahead of the inside at this press (ooze 0.000; 0.31 pressed 24
--    mm, where the raw one curls over the crackers' edges too, 0.05;
--    docs/validation.md, "The marshmallow's ooze (#18)").
--  * What falls below the crackers is ooze run off their ends, not a leak
--    (helper marshfall; docs/validation.md, "Particles below the
--    marshmallow's crackers"). The sticky fountain flow carries the roasted
--    one's broken crust past both cracker ends from ~1.6 s and it hangs over
--    them; at the press's end (1.83-1.94 s) a few crumbs of that crust (skin
--    particles; at dx 2 mm each has damage 1) drop off the overhangs, 2-12 mm
--    beyond the lower cracker's ends: 6 at dx 2 mm (still falling at 2 s), 3
--    at 1.5 mm (on the floor; 14 more in a flap sagging 5-7 mm below the
--    cracker). None crosses a cracker (tests/contact/thin_plate.lua: a plate
--    a quarter of a cell thick holds). With slip crackers or in 3D (dx 4 mm)
--    nothing falls; the raw one drapes over the ends but sheds nothing.
-- The material is Table 2's s'more (h.library.paper.smore) with a
-- marshmallow's own temperature curve and expansion and a skin that dries
-- (below, at `mat`). The molten inside's yield stress is the preset's (below,
-- "Can the molten inside stand?"): a melted foam cannot stand under its own
-- weight, and only the crust holds the roasted marshmallow up.
-- Writes, under hearth-out/marshmallow/: raw_%04d.png and roasted_%04d.png
-- (temperature), <name>_damage_roast.png and <name>_damage_press.png
-- (damage at the end of the roast and of the run), <name>_saturation_roast.png,
-- and marshmallow.csv: over time, the thickness (lowest to highest material on
-- the centre line), the centre temperature and the ooze (below) of the raw
-- and the roasted one. `--set only=raw` (or roasted) runs one scene (the
-- other's columns NaN).
-- ooze_raw and ooze_roasted, the fraction of each outline that is inside material (below), have no unit
-- (tests/scene_csv.py's unit rule):
-- marshmallow.csv has no unit: ooze_raw, ooze_roasted
local h = require "hearth"
local D = require "hearth.dough"
local P = h.params { dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" },
  dx = h.number { 0.002, above = 0, unit = "m", what = "the grid spacing" },
  roast = h.number { 0.9, min = 0, unit = "s", what = "the roast before the press" },
  press = h.number { 1.0, min = 0, unit = "s", what = "the press's time" },
  speed = h.number { 0.01, min = 0, unit = "m/s", what = "each cracker's speed toward the other" },
  frames = h.number { 20, min = 1, integer = true, unit = "frames", what = "PNG frames over the run" },
  expansion = h.number { 0.1, min = 0, what = "the marshmallow's thermal expansion (the material's)" },
  only = h.choice { "", [""] = "both marshmallows", raw = "the raw one alone", roasted = "the roasted one alone" },
  mode = h.choice("sticky", h.contact_words),
  friction = h.number { 0.5, min = 0,
    what = "the crackers' Coulomb friction coefficient" } } -- mode: the crackers' contact
local d3 = P.dim == 3
local dx = h.dx_3d(P.dx, 0.004, d3) -- says so when it raises dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local c = D.paper.smore
print("marshmallow.lua: h.library.paper.smore (its tau_y curve and expansion a marshmallow's, a skin that dries "
  .. "brittle), animation units (Ding Table 2): heat runs in seconds, not minutes")
local W, H, zc = 0.08, 0.08, 0.04         -- m: each scene's box, depth centre (3D)
local BASE, HM, RM = 0.02, 0.025, 0.015   -- m: marshmallow's bottom, height and half width
local CW, CT, GAP = 0.025, 0.004, 0.004   -- m: crackers' half width and thickness, gap above the marshmallow
local AWAY, LAY = 0.012, 0.001            -- m: the crackers' extra distance in the roast; the lower one's gap when laid
local xc = W / 2
local closure, room = 2 * P.speed * P.press, HM + GAP - HM / 5 -- m: how far the crackers close, and may
if closure > room then
  -- the closure as %.1f mm, or %g past a kilometre (--set speed=1e300 had printed 300 digits)
  local mm = closure * 1e3 < 1e6 and ("%.1f"):format(closure * 1e3) or ("%g"):format(closure * 1e3)
  h.refuse(("--set speed=%g, press=%g: the crackers would close %s mm, more than the %.1f mm that leaves the "
    .. "marshmallow a fifth of its %.0f mm height; keep 2 speed press <= %.3f m (at this speed, press <= %.3g s)")
    :format(P.speed, P.press, mm, room * 1e3, HM * 1e3, room, room / (2 * P.speed)))
end

-- The material. A marshmallow is a sugar-gelatin foam, not a dough: nothing in it gelatinises, so Fig. 8's
-- starch set (tau_y x20 at 70 degC) is the wrong physics for it. Heat melts it: its gelatin gel melts at
-- ~30-35 degC (Djabourov, Leblond & Papon 1988, J. Phys. France 49, 333), and the sugar syrup left thins as
-- it heats (aqueous sugars lose several-fold viscosity from 20 to 70 degC: Telis, Telis-Romero, Mazzotti &
-- Gabas 2007, Int. J. Food Prop. 10, 185). So tau_y follows Fig. 8 to its melted value at 35 degC and keeps
-- it to 100 degC; past that the syrup boils off its water, and by the hard-crack stage (~150 degC, ~1%
-- water: McGee 2004, On Food and Cooking, ch. 12) it is a sugar glass when it cools: x20 there (Fig. 8's
-- set value), Ding et al.'s "slightly burnt crust with a gooey center" (§7.2). Irreversible, as the
-- preset's curves. eta keeps the preset's falling curve.
-- Can the molten inside stand? Melted, it is a foam of gas in a sugar syrup, whose yield stress is the
-- bubbles' capillary pressure times a packing term: ~0.5 (sigma / R) (phi - 0.64)^2 (Mason, Bibette & Weitz
-- 1996, J. Colloid Interface Sci. 179, 439, for compressed emulsions; foams alike, Princen & Kiss 1989, J.
-- Colloid Interface Sci. 128, 176). With sigma ~0.05 N/m, bubbles R ~30 um and a gas fraction phi ~0.65-0.75
-- (density 500 against the syrup's ~1400 kg/m^3) that is ~0.1-10 Pa, under the preset's 60 Pa and far under
-- its weight's rho g H = 123 Pa at the base. So it cannot stand (a heated marshmallow droops off its stick),
-- and the preset is not too weak: what holds a roasted marshmallow up is its crust. Kept.
-- The skin dries (not in Table 2; our estimates): water at saturation S0 = 0.085 (a marshmallow is ~16-17%
-- water, wet basis: USDA FoodData Central, "Candies, marshmallows", 16.4 g/100 g; s = x_w rho / rho_w =
-- 0.17 x 500 / 1000), diffusivity D = 7.5e-6 m^2/s (eq. 22's K = D / (theta s0), theta 293.15 K) and
-- evaporation 2 kg/(m^2 s K) in the flame's dry air (chosen so the skin dries ~3 mm, two cells, in the
-- roast; with D fixed the dried fraction X/X0 does not depend on S0, which sets only the water's mass). Dried below X/X0 = 0.65 the sugar is a glass (water plasticises amorphous sugars and
-- their glass transition rises steeply as it leaves: Roos & Karel 1991, J. Food Sci. 56, 38; Roos 1995,
-- Phase Transitions in Foods, ch. 5): E and tau_y x10 (x1 above 0.85), and its elastic strain to fracture
-- falls from 1 (a wet foam stretches) to 1e-3, under the law's yield strain tau_y / E ~1.5e-3, so the dried
-- crust breaks rather than flows (cam_clay_dough's strain rule). The raw one's air holds its water (oven
-- saturation S0: a marshmallow's water activity is about room humidity), so it does not dry.
-- Expansion 0.1 Pa/K (the other goods' value) for the preset's 2 (--set expansion=2): when the core's
-- thermal term was a pressure that plastic flow never relaxed, 2 Pa/K x 100 K made the molten
-- marshmallow flow out for as long as it was hot (guard, t = 0.855 s; docs/validation.md). Eq. 10 is now a
-- thermal strain (core/sim/material.h), and at 2 the scene runs to the end
-- (baking_marshmallow_paper_expansion_completes). The default stays 0.1, the claims' value.
local S0, F, EF_DRY = 0.085, 10, 1e-3
local ty = c.yield
local dry = h.curve { { 0.65, F }, { 0.85, 1 }, of = "moisture", irreversible = true }
local smore = h.library.paper.smore
smore.tau_y = h.curve { { D.THETA[1], ty * D.TAU_SHAPE[1] }, { D.THETA[2], ty * D.TAU_SHAPE[2] },
  { D.THETA[3], ty * D.TAU_SHAPE[3] }, { 100, ty * D.TAU_SHAPE[3] }, { 150, ty * D.TAU_SHAPE[4] }, irreversible = true }
  * dry
smore.E = c.E * dry
smore.fracture_strain = 1 * h.curve { { 0.65, EF_DRY }, { 0.85, 1 }, of = "moisture", irreversible = true }
smore.water_diffusivity = 7.5e-6 / (293.15 * S0)
smore.evaporation = 2
smore.expansion = P.expansion
local mat = h.material("cam_clay_dough", smore)

-- The ooze (Ding et al. Fig. 18: "when pressed the crust breaks and the inside oozes out"): the skin is
-- the material that starts within SKIN of the marshmallow's surface, the inside the rest (by particle
-- id, so it follows the material). The outline is, in each band of height dx, the outermost particle on
-- each side of the marshmallow's axis (3D: in each of 8 sectors around it). An intact skin, however it
-- is squashed, stays the outline (the inside flows with it); the inside reaches the outline only where
-- it escapes through an opening in the skin. ooze = the fraction of the outline that is inside material.
local SKIN = 0.004 -- m: two cells at the default dx
local function ooze(s, skin)
  local r = s:particles { fields = { "id", "x" } }
  local best, who = {}, {}
  for k = 1, r.n do
    local x, y, z = r.x[3 * k - 2], r.x[3 * k - 1], r.x[3 * k]
    local rad, side
    if d3 then
      rad = math.sqrt((x - xc) ^ 2 + (z - zc) ^ 2)
      side = math.floor((math.atan(z - zc, x - xc) + math.pi) / (2 * math.pi) * 8) % 8
    else
      rad, side = math.abs(x - xc), x < xc and 0 or 1
    end
    local key = math.floor(y / dx) * 8 + side
    if not best[key] or rad > best[key] then best[key], who[key] = rad, r.id[k] end
  end
  local n, o = 0, 0
  for _, id in pairs(who) do n = n + 1; if not skin[id] then o = o + 1 end end
  return n > 0 and o / n or 0
end

local function measure(s)
  local n = 600
  local d = s:line("density", v(xc, BASE - AWAY - CT, zc), v(xc, H, zc), n + 1)
  local lo, hi
  for k, val in ipairs(d) do if val == val then lo = lo or k; hi = k end end
  if not lo then return 0, 0 / 0 end
  local step = (H - BASE + AWAY + CT) / n
  local ylo, yhi = BASE - AWAY - CT + (lo - 1) * step, BASE - AWAY - CT + (hi - 1) * step
  return yhi - ylo, s:probe("temperature", v(xc, (ylo + yhi) / 2, zc))
end

local until_t = P.roast + P.press + 0.1
local cols, names = {}, { "raw", "roasted" }
for _, name in ipairs(names) do
  local roasted = name == "roasted"
  cols[name] = {}
  -- the frames' title: which marshmallow, and that the seconds are Table 2's animation units (#18, helper userview4)
  local label = ("%s marshmallow; Table 2's animation units"):format(name)
  if P.only == "" or P.only == name then
    -- the roasted one in the flame's dry air, the raw one in room air (Table 2's initial temperature) that
    -- holds its water
    local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(W, H, 0.08) }, gravity = v(0, 0, 0),
      oven = roasted and { temperature = c.ambient_theta, beta = c.ambient_beta, saturation = 0 }
        or { temperature = c.theta0, beta = c.ambient_beta, saturation = S0 },
      name = "marshmallow", time_units = "animation" }
    local lower = s:collider { shape = h.box(v(xc - CW, BASE - AWAY - CT, zc - CW), v(xc + CW, BASE - AWAY, zc + CW)),
      mode = P.mode, friction = P.friction }
    local upper = s:collider { shape = h.box(v(xc - CW, BASE + HM + GAP + AWAY, zc - CW),
      v(xc + CW, BASE + HM + GAP + AWAY + CT, zc + CW)), mode = P.mode, friction = P.friction }
    local shape = d3 and h.cylinder(v(xc, BASE + HM / 2, zc), { 0, 1, 0 }, RM, HM / 2)
      or h.box(v(xc - RM, BASE, zc), v(xc + RM, BASE + HM, zc))
    s:add { shape = shape, material = mat, temperature = c.theta0, ppc = d3 and 8 or 4, saturation = S0 }
    local skin = {}
    do
      local r = s:particles { fields = { "id", "x" } }
      for k = 1, r.n do
        local x, y, z = r.x[3 * k - 2], r.x[3 * k - 1], r.x[3 * k]
        local rad = d3 and math.sqrt((x - xc) ^ 2 + (z - zc) ^ 2) or math.abs(x - xc)
        skin[r.id[k]] = math.min(RM - rad, y - BASE, BASE + HM - y) < SKIN
      end
    end
    -- out of the fire (the room's air), laid on the lower cracker (LAY under it, it drops onto it) under
    -- gravity, the upper cracker GAP above it, and the press
    s:at(P.roast, function(sc)
      if roasted then sc:oven(c.theta0, c.ambient_beta) end
      sc:png("damage", name .. "_damage_roast.png", { label = label })
      sc:png("saturation", name .. "_saturation_roast.png", { range = { 0, S0 }, label = label })
      sc:move(lower, v(0, AWAY - LAY, 0))
      sc:move(upper, v(0, -AWAY, 0))
      sc:gravity(v(0, -9.81, 0))
      sc:collider_velocity(lower, v(0, P.speed, 0), 0)
      sc:collider_velocity(upper, v(0, -P.speed, 0), 0)
    end)
    s:at(P.roast + P.press, function(sc)
      sc:collider_velocity(lower, v(0, 0, 0), 0)
      sc:collider_velocity(upper, v(0, 0, 0), 0)
    end)
    -- one colour range for both (the raw one's own, room air to room air, was -0.5..0.5 degC), so their frames compare
    s:run { until_t = until_t, every = until_t / P.frames, png = { field = "temperature", path = name .. "_%04d.png",
      range = { c.theta0, c.ambient_theta }, label = label },
      on_frame = function(f)
        local th, T = measure(s)
        cols[name][#cols[name] + 1] = { t = f.t, th = th, T = T, ooze = ooze(s, skin) }
      end }
    s:png("damage", name .. "_damage_press.png", { label = label })
  end
end

local rows = { "t_s,thickness_raw_m,thickness_roasted_m,centre_temperature_raw_degC,centre_temperature_roasted_degC,"
  .. "ooze_raw,ooze_roasted" }
local nan = { th = 0 / 0, T = 0 / 0, ooze = 0 / 0 }
local n = math.max(#cols.raw, #cols.roasted)
for k = 1, n do
  local a, b = cols.raw[k] or nan, cols.roasted[k] or nan
  rows[#rows + 1] = ("%.3f,%.5f,%.5f,%.2f,%.2f,%.4f,%.4f"):format((cols.raw[k] or cols.roasted[k]).t, a.th, b.th,
    a.T, b.T, a.ooze, b.ooze)
end
h.write("marshmallow.csv", table.concat(rows, "\n") .. "\n")
local out = {}
for _, name in ipairs(names) do
  local last = cols[name][#cols[name]]
  if last then out[#out + 1] = ("%s %.4f m thick (centre %.1f degC), ooze %.3f"):format(name, last.th, last.T, last.ooze) end
end
print("after the press: " .. table.concat(out, ", ") .. " (ooze: inside material on the outline)")

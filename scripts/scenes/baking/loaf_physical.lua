-- A loaf in physical units (issue #18): h.library.dough.bread (measured
-- density, heat capacity, conductivity and water of a proofed bread dough,
-- lua/hearth/dough_physical.lua) on a tray in its 200 degC oven, with the
-- latent heat and the boiling point on. Heat and water run S = 300 times
-- fast (the preset's time scale): 5 s of simulated time are a 25 minute bake.
-- The crust is a few mm thick: at the default dx = 5 mm the front spans a
-- particle's stencil (10 mm), so the top particle still holds water at the
-- end; dx = 2.5 mm shows the dried crust (docs/gallery/crumb_plateau.md).
-- The tray: tray = "separate" (default; a greased tray or baking paper: the base may slide, friction 0.4, and lift)
-- or "sticky" (a bare tray the dough sticks to: the contact holds the base where it touches, in tension too).
-- On the separate tray the bottom rows, heated through 25..70 degC in the first minute, swell under their pores'
-- gas (gas.h, gas_tau_ambient) and push the base up, and it comes back down: the tray holds a node only where the
-- dough touches it (mpm_touch.c), so the base rests with its lowest particles at their half-spacing above the tray.
-- The loaf is seeded with smooth_surface (its outer layer of particles on the lattice, unjittered): jittered, its
-- base was as rough as the jitter (lower edges spread over 0.25 dx), the bottom rows' swelling pushed the deepest
-- particles out to rest on the tray and the rest of the base then stood up to 1.1 mm (5 mm) off it; smooth, at most
-- 0.15 mm (docs/validation.md, "The physical loaf's base lifts: traced"). On the sticky tray the base stays, but at
-- dx 2.5 mm the top tore open at 12 min (measured jittered: "The physical loaf's base on its tray").
--   hearth run scripts/scenes/baking/loaf_physical.lua [--set dx=0.0025] [--set latent=false] [--set tray=sticky]
-- What it shows: the crumb climbs to 100 degC and holds there while it holds
-- water (the boiling plateau), while the crust dries and heats on toward the
-- oven. Writes, under hearth-out/loaf_physical/: loaf.csv (per frame, in real
-- minutes: the crumb's and the crust's temperature and saturation, particle
-- values (crust_and_crumb), the loaf's height and the water left; the top's, the base's and the crumb's browning
-- index, fields/browning.c's 0..1; the loaf's area, V0 J summed), temperature_%04d.png, and at the end temperature.png, saturation.png and
-- browning.png; loaf.csv's base_lift_m is the most the lowest particle has risen off its start, over the raw
-- base's middle 80% (16 columns of 4 mm across x0 +- 32 mm), and base_gap_m the most any column's lowest particle
-- edge stands off the tray; top_surface_T_degC and top_surface_saturation the temperature and saturation the top
-- particle browned at in the frame's last step (the fields browning_temperature, browning_saturation: its surface's,
-- by the oven's and the evaporation's closures, browning.c), the crust's surface as the colour sees it; tray_T_degC
-- the tray's temperature (it goes in cold and the dough draws on it).
-- water_left, the loaf's water over the raw dough's, has no unit (tests/scene_csv.py's unit rule):
-- loaf.csv has no unit: water_left
local h = require "hearth"
local P = h.params { dx = h.number { 0.005, above = 0, unit = "m", what = "the grid spacing" },
  frames = h.number { 25, min = 1, integer = true, unit = "frames", what = "PNG frames over the run" },
  latent = h.flag { true, what = "the water's latent heat: the crumb holds at the 100 degC boiling plateau" },
  until_real = h.number { 0, min = 0, unit = "s", what = "the real bake time (0: the oven's own)" },
  -- with --set oven.wall_temperature / oven.emissivity (radiating walls, docs/validation.md "An oven's hot walls"):
  -- the air's own coefficient, the preset's 30 being an effective one with radiation in it
  h_c = h.number { 0, min = 0, unit = "W/(m^2 K)", what = "the oven air's coefficient in real time (0: the preset's beta)" },
  tray = h.choice { "separate",
  separate = "friction 0.4: the foot slides out, as on a greased or papered tray",
  sticky = "the foot held where it touched, as on a bare tray the dough has wetted" } }
local oven = h.library.oven.bread
local S = oven.time_scale
local until_t = (P.until_real > 0 and P.until_real or oven.bake_time * S) / S
print(("loaf_physical.lua: h.library.dough.bread, %s; bake %.0f min in %.1f s"):format(oven.units, until_t * S / 60, until_t))

local TRAY, WIDTH, BODY, X0 = 0.02, 0.08, 0.03, 0.07 -- m: tray top, loaf width, straight part, loaf centre
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.14, 0.14 } }, name = "loaf_physical",
  oven = { temperature = oven.temperature, beta = P.h_c > 0 and P.h_c * S or oven.beta, wall_temperature = oven.wall_temperature,
    emissivity = oven.emissivity, radiation_scale = oven.radiation_scale }, latent_heat = P.latent and oven.latent_heat,
  boiling_point = oven.boiling_point, browning = true, browning_scale = oven.browning_scale,
  gas_vent = oven.gas_vent, vent_porosity = oven.vent_porosity, time_scale = S }
-- the tray goes in cold with the dough (oven.pan_start_temperature, pan_warm_time: dough_physical.lua) and the dough
-- draws its heat from it (oven.pan_heat_capacity): the sheet is the box's floor, 0.14 m per metre of depth, 57% under
-- the loaf (cookies.lua's sheet likewise; #18, helper userfix7: it had stood at 200 degC from the first step)
local tray = h.recipes.tray(s, TRAY, h.recipes.pan(oven, 0.14, { mode = P.tray }))
-- smooth_surface: the outer layer on the lattice, so the base is flat on the tray (the header)
s:add { shape = h.shapes.loaf({ X0, TRAY }, WIDTH, BODY), material = h.material("cam_clay_dough", h.library.dough.bread),
  temperature = oven.dough_temperature, smooth_surface = true }

local function height() return h.recipes.height(s, X0, TRAY, 0.14, 280) end
-- particle values, as the unit tests read them (a probe is the grid's B-spline
-- average over three cells, which blurs a crust a few mm thick): the crust is
-- the topmost particle within dx/2 of the loaf's vertical axis, the base the
-- lowest one there (on the tray), the crumb the particle nearest the axis at
-- 45% of the loaf's height
local function crust_and_crumb(H)
  local r = s:particles { fields = { "x", "temperature", "saturation", "browning", "browning_temperature",
    "browning_saturation" } }
  local top, base, ctr, dc = nil, nil, nil, math.huge
  for i = 1, r.n do
    local x, y = r.x[3 * i - 2], r.x[3 * i - 1]
    if y > TRAY then
      if math.abs(x - X0) < P.dx / 2 and (not top or y > r.x[3 * top - 1]) then top = i end
      if math.abs(x - X0) < P.dx / 2 and (not base or y < r.x[3 * base - 1]) then base = i end
      local d = math.abs(x - X0) + math.abs(y - (TRAY + 0.45 * H))
      if d < dc then ctr, dc = i, d end
    end
  end
  return r.temperature[ctr], r.saturation[ctr], r.temperature[top], r.saturation[top], r.browning[top],
    r.browning[base], r.browning[ctr], r.browning_temperature[top], r.browning_saturation[top]
end
-- the loaf's area (m^2 per metre of depth, 2D): V0 J summed over its particles, every one made with the same V0
-- (one dx and ppc), read at the start as volume / count (as bread.lua's)
local v0
local function area()
  local p = s:particles { fields = { "J" } }
  v0 = v0 or s:volume() / p.n
  local a = 0
  for k = 1, p.n do a = a + v0 * p.J[k] end
  return a
end
-- the base's lift: per 4 mm column over the raw base's middle 80% (x0 +- 32 mm), the lowest particle's height;
-- base_lift = the largest rise of any column's lowest particle over its height at the start
local base0
local function base_lift()
  local r, lo = s:particles { fields = { "x" } }, {}
  for i = 1, r.n do
    local b = math.floor((r.x[3 * i - 2] - (X0 - 0.032)) / 0.004) + 1
    if b >= 1 and b <= 16 and (not lo[b] or r.x[3 * i - 1] < lo[b]) then lo[b] = r.x[3 * i - 1] end
  end
  base0 = base0 or lo
  local m = 0
  for b = 1, 16 do if lo[b] and base0[b] then m = math.max(m, lo[b] - base0[b]) end end
  return m
end
base_lift()
-- the base's gap: per column as above, the lowest lower edge of a particle, y - h_p with h_p = (V0 J)^(1/2) / 2 its
-- half-extent (mpm_touch.c's, which the tray's contact reads), over the tray; base_gap = the largest over the columns.
-- The lift above also counts the lowest particles' own swelling and their seeding's jitter; the gap is the base's
-- distance from the tray itself
local function base_gap()
  local r, lo = s:particles { fields = { "x", "J" } }, {}
  v0 = v0 or s:volume() / r.n
  for i = 1, r.n do
    local b = math.floor((r.x[3 * i - 2] - (X0 - 0.032)) / 0.004) + 1
    local edge = r.x[3 * i - 1] - 0.5 * math.sqrt(v0 * r.J[i])
    if b >= 1 and b <= 16 and (not lo[b] or edge < lo[b]) then lo[b] = edge end
  end
  local m = -math.huge
  for b = 1, 16 do if lo[b] then m = math.max(m, lo[b] - TRAY) end end
  return m
end
local w0 = s:stats().water_mass
local rows = { "t_real_min,centre_T_degC,centre_saturation,top_T_degC,top_saturation,height_m,water_left,top_browning,"
  .. "base_browning,centre_browning,area_m2,base_lift_m,base_gap_m,top_surface_T_degC,top_surface_saturation,tray_T_degC" }
local last
print(rows[1]) -- the rows each frame prints below are loaf.csv's: its header first, so they read as columns
-- the pictures' titles give the real time (the oven's rates run S times fast) beside the simulated seconds, after
-- what they show: a frame read alone (a paper's figure) said its time alone (#18, helper userview4)
local label = ("physical loaf, oven %g °C, tray in cold, %s"):format(oven.temperature, P.tray)
s:run { until_t = until_t, every = until_t / P.frames,
  png = { field = "temperature", path = "temperature_%04d.png", time_scale = S, label = label },
  on_frame = function(f)
    local H = height()
    local Tc, sc, Tt, st, bt, bb, bc, Ts, ss = crust_and_crumb(H)
    last = { f.t * S / 60, Tc, sc, Tt, st, H, s:stats().water_mass / w0, bt, bb, bc, area(), base_lift(), base_gap(),
      Ts, ss, s:collider_heat(tray).temperature }
    rows[#rows + 1] = ("%.2f,%.2f,%.4f,%.2f,%.4f,%.5f,%.4f,%.4f,%.4f,%.4f,%.6g,%.6f,%.6f,%.2f,%.4f,%.2f")
      :format(table.unpack(last))
    h.write("loaf.csv", table.concat(rows, "\n") .. "\n")
    print(rows[#rows])
  end }
s:png("temperature", "temperature.png", { time_scale = S, label = label })
-- the dough's own span, 0 to the saturation it was seeded with (0.218), not 0..1, where the whole loaf read one dark
-- blue and its drying rind did not show (#18, helper userview4)
local s0 = h.library.dough.bread.saturation
s:png("saturation", "saturation.png", { time_scale = S, label = label, range = { 0, s0 } })
s:png("browning", "browning.png", { time_scale = S, label = label })
print(("after %.0f min: centre %.1f degC at saturation %.3f, top %.1f degC at saturation %.3f; height %.1f mm; "
  .. "%.1f%% of the water left (latent_heat = %s); browning: top %.3f, base %.3f, centre %.3f; "
  .. "base lift %.2f mm (tray = %s, at %.1f degC)"):format(last[1], last[2], last[3], last[4], last[5], 1000 * last[6],
  100 * last[7], tostring(P.latent), last[8], last[9], last[10], 1000 * last[12], P.tray, last[16]))

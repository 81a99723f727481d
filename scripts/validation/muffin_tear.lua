-- muffin_tear.lua: muffins.lua's cup with the muffin's crust switchable, for
-- docs/validation.md ("The muffin's tear: a skin spent before it is a crust",
-- #18, helper tear2; "The muffin's tear over dx", helper muffin3; "The crown's
-- crack", helper crownband). It runs scripts/scenes/baking/muffins.lua itself (same
-- cup, same measures, same muffins.csv and damage.png), with
-- h.library.paper.muffin / paper_oven.muffin changed by:
--   dry_fracture  1: the preset's stretch to fracture over water (FRACTURE in
--                 lua/hearth/dough.lua); 0: none (fracture_strain 100, raw
--                 dough's), so only the set crumb's (fracture_strain_set) is left
--   glass         an extra factor on E and tau_y below X/X0 = glass_at - 0.2,
--                 1 above glass_at, log-linear between, times DRY's own factor
--                 (1: the preset): a skin that much stiffer than its batter
--   glass_at      see glass (0.65: the marshmallow's glass edge)
--   set_strain    the set crumb's stretch to fracture at 70 degC (-1: the preset's 0.15)
--   set_prop      1: the set crumb's stretch to fracture in proportion to its set, as the heat-set's water
--                 brittleness (fracture_unset): fracture_strain_set / s over the set's two points, s rising
--                 linearly 0 -> 1 (10 points, capped at the raw 100); 0: the preset's value ramp 100 -> 0.15
--   two_field     1: the scene's two_field setting (two velocity fields at the nodes a crack crosses, Homel &
--                 Herbold 2017, core/sim/solver/mpm_two_field.c), so a crack's sides move apart; 0: one field
--   set_stiff     factor G on E once set (1: the preset): E's base a temperature curve, 1 up to the set's
--                 onset (55 degC) and G at its end (70), irreversible, times DRY's moisture factor as before:
--                 a set crust (and set crumb) G times stiffer than the batter it covers
--   air_beta      factor on the oven air's heat transfer (Table 2's 75 W/(m^2 K))
--   heat_set      1: the preset's heat-set (fracture_unset, HEAT_SET in lua/hearth/dough.lua: the
--                 water's brittleness waits for the set); 0: none, the skin brittle by its water alone
--   fracture      1: the preset's crust fracture; 0: nothing cracks (fracture_strain 100, the raw
--                 dough's, and no set crumb's): what the top does by flow alone
--   band          factor on the crack band's opening crack_opening (1: the preset's 0.06 mm; 0: no band)
--   skin_dry      1: DRY's stiffening of a dried skin (E and tau_y over X/X0, lua/hearth/dough.lua);
--                 0: none, E and tau_y the batter's at any water (overrides glass)
--   crust_depth   m, 0: off. DRY's factor read as the in-plane (Voigt, parallel) average of a cell of
--                 size dx that holds a crust layer this deep which lost all of the cell's water, the
--                 crumb below it wet: at X/X0 = r the layer is at 1 - (1 - r) dx / depth and the cell's
--                 factor is 1 + (depth / dx) (f(layer) - 1), so the skin's stiffness per unit area
--                 follows the water lost per unit area, not the cell's size (a crack band for the
--                 crust's stiffness). Only where dx > crust_depth (a cell finer reads its own water)
--   ppc           particles a cell, passed to muffins.lua (0: its default, 4 in 2D)
--   damage_frames 1: the run's PNG frames show damage (particles) instead of temperature
--   axis_probe    1: each frame also prints a line "axis t=... top=..." (stdout; the CSV is unchanged): the
--                 particles within 2 mm of the first cup's axis in 1 mm bins of depth below the highest of
--                 them, each bin's mean temperature (degC) / damage / X/X0 (helper muffin4: is the crumb's
--                 heat under the crown the same over dx?)
--   crown_probe   1: each frame also prints a line "crown t=..." (stdout; the CSV is unchanged): over the first
--                 cup's one-cell bins within 20 mm of its axis, each bin's highest particle (mm above the rim),
--                 its highest intact one (damage below 1), the largest damage within 1.5 cells under the
--                 top, and the highest intact one's horizontal stress (Pa, tension positive) (helper
--                 crownband: does the crown's damage localise, or spread? do a crack's neighbours unload?)
--   hearth run scripts/validation/muffin_tear.lua --quiet --set cups=1 --set until_t=1.5 [--set dry_fracture=0] ...
-- from any folder (the scene is found beside this script: h.scene_path; or --set muffins=PATH to muffins.lua).
local h = require "hearth"
local D = require "hearth.dough"
local P = h.params { dim = 2, dx = 0.004, until_t = 3, frames = 6, cups = 3, fill = 0.022, wall_mode = "slip",
  dry_fracture = 1, heat_set = 1, glass = 1, glass_at = 0.65, set_strain = -1, air_beta = 1, damage_frames = 0,
  fracture = 1, band = 1, skin_dry = 1, crust_depth = 0, axis_probe = 0, crown_probe = 0, set_prop = 0, two_field = 0,
  set_stiff = 1, ppc = 0,
  muffins = h.scene_path("../scenes/baking/muffins.lua") }

-- muffins.lua's own h.params sees the values parsed here (it declares a subset of these names)
h.pass_params(P)

-- DRY's factor at X/X0 = r (log-linear over its points, flat past its ends)
local function dry_factor(pts, r)
  if r <= pts[1][1] then return pts[1][2] end
  for i = 2, #pts do
    if r <= pts[i][1] then
      return pts[i - 1][2] * (pts[i][2] / pts[i - 1][2]) ^ ((r - pts[i - 1][1]) / (pts[i][1] - pts[i - 1][1]))
    end
  end
  return pts[#pts][2]
end

local paper, paper_oven = h.library.paper, h.library.paper_oven
h.library.paper = setmetatable({}, { __index = function(_, name)
  local p = paper[name]
  if name ~= "muffin" then return p end
  local base, curves, _, dry = D.preset("muffin")
  if P.glass ~= 1 then -- one moisture curve (the core takes one a parameter): DRY's points times the glass
    local lo, hi = P.glass_at - 0.2, P.glass_at
    local rs = { lo, hi }
    for _, pt in ipairs(dry.E) do rs[#rs + 1] = pt[1] end
    table.sort(rs)
    local pts = { irreversible = true, of = "moisture" }
    for _, r in ipairs(rs) do
      if r > 0 and r <= 1 and (#pts == 0 or r > pts[#pts][1]) then
        local g = r <= lo and P.glass or r >= hi and 1 or P.glass ^ ((hi - r) / 0.2)
        pts[#pts + 1] = { r, dry_factor(dry.E, r) * g }
      end
    end
    p.E = base.E * h.curve(pts)
    p.tau_y = h.curve(curves.tau_y) * h.curve(pts)
  end
  if P.skin_dry == 0 then
    p.E = base.E
    p.tau_y = h.curve(curves.tau_y)
  end
  if P.crust_depth > 0 and P.dx > P.crust_depth then -- the knots of DRY's curve mapped (header)
    local a = P.crust_depth / P.dx
    local pts = { irreversible = true, of = "moisture" }
    for i, pt in ipairs(dry.E) do pts[i] = { 1 - (1 - pt[1]) * a, 1 + a * (pt[2] - 1) } end
    p.E = base.E * h.curve(pts)
    p.tau_y = h.curve(curves.tau_y) * h.curve(pts)
  end
  if P.dry_fracture == 0 then p.fracture_strain = base.fracture_strain end
  if P.fracture == 0 then p.fracture_strain, p.fracture_strain_set = base.fracture_strain, 0 end
  if P.band ~= 1 then p.crack_opening = base.crack_opening * P.band end
  if P.heat_set == 0 then p.fracture_unset = nil end
  if P.set_strain > 0 then
    local st = curves.fracture_strain_set
    p.fracture_strain_set = h.curve { { st[1][1], st[1][2] }, { st[2][1], P.set_strain }, irreversible = true }
  end
  if P.set_stiff ~= 1 then
    local ty = curves.tau_y
    local ta, tb = ty[#ty - 1][1], ty[#ty][1]
    p.E = h.curve { { ta, base.E }, { tb, base.E * P.set_stiff }, irreversible = true } * h.curve(dry.E)
  end
  if P.set_prop == 1 then
    local st = curves.fracture_strain_set
    local ta, tb, ef = st[1][1], st[2][1], P.set_strain > 0 and P.set_strain or st[2][2]
    local pts = { { ta, st[1][2] }, irreversible = true }
    for i = 1, 10 do pts[#pts + 1] = { ta + (tb - ta) * i / 10, math.min(st[1][2], ef * 10 / i) } end
    p.fracture_strain_set = h.curve(pts)
  end
  return p
end })
h.library.paper_oven = setmetatable({}, { __index = function(_, name)
  local o = paper_oven[name]
  if name == "muffin" then o.beta = o.beta * P.air_beta end
  return o
end })

-- around_run(fn): every scene's s:run first lets fn(self, r) change the run's table
local function around_run(fn)
  local scene = h.scene
  h.scene = function(o)
    local s = scene(o)
    local methods = getmetatable(s).__index
    local run = methods.run
    methods.run = function(self, r)
      fn(self, r)
      return run(self, r)
    end
    return s
  end
end

-- the scene's two velocity fields at cracks (header)
if P.two_field == 1 then
  local scene = h.scene
  h.scene = function(o)
    o.two_field = true
    return scene(o)
  end
end

-- the frames: damage instead of temperature
if P.damage_frames == 1 then
  around_run(function(_, r)
    r.png = { field = "damage", path = "damage_%04d.png", kind = "particles", range = { 0, 1 } }
  end)
end

-- the axis probe (header): wraps the run's on_frame; the cup's centre as muffins.lua puts it (on a node)
if P.axis_probe == 1 then
  around_run(function(self, r)
    local f0, s0 = r.on_frame, h.library.paper_oven.muffin.saturation
    r.on_frame = function(f)
      local q = self:particles { fields = { "x", "temperature", "damage", "saturation", "J" } }
      local xc = math.floor(0.5 * 0.08 / P.dx + 0.5) * P.dx -- muffins.lua's xs[1] (SPACING 0.08)
      local top, bins = -math.huge, {}
      for k = 1, q.n do
        if math.abs(q.x[3 * k - 2] - xc) < 0.002 then top = math.max(top, q.x[3 * k - 1]) end
      end
      for k = 1, q.n do
        if math.abs(q.x[3 * k - 2] - xc) < 0.002 then
          local b = math.floor((top - q.x[3 * k - 1]) / 0.001)
          local B = bins[b] or { 0, 0, 0, 0 }
          B[1], B[2], B[3], B[4] = B[1] + 1, B[2] + q.temperature[k], B[3] + q.damage[k],
            B[4] + q.saturation[k] * q.J[k] / s0
          bins[b] = B
        end
      end
      local cols = {}
      for b = 0, 12 do
        local B = bins[b]
        cols[#cols + 1] = B and ("%d:%.0f/%.2f/%.2f"):format(b, B[2] / B[1], B[3] / B[1], B[4] / B[1]) or ("%d:-"):format(b)
      end
      print(("axis t=%.3f top=%.2fmm above the rim %s"):format(f.t, (top - 0.042) * 1e3, table.concat(cols, " ")))
      if f0 then return f0(f) end
    end
  end)
end

-- the crown probe (header): wraps the run's on_frame, as the axis probe
if P.crown_probe == 1 then
  around_run(function(self, r)
    local f0 = r.on_frame
    r.on_frame = function(f)
      local q = self:particles { fields = { "x", "damage", "stress_xx" } }
      local xc = math.floor(0.5 * 0.08 / P.dx + 0.5) * P.dx
      local nb = math.floor(0.02 / P.dx)
      local top, intact, dmg, sxx = {}, {}, {}, {}
      for k = 1, q.n do
        local b = math.floor((q.x[3 * k - 2] - xc) / P.dx + 0.5)
        if math.abs(b) <= nb then
          local y = q.x[3 * k - 1]
          top[b] = math.max(top[b] or -math.huge, y)
          if q.damage[k] < 1 and y > (intact[b] or -math.huge) then intact[b], sxx[b] = y, q.stress_xx[k] end
        end
      end
      for k = 1, q.n do
        local b = math.floor((q.x[3 * k - 2] - xc) / P.dx + 0.5)
        if math.abs(b) <= nb and q.x[3 * k - 1] > top[b] - 1.5 * P.dx then dmg[b] = math.max(dmg[b] or 0, q.damage[k]) end
      end
      local cols = {}
      for b = -nb, nb do
        cols[#cols + 1] = top[b] and ("%.1f/%.1f/%.2f/%.0f"):format((top[b] - 0.042) * 1e3, ((intact[b] or 0.012) - 0.042) * 1e3,
          dmg[b], sxx[b] or 0)
          or "-"
      end
      print(("crown t=%.3f %s"):format(f.t, table.concat(cols, " ")))
      if f0 then return f0(f) end
    end
  end)
end

dofile(P.muffins)

-- crack_heat.lua: bread.lua's plain loaf (only = 1) with the preset's heat and
-- crust switchable, for docs/validation.md ("The unscored crack at 5 mm: heat
-- or resolution? (#18, crack5)"). It runs scripts/scenes/baking/bread.lua
-- itself (same loaf, same measures, same bread.csv), with
-- h.library.paper.bread / paper_oven.bread changed by:
--   conductivity  factor on Table 2's kappa (100 W/(m K)); 0.0234 is a real
--                 crumb's diffusivity on the water's clock (see the doc)
--   oven, pan     air and tray temperature (degC; -1: Table 2's 100)
--   dough         the raw dough's temperature (degC; -1: Table 2's 1); the thermal strain's
--                 reference_temperature stays the preset's
--   set_strain    the set crumb's stretch to fracture at 70 degC (-1: the preset's 0.15)
--   set_prop      1: the set crumb's stretch to fracture in proportion to its set (its brittleness
--                 times the set fraction s, linear 0 -> 1 over 35-70 degC: set_strain / s, 10
--                 points, capped at 100), as muffin_tear.lua's set_prop (helper crownband); 0: the
--                 preset's value ramp 100 -> 0.15
--   dry_shift     multiplies the water contents X of FRACTURE's curve (the stretch
--                 to fracture over X): > 1 makes a wetter crust as brittle as a
--                 drier one (1: the preset)
--   hearth run scripts/validation/crack_heat.lua --quiet [--set dx=0.004] [--set conductivity=0.0234] ...
-- from any folder (the scene is found beside this script: h.scene_path; or --set bread=PATH to bread.lua).
-- Besides bread.csv's row, every frame prints the temperature (degC) of the
-- loaf's top particle on its axis, of the particle 10 mm below it, of the
-- crumb's centre (35 mm above the tray) and of the bottom particle, and the
-- largest damage below 1 among the particles of the top 5 mm.
local h = require "hearth"
local D = require "hearth.dough"
local P = h.params { dim = 2, dx = 0.005, until_t = 2.5, frames = 10, slit_depth = 0.02, slit_width = 0.01, only = 1,
  conductivity = 1, oven = -1, pan = -1, set_strain = -1, set_prop = 0, dry_shift = 1, dough = -1,
  bread = h.scene_path("../scenes/baking/bread.lua") }

-- bread.lua's own h.params sees the values parsed here (it declares a subset of these names)
h.pass_params(P)

local paper, paper_oven = h.library.paper, h.library.paper_oven
h.library.paper = setmetatable({}, { __index = function(_, name)
  local p = paper[name]
  if name ~= "bread" then return p end
  p.conductivity = p.conductivity * P.conductivity
  if P.set_strain > 0 then
    p.fracture_strain_set = h.curve { { D.THETA[3], 100 }, { D.THETA[4], P.set_strain }, irreversible = true }
  end
  if P.set_prop == 1 then
    local ta, tb, ef = D.THETA[3], D.THETA[4], P.set_strain > 0 and P.set_strain or 0.15
    local pts = { { ta, 100 }, irreversible = true }
    for i = 1, 10 do pts[#pts + 1] = { ta + (tb - ta) * i / 10, math.min(100, ef * 10 / i) } end
    p.fracture_strain_set = h.curve(pts)
  end
  if P.dry_shift ~= 1 then -- FRACTURE's curve (lua/hearth/dough.lua) with its water contents scaled
    local _, _, _, dry = D.preset("bread")
    local pts = { irreversible = true, of = "moisture" }
    for i, pt in ipairs(dry.fracture_strain) do
      pts[i] = { pt[1] < 1 and pt[1] * P.dry_shift or pt[1], pt[2] }
    end
    p.fracture_strain = 100 * h.curve(pts)
  end
  return p
end })
h.library.paper_oven = setmetatable({}, { __index = function(_, name)
  local o = paper_oven[name]
  if name == "bread" and P.oven > 0 then o.temperature = P.oven end
  if name == "bread" and P.pan > 0 then o.pan_temperature = P.pan end
  if name == "bread" and P.dough > 0 then o.dough_temperature = P.dough end
  return o
end })

-- the scene, to read its particles each frame
local scene, s = h.scene, nil
h.scene = function(o)
  s = scene(o)
  local methods = getmetatable(s).__index
  local run = methods.run
  methods.run = function(self, r)
    local on_frame = r.on_frame
    r.on_frame = function(f)
      on_frame(f)
      local p = self:particles { fields = { "x", "temperature", "damage" } }
      local x0, col, top = 0.07, {}, -math.huge
      for k = 1, p.n do
        local y = p.x[3 * k - 1]
        top = math.max(top, y)
        if math.abs(p.x[3 * k - 2] - x0) < P.dx / 2 then col[#col + 1] = k end
      end
      table.sort(col, function(a, b) return p.x[3 * a - 1] > p.x[3 * b - 1] end)
      local function T_at(y) -- the axis particle nearest height y
        local best
        for _, k in ipairs(col) do
          if not best or math.abs(p.x[3 * k - 1] - y) < math.abs(p.x[3 * best - 1] - y) then best = k end
        end
        return best and p.temperature[best] or 0 / 0
      end
      local dmax = 0
      for k = 1, p.n do
        if p.x[3 * k - 1] > top - 0.005 and p.damage[k] < 1 then dmax = math.max(dmax, p.damage[k]) end
      end
      local ytop = #col > 0 and p.x[3 * col[1] - 1] or 0
      print(("t %.2f  T top %.1f, 10 mm below %.1f, centre %.1f, bottom %.1f degC; top 5 mm damage max %.2f"):format(f.t,
        T_at(ytop), T_at(ytop - 0.010), T_at(0.02 + 0.035), T_at(0.02), dmax))
    end
    return run(self, r)
  end
  return s
end

dofile(P.bread)

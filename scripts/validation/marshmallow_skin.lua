-- marshmallow_skin.lua: does a roasted marshmallow with a dried, brittle skin
-- over a molten inside ooze when pressed (Ding et al. 2019 Fig. 18)? 2D, or
-- 3D with --set dim=3 (marshmallow.lua's upright cylinder; try dx 3 mm).
-- For docs/validation.md "The marshmallow's ooze (#18)"; a lever tried on
-- marshmallow.lua's geometry, not a preset. One marshmallow per scene:
--   hearth run scripts/validation/marshmallow_skin.lua --quiet --set only=roasted
--   hearth run scripts/validation/marshmallow_skin.lua --quiet --set only=raw
-- The material is Table 2's s'more (h.library.paper.smore's numbers) with
--  * no starch set: tau_y follows Fig. 8 to the melted value at 35 degC and
--    stays there (a sugar-gelatin foam melts and does not gelatinise);
--  * a skin that dries: water (saturation s0, K theta = Kw m^2/s, evaporation
--    evap kg/(m^2 s K)) and a moisture factor x F on E and tau_y below X/X0 =
--    0.65 (x1 above 0.85), as tests/lua/crust_cracks.lua, with its
--    fracture_strain falling from 1 (wet: ductile) to ef_dry (dry). The law's
--    yield strain is tau_y / E ~ 1.5e-3 whatever F, so ef_dry 1e-3 is brittle.
-- The roasted one roasts in Table 2's s'more flame (ambient 400 degC, beta 120
-- W/(m^2 K)) in dry air (oven saturation 0) for `roast` seconds; the flame goes
-- out and the crackers close at `speed` each for `press` seconds. The raw one
-- sits in air in equilibrium with its water (oven saturation s0: a
-- marshmallow's water activity is about room humidity, so it does not dry).
-- The crackers' contact is `mode` (slip; sticky holds the material at their
-- faces, a fountain squeeze flow) with Coulomb `friction` (0.5).
-- `--set two_field=1` gives the grid two velocity fields at cracks (the scene
-- setting two_field: damage-field-gradient partitioning, 2D; slip crackers).
-- Note the ooze below counts particles that fell off the crackers, in their
-- height bands, as the outline there.
-- Prints, each frame: the ooze (marshmallow.lua's measure: the fraction of
-- the outline, the outermost particle on each side in each band of height
-- dx, that is inside material, i.e. started more than `skin` from the
-- surface), the skin particles cracked (damage 1) and the centre temperature;
-- writes <name>_damage.png and <name>_saturation.png at the end.
local h = require "hearth"
local D = require "hearth.dough"
local P = h.params { dim = 2, dx = 0.002, roast = 0.9, press = 0.8, speed = 0.01, frames = 17, F = 10, ef_dry = 1e-3,
  Kw = 1.5e-5, evap = 2, s0 = 0.5, skin = 0.004,
  only = h.choice { "", [""] = "both marshmallows", raw = "the raw one alone", roasted = "the roasted one alone" },
  mode = h.choice("slip", h.contact_words), friction = 0.5, two_field = 0 }
local d3 = P.dim == 3
local dx = P.dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
local W, H = 0.08, 0.08
local BASE, HM, RM = 0.02, 0.025, 0.015 -- marshmallow.lua's: lower cracker's top, height, half width
local CW, CT, GAP = 0.025, 0.004, 0.004
local xc, zc = W / 2, 0.04
local c = D.paper.smore
local dry = h.curve { { 0.65, P.F }, { 0.85, 1 }, of = "moisture", irreversible = true }
local tau_pts, eta_pts = { irreversible = true }, { irreversible = true }
for i, T in ipairs(D.THETA) do
  if i < 4 then tau_pts[#tau_pts + 1] = { T, c.yield * D.TAU_SHAPE[i] } end -- no starch set
  eta_pts[#eta_pts + 1] = { T, c.eta * D.ETA_SCALE * D.ETA_SHAPE[i] }
end
local mat = h.material("cam_clay_dough", {
  E = c.E * dry, nu = 0.3, density = c.density, specific_heat = c.specific_heat, conductivity = c.kappa,
  tau_y = h.curve(tau_pts) * dry, eta = h.curve(eta_pts),
  fracture_strain = 1 * h.curve { { 0.65, P.ef_dry }, { 0.85, 1 }, of = "moisture", irreversible = true },
  porosity = 0.1, expansion = 2, reference_temperature = c.theta0,
  water_diffusivity = P.Kw / 293.15, evaporation = P.evap })

for _, name in ipairs { "raw", "roasted" } do
  if P.only == "" or P.only == name then
    local roast = name == "roasted"
    local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(W, H, 0.08) }, gravity = v(0, -9.81, 0),
      oven = roast and { temperature = c.ambient_theta, beta = c.ambient_beta, saturation = 0 } or { saturation = P.s0 },
      two_field = P.two_field == 1, name = "marshmallow_skin" }
    local lower = s:collider { shape = h.box(v(xc - CW, BASE - CT, zc - CW), v(xc + CW, BASE, zc + CW)), mode = P.mode,
      friction = P.friction }
    local upper = s:collider { shape = h.box(v(xc - CW, BASE + HM + GAP, zc - CW), v(xc + CW, BASE + HM + GAP + CT, zc + CW)),
      mode = P.mode, friction = P.friction }
    -- marshmallow.lua's shapes: a box in 2D, an upright cylinder in 3D
    local shape = d3 and h.cylinder(v(xc, BASE + HM / 2, zc), { 0, 1, 0 }, RM, HM / 2)
      or h.box(v(xc - RM, BASE, zc), v(xc + RM, BASE + HM, zc))
    s:add { shape = shape, material = mat, temperature = c.theta0, ppc = d3 and 8 or 4, saturation = P.s0 }
    local skin = {}
    local r0 = s:particles { fields = { "id", "x" } }
    for i = 1, r0.n do
      local x, y, z = r0.x[3 * i - 2], r0.x[3 * i - 1], r0.x[3 * i]
      local rad = d3 and math.sqrt((x - xc) ^ 2 + (z - zc) ^ 2) or math.abs(x - xc)
      skin[r0.id[i]] = math.min(RM - rad, y - BASE, BASE + HM - y) < P.skin
    end
    local function ooze()
      local r = s:particles { fields = { "id", "x", "damage" } }
      local best, who, cracked = {}, {}, 0
      for i = 1, r.n do
        local x, y, z = r.x[3 * i - 2], r.x[3 * i - 1], r.x[3 * i]
        local rad, side -- 3D: 8 sectors around the axis
        if d3 then
          rad = math.sqrt((x - xc) ^ 2 + (z - zc) ^ 2)
          side = math.floor((math.atan(z - zc, x - xc) + math.pi) / (2 * math.pi) * 8) % 8
        else
          rad, side = math.abs(x - xc), x < xc and 0 or 1
        end
        local key = math.floor(y / dx) * 8 + side
        if not best[key] or rad > best[key] then best[key], who[key] = rad, r.id[i] end
        if skin[r.id[i]] and r.damage[i] >= 1 then cracked = cracked + 1 end
      end
      local n, out = 0, 0
      for _, id in pairs(who) do n = n + 1; if not skin[id] then out = out + 1 end end
      return out / n, cracked
    end
    local nskin = 0
    for _, v in pairs(skin) do if v then nskin = nskin + 1 end end
    s:at(P.roast, function(sc)
      if roast then sc:oven(nil) end
      sc:collider_velocity(lower, v(0, P.speed, 0), 0)
      sc:collider_velocity(upper, v(0, -P.speed, 0), 0)
    end)
    s:at(P.roast + P.press, function(sc)
      sc:collider_velocity(lower, v(0, 0, 0), 0)
      sc:collider_velocity(upper, v(0, 0, 0), 0)
    end)
    local until_t = P.roast + P.press + 0.1
    s:run { until_t = until_t, every = until_t / P.frames, on_frame = function(f)
      local o, cr = ooze()
      print(("%s t %.2f s: ooze %.3f, skin cracked %d of %d, centre %.1f degC"):format(name, f.t, o, cr, nskin,
        s:probe("temperature", v(xc, BASE + HM / 2, zc))))
    end }
    s:png("damage", name .. "_damage.png")
    s:png("saturation", name .. "_saturation.png")
  end
end

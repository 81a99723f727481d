-- marshmallow_shell.lua: the best case for the marshmallow's ooze (Ding et al.
-- 2019 Fig. 18, "when pressed the crust breaks and the inside oozes out"):
-- a crust laid in by hand rather than roasted. One marshmallow of
-- marshmallow.lua's size (2D, 30 x 25 mm on a cracker, the upper cracker
-- `gap` above it), whose outer `ct` is a stiff crust (E and tau_y x F and
-- x3F of the inside's) that breaks (cam_clay_dough's stretch rule,
-- fracture_strain `ef`), over a molten inside (the scene's molten s'more:
-- tau_y 60 Pa, E 4e4 Pa). No heat: this asks only whether a crust over goo,
-- pressed, lets the goo out. For docs/validation.md "The marshmallow's ooze
-- (#18)":
--   hearth run scripts/validation/marshmallow_shell.lua --quiet                 (the scene's press before ooze4)
--   hearth run scripts/validation/marshmallow_shell.lua --quiet --set speed=0.01 (20 mm closure)
-- `--set tf=1` gives the grid two velocity fields at cracks (two_field).
-- The crackers start `gap` above the marshmallow and close at `speed` each
-- from t = 0.05 s for `press` s: the defaults are marshmallow.lua's before
-- helper ooze4 (4 mm, 5 mm/s, 1 s: 10 mm of closure, 6 mm of it on the
-- marshmallow; the scene now presses 20 mm between sticking crackers).
-- Prints each frame marshmallow.lua's ooze (the fraction of the outline, the
-- outermost particle on each side in each band of height dx, that started
-- more than `skin` from the surface) and the skin particles cracked; writes
-- damage_NN.png each frame (the density with ef = 0, where nothing cracks).
local h = require "hearth"
local P = h.params { dx = 0.002, press = 1.0, speed = 0.005, gap = 0.004, frames = 8, F = 10, ef = 0.05,
  ct = 0.004, skin = 0.004, tf = 0, friction = 0.5 }
local dx = P.dx
local function v(x, y) return { x, y } end
local W, H = 0.08, 0.08
local BASE, HM, RM = 0.02, 0.025, 0.015 -- marshmallow.lua's: lower cracker's top, height, half width
local CW, CT = 0.025, 0.004
local xc = W / 2
local s = h.scene { dim = 2, dx = dx, box = { v(0, 0), v(W, H) }, gravity = v(0, -9.81), two_field = P.tf == 1,
  name = "marshmallow_shell" }
local TIN, EIN = 60, 4e4 -- Pa: the molten s'more's tau_y (200 x Fig. 8's 0.3) and Table 2's E
local goo = h.material("cam_clay_dough", { E = EIN, nu = 0.3, density = 500, tau_y = TIN, eta = 60, porosity = 0.1 })
local crust = h.material("cam_clay_dough", { E = EIN * P.F, nu = 0.3, density = 500, tau_y = TIN * P.F * 3, eta = 60,
  porosity = 0.1, fracture_strain = P.ef, fracture_stretch = 1 })
local lower = s:collider { shape = h.box(v(xc - CW, BASE - CT), v(xc + CW, BASE)), mode = "slip", friction = P.friction }
local upper = s:collider { shape = h.box(v(xc - CW, BASE + HM + P.gap), v(xc + CW, BASE + HM + P.gap + CT)),
  mode = "slip", friction = P.friction }
local c = P.ct
s:add { shape = h.box(v(xc - RM + c, BASE + c), v(xc + RM - c, BASE + HM - c)), material = goo, ppc = 4 }
for _, b in ipairs { { -RM, 0, RM, c }, { -RM, HM - c, RM, HM }, { -RM, c, -RM + c, HM - c }, { RM - c, c, RM, HM - c } } do
  s:add { shape = h.box(v(xc + b[1], BASE + b[2]), v(xc + b[3], BASE + b[4])), material = crust, ppc = 4 }
end
local skin, nskin = {}, 0
local r0 = s:particles { fields = { "id", "x" } }
for i = 1, r0.n do
  local x, y = r0.x[3 * i - 2], r0.x[3 * i - 1]
  skin[r0.id[i]] = math.min(RM - math.abs(x - xc), y - BASE, BASE + HM - y) < P.skin
  if skin[r0.id[i]] then nskin = nskin + 1 end
end
local function ooze() -- marshmallow.lua's measure, 2D
  local r = s:particles { fields = P.ef > 0 and { "id", "x", "damage" } or { "id", "x" } } -- ef 0: never cracks
  local best, who, cracked = {}, {}, 0
  for i = 1, r.n do
    local x, y = r.x[3 * i - 2], r.x[3 * i - 1]
    local rad, side = math.abs(x - xc), x < xc and 0 or 1
    local key = math.floor(y / dx) * 8 + side
    if not best[key] or rad > best[key] then best[key], who[key] = rad, r.id[i] end
    if skin[r.id[i]] and r.damage and r.damage[i] >= 1 then cracked = cracked + 1 end
  end
  local n, out = 0, 0
  for _, id in pairs(who) do n = n + 1; if not skin[id] then out = out + 1 end end
  return out / n, cracked
end
s:at(0.05, function(sc)
  sc:collider_velocity(lower, v(0, P.speed), 0)
  sc:collider_velocity(upper, v(0, -P.speed), 0)
end)
s:at(0.05 + P.press, function(sc)
  sc:collider_velocity(lower, v(0, 0), 0)
  sc:collider_velocity(upper, v(0, 0), 0)
end)
local until_t, k = 0.05 + P.press, 0
s:run { until_t = until_t, every = until_t / P.frames, on_frame = function(f)
  local o, cr = ooze()
  print(("t %.2f s: ooze %.3f, skin cracked %d of %d, crackers %.1f mm apart"):format(f.t, o, cr, nskin,
    (HM + P.gap - 2 * P.speed * math.max(0, math.min(f.t, until_t) - 0.05)) * 1e3))
  s:png(P.ef > 0 and "damage" or "density", ("damage_%02d.png"):format(k)); k = k + 1
end }

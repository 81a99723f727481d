-- A block dropped onto two pebbles (helper pancakeheat, #18): the physical pancake's set sheet lands on strands of
-- its raw side that dripped onto the pan, one particle each, and rests well over them (docs/validation.md, "The
-- pancake's middle at 2 mm"). Here the same in its simplest form: on a separate tray (h.recipes.tray, y = 2 cm) lie
-- two pebbles of one particle each (`pebble` x `pebble` cells of the lattice, default 1: a quarter cell, h_p = dx / 4
-- half-extent) 2 cm apart, and a w x ht elastic block (E 1e5 Pa, 1000 kg/m^3, damped 100 1/s) is released
-- `lift` cells above them over both, for t seconds. two_field = true gives the bodies their own velocity fields
-- where they meet (core/sim/solver/mpm_two_field.c). Touching, the block's lowest particle over a pebble stands at the
-- pebble's top plus its own half-spacing h_p.
-- Prints one line:
--   result over=<the block's lowest particle over the pebbles, dx above the tray> contact=<where it would stand
--   touching them, dx> away=<its lowest particle midway between them, dx> pebble=<the pebbles' highest particle, dx>
local h = require "hearth"
local P = h.params { dx = 0.002, t = 0.4, lift = 1.0, pebble = 1, w = 0.04, ht = 0.006, two_field = false }
local TRAY, XC, GAP = 0.02, 0.07, 0.02
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.14, 0.1 } }, name = "pebble", damping = 100,
  two_field = P.two_field }
h.recipes.tray(s, TRAY, { mode = "separate" })
local m = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000 })
local hp = P.dx / 2 -- the lattice spacing at 4 particles a cell
local size = P.pebble * hp
-- each pebble's box ends on a lattice line (x = XC -+ GAP / 2, multiples of hp), so it holds pebble^2 lattice sites
-- (a box centred on them has its edges on the sites); its centre is size / 2 left of that line
for _, x in ipairs { XC - GAP / 2, XC + GAP / 2 } do
  s:add { shape = h.box({ x - size, TRAY }, { x, TRAY + size }), material = m, ppc = 4, jitter = 0 }
end
local n_pebbles = s:stats().particles
local y0 = TRAY + size + P.lift * P.dx
s:add { shape = h.box({ XC - P.w / 2, y0 }, { XC + P.w / 2, y0 + P.ht }), material = m, ppc = 4, jitter = 0 }
s:run { until_t = P.t }
local r = s:particles { fields = { "x", "id" } }
local over, away, top = math.huge, math.huge, -math.huge
for i = 1, r.n do
  local x, y = r.x[3 * i - 2], r.x[3 * i - 1]
  if r.id[i] < n_pebbles then
    top = math.max(top, y)
  elseif math.abs(math.abs(x - XC + size / 2) - GAP / 2) < size / 2 + hp / 2 then
    over = math.min(over, y)
  elseif math.abs(x - XC + size / 2) < hp then
    away = math.min(away, y)
  end
end
print(("result over=%.4f contact=%.4f away=%.4f pebble=%.4f pebbles=%d"):format((over - TRAY) / P.dx,
  (top + hp / 2 + hp / 2 - TRAY) / P.dx, (away - TRAY) / P.dx, (top - TRAY) / P.dx, n_pebbles))

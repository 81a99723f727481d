-- A tensile test of the dough law's fracture (issue #18, plugins/cam_clay_dough.c "crust fracture"):
-- a 6 x 1.2 cm strip held by two sticky grips, the right one pulled at 2 cm/s for 1 s (no gravity).
-- Three strips of cam_clay_dough:
--   crust:   E 1.5e5 Pa, tau_y 6e3 Pa (a dried crust: dough.lua's DRY factor ~30 on E 5e3, tau_y 200),
--            fracture_strain 0.02 (a glassy crust breaks at a few per cent, below its yield strain);
--   crumb:   E 5e3 Pa, tau_y 200 Pa, fracture_strain 1 (a rubbery dough parts only at Hencky strains ~1);
--   plastic: the crust without fracture (fracture_strain 0: Ding et al.'s law as it was).
-- Both have the yield strain tau_y / E = 0.04: brittleness is the fracture strain falling below it.
-- Prints per strip the widest empty run along the strip's centre line between the grips, in cells
-- (a crack parts the strip across), and the largest damage.
local h = require "hearth"
local P = h.params { dx = 0.002, which = "crust", v = 0.01, t = 0.3 }
local dx = P.dx
local strips = {
  crust = { E = 1.5e5, tau_y = 6e3, fracture_strain = 0.02 },
  crumb = { E = 5e3, tau_y = 200, fracture_strain = 1 },
  plastic = { E = 1.5e5, tau_y = 6e3, fracture_strain = 0 },
}
local q = strips[P.which] or error("which: crust, crumb or plastic")
local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 0.14, 0.06 } }, gravity = { 0, 0 }, name = "crust_tension" }
local m = h.material("cam_clay_dough", { E = q.E, nu = 0.3, density = 500, tau_y = q.tau_y, eta = 0,
  fracture_strain = q.fracture_strain })
local y0, y1, x0, x1, grip = 0.024, 0.036, 0.02, 0.08, 0.008
s:collider { shape = h.box({ x0 - 0.01, y0 - 0.01 }, { x0 + grip, y1 + 0.01 }), mode = "sticky" }
local right = s:collider { shape = h.box({ x1 - grip, y0 - 0.01 }, { x1 + 0.01, y1 + 0.01 }), mode = "sticky",
  velocity = { P.v, 0 } }
s:add { shape = h.box({ x0, y0 }, { x1, y1 }), material = m }
s:run { until_t = P.t }
-- A through-crack: a column of width dx in which every occupied row (height dx) of the strip holds a
-- cracked particle (damage 1) within one column either side: the strip is cut across its thickness.
-- Rows are the strip's own (between y0 and y1): a chip thrown off when the crust snaps is not a row.
-- (without a fracture strain the material cannot crack and the scene has no damage field: all 0)
local r = s:particles { fields = q.fracture_strain > 0 and { "x", "damage" } or { "x" } }
r.damage = r.damage or setmetatable({}, { __index = function() return 0 end })
local xl, occupied, cracked, dmax = x0 - 0.01, {}, {}, 0
for i = 1, r.n do
  local c = math.floor((r.x[3 * i - 2] - xl) / dx)
  local row = math.floor((r.x[3 * i - 1] - y0) / dx)
  if row >= 0 and row * dx < y1 - y0 - 1e-9 then occupied[row] = true end -- the strip's rows, not a thrown chip's
  if r.damage[i] >= 1 then cracked[c] = cracked[c] or {}; cracked[c][row] = true end
  dmax = math.max(dmax, r.damage[i])
end
local through = nil
for c = math.floor((x0 + grip - xl) / dx), math.floor((x1 - grip - xl) / dx) + 1 do
  local all = true
  for row in pairs(occupied) do
    local hit = false
    for k = c - 1, c + 1 do hit = hit or (cracked[k] and cracked[k][row]) or false end
    if not hit then all = false; break end
  end
  if all then through = xl + (c + 0.5) * dx; break end
end
s:png(q.fracture_strain > 0 and "damage" or "von_mises", "crust_tension_" .. P.which .. ".png")
local live = false
for _, f in ipairs(s:stats().fields) do live = live or f == "damage" end
print(("crust_tension %s: damage field %s"):format(P.which, live and "live" or "off"))
print(("crust_tension %s dx %g mm: pulled %.1f mm, largest damage %.3f, through-crack %s"):format(P.which, dx * 1e3,
  P.v * P.t * 1e3, dmax, through and ("at x = %.1f mm"):format(through * 1e3) or "none"))

-- A w x ht (default 6 x 3 cm) block of h.library.dough.bread (cold, no oven) released at rest with its base `lift` cells above
-- a face, under gravity for t seconds (#18, helper traygap; the defect's reproduction from /tmp/gap/gap.lua).
-- face = "tray": h.recipes.tray (a plane at y = 2 cm, mode `mode`, friction 0.4); "wall": no collider, the
-- domain's floor (wall = `mode`), whose face is one cell inside the box (G2P keeps particles there).
-- Prints, every tenth of t, the lowest particle's distance to the face in dx, and at the end one line:
--   result lowest=<dx> spread=<dx over the last 40% of t> hp=<the particles' half-spacing in dx>
local h = require "hearth"
local P = h.params { dx = 0.005, lift = 1.0, t = 0.4, face = "tray", mode = "separate", w = 0.06, ht = 0.03, dim = 2, off = 0 }
if not (P.off >= 0 and P.off < 1) then
  error(("drop.lua: off %g: expected [0, 1) (cells the tray lies above the node row under it)"):format(P.off))
end
if P.off > 0 and (P.face ~= "tray" or P.dim ~= 2) then
  error(("drop.lua: off %g: only for face = \"tray\" in 2D (the tray between node rows)"):format(P.off))
end
local TRAY = 0.02
local wall = P.face == "wall"
-- dim = 3: a w x ht x w block in a 0.14 x 0.14 x (w + 4 cm) box (8 particles a cell: half-spacing dx/4 too)
local D3 = P.dim == 3
-- off > 0 (2D): the box moved down by off cells, so the tray lies off dx above the node row under it (0: on a row, as
-- tests/contact/spread.lua; the box is then exactly the one the other cases use)
local y_lo = P.off > 0 and -P.off * P.dx or 0
local s = h.scene { dim = P.dim, dx = P.dx, box = D3 and { { 0, 0, 0 }, { 0.14, 0.14, P.w + 0.04 } } or { { 0, y_lo }, { 0.14, 0.14 + y_lo } },
  name = "drop",
  wall = wall and P.mode or "slip" }
local floor_y = wall and P.dx or TRAY
if not wall then h.recipes.tray(s, TRAY, { mode = P.mode }) end
local y0 = floor_y + P.lift * P.dx
local zc = P.w / 2 + 0.02
s:add { shape = D3 and require("hearth.core").box({ 0.07 - P.w / 2, y0, zc - P.w / 2 }, { 0.07 + P.w / 2, y0 + P.ht, zc + P.w / 2 })
    or require("hearth.core").box({ 0.07 - P.w / 2, y0 }, { 0.07 + P.w / 2, y0 + P.ht }),
  material = h.material("cam_clay_dough", h.library.dough.bread), temperature = 25 }
local function low()
  local r = s:particles { fields = { "x" } }
  local m = math.huge
  for i = 1, r.n do m = math.min(m, r.x[3 * i - 1]) end
  return (m - floor_y) / P.dx
end
print(("t 0.00 lowest %.4f dx"):format(low()))
local late = {}
for k = 1, 10 do
  s:run { until_t = P.t * k / 10 }
  local l = low()
  print(("t %.2f lowest %.4f dx"):format(P.t * k / 10, l))
  if k >= 6 then late[#late + 1] = l end
end
local lo, hi = math.huge, -math.huge
for _, l in ipairs(late) do lo, hi = math.min(lo, l), math.max(hi, l) end
-- bodies.c's default ppc (4 in 2D, 8 in 3D): 2 a cell along each axis, half-spacing dx / 4
print(("result lowest=%.4f spread=%.4f hp=%.4f hash=%s"):format(late[#late], hi - lo, 0.25, s:hash()))

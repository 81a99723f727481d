-- A thin plate pressing a soft block (helper marshfall, #18): a collider `thick` cells thick (marshmallow.lua's
-- crackers are 4 mm: two cells at its 2D dx, one at its 3D dx of 4 mm) comes down at u onto a w x ht block of a
-- Newtonian fluid (viscosity `visc` Pa s) resting on a thick sticky tray, and presses it `press` m. The plate is
-- twice the block's width, so the block spreads under it and never reaches its edges: a particle can get above
-- the plate only through it. An MPM collider acts on grid nodes and a plate thinner than a cell may hold no
-- node inside it; collider_project_particle then puts a particle inside it back on its nearest face, which
-- for a particle past the mid-plane is the far one.
-- Prints, at 20 samples, the highest particle against the plate's face (in dx) and how many particles are past
-- its mid-plane, and at the end one line:
--   result past=<the most past the mid-plane at any sample> highest=<the highest particle at the end, dx over the
--   face (negative: under it)> pressed=<how far the block's top came down, m>
local h = require "hearth"
local P = h.params { dx = 0.002, dim = 2, thick = 0.25, mode = "sticky", u = 0.1, press = 0.008, visc = 10,
  w = 0.04, ht = 0.02 }
local d3 = P.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
local TRAY, X0, Z0 = 0.02, 0.07, 0.05
local s = h.scene { dim = P.dim, dx = P.dx, box = { v(0, 0, 0), v(0.14, 0.1, 0.1) }, name = "thin_plate" }
h.recipes.tray(s, TRAY, { mode = "sticky" })
s:add { shape = h.box(v(X0 - P.w / 2, TRAY, Z0 - P.w / 2), v(X0 + P.w / 2, TRAY + P.ht, Z0 + P.w / 2)),
  material = h.material("newtonian", { viscosity = P.visc, bulk = 1e5, density = 1000 }) }
local function top()
  local r = s:particles { fields = { "x" } }
  local hi = -math.huge
  for i = 1, r.n do hi = math.max(hi, r.x[3 * i - 1]) end
  return hi, r
end
local top0 = top()
-- the plate's face half a cell over the block, where it starts to move
local face0, th = TRAY + P.ht + 0.5 * P.dx, P.thick * P.dx
s:collider { shape = h.box(v(X0 - P.w, face0, Z0 - P.w), v(X0 + P.w, face0 + th, Z0 + P.w)), mode = P.mode,
  velocity = v(0, -P.u, 0) }
local t_end = (P.press + 0.5 * P.dx) / P.u
local past, hi = 0, 0
for k = 1, 20 do
  local t = t_end * k / 20
  s:run { until_t = t }
  local face = face0 - P.u * t
  local y, r = top()
  local n = 0
  for i = 1, r.n do if r.x[3 * i - 1] > face + 0.5 * th then n = n + 1 end end
  past, hi = math.max(past, n), (y - face) / P.dx
  print(("t %.4f highest particle %.3f dx over the plate's face; %d past its mid-plane"):format(t, hi, n))
end
print(("result past=%d highest=%.4f pressed=%.5f"):format(past, hi, top0 - top()))

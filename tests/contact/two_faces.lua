-- Glue per face (helper glue): a 4 x 0.5 cm elastic sheet (2 particle rows at dx 5 mm) glued under a sticky plate
-- that carries it sideways at u over a sticky tray it never touches: the sheet's lower row passes `gap` cells
-- above the tray (0.75: past its half-spacing's reach, 0.25; the seeding lattice puts rows at a quarter and three
-- quarters of a cell), its upper row, glued to the plate, gap + 0.5 cells above it (1.25), inside the stencil of
-- the tray's face row (within 1.5 cells). A tray that held the nodes of any glued particle's stencil
-- would drag the sheet; a tray that holds only its own glued particles' (mpm_touch.c) does not.
-- Prints, at the end: result carried=<the sheet's mean x displacement over the plate's> lower=<its lower row's>
local h = require "hearth"
local P = h.params { dx = 0.005, gap = 0.75, u = 0.05, t = 0.2 }
local TRAY = 0.02
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.2, 0.1 } }, gravity = { 0, 0 }, name = "two_faces" }
s:collider { shape = h.box({ -1, -1 }, { 1, TRAY }), mode = "sticky" }
local face = TRAY + (P.gap + 0.75) * P.dx -- the plate's face: the sheet's edge is a quarter cell below the lower row
s:collider { shape = h.box({ 0.02, face }, { 0.1, face + 0.01 }), mode = "sticky", velocity = { P.u, 0 } }
s:add { shape = h.box({ 0.04, face - P.dx }, { 0.08, face }), material = h.material("elastic", { E = 1e6, nu = 0.3, density = 1000 }),
  jitter = 0 }
local function rows()
  local r = s:particles { fields = { "x" } }
  local lo = math.huge
  for i = 1, r.n do lo = math.min(lo, r.x[3 * i - 1]) end
  local all, low, n, nl = 0, 0, 0, 0
  for i = 1, r.n do
    all, n = all + r.x[3 * i - 2], n + 1
    if r.x[3 * i - 1] < lo + 0.25 * P.dx then low, nl = low + r.x[3 * i - 2], nl + 1 end
  end
  return all / n, low / nl, (lo - TRAY) / P.dx
end
local a0, l0, y0 = rows()
s:run { until_t = P.t }
local a1, l1, y1 = rows()
print(("result carried=%.4f lower=%.4f lower_row_dx=%.4f->%.4f"):format((a1 - a0) / (P.u * P.t), (l1 - l0) / (P.u * P.t), y0, y1))

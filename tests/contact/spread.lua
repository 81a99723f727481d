-- The separate tray between node rows (#18, helper touchrows): a w x ht (6 x 2 cm) elastic block standing on
-- h.recipes.tray (separate, Coulomb friction `mu`), pushed outward by a body force A (x - xc) ramped on over
-- `ramp` seconds (a centrifugal-like load: it makes the block spread sideways as a rising loaf's foot does), with
-- damping so that it comes to rest. The box's floor is moved down by `off` cells, so the tray lies `off` dx above
-- the node row under it (0: a row on the tray). 16 particles a cell (4 a cell along each axis, spacing dx / 4):
-- at every quarter offset the lowest row then lies dx / 8 above the tray, its half-spacing, where a resting body
-- stands (tests/contact/drop.lua), so every offset starts from the same body.
-- mode = "slide" instead: the block (no body force) is given a uniform velocity u along x and slides to a stop on
-- the tray (a rigid block's Coulomb stop distance is u^2 / (2 mu g)).
-- Prints the state's hash, then one line at the end:
--   result base=<the base's edge particles' outward move, mm> top=<the top edge's, mm> mid=<the mid-height edge's>
--          lowest=<the lowest particle's height over the tray, dx> (slide: slid=<the mean x move, mm> v=<mean vx>)
local h = require "hearth"
local core = require "hearth.core"
local P = h.params { dx = 0.005, off = 0, mu = 0.4, A = 2000, ramp = 0.1, t = 0.3, damping = 20, E = 2e4, nu = 0.3,
  w = 0.06, ht = 0.02, mode = "spread", u = 0.2, tray_mode = "separate" }
if not (P.off >= 0 and P.off < 1) then
  error(("spread.lua: off %g: expected [0, 1) (cells the tray lies above the node row under it)"):format(P.off))
end
local TRAY, XC = 0.02, 0.07
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, -P.off * P.dx }, { 0.14, 0.06 - P.off * P.dx } }, name = "spread",
  damping = P.mode == "spread" and P.damping or 0 }
h.recipes.tray(s, TRAY, { mode = P.tray_mode, friction = P.mu })
s:add { shape = core.box({ XC - P.w / 2, TRAY }, { XC + P.w / 2, TRAY + P.ht }), ppc = 16, jitter = 0,
  material = h.material("elastic", { E = P.E, nu = P.nu, density = 1000 }),
  velocity = P.mode == "slide" and { P.u, 0 } or { 0, 0 } }
if P.mode == "spread" then
  s:body_force(function(x, y, z, t) return P.A * math.min(1, t / P.ramp) * (x - XC), 0 end)
end
local r0 = s:particles { fields = { "x", "id" } }
local X0 = {}
local ylo, yhi = math.huge, -math.huge
for i = 1, r0.n do
  X0[r0.id[i]] = { r0.x[3 * i - 2], r0.x[3 * i - 1] }
  ylo, yhi = math.min(ylo, r0.x[3 * i - 1]), math.max(yhi, r0.x[3 * i - 1])
end
local xlo, xhi = math.huge, -math.huge
for _, p in pairs(X0) do xlo, xhi = math.min(xlo, p[1]), math.max(xhi, p[1]) end
s:run { until_t = P.t }
local r = s:particles { fields = { "x", "v", "id" } }
-- the edge particles (the outermost column on each side) of a row at height y0: their mean outward move
local sum, cnt = { base = 0, top = 0, mid = 0 }, { base = 0, top = 0, mid = 0 }
local ymid = ylo + 0.5 * (yhi - ylo)
local slid, vx, low = 0, 0, math.huge
for i = 1, r.n do
  local p0 = X0[r.id[i]]
  local dxm = r.x[3 * i - 2] - p0[1]
  slid, vx = slid + dxm, vx + r.v[3 * i - 2]
  low = math.min(low, r.x[3 * i - 1])
  local side = (math.abs(p0[1] - xlo) < 1e-9 and -1) or (math.abs(p0[1] - xhi) < 1e-9 and 1) or 0
  if side ~= 0 then
    for _, k in ipairs { "base", "top", "mid" } do
      local yk = k == "base" and ylo or k == "top" and yhi or nil
      if (yk and math.abs(p0[2] - yk) < 1e-9) or (k == "mid" and math.abs(p0[2] - ymid) < 0.13 * P.dx) then
        sum[k], cnt[k] = sum[k] + side * dxm, cnt[k] + 1
      end
    end
  end
end
local function mm(k) return cnt[k] > 0 and 1000 * sum[k] / cnt[k] or 0 / 0 end
print("hash " .. s:hash())
print(("result base=%.4f top=%.4f mid=%.4f slid=%.4f v=%.5f lowest=%.4f"):format(mm("base"), mm("top"), mm("mid"),
  1000 * slid / r.n, vx / r.n, (low - TRAY) / P.dx))

-- hearth.shapes: shapes built from the primitives, in plain Lua.
--   local h = require "hearth"; h.shapes.ring({0.5, 0.5}, 0.05, 0.1)
local core = ...
local S = {}

local function xy(v) return v[1], v[2], v[3] or 0 end

--- An annulus (a ring doughnut in 2D, a thick spherical shell in 3D).
function S.ring(c, r_in, r_out)
  if not (r_out > r_in and r_in > 0) then error("shapes.ring: need 0 < r_in < r_out", 2) end
  return core.sphere(c, r_out) - core.sphere(c, r_in)
end

--- A 2D box with corners rounded by r.
function S.rounded_box(lo, hi, r)
  local x0, y0 = xy(lo)
  local x1, y1 = xy(hi)
  if not (r > 0 and 2 * r < x1 - x0 and 2 * r < y1 - y0) then
    error("shapes.rounded_box: need 0 < r < half the smaller side", 2)
  end
  local s = core.box({ x0 + r, y0 }, { x1 - r, y1 }) + core.box({ x0, y0 + r }, { x1, y1 - r })
  for _, p in ipairs { { x0 + r, y0 + r }, { x1 - r, y0 + r }, { x0 + r, y1 - r }, { x1 - r, y1 - r } } do
    s = s + core.sphere(p, r)
  end
  return s
end

--- A cookie: a flat disc of radius r and thickness t lying on y = c[2] - t/2
--- (a capsule in 2D, a rounded cylinder in 3D).
function S.cookie(c, r, t)
  local x, y, z = xy(c)
  if not (r > t / 2 and t > 0) then error("shapes.cookie: need r > t/2 > 0", 2) end
  if #c == 2 then return core.capsule({ x - r + t / 2, y }, { x + r - t / 2, y }, t / 2) end
  return core.cylinder({ x, y, z }, { 0, 1, 0 }, r - t / 2, t / 2) +
    core.cylinder({ x, y, z }, { 0, 1, 0 }, r, t / 4)
end

--- A loaf: a box of width w and height h0 with a round top of radius w/2 (2D).
function S.loaf(base, w, h0)
  local x, y = xy(base)
  if not (w > 0 and h0 > 0) then error("shapes.loaf: need w > 0 and h > 0", 2) end
  return core.box({ x - w / 2, y }, { x + w / 2, y + h0 }) + core.sphere({ x, y + h0 }, w / 2) -
    core.box({ x - w, y - w }, { x + w, y })
end

return S

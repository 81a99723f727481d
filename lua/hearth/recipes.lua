-- hearth.recipes: scene-building steps that come up again and again.
--   local R = h.recipes; R.tray(s, 0.01, { temperature = 180, beta = 35 })
local core = ...
local R = {}

--- A flat tray (a plane collider at height y), optionally heated.
--- opts: mode ("separate"), friction (0.4), temperature (degC), beta (W/(m^2 K)).
function R.tray(s, y, opts)
  opts = opts or {}
  return s:collider { shape = core.plane({ 0, y, 0 }, { 0, 1, 0 }), mode = opts.mode or "separate",
    friction = opts.friction or 0.4, temperature = opts.temperature, beta = opts.beta }
end

--- Centres of an n x m arrangement filling lo..hi (row-major, x fastest):
--- for the 3 x 3 grids of samples the papers show.
function R.grid(n, m, lo, hi)
  local out = {}
  for j = 1, m do
    for i = 1, n do
      out[#out + 1] = { lo[1] + (i - 0.5) * (hi[1] - lo[1]) / n, lo[2] + (j - 0.5) * (hi[2] - lo[2]) / m }
    end
  end
  return out
end

--- The height of the material above y0 along the vertical line at x
--- (the highest sample where the density probe finds material).
function R.height(s, x, y0, y1, n)
  n = n or 200
  local d = s:line("density", { x, y0 }, { x, y1 }, n + 1)
  local top = nil
  for i, v in ipairs(d) do
    if v == v then top = y0 + (i - 1) * (y1 - y0) / n end
  end
  return top and (top - y0) or 0
end

return R

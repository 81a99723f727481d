-- Muffin tray (Ding et al. 2019, Fig. 2): batter in heated cups rises into a dome.
--   hearth run scripts/scenes/baking/muffins.lua [--set dim=3] [--set cups=3]
-- Writes, under hearth-out/muffins/: heat_%04d.png (temperature) and
-- muffins.csv: per frame, each muffin's top above its cup's rim and the
-- curvature of its top (negative = domed).
-- Status: with the muffin preset as documented in lua/hearth/dough.lua the
-- batter settles in its cups (top ~12 mm below the rim, slightly dished) and
-- does not dome yet: at the gas rate that would lift it, the 2 Pa batter
-- tears (the porous-weakening runaway described there).
local h = require "hearth"
local P = h.params { dim = 2, dx = 0.004, until_t = 2.5, frames = 5, cups = 3, fill = 0.022 }
local d3 = P.dim == 3
local dx = d3 and math.max(P.dx, 0.006) or P.dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local oven = h.library.oven.muffin
local TRAY, R, CUP_H, WALL, SPACING = 0.01, 0.025, 0.03, 0.004, 0.075 -- m
local W = SPACING * P.cups
local zc = 0.04
local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(W, 0.1, 0.08) },
  oven = { temperature = oven.temperature, beta = oven.beta }, name = "muffins" }
local batter = h.material("cam_clay_dough", h.library.dough.muffin)
local xs = {}
for i = 1, P.cups do
  xs[i] = (i - 0.5) * SPACING
  -- the cup: a heated container open at the top; in 2D its section is a U
  s:collider { shape = h.cup(v(xs[i], TRAY, zc), { 0, 1, 0 }, R, CUP_H, WALL, WALL), mode = "slip", friction = 0.3,
    temperature = oven.pan_temperature, beta = oven.pan_beta }
  local inner = d3 and h.cylinder(v(xs[i], TRAY + WALL + P.fill / 2, zc), { 0, 1, 0 }, R - dx / 2, P.fill / 2)
    or h.box({ xs[i] - R + dx / 2, TRAY + WALL }, { xs[i] + R - dx / 2, TRAY + WALL + P.fill })
  s:add { shape = inner, material = batter, temperature = oven.dough_temperature, ppc = d3 and 8 or 4 }
end
local RIM = TRAY + WALL + CUP_H

local function top(x)
  local n = 1000
  local d = s:line("density", v(x, TRAY, zc), v(x, 0.1, zc), n + 1)
  local y = TRAY
  for k, val in ipairs(d) do if val == val then y = TRAY + (k - 1) * (0.1 - TRAY) / n end end
  return y
end
-- curvature of a parabola through the top over the middle 60% of the cup
local function curvature(x0)
  local S0, S2, S4, T0, T2 = 0, 0, 0, 0, 0
  for k = -4, 4 do
    local u = k / 4 * 0.6 * R
    local y = top(x0 + u)
    S0, S2, S4, T0, T2 = S0 + 1, S2 + u * u, S4 + u ^ 4, T0 + y, T2 + y * u * u
  end
  return 2 * (S0 * T2 - S2 * T0) / (S0 * S4 - S2 * S2)
end

local head = { "t" }
for i = 1, P.cups do head[#head + 1] = ("top_above_rim_%d_m,top_curvature_%d_1_per_m"):format(i, i) end
local rows = { table.concat(head, ",") }
s:run { until_t = P.until_t, every = P.until_t / P.frames, png = { field = "temperature", path = "heat_%04d.png" },
  on_frame = function(f)
    local r = { ("%.3f"):format(f.t) }
    for i = 1, P.cups do r[#r + 1] = ("%.5f,%.3f"):format(top(xs[i]) - RIM, curvature(xs[i])) end
    rows[#rows + 1] = table.concat(r, ",")
    h.write("muffins.csv", table.concat(rows, "\n") .. "\n")
    print(rows[#rows])
  end }

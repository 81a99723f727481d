-- cookie_gas_trace.lua: where a leavened cookie's CO2 goes (#18, issue's
-- "the leavened cookie 1.3x"). cookies.lua's dough ball (h.library.paper.cookie,
-- radius 30 mm, 25 mm thick, 150 degC, leavener 0.015 x dough_scale.gas) alone on
-- its tray; three particles marked by id at the start, the centre (10 mm above
-- the tray), the top of the axis and the rim at mid-height, and printed each
-- frame: temperature, CO2 n^g (mol per reference m^3), porosity n^p, gas
-- pressure (eq. 13), tau_y of Fig. 8's curve at that temperature and the gas
-- pressure at which that skeleton yields in pure tension, tau_y / sqrt(M(n^p))
-- (eq. 12); and the whole cookie's CO2 (s:stats().gas_moles), area, height
-- and base width.
--   hearth run scripts/validation/cookie_gas_trace.lua --quiet [--set dx=0.005]
--   [--set gas=0] (the unleavened twin) [--set frames=25]
local h = require "hearth"
local D = require "hearth.dough"
local P = h.params { dx = 0.0075, until_t = 2.5, frames = 25, gas = 1 }
local TRAY, X, R, THICK = 0.02, 0.07, 0.03, 0.025
local d = h.library.paper.cookie
local _, curves = D.preset("cookie")
d.gas_rate = 0.015 * h.library.dough_scale.gas * P.gas
local oven = h.library.paper_oven.cookie
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.14, 0.09 } },
  oven = { temperature = 150, beta = oven.beta }, name = "cookie_gas_trace" }
h.recipes.tray(s, TRAY, { temperature = 150, beta = oven.pan_beta })
s:add { shape = h.shapes.cookie({ X, TRAY + THICK / 2 }, R, THICK), material = h.material("cam_clay_dough", d),
  temperature = oven.dough_temperature, ppc = 4 }

local function tau_at(T) -- the preset's tau_y curve (linear between Fig. 8's points, flat outside)
  local pts = curves.tau_y
  if T <= pts[1][1] then return pts[1][2] end
  for k = 2, #pts do
    local a, b = pts[k - 1], pts[k]
    if T <= b[1] then return a[2] + (b[2] - a[2]) * (T - a[1]) / (b[1] - a[1]) end
  end
  return pts[#pts][2]
end
local function M_of(n) local l = math.log(1 / n); return 9 / (4 * l * l * (3.5 * n + 1)) end

-- the marked particles: nearest to each start point
local marks = { { "centre", X, TRAY + 0.01 }, { "top", X, TRAY + THICK }, { "rim", X - R - THICK / 2, TRAY + THICK / 2 } }
local r0 = s:particles { fields = { "id", "x" } }
for _, m in ipairs(marks) do
  local best = math.huge
  for i = 1, r0.n do
    local dd = (r0.x[3 * i - 2] - m[2]) ^ 2 + (r0.x[3 * i - 1] - m[3]) ^ 2
    if dd < best then m.id, best = r0.id[i], dd end
  end
end
local fields = P.gas > 0 and { "id", "x", "temperature", "gas", "porosity", "gas_pressure" } or { "id", "x", "temperature" }
local function extent()
  local x, top, lo, hi = s:positions(), 0, math.huge, -math.huge
  for p = 0, #x // 3 - 1 do
    local px, py = x[3 * p + 1], x[3 * p + 2]
    if math.abs(px - X) < P.dx then top = math.max(top, py - TRAY) end
    if py < TRAY + 1.5 * P.dx then lo, hi = math.min(lo, px), math.max(hi, px) end
  end
  return top, hi - lo
end
print("t_s,who,T_degC,n_g_mol_m3,n_p,gas_pressure_Pa,tau_y_Pa,tension_yield_Pa,x_m,y_m | cookie: CO2_mol,area_m2,top_m,base_m")
local a0
s:run { until_t = P.until_t, every = P.until_t / P.frames, on_frame = function(f)
  local r = s:particles { fields = fields }
  local top, base = extent()
  a0 = a0 or s:volume()
  for _, m in ipairs(marks) do
    for i = 1, r.n do
      if r.id[i] == m.id then
        local T = r.temperature[i]
        local np = r.porosity and r.porosity[i] or 0.1
        print(("%.2f,%s,%.1f,%.4g,%.3f,%.1f,%.1f,%.1f,%.4f,%.4f"):format(f.t, m[1], T, r.gas and r.gas[i] or 0, np,
          r.gas_pressure and r.gas_pressure[i] or 0, tau_at(T), tau_at(T) / math.sqrt(M_of(np)), r.x[3 * i - 2],
          r.x[3 * i - 1]))
      end
    end
  end
  print(("%.2f,cookie,CO2 %.4g mol/m,area %+.1f%%,top %.1f mm,base %.1f mm"):format(f.t, s:stats().gas or 0,
    100 * (s:volume() / a0 - 1), top * 1e3, base * 1e3))
end }

-- rise_loaf.lua: one plain 2D loaf of h.library.paper.bread in
-- h.library.paper_oven.bread (bread.lua's first loaf, alone), with each suspected
-- cause of "nothing rises" switchable, for docs/validation.md ("Rise (#18)").
--   hearth run scripts/validation/rise_loaf.lua --quiet [--set dx=0.0025] [--set gas=0] ...
-- Factors on the preset: gas (gas_rate), tau (tau_y curve), eta (eta curve),
-- expansion (Pa/K, absolute), g (gravity, m/s^2), max_porosity, compaction,
-- oven (air and tray temperature, degC), pore_hardening (plugin, when given).
-- Prints one line per frame: t, height above the tray on the centre line,
-- area (s:volume(), m^2), base width, the largest porosity on the centre line
-- and the centre temperature; at the centre probe (10 mm above the tray for
-- the cookie, 35 mm for the loaf; gas 10 mm) the gas pressure, the porosity
-- there, tau_y (the preset's curve at the centre temperature: the oven only
-- heats, so it is the highest temperature reached) and the gas pressure at
-- which that skeleton yields in pure tension, tau_y / sqrt(M(n^p)) (eq. 12);
-- then raw -> peak -> end of height and area.
local h = require "hearth"
local D = require "hearth.dough"
local P = h.params { dx = 0.005, until_t = 2.5, frames = 10, gas = 1, tau = 1, eta = 1, expansion = -1, g = 9.81,
  max_porosity = -1, compaction = -1, oven = -1, pore_hardening = -1, soft_until = -1,
  dough = h.choice { "bread", bread = "h.library.paper.bread as a loaf", cookie = "h.library.paper.cookie as a cookie",
    muffin = "h.library.paper.muffin as a loaf", pancake = "h.library.paper.pancake as a loaf",
    lava_cake = "h.library.paper.lava_cake as a loaf", smore = "h.library.paper.smore as a loaf" },
  soft = h.choice { "both", both = "tau_y and eta", tau = "tau_y only", eta = "eta only" },
  png = "" }
local params, curves, oven = D.preset(P.dough)
-- soft_until (degC): the fat-melted value of Fig. 8 (its 35 degC point) held up to this temperature, on
-- the curves `soft` names: "both" (tau_y and eta), "tau" (tau_y only) or "eta"
local function scaled(pts, f, which)
  local c = { irreversible = true }
  local su = (P.soft == "both" or P.soft == which) and P.soft_until or -1
  for _, p in ipairs(pts) do
    if su > 0 and p[1] > su and #c > 0 and c[#c][1] < su then
      c[#c + 1] = { su, c[#c][2] }
    end
    c[#c + 1] = { p[1], p[2] * f }
  end
  return c
end
params.gas_rate = params.gas_rate * P.gas
if params.gas_rate_2 then params.gas_rate_2 = params.gas_rate_2 * P.gas end -- the cookie's second CO2 share
-- the cookie's shares' amounts (its leavener): the same factor
if params.gas_amount then params.gas_amount = params.gas_amount * P.gas end
if params.gas_amount_2 then params.gas_amount_2 = params.gas_amount_2 * P.gas end
local tau_pts = scaled(curves.tau_y, P.tau, "tau")
params.tau_y = h.curve(tau_pts)
params.eta = h.curve(scaled(curves.eta, P.eta, "eta"))
if P.expansion >= 0 then params.expansion = P.expansion end
if P.max_porosity > 0 then params.max_porosity = P.max_porosity end
if P.compaction >= 0 then params.compaction = P.compaction end
if P.pore_hardening >= 0 then params.pore_hardening = P.pore_hardening end
local T_oven = P.oven >= 0 and P.oven or oven.temperature
local TRAY, WIDTH, BODY, X = 0.02, 0.08, 0.03, 0.07
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.14, 0.14 } }, gravity = { 0, -P.g },
  oven = { temperature = T_oven, beta = oven.beta }, name = "rise_loaf" }
h.recipes.tray(s, TRAY, { temperature = P.oven >= 0 and P.oven or oven.pan_temperature, beta = oven.pan_beta })
-- --set dough=cookie: cookies.lua's dough ball (radius 30 mm, 25 mm thick) in the cookie's oven
local shape = P.dough == "cookie" and h.shapes.cookie({ X, TRAY + 0.0125 }, 0.03, 0.025) or h.shapes.loaf({ X, TRAY }, WIDTH, BODY)
s:add { shape = shape, material = h.material("cam_clay_dough", params),
  temperature = oven.dough_temperature, ppc = 4 }

-- tau_y of the curve given to the dough at temperature T (linear between its points, flat outside)
local function tau_at(T)
  local pts = tau_pts
  if T <= pts[1][1] then return pts[1][2] end
  for k = 2, #pts do
    local a, b = pts[k - 1], pts[k]
    if T <= b[1] then return a[2] + (b[2] - a[2]) * (T - a[1]) / (b[1] - a[1]) end
  end
  return pts[#pts][2]
end
-- eq. 12's porosity coefficient M(n) = 9 / (4 ln^2(1/n) (7/2 n + 1))
local function M_of(n) local l = math.log(1 / n); return 9 / (4 * l * l * (3.5 * n + 1)) end

local N = 700
local function column(field, x)
  return s:line(field, { x, TRAY }, { x, 0.14 }, N + 1)
end
local function height(x)
  local top = 0
  for k, val in ipairs(column("density", x)) do if val == val then top = (k - 1) * (0.14 - TRAY) / N end end
  return top
end
local function base_width()
  local d = s:line("density", { 0, TRAY + 1.5 * P.dx }, { 0.14, TRAY + 1.5 * P.dx }, N + 1)
  local lo, hi
  for k, val in ipairs(d) do if val == val then lo = lo or k; hi = k end end
  return lo and (hi - lo) * 0.14 / N or 0
end
local function max_porosity()
  local m = 0
  if P.gas > 0 then for _, val in ipairs(column("porosity", X)) do if val == val and val > m then m = val end end end
  return m
end
local raw, peak, last = nil, nil, nil
print("t_s,height_m,area_m2,base_width_m,max_porosity,centre_T_degC,centre_gas_pressure_Pa,centre_porosity,centre_tau_y_Pa,"
  .. "centre_yield_gas_Pa")
-- --set png=FIELD: a frame of that field each frame (hearth-out/rise_loaf/FIELD_%04d.png)
s:run { until_t = P.until_t, every = P.until_t / P.frames,
  png = P.png ~= "" and { field = P.png, path = P.png .. "_%04d.png" } or nil, on_frame = function(f)
  local r = { t = f.t, h = height(X), a = s:volume(), w = base_width(), n = max_porosity(),
    T = s:probe("temperature", { X, TRAY + (P.dough == "cookie" and 0.01 or 0.035) }) }
  raw = raw or r
  if not peak or r.a > peak.a then peak = r end
  last = r
  local pg = P.gas > 0 and s:probe("gas_pressure", { X, TRAY + 0.01 }) or 0
  local np = P.gas > 0 and s:probe("porosity", { X, TRAY + 0.01 }) or params.porosity
  local ty = tau_at(r.T)
  print(("%.3f,%.5f,%.6g,%.5f,%.3f,%.1f,%.1f,%.3f,%.1f,%.1f"):format(r.t, r.h, r.a, r.w, r.n, r.T, pg, np, ty,
    ty / math.sqrt(M_of(np))))
end }
print(("summary: height %.1f -> %.1f mm (%.0f%%); area peak %+.1f%% at %.2f s, end %+.1f%%; base width %.1f -> %.1f mm")
  :format(raw.h * 1e3, last.h * 1e3, 100 * last.h / raw.h, 100 * (peak.a / raw.a - 1), peak.t,
    100 * (last.a / raw.a - 1), raw.w * 1e3, last.w * 1e3))

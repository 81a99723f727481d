-- cookie_top_trace.lua: how the unleavened cookie's top takes its shape (#18,
-- "no leavener at all yields a flat one"; docs/validation.md "The unleavened
-- cookie's top: traced"). cookies.lua's dough as it was until helper flat3
-- (h.library.paper.cookie at Table 2's kappa, a 60 x 25 mm capsule at 150 degC,
-- vent 5 m/s; cookies.lua now bakes a real dough's conductivity and a 17.5 mm
-- dough) alone in one 180 mm slot, read each frame:
--   * the top from the particles: the highest particle in each one-cell bin;
--     H (the centre bin), the width w (particles' extent), the top at the
--     middle third's ends (x = +-w/6) and the sag there, H - mean of the two;
--   * the profile h(x)/H at x/x_N = 1/3, 1/2, 2/3 (x_N = w/2) beside two
--     similarity shapes of a constant-volume current on a no-slip base:
--     Huppert 1982's Newtonian one, (1 - xi^2)^(1/3) (0.961, 0.909, 0.822;
--     J. Fluid Mech. 121:43), and a power-law fluid's of index n,
--     (1 - xi^(n+1))^(1/(n+2)), derived the same way from the lubrication
--     flux q ~ h^((2n+1)/n) |h_x|^(1/n) and q = (dx_N/dt / x_N) x h (n = 1
--     gives Huppert's); the dough law's flow rate goes as (tau^2 - tau_y^2)
--     tau / eta (eq. 12 with g = f^2/2, f in Pa^2), so well past the yield its
--     stress goes as rate^(1/3), and n = 1/3 gives 0.893, 0.805, 0.688;
--   * the particle fit's curvature (h.top_curvature) and the density probe's
--     (cookies.lua's measure, 9 samples over the middle third);
--   * which parts have set: the temperature (tau_y follows the largest reached,
--     irreversible; in the oven a particle's temperature only rises) at the top
--     centre, the bottom centre, the rim and the centre (last column), and the share of the cookie past 71
--     and 78 degC (COOKIE_SET's set points);
--   * the rim's speed (m/s): how fast it still spreads.
--   hearth run scripts/validation/cookie_top_trace.lua --quiet [--set dx=0.005]
--   [--set gas=1] (the leavened twin, leavener 0.015) [--set frames=25] [--set seed=2]
--   [--set eta=0.1] [--set tau=0.5]  factors on the preset's eta and tau_y curves (what spreading longer does)
--   [--set friction=0] [--set tray_mode=sticky]  the tray's contact (h.recipes.tray; cookies.lua's: separate, 0.4)
--   [--set conductivity=0.01 --set until_t=8]  a factor on Table 2's kappa (0.01: a real dough's, Biot ~1.5, so the
--                   top, rim and base heat first; cookies.lua's lever of the same name), with a bake long enough to set it
local h = require "hearth"
local P = h.params { dx = 0.005, until_t = 2.5, frames = 25, gas = 0, seed = 1, vent = 5, eta = 1, tau = 1, friction = 0.4,
  tray_mode = h.choice("separate", h.contact_words), png = true, conductivity = 1 }
local TRAY, SLOT, R, THICK = 0.02, 0.18, 0.03, 0.025
local X = SLOT / 2
local d = h.library.paper.cookie
d.gas_rate = 0.015 * h.library.dough_scale.gas * P.gas
d.conductivity = d.conductivity * P.conductivity
if P.eta ~= 1 or P.tau ~= 1 then -- scale the curves (point lists of h.curve)
  local function scaled(c, f) -- c: D.preset's point list
    local pts = { irreversible = true }
    for i, p in ipairs(c) do pts[i] = { p[1], p[2] * f } end
    return h.curve(pts)
  end
  local D = require "hearth.dough"
  local _, curves = D.preset("cookie")
  d.eta, d.tau_y = scaled(curves.eta, P.eta), scaled(curves.tau_y, P.tau)
end
local oven = h.library.paper_oven.cookie
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { SLOT, 0.09 } },
  oven = { temperature = 150, beta = oven.beta }, gas_vent = P.vent, name = "cookie_top_trace", seed = P.seed }
h.recipes.tray(s, TRAY, { temperature = 150, beta = oven.pan_beta, mode = P.tray_mode, friction = P.friction })
s:add { shape = h.shapes.cookie({ X, TRAY + THICK / 2 }, R, THICK), material = h.material("cam_clay_dough", d),
  temperature = oven.dough_temperature, ppc = 4 }
-- frames (--set png=false: none): hearth-out/cookie_top_trace/top_%04d.png, coloured by temperature

-- marked particles: nearest to the top centre, the bottom centre, the left rim at mid-height and the centre
local marks = { { "top", X, TRAY + THICK }, { "bottom", X, TRAY }, { "rim", X - R - THICK / 2, TRAY + THICK / 2 },
  { "centre", X, TRAY + THICK / 2 } }
local r0 = s:particles { fields = { "id", "x" } }
for _, m in ipairs(marks) do
  local best = math.huge
  for i = 1, r0.n do
    local dd = (r0.x[3 * i - 2] - m[2]) ^ 2 + (r0.x[3 * i - 1] - m[3]) ^ 2
    if dd < best then m.id, best = r0.id[i], dd end
  end
end

local function probe_curvature(w) -- cookies.lua's measure: the density line's top at 9 points over the middle third
  local function line_h(x)
    local dd = s:line("density", { x, TRAY }, { x, 0.09 }, 1401)
    local top = 0
    for k, val in ipairs(dd) do if val == val then top = (k - 1) * (0.09 - TRAY) / 1400 end end
    return top
  end
  local n, S2, S4, T0, T2 = 9, 0, 0, 0, 0
  for k = 1, n do
    local u = (k - 5) / 4 * w / 6
    local y = line_h(X + u)
    S2, S4, T0, T2 = S2 + u * u, S4 + u ^ 4, T0 + y, T2 + y * u * u
  end
  return 2 * (n * T2 - S2 * T0) / (n * S4 - S2 * S2)
end

print("t_s,H_mm,w_mm,sag_third_mm,h_third,h_half,h_two_thirds,k_particles,k_probe,k_huppert,"
  .. "T_top,T_bottom,T_rim,set71,set78,rim_speed_m_s,T_centre")
s:run { until_t = P.until_t, every = P.until_t / P.frames,
  png = P.png and { field = "temperature", path = "top_%04d.png" } or nil, on_frame = function(f)
  local r = s:particles { fields = { "id", "x", "v", "temperature" } }
  local top, lo, hi, n71, n78 = {}, math.huge, -math.huge, 0, 0
  local T = {}
  local rim_v = 0
  for p = 0, r.n - 1 do
    local px, py = r.x[3 * p + 1] - X, r.x[3 * p + 2] - TRAY
    local b = math.floor(px / P.dx + 0.5)
    if not top[b] or py > top[b] then top[b] = py end
    lo, hi = math.min(lo, px), math.max(hi, px)
    local tm = r.temperature[p + 1]
    if tm >= 71 then n71 = n71 + 1 end
    if tm >= 78 then n78 = n78 + 1 end
    for _, m in ipairs(marks) do if r.id[p + 1] == m.id then T[m[1]] = tm end end
    if r.id[p + 1] == marks[3].id then rim_v = -r.v[3 * p + 1] end
  end
  local w = hi - lo
  local xN = w / 2
  local function top_at(x) -- the top between bin centres, linear
    local u = x / P.dx
    local b0 = math.floor(u)
    local y0, y1 = top[b0], top[b0 + 1]
    if not (y0 and y1) then return y0 or y1 or 0 end
    return y0 + (y1 - y0) * (u - b0)
  end
  local H = top_at(0)
  local function rel(xi) return (top_at(xi * xN) + top_at(-xi * xN)) / (2 * H) end
  local sag = H - (top_at(w / 6) + top_at(-w / 6)) / 2
  local kp = h.top_curvature(s, { keep = function() return true end, origin = X, bin = P.dx, fraction = 0.6 })
  print(("%.2f,%.2f,%.1f,%.3f,%.3f,%.3f,%.3f,%.2f,%.2f,%.2f,%.1f,%.1f,%.1f,%.2f,%.2f,%.4f,%.1f"):format(f.t, H * 1e3, w * 1e3,
    sag * 1e3, rel(1 / 3), rel(0.5), rel(2 / 3), kp, probe_curvature(w), -2 * H / (3 * xN * xN), T.top or -1,
    T.bottom or -1, T.rim or -1, n71 / r.n, n78 / r.n, rim_v, T.centre or -1))
end }

-- A settled elastic column: h.scene{damping} and s:run{until_rest} bring a
-- column released from rest onto a slip floor to rest, and its vertical
-- stress on the centre line matches the static solution sigma_yy =
-- -rho g (top - y) (free sides, slip floor: uniaxial in the small-strain
-- limit). Two resolutions; the same column undamped is still moving.
local h = require "hearth"
local rho, g, E, H, W, floor = 1000, 9.81, 1e6, 0.3, 0.4, 0.1
local function column(n, damping)
  local dx = 1 / n
  local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 1, 1 } }, damping = damping }
  local m = h.material("elastic", { E = E, nu = 0.3, density = rho })
  s:collider { shape = h.plane({ 0, floor }, { 0, 1 }), mode = "slip" }
  s:add { shape = h.box({ 0.5 - W / 2, floor }, { 0.5 + W / 2, floor + H }), material = m, ppc = 4, jitter = 0 }
  local st = s:run { until_t = 0.5, until_rest = 1e-5 }
  local r = s:particles { fields = { "x" } }
  local top, bot = -math.huge, math.huge
  for i = 1, r.n do top, bot = math.max(top, r.x[3 * i - 1]), math.min(bot, r.x[3 * i - 1]) end
  top, bot = top + 0.25 * dx, bot - 0.25 * dx -- particles sit a quarter cell (ppc 4) inside the surface
  local ratio = {}
  for k, f in ipairs { 0.05, 0.25, 0.5, 0.75 } do
    local y = bot + f * (top - bot)
    ratio[k] = s:probe("stress_yy", { 0.5, y }) / (-rho * g * (top - y))
  end
  print(("dx 1/%d, damping %g 1/s: at rest %s at t %.4g s (%d steps), max speed %.3g m/s; "
    .. "sigma_yy / static at the centre, 0.05 0.25 0.5 0.75 of the height: %.4f %.4f %.4f %.4f"):format(n, damping,
    tostring(st.at_rest), st.t, st.step, st.max_speed, ratio[1], ratio[2], ratio[3], ratio[4]))
  return st, ratio
end
for _, n in ipairs { 32, 64 } do
  local st, ratio = column(n, 300)
  assert(st.at_rest and st.max_speed < 1e-5, "the damped column did not come to rest by t = 0.5 s")
  assert(math.abs(ratio[3] - 1) < 0.05, "mid-height vertical stress off the static solution by 5% or more")
  assert(math.abs(ratio[4] - 1) < 0.05, "vertical stress at 3/4 height off the static solution by 5% or more")
end
local st = column(32, 0)
assert(not st.at_rest and st.max_speed > 1e-3, "undamped, the column should still ring at t = 0.5 s")
print("settled_column ok")

-- settled_column.lua: the settled elastic column of tests/lua/settled_column.lua
-- at three resolutions and three dampings, for docs/validation.md.
--   hearth run scripts/validation/settled_column.lua --quiet
-- A column (0.4 x 0.3 m, E = 1 MPa, nu = 0.3, rho = 1000) released from
-- rest on a slip plane settles under damping until s:run{until_rest}; its
-- vertical stress on the centre line (s:probe "stress_yy") is compared with
-- the static solution -rho g (top - y) at fractions of the height. The
-- 0.05 row is the base, next to the floor.
local h = require "hearth"
local rho, g, E, H, W, floor = 1000, 9.81, 1e6, 0.3, 0.4, 0.1
local fr = { 0.05, 0.25, 0.5, 0.75 }
local function column(n, damping)
  local dx = 1 / n
  local s = h.scene { dim = 2, dx = dx, box = { { 0, 0 }, { 1, 1 } }, damping = damping }
  local m = h.material("elastic", { E = E, nu = 0.3, density = rho })
  s:collider { shape = h.plane({ 0, floor }, { 0, 1 }), mode = "slip" }
  s:add { shape = h.box({ 0.5 - W / 2, floor }, { 0.5 + W / 2, floor + H }), material = m, ppc = 4, jitter = 0 }
  local st = s:run { until_t = 2, until_rest = 1e-5 }
  local r = s:particles { fields = { "x" } }
  local top, bot = -math.huge, math.huge
  for i = 1, r.n do top, bot = math.max(top, r.x[3 * i - 1]), math.min(bot, r.x[3 * i - 1]) end
  top, bot = top + 0.25 * dx, bot - 0.25 * dx
  local row = { ("| 1/%d | %g | %s | %.4g | %d |"):format(n, damping, tostring(st.at_rest), st.t, st.step) }
  local err = {}
  for k, f in ipairs(fr) do
    local y = bot + f * (top - bot)
    err[k] = s:probe("stress_yy", { 0.5, y }) / (-rho * g * (top - y)) - 1
    row[#row + 1] = ("%+.2f%% |"):format(100 * err[k])
  end
  print(table.concat(row, " "))
  return err
end
print("| dx | damping (1/s) | at rest | t (s) | steps | base (0.05 H) | 0.25 H | 0.5 H | 0.75 H |")
print("|---|---|---|---|---|---|---|---|---|")
local errs = {}
for _, n in ipairs { 32, 64, 128 } do errs[n] = column(n, 300) end
for _, c in ipairs { 30, 3000 } do column(64, c) end
for k, f in ipairs(fr) do
  local a, b, c = math.abs(errs[32][k]), math.abs(errs[64][k]), math.abs(errs[128][k])
  print(("observed order at %.2f H: %.2f (1/32 to 1/64), %.2f (1/64 to 1/128)"):format(f, math.log(a / b, 2),
    math.log(b / c, 2)))
end

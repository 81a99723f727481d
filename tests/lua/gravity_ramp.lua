-- s:gravity: a step change at an event and a ramp g(t) = -a t, on a body in
-- free flight (no contact in the time run), against v = integral of g dt.
local h = require "hearth"
local function body()
  local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 4 } }, gravity = { 0, 0 }, dt_max = 1e-3 }
  local m = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 })
  s:add { shape = h.box({ 0.4, 3.4 }, { 0.6, 3.6 }), material = m, ppc = 4 }
  return s
end
local function mean_v(s)
  local r = s:particles { fields = { "v" } }
  local vx, vy = 0, 0
  for i = 1, r.n do vx, vy = vx + r.v[3 * i - 2] / r.n, vy + r.v[3 * i - 1] / r.n end
  return vx, vy
end
-- a step: gravity switched on at t = 0.1 and sideways at t = 0.2
local s = body()
s:at(0.1, function(sc) sc:gravity { 0, -5 } end)
s:at(0.2, function(sc) sc:gravity { 2, -5 } end)
s:run { until_t = 0.3 }
local vx, vy = mean_v(s)
print(("step: v = (%.9g, %.9g) m/s, want (0.2, -1)"):format(vx, vy))
assert(math.abs(vx - 0.2) < 1e-9 and math.abs(vy + 1) < 1e-9, "gravity set at events")
assert(s:settings().gravity[1] == 2 and s:settings().gravity[2] == -5, "s:settings() shows the gravity now")
-- a ramp: g = -a t from t = 0; v(T) = -a T^2 / 2, less a first-order dt error (left sums)
local a, T = 10, 0.2
s = body()
s:gravity(function(t) return { 0, -a * t } end)
local st = s:run { until_t = T }
vx, vy = mean_v(s)
local want = -a * T * T / 2
print(("ramp: v_y = %.9g m/s, want %.9g (%.3g%% off, %d steps of dt <= 1e-3 s)"):format(vy, want,
  100 * math.abs(vy / want - 1), st.step))
assert(math.abs(vy / want - 1) < 0.01 and math.abs(vx) < 1e-12, "gravity ramp")
-- a function that returns nonsense is named
s = body()
s:gravity(function(t) return "down" end)
local ok, e = pcall(s.step, s, 1)
assert(not ok and e:find("s:gravity function at t = 0 returned string", 1, true), e)
s = body()
s:gravity(function(t) return { 0, 0 / 0 } end)
ok, e = pcall(s.step, s, 1)
assert(not ok and e:find("finite numbers", 1, true), e)
s:gravity { 0, 0 } -- a constant again replaces the function
s:step(1) -- and marks the scene as run, so hearth run does not run it again
ok, e = pcall(s.gravity, s, "down")
assert(not ok and e:find("s:gravity", 1, true), e)
print("gravity_ramp ok")

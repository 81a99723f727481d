-- s:particles: every particle found again by its id after the step has
-- reordered them. Two bodies in free flight (no gravity, no contact in the
-- time run): the moving one keeps its velocity exactly, so each particle
-- must be at x0 + v t, found by id wherever the sort put it.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, gravity = { 0, 0 } }
local m = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.1, 0.2 }, { 0.3, 0.4 }), material = m, ppc = 4, velocity = { 0.5, 0.25 } }
s:add { shape = h.box({ 0.6, 0.6 }, { 0.8, 0.8 }), material = m, ppc = 4, temperature = 20 }
local a = s:particles { fields = { "id", "x", "v", "temperature", "stress" } }
assert(a.n == #a.id and #a.x == 3 * a.n and #a.v == 3 * a.n and #a.stress == 9 * a.n and #a.temperature == a.n,
  "array lengths: n, 3n for vectors, 9n for the stress")
local x0, v0, seen = {}, {}, {}
for i = 1, a.n do
  local id = a.id[i]
  assert(not seen[id], "ids are unique")
  seen[id] = true
  x0[id] = { a.x[3 * i - 2], a.x[3 * i - 1] }
  v0[id] = { a.v[3 * i - 2], a.v[3 * i - 1] }
end
s:run { until_t = 0.2 }
local b = s:particles { fields = { "x", "id" } }
assert(b.n == a.n, "no particle lost")
local moved, worst = 0, 0
for i = 1, b.n do
  local id = b.id[i]
  assert(x0[id], "an id that was not there before: " .. tostring(id))
  if a.id[i] ~= id then moved = moved + 1 end
  local t = s:stats().t
  for k = 1, 2 do
    worst = math.max(worst, math.abs(b.x[3 * i - 3 + k] - (x0[id][k] + v0[id][k] * t)))
  end
end
print(("particles %d, t %.4g s, moved in the order %d, largest |x - (x0 + v t)| %.3g m"):format(b.n, s:stats().t, moved,
  worst))
assert(moved > 0, "the step reordered no particle: the test would not see an id that does not follow its particle")
assert(worst < 1e-9, "a particle found by its id is not where its free flight takes it")
-- misspelt and dead fields
local ok, e = pcall(s.particles, s, { fields = { "temperatur" } })
assert(not ok and e:find("did you mean 'temperature'?", 1, true) and e:find("live fields: id, x, v,", 1, true), e)
ok, e = pcall(s.particles, s, { fields = { "saturation" } })
assert(not ok and e:find("is not live", 1, true) and e:find("saturation = 0.5", 1, true), e)
ok, e = pcall(s.particles, s, { feilds = { "x" } })
assert(not ok and e:find("did you mean 'fields'?", 1, true), e)
print("particles_track ok")

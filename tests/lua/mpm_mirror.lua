-- The oven's heat in MPM on a mirror-symmetric loaf: bread.lua's unscored
-- loaf (Ding Table 2 bread in its oven, on the heated tray) about x = 70 mm,
-- seeded without jitter, so each particle has a mirror image. Prints the
-- worst |T - T_mirror| over the pairs and the right half's mean temperature
-- less the left's at t = until_t (mpm_oven_mirror_symmetric).
local h = require "hearth"
local P = h.params { dx = 0.005, until_t = 0.1 }
local oven = h.library.paper_oven.bread
local TRAY, WIDTH, BODY, XC = 0.02, 0.08, 0.03, 0.07
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 2 * XC, 0.14 } },
  oven = { temperature = oven.temperature, beta = oven.beta } }
h.recipes.tray(s, TRAY, { temperature = oven.pan_temperature, beta = oven.pan_beta })
local dough = h.material("cam_clay_dough", h.library.paper.bread)
s:add { shape = h.shapes.loaf({ XC, TRAY }, WIDTH, BODY), material = dough, temperature = oven.dough_temperature,
  saturation = oven.saturation, ppc = 4, jitter = 0 }
-- each particle's mirror image by its seeded position (ids follow them)
local r = s:particles { fields = { "id", "x" } }
local at = {}
for i = 1, r.n do at[("%.7f,%.7f"):format(r.x[3 * i - 2], r.x[3 * i - 1])] = r.id[i] end
local mate, unpaired = {}, 0
for i = 1, r.n do
  local j = at[("%.7f,%.7f"):format(2 * XC - r.x[3 * i - 2], r.x[3 * i - 1])]
  if j then mate[r.id[i]] = j else unpaired = unpaired + 1 end
end
s:run { until_t = P.until_t }
r = s:particles { fields = { "id", "x", "temperature" } }
local T, sl, nl, sr, nr = {}, 0, 0, 0, 0
for i = 1, r.n do
  T[r.id[i]] = r.temperature[i]
  if r.x[3 * i - 2] < XC then sl, nl = sl + r.temperature[i], nl + 1 else sr, nr = sr + r.temperature[i], nr + 1 end
end
local worst = 0
for a, b in pairs(mate) do worst = math.max(worst, math.abs(T[a] - T[b])) end
print(("mpm_mirror: dx %g m, %d particles, %d unpaired; at t = %.3f s mean %.3f degC, worst |T - T_mirror| %.3g degC, "
  .. "right less left %.3g degC"):format(P.dx, r.n, unpaired, s:stats().t, (sl + sr) / (nl + nr), worst, sr / nr - sl / nl))

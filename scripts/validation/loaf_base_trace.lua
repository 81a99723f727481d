-- loaf_base_trace.lua: what lifts the physical loaf's base off its tray (#18, helper loafbase; docs/validation.md,
-- "The physical loaf's base lifts: traced"). loaf_physical.lua's loaf (h.library.dough.bread in h.library.oven.bread,
-- on h.recipes.tray) with switches, and per frame, over the raw base's 16 middle columns of 4 mm (the claim's), each
-- column's lowest particle edge over the tray (y - h_p, h_p = (V0 J)^(1/2) / 2: loaf.csv's base_gap_m per column),
-- the largest rise of a column's lowest particle (base_lift_m), the worst column's particle (height, J, T, stress_yy,
-- v_y) and the mean J, T and stress_yy of the particles within a cell of the tray. Ends with a SUMMARY line: the
-- gap at the start, at 2 real min and its largest over the first 2 and 3 min.
--   hearth run scripts/validation/loaf_base_trace.lua [--set dx=0.0025] [--set detail=1] (every column's gap)
--   switches: jitter=0 (the seeding's, default 0.5), smooth=1 (s:add's smooth_surface), open=26 (the pores open from
--   26 degC: no gas gauge), expansion=0 (eq. 10's thermal coupling), latent=false, gas=0 (the CO2 rate's factor),
--   vent=0 (gas_vent's factor), water=0 (evaporation's and water diffusivity's factor), browning=false, tray=sticky,
--   off=F (the tray and loaf moved up F dx off the node row), seed=N (the jitter's draw), flatbase=1 (the base's
--   first particle row a body of its own, unjittered: smooth's forerunner), until_real=S (real seconds, default 180),
--   frames=N (default 36: every 5 real s), quiet=1 (SUMMARY only)
local h = require "hearth"
local P = h.params { dx = 0.005, frames = 36, latent = true, until_real = 180, tray = h.choice { "separate",
  separate = "friction 0.4, as loaf_physical.lua", sticky = "the foot held where it touched" }, off = 0.0,
  open = 70, expansion = 0.1, gas = 1.0, browning = true, vent = 1.0, detail = 0, jitter = 0.5, quiet = 0, seed = 1,
  flatbase = 0, smooth = 0, water = 1.0 }
local oven = h.library.oven.bread
local S = oven.time_scale
local until_t = P.until_real / S
local TRAY, WIDTH, BODY, X0 = 0.02 + P.off * P.dx, 0.08, 0.03, 0.07
local mp = {}
for k, v in pairs(h.library.dough.bread) do mp[k] = v end
mp.open_temperature = P.open
mp.expansion = P.expansion
mp.gas_rate = mp.gas_rate * P.gas
mp.evaporation, mp.water_diffusivity = mp.evaporation * P.water, mp.water_diffusivity * P.water
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.14, 0.14 } }, name = "loaf_base_trace", seed = P.seed,
  oven = { temperature = oven.temperature, beta = oven.beta }, latent_heat = P.latent and oven.latent_heat,
  boiling_point = oven.boiling_point, browning = P.browning, browning_scale = oven.browning_scale,
  gas_vent = oven.gas_vent * P.vent, vent_porosity = oven.vent_porosity }
h.recipes.tray(s, TRAY, { temperature = oven.pan_temperature, beta = oven.pan_beta, mode = P.tray })
local mat = h.material("cam_clay_dough", mp)
if P.flatbase > 0 then
  -- the base's first particle row (lattice centres dx/4 above the tray) unjittered, the rest as usual
  local band = h.box({ 0, TRAY - 0.01 }, { 0.14, TRAY + P.dx / 2 })
  local loaf, T0 = h.shapes.loaf({ X0, TRAY }, WIDTH, BODY), oven.dough_temperature
  s:add { shape = loaf * band, material = mat, temperature = T0, jitter = 0 }
  s:add { shape = loaf - band, material = mat, temperature = T0, jitter = P.jitter }
else
  s:add { shape = h.shapes.loaf({ X0, TRAY }, WIDTH, BODY), material = mat, temperature = oven.dough_temperature,
    jitter = P.jitter, smooth_surface = P.smooth > 0 }
end
local v0
local lo0
local SUM = {} -- per frame: real s, largest gap, mean gap, largest lift
local function cols(t)
  local r = s:particles { fields = { "x", "J", "temperature", "stress_yy", "v", "id" } }
  v0 = v0 or s:volume() / r.n
  local lo, ly, li = {}, {}, {}
  for i = 1, r.n do
    local b = math.floor((r.x[3 * i - 2] - (X0 - 0.032)) / 0.004) + 1
    local edge = r.x[3 * i - 1] - 0.5 * math.sqrt(v0 * r.J[i])
    if b >= 1 and b <= 16 then
      if not lo[b] or edge < lo[b] then lo[b] = edge; li[b] = i end
      if not ly[b] or r.x[3 * i - 1] < ly[b] then ly[b] = r.x[3 * i - 1] end
    end
  end
  lo0 = lo0 or ly
  local mg, mb, sg, ml = -1, 0, 0, -1
  for b = 1, 16 do
    local g = lo[b] - TRAY
    sg = sg + g
    if g > mg then mg, mb = g, b end
    ml = math.max(ml, ly[b] - lo0[b])
  end
  local i = li[mb]
  -- the bottom layer: mean J, T over particles within 1 dx of the tray, in the middle 80%
  local nJ, sJ, sT, sS = 0, 0, 0, 0
  for k = 1, r.n do
    if math.abs(r.x[3 * k - 2] - X0) < 0.032 and r.x[3 * k - 1] - TRAY < P.dx then
      nJ = nJ + 1; sJ = sJ + r.J[k]; sT = sT + r.temperature[k]; sS = sS + r.stress_yy[k]
    end
  end
  local line = ("t %6.1f s: gap max %.3f mm (col %2d, mean %.3f), lift max %.3f; worst: y %.3f mm J %.3f T %.1f "
    .. "syy %.0f vy %.2e; bottom dx: J %.3f T %.1f syy %.0f"):format(t * S, mg * 1e3, mb, sg / 16 * 1e3, ml * 1e3,
    (r.x[3 * i - 1] - TRAY) * 1e3, r.J[i], r.temperature[i], r.stress_yy[i], r.v[3 * i - 1], sJ / nJ, sT / nJ, sS / nJ)
  if P.quiet == 0 then print(line) end
  SUM[#SUM + 1] = { t * S, mg, sg / 16, ml }
  if P.detail > 0 and P.quiet == 0 then
    local g = {}
    for b = 1, 16 do g[#g + 1] = ("%.2f"):format((lo[b] - TRAY) * 1e3) end
    print("   gaps: " .. table.concat(g, " "))
  end
end
cols(0)
s:run { until_t = until_t, every = until_t / P.frames, on_frame = function(f) cols(f.t) end }
local m2, m3 = -1, -1
for _, r in ipairs(SUM) do
  if r[1] <= 120.01 then m2 = math.max(m2, r[2]) end
  m3 = math.max(m3, r[2])
end
local function at(tt) for _, r in ipairs(SUM) do if math.abs(r[1] - tt) < 0.01 then return r end end end
local a, b = at(0), at(120)
print(("SUMMARY dx %.2f mm: gap start %.2f mean %.2f; at 2 min %.2f (mean %.2f, lift %.2f); max <=2 min %.2f, "
  .. "<=3 min %.2f mm"):format(P.dx * 1e3, a[2] * 1e3, a[3] * 1e3, b[2] * 1e3, b[3] * 1e3, b[4] * 1e3, m2 * 1e3,
  m3 * 1e3))

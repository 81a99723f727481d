-- progress_rate_per_run: two scenes run one after the other in one hearth run (as cookies.lua bakes one oven after
-- another), the same block falling on the same tray, the second for a quarter of the first's time: the same work per
-- step, so each run's last progress line should give about the same steps/s (steps over the process's time would
-- give the second about 0.2x the first's).
local h = require "hearth"
local P = h.params { until_t = 2 }
local function one(until_t)
  local s = h.scene { dim = 2, dx = 0.005, box = { { 0, 0 }, { 0.2, 0.1 } } }
  local m = h.material("elastic", { E = 2e5, nu = 0.3, density = 1000 })
  s:collider { shape = h.plane({ 0, 0.01 }, { 0, 1 }), mode = "separate" }
  s:add { shape = h.box({ 0.05, 0.02 }, { 0.15, 0.06 }), material = m }
  s:run { until_t = until_t }
  print(("steps %d"):format(s:stats().step))
end
one(P.until_t)
one(P.until_t / 4)

-- A tray that goes into the oven cold (s:collider's start_temperature and warm_time, colliders.h): what it refuses,
-- that it heats a slab more slowly than a tray at the oven's temperature from the start, and that a checkpoint
-- saved while it warms goes on as the run it was saved from.
local h = require "hearth"
local function fails(fn, want)
  local ok, e = pcall(fn)
  assert(not ok, "expected an error containing: " .. want)
  assert(tostring(e):find(want, 1, true), ("'%s' not in: %s"):format(want, tostring(e)))
end
local floor = h.plane({ 0, 0.1 }, { 0, 1 })
local function scene(warm)
  local s = h.scene { dim = 2, dx = 1 / 50, gravity = { 0, 0 } }
  local m = h.material("elastic", { E = 1e4, density = 1000, conductivity = 1, specific_heat = 1 })
  if warm then s:collider { shape = floor, temperature = 120, beta = 50, start_temperature = 20, warm_time = 0.05 }
  else s:collider { shape = floor, temperature = 120, beta = 50 } end
  s:add { shape = h.box({ 0.2, 0.1 }, { 0.4, 0.14 }), material = m, temperature = 20, fixed = true, jitter = 0 }
  return s
end
local s = scene(true)
fails(function() s:collider { shape = floor, temperature = 100, start_temperature = 20 } end, "go together")
fails(function() s:collider { shape = floor, temperature = 100, warm_time = 10 } end, "go together")
fails(function() s:collider { shape = floor, start_temperature = 20, warm_time = 10 } end, "needs the collider's temperature")
fails(function() s:collider { shape = floor, temperature = 100, start_temperature = 20, warm_time = 0 } end, "warm_time (s, > 0)")
fails(function() s:collider { shape = floor, temperature = 100, start_temperature = 20, warm_time = 0 / 0 } end, "warm_time (s, > 0)")
fails(function() s:collider { shape = floor, temperature = 100, start_temperature = "cold", warm_time = 1 } end,
  "start_temperature is a string; valid: a number, degrees C")
fails(function() s:collider { shape = floor, temperature = 100, start_temperature = 0 / 0, warm_time = 1 } end,
  "start_temperature = nan degrees C; valid range [-273.15, 5000]")
fails(function() s:collider { shape = floor, temperature = 100, start_temperature = -300, warm_time = 1 } end,
  "start_temperature = -300 degrees C; valid range [-273.15, 5000]")
s:run { until_t = 0.03 }
s:save("warm.ck")
local r = h.load("warm.ck")
r:run { until_t = 0.1 }
s:run { until_t = 0.1 }
assert(r:hash() == s:hash(), "a restored scene warms on as the one it was saved from")
local still = scene(false)
still:run { until_t = 0.1 }
local cold, hot = s:probe("temperature", { 0.3, 0.105 }), still:probe("temperature", { 0.3, 0.105 })
print(("slab bottom at 0.1 s: tray warming from 20 degC %.3f, tray at 120 degC from the start %.3f"):format(cold, hot))
assert(cold > 20 and cold < hot - 1, "the cold tray heats the slab later")
print("warming_tray ok")

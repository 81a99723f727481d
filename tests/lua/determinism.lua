-- lua_determinism: jittered particles from a seed; the hash and the CSV
-- series must be the same on every run with the same seed.
local h = require "hearth"
local P = h.params { seed = 7 }
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, seed = P.seed }
local jelly = h.material("elastic", { E = 2e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.35, 0.4 }, { 0.65, 0.6 }), material = jelly, ppc = 4, jitter = 0.5 }
s:add { shape = h.disc({ 0.5, 0.75 }, 0.08), material = jelly, ppc = 4, jitter = 0.5, velocity = { 0.3, 0 } }
s:collider { shape = h.plane({ 0, 0.1 }, { 0, 1 }), mode = "separate", friction = 0.2 }
print("hash0 " .. s:hash())
s:run { until_t = 0.05, every = 0.01, csv = "series.csv",
  probes = { { "speed", { 0.5, 0.5 } }, { "velocity", { 0.5, 0.45 } } } }
print("particles " .. s:stats().particles)
print("hash " .. s:hash())

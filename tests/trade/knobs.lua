-- A tiny scene for the trade tests: a block that falls for 0.05 s, a declared
-- parameter, a custom metric and a mixed sauce (for the blend knob).
local h = require "hearth"
local P = h.params { size = 0.125 }
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
local mix = h.mix { { { kappa = 1e6, mu = 1e5, sigma_y = 10, eta = 1, h = 1 }, 0.5 },
                    { { kappa = 1e6, mu = 1e5, sigma_y = 40, eta = 4, h = 1 }, 0.5 } }
s:add { shape = h.box({ 0.5 - P.size, 0.5 - P.size }, { 0.5 + P.size, 0.5 + P.size }), material = h.material("elastic", { E = 1e4 }) }
h.metric("particles", function(sc) return sc:stats().particles end)
h.metric("mixed_yield", function() return mix.sigma_y end)
h.metric("dx", function(sc) return 1 / 32 end)
h.metric("not_a_number", function() return "tall" end)
s:run { until_t = 0.05 }

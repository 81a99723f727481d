-- damping and until_rest refuse what they cannot do, saying why; a damped
-- scene's checkpoint (format version 5) keeps its damping
local h = require "hearth"
local function fails(fn, want)
  local ok, e = pcall(fn)
  assert(not ok, "expected an error containing: " .. want)
  assert(tostring(e):find(want, 1, true), ("'%s' not in: %s"):format(want, tostring(e)))
end
fails(function() h.scene { damping = -1 } end, "damping")
fails(function() h.scene { solver = "sph", damping = 5 } end, "only the MPM solver damps")
local s = h.scene { dim = 2, dx = 1 / 16, damping = 5 }
local m = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m }
s:save("damped.ck")
assert(h.load("damped.ck"):settings().damping == 5, "the restored scene damps as saved")
fails(function() s:run { until_t = 0.1, until_rest = -1 } end, "until_rest")
fails(function() s:run { until_t = 0.1, until_rst = 1 } end, "did you mean 'until_rest'?")
assert(s:settings().damping == 5, "s:settings() reports the damping")
print("damping_errors ok")

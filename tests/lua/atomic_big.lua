-- lua_atomic_output: large files every frame, for a kill -9 in the middle.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 1, 1 } } }
local jelly = h.material("elastic", { E = 2e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.05, 0.05 }, { 0.95, 0.7 }), material = jelly, ppc = 9 }
print("particles " .. s:stats().particles)
io.stdout:flush()
s:run { until_t = 1000, every = 1e-4, csv = "series.csv", probes = { { "speed", { 0.5, 0.3 } } },
  png = { field = "speed", path = "frame_%05d.png", kind = "particles", width = 400, height = 400 },
  on_frame = function(fr)
    fr:vtu("frame_%05d.vtu")
    fr:vtu("latest.vtu") -- the same name rewritten every frame
    fr:png("speed", "latest.png", { kind = "slice", width = 300 })
  end }

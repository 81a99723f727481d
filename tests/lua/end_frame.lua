-- run_until_ends_on_frame: a run of 0.25 s with a frame every 0.1 s (0.25 is not a multiple of it), its frames' times
-- printed one a line, with a VTU series beside them (every 0.1 s too) when --set vtu=true. Run with --until to cut it.
local h = require "hearth"
local P = h.params { vtu = h.flag { false, what = "write a VTU series beside the frames" } }
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
s:collider { shape = h.plane({ 0, 0.1 }, { 0, 1 }), mode = "separate" }
s:add { shape = h.box({ 0.4, 0.3 }, { 0.6, 0.5 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
s:run { until_t = 0.25, every = 0.1, vtu = P.vtu and { path = "d_%04d.vtu", pvd = "d.pvd" } or nil,
  on_frame = function(f) print(("frame %d t = %.6g"):format(f.index, f.t)) end }
print(("end t = %.6g"):format(s:stats().t))

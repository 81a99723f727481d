-- lua_atomic_output: a Lua error after some frames must leave only whole files.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
local jelly = h.material("elastic", { E = 2e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.7, 0.6 }), material = jelly, ppc = 4 }
s:run { until_t = 0.05, every = 0.005, csv = "series.csv",
  png = { field = "speed", path = "frame_%04d.png" },
  on_frame = function(fr)
    fr:vtu("frame_%04d.vtu")
    fr:ply("frame_%04d.ply")
    if fr.index == 4 then error("deliberate failure at frame " .. fr.index) end
  end }

-- lua_png_outputs: pictures from frames and from the scene.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 0.5 } } }
local jelly = h.material("elastic", { E = 2e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.3, 0.1 }, { 0.7, 0.35 }), material = jelly, ppc = 4, velocity = { 0.5, 0.2 } }
s:run { until_t = 0.01, every = 0.01, on_frame = function(fr)
  if fr.index == 1 then
    print("slice " .. fr:png("speed", "frame_slice.png", { kind = "slice", width = 160 }))
    print("particles " .. fr:png("velocity", "frame_particles_%02d.png", { kind = "particles", width = 120, height = 90 }))
  end
end }
print("scene_particles " .. s:png("density", "sub/scene_particles.png", { kind = "particles", width = 200, height = 150 }))
print("scene_slice " .. s:png("speed", "scene_slice.png", { width = 256 }))
print("default " .. s:png("speed", "default.png"))
local ok, err = pcall(s.png, s, "speed", "bad.png", { kind = "pixels" })
print("bad_kind " .. tostring(ok) .. " " .. tostring(err))

-- lua_user_test.sh default_scene_water_sourced: the dashboard's default scene (assets/cookie_bake.lua) run as it
-- is, its cookie's material parameters caught on their way to h.material and printed.
local h = require "hearth"
local material = h.material
h.material = function(plugin, p)
  if p.saturation then
    print(("water saturation %.6g water_diffusivity %.6g evaporation %.6g"):format(p.saturation, p.water_diffusivity,
      p.evaporation))
  end
  return material(plugin, p)
end
dofile(h.scene_path("../../assets/cookie_bake.lua"))

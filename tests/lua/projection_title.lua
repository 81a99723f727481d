-- particles_3d_title_says_projection: a 3D particle picture's title says it is seen along -z, a projection of every
-- depth (#18, helper userfix9; userview4's item 15); a 2D particle picture's and a 3D slice's titles do not. A 3D
-- jelly block, two pictures of it and the same in 2D; the 3D scene, not run here, is run by `hearth run` (its
-- frame_%04d.png, particles: the test passes --until); tests/png_title.py reads the files' Title text.
local h = require "hearth"
for _, dim in ipairs { 2, 3 } do
  local d3 = dim == 3
  local s = h.scene { dim = dim, dx = 0.01, box = d3 and { { 0, 0, 0 }, { 0.1, 0.1, 0.1 } } or { { 0, 0 }, { 0.1, 0.1 } } }
  local jelly = h.material("elastic", { E = 2e5, nu = 0.3, density = 1000 })
  s:add { shape = d3 and h.box({ 0.03, 0.03, 0.03 }, { 0.07, 0.07, 0.07 }) or h.box({ 0.03, 0.03 }, { 0.07, 0.07 }),
    material = jelly, temperature = 20 }
  s:png("temperature", ("particles_%dd.png"):format(dim), { kind = "particles", width = 300 })
  s:png("temperature", ("slice_%dd.png"):format(dim), { kind = "slice", width = 300 })
  -- slice_3d_title_says_plane (helper userfix11): a 3D slice across x, its title naming where it cuts
  if d3 then s:png("temperature", "slice_3d_x.png", { kind = "slice", axis = "x", at = 0.03, width = 300 }) end
end

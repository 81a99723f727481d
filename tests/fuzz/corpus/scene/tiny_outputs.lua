local h = require "hearth"
local s = h.scene{dim = 2, box = {{0, 0}, {0.1, 0.1}}, dx = 0.01, seed = 2}
local soup = h.material("newtonian", {density = 1000, bulk = 2e4, viscosity = 0.5})
s:add{material = soup, shape = h.disc({0.05, 0.05}, 0.02), ppc = 2}
s:step(2)
s:save("ck.bin")
h.write("note.txt", "hello")
s:vtu("p.vtu")
s:ply("p.ply")

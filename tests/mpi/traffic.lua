-- mpi_halo_traffic_bounded: an elastic bar of length len (m) thrown along a
-- box 2 m long (slabs along x) onto a floor, 100 steps. tests/mpi_test.sh
-- runs it at two lengths (twice the particles) and reads each rank's bytes.
local h = require "hearth"
local P = h.params { len = 0.6, steps = 100 }
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 2, 0.5 } }, wall = "slip" }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 0.2, 0.15 }, { 0.2 + P.len, 0.35 }), material = jelly, ppc = 4, velocity = { 0.5, -1 } }
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }
s:step(P.steps)
local st = s:stats()
print(("steps %d particles %d kinetic %.17g"):format(st.step, st.particles, st.kinetic))

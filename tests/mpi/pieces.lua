-- mpi_vtu_pieces_read_as_one_*: the standard elastic block (elastic_block.lua)
-- run with VTU frames. Under mpirun each rank writes its piece of every frame
-- and rank 0 the .pvtu index (docs/outputs.md); tests/vtk_pieces.py reads the
-- pieces with VTK and compares them with a one-process run's .vtu frames.
local h = require "hearth"
local P = h.params { dim = 2, until_t = 0.1, every = 0.05, whole = 0 }
local s = h.scene { dim = P.dim, dx = P.dim == 3 and 1 / 32 or 1 / 64, box = { { 0, 0, 0 }, { 1, 1, 0.5 } }, wall = "slip" }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000 })
local block = P.dim == 3 and h.box({ 0.3, 0.15, 0.15 }, { 0.7, 0.35, 0.35 }) or h.box({ 0.3, 0.15 }, { 0.7, 0.35 })
s:add { shape = block, material = jelly, ppc = 4, velocity = P.dim == 3 and { 0.5, -1, 0.2 } or { 0.5, -1 } }
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }
s:run { until_t = P.until_t, every = P.every, vtu = { path = "vtu/block_%04d.vtu" } }
-- whole = 1: the whole scene gathered into one file (s:vtu), whose bits the
-- last frame's pieces must hold (the gather is left out of the run that
-- checks that the frames gather nothing)
if P.whole == 1 then s:vtu("vtu/whole.vtu") end

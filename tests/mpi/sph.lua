-- mpi_sph_refused: SPH runs in one process; under more than one rank the
-- scene is refused with a message that says so.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, solver = "sph" }
print("created", s)

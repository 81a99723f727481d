-- mpi_guard_stops_all_ranks: two blocks side by side along x; only the right
-- one (the last rank's particle blocks) turns its stress NaN after a few steps
-- (tests/plugins/nan_after.c). The guard must stop every rank, and rank 0
-- must print the diagnosis although its own particles are fine.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 1, 1 } }, gravity = { 0, 0 } }
local calm = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 })
local bad = h.material("nan_after", { E = 1e4, nu = 0.3, density = 1000, after = 5 })
s:add { shape = h.box({ 0.1, 0.3 }, { 0.45, 0.7 }), material = calm, ppc = 4 }
s:add { shape = h.box({ 0.75, 0.4 }, { 0.9, 0.6 }), material = bad, ppc = 4 }
s:step(50)
print("not stopped")

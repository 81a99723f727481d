-- The SPH dam break the instruction counts use (scripts/bench/sph_instructions.sh,
-- issue #20's comparison with DualSPHysics at 20k and 80k particles): a 2D
-- water column 0.2 m x 0.4 m, one particle per dx^2 (dx = 0.002: 20,000
-- particles; 0.001: 80,000), collapsing in a 1.2 m x 0.6 m box, with
-- artificial viscosity and XSPH. Steps `steps` steps after a 2-step warm-up
-- (buffers sized), untimed: a profiler reads it. --set hash=1 prints the
-- particles' hash after the steps.
--   OMP_NUM_THREADS=1 hearth run scripts/bench/sph_dam_break.lua --set dx=0.002 --set steps=4
local h = require "hearth"
local P = h.params { dx = 0.002, steps = 4, hash = 0, dim = 2 }
-- dim=3 (for the bit checks of scripts/bench/sph_identical.sh): the column 0.1 m deep in a box 0.2 m deep
local s = P.dim == 3
  and h.scene { dim = 3, dx = P.dx, box = { { 0, 0, 0 }, { 1.2, 0.6, 0.2 } }, solver = "sph", wall = "slip",
    sph = { av_beta = 1, xsph0 = 0.05 } }
  or h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 1.2, 0.6 } }, solver = "sph", wall = "slip",
    sph = { av_beta = 1, xsph0 = 0.05 } }
local water = h.material("newtonian", { density = 1000, bulk = 2e5, viscosity = 1e-3 })
s:add { shape = P.dim == 3 and h.box({ 0, 0, 0 }, { 0.2, 0.4, 0.1 }) or h.box({ 0, 0 }, { 0.2, 0.4 }), material = water,
  ppc = 1, jitter = 0 }
s:step(2)
if P.steps > 0 then s:step(P.steps) end
-- hash=1: the particles' bits after the steps (every column), to check a change keeps them
if P.hash ~= 0 then print(("%d particles, %d steps: hash %s"):format(s:stats().particles, s:stats().step, s:hash())) end

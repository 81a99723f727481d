-- The benchmark block of `hearth bench` (2D) as a scene, for
-- scripts/bench/tui_overhead.sh: an elastic block filling [0.2,0.8]^2 of the
-- unit box, neo-Hookean E = 1e5 Pa, nu = 0.3, rho = 1000, sticky walls,
-- dt = 1e-4 * 64 / cells. s:step(n) takes exactly n steps (in the dashboard
-- it hands back to the screen after each).
local h = require "hearth"
local P = h.params { cells = 128, steps = 300 }
local dt = 1e-4 * 64 / P.cells
s = h.scene { dim = 2, dx = 1 / P.cells, box = { { 0, 0 }, { 1, 1 } }, wall = "sticky", dt_max = dt, cfl = 0.5,
  seed = 7 }
s:add { shape = h.box({ 0.2, 0.2 }, { 0.8, 0.8 }), material = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000 }),
  ppc = 4 }
s:step(P.steps)

-- The same dough in the same oven under solver = "mpm" and solver = "sph", one command:
--   hearth run scripts/scenes/sph/compare_mpm_sph.lua [--until 0.5]
-- The dough is one maxwell_sph material (Rodriguez-Arenas 2011 eq. 3.20; the
-- ABI is solver-agnostic, so the plugin runs unchanged in both). Each run
-- reports its CPU time (os.clock, s), steps, particles and final shape (width and height, m, of
-- the material from density lines), side by side, and compare.csv holds both.
-- Heat enters differently: MPM through the oven's Robin flux (Ding et al.);
-- SPH through eq. 3.42 at surface particles (per unit area, heat_ext = h / c
-- = 6.1 kg/(m^2 s), what the thesis's printed form gave with 3e8 at dx 4 mm:
-- an animation-scaled h of 6.1 x 2500 = 15000 W/(m^2 K)) plus the same Robin
-- flux, which at beta = 20 is about 1/800 of it.
-- solver, a word (mpm or sph), has no unit (tests/scene_csv.py's unit rule):
-- compare.csv has no unit: solver
local h = require "hearth"
local P = h.params { t_end = h.number { 0.5, above = 0, unit = "s", what = "each solver's simulated time" },
  dx = h.number { 0.004, above = 0, unit = "m", what = "the grid spacing" },
  oven = h.number { 180, min = -273.15, max = 5000, unit = "degC", what = "the oven's temperature" } }

local function run(solver)
  local opts = { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.3, 0.15 } }, solver = solver,
    oven = { temperature = P.oven, beta = 20 } }
  if solver == "sph" then opts.sph = { heat_ext = 6.1, heat_int = 0.5, av_beta = 1, xsph0 = 0.05 } end
  local s = h.scene(opts)
  local dough = h.material("maxwell_sph", { density = 1100, bulk = 3e4, mu_e = 2e3, lambda = 2, viscosity = 20,
    conductivity = 0.5, specific_heat = 2500 })
  s:add { shape = h.box({ 0.1, 0.01 }, { 0.2, 0.06 }), material = dough, ppc = solver == "sph" and 1 or 4,
    jitter = 0, temperature = 26 }
  s:collider { shape = h.plane({ 0, 0.01 }, { 0, 1 }), mode = "slip", friction = 0.3 }
  local t0 = os.clock()
  s:run { until_t = P.t_end, every = P.t_end, png = { field = "temperature", path = solver .. "_%04d.png" } }
  local cpu = os.clock() - t0
  local function extent(a, b, n)
    local v, lo, hi = s:line("density", a, b, n), nil, nil
    for i, d in ipairs(v) do if d == d then lo = lo or i; hi = i end end
    if not lo then return 0 end
    return (hi - lo + 1) / n * math.sqrt((b[1] - a[1]) ^ 2 + (b[2] - a[2]) ^ 2)
  end
  local st = s:stats()
  return { solver = solver, cpu = cpu, steps = st.step, particles = st.particles,
    width = extent({ 0, 0.015 }, { 0.3, 0.015 }, 301), height = extent({ 0.15, 0.01 }, { 0.15, 0.15 }, 141) }
end

local r = { run("mpm"), run("sph") }
local rows = { "solver,cpu_s,steps,particles,width_m,height_m" }
print(("%-6s %10s %8s %10s %10s %10s"):format("solver", "cpu (s)", "steps", "particles", "width (m)", "height (m)"))
for _, x in ipairs(r) do
  print(("%-6s %10.2f %8d %10d %10.4f %10.4f"):format(x.solver, x.cpu, x.steps, x.particles, x.width, x.height))
  rows[#rows + 1] = ("%s,%.3f,%d,%d,%.5f,%.5f"):format(x.solver, x.cpu, x.steps, x.particles, x.width, x.height)
end
h.write("compare.csv", table.concat(rows, "\n") .. "\n")

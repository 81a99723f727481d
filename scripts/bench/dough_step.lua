-- The cost of one cam_clay_dough step with every field on, relative to the
-- elastic benchmark step (`hearth bench`: a block filling [0.2,0.8]^dim of the
-- unit box, 4 particles per cell in 2D, 8 in 3D, neo-Hookean E = 1e5 Pa) on
-- the same particles, in one run. Run with one thread for a clean ratio:
--   OMP_NUM_THREADS=1 hearth run scripts/bench/dough_step.lua [--set dim=3] [--set cells=32]
-- Prints seconds per step for: elastic (momentum only), elastic with the
-- dough's fields (oven, temperature, CO2, expansion), and the dough with all
-- fields, and the ratios. Timings are CPU seconds (os.clock).
local h = require "hearth"
local P = h.params { dim = 2, cells = 64, steps = 200, only = "" }
local d3 = P.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local function timed(material, fields)
  local s = h.scene { dim = P.dim, dx = 1 / P.cells, box = { v(0, 0, 0), v(1, 1, 1) }, wall = "sticky", seed = 7,
    dt_max = 1e-5, oven = fields and { temperature = 150, beta = 25 } or nil }
  s:add { shape = h.box(v(0.2, 0.2, 0.2), v(0.8, 0.8, 0.8)), material = material, ppc = d3 and 8 or 4,
    temperature = fields and 20 or nil }
  s:step(2) -- warm-up: buffers sized
  local t0 = os.clock()
  s:step(P.steps)
  local dt = (os.clock() - t0) / P.steps
  return dt, s:stats().particles
end

local elastic = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000 })
local elastic_fields = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000, specific_heat = 20, conductivity = 30,
  gas_rate = 2.5e-5, expansion = 0.1, reference_temperature = 20 })
local dough = h.material("cam_clay_dough", h.library.dough.cookie)

-- only=elastic|dough: step that one scene, untimed (scripts/bench/dough_instructions.sh counts it under callgrind)
if P.only ~= "" then
  if P.only ~= "elastic" and P.only ~= "dough" then error("only: elastic or dough, not '" .. P.only .. "'") end
  timed(P.only == "dough" and dough or elastic, P.only == "dough")
  return
end

local te, n = timed(elastic, false)
local tf = timed(elastic_fields, true)
local td = timed(dough, true)
print(("%dD, %d particles, %d steps each (1 thread unless OMP_NUM_THREADS says otherwise)"):format(P.dim, n, P.steps))
print(("elastic step                 %.3e s"):format(te))
print(("elastic + dough's fields     %.3e s  (%.2fx)"):format(tf, tf / te))
print(("cam_clay_dough, all fields   %.3e s  (%.2fx the elastic step; target <= 2.5x)"):format(td, td / te))

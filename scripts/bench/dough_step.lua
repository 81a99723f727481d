-- The cost of one cam_clay_dough step with every field on, relative to the
-- elastic benchmark step (`hearth bench`: a block filling [0.2,0.8]^dim of the
-- unit box, 4 particles per cell in 2D, 8 in 3D, neo-Hookean E = 1e5 Pa) on
-- the same particles, in one run. Run with one thread for a clean ratio:
--   OMP_NUM_THREADS=1 hearth run scripts/bench/dough_step.lua [--set dim=3] [--set cells=32] [--set rounds=5]
-- Prints seconds per step for: elastic (momentum only), elastic with the
-- dough's fields (oven, temperature, CO2, expansion), and the dough with all
-- fields, and the ratios: the median over the rounds of each round's ratio,
-- and their range. Timings are CPU seconds (os.clock).
local h = require "hearth"
local P = h.params { dim = 2, cells = 64, steps = 200, rounds = 5, cycle = false,
  only = h.choice { "", [""] = "the timed benchmark of all three", elastic = "step the elastic scene alone, untimed",
    fields = "step the elastic scene with fields alone, untimed", dough = "step the dough scene alone, untimed" } }
local d3 = P.dim == 3
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end

local function scene(material, fields)
  local s = h.scene { dim = P.dim, dx = 1 / P.cells, box = { v(0, 0, 0), v(1, 1, 1) }, wall = "sticky", seed = 7,
    dt_max = 1e-5, oven = fields and { temperature = 150, beta = 25 } or nil }
  s:add { shape = h.box(v(0.2, 0.2, 0.2), v(0.8, 0.8, 0.8)), material = material, ppc = d3 and 8 or 4,
    temperature = fields and 20 or nil }
  s:step(2) -- warm-up: buffers sized
  return s
end
local function timed(s) -- CPU seconds per step over the next P.steps steps
  local t0 = os.clock()
  s:step(P.steps)
  return (os.clock() - t0) / P.steps
end

local elastic = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000 })
local elastic_fields = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000, specific_heat = 20, conductivity = 30,
  gas_rate = 2.5e-5, expansion = 0.1, reference_temperature = 20 })
local dough = h.material("cam_clay_dough", h.library.paper.cookie)

-- only=elastic|fields|dough: step that one scene, untimed, for a profiler
-- (scripts/bench/dough_instructions.sh counts elastic and dough under callgrind)
if P.only ~= "" then
  local pick = { elastic = { elastic, false }, fields = { elastic_fields, true }, dough = { dough, true } }
  local m = pick[P.only] -- h.params took only a word of these
  local s = scene(m[1], m[2])
  if P.cycle then -- the steps between the fields' updates (core/sim/fields/field_clock.c), for the average
    repeat s:step(1) until s:stats().field_cycle > 0 or s:stats().step > 100000
    print(("field cycle %d steps"):format(s:stats().field_cycle))
    return
  end
  timed(s)
  return
end

-- The three scenes step in turn, P.rounds times, and each round gives its
-- own ratios: a machine that slows down for a while slows all three of a
-- round alike, so the median of the rounds' ratios is steadier than a
-- ratio of two single timings taken seconds apart.
local se, sf, sd = scene(elastic, false), scene(elastic_fields, true), scene(dough, true)
local te, tf, td, rf, rd = {}, {}, {}, {}, {}
for r = 1, P.rounds do
  te[r], tf[r], td[r] = timed(se), timed(sf), timed(sd)
  rf[r], rd[r] = tf[r] / te[r], td[r] / te[r]
end
local function median(t)
  local c = { table.unpack(t) }
  table.sort(c)
  local n = #c
  return n % 2 == 1 and c[(n + 1) / 2] or 0.5 * (c[n / 2] + c[n / 2 + 1])
end
local function range(t)
  local c = { table.unpack(t) }
  table.sort(c)
  return ("%.2f..%.2f"):format(c[1], c[#c])
end
print(("%dD, %d particles, %d rounds of %d steps each (1 thread unless OMP_NUM_THREADS says otherwise)"):format(P.dim,
  se:stats().particles, P.rounds, P.steps))
print(("elastic step                 %.3e s (median)"):format(median(te)))
print(("elastic + dough's fields     %.3e s  (%.2fx, rounds %s)"):format(median(tf), median(rf), range(rf)))
print(("cam_clay_dough, all fields   %.3e s  (%.2fx the elastic step, rounds %s; target <= 2.5x)"):format(median(td),
  median(rd), range(rd)))

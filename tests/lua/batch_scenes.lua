-- batch_scene_matches_one_point: scenes whose plugins have a batched stress
-- (<hearth/material.h> rule 7) print the hash of their particle state after a
-- few steps. lua_test.sh runs this twice, as it is and with
-- HEARTH_PLUGIN_NO_BATCH=1 (one stress call per point), and compares the two
-- outputs byte for byte. P.plugin = "batch_mismatch" adds a scene of the
-- deliberately wrong test plugin, whose hash must differ between the two runs
-- (so the switch is seen to switch).
local h = require "hearth"
local P = h.params { mismatch = 0 }
local function v(d3, x, y, z) return d3 and { x, y, z } or { x, y } end

local function block(name, dim, material, fields, steps)
  local d3 = dim == 3
  local s = h.scene { dim = dim, dx = d3 and 1 / 12 or 1 / 32, box = { v(d3, 0, 0, 0), v(d3, 1, 1, 1) }, seed = 7,
    dt_max = 1e-3, oven = fields and { temperature = 150, beta = 25 } or nil }
  s:add { shape = h.box(v(d3, 0.3, 0.3, 0.3), v(d3, 0.7, 0.6, 0.7)), material = material, ppc = d3 and 8 or 4,
    jitter = 0.5, velocity = v(d3, 0.3, -0.5, 0.1), temperature = fields and 20 or nil }
  s:add { shape = d3 and h.sphere({ 0.5, 0.8, 0.5 }, 0.1) or h.disc({ 0.5, 0.8 }, 0.1), material = material, ppc = d3 and 8 or 4,
    velocity = v(d3, 0, -2, 0), temperature = fields and 20 or nil }
  s:step(steps)
  print(name .. " " .. s:stats().particles .. " " .. s:hash())
end

local elastic = h.material("elastic", { E = 2e4, nu = 0.3, density = 1000 })
block("elastic_2d", 2, elastic, false, 60)
block("elastic_3d", 3, elastic, false, 20)
-- E follows the temperature: one parameter in a column of the block
local warm = h.material("elastic", { E = h.curve { { 20, 2e4 }, { 150, 5e3 } }, nu = 0.3, density = 1000,
  specific_heat = 20, conductivity = 30, gas_rate = 2.5e-5, expansion = 0.1, reference_temperature = 20 })
block("elastic_curve_2d", 2, warm, true, 60)
local dough = h.material("dough_batched", h.library.paper.cookie)
block("dough_2d", 2, dough, true, 60)
block("dough_3d", 3, dough, true, 15)
-- a drying crust (tests/lua/crust_cracks.lua, shorter): water, moisture curves on E, tau_y and
-- fracture_strain (three parameter columns), damage and the tension cut-off
do
  local dry = h.curve { { 0.65, 30 }, { 0.85, 1 }, of = "moisture", irreversible = true }
  local ef = 1 * h.curve { { 0.65, 0.02 }, { 0.85, 1 }, of = "moisture", irreversible = true }
  local m = h.material("dough_batched", { E = 5e3 * dry, nu = 0.3, density = 500, tau_y = 200 * dry, eta = 0,
    fracture_strain = ef, specific_heat = 20, conductivity = 30, expansion = 10, reference_temperature = 20,
    porosity = 0.1, max_porosity = 0.6, water_diffusivity = 2e-4 / 293.15, evaporation = 2 })
  local s = h.scene { dim = 2, dx = 0.004, box = { { 0, 0 }, { 0.12, 0.08 } }, oven = { temperature = 120, beta = 1000 } }
  s:collider { shape = h.plane({ 0, 0.01 }, { 0, 1 }), mode = "sticky" }
  s:add { shape = h.box({ 0.02, 0.01 }, { 0.10, 0.04 }), material = m, temperature = 20, saturation = 0.4 }
  s:step(80)
  print("crust_2d " .. s:stats().particles .. " " .. s:hash())
end
if P.mismatch == 1 then
  block("mismatch_2d", 2, h.material("batch_mismatch", { E = 2e4, nu = 0.3, density = 1000 }), false, 30)
end

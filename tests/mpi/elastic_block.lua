-- mpi_elastic_*: the standard elastic block (scripts/scenes/drop_block.lua's
-- block and floor), 100 steps, then every particle's id, x, v, J and stress to
-- state.csv (17 digits) for tests/mpi_test.sh to compare between rank counts.
local h = require "hearth"
local P = h.params { dim = 2, steps = 100 }
local s = h.scene { dim = P.dim, dx = P.dim == 3 and 1 / 32 or 1 / 64, box = { { 0, 0, 0 }, { 1, 1, 0.5 } }, wall = "slip" }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000 })
local block = P.dim == 3 and h.box({ 0.3, 0.15, 0.15 }, { 0.7, 0.35, 0.35 }) or h.box({ 0.3, 0.15 }, { 0.7, 0.35 })
s:add { shape = block, material = jelly, ppc = 4, velocity = P.dim == 3 and { 0.5, -1, 0.2 } or { 0.5, -1 } }
s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }
s:step(P.steps)
local r = s:particles { fields = { "id", "x", "v", "J", "stress" } }
local lines = {}
for i = 1, r.n do
  local row = { ("%d"):format(r.id[i]) }
  for k = 1, 3 do row[#row + 1] = ("%.17g"):format(r.x[3 * (i - 1) + k]) end
  for k = 1, 3 do row[#row + 1] = ("%.17g"):format(r.v[3 * (i - 1) + k]) end
  row[#row + 1] = ("%.17g"):format(r.J[i])
  for k = 1, 9 do row[#row + 1] = ("%.17g"):format(r.stress[9 * (i - 1) + k]) end
  lines[#lines + 1] = table.concat(row, ",")
end
h.write("state.csv", table.concat(lines, "\n") .. "\n")
local st = s:stats()
print(("steps %d particles %d kinetic %.17g hash %s"):format(st.step, st.particles, st.kinetic, s:hash()))

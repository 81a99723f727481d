-- mpi_checkpoint_restores_on_other_ranks: mode=save runs the elastic block
-- (elastic_block.lua's) 50 steps, saves ck.bin, takes 50 more and writes
-- state.csv; mode=load restores ck.bin (from the output folder) and takes the
-- same 50 steps. Run on 2 ranks to save, then on 1 and 4 to load.
local h = require "hearth"
local P = h.params { mode = "save" }
local s
if P.mode == "save" then
  s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0, 0 }, { 1, 1, 0.5 } }, wall = "slip" }
  local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000 })
  s:add { shape = h.box({ 0.3, 0.15 }, { 0.7, 0.35 }), material = jelly, ppc = 4, velocity = { 0.5, -1 } }
  s:collider { shape = h.plane({ 0, 0.1, 0 }, { 0, 1, 0 }), mode = "separate", friction = 0.3 }
  s:step(50)
  s:save("ck.bin")
else
  s = h.load("ck.bin")
end
s:step(50)
local r = s:particles { fields = { "id", "x", "v", "J" } }
local lines = {}
for i = 1, r.n do
  lines[#lines + 1] = ("%d,%.17g,%.17g,%.17g,%.17g,%.17g"):format(r.id[i], r.x[3 * i - 2], r.x[3 * i - 1], r.v[3 * i - 2],
    r.v[3 * i - 1], r.J[i])
end
h.write(P.mode == "save" and "state.csv" or "state_loaded.csv", table.concat(lines, "\n") .. "\n")
print(("%s steps %d particles %d hash %s"):format(P.mode, s:stats().step, s:stats().particles, s:hash()))

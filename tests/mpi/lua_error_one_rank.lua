-- mpi_lua_error_on_one_rank_ends: a heated jelly slab over the ranks (stats()
-- is collective while slabs are kept), and a Lua error that the last rank
-- alone raises between two step calls (a scene reading rank-dependent input:
-- here the rank number from the environment). The run must end with that
-- rank's message, not hang with the others in their next step and the failed
-- rank in its run record's stats() (#21).
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 2, 0.5 } }, wall = "slip", oven = { temperature = 200, beta = 40 } }
local jelly = h.material("elastic", { E = 5e4, nu = 0.3, density = 1000, specific_heat = 3000, conductivity = 5 })
s:add { shape = h.box({ 0.2, 0.1 }, { 1.8, 0.3 }), material = jelly, ppc = 4, temperature = 20 }
s:step(10)
local size = tonumber(os.getenv("OMPI_COMM_WORLD_SIZE") or "1")
if os.getenv("OMPI_COMM_WORLD_RANK") == tostring(size - 1) and size > 1 then
  error("an error raised on rank " .. (size - 1) .. " alone")
end
s:step(10)
print(("steps %d"):format(s:stats().step))

-- mpi_discs_conserve_momentum: two elastic discs (the same material and
-- particle size, so every particle has the same mass) meet off-centre in
-- empty space, no gravity, no walls near: they cross the ranks' particle
-- runs many times over and leave spinning. Prints the particle count, the
-- sums of v and of x cross v (momentum and angular momentum per particle
-- mass) at the start and the end, and writes state.csv as elastic_block.lua.
local h = require "hearth"
local P = h.params { steps = 150 }
local s = h.scene { dim = 2, dx = 1 / 64, box = { { 0, 0 }, { 1, 1 } }, gravity = { 0, 0 } }
local jelly = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 })
s:add { shape = h.disc({ 0.3, 0.44 }, 0.12), material = jelly, ppc = 4, velocity = { 1.5, 0 } }
s:add { shape = h.disc({ 0.7, 0.56 }, 0.12), material = jelly, ppc = 4, velocity = { -1.5, 0 } }
local function sums()
  local r = s:particles { fields = { "id", "x", "v" } }
  local px, py, l, vabs = 0, 0, 0, 0
  for i = 1, r.n do
    local x, y, vx, vy = r.x[3 * i - 2], r.x[3 * i - 1], r.v[3 * i - 2], r.v[3 * i - 1]
    px, py = px + vx, py + vy
    l = l + x * vy - y * vx
    vabs = vabs + math.sqrt(vx * vx + vy * vy)
  end
  return r, px, py, l, vabs
end
local _, px0, py0, l0, vabs0 = sums()
s:step(P.steps)
local r, px, py, l = sums()
print(("particles %d t %.6g"):format(r.n, s:stats().t))
print(("start p %.17g %.17g L %.17g |v| %.17g"):format(px0, py0, l0, vabs0))
print(("end p %.17g %.17g L %.17g"):format(px, py, l))
local lines = {}
for i = 1, r.n do
  lines[#lines + 1] = ("%d,%.17g,%.17g,%.17g,%.17g"):format(r.id[i], r.x[3 * i - 2], r.x[3 * i - 1], r.v[3 * i - 2], r.v[3 * i - 1])
end
h.write("state.csv", table.concat(lines, "\n") .. "\n")
s:png("speed", "discs.png")

-- h.union / h.intersection / h.difference of many shapes at once (lua_union_many_shapes):
-- the fold kept every partial result on Lua's stack and overran it past a few
-- dozen shapes; whether that then crashed depended on the heap's layout (SIGABRT
-- "free(): invalid pointer" at a later collection for the SPH roll's 150
-- dispersed bubbles, #18; SIGSEGV here at 100 shapes), so several counts.
local h = require "hearth"
local r = 0.0004
for _, n in ipairs { 40, 70, 100, 130, 160, 250, 500 } do
  local discs = {}
  for i = 1, n do discs[i] = h.disc({ 0.001 * i, 0.05 }, r) end
  local u = h.union(table.unpack(discs))
  for i = 1, n, 7 do
    assert(u:sdf({ 0.001 * i, 0.05 }) < 0, ("union of %d: disc %d's centre is outside"):format(n, i))
  end
  assert(u:sdf({ 0.0015, 0.05 }) > 0, "union: a point between two discs is inside")
  local all = h.intersection(h.box({ 0, 0 }, { 1, 1 }), table.unpack(discs))
  assert(all:sdf({ 0.001, 0.05 }) > 0, "intersection of disjoint discs is not empty")
  local holed = h.difference(h.box({ 0, 0 }, { 1, 1 }), table.unpack(discs))
  assert(holed:sdf({ 0.002, 0.05 }) > 0 and holed:sdf({ 0.0025, 0.05 }) < 0, "difference: wrong side")
  u, all, holed, discs = nil, nil, nil, nil
  collectgarbage()
end
print("union many ok")

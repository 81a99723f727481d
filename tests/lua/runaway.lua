-- sandbox_sigint_loop: a scene that never ends by itself, in several ways
-- (--set kind=loop|pcall_loop|recursion_loop|run|long_step); prints "started" first.
local h = require "hearth"
local P = h.params { kind = "loop" }
io.stdout:setvbuf("no")
print("started")
if P.kind == "loop" then
  while true do end
elseif P.kind == "pcall_loop" then
  -- catching the interrupt must not keep the scene alive
  while true do pcall(function() while true do end end) end
elseif P.kind == "recursion" then
  -- deep recursion that catches its own stack overflows and goes on forever
  local function f(n) while true do pcall(f, n + 1) end end
  f(1)
elseif P.kind == "rep_loop" then
  -- big strings made and dropped, under the memory ceiling, forever
  while true do local s = string.rep("x", 1 << 22) end
elseif P.kind == "coroutine_loop" then
  local co = coroutine.wrap(function() while true do end end)
  co()
elseif P.kind == "long_step" then
  -- one step that takes many seconds inside the core: 2000 copies of one cup around a block of ~130 000 particles,
  -- each near every particle and node (a collider's distance found twice per particle in G2P and once per node)
  local s = h.scene { dim = 2, dx = 1 / 256, box = { { 0, 0 }, { 1, 1 } } }
  s:add { shape = h.box({ 0.05, 0.05 }, { 0.95, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
  for _ = 1, 2000 do s:collider { shape = h.container({ 0.5, 0.02 }, { 0, 1 }, 0.46, 0.9, 0.01, 0.01) } end
  print("stepping")
  s:run { until_t = 1e6 }
elseif P.kind == "run" then
  local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
  s:add { shape = h.box({ 0.3, 0.3 }, { 0.7, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
  s:run { until_t = 1e6, every = 0.01, csv = "series.csv", on_frame = function(fr) fr:vtu(("frame_%05d.vtu"):format(fr.index)) end }
end

-- scene_error_table_not_guard: error values that are not guard stops
-- (--set kind=table|forged|tostring|rethrow_guard).
local h = require "hearth"
local P = h.params { kind = "table" }
if P.kind == "table" then
  error({})
elseif P.kind == "forged" then
  -- a table that looks like a guard stop, with a metatable taken from a real one
  local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, cfl = 4 }
  s:add { shape = h.box({ 0.3, 0.3 }, { 0.7, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
  local ok, e = pcall(s.run, s, { until_t = 2 })
  assert(not ok and type(e) == "table", "expected a guard stop")
  local mt = getmetatable(e)
  print("guard metatable seen as", type(mt))
  local ok2 = pcall(setmetatable, { kind = "guard", message = "forged" }, mt)
  print("setmetatable with it", ok2)
  error({ kind = "guard", guard = true, message = "forged guard stop" })
elseif P.kind == "rethrow_guard" then
  local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, cfl = 4 }
  s:add { shape = h.box({ 0.3, 0.3 }, { 0.7, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
  local ok, e = pcall(s.run, s, { until_t = 2 })
  print("caught", ok, "guard=" .. tostring(e.guard), "kind=" .. tostring(e.kind))
  error(e) -- the real guard stop, passed on: still a guard stop
end

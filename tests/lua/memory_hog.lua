-- sandbox_lua_memory: grows a table until the ceiling (--set kind=table|rep).
local h = require "hearth"
local P = h.params { kind = "table" }
if P.kind == "rep" then
  local s = string.rep("x", 1 << 30) -- 1 GiB: over the default 512 MiB ceiling
  print(#s)
else
  local t = {}
  for i = 1, 1e9 do t[i] = ("row %d of a table that grows without end"):format(i) end
end
print("unreachable")

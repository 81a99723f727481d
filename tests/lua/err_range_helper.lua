local h = require "hearth"
-- a scene function between the refusal and the chunk: the traceback names the call that made the bad value
local function soft(nu)
  local m = h.material("elastic", { E = 1e4, nu = nu, density = 1000 })
  return m
end
local m = soft(0.7)

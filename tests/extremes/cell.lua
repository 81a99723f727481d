-- One cell of the stability matrix (tests/extremes/matrix.py): a small 2D block
-- of one plugin's material, one parameter set to `value`, dropped (or thrown at
-- `speed`) onto a floor for a fixed number of steps. Prints one line that the
-- matrix reads:  cell status=ok|guard steps=N max_speed=V nonfinite=K rollbacks=R diag=...
local h = require "hearth"
local P = h.params { plugin = "elastic", param = "none", value = 0, speed = 0, temperature = -999, expansion = 0,
  gas_rate = 0, porosity = -1, saturation = -1, steps = 60, cfl_ = 0.5, guard_ = "stop" }

local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, cfl = P.cfl_, guard = P.guard_ }
local params = {}
if P.param ~= "none" then params[P.param] = P.value end
if P.expansion > 0 then params.expansion = P.expansion end
if P.gas_rate > 0 then params.gas_rate = P.gas_rate end
if P.porosity >= 0 then params.porosity = P.porosity end
if P.saturation >= 0 then -- water that moves, evaporates and pushes back
  params.water_diffusivity, params.evaporation, params.water_stiffness = 1e-8, 1e-4, 1e4
end
local m = h.material(P.plugin, params)
s:add { shape = h.box({ 0.4, 0.15 }, { 0.6, 0.35 }), material = m, ppc = 4, velocity = { 0, -P.speed },
  temperature = P.temperature > -274 and P.temperature or nil, saturation = P.saturation >= 0 and P.saturation or nil }
s:collider { shape = h.plane({ 0, 0.1 }, { 0, 1 }), mode = "separate", friction = 0.3 }

local ok, e = pcall(s.step, s, P.steps)
s:_state().ran = true -- hearth run must not run the scene again after a guard stop
local st = s:stats()
local x, bad = s:positions(), 0
for i = 1, #x do
  if x[i] ~= x[i] or x[i] == math.huge or x[i] == -math.huge then bad = bad + 1 end
end
if not ok and not (type(e) == "table" and e.guard) then error(e, 0) end -- a script error is not a guard stop
print(("cell status=%s steps=%d max_speed=%.6g nonfinite=%d rollbacks=%d diag=%s"):format(ok and "ok" or "guard",
  st.step, st.max_speed, bad, st.rollbacks, ok and "" or tostring(e.message):gsub("\n", " ")))

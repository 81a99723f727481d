-- h.scene against the core's settings schema (hearth_scene_settings): what a
-- Lua scene gets by default is the C default, the drift #16 named (oven beta
-- 0 in C, 10 in Lua) stays resolved, and checks and suggestions come from it.
local h = require "hearth"
local list = h._scene_settings
assert(#list > 40, "the schema reached Lua")

local function same(a, b) return a == b or (a ~= a and b ~= b) end

-- h.scene{} through the core and back (s:settings() reads the C definition)
local got = h.scene {}:settings()
local n = 0
for _, e in ipairs(list) do
  if not e.lua_only then
    local v = got[e.name]
    if e.kind == "vector" then
      for i = 1, 3 do assert(same(v[i], e.vec_default[i]), e.name .. "[" .. i .. "]") end
    elseif e.kind == "box" then
      -- a 2D scene keeps z = 0 (hearth_scene_create does), so x and y only
      for b = 1, 2 do
        for i = 1, 2 do assert(same(v[b][i], e.vec_default[b][i]), ("%s[%d][%d]"):format(e.name, b, i)) end
      end
    else
      assert(same(v, e.default), ("%s: h.scene{} gives %s, the schema's default is %s"):format(e.name, tostring(v),
        tostring(e.default)))
    end
    n = n + 1
  end
end
assert(n > 40, "compared " .. n)
assert(got["oven.temperature"] == nil, "no oven by default")

-- an oven without its beta takes the schema's 10, as Lua scenes always did
local s = h.scene { oven = { temperature = 180 } }
assert(s:settings()["oven.beta"] == 10, "oven.beta default")
assert(select(2, s:oven()) == 10)

-- every setting is a key h.scene takes; sub-table keys under their table
for _, e in ipairs(list) do
  local top, sub = e.name:match("^([^.]+)%.(.+)$")
  local o = {}
  if e.default ~= nil then
    if top then o[top] = { [sub] = e.default } else o[e.name] = e.default end
    if top == "sph" then o.solver = "sph" end
    if top == "oven" then o.oven.temperature = o.oven.temperature or 100 end
    local ok, err = pcall(h.scene, o)
    assert(ok, e.name .. " at its default: " .. tostring(err))
  end
end

-- messages: the setting, the value, the range with its unit; suggestions from the schema's names
local function refused(o, text)
  local ok, err = pcall(h.scene, o)
  assert(not ok and tostring(err):find(text, 1, true), ("expected '%s', got %s"):format(text, tostring(err)))
end
refused({ oven = { temperature = 180, beta = -1 } }, "h.scene: oven.beta = -1; valid range [0, inf) W/(m^2 K)")
refused({ solver = "sph", sph = { gamma = 20 } }, "h.scene: sph.gamma = 20; valid range [1, 15]")
refused({ solver = "sph", sph = { gama = 7 } }, "h.scene: sph: unknown field 'gama'; did you mean 'gamma'?")
refused({ ovn = {} }, "did you mean 'oven'?")
refused({ cfl = 0 }, "h.scene: cfl = 0; valid range (0, 4]")
refused({ dim = 4 }, "h.scene: dim = 4; valid range [2, 3]")
refused({ wall = "grip" }, "h.scene: wall = grip; valid: sticky, slip, separate")
refused({ sph = { gamma = 7 } }, 'needs solver = "sph"')
refused({ oven = { beta = 5 } }, "h.scene: oven.temperature = nil")
refused({ water_momentum = 1 }, "h.scene: water_momentum must be true or false")
-- the oven's radiating walls (fields/thermal.h): optional in the oven's table, checked when given
refused({ oven = { temperature = 180, emissivity = 1.5 } }, "h.scene: oven.emissivity = 1.5; valid range [0, 1]")
refused({ oven = { temperature = 180, wall_temperature = -300 } },
  "h.scene: oven.wall_temperature = -300; valid range [-273.15, 5000] degC")
refused({ oven = { temperature = 180, radiation_scale = 0 } }, "h.scene: oven.radiation_scale = 0; valid range (0,")
refused({ oven = { wall_temperature = 250 } }, "h.scene: oven.temperature = nil")
local w = h.scene { oven = { temperature = 180, beta = 30, wall_temperature = 250, emissivity = 0.9 } }:settings()
assert(w["oven.wall_temperature"] == 250 and w["oven.emissivity"] == 0.9 and w["oven.radiation_scale"] == 1, "walls")
print("settings ok")

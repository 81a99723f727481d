-- hearth: the Lua face of the simulator.
--
-- The C core (hearth.core) does one thing per call; this file checks the
-- tables scenes pass, gives defaults, and adds what is easier in Lua: events,
-- runs with frames, CSV series, scene parameters. Errors point at the line of
-- the scene that made the bad call, name the field and give the valid range.
local core = ...
local h = { version = core.version, library = {} }

for _, k in ipairs { "box", "sphere", "disc", "cylinder", "capsule", "plane", "container", "cup", "mask",
                     "extrude", "union", "intersection", "difference" } do
  h[k] = core[k]
end

h.shapes = require "hearth.shapes"
h.recipes = require "hearth.recipes"

-- ---- checking ------------------------------------------------------------

local function distance(a, b)
  local prev = {}
  for j = 0, #b do prev[j] = j end
  for i = 1, #a do
    local cur = { [0] = i }
    for j = 1, #b do
      local cost = a:sub(i, i) == b:sub(j, j) and 0 or 1
      cur[j] = math.min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + cost)
    end
    prev = cur
  end
  return prev[#b]
end

local function sorted_keys(t)
  local ks = {}
  for k in pairs(t) do ks[#ks + 1] = tostring(k) end
  table.sort(ks)
  return ks
end

local function nearest(word, valid)
  local best, bd = nil, math.huge
  for k in pairs(valid) do
    local d = distance(word, k)
    if d < bd then best, bd = k, d end
  end
  if best and bd <= 1 + #word // 2 then return best end
end

local function check_keys(t, valid, what, level)
  for k in pairs(t) do
    if not valid[k] then
      local near = type(k) == "string" and nearest(k, valid)
      error(("%s: unknown field '%s'%s (valid: %s)"):format(what, tostring(k),
        near and ("; did you mean '" .. near .. "'?") or "", table.concat(sorted_keys(valid), ", ")), level or 3)
    end
  end
end

local function check_number(v, what, lo, hi, unit, level)
  if type(v) ~= "number" or v ~= v or v < lo or v > hi then
    error(("%s = %s; valid range [%s, %s]%s"):format(what, tostring(v), tostring(lo), tostring(hi),
      unit and (" " .. unit) or ""), level or 3)
  end
  return v
end

local function check_choice(v, what, choices, level)
  for i, c in ipairs(choices) do
    if v == c then return i - 1 end
  end
  error(("%s = %s; valid: %s"):format(what, tostring(v), table.concat(choices, ", ")), level or 3)
end

local function check_vec(v, what, level)
  if type(v) ~= "table" or (#v ~= 2 and #v ~= 3) then
    error(("%s: expected a vector like {x, y} or {x, y, z}, got %s"):format(what, type(v)), level or 3)
  end
  for i = 1, #v do
    if type(v[i]) ~= "number" then error(("%s[%d]: expected a number"):format(what, i), level or 3) end
  end
  return { v[1], v[2], v[3] or 0 }
end

local function is_shape(v) return type(v) == "userdata" and tostring(v):sub(1, 12) == "hearth.shape" end

-- The scene's and solvers' settings: the core's one schema (core/sim/settings.c,
-- hearth_scene_settings), read here at run time. h.scene's keys, checks,
-- defaults and suggestions and --set's knobs all come from it.
local scene_settings = core.scene_settings()
local scene_setting = {}
for _, e in ipairs(scene_settings) do scene_setting[e.name] = e end
h._scene_settings = scene_settings

--- Scene settings `--set` may override when the scene's h.params does not
--- declare the name itself (so `hearth trade --knob dx=...` works on any scene):
--- the h.scene settings the schema marks as knobs, and ppc (every s:add).
local scene_knobs = { ppc = true }
for _, e in ipairs(scene_settings) do
  if e.knob then scene_knobs[e.name] = true end
end
h._scene_knobs = scene_knobs

-- The --set values meant for scene settings (not declared by h.params), as strings.
local function knob_sets()
  local k = {}
  for name, v in pairs(core.options().sets) do
    if scene_knobs[name] and not (h._param_names and h._param_names[name]) then k[name] = v end
  end
  return k
end

-- A bad --set is a usage error (exit 2), not a scene error: the object
-- core.usage_error raises is marked so `hearth run` can tell.
local usage_error = core.usage_error

local function knob_number(name, v, level)
  return tonumber(v) or usage_error(("--set %s=%s: expected a number"):format(name, v), level or 3)
end

h._check = { keys = check_keys, number = check_number, choice = check_choice, vec = check_vec }

-- ---- curves and materials -------------------------------------------------

-- A mixed parameter table remembers its constituents in its metatable (so
-- pairs() still sees only parameters): a scene whose blend mode is "linear"
-- or "labels" rebuilds the material from them (see material_id).
local mix_mt = { __name = "hearth.mix" }
local blend_modes = scene_setting.blend.words

local function mix_info(t)
  local mt = type(t) == "table" and getmetatable(t)
  return type(mt) == "table" and mt.__name == mix_mt.__name and mt.mix or nil
end

local curve_mt = { __name = "hearth.curve" }
local material_mt = { __name = "hearth.material" }

--- A piecewise-linear function of temperature: h.curve{{T1, v1}, {T2, v2}, ..., irreversible = true}.
--- With of = "moisture" the points are {X/X0, factor}: a factor over the moisture ratio (the water a
--- particle holds over the water it was given) that multiplies a parameter, written as a product:
---   E = 2e4 * h.curve{{0.1, 30}, {0.5, 1}, of = "moisture", irreversible = true}
---   tau_y = h.curve{{20, 100}, {70, 2000}} * h.curve{{0.1, 30}, {0.5, 1}, of = "moisture"}
function h.curve(t)
  if type(t) ~= "table" or #t < 1 then error("h.curve: expected a table of {T, value} points", 2) end
  check_keys(t, setmetatable({ irreversible = true, of = true }, { __index = function(_, k) return math.type(k) == "integer" end }),
    "h.curve")
  check_choice(t.of or "temperature", "h.curve: of", { "temperature", "moisture" })
  local moist = t.of == "moisture"
  local what = moist and "{moisture ratio, factor}" or "{temperature, value}"
  local c = { irreversible = t.irreversible and true or false, moisture = moist }
  for i, p in ipairs(t) do
    if type(p) ~= "table" or type(p[1]) ~= "number" or type(p[2]) ~= "number" then
      error(("h.curve: point %d must be %s"):format(i, what), 2)
    end
    if i > 1 and not (p[1] > t[i - 1][1]) then
      error(("h.curve: %s must increase (point %d: %g after %g)"):format(moist and "moisture ratios" or "temperatures",
        i, p[1], t[i - 1][1]), 2)
    end
    c[i] = { p[1], p[2] }
  end
  return setmetatable(c, curve_mt)
end

-- A parameter made of a base (a number or a temperature curve) times a moisture curve's factor;
-- p.base and p.factor read them, and a curve base's points read through (p[1], p.irreversible).
local product_mt = { __name = "hearth.curve_product" }
product_mt.__index = function(p, k) local b = rawget(p, "base"); if type(b) == "table" then return b[k] end end
curve_mt.__mul = function(a, b)
  if getmetatable(a) == curve_mt and a.moisture then a, b = b, a end
  if not (getmetatable(b) == curve_mt and b.moisture) then
    error("h.curve: a product needs one moisture curve (h.curve{..., of = \"moisture\"})", 2)
  end
  if not (type(a) == "number" or (getmetatable(a) == curve_mt and not a.moisture)) then
    error("h.curve: a moisture curve multiplies a number or a temperature curve", 2)
  end
  return setmetatable({ base = a, factor = b }, product_mt)
end

--- A material from a plugin, its parameters checked against the plugin's schema now.
function h.material(plugin, params)
  if type(plugin) ~= "string" then error("h.material: the first argument is the plugin name, e.g. \"elastic\"", 2) end
  params = params or {}
  local plain, curves, factors = {}, {}, {}
  for k, v in pairs(params) do
    if type(k) ~= "string" then error("h.material: parameter names must be strings", 2) end
    if getmetatable(v) == product_mt then v, factors[k] = v.base, v.factor end
    if type(v) == "number" then plain[k] = v
    elseif getmetatable(v) == curve_mt and v.moisture then
      error(("h.material: parameter '%s': a moisture curve is a factor; write %s = <value> * h.curve{..., of = \"moisture\"}")
        :format(k, k), 2)
    elseif getmetatable(v) == curve_mt then curves[k] = v
    else error(("h.material: parameter '%s' must be a number or h.curve{...}, got %s"):format(k, type(v)), 2) end
  end
  local ok, e = pcall(core.material_check, plugin, plain)
  if not ok then error(e, 2) end
  for k, c in pairs(curves) do
    for i, p in ipairs(c) do
      local t = {}
      for kk, vv in pairs(plain) do t[kk] = vv end
      t[k] = p[2]
      ok, e = pcall(core.material_check, plugin, t)
      if not ok then error(("%s (curve point %d, at %g degC)"):format(e, i, p[1]), 2) end
    end
  end
  -- a moisture factor's products are checked against the range when the scene registers it (the core's check)
  return setmetatable({ plugin = plugin, params = plain, curves = curves, factors = factors, mix = mix_info(params) },
    material_mt)
end

--- Write a text file (a CSV, a note) atomically; relative paths go under the output folder.
--- h.colormap(name, t) -> r, g, b: the colour pictures give t (0..1) in a colour map
h.colormap = core.colormap

function h.write(path, text)
  if type(path) ~= "string" or type(text) ~= "string" then error("h.write(path, text): two strings", 2) end
  local ok, e = pcall(core.write_atomic, path, text, "h.write")
  if not ok then error(e, 2) end
  return e
end

--- The leading coefficient a of the least-squares parabola y = a u^2 + b u + c
--- through points {{u, y}, ...} (normal equations, Cramer's rule); NaN with
--- fewer than 3 points. The baking scenes measure a top's curvature as 2a.
function h.parabola(points)
  local m = { 0, 0, 0, 0, 0, 0, 0, 0 } -- sums of 1, u, u^2, u^3, u^4, y, yu, yu^2
  for _, p in ipairs(points) do
    local u, y = p[1], p[2]
    m[1], m[2], m[3], m[4], m[5] = m[1] + 1, m[2] + u, m[3] + u * u, m[4] + u ^ 3, m[5] + u ^ 4
    m[6], m[7], m[8] = m[6] + y, m[7] + y * u, m[8] + y * u * u
  end
  if m[1] < 3 then return 0 / 0 end
  local function det(a, b, c) -- columns a, b, c of a 3x3 matrix
    return a[1] * (b[2] * c[3] - b[3] * c[2]) - b[1] * (a[2] * c[3] - a[3] * c[2]) + c[1] * (a[2] * b[3] - a[3] * b[2])
  end
  local c1, c2, c3, r = { m[1], m[2], m[3] }, { m[2], m[3], m[4] }, { m[3], m[4], m[5] }, { m[6], m[7], m[8] }
  return det(c1, c2, r) / det(c1, c2, c3)
end

-- ---- material library ---------------------------------------------------

-- h.library.sauce.<name>: the 21 sauces of Nagasawa et al. Table 1 as
-- parameter tables for the von_mises_sauce plugin (kappa 1e6 Pa and mu 1e5 Pa,
-- as the paper assumed in §4.6). Read from assets/sauces.csv on first use.
local function load_sauces()
  local dir = core.options().assets_dir or "assets"
  local f, e = io.open(dir .. "/sauces.csv", "r")
  if not f then error("h.library.sauce: cannot read " .. dir .. "/sauces.csv (" .. tostring(e) .. ")", 3) end
  local lib, header = {}, nil
  for line in f:lines() do
    if not line:match("^%s*#") and line:match("%S") then
      local cells = {}
      for c in (line .. ","):gmatch("([^,]*),") do cells[#cells + 1] = c:match("^%s*(.-)%s*$") end
      if not header then
        header = {}
        for i, c in ipairs(cells) do header[c] = i end
      else
        lib[cells[header.name]] = { kappa = 1e6, mu = 1e5, h = tonumber(cells[header.h]),
          eta = tonumber(cells[header.eta]), sigma_y = tonumber(cells[header.sigma_y]),
          label = cells[header.label] }
      end
    end
  end
  f:close()
  return lib
end

local sauce_mt = {}
sauce_mt.__index = function(t, name)
  local lib = rawget(t, "_all")
  if not lib then
    lib = load_sauces()
    rawset(t, "_all", lib)
  end
  local s = lib[name]
  if not s then
    error(("h.library.sauce: no sauce '%s'%s (valid: %s)"):format(tostring(name),
      nearest(tostring(name), lib) and ("; did you mean '" .. nearest(tostring(name), lib) .. "'?") or "",
      table.concat(sorted_keys(lib), ", ")), 2)
  end
  local copy = {} -- a fresh table each time, so a scene may change its copy
  for k, v in pairs(s) do if k ~= "label" then copy[k] = v end end
  return copy
end
h.library.sauce = setmetatable({}, sauce_mt)

-- h.library.sph.<name>: Rodriguez-Arenas 2011 presets (Table 4.1 as bread_roll); see sph_library.lua.
h.library.sph = (require "hearth.sph_library")(h)

--- h.mix{ {params_a, 0.5}, {params_b, 0.5}, plugin = "von_mises_sauce" }: one parameter set
--- blended by the plugin's own blend rule (Nagasawa et al. eq. 28-31 for sauces).
--- The scene's `blend` key decides how a body made of it is simulated: that blend
--- ("nonlinear"), the weighted mean of every parameter ("linear", core.blend(..., "linear")),
--- or one material per constituent drawn per particle with the ratios ("labels", through
--- hearth_scene_body_labels). With h.scene{mixing = "dynamic"} the h.mix bodies instead
--- share one mixture material (hearth_scene_add_mixture, mixing.c): each particle keeps
--- its initial ratios as a label, takes dynamic ratios from its neighbours through the
--- grid every step (Nagasawa et al. eq. 43-44), and its parameters are the plugin's
--- blend at them.
function h.mix(t)
  if type(t) ~= "table" or #t < 1 then error("h.mix: expected { {params, ratio}, ... }", 2) end
  check_keys(t, setmetatable({ plugin = true }, { __index = function(_, k) return math.type(k) == "integer" end }),
    "h.mix")
  local plugin = t.plugin or "von_mises_sauce"
  local mode = t.blend or knob_sets().blend or "nonlinear"
  check_choice(mode, "h.mix: blend", { "nonlinear", "linear" })
  if mode == "linear" then -- the naive rule the plugin's blend improves on: weighted means of the parameters
    local out = {}
    for i, c in ipairs(t) do
      if type(c) ~= "table" or type(c[1]) ~= "table" or type(c[2]) ~= "number" then
        error(("h.mix: entry %d must be {params, ratio}"):format(i), 2)
      end
      for k, v in pairs(c[1]) do out[k] = (out[k] or 0) + c[2] * v end
    end
    return out
  end
  local sets, weights = {}, {}
  for i, c in ipairs(t) do
    if type(c) ~= "table" or type(c[1]) ~= "table" or type(c[2]) ~= "number" then
      error(("h.mix: entry %d must be {params, ratio}"):format(i), 2)
    end
    sets[i], weights[i] = c[1], c[2]
  end
  local ok, r = pcall(core.blend, plugin, sets, weights)
  if not ok then error(r, 2) end
  return setmetatable(r, { __name = mix_mt.__name, mix = { plugin = plugin, sets = sets, weights = weights } })
end



--- h.blend(mix, mode): the parameters a scene with blend = mode simulates a mixture with:
--- "nonlinear" (the model) or "linear" (the weighted mean of every parameter).
function h.blend(m, mode)
  local mix = mix_info(m)
  if not mix then error("h.blend: expected a table made by h.mix{...}", 2) end
  check_choice(mode or "nonlinear", "h.blend: mode", { "nonlinear", "linear" })
  local ok, r = pcall(core.blend, mix.plugin, mix.sets, mix.weights, mode or "nonlinear")
  if not ok then error(r, 2) end
  return r
end

-- h.library.paper.<name>: the baked goods of Ding et al. Table 2 with Fig. 8's
-- temperature curves, in the paper's animation units, as parameters for the
-- cam_clay_dough plugin; h.library.paper_oven.<name>: their oven, pan and
-- dough temperatures. The unit and scale choices are documented in
-- lua/hearth/dough.lua.
-- h.library.dough.<name>: doughs in physical units (measured density, heat
-- capacity, conductivity, water), each number's source in
-- lua/hearth/dough_physical.lua; h.library.oven.<name>: their oven, with the
-- latent heat and boiling on and the time scale S the preset runs at.
local dough_data, physical_data = require "hearth.dough", require "hearth.dough_physical"
local function dough_lookup(what, data, pick)
  return setmetatable({}, { __index = function(_, name)
    if not data.preset(name) then
      local valid = data.paper and data.paper or data.goods
      local near = nearest(tostring(name), valid)
      error(("h.library.%s: no preset '%s'%s (valid: %s)"):format(what, tostring(name),
        near and ("; did you mean '" .. near .. "'?") or "", table.concat(sorted_keys(valid), ", ")), 2)
    end
    return pick(data.preset(name)) -- a fresh table each time, so a scene may change its copy
  end })
end
local function with_curves(params, curves, _, dry)
  for k, pts in pairs(curves) do params[k] = h.curve(pts) end
  -- a dried crust stiffens (dough.lua's DRY): factors over the moisture ratio on E and tau_y
  for k, pts in pairs(dry or {}) do params[k] = (params[k] or error("dough: no base for " .. k)) * h.curve(pts) end
  return params
end
local function oven_of(_, _, oven) return oven end
h.library.paper = dough_lookup("paper", dough_data, with_curves)
h.library.paper_oven = dough_lookup("paper_oven", dough_data, oven_of)
h.library.dough = dough_lookup("dough", physical_data, with_curves)
h.library.oven = dough_lookup("oven", physical_data, oven_of)
-- what Table 2's eta and alpha^g are multiplied by in h.library.paper (a scene converting its own Table 2 numbers)
h.library.dough_scale = { eta = dough_data.ETA_SCALE, gas = dough_data.GAS_SCALE }

-- ---- scene parameters -----------------------------------------------------

--- Named defaults that `hearth run scene.lua --set name=value` overrides.
--- A default that is a list of numbers takes `--set name=1,2.5,3`.
function h.params(defaults)
  if type(defaults) ~= "table" then error("h.params: expected a table of name = default", 2) end
  local P = {}
  h._param_names = {}
  for k, v in pairs(defaults) do P[k], h._param_names[k] = v, true end
  for k, v in pairs(core.options().sets) do
    local d = defaults[k]
    if d == nil and scene_knobs[k] then -- a scene setting, applied by h.scene / s:add / h.mix
    elseif d == nil then
      local near = nearest(k, defaults)
      usage_error(("--set %s: this scene has no parameter '%s'%s; valid names: %s"):format(k, k,
        near and ("; did you mean '" .. near .. "'?") or "", table.concat(sorted_keys(defaults), ", ")), 2)
    end
    if type(d) == "number" then
      P[k] = tonumber(v) or usage_error(("--set %s=%s: expected a number"):format(k, v), 2)
    elseif type(d) == "table" then
      local t = {}
      for w in (v .. ","):gmatch("([^,]*),") do
        t[#t + 1] = tonumber(w) or usage_error(("--set %s=%s: expected numbers separated by commas"):format(k, v), 2)
      end
      P[k] = t
    elseif type(d) == "boolean" then
      if v ~= "true" and v ~= "false" then usage_error(("--set %s=%s: expected true or false"):format(k, v), 2) end
      P[k] = v == "true"
    else
      P[k] = v
    end
  end
  h._params_declared = true
  return P
end

-- ---- scenes -----------------------------------------------------------------

local S = core.scene_methods
-- h.scene's keys: a setting "oven.beta" is the key beta of the sub-table oven
local scene_keys, scene_subkeys = {}, {}
for _, e in ipairs(scene_settings) do
  local top, sub = e.name:match("^([^.]+)%.(.+)$")
  if top then
    scene_keys[top] = true
    scene_subkeys[top] = scene_subkeys[top] or {}
    scene_subkeys[top][sub] = true
  else
    scene_keys[e.name] = true
  end
end
local contact = { "sticky", "slip", "separate", "grip" }

-- a number as a person writes it: 4, not 4.0; inf for no bound
local function num_text(x)
  if x == math.huge then return "inf" end
  if x == math.floor(x) and math.abs(x) < 2 ^ 53 then return ("%d"):format(x) end
  return ("%.14g"):format(x)
end

local function range_text(e)
  local unit = (e.unit ~= "" and e.unit ~= "1") and (" " .. e.unit) or ""
  return ("%s%s, %s%s%s"):format(e.min_open and "(" or "[", num_text(e.min), num_text(e.max),
    e.max == math.huge and ")" or "]", unit)
end

-- Setting e's value v from h.scene's table, checked against the schema;
-- returns what core.scene_new takes (a number, a word's index, a boolean, a
-- vector, {lo=, hi=} for the box). Errors point at the scene's line.
local function check_setting(e, v)
  local what = "h.scene: " .. e.name
  if e.kind == "real" or e.kind == "int" or e.kind == "seed" then
    local bad = type(v) ~= "number" or v ~= v or v == math.huge or v == -math.huge
      or (e.min_open and not (v > e.min) or v < e.min) or v > e.max
      or (e.kind ~= "real" and v ~= math.floor(v))
    if bad then
      error(("%s = %s; valid range %s%s (%s)"):format(what, tostring(v), range_text(e),
        e.kind ~= "real" and ", whole numbers" or "", e.help), 3)
    end
    return v
  elseif e.kind == "flag" then
    if type(v) ~= "boolean" then error(("%s must be true or false, got %s (%s)"):format(what, type(v), e.help), 3) end
    return v
  elseif e.kind == "choice" then
    return check_choice(type(v) == "string" and v:lower() or v, what, e.words, 4)
  elseif e.kind == "vector" then
    return check_vec(v, what, 4)
  elseif e.kind == "box" then
    if type(v) ~= "table" or #v ~= 2 then error(what .. " = {{lo}, {hi}}", 3) end
    return { lo = check_vec(v[1], what .. "[1]", 4), hi = check_vec(v[2], what .. "[2]", 4) }
  end
  return v
end

--- A scene: h.scene{dim = 2, dx = 0.01, box = {{0,0},{1,1}}, gravity = {0,-9.81}, ...}
--- (`hearth help scene` lists every setting; docs/lua.md too)
function h.scene(o)
  o = o or {}
  if type(o) ~= "table" then error("h.scene: expected a table", 2) end
  for k in pairs(core.options().sets) do
    if not h._params_declared and not scene_knobs[k] then
      usage_error(("--set %s: this scene declares no parameters with h.params{...} before h.scene; scene settings that --set may change: %s")
        :format(k, table.concat(sorted_keys(scene_knobs), ", ")), 2)
    end
  end
  check_keys(o, scene_keys, "h.scene")
  for top, keys in pairs(scene_subkeys) do
    if o[top] ~= nil then
      if type(o[top]) ~= "table" then
        error(("h.scene: %s = {%s = ..., ...}"):format(top, table.concat(sorted_keys(keys), " = ..., ")), 2)
      end
      check_keys(o[top], keys, "h.scene: " .. top)
    end
  end
  local ks = knob_sets()
  if next(ks) then -- --set dx=... and friends replace what the scene file says
    local oo = {}
    for k, v in pairs(o) do oo[k] = v end
    for _, e in ipairs(scene_settings) do
      local v = ks[e.name]
      if v and not e.lua_only then -- blend is h.mix's
        if e.kind == "choice" then
          local ok = false
          for _, c in ipairs(e.words) do ok = ok or v:lower() == c end
          if not ok then usage_error(("--set %s=%s: valid: %s"):format(e.name, v, table.concat(e.words, ", ")), 2) end
          oo[e.name] = v
        else
          oo[e.name] = knob_number(e.name, v)
        end
      end
    end
    if oo.dim == 3 and oo.box and not ((oo.box[2][3] or 0) > (oo.box[1][3] or 0)) then
      usage_error("--set dim=3: this scene's box has no z extent, so it cannot run in 3D", 2)
    end
    o = oo
  end
  -- every setting, in the schema's order: the given value checked, or the default
  local def, lua_side = {}, {}
  for _, e in ipairs(scene_settings) do
    local top, sub = e.name:match("^([^.]+)%.(.+)$")
    local v
    if top then v = o[top] and o[top][sub] else v = o[e.name] end
    -- (oven = {saturation = ...} alone is humid air for evaporation, without heat)
    if v == nil and e.nan_ok and top and o[top] ~= nil and not (top == "oven" and o.oven.saturation ~= nil) then
      -- a sub-table's unset-able setting is its reason to be there (oven = {...} needs its temperature)
      error(("h.scene: %s = nil; valid range %s (%s)"):format(e.name, range_text(e), e.help), 2)
    end
    if v ~= nil then
      v = check_setting(e, v)
      if e.lua_only then lua_side[e.name] = v else def[e.name] = v end
    elseif e.lua_only then
      lua_side[e.name] = e.kind == "choice" and check_choice(e.default, e.name, e.words) or e.default
    end
  end
  -- the sph.* settings belong to the SPH solver (its word in the schema, not a number here)
  if o.sph ~= nil and def.solver ~= check_choice("sph", "solver", scene_setting.solver.words) then
    error("h.scene: sph = {...} needs solver = \"sph\"", 2)
  end
  local dim = def.dim or scene_setting.dim.default
  local ok, s = pcall(core.scene_new, def)
  if not ok then error(s, 2) end
  local st = s:_state()
  st.events, st.mats, st.name, st.frame, st.dim = {}, {}, lua_side.name, 0, dim
  -- how bodies made of h.mix{...} materials are simulated (Nagasawa et al. Figs. 1, 9, 10):
  -- "nonlinear" the blend model, "linear" linearly blended parameters, "labels" random binary labels
  st.blend = blend_modes[lua_side.blend + 1]
  -- mixing = "dynamic": h.mix bodies share one mixture whose ratios follow the particles (Nagasawa et al. eq. 43-44)
  st.mixing = scene_setting.mixing.words[lua_side.mixing + 1]
  if st.mixing == "dynamic" and st.blend ~= "nonlinear" then
    error(('h.scene: mixing = "dynamic" blends through the model; it needs blend = "nonlinear" (got "%s")'):format(st.blend), 2)
  end
  st.seed = def.seed or scene_setting.seed.default
  h._last_scene = s
  return s
end

-- A scene made outside Lua (a checkpoint, the dashboard's built-in demo) becomes the current scene.
function h._adopt(s)
  local st = s:_state()
  st.events, st.mats, st.frame = {}, {}, 0
  h._last_scene = s
  return s
end

h.load = function(path)
  local ok, s = pcall(core.load, path)
  if not ok then error(s, 2) end
  return h._adopt(s)
end

-- A host that draws between steps (the dashboard) runs scene code in a
-- coroutine; s:run and s:step hand control back after every step there.
local host_yields -- the options do not change once the module is open
local function host_yield()
  if host_yields == nil then host_yields = core.options().yield and true or false end
  if host_yields and coroutine.isyieldable() then coroutine.yield("step") end
end

local function register(s, m, params)
  local id = s:_material(m.plugin, params)
  for _, set in ipairs { m.curves, m.factors or {} } do
    for k, c in pairs(set) do
      local T, V = {}, {}
      for i, p in ipairs(c) do T[i], V[i] = p[1], p[2] end
      s:_curve(id, k, T, V, c.irreversible, c.moisture)
    end
  end
  return id
end

-- The material id of m in scene s; for a mixture under blend = "labels", a
-- list of one id per constituent and the list of ratios.
local function material_id(s, m)
  if getmetatable(m) ~= material_mt then error("material: expected h.material(...)", 3) end
  local st = s:_state()
  local id = st.mats[m]
  if id then return id, st.mats[id] end
  local mix = m.mix
  if mix and st.mixing == "dynamic" then
    -- one mixture for the scene, its constituents those of the first h.mix; a body's
    -- ratios are its own mix's weights, matched to those constituents by their parameters
    local function same(a, b)
      for k, v in pairs(a) do if b[k] ~= v then return false end end
      for k, v in pairs(b) do if a[k] ~= v then return false end end
      return true
    end
    if not st.dynamic then
      st.dynamic = { plugin = mix.plugin, sets = mix.sets, id = s:_mixture(mix.plugin, mix.sets) }
    end
    local dm, ratios = st.dynamic, {}
    if mix.plugin ~= dm.plugin then error("h.mix: a dynamic mixture is of one plugin (" .. dm.plugin .. ")", 3) end
    for j = 1, #dm.sets do ratios[j] = 0 end
    for i, set in ipairs(mix.sets) do
      local found
      for j, d in ipairs(dm.sets) do if same(set, d) then found = j break end end
      if not found then
        error(("h.mix: constituent %d is not in the scene's dynamic mixture; its first h.mix names every constituent "
          .. "(give the others ratio 0)"):format(i), 3)
      end
      ratios[found] = ratios[found] + mix.weights[i]
    end
    return dm.id, nil, ratios
  end
  if not mix or st.blend == "nonlinear" then
    id = register(s, m, m.params)
    st.mats[m] = id
    return id
  end
  -- parameters the scene changed after mixing (say the moduli or a density) win over the blend
  local blended = core.blend(mix.plugin, mix.sets, mix.weights)
  local function with_changes(p)
    for k, v in pairs(m.params) do
      if blended[k] ~= v then p[k] = v end
    end
    return p
  end
  if st.blend == "linear" then
    id = register(s, m, with_changes(core.blend(mix.plugin, mix.sets, mix.weights, "linear")))
  else -- labels: one material per constituent
    local ids, ratios = {}, {}
    for i, set in ipairs(mix.sets) do
      ids[i], ratios[i] = register(s, m, with_changes(core.blend(mix.plugin, { set }, { 1 }))), mix.weights[i]
    end
    id = ids
    st.mats[ids] = ratios
  end
  st.mats[m] = id
  return id, st.mats[id]
end

--- s:add{shape = ..., material = ..., ppc = 4, velocity = {0,0}, jitter = 0.5, temperature = 20, saturation = 0.5,
---   fixed_temperature = false} -> body id (fixed_temperature: the body keeps its temperature, a Dirichlet boundary)
--- A fixed body (fixed = true) under SPH is a wall; velocity = {..} or function(t), omega = ... and
--- pivot = {..} (spelt as s:collider's) make it move rigidly: a lid, a paddle, a piston.
function S:add(o)
  if type(o) ~= "table" then error("s:add: expected a table", 2) end
  check_keys(o, { shape = true, material = true, ppc = true, velocity = true, jitter = true, temperature = true,
    name = true, fixed = true, saturation = true, omega = true, pivot = true, fixed_temperature = true }, "s:add")
  local mv, mw, mp, start_v = nil, o.omega, nil, o.velocity
  if o.fixed and (o.velocity ~= nil or o.omega ~= nil or o.pivot ~= nil) then -- a moving wall
    mv = o.velocity
    if mv ~= nil and type(mv) ~= "function" then mv = check_vec(mv, "s:add: velocity") end
    if mw ~= nil and type(mw) ~= "function" and type(mw) ~= "number" then mw = check_vec(mw, "s:add: omega") end
    mp = o.pivot and check_vec(o.pivot, "s:add: pivot") or nil
    start_v = nil -- the particles take the motion's velocity each step
  elseif o.omega ~= nil or o.pivot ~= nil then
    error("s:add: omega and pivot move a fixed body (fixed = true, SPH walls); a free body takes velocity only", 2)
  end
  if not is_shape(o.shape) then error("s:add: shape = h.box(...), h.disc(...), ... is required", 2) end
  if o.material == nil then error("s:add: material = h.material(...) is required", 2) end
  local mat = o.material
  local mix = mix_info(mat)
  if mix then -- a bare h.mix{...} table: the mixture's plugin with those parameters, one material per table
    local st = self:_state()
    st.mix_materials = st.mix_materials or setmetatable({}, { __mode = "k" })
    local mm = st.mix_materials[mat]
    if not mm then
      local okm
      okm, mm = pcall(h.material, mix.plugin, mat)
      if not okm then error(mm, 2) end
      st.mix_materials[mat] = mm
    end
    mat = mm
  end
  local ok, id, ratios, mix_ratios = pcall(material_id, self, mat)
  if not ok then error(id, 2) end
  local kppc = knob_sets().ppc
  local ppc = check_number(kppc and knob_number("ppc", kppc) or o.ppc or 4, "s:add: ppc", 1, 1000, "particles per cell")
  local jitter = check_number(o.jitter or 0.5, "s:add: jitter", 0, 1)
  local vel = check_vec(start_v or { 0, 0, 0 }, "s:add: velocity")
  if o.temperature ~= nil then check_number(o.temperature, "s:add: temperature", -273.15, 5000, "degC") end
  if o.saturation ~= nil then check_number(o.saturation, "s:add: saturation", 0, 1) end
  if o.fixed_temperature and o.temperature == nil then
    error("s:add: fixed_temperature = true needs temperature = ... (degC), the temperature the body keeps", 2)
  end
  local ok2, body = pcall(self._add, self, o.shape, type(id) == "table" and id[1] or id, math.floor(ppc), jitter, vel,
    o.temperature, o.fixed, o.saturation, mix_ratios, o.fixed_temperature and true or false)
  if not ok2 then error(body, 2) end
  if mv ~= nil or mw ~= nil or mp ~= nil then
    local okm, em = pcall(self._body_motion, self, body, mv, mw, mp)
    if not okm then error(em, 2) end
  end
  if type(id) == "table" then -- blend = "labels": each particle one constituent, drawn with its ratio
    local st = self:_state()
    local ok3, counts = pcall(self._labels, self, body, id, ratios, st.seed * 7919 + body)
    if not ok3 then error(counts, 2) end
    st.label_counts = st.label_counts or {}
    st.label_counts[body] = counts
  end
  return body
end

--- s:collider{shape = ..., mode = "separate", friction = 0, velocity = {..} or function(t), omega = ..., pivot = {..},
---   temperature = degC, beta = W/(m^2 K) or fixed_temperature = true, saturation = 0..1, beta_water = kg/(m^2 s)}
--- fixed_temperature = true (or beta = math.huge) holds the touching material at temperature (Dirichlet).
function S:collider(o)
  if type(o) ~= "table" then error("s:collider: expected a table", 2) end
  check_keys(o, { shape = true, mode = true, friction = true, velocity = true, omega = true, pivot = true, name = true,
    temperature = true, beta = true, saturation = true, fixed_temperature = true, beta_water = true }, "s:collider")
  if o.saturation ~= nil then check_number(o.saturation, "s:collider: saturation", 0, 1) end
  if o.beta_water ~= nil then
    check_number(o.beta_water, "s:collider: beta_water", 0, 1e9, "kg/(m^2 s)")
    if o.saturation == nil then
      error("s:collider: beta_water needs saturation = ... (the saturation it exchanges water toward, 0..1)", 2)
    end
  end
  if o.temperature ~= nil then check_number(o.temperature, "s:collider: temperature", -273.15, 5000, "degC") end
  if o.beta ~= nil and o.beta ~= math.huge then check_number(o.beta, "s:collider: beta", 0, 1e9, "W/(m^2 K)") end
  if o.fixed_temperature and o.temperature == nil then
    error("s:collider: fixed_temperature = true needs temperature = ... (degC), the temperature it holds", 2)
  end
  if o.fixed_temperature and o.beta ~= nil and o.beta ~= math.huge then
    error("s:collider: fixed_temperature = true holds the temperature; a finite beta contradicts it (leave beta out)", 2)
  end
  if not is_shape(o.shape) then error("s:collider: shape = h.plane(...), h.box(...), ... is required", 2) end
  local mode = check_choice(o.mode or "separate", "s:collider: mode", contact)
  local fr = check_number(o.friction or 0, "s:collider: friction", 0, 1e6)
  local v = o.velocity
  if v ~= nil and type(v) ~= "function" then v = check_vec(v, "s:collider: velocity") end
  local w = o.omega
  if w ~= nil and type(w) ~= "function" and type(w) ~= "number" then w = check_vec(w, "s:collider: omega") end
  local p = o.pivot and check_vec(o.pivot, "s:collider: pivot") or nil
  local ok, id = pcall(self._collider, self, o.shape, mode, fr, v, w, p, o.temperature,
    o.temperature and (o.fixed_temperature and math.huge or o.beta or 100) or 0, o.saturation, o.beta_water)
  if not ok then error(id, 2) end
  return id
end

--- s:at(t, fn): call fn(s) once sim time reaches t (runs stop exactly there).
function S:at(t, fn)
  check_number(t, "s:at: time", 0, math.huge, "s")
  if type(fn) ~= "function" then error("s:at: the second argument must be a function(s)", 2) end
  local ev = self:_state().events
  local i = #ev + 1
  while i > 1 and ev[i - 1].t > t do i = i - 1 end
  table.insert(ev, i, { t = t, fn = fn })
end

local function fire_events(s)
  local ev, now = s:_state().events, s:_time() -- not s:stats(): it sums over every particle, and this runs every step
  while ev[1] and ev[1].t <= now + 1e-12 * math.max(1, now) do
    table.remove(ev, 1).fn(s)
  end
end

--- s:step(n): n steps (events fire when their time has passed).
function S:step(n)
  n = n or 1
  check_number(n, "s:step: n", 0, 1e9)
  for _ = 1, n do
    fire_events(self)
    host_yield()
    self:_step(1)
  end
  fire_events(self)
  self:_state().ran = true -- hearth run does not run a stepped scene again
  return self
end

--- s:gravity({gx, gy[, gz]}) sets gravity (m/s^2) from now on (at an event, say);
--- s:gravity(function(t) return {gx, gy[, gz]} end) makes it a function of time,
--- evaluated at the start of every step (a ramp, a tilt, a shaker).
function S:gravity(g)
  if type(g) ~= "function" then g = check_vec(g, "s:gravity") end
  self:_gravity(g)
  return self
end

--- s:body_force(function(x, y, z, t) return fx, fy[, fz] end) adds an acceleration field
--- (m/s^2) that varies in space and time to gravity: MPM evaluates it at every grid node with
--- mass, every step (SPH at every particle), on one thread. s:body_force(nil) removes it.
function S:body_force(fn)
  if fn ~= nil and type(fn) ~= "function" then
    error(("s:body_force: expected a function(x, y, z, t) returning fx, fy[, fz], or nil; got %s"):format(type(fn)), 2)
  end
  self:_body_force(fn)
  return self
end

--- s:particles{fields = {"id", "x", "v", "temperature", ...}} -> {n = count, id = {...}, x = {...}, ...}:
--- every particle's values, in one order for all the fields asked for. Scalars are n numbers;
--- vectors are flattened, 3 numbers a particle ({x1, y1, z1, x2, ...}, as s:positions());
--- "stress" 9 a particle (row-major xx xy xz yx yy yz zx zy zz). "x" is the position, "v"
--- the velocity, "id" the particle's id: the order changes from step to step (the step
--- sorts particles) but an id stays with its particle, so a marked particle is found again
--- by its id.
local particle_aliases = { x = true, v = "velocity", id = true }
function S:particles(o)
  if type(o) ~= "table" then error("s:particles: expected a table {fields = {...}}", 2) end
  check_keys(o, { fields = true }, "s:particles")
  if type(o.fields) ~= "table" or #o.fields == 0 then
    error("s:particles: fields = {\"x\", \"v\", ...} (a list of field names) is required", 2)
  end
  local valid, live = { x = true, v = true, id = true }, self:stats().fields
  for _, f in ipairs(live) do
    valid[f] = true
    if f == "velocity" then valid.velocity_x, valid.velocity_y, valid.velocity_z = true, true, true end
    if f == "stress" then
      for _, c in ipairs { "xx", "yy", "zz", "xy", "xz", "yz" } do valid["stress_" .. c] = true end
    end
  end
  local r = { n = self:stats().particles }
  for k, f in ipairs(o.fields) do
    if type(f) ~= "string" then error(("s:particles: fields[%d] is a %s, not a field name"):format(k, type(f)), 2) end
    if not valid[f] then
      -- a known field that is not live says how to turn it on; anything else is a misspelling
      local ok, e = pcall(self._particle_field, self, f)
      if not ok and tostring(e):find("is not live", 1, true) then error("s:particles: " .. tostring(e), 2) end
      local near = nearest(f, valid)
      error(("s:particles: unknown field '%s'%s (live fields: id, x, v, %s)"):format(f,
        near and ("; did you mean '" .. near .. "'?") or "", table.concat(live, ", ")), 2)
    end
    if f == "x" then r.x = self:positions()
    else r[f] = self:_particle_field(particle_aliases[f] == true and f or particle_aliases[f] or f) end
  end
  return r
end

--- s:slice(field, {axis = "z", at = 0.5, res = 64}) -> rows of numbers (row 1 at the low end)
function S:slice(field, o)
  o = o or {}
  check_keys(o, { axis = true, at = true, res = true }, "s:slice")
  local axis = check_choice(o.axis or "z", "s:slice: axis", { "x", "y", "z" })
  local st = self:_state()
  local res = o.res or 64
  if type(res) == "number" then res = { res, res } end
  return self:_slice(field, axis, o.at or 0, res[1], res[2])
end

-- ---- runs, frames and series ------------------------------------------------

local frame_mt = {}
frame_mt.__index = frame_mt
local function frame_path(fr, path)
  if type(path) ~= "string" then error("frame: expected a file path", 3) end
  if path:find("%%") then return path:format(fr.index) end
  return path
end
function frame_mt:png(field, path, opts) return self.scene:png(field, frame_path(self, path), opts) end
function frame_mt:vtu(path) return self.scene:vtu(frame_path(self, path)) end
function frame_mt:ply(path, opts) return self.scene:ply(frame_path(self, path), opts) end
function frame_mt:save(path) return self.scene:save(frame_path(self, path)) end
function frame_mt:stats() return self.scene:stats() end

local function default_field(s)
  for _, f in ipairs(s:stats().fields) do
    if f == "temperature" then return f end
  end
  return "speed"
end

local run_keys = { until_t = true, every = true, on_frame = true, csv = true, probes = true, png = true, until_rest = true,
  vtu = true, ply = true, movie = true }
local run_png_keys = { field = true, path = true, kind = true, width = true, height = true, axis = true, at = true,
  range = true, colormap = true }
local png_keys = { kind = true, width = true, height = true, axis = true, at = true, range = true, colormap = true, grow = true }

-- s:png checks its options here first, for the "did you mean" (the C method checks again)
local raw_png = S.png
function S:png(field, path, opts)
  if type(opts) == "table" then check_keys(opts, png_keys, "s:png") end
  local ok, r, info = pcall(raw_png, self, field, path, opts)
  if not ok then error(r, 2) end -- the scene's line, not this one
  return r, info
end

-- s:run's output tables: a misspelt option must fail, not be ignored
local function check_run_outputs(o)
  if o.png ~= nil then
    if type(o.png) ~= "table" then error(("s:run: png = {field = ..., path = ...}, got %s"):format(type(o.png)), 3) end
    check_keys(o.png, run_png_keys, "s:run: png", 4)
    if o.png.colormap ~= nil then -- before the run, not at its first frame
      local ok, err = pcall(core.colormap, o.png.colormap, 0)
      if not ok then error("s:run: png: " .. tostring(err), 3) end
    end
  end
  if o.csv ~= nil and type(o.csv) ~= "string" then
    error(("s:run: csv = \"series.csv\" (a file name), got %s"):format(type(o.csv)), 3)
  end
  if o.probes ~= nil then
    if type(o.probes) ~= "table" then error(("s:run: probes = {{field, {x, y}}, ...}, got %s"):format(type(o.probes)), 3) end
    for k, p in pairs(o.probes) do
      if math.type(k) ~= "integer" then
        error(("s:run: probes: unknown field '%s'; probes is a list {{field, {x, y}}, ...}"):format(tostring(k)), 3)
      end
      if type(p) ~= "table" or type(p[1]) ~= "string" then
        error(("s:run: probes[%s] = {field, {x, y}}, e.g. {\"speed\", {0.5, 0.2}}"):format(tostring(k)), 3)
      end
      for pk in pairs(p) do
        if pk ~= 1 and pk ~= 2 then
          local near = type(pk) == "string" and nearest(pk, { field = true, point = true })
          error(("s:run: probes[%s]: unknown field '%s'%s (a probe is {field, {x, y}})"):format(tostring(k), tostring(pk),
            near and ("; did you mean '" .. near .. "'? write it as the first or second entry") or ""), 3)
        end
      end
    end
  end
end


-- ---- particle dumps in runs: s:run{vtu = {...}, ply = {...}} ----------------
-- Each dump keeps its own cadence (every, default the run's) and counter; the
-- counter and the VTU's .pvd list live in the scene's state, keyed by the path
-- pattern, so a second s:run with the same pattern continues the series and
-- its collection. The .pvd is rewritten whole (atomically) after every frame:
-- a run opened in ParaView while it goes, or after a kill, has a collection
-- listing exactly the frames on disk.

local run_dump_keys = {
  vtu = { path = true, every = true, pvd = true },
  ply = { path = true, every = true, color = true, range = true, colormap = true },
}
local dump_default_path = { vtu = "particles_%04d.vtu", ply = "particles_%04d.ply" }

local function check_dump_outputs(o)
  for _, kind in ipairs { "vtu", "ply" } do
    local d = o[kind]
    if d ~= nil and d ~= true then
      if type(d) ~= "table" then
        error(("s:run: %s = {path = \"%s\", every = ...} or true, got %s"):format(kind, dump_default_path[kind], type(d)), 3)
      end
      check_keys(d, run_dump_keys[kind], "s:run: " .. kind, 4)
      if d.path ~= nil and (type(d.path) ~= "string" or not d.path:find("%%0?%d*d")) then
        error(("s:run: %s.path = %s: a file pattern with the frame number as %%d or %%04d, e.g. \"%s\""):format(
          kind, tostring(d.path), dump_default_path[kind]), 3)
      end
      if d.every ~= nil then check_number(d.every, "s:run: " .. kind .. ".every", 1e-12, 1e12, "s", 4) end
      if d.pvd ~= nil and (type(d.pvd) ~= "string" or d.pvd:find("/") or not d.pvd:find("%.pvd$")) then
        error(("s:run: vtu.pvd = %s: a file name ending in .pvd (it is written beside the frames)"):format(tostring(d.pvd)), 3)
      end
    end
  end
end

-- "out/bake_%04d.vtu" -> "out/bake.pvd"; a pattern that is only the number -> "frames.pvd"
local function pvd_path(path, name)
  local dir, base = path:match("^(.*/)([^/]*)$")
  dir, base = dir or "", base or path
  if name then return dir .. name end
  local stem = base:gsub("%%0?%d*d", ""):gsub("%.vtu$", ""):gsub("[_%-%.]+$", "")
  return dir .. (stem ~= "" and stem or "frames") .. ".pvd"
end

local function xml_attr(v) return (v:gsub("&", "&amp;"):gsub("<", "&lt;"):gsub(">", "&gt;"):gsub('"', "&quot;")) end

-- VTK's collection format, which ParaView (and vtkXMLCollectionReader) read
-- as one data set with a time axis: one DataSet per frame, file relative to
-- the .pvd. %.17g: timestep reads back as the frame's TimeValue, bit for bit.
local function pvd_text(list)
  local out = { '<?xml version="1.0"?>\n<VTKFile type="Collection" version="0.1" byte_order="LittleEndian">\n<Collection>\n' }
  for _, e in ipairs(list) do
    out[#out + 1] = ('<DataSet timestep="%.17g" group="" part="0" file="%s"/>\n'):format(e[1], xml_attr(e[2]))
  end
  out[#out + 1] = "</Collection>\n</VTKFile>\n"
  return table.concat(out)
end

-- The dumps one run writes: {kind, path, every, next, state, opts}.
local function run_dumps(self, o, opts, t0, every)
  local specs = {}
  for _, kind in ipairs { "vtu", "ply" } do
    local d = o[kind]
    if d == nil and kind == "vtu" and opts.vtu_dir then d = { path = opts.vtu_dir .. "/frame_%04d.vtu" } end
    if d ~= nil then
      if d == true then d = {} end
      local st = self:_state()
      st.dumps = st.dumps or {}
      local path = d.path or dump_default_path[kind]
      local key = kind .. "\0" .. path
      st.dumps[key] = st.dumps[key] or { count = 0, list = {} }
      -- a series continued by another s:run already has this instant (the
      -- last run's end): a second file at the same time would give the .pvd
      -- two data sets for one time step
      local e = d.every or every
      local first = st.dumps[key].last_t == t0 and t0 + e or t0
      specs[#specs + 1] = { kind = kind, path = path, every = e, next = first, state = st.dumps[key],
        pvd = kind == "vtu" and pvd_path(path, d.pvd) or nil,
        opts = kind == "ply" and { color = d.color, range = d.range, colormap = d.colormap } or nil }
    end
  end
  return specs
end

-- Earliest time a dump is due (the run steps land on it, as on frames).
local function dumps_next(specs, t)
  for _, d in ipairs(specs) do t = math.min(t, d.next) end
  return t
end

-- Write the dumps due at time t (all of them when force: the run's end at rest).
local function dumps_write(self, specs, t, force)
  for _, d in ipairs(specs) do
    if force or t >= d.next - 1e-9 * d.every then
      local path = d.path:format(d.state.count)
      if d.kind == "vtu" then
        self:vtu(path)
        d.state.list[#d.state.list + 1] = { t, path:match("([^/]*)$") }
        core.write_atomic(d.pvd, pvd_text(d.state.list), "s:run{vtu = ...}")
      else
        local ok, err = pcall(self.ply, self, path, d.opts)
        if not ok then error(err, 0) end
      end
      d.state.count, d.state.last_t = d.state.count + 1, t
      repeat d.next = d.next + d.every until d.next > t + 1e-9 * d.every
    end
  end
end

-- ---- movies: s:run{movie = "bake.mp4"} or hearth run --movie FILE ----------
-- The run's PNG frames are encoded by the ffmpeg program (lua_output.c's
-- core.movie); without ffmpeg a notice says so and the frames stay.
local movie_keys = { path = true, fps = true }
local function movie_option(o, opts)
  local m, from = o.movie, "s:run: movie"
  if m == nil and opts.movie then m, from = opts.movie, "--movie" end
  if m == nil then return nil end
  if type(m) == "string" then m = { path = m } end
  if type(m) ~= "table" then
    error(("s:run: movie = \"bake.mp4\" or {path = \"bake.mp4\", fps = 10}, got %s"):format(type(m)), 3)
  end
  check_keys(m, movie_keys, "s:run: movie", 4)
  if type(m.path) ~= "string" or m.path == "" then
    error("s:run: movie.path = \"bake.mp4\", the movie file (its extension picks the container)", 3)
  end
  if not m.path:match("%.%w+$") then -- ffmpeg picks the container from it
    error(("s:run: movie.path = %q needs an extension naming the container, e.g. \"bake.mp4\""):format(m.path), 3)
  end
  if m.fps ~= nil then check_number(m.fps, "s:run: movie.fps", 0.01, 1000, "frames/s", 4) end
  if not o.png then
    error(("%s = %q needs the run's PNG frames: add png = {field = ..., path = \"frame_%%04d.png\"} to s:run")
      :format(from, m.path), 3)
  end
  local pattern = o.png.path or "frame_%04d.png"
  local n = 0
  for _ in pattern:gmatch("%%0?%d*d") do n = n + 1 end
  local _, pct = pattern:gsub("%%", "")
  if n ~= 1 or pct ~= 1 then
    error(("%s = %q: png.path = %q must number its frames with one %%d or %%04d, so each frame is its own file")
      :format(from, m.path, pattern), 3)
  end
  return { path = m.path, fps = m.fps or 10, pattern = pattern }
end

local function movie_write(st, mv, first)
  -- a later s:run with the same movie and frames continues it
  st.movie_first = st.movie_first or {}
  local key = mv.path .. "\0" .. mv.pattern
  st.movie_first[key] = st.movie_first[key] or first
  local from = st.movie_first[key]
  if st.frame > from then core.movie(mv.pattern, from, st.frame - from, mv.path, mv.fps) end
end

--- s:run{until_t = T, every = dt, on_frame = function(frame) ... end, csv = "series.csv",
---       probes = {{"speed", {x, y}}, ...}, png = {field = "speed", path = "frame_%04d.png", kind = "particles"},
---       vtu = {path = "bake_%04d.vtu", every = dt, pvd = "bake.pvd"},
---       ply = {path = "bake_%04d.ply", every = dt, color = "temperature", range = {20, 200}, colormap = "inferno"},
---       movie = "bake.mp4" or {path = "bake.mp4", fps = 10}}
function S:run(o)
  o = o or {}
  if type(o) ~= "table" then error("s:run: expected a table", 2) end
  check_keys(o, run_keys, "s:run")
  check_run_outputs(o)
  check_dump_outputs(o)
  local opts = core.options()
  local mv = movie_option(o, opts)
  local t0 = self:_time()
  local until_t = opts.until_t or o.until_t
  if until_t == nil then error("s:run: until_t is required (or pass --until to hearth run)", 2) end
  check_number(until_t, "s:run: until_t", 0, 1e12, "s")
  local rest = o.until_rest
  if rest ~= nil then check_number(rest, "s:run: until_rest", 0, 1e12, "m/s") end
  local span = until_t - t0
  local every = o.every
  if opts.frames then every = span / opts.frames end
  if every ~= nil then check_number(every, "s:run: every", 1e-12, 1e12, "s") end
  every = every or math.max(span, 1e-12)
  local st = self:_state()
  local probes = o.probes or {}
  local rows
  if o.csv then
    local head = { "t", "step", "dt", "particles", "kinetic", "max_speed" }
    for _, p in ipairs(probes) do
      local v = check_vec(p[2], "s:run: probe point")
      head[#head + 1] = ("%s@%g:%g:%g"):format(p[1], v[1], v[2], v[3])
    end
    rows = { table.concat(head, ",") }
  end
  local function frame()
    local stt = self:stats()
    local fr = setmetatable({ t = stt.t, index = st.frame, scene = self }, frame_mt)
    if o.png then
      local pf = o.png
      local field = pf.field or default_field(self)
      -- frames compare: a field without a fixed range (and no range given)
      -- keeps the range its frames have drawn so far, widened as needed
      st.png_range = st.png_range or {}
      local _, info = self:png(field, frame_path(fr, pf.path or "frame_%04d.png"),
        { kind = pf.kind or "particles", width = pf.width, height = pf.height, axis = pf.axis, at = pf.at,
          range = pf.range, colormap = pf.colormap, grow = st.png_range[field] })
      if info then st.png_range[field] = info.range end
    end
    if rows then
      local r = { ("%.9g"):format(stt.t), stt.step, ("%.6g"):format(stt.dt), stt.particles,
        ("%.9g"):format(stt.kinetic), ("%.9g"):format(stt.max_speed) }
      for _, p in ipairs(probes) do
        local v = self:probe(p[1], p[2])
        local m = v
        if type(v) == "table" then -- a vector's magnitude, a tensor's Frobenius norm
          m = 0
          for _, c in ipairs(v) do m = m + c * c end
          m = math.sqrt(m)
        end
        r[#r + 1] = ("%.9g"):format(m)
      end
      rows[#rows + 1] = table.concat(r, ",")
      core.write_atomic(o.csv, table.concat(rows, "\n") .. "\n", "s:run{csv = ...}")
    end
    if o.on_frame then o.on_frame(fr) end
    st.frame = st.frame + 1
  end
  fire_events(self)
  local first_frame = st.frame
  frame()
  local dumps = run_dumps(self, o, opts, t0, every)
  dumps_write(self, dumps, t0, false)
  local next_frame = t0 + every
  local yield_steps = opts.yield and coroutine.isyieldable()
  -- until_rest: the largest particle speed is checked after every batch of
  -- steps (at most 64) and at frames; the run is at rest when it is below the
  -- tolerance and not larger than at the check before. The second condition
  -- keeps a body released from rest (slow in its first steps, but
  -- accelerating) from counting as settled.
  local at_rest, last_speed = false, math.huge
  while self:_time() < until_t - 1e-12 * math.max(1, until_t) and not at_rest do
    local now = self:_time()
    local target = dumps_next(dumps, math.min(next_frame, until_t))
    local ev = st.events[1]
    if ev and ev.t > now and ev.t < target then target = ev.t end
    if yield_steps then
      local t = self:_time()
      while t < target do -- one step at a time, the host draws in between
        host_yield()
        self:_advance(target, 1)
        local t1 = self:_time()
        if t1 == t then break end -- no step was possible (dt underflow): as _advance would
        t = t1
      end
    else
      -- at most 64 steps before the progress bar moves; steps land only on the
      -- real target (a frame, an event, the end), so progress never shortens dt
      self:_advance(target, 64)
    end
    fire_events(self)
    local stt = self:stats()
    if rest then
      at_rest = stt.max_speed < rest and stt.max_speed <= last_speed
      last_speed = stt.max_speed
    end
    if stt.t >= next_frame - 1e-9 * every or at_rest then
      frame() -- a run that stops at rest ends with a frame of the rest state
      next_frame = next_frame + every
    end
    dumps_write(self, dumps, stt.t, at_rest)
    core.progress(stt.t, until_t, stt.step, false)
  end
  local stt = self:stats()
  core.progress(stt.t, until_t, stt.step, true)
  if mv then movie_write(st, mv, first_frame) end
  st.ran = true
  if rest then stt.at_rest = at_rest end
  return stt
end

-- Called by `hearth run` after the scene file: checks --set use, and runs a
-- scene the file built but did not run.
function h._finish()
  for k in pairs(core.options().sets) do
    if not h._params_declared and not scene_knobs[k] then
      usage_error(("--set %s: this scene declares no parameters (h.params{...}); there is nothing to set"):format(k))
    end
  end
  local s = h._last_scene
  if s and not s:_state().ran then
    local opts = core.options()
    s:run { until_t = opts.until_t or 1.0, png = { path = "frame_%04d.png" },
            every = opts.frames and nil or (opts.until_t or 1.0) / 10 }
  end
end

-- ---- metrics (what `hearth trade` and `hearth run --metric` measure) ---------

h._metrics = {}

--- h.metric("height", function(s) return ... end): a number the scene reports at the
--- end of its run, for `hearth trade SCENE --metric height`. A scene's own metric
--- replaces a built-in of the same name.
function h.metric(name, fn)
  if type(name) ~= "string" or not name:match("^[%w_]+$") then
    error("h.metric: the first argument is a name of letters, digits and _", 2)
  end
  if type(fn) ~= "function" then error("h.metric: the second argument is a function(s) returning a number", 2) end
  h._metrics[name] = fn
end

-- Extent of the particles: lowest and highest coordinate per axis, and the centroid.
local function extent(s)
  local x, n = s:positions(), s:stats().particles
  if n == 0 then error("metric: the scene has no particles", 0) end
  local lo, hi, c = { math.huge, math.huge, math.huge }, { -math.huge, -math.huge, -math.huge }, { 0, 0, 0 }
  for i = 0, n - 1 do
    for k = 1, 3 do
      local v = x[3 * i + k]
      if v < lo[k] then lo[k] = v end
      if v > hi[k] then hi[k] = v end
      c[k] = c[k] + v / n
    end
  end
  return lo, hi, c, x, n
end

h.builtin_metrics = {
  -- top minus bottom of the material (m)
  height = function(s) local lo, hi = extent(s); return hi[2] - lo[2] end,
  -- largest horizontal distance of a particle from the centroid (m): x in 2D, x and z in 3D
  spread = function(s)
    local _, _, c, x, n = extent(s)
    local r = 0
    for i = 0, n - 1 do
      local d = (x[3 * i + 1] - c[1]) ^ 2 + (x[3 * i + 3] - c[3]) ^ 2
      if d > r then r = d end
    end
    return math.sqrt(r)
  end,
  -- temperature at the centre of the material's bounding box (degC)
  centre_temperature = function(s)
    local lo, hi = extent(s)
    return s:probe("temperature", { (lo[1] + hi[1]) / 2, (lo[2] + hi[2]) / 2, (lo[3] + hi[3]) / 2 })
  end,
  -- the furthest particle along +x (m): the front of a flow or a nozzle jet
  front = function(s) local _, hi = extent(s); return hi[1] end,
  -- the material's volume at the end, sum of V0 J (m^3, or m^2 in 2D)
  volume = function(s) return s:volume() end,
  -- water lost from the material (kg): needs the water field
  water_lost = function(s)
    for _, f in ipairs(s:stats().fields) do
      if f == "water" and s.water_lost then return s:water_lost() end
    end
    error("metric water_lost: this scene has no water field (water transport is not built yet, or no material holds water)", 0)
  end,
}
h.builtin_metrics.centre_temp = h.builtin_metrics.centre_temperature
h.builtin_metrics.final_volume = h.builtin_metrics.volume

-- Evaluate a metric on the scene the file built (called by `hearth run --metric`).
function h._metric(name)
  local fn = h._metrics[name] or h.builtin_metrics[name]
  if not fn then
    local all = {}
    for k in pairs(h._metrics) do all[k] = true end
    for k in pairs(h.builtin_metrics) do all[k] = true end
    local near = nearest(name, all)
    error(("--metric %s: no such metric%s (this scene has: %s)"):format(name,
      near and ("; did you mean '" .. near .. "'?") or "", table.concat(sorted_keys(all), ", ")), 0)
  end
  local s = h._last_scene
  if not s then error("--metric " .. name .. ": the scene file built no scene", 0) end
  local v = fn(s)
  if type(v) ~= "number" then
    error(("--metric %s: the metric returned %s, not a number"):format(name, type(v)), 0)
  end
  return v, s:stats()
end

return h

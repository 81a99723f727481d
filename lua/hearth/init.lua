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

h._check = { keys = check_keys, number = check_number, choice = check_choice, vec = check_vec }

-- ---- curves and materials -------------------------------------------------

-- A mixed parameter table remembers its constituents in its metatable (so
-- pairs() still sees only parameters): a scene whose blend mode is "linear"
-- or "labels" rebuilds the material from them (see material_id).
local mix_mt = { __name = "hearth.mix" }
local blend_modes = { "nonlinear", "linear", "labels" }

local function mix_info(t)
  local mt = type(t) == "table" and getmetatable(t)
  return type(mt) == "table" and mt.__name == mix_mt.__name and mt.mix or nil
end

local curve_mt = { __name = "hearth.curve" }
local material_mt = { __name = "hearth.material" }

--- A piecewise-linear function of temperature: h.curve{{T1, v1}, {T2, v2}, ..., irreversible = true}
function h.curve(t)
  if type(t) ~= "table" or #t < 1 then error("h.curve: expected a table of {T, value} points", 2) end
  check_keys(t, setmetatable({ irreversible = true }, { __index = function(_, k) return math.type(k) == "integer" end }),
    "h.curve")
  local c = { irreversible = t.irreversible and true or false }
  for i, p in ipairs(t) do
    if type(p) ~= "table" or type(p[1]) ~= "number" or type(p[2]) ~= "number" then
      error(("h.curve: point %d must be {temperature, value}"):format(i), 2)
    end
    if i > 1 and not (p[1] > t[i - 1][1]) then
      error(("h.curve: temperatures must increase (point %d: %g after %g)"):format(i, p[1], t[i - 1][1]), 2)
    end
    c[i] = { p[1], p[2] }
  end
  return setmetatable(c, curve_mt)
end

--- A material from a plugin, its parameters checked against the plugin's schema now.
function h.material(plugin, params)
  if type(plugin) ~= "string" then error("h.material: the first argument is the plugin name, e.g. \"elastic\"", 2) end
  params = params or {}
  local plain, curves = {}, {}
  for k, v in pairs(params) do
    if type(k) ~= "string" then error("h.material: parameter names must be strings", 2) end
    if type(v) == "number" then plain[k] = v
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
  return setmetatable({ plugin = plugin, params = plain, curves = curves, mix = mix_info(params) }, material_mt)
end

--- Write a text file (a CSV, a note) atomically; relative paths go under the output folder.
function h.write(path, text)
  if type(path) ~= "string" or type(text) ~= "string" then error("h.write(path, text): two strings", 2) end
  local ok, e = pcall(core.write_atomic, path, text)
  if not ok then error(e, 2) end
  return e
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

--- h.mix{ {params_a, 0.5}, {params_b, 0.5}, plugin = "von_mises_sauce" }: one parameter set
--- blended by the plugin's own blend rule (Nagasawa et al. eq. 28-31 for sauces).
--- The scene's `blend` key decides how a body made of it is simulated.
function h.mix(t)
  if type(t) ~= "table" or #t < 1 then error("h.mix: expected { {params, ratio}, ... }", 2) end
  check_keys(t, setmetatable({ plugin = true }, { __index = function(_, k) return math.type(k) == "integer" end }),
    "h.mix")
  local plugin = t.plugin or "von_mises_sauce"
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

-- ---- scene parameters -----------------------------------------------------

--- Named defaults that `hearth run scene.lua --set name=value` overrides.
function h.params(defaults)
  if type(defaults) ~= "table" then error("h.params: expected a table of name = default", 2) end
  local P = {}
  for k, v in pairs(defaults) do P[k] = v end
  for k, v in pairs(core.options().sets) do
    local d = defaults[k]
    if d == nil then
      error(("--set %s: this scene has no parameter '%s'; valid names: %s"):format(k, k,
        table.concat(sorted_keys(defaults), ", ")), 2)
    end
    if type(d) == "number" then
      P[k] = tonumber(v) or error(("--set %s=%s: expected a number"):format(k, v), 2)
    elseif type(d) == "boolean" then
      if v ~= "true" and v ~= "false" then error(("--set %s=%s: expected true or false"):format(k, v), 2) end
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
local scene_keys = { dim = true, dx = true, box = true, solver = true, gravity = true, cfl = true, dt_max = true,
  wall = true, friction = true, guard = true, max_rollbacks = true, seed = true, name = true, oven = true, heat = true,
  blend = true }
local contact = { "sticky", "slip", "separate" }

--- A scene: h.scene{dim = 2, dx = 0.01, box = {{0,0},{1,1}}, gravity = {0,-9.81}, ...}
function h.scene(o)
  o = o or {}
  if type(o) ~= "table" then error("h.scene: expected a table", 2) end
  if next(core.options().sets) and not h._params_declared then
    error("--set: this scene declares no parameters with h.params{...} before h.scene; there is nothing to set", 2)
  end
  check_keys(o, scene_keys, "h.scene")
  local dim = o.dim or 2
  if dim ~= 2 and dim ~= 3 then error(("h.scene: dim = %s; valid: 2, 3"):format(tostring(dim)), 2) end
  if o.solver and o.solver ~= "mpm" then
    error(("h.scene: solver = %s; valid: mpm (sph is not built yet)"):format(tostring(o.solver)), 2)
  end
  local box = o.box or { { 0, 0, 0 }, { 1, 1, 1 } }
  if type(box) ~= "table" or #box ~= 2 then error("h.scene: box = {{lo}, {hi}}", 2) end
  local def = {
    dim = dim,
    dx = check_number(o.dx or 0.01, "h.scene: dx", 1e-6, 1e3, "m"),
    lo = check_vec(box[1], "h.scene: box[1]"), hi = check_vec(box[2], "h.scene: box[2]"),
    gravity = check_vec(o.gravity or { 0, -9.81, 0 }, "h.scene: gravity"),
    cfl = check_number(o.cfl or 0.5, "h.scene: cfl", 1e-6, 4),
    dt_max = check_number(o.dt_max or 0, "h.scene: dt_max", 0, 1e6, "s"),
    wall = check_choice(o.wall or "slip", "h.scene: wall", contact),
    friction = check_number(o.friction or 0, "h.scene: friction", 0, 1e6),
    guard = check_choice(o.guard or "stop", "h.scene: guard", { "stop", "rollback" }),
    max_rollbacks = check_number(o.max_rollbacks or 8, "h.scene: max_rollbacks", 0, 60),
    seed = check_number(o.seed or 1, "h.scene: seed", 0, 2 ^ 52),
    heat_implicit = check_choice(o.heat or "explicit", "h.scene: heat", { "explicit", "implicit" }),
    oven_beta = 0,
  }
  if o.oven ~= nil then
    if type(o.oven) ~= "table" then error("h.scene: oven = {temperature = degC, beta = W/(m^2 K)}", 2) end
    check_keys(o.oven, { temperature = true, beta = true }, "h.scene: oven")
    def.oven_temperature = check_number(o.oven.temperature, "h.scene: oven.temperature", -273.15, 5000, "degC")
    def.oven_beta = check_number(o.oven.beta or 10, "h.scene: oven.beta", 0, 1e9, "W/(m^2 K)")
  end
  if dim == 2 then def.lo[3], def.hi[3] = 0, 0 end
  local ok, s = pcall(core.scene_new, def)
  if not ok then error(s, 2) end
  local st = s:_state()
  st.events, st.mats, st.name, st.frame, st.dim = {}, {}, o.name, 0, dim
  -- how bodies made of h.mix{...} materials are simulated (Nagasawa et al. Figs. 1, 9, 10):
  -- "nonlinear" the blend model, "linear" linearly blended parameters, "labels" random binary labels
  st.blend = blend_modes[check_choice(o.blend or "nonlinear", "h.scene: blend", blend_modes) + 1]
  st.seed = def.seed
  h._last_scene = s
  return s
end

h.load = function(path)
  local ok, s = pcall(core.load, path)
  if not ok then error(s, 2) end
  local st = s:_state()
  st.events, st.mats, st.frame = {}, {}, 0
  h._last_scene = s
  return s
end

local function register(s, m, params)
  local id = s:_material(m.plugin, params)
  for k, c in pairs(m.curves) do
    local T, V = {}, {}
    for i, p in ipairs(c) do T[i], V[i] = p[1], p[2] end
    s:_curve(id, k, T, V, c.irreversible)
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

--- s:add{shape = ..., material = ..., ppc = 4, velocity = {0,0}, jitter = 0.5, temperature = 20} -> body id
function S:add(o)
  if type(o) ~= "table" then error("s:add: expected a table", 2) end
  check_keys(o, { shape = true, material = true, ppc = true, velocity = true, jitter = true, temperature = true,
    name = true, fixed = true }, "s:add")
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
  local ok, id, ratios = pcall(material_id, self, mat)
  if not ok then error(id, 2) end
  local ppc = check_number(o.ppc or 4, "s:add: ppc", 1, 1000, "particles per cell")
  local jitter = check_number(o.jitter or 0.5, "s:add: jitter", 0, 1)
  local vel = check_vec(o.velocity or { 0, 0, 0 }, "s:add: velocity")
  if o.temperature ~= nil then check_number(o.temperature, "s:add: temperature", -273.15, 5000, "degC") end
  local ok2, body = pcall(self._add, self, o.shape, type(id) == "table" and id[1] or id, math.floor(ppc), jitter, vel,
    o.temperature, o.fixed)
  if not ok2 then error(body, 2) end
  if type(id) == "table" then -- blend = "labels": each particle one constituent, drawn with its ratio
    local st = self:_state()
    local ok3, counts = pcall(self._labels, self, body, id, ratios, st.seed * 7919 + body)
    if not ok3 then error(counts, 2) end
    st.label_counts = st.label_counts or {}
    st.label_counts[body] = counts
  end
  return body
end

--- s:collider{shape = ..., mode = "separate", friction = 0, velocity = {..} or function(t), omega = ..., pivot = {..}}
function S:collider(o)
  if type(o) ~= "table" then error("s:collider: expected a table", 2) end
  check_keys(o, { shape = true, mode = true, friction = true, velocity = true, omega = true, pivot = true, name = true,
    temperature = true, beta = true }, "s:collider")
  if o.temperature ~= nil then check_number(o.temperature, "s:collider: temperature", -273.15, 5000, "degC") end
  if o.beta ~= nil then check_number(o.beta, "s:collider: beta", 0, 1e9, "W/(m^2 K)") end
  if not is_shape(o.shape) then error("s:collider: shape = h.plane(...), h.box(...), ... is required", 2) end
  local mode = check_choice(o.mode or "separate", "s:collider: mode", contact)
  local fr = check_number(o.friction or 0, "s:collider: friction", 0, 1e6)
  local v = o.velocity
  if v ~= nil and type(v) ~= "function" then v = check_vec(v, "s:collider: velocity") end
  local w = o.omega
  if w ~= nil and type(w) ~= "function" and type(w) ~= "number" then w = check_vec(w, "s:collider: omega") end
  local p = o.pivot and check_vec(o.pivot, "s:collider: pivot") or nil
  local ok, id = pcall(self._collider, self, o.shape, mode, fr, v, w, p, o.temperature,
    o.temperature and (o.beta or 100) or 0)
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
  local ev, now = s:_state().events, s:stats().t
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
    self:_step(1)
  end
  fire_events(self)
  self:_state().ran = true -- hearth run does not run a stepped scene again
  return self
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
function frame_mt:ply(path) return self.scene:ply(frame_path(self, path)) end
function frame_mt:save(path) return self.scene:save(frame_path(self, path)) end
function frame_mt:stats() return self.scene:stats() end

local function default_field(s)
  for _, f in ipairs(s:stats().fields) do
    if f == "temperature" then return f end
  end
  return "speed"
end

local run_keys = { until_t = true, every = true, on_frame = true, csv = true, probes = true, png = true }

--- s:run{until_t = T, every = dt, on_frame = function(frame) ... end, csv = "series.csv",
---       probes = {{"speed", {x, y}}, ...}, png = {field = "speed", path = "frame_%04d.png", kind = "particles"}}
function S:run(o)
  o = o or {}
  if type(o) ~= "table" then error("s:run: expected a table", 2) end
  check_keys(o, run_keys, "s:run")
  local opts = core.options()
  local t0 = self:stats().t
  local until_t = opts.until_t or o.until_t
  if until_t == nil then error("s:run: until_t is required (or pass --until to hearth run)", 2) end
  check_number(until_t, "s:run: until_t", 0, 1e12, "s")
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
      self:png(pf.field or default_field(self), frame_path(fr, pf.path or "frame_%04d.png"),
        { kind = pf.kind or "particles", width = pf.width, height = pf.height, axis = pf.axis, at = pf.at })
    end
    if rows then
      local r = { ("%.9g"):format(stt.t), stt.step, ("%.6g"):format(stt.dt), stt.particles,
        ("%.9g"):format(stt.kinetic), ("%.9g"):format(stt.max_speed) }
      for _, p in ipairs(probes) do
        local v = self:probe(p[1], p[2])
        r[#r + 1] = type(v) == "table" and ("%.9g"):format(math.sqrt(v[1] ^ 2 + v[2] ^ 2 + v[3] ^ 2))
          or ("%.9g"):format(v)
      end
      rows[#rows + 1] = table.concat(r, ",")
      core.write_atomic(o.csv, table.concat(rows, "\n") .. "\n")
    end
    if o.on_frame then o.on_frame(fr) end
    st.frame = st.frame + 1
  end
  fire_events(self)
  frame()
  local next_frame = t0 + every
  local chunk = math.max(span / 200, 1e-12) -- so the progress bar moves between sparse frames
  while self:stats().t < until_t - 1e-12 * math.max(1, until_t) do
    local now = self:stats().t
    local target = math.min(next_frame, until_t, now + chunk)
    local ev = st.events[1]
    if ev and ev.t > now and ev.t < target then target = ev.t end
    self:_advance(target)
    fire_events(self)
    local stt = self:stats()
    if stt.t >= next_frame - 1e-9 * every then
      frame()
      next_frame = next_frame + every
    end
    core.progress(stt.t, until_t, stt.step, false)
  end
  local stt = self:stats()
  core.progress(stt.t, until_t, stt.step, true)
  st.ran = true
  return stt
end

-- Called by `hearth run` after the scene file: checks --set use, and runs a
-- scene the file built but did not run.
function h._finish()
  local sets = core.options().sets
  if next(sets) and not h._params_declared then
    error("--set: this scene declares no parameters (h.params{...}); there is nothing to set", 0)
  end
  local s = h._last_scene
  if s and not s:_state().ran then
    local opts = core.options()
    s:run { until_t = opts.until_t or 1.0, png = { path = "frame_%04d.png" },
            every = opts.frames and nil or (opts.until_t or 1.0) / 10 }
  end
end

return h

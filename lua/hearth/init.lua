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
  if type(t) ~= "table" then
    error(("%s: expected a table of options (valid: %s), got a %s"):format(what, table.concat(sorted_keys(valid), ", "),
      type(t)), level or 3)
  end
  for k in pairs(t) do
    if not valid[k] then
      local near = type(k) == "string" and nearest(k, valid)
      error(("%s: unknown field '%s'%s (valid: %s)"):format(what, tostring(k),
        near and ("; did you mean '" .. near .. "'?") or "", table.concat(sorted_keys(valid), ", ")), level or 3)
    end
  end
end

-- a value as an error message shows it: Lua's tostring writes 0/0 as "-nan" (its sign bit), a sign a NaN does not
-- have for the reader; the core's messages say "nan" too (core/sim/error.c)
local function shown(v)
  if type(v) == "number" and v ~= v then return "nan" end
  return tostring(v)
end

local function check_number(v, what, lo, hi, unit, level)
  if type(v) ~= "number" or v ~= v or v < lo or v > hi then
    error(("%s = %s; valid range [%s, %s]%s"):format(what, shown(v), tostring(lo), tostring(hi),
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

-- A bad --set is a usage error (exit 2), not a scene error: what core.usage_error raises is marked for `hearth run`.
local usage_error = core.usage_error

-- "--set k=v" as a message shows it: a value past 60 characters (--set leaveners= with a list of 10000 numbers) is
-- cut to its first 40 and its length, so the refusal stays one line a user can read (h.params' messages too)
local function shorten(v)
  v = tostring(v)
  return #v > 60 and ("%s... (%d characters)"):format(v:sub(1, 40), #v) or v
end
local function set_text(k, v) return ("--set %s=%s"):format(k, shorten(v)) end
h._shorten, h._set_text = shorten, set_text

h._check = { keys = check_keys, number = check_number, choice = check_choice, vec = check_vec }

-- ---- curves and materials -------------------------------------------------

-- A mixed parameter table remembers its constituents in its metatable (so
-- pairs() still sees only parameters): a scene whose blend mode is "linear"
-- or "labels" rebuilds the material from them (see material_id).
local mix_mt = { __name = "hearth.mix" }
local blend_modes = scene_setting.blend.words
--- h.dx_3d(dx, floor, d3) -> the grid spacing a scene runs at: dx, or in 3D (d3 true) at least floor (m), the
--- scene's floor for a 3D run's cost. When it raises dx it says so on stdout: `--set dim=3 --set dx=0.001` of
--- lava_cake.lua had run at 4 mm without a word, a different run from the one asked for.
function h.dx_3d(dx, floor, d3)
  if d3 and dx < floor then
    print(("hearth: dx = %g m is below this scene's 3D floor; the 3D run uses dx = %g m"):format(dx, floor))
    return floor
  end
  return dx
end

--- h.blend_words: h.scene's blend modes, each with what it does, for a scene's parameter that picks one:
--- h.params{blend = h.choice("nonlinear", h.blend_words)}.
h.blend_words = {
  nonlinear = "the plugin's blend model (Nagasawa et al. eq. 28-31)",
  linear = "the weighted mean of every parameter",
  labels = "one material per constituent, drawn per particle with the ratios",
}
for _, w in ipairs(blend_modes) do assert(h.blend_words[w], "h.blend_words lacks the schema's blend word " .. w) end

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
      error(("h.curve: %s must increase (point %d: %s after %s)"):format(moist and "moisture ratios" or "temperatures",
        i, shown(p[1]), shown(t[i - 1][1])), 2)
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
  -- a .csv cell: a negative zero reads 0 (%.6f of -1e-9 wrote -0.000000; userview4, userfix8), NaN (not measured) ""
  if path:match("%.csv$") then text = text:gsub("[^,\n]+", function(c) if c:match("^%-?nan$") then return "" end
    if c:match("^%-0%.?0*$") or c:match("^%-0%.?0*e[-+]%d+$") then return c:sub(2) end end) end
  local ok, e = pcall(core.write_atomic, path, text, "h.write")
  if not ok then error(e, 2) end
  return e
end

--- The leading coefficient a of the least-squares parabola y = a u^2 + b u + c
--- through points {{u, y}, ...} (normal equations, Cramer's rule), and its
--- standard error from the residuals, se(a) = sqrt(RSS / (n - 3) (M^-1)_aa)
--- (M the normal matrix; NaN with 3 points); NaN with fewer than 3 points. The
--- baking scenes measure a top's curvature as 2a.
function h.parabola(points)
  local m = { 0, 0, 0, 0, 0, 0, 0, 0 } -- sums of 1, u, u^2, u^3, u^4, y, yu, yu^2
  for _, p in ipairs(points) do
    local u, y = p[1], p[2]
    m[1], m[2], m[3], m[4], m[5] = m[1] + 1, m[2] + u, m[3] + u * u, m[4] + u ^ 3, m[5] + u ^ 4
    m[6], m[7], m[8] = m[6] + y, m[7] + y * u, m[8] + y * u * u
  end
  if m[1] < 3 then return 0 / 0, 0 / 0 end
  local function det(a, b, c) -- columns a, b, c of a 3x3 matrix
    return a[1] * (b[2] * c[3] - b[3] * c[2]) - b[1] * (a[2] * c[3] - a[3] * c[2]) + c[1] * (a[2] * b[3] - a[3] * b[2])
  end
  local c1, c2, c3, r = { m[1], m[2], m[3] }, { m[2], m[3], m[4] }, { m[3], m[4], m[5] }, { m[6], m[7], m[8] }
  local D = det(c1, c2, c3)
  local a, b, c = det(c1, c2, r) / D, det(c1, r, c3) / D, det(r, c2, c3) / D
  local rss = 0
  for _, p in ipairs(points) do rss = rss + (p[2] - (a * p[1] ^ 2 + b * p[1] + c)) ^ 2 end
  return a, math.sqrt(rss / (m[1] - 3) * (m[1] * m[3] - m[2] * m[2]) / D)
end

--- h.top_curvature(s, {keep = function(id) ..., origin = x0, bin = dx, fraction = 0.6, z = zc, rest = y0s})
--- -> k, se, n: the curvature of a body's top surface read from its particles,
--- k = 2a of the least-squares parabola y = a u^2 + b u + c (negative: domed),
--- se its standard error (2 se(a) of h.parabola) and n the points fitted. The top
--- is the highest particle y of the particles `keep(id)` accepts in each bin of
--- width `bin` (bins centred on origin + j bin); the fit takes the bins whose
--- centre lies within the middle `fraction` of the body's width (its particles'
--- extent in x). In 3D only particles with |z - o.z| < bin/2 count. se says the
--- reading's own scatter: a flat top read with the particles' jitter gives k
--- within a few se of 0, either sign; the baking claims compare k with 2 se
--- (tests/baking_test.sh, claim_cookie_domed_vs_baseline; docs/validation.md,
--- "Fig. 17: the top's curvature and its noise").
--- rest = {[id] = y, ...} (optional): the particles' heights when the body was
--- placed. Each bin's top is then its highest particle's displacement y - rest[id]
--- rather than its y, so k is the curvature the top gained since (its curvature,
--- when the placed top was flat). Why: a placed particle sits up to jitter/2 of a
--- lattice spacing off its lattice point, and a static flat top read from those
--- heights reads that jitter (cookies.lua's capsule at dx 3.75 mm: -3.7 to +0.4
--- 1/m over five seeds; 0 without jitter); each particle carries its own offset,
--- so its displacement does not (docs/validation.md, "Fig. 17 at 3.75 mm: the
--- jitter, read and removed").
function h.top_curvature(s, o)
  if type(o) ~= "table" or type(o.keep) ~= "function" or type(o.origin) ~= "number" or not (type(o.bin) == "number" and o.bin > 0) then
    error("h.top_curvature(s, {keep = function(id), origin = x, bin = width > 0, fraction = 0.6, z = z}): keep, origin and bin are required", 2)
  end
  local frac = o.fraction or 0.6
  if not (frac > 0 and frac <= 1) then error(("h.top_curvature: fraction = %s; valid range (0, 1]"):format(shown(frac)), 2) end
  if o.rest ~= nil and type(o.rest) ~= "table" then
    error("h.top_curvature: rest must be a table {[particle id] = its height at rest}", 2)
  end
  local r = s:particles { fields = { "id", "x" } }
  local x, bin, top, who, lo, hi = r.x, o.bin, {}, {}, math.huge, -math.huge
  for p = 0, r.n - 1 do
    local px, py, pz = x[3 * p + 1], x[3 * p + 2], x[3 * p + 3]
    if o.keep(r.id[p + 1]) and (not o.z or math.abs(pz - o.z) < bin / 2) then
      local b = math.floor((px - o.origin) / bin + 0.5)
      if not top[b] or py > top[b] then top[b], who[b] = py, r.id[p + 1] end
      lo, hi = math.min(lo, px), math.max(hi, px)
    end
  end
  local mid, half, pts = (lo + hi) / 2, frac / 2 * (hi - lo), {}
  for b, y in pairs(top) do
    local u = o.origin + b * bin - mid
    if math.abs(u) <= half then
      if o.rest then
        local y0 = o.rest[who[b]]
        if type(y0) ~= "number" then
          error(("h.top_curvature: rest has no height for particle %d (the top of the bin at %g)"):format(who[b],
            o.origin + b * bin), 2)
        end
        y = y - y0
      end
      pts[#pts + 1] = { u, y }
    end
  end
  table.sort(pts, function(p, q) return p[1] < q[1] end) -- the sums in one order, whatever pairs() gives
  local a, se = h.parabola(pts)
  return 2 * a, 2 * se, #pts
end

-- ---- material library (h.library's presets: library.lua, sph_library.lua) ----

(require "hearth.library")(h, core, { nearest = nearest, sorted_keys = sorted_keys })

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

-- ---- scene parameters: h.params, h.choice, h.pass_params (params.lua) ----------

(require "hearth.params")(h, core, { nearest = nearest, sorted_keys = sorted_keys, scene_knobs = scene_knobs })

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
--- h.contact_words: s:collider's modes, each with what it does, for a scene's parameter that picks one:
--- h.params{tray = h.choice("separate", h.contact_words)}.
h.contact_words = {
  sticky = "holds what touches its face where it touched, in tension too",
  slip = "lets the body slide along its face without friction and lift off",
  separate = "lets the body slide with Coulomb friction and lift off",
  grip = "holds every grid node on and inside it",
}
for _, w in ipairs(contact) do assert(h.contact_words[w], "h.contact_words lacks the mode " .. w) end

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
      error(("%s = %s; valid range %s%s (%s)"):format(what, shown(v), range_text(e),
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
  if h._listed then core.listed() end -- hearth run --params listed them: nothing is made
  if core.options().list_params and not h._params_declared then -- hearth run --params, and no h.params
    h._list_knobs { "parameters (--set name=value): this scene declares none (h.params{...})" }
  end
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
          if not ok then usage_error(("%s: valid: %s"):format(set_text(e.name, v), table.concat(e.words, ", ")), 2) end
        else v = h._knob_in_range(e, v) end
        local top, sub = e.name:match("^([^.]+)%.(.+)$") -- a dotted knob (oven.emissivity): a key of its table's copy
        if top then local t = {}; for a, b in pairs(oo[top] or {}) do t[a] = b end; t[sub], oo[top] = v, t else oo[e.name] = v end
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
    -- (oven = {saturation = ...} alone is humid air for evaporation, without heat; the walls are optional)
    if v == nil and e.nan_ok and top and o[top] ~= nil and not (top == "oven" and (o.oven.saturation or sub ~= "temperature")) then
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
  h._dx_fits_box(def) -- a --set dx too coarse for the box: exit 2 naming dx (params.lua)
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
  s:_clock(lua_side.time_scale, scene_setting.time_units.words[lua_side.time_units + 1]) -- what a time reads (run.lua)
  h._last_scene = s
  return s
end

-- A scene made outside Lua (a checkpoint, the dashboard's built-in demo) becomes the current scene.
function h._adopt(s)
  local st = s:_state()
  st.events, st.mats, st.frame, st.dim, st.seed = {}, {}, 0, s:settings().dim, s:settings().seed -- s:run's CSV units
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

-- A crack band (Bazant & Oh 1983) is as wide as the point that cracks: a material given crack_band = 0
-- (lua/hearth/dough.lua's presets) registers with the scene's cell size dx, so the energy a crack takes (G_f per
-- area) does not change with the resolution while dx < w_c / fracture_strain (cam_clay_dough.c, "the crack band").
local function register(s, m, params)
  if params.crack_band == 0 then
    local p = {}
    for k, v in pairs(params) do p[k] = v end
    p.crack_band = s:settings().dx
    params = p
  end
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
---   fixed_temperature = false, smooth_surface = false} -> body id (fixed_temperature: the body keeps its temperature, a
---   Dirichlet boundary; smooth_surface: the particles within 1.25 lattice spacings of the surface are not jittered)
--- A fixed body (fixed = true) under SPH is a wall; velocity = {..} or function(t), omega = ... and
--- pivot = {..} (spelt as s:collider's) make it move rigidly: a lid, a paddle, a piston.
function S:add(o)
  if type(o) ~= "table" then error("s:add: expected a table", 2) end
  check_keys(o, { shape = true, material = true, ppc = true, velocity = true, jitter = true, temperature = true,
    name = true, fixed = true, saturation = true, omega = true, pivot = true, fixed_temperature = true,
    smooth_surface = true }, "s:add")
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
  local ppc = check_number(kppc and h._knob_in_range(h._ppc_knob, kppc) or o.ppc or 4, "s:add: ppc", 1, 1000, "particles per cell")
  local jitter = check_number(o.jitter or 0.5, "s:add: jitter", 0, 1)
  local vel = check_vec(start_v or { 0, 0, 0 }, "s:add: velocity")
  if o.temperature ~= nil then check_number(o.temperature, "s:add: temperature", -273.15, 5000, "degC") end
  if o.saturation ~= nil then check_number(o.saturation, "s:add: saturation", 0, 1) end
  if o.fixed_temperature and o.temperature == nil then
    error("s:add: fixed_temperature = true needs temperature = ... (degC), the temperature the body keeps", 2)
  end
  if o.smooth_surface ~= nil and type(o.smooth_surface) ~= "boolean" then
    error(("s:add: smooth_surface = %s; valid: true or false"):format(tostring(o.smooth_surface)), 2)
  end
  local ok2, body = pcall(self._add, self, o.shape, type(id) == "table" and id[1] or id, math.floor(ppc), jitter, vel,
    o.temperature, o.fixed, o.saturation, mix_ratios, o.fixed_temperature and true or false, o.smooth_surface == true)
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
---   temperature = degC, beta = W/(m^2 K) or fixed_temperature = true, saturation = 0..1, beta_water = kg/(m^2 s),
---   start_temperature = degC, warm_time = s, heat_capacity = J/(m^2 K), area = m^2, face_beta = W/(m^2 K) (docs/lua.md)}
--- fixed_temperature = true (or beta = math.huge) holds the touching material at temperature (Dirichlet).
function S:collider(o)
  if type(o) ~= "table" then error("s:collider: expected a table", 2) end
  check_keys(o, { shape = true, mode = true, friction = true, velocity = true, omega = true, pivot = true, name = true,
    temperature = true, beta = true, saturation = true, fixed_temperature = true, beta_water = true,
    start_temperature = true, warm_time = true, heat_capacity = true, area = true, face_beta = true }, "s:collider")
  if o.saturation ~= nil then check_number(o.saturation, "s:collider: saturation", 0, 1) end
  if o.beta_water ~= nil then
    check_number(o.beta_water, "s:collider: beta_water", 0, 1e9, "kg/(m^2 s)")
    if o.saturation == nil then
      error("s:collider: beta_water needs saturation = ... (the saturation it exchanges water toward, 0..1)", 2)
    end
  end
  if o.temperature ~= nil then check_number(o.temperature, "s:collider: temperature", -273.15, 5000, "degC") end
  if o.beta ~= nil and o.beta ~= math.huge then check_number(o.beta, "s:collider: beta", 0, 1e9, "W/(m^2 K)") end
  if (o.start_temperature == nil) ~= (o.warm_time == nil and o.face_beta == nil) or (o.warm_time and not (type(o.warm_time) == "number" and o.warm_time > 0)) then
    error("s:collider: start_temperature (degC, when added) and warm_time (s, > 0) go together: a tray warming to temperature", 2)
  end
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
    o.temperature and (o.fixed_temperature and math.huge or o.beta or 100) or 0, o.saturation, o.beta_water,
    o.start_temperature, o.warm_time, o.heat_capacity, o.area, o.face_beta)
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
    if f == "browning" then valid.browning_temperature, valid.browning_saturation = true, true end -- probe.c: unlisted
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

-- ---- runs: s:run, its frames, series, dumps and movies (run.lua) ------------

(require "hearth.run")(S, { check_keys = check_keys, check_number = check_number, check_vec = check_vec,
  nearest = nearest, fire_events = fire_events, host_yield = host_yield })

-- Called by `hearth run` after the scene file: checks --set use, and runs a
-- scene the file built but did not run.
function h._finish()
  if core.options().list_params and not h._params_declared then -- hearth run --params, no h.params, no h.scene
    h._list_knobs { "parameters (--set name=value): this scene declares none (h.params{...})" }
  end
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

-- ---- metrics (what `hearth trade` and `hearth run --metric` measure; metrics.lua) ----

(require "hearth.metrics")(h, { nearest = nearest, sorted_keys = sorted_keys })

return h

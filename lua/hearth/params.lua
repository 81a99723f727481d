-- hearth.params: a scene's own knobs, which `hearth run SCENE.lua --set name=value` overrides:
-- h.params, h.choice (a word-valued parameter: its words and what each means), h.number (a numeric
-- parameter: its valid range, unit and meaning), h.pass_params
-- (a wrapper script that runs a shipped scene) and the listing of `hearth run SCENE.lua --params`.
-- Loaded by init.lua: (require "hearth.params")(h, core, {nearest = ..., sorted_keys = ..., scene_knobs = ...}).
--
-- Why one declaration of the words: each scene used to check its word parameters its own way, after
-- other work, with its own message; some misspellings ran silently (a validation script's `--set
-- soft=bth` softened nothing, `--set material=elastik` ran the dough, `--set only=rwa` pressed no
-- marshmallow, cup_spoon.lua's `mixing` under a linear blend took any word). A word declared here is
-- checked before the scene makes anything, and the message is the same everywhere: the scene file
-- and line, the parameter, the word given, every valid word with what it means, and the nearest one.
--
-- Why one declaration of a number's range (#18, helper setrange): a numeric --set had none, so a value the scene
-- could not use was refused (when at all) by whatever it became first ("box: hi[1] = 0.21 must exceed lo[1] =
-- 0.21" for bread.lua's slit_width=0, "s:at: time = -1" for lava_cake.lua's bake=-1), or by a check each scene
-- wrote by hand in its own words. h.number's range is checked with the words, before the scene makes anything.

return function(h, core, u)
local nearest, sorted_keys, scene_knobs = u.nearest, u.sorted_keys, u.scene_knobs
local usage_error = core.usage_error
local shorten, set_text = h._shorten, h._set_text -- a long value cut, "--set k=v" with it (init.lua)

local choice_mt = { __name = "hearth.choice" }
local function is_choice(v) return getmetatable(v) == choice_mt end

-- a word as messages and the listing show it: quoted, so the empty word reads ""
local function q(w) return '"' .. w .. '"' end

--- h.choice{"default", word = "what it means", other = "...", ...}: a word-valued parameter for
--- h.params. The first (array) item is the default; every other key is a valid word, its value a
--- short description that the refusal of a wrong word and `hearth run SCENE.lua --params` show.
--- The empty word is a word like any other: `[""] = "both"` (`--set only=`).
--- h.choice("default", words, more, ...): the same with the words of tables {word = "what it means", ...}
--- that scenes share (h.contact_words: a collider's modes; h.blend_words; h.library.sauce_words()),
--- merged with a scene's own: h.choice("mix", h.library.sauce_words(), {mix = "half mayo, half mustard"}).
function h.choice(t, ...)
  if type(t) == "string" and select("#", ...) > 0 then
    local c = { t }
    for i = 1, select("#", ...) do
      local w = select(i, ...)
      if type(w) ~= "table" then
        error(("h.choice(default, words, ...): argument %d is a %s, not a table {word = \"what it means\"}"):format(i + 1,
          type(w)), 2)
      end
      for k, v in pairs(w) do
        if k == 1 then error("h.choice(default, words, ...): a words table holds only word = \"what it means\" pairs", 2) end
        if c[k] ~= nil then error(("h.choice(default, words, ...): word %s given twice"):format(q(tostring(k))), 2) end
        c[k] = v
      end
    end
    t = c
  elseif type(t) ~= "table" or select("#", ...) > 0 then
    error('h.choice: expected {"default", word = "what it means", ...} or ("default", {word = "what it means", ...}, '
      .. '...)', 2)
  end
  if t[1] == nil then
    error('h.choice: the default comes first: h.choice{"default", word = "what it means", ...}', 2)
  end
  local words, n = {}, 0
  for k, v in pairs(t) do
    if k == 1 then -- the default, checked by h.params, where the parameter's name is known
    elseif type(k) ~= "string" then
      error(('h.choice: %s is not a word: one default comes first, then word = "what it means" pairs')
        :format(tostring(k)), 2)
    elseif type(v) ~= "string" or v == "" then
      error(('h.choice: word %s needs a short description (a non-empty string), got %s'):format(q(k),
        type(v) == "string" and q(v) or tostring(v)), 2)
    elseif k:find("[,%s=]") then
      error(('h.choice: word %s holds a comma, a space or =, which --set name=word cannot give'):format(q(k)), 2)
    else
      words[k], n = v, n + 1
    end
  end
  if n < 2 then error("h.choice: a choice needs at least two words, each with its description", 2) end
  return setmetatable({ default = t[1], words = words }, choice_mt)
end

local number_mt = { __name = "hearth.number" }
local function is_number(v) return getmetatable(v) == number_mt end

local function finite(x) return type(x) == "number" and x == x and x ~= math.huge and x ~= -math.huge end

-- a number as the messages and the listing show it (%.10g: 0.1 stays 0.1; nan without a sign)
local function num(x)
  if x ~= x then return "nan" end
  if math.type and math.type(x) == "integer" then return tostring(x) end
  return ("%.10g"):format(x)
end

-- A unit's top (#18): what the run itself takes in that unit. s:run takes no time past 1e12 s (its until_t and every,
-- run.lua), `hearth run --frames` no more than 1e6 frames (app/cmd_run.c), and the core no temperature past 5000 degC
-- (every temperature a scene sets, and the guard's range: core/sim/solver/guard.c), so a number declared in seconds,
-- frames or degC is refused past them by its own name and range ("--set until_t=1e300: until_t (...) takes a number
-- in (0, 1e+12] s"), not later by what the scene made of it ("s:run: every = 2.5e+299", naming no parameter). One
-- rule for every scene, not a max in each; a declared max or below under the top stands.
local unit_top = { s = 1e12, frames = 1e6, degC = 5000 }

--- h.number{default, min = a, max = b, above = a, below = b, integer = true, unit = "m", what = "meaning",
--- also = {[0] = "what 0 means"}}: a numeric parameter for h.params with its valid range. min and max are
--- inclusive bounds, above and below strict ones (above = 0: > 0); either end may be left open (no bound).
--- integer = true takes whole numbers only (counts: cups, frames). list = true takes one or more numbers, each in the
--- range (`--set ovens=190,150`; the default a list {190, 150, 110}); max_count = N takes at most N of them (each one
--- a cookie or a strip the scene lays out: `--set leaveners=` with 10000 numbers had built a tray 10000 cookies wide and
--- run out of time and memory instead of being refused). also lists values outside the range that
--- the scene gives a meaning of its own (0: the preset's; -1: Table 2's curve). unit and what are shown in the
--- refusal and in `hearth run SCENE.lua --params`; what is required (a short meaning), unit when the number has one.
--- unit = "s" (a time) tops the range at 1e12 s, unit = "frames" (a count of frames) at 1e6 and unit = "degC" at
--- 5000 degC: what the run takes.
function h.number(t)
  if type(t) ~= "table" then
    error('h.number: expected {default, min = a, max = b, unit = "m", what = "what it means"}', 2)
  end
  local n = { default = t[1] }
  for k, v in pairs(t) do
    if k == 1 then
    elseif k == "min" or k == "max" or k == "above" or k == "below" then
      if not finite(v) then error(("h.number: %s = %s is not a finite number"):format(k, tostring(v)), 2) end
      n[k] = v
    elseif k == "max_count" then
      if math.type(v) ~= "integer" or v < 1 then error(("h.number: max_count = a whole number >= 1, got %s")
        :format(tostring(v)), 2) end
      n[k] = v
    elseif k == "integer" or k == "list" then
      if type(v) ~= "boolean" then error(("h.number: %s = true or false, got %s"):format(k, tostring(v)), 2) end
      n[k] = v
    elseif k == "unit" or k == "what" then
      if type(v) ~= "string" or v == "" then error(("h.number: %s needs a non-empty string"):format(k), 2) end
      n[k] = v
    elseif k == "also" then
      if type(v) ~= "table" then error('h.number: also = {[value] = "what it means"}, got ' .. type(v), 2) end
      for x, m in pairs(v) do
        if not finite(x) or type(m) ~= "string" or m == "" then
          error('h.number: also = {[value] = "what it means"}: each key a finite number, each value a meaning', 2)
        end
      end
      n.also = v
    else
      error(("h.number: unknown key %s (default first, then min, max, above, below, integer, list, max_count, unit, what, also)")
        :format(tostring(k)), 2)
    end
  end
  if n.max_count and not n.list then error("h.number: max_count needs list = true", 2) end
  if n.min and n.above then error("h.number: give min or above, not both", 2) end
  if n.max and n.below then error("h.number: give max or below, not both", 2) end
  if not n.what then error('h.number: what = "a short meaning" is required (the refusal and --params show it)', 2) end
  local top = n.unit and unit_top[n.unit]
  if top and not ((n.max or n.below or math.huge) <= top) then n.max, n.below = top, nil end
  local lo, hi = n.min or n.above, n.max or n.below
  if lo and hi and not (lo < hi or (lo == hi and n.min and n.max)) then
    error(("h.number: the range from %s to %s is empty"):format(num(lo), num(hi)), 2)
  end
  if not (n.min or n.max or n.above or n.below or n.integer) then
    error("h.number: give a range (min, max, above, below) or integer = true", 2)
  end
  return setmetatable(n, number_mt)
end

local flag_mt = { __name = "hearth.flag" }
local function is_flag(v) return getmetatable(v) == flag_mt end

--- h.flag{default, what = "meaning"}: a true-or-false parameter for h.params with what it switches, which the refusal
--- of a value other than true or false and `hearth run SCENE.lua --params` show. A bare boolean default still works,
--- listed with no meaning (#18, helper userview3: the SPH cake's and bread's `water = true`, drying's `latent_heat =
--- false` and cookies' `water` and `baseline` were listed as a bare word, with nothing to say what they switch).
function h.flag(t)
  if type(t) ~= "table" or type(t[1]) ~= "boolean" then
    error('h.flag: expected {true or false, what = "what it switches"}', 2)
  end
  for k in pairs(t) do
    if k ~= 1 and k ~= "what" then error(("h.flag: unknown key %s (the default first, then what)"):format(tostring(k)), 2) end
  end
  if type(t.what) ~= "string" or t.what == "" then
    error('h.flag: what = "what it switches" is required (the refusal and --params show it)', 2)
  end
  return setmetatable({ default = t[1], what = t.what }, flag_mt)
end

-- n's range as the messages and the listing show it: "a number in (0, 0.05] m", "a whole number in [1, 20]"
local function range_text(n)
  local lo = n.min and ("[" .. num(n.min)) or n.above and ("(" .. num(n.above)) or "(-inf"
  local hi = n.max and (num(n.max) .. "]") or n.below and (num(n.below) .. ")") or "inf)"
  local unit = n.unit and (" " .. n.unit) or ""
  local r = (n.list and (n.integer and "whole numbers, each in " or "numbers separated by commas, each in ")
    or (n.integer and "a whole number in " or "a number in ")) .. lo .. ", " .. hi .. unit
  if n.min and n.min == n.max then r = "only " .. num(n.min) .. unit end
  if n.max_count then r = r .. ("; at most %d of them"):format(n.max_count) end
  if n.also then
    local ks = {}
    for x in pairs(n.also) do ks[#ks + 1] = x end
    table.sort(ks)
    for _, x in ipairs(ks) do r = r .. ("; or %s: %s"):format(num(x), n.also[x]) end
  end
  return r
end

local function in_range(n, x)
  if not finite(x) then return false end
  if n.also and n.also[x] then return true end
  return not ((n.min and x < n.min) or (n.above and x <= n.above) or (n.max and x > n.max)
    or (n.below and x >= n.below) or (n.integer and x ~= math.floor(x)))
end

-- A value x for the parameter `name` declared as number n: nil when valid, else the message (from `what`:
-- "--set dx=-1", the scene's default, or the script that passed it) naming the parameter, its meaning, its range.
local function number_error(n, name, x, what)
  local bad = x -- a list's first number out of range (or x itself when it is not a list)
  if n.list and n.max_count and type(x) == "table" and #x > n.max_count then
    return ("%s: %s (%s) takes %s, not a list of %d"):format(what, name, n.what, range_text(n), #x)
  end
  if n.list and type(x) == "table" and #x > 0 then
    bad = nil
    for i = #x, 1, -1 do if not in_range(n, x[i]) then bad = x[i] end end
    if bad == nil then return nil end
  elseif not n.list and in_range(n, x) then
    return nil
  end
  return ("%s: %s (%s) takes %s, not %s"):format(what, name, n.what, range_text(n),
    type(bad) == "number" and num(bad) or type(bad) == "table" and "an empty list" or shorten(bad))
end

-- The valid words of choice c, one a line, each with its description, sorted (the empty word first).
local function word_lines(c, indent)
  local ks, wide = sorted_keys(c.words), 0
  for _, w in ipairs(ks) do wide = math.max(wide, #w + 2) end
  local out = {}
  for _, w in ipairs(ks) do
    out[#out + 1] = ("%s%-" .. wide .. "s  %s"):format(indent, q(w), c.words[w])
  end
  return table.concat(out, "\n")
end

-- A word w for the parameter `name` declared as choice c: nil when valid, else the message (from
-- `what`: "--set tray=stiky", or the script that passed it) naming it, every valid word and the nearest.
local function word_error(c, name, w, what)
  if type(w) == "string" and c.words[w] then return nil end
  local near = type(w) == "string" and nearest(w, c.words)
  return ("%s: %s takes one of the words below, not %s%s\n%s"):format(what, name,
    type(w) == "string" and q(shorten(w)) or tostring(w), near and ("; did you mean " .. q(near) .. "?") or "", word_lines(c, "  "))
end

-- The scene author's own mistake: a default that is not one of its words (a plain error, exit 1).
local function check_default(c, name, level)
  local what = ("h.params: %s's default"):format(name)
  local m
  if is_number(c) then m = number_error(c, name, c.default, what) else m = word_error(c, name, c.default, what) end
  if m then error(m, level + 1) end
end

-- `hearth run SCENE.lua --params`: the scene's parameters, their defaults and, for a choice, its words.
local function value_text(v)
  if is_choice(v) then return q(v.default) end
  if is_number(v) or is_flag(v) then v = v.default end
  if type(v) == "number" then return num(v) end -- 40000, not 40000.0; 1e+10, not 10000000000.0
  if type(v) == "table" then
    local t = {}
    for i, x in ipairs(v) do t[i] = type(x) == "number" and num(x) or tostring(x) end
    return table.concat(t, ",")
  end
  if type(v) == "string" then return q(v) end
  return tostring(v)
end

local function list_params(defaults)
  local lines = { "parameters (--set name=value), with their defaults:" }
  for _, k in ipairs(sorted_keys(defaults)) do
    local v = defaults[k]
    lines[#lines + 1] = ("  %s = %s%s"):format(k, value_text(v), is_choice(v) and ", one of:" or "")
    if is_choice(v) then lines[#lines + 1] = word_lines(v, "      ") end
    if is_number(v) then lines[#lines + 1] = ("      %s: %s"):format(v.what, range_text(v)) end
    if is_flag(v) then lines[#lines + 1] = ("      %s: true or false"):format(v.what) end
  end
  h._list_knobs(lines, defaults)
end

-- the scene settings --set may change besides (h.scene's knobs that the scene does not declare itself), and the
-- stop of the listing
function h._list_knobs(lines, declared)
  local knobs = {}
  for k in pairs(scene_knobs) do
    if not (declared and declared[k] ~= nil) then knobs[k] = true end
  end
  lines[#lines + 1] = "scene settings --set may also change: " .. table.concat(sorted_keys(knobs), ", ")
    .. " (hearth help scene)"
  io.stdout:write(table.concat(lines, "\n"), "\n")
  h._listed = true -- h.scene raises it again, should a scene's pcall swallow the stop
  core.listed() -- ends the run here: exit 0, nothing simulated
end

-- `--set name=1,2.5,3`: the numbers, or a usage error naming the parameter
local function numbers(k, v)
  local t = {}
  for w in (v .. ","):gmatch("([^,]*),") do
    t[#t + 1] = tonumber(w) or usage_error(("%s: expected numbers separated by commas"):format(set_text(k, v)), 3)
  end
  return t
end

--- Named defaults that `hearth run scene.lua --set name=value` overrides.
--- A default that is a list of numbers takes `--set name=1,2.5,3`; a boolean `true` or `false`;
--- h.choice{"default", word = "what it means", ...} one of its words (refused otherwise, before the
--- scene makes anything, naming the scene file, the parameter, every word and the nearest);
--- h.number{default, min = , max = , unit = , what = , ...} a number in its range (refused otherwise, the same way,
--- naming the parameter, what it means, the value and the range with its unit); h.flag{default, what = } true or
--- false (refused otherwise, naming what it switches).
function h.params(defaults)
  if type(defaults) ~= "table" then error("h.params: expected a table of name = default", 2) end
  local P = {}
  h._param_names = {}
  for k, v in pairs(defaults) do
    if is_choice(v) or is_number(v) then
      check_default(v, k, 2)
      P[k] = v.default
    elseif is_flag(v) then
      P[k] = v.default
    else
      P[k] = v
    end
    h._param_names[k] = true
  end
  if core.options().list_params then list_params(defaults) end
  for k, v in pairs(core.options().sets) do
    local d = defaults[k]
    if d == nil and scene_knobs[k] then -- a scene setting, applied by h.scene / s:add / h.mix
    elseif d == nil then
      local near = nearest(k, defaults)
      usage_error(("--set %s: this scene has no parameter '%s'%s; valid names: %s"):format(k, k,
        near and ("; did you mean '" .. near .. "'?") or "", table.concat(sorted_keys(defaults), ", ")), 2)
    end
    if type(d) == "number" then
      P[k] = tonumber(v) or usage_error(("%s: expected a number"):format(set_text(k, v)), 2)
    elseif is_number(d) then
      local x = tonumber(v)
      if d.list then x = numbers(k, v) end
      local m = number_error(d, k, x or v, set_text(k, v))
      if m then usage_error(m, 2) end
      P[k] = x
    elseif is_flag(d) then
      if v ~= "true" and v ~= "false" then
        usage_error(("%s: %s (%s) takes true or false"):format(set_text(k, v), k, d.what), 2)
      end
      P[k] = v == "true"
    elseif is_choice(d) then
      local m = word_error(d, k, v, set_text(k, v))
      if m then usage_error(m, 2) end
      P[k] = v
    elseif type(d) == "table" then
      P[k] = numbers(k, v)
    elseif type(d) == "boolean" then
      if v ~= "true" and v ~= "false" then usage_error(("%s: expected true or false"):format(set_text(k, v)), 2) end
      P[k] = v == "true"
    else
      P[k] = v
    end
  end
  h._params_declared = true
  return P
end

--- A scene setting's value from --set (h.scene's knobs; s:add's ppc) checked against its range in the schema
--- (core.scene_settings' e: min, max, min_open, kind, help, unit): out of it, a usage error (exit 2) said as h.params
--- says its own numbers, where the scene's h.scene line had taken the blame as a scene error (exit 1; #18, helper
--- userview4). raw is the --set's text; returns its number.
function h._knob_in_range(e, raw)
  local x = tonumber(raw) or usage_error(("%s: expected a number"):format(set_text(e.name, raw)), 3)
  local unit = e.unit ~= "" and e.unit ~= "1" and e.unit or nil
  local n = { what = e.help, unit = unit, integer = e.kind ~= "real" or nil, max = e.max ~= math.huge and e.max or nil,
    min = not e.min_open and e.min > -math.huge and e.min or nil, above = e.min_open and e.min or nil }
  local m = number_error(n, e.name, x, set_text(e.name, raw))
  if m then usage_error(m, 3) end
  return x
end

--- A --set dx that leaves the scene's box shorter than 6 dx on an axis (the core's floor, core/sim/scene.c): a usage
--- error (exit 2) naming dx and the range this box takes, (0, shortest axis / 6] m, where the core's "box axis x spans
--- [0, 0.14] m; it must be at least 6 dx" blamed the box (exit 1) for the user's dx (#18, helpers userview4, userfix8).
--- One check for every scene whose dx --set gives (each scene's h.number for dx is declared before its box is known).
function h._dx_fits_box(def)
  local raw, box = core.options().sets.dx, def.box
  if raw == nil or box == nil or type(def.dx) ~= "number" then return end
  local dim, span, axis = def.dim or 2, math.huge, 1
  for k = 1, dim do
    local w = (box.hi[k] or 0) - (box.lo[k] or 0)
    if w < span then span, axis = w, k end
  end
  if def.dx * 6 > span then
    usage_error(("%s: dx (the grid spacing) takes a number in (0, %s] m in this scene, not %s: its box's %s axis spans "
      .. "%s m, at least 6 dx"):format(set_text("dx", raw), num(span / 6), num(def.dx), ("xyz"):sub(axis, axis),
      num(span)), 3)
  end
end

-- --set ppc, a knob of every s:add (not in the scene settings' schema)
h._ppc_knob = { name = "ppc", help = "particles per cell of every body", kind = "int", min = 1, max = 1000, unit = "" }

--- h.refuse(msg): a scene's own refusal of its parameters where h.params's ranges cannot say it, a check across two
--- of them (pull_twist's speed against its E, marshmallow's press against its speed): a usage error as h.params's
--- (exit 2 in hearth run, no traceback) at the scene's line. error() had given exit 1, the code of a scene's own fault.
function h.refuse(msg)
  if type(msg) ~= "string" then error("h.refuse: expected the message (a string), got " .. type(msg), 2) end
  usage_error(msg, 2)
end

--- h.scene_path(rel): rel as a path from the folder of the scene file hearth runs (hl_options.scene_dir; with no scene
--- file, the folder hearth runs in), an absolute path as it is. A script that runs a shipped scene by dofile names it
--- so and runs from any folder (#18, helper userfix10: scripts/validation/loaf_whatif.lua's
--- "scripts/scenes/baking/loaf_physical.lua" was read from the working folder, so only from the source root). It only
--- makes a path: what a scene may read is the sandbox's rule, unchanged (docs/security.md).
function h.scene_path(rel)
  if type(rel) ~= "string" or rel == "" then
    local got = rel == "" and '""' or type(rel)
    error("h.scene_path: expected a path relative to the scene file's folder, got " .. got, 2)
  end
  if rel:sub(1, 1) == "/" then return rel end
  return (core.options().scene_dir or ".") .. "/" .. rel
end

--- For a script that runs a shipped scene (dofile) after parsing its own h.params P, a superset of the scene's
--- names so that every --set reaches it: from here on the scene's h.params returns P's value of each name it
--- declares, and its own default for a name P does not know (a parameter the scene gained after the script).
--- The scene's h.choice words and h.number ranges still hold: a value of P that the scene does not take is refused
--- there, naming the scene's file and line (a usage error when --set gave it, else the script's mistake).
function h.pass_params(P)
  if type(P) ~= "table" then error("h.pass_params: expected the table h.params returned, got " .. type(P), 2) end
  h.params = function(defaults)
    if type(defaults) ~= "table" then error("h.params: expected a table of name = default", 2) end
    local Q = {}
    for k, v in pairs(defaults) do
      local refusal = is_choice(v) and word_error or is_number(v) and number_error -- a declared word or number
      if refusal then
        check_default(v, k, 2)
        local x = P[k]
        if x == nil then
          x = v.default
        else
          local given = core.options().sets[k]
          local m = refusal(v, k, x, given and set_text(k, given)
            or ("%s = %s, passed by the script's h.pass_params"):format(k, is_choice(v) and q(tostring(x)) or tostring(x)))
          if m and given then usage_error(m, 2) elseif m then error(m, 2) end
        end
        Q[k] = x
      elseif is_flag(v) then -- a wrapper's own value must be a boolean too
        local x = P[k]
        if x == nil then x = v.default end
        if type(x) ~= "boolean" then
          error(("%s = %s, passed by the script's h.pass_params: %s (%s) takes true or false"):format(k, tostring(x), k,
            v.what), 2)
        end
        Q[k] = x
      elseif P[k] == nil then
        Q[k] = v
      else
        Q[k] = P[k]
      end
    end
    return Q
  end
end

end

-- hearth.library: the preset tables of h.library: the sauces of Nagasawa et
-- al. Table 1 (h.library.sauce) and the doughs of Ding et al. Table 2 in the
-- paper's animation units (h.library.paper, paper_oven) and in physical units
-- (h.library.dough, oven). The numbers live in assets/sauces.csv,
-- dough.lua and dough_physical.lua; this file only looks them up, with an
-- error naming the valid presets. Loaded by init.lua:
-- (require "hearth.library")(h, core, {nearest = ..., sorted_keys = ...}).

return function(h, core, u)
local nearest, sorted_keys = u.nearest, u.sorted_keys

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

--- h.library.sauce_words(): every sauce's name with its Table 1 label and numbers, for a scene's parameter
--- that picks one: h.params{sauce = h.choice("mayo", h.library.sauce_words())}.
function h.library.sauce_words()
  local _ = h.library.sauce.honey -- loads the table (a sauce every Table 1 has)
  local words = {}
  for name, s in pairs(rawget(h.library.sauce, "_all")) do
    words[name] = ("%s, Table 1: eta %g Pa s, sigma_y %g Pa, h %g"):format(s.label, s.eta, s.sigma_y, s.h)
  end
  return words
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
end

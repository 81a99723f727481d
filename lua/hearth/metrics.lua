-- hearth.metrics: the numbers `hearth trade` and `hearth run --metric` measure
-- at the end of a run: h.metric (a scene's own), h.builtin_metrics and
-- h._metric. Loaded by init.lua: (require "hearth.metrics")(h, {nearest = ..., sorted_keys = ...}).

return function(h, u)
local nearest, sorted_keys = u.nearest, u.sorted_keys

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
end

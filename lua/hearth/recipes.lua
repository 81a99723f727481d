-- hearth.recipes: scene-building steps that come up again and again.
--   local R = h.recipes; R.tray(s, 0.01, { temperature = 180, beta = 35 })
local core = ...
local R = {}

--- A preset oven's pan as s:collider's keys: pan_temperature and pan_beta; for a pan that goes in cold,
--- pan_start_temperature and pan_warm_time (the scene's time); for one the food draws its heat from,
--- pan_heat_capacity (J/(m^2 K)) over `area` (m^2; 2D: m per metre of depth), left out without a warm time. `extra`'s
--- keys (shape, mode, friction, another temperature) go over these. Every pan of a physical preset (the loaf's and
--- the cookie's sheet, the muffin's tin, the lava cake's mould) is made from it.
function R.pan(oven, area, extra)
  if type(oven) ~= "table" then
    error(("h.recipes.pan: oven is a preset oven's table (h.library.oven.<name>), not %s"):format(type(oven)), 2)
  end
  local C = oven.pan_warm_time and oven.pan_heat_capacity
  local o = { temperature = oven.pan_temperature, beta = oven.pan_beta, start_temperature = oven.pan_start_temperature,
    warm_time = oven.pan_warm_time, heat_capacity = C, area = C and area or nil }
  for k, v in pairs(extra or {}) do o[k] = v end
  return o
end

--- A flat tray (a plane collider at height y), optionally heated.
--- opts: mode ("separate"), friction (0.4), temperature (degC), beta (W/(m^2 K)), and for a tray that goes in
--- cold start_temperature (degC) and warm_time (s, the scene's time: a scaled preset's real seconds over its S), and
--- for one the food draws its heat from heat_capacity (J/(m^2 K)) and area (m^2; 2D: m) (s:collider's).
function R.tray(s, y, opts)
  opts = opts or {}
  return s:collider { shape = core.plane({ 0, y, 0 }, { 0, 1, 0 }), mode = opts.mode or "separate",
    friction = opts.friction or 0.4, temperature = opts.temperature, beta = opts.beta,
    start_temperature = opts.start_temperature, warm_time = opts.warm_time, heat_capacity = opts.heat_capacity,
    area = opts.heat_capacity and opts.area or nil }
end

--- A muffin cup and its batter (scripts/scenes/baking/muffins.lua, Ding Fig. 2; tear_open.lua bakes one
--- the same way): a heated cup open at the top (h.cup: its base the inside of the floor, the floor below it;
--- in 2D its section is a U) and the batter filling it to the walls from the floor up.
--- o: dim, x (the cup's axis), base (the inner floor's y), radius, height (the wall above the floor), wall (wall and
--- floor thickness), fill (the batter's depth), zc (3D: the axis' z), material, oven (a preset's oven: pan
--- temperature and beta, and for a tin that goes in cold pan_start_temperature and pan_warm_time as R.tray's
--- start_temperature and warm_time, and pan_heat_capacity as its heat_capacity over the cup's inside; dough temperature,
--- saturation), mode (the cup's contact), ppc. Returns the cup's
--- collider.
function R.muffin_cup(s, o)
  local d3 = o.dim == 3
  local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
  -- a tin the batter draws its heat from (the oven's pan_heat_capacity): the cup's metal as one lumped sheet, its area
  -- the inside's floor and wall (2D: per metre of depth, the U's floor and two walls)
  local area = d3 and math.pi * o.radius * (o.radius + 2 * o.height) or 2 * (o.radius + o.height)
  local cup = s:collider(R.pan(o.oven, area, { mode = o.mode, friction = 0.3,
    shape = core.cup(v(o.x, o.base, o.zc), { 0, 1, 0 }, o.radius, o.height, o.wall, o.wall) }))
  local inner = d3 and core.cylinder(v(o.x, o.base + o.fill / 2, o.zc), { 0, 1, 0 }, o.radius, o.fill / 2)
    or core.box({ o.x - o.radius, o.base }, { o.x + o.radius, o.base + o.fill })
  s:add { shape = inner, material = o.material, temperature = o.oven.dough_temperature, saturation = o.oven.saturation,
    ppc = o.ppc }
  return cup
end

--- A loaf's shape (scripts/scenes/baking/bread.lua, Ding Fig. 15; tear_open.lua bakes one the same way): a box of
--- width w standing `body` high on y = tray with a round top of radius w/2 (2D: h.shapes.loaf), in 3D extruded
--- along z over zc +- zw/2.
function R.loaf_shape(dim, x, tray, w, body, zc, zw)
  if dim ~= 3 then return require("hearth.shapes").loaf({ x, tray }, w, body) end
  return core.box({ x - w / 2, tray, zc - zw / 2 }, { x + w / 2, tray + body, zc + zw / 2 }) +
    core.cylinder({ x, tray + body, zc }, { 0, 0, 1 }, w / 2, zw / 2) -
    core.box({ x - w, tray - w, 0 }, { x + w, tray, 2 * zc })
end

--- Centres of an n x m arrangement filling lo..hi (row-major, x fastest):
--- for the 3 x 3 grids of samples the papers show.
function R.grid(n, m, lo, hi)
  local out = {}
  for j = 1, m do
    for i = 1, n do
      out[#out + 1] = { lo[1] + (i - 0.5) * (hi[1] - lo[1]) / n, lo[2] + (j - 0.5) * (hi[2] - lo[2]) / m }
    end
  end
  return out
end

--- The height of the material above y0 along the vertical line at x
--- (the highest sample where the density probe finds material).
function R.height(s, x, y0, y1, n)
  n = n or 200
  local d = s:line("density", { x, y0 }, { x, y1 }, n + 1)
  local top = nil
  for i, v in ipairs(d) do
    if v == v then top = y0 + (i - 1) * (y1 - y0) / n end
  end
  return top and (top - y0) or 0
end

--- The height above y0 of the lowest material along the vertical line at x: the top of the first run of samples
--- with material, going up from y0 (0 when there is none). Material above a gap (drops on a
--- celery stick lifted out of its dip, a crumb in the air) is not the surface, where R.height reads the highest
--- (#18, helper userview4: celery_dip.lua's "sauce surface" read the drops on the celery, 71 mm for a 25 mm bath).
function R.surface(s, x, y0, y1, n)
  n = n or 200
  local d = s:line("density", { x, y0 }, { x, y1 }, n + 1)
  local top = nil
  for i, v in ipairs(d) do
    if v == v then top = y0 + (i - 1) * (y1 - y0) / n elseif top then break end
  end
  return top and (top - y0) or 0
end

--- A nozzle (Nagasawa et al. 2019, Fig. 8) in a 2D scene: a slot of `width`
--- centred at x whose exit is at height y, extruding `material` downwards at
--- `speed` from time `from` to `to`. Every spacing / speed seconds one row of
--- particles (spacing = dx / sqrt(ppc)) leaves the slot; rows sit on the
--- seeding lattice, so the stream is evenly filled. Returns the number of rows.
--- The nozzle's two walls are a collider (separate, no friction), wall thick
--- and length long, from 2 dx above the exit up: frames and the dashboard draw
--- it as they draw the other colliders, and material that piles back up to the
--- nozzle meets it. No grid node the falling stream reaches lies in the walls,
--- so the stream is the one the nozzle gave without them (the fronts of
--- nozzle.lua are unchanged to the last digit).
--- opts: x, y, width, speed, material, dx (the scene's), from (0), to, ppc (4),
--- walls (true), wall (max(dx, width / 4), m), length (2 width, m).
function R.nozzle(s, o)
  for _, k in ipairs { "x", "y", "width", "speed", "dx", "to" } do
    if type(o[k]) ~= "number" then error(("recipes.nozzle: %s (a number) is required"):format(k), 2) end
  end
  if o.material == nil then error("recipes.nozzle: material is required", 2) end
  if not (o.speed > 0 and o.width > 0 and o.dx > 0) then error("recipes.nozzle: speed, width and dx must be > 0", 2) end
  local ppc = o.ppc or 4
  local hp = o.dx / math.floor(math.sqrt(ppc) + 0.5)
  local y = math.floor(o.y / hp + 0.5) * hp
  local period, from = hp / o.speed, o.from or 0
  local rows = math.floor((o.to - from) / period)
  local shape = core.box({ o.x - o.width / 2, y }, { o.x + o.width / 2, y + hp })
  if o.walls ~= false then
    local t, len = o.wall or math.max(o.dx, o.width / 4), o.length or 2 * o.width
    local l, r, yb = o.x - o.width / 2, o.x + o.width / 2, y + 2 * o.dx
    s:collider { shape = core.union(core.box({ l - t, yb }, { l, yb + len }), core.box({ r, yb }, { r + t, yb + len })),
      mode = "separate", friction = 0 }
  end
  local function emit(sc)
    sc:add { shape = shape, material = o.material, ppc = ppc, jitter = 0, velocity = { 0, -o.speed } }
  end
  for k = 0, rows - 1 do s:at(from + k * period, emit) end
  return rows
end

--- How far material reaches along a line: samples the density from `a`
--- along the unit direction `dir` for `len` metres every `step` metres and
--- returns the distance of the last sample inside the material (0 if none).
function R.reach(s, a, dir, len, step)
  local n = math.floor(len / step) + 1
  local b = { a[1] + len * dir[1], a[2] + len * dir[2], (a[3] or 0) + len * (dir[3] or 0) }
  local d = s:line("density", a, b, n)
  local f = 0
  for j, v in ipairs(d) do if v == v then f = (j - 1) * len / (n - 1) end end
  return f
end

return R

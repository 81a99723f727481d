-- hearth.run: s:run and its outputs: frames (png), CSV series with probes,
-- particle dumps (vtu with a .pvd collection, ply) and movies. Loaded by
-- init.lua, which passes the scene methods and the checking helpers it shares:
--   (require "hearth.run")(S, {check_keys = ..., check_number = ..., ...})
-- Errors point at the scene's line (level 2 from a method, 3 from a check
-- called by one), as in init.lua.
local core = ...

return function(S, u)
local check_keys, check_number, check_vec, nearest = u.check_keys, u.check_number, u.check_vec, u.nearest
local fire_events, host_yield = u.fire_events, u.host_yield
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
  range = true, colormap = true, time_scale = true, label = true, region = true, depth = true }
local png_keys = { kind = true, width = true, height = true, axis = true, at = true, range = true, colormap = true, grow = true,
  time_scale = true, label = true, region = true, depth = true }

-- The scene's clock (h.scene's time_scale and time_units; #18, helper userfix10): the real seconds a simulated second
-- stands for, or Ding et al.'s Table 2 animation units, which no real time measures. Pictures without their own
-- time_scale take the scene's, and the dashboard's status line reads both (hearth_lua.c hl_scene_clock), so a frame
-- and the dashboard say the same time.
function S:_clock(time_scale, units)
  if units == "animation" and time_scale ~= 1 then
    error(("h.scene: time_units = \"animation\" has no real time; time_scale = %s asks for one (leave it at 1)")
      :format(time_scale), 3)
  end
  local st = self:_state()
  st.time_scale, st.time_units = time_scale, units
end

-- s:png checks its options here first, for the "did you mean" (the C method checks again)
local raw_png = S.png
function S:png(field, path, opts)
  if type(opts) == "table" then check_keys(opts, png_keys, "s:png") end
  local scale = self:_state().time_scale
  if scale and scale ~= 1 and (opts == nil or type(opts) == "table" and opts.time_scale == nil) then
    local o = { time_scale = scale } -- the scene's clock (S:_clock), where the picture gives none
    for k, v in pairs(opts or {}) do o[k] = v end
    opts = o
  end
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
    local ts = o.png.time_scale -- likewise
    if ts ~= nil and not (type(ts) == "number" and ts > 0 and ts <= 1e9) then
      error(("s:run: png: time_scale = %s; valid range (0, 1e9], the real seconds one simulated second stands for")
        :format(ts ~= ts and "nan" or tostring(ts)), 3)
    end
    local lb = o.png.label -- likewise: its length and characters are hearth_render's to check, at the first frame
    if lb ~= nil and type(lb) ~= "string" then
      error(("s:run: png: label = a short text before the time in each frame's title (a string), got %s"):format(type(lb)), 3)
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


-- ---- errors of outputs during a run -----------------------------------------
-- An output that fails while the run goes (a field the scene does not have, a
-- folder that does not exist, a bad range, a colormap) is the scene's mistake:
-- its message names the scene's s:run line and the output, not the line of
-- this file that wrote the frame (error(msg, 2) in a method points at its
-- caller, which during a run is this file). Marked errors (guard stops,
-- interrupts) are objects and pass unchanged.

-- "scene.lua:12: ": the first caller of s:run outside the hearth module (a
-- recipe's s:run is the scene's line that called the recipe).
local function scene_where()
  local first
  for level = 4, 16 do -- 1 pcall, 2 this function, 3 s:run, 4 its caller
    local _, w = pcall(error, "", level)
    if w == "" then break end
    first = first or w
    if not w:find("^%[hearth%]/") then return w end
  end
  return first or ""
end

local function rethrow(where, what, ok, ...)
  if ok then return ... end
  local e = ...
  if type(e) ~= "string" then error(e, 0) end
  e = e:gsub("^%[hearth%]/[^:]*:%d+: ", "")
  e = e:gsub("^s:" .. what .. ": ", ""):gsub("^" .. what .. ": ", "")
  error(("%ss:run: %s: %s"):format(where, what, e), 0)
end

-- fn(...) for output what ("png", "vtu", ...), its error placed at where
local function output(where, what, fn, ...) return rethrow(where, what, pcall(fn, ...)) end

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

-- A scene restored by h.load continues the VTU series its saved run left in the output folder: the first s:run
-- of a pattern keeps the .pvd's frames before the scene's time t0 (numbered 0, 1, ... by this pattern, as a run
-- writes them) and numbers on after them, where it started at 0 and wrote over the first leg's frames and
-- collection (#18, helper userview5). A .pvd that is not such a series, or none, starts afresh, as before.
local function continue_pvd(state, pattern, pvd, t0)
  local text = core.read_text(pvd)
  if not text then return end
  local list = {}
  for ts, file in text:gmatch('<DataSet timestep="([^"]*)"[^>]-file="([^"]*)"') do
    local t = tonumber(ts)
    local own = pattern:format(#list):match("([^/]*)$")
    -- not this pattern's series (under mpirun a frame is its .pvtu index)
    if not t or (file ~= own and file ~= own:gsub("%.vtu$", ".pvtu")) then return end
    if t < t0 then list[#list + 1] = { t, file } end
  end
  state.count, state.list = #list, list
end

-- A restored scene's PNG frames and PLY dumps continue the same way (#18, helper restartkeep): the first s:run of
-- a pattern keeps the files pattern % 0, 1, ... that exist and were drawn before the checkpoint, and numbers on
-- after them. Each file says when it was drawn: a PLY's header its time ("comment hearth t=", %.17g, exact), a PNG's
-- title its step (render.c writes "step N)" in every title; its time is in %.4g). before(head) reads a file's first
-- 8 KB (the PNG's title chunk is written before the image, the PLY's header before the particles).
local function kept_frames(pattern, before)
  local conv = 0
  for _ in pattern:gmatch("%%0?%d*d") do conv = conv + 1 end
  local _, pct = pattern:gsub("%%", "")
  if conv ~= 1 or pct ~= 1 then return 0 end -- not a numbered series (one file drawn over, or the run refuses it)
  local n = 0
  while true do
    local head = core.read_text(pattern:format(n), 8192)
    if not head or not before(head) then return n end
    n = n + 1
  end
end

local function png_before(step0)
  return function(head)
    local title = head:match("iTXtTitle\0[\0\1][\0\1]\0\0([^\0]*)") -- keyword, flag, method, empty language keys
    local step
    for n in (title or ""):gmatch("step (%d+)%)") do step = tonumber(n) end
    return step ~= nil and step < step0
  end
end

local function ply_before(t0)
  return function(head)
    local t = tonumber(head:match("^ply\n[^\0]-\ncomment hearth t=([^\n]*)\n") or "")
    return t ~= nil and t < t0
  end
end

-- A restored scene's s:run{csv = ...} keeps the rows the saved run wrote before the checkpoint's time (t_s, in the
-- %.9g the rows are written in, so the checkpoint's own row is the new leg's) and appends after them; the file is
-- rewritten whole at each frame (atomically), as before. A file whose header is not this run's starts afresh.
local function continue_csv(path, rows, t0)
  local text = core.read_text(path)
  if not text then return rows end
  local lines = {}
  for line in text:gmatch("[^\n]+") do lines[#lines + 1] = line end
  if lines[1] ~= rows[1] then return rows end
  local cut, kept = tonumber(("%.9g"):format(t0)), { rows[1] }
  for i = 2, #lines do
    local t = tonumber(lines[i]:match("^[^,]*"))
    if not t then return rows end -- not a series s:run wrote
    if t < cut then kept[#kept + 1] = lines[i] end
  end
  return kept
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
      if not st.dumps[key] then
        st.dumps[key] = { count = 0, list = {} }
        if kind == "vtu" and st.restored then continue_pvd(st.dumps[key], path, pvd_path(path, d.pvd), t0) end
        if kind == "ply" and st.restored then st.dumps[key].count = kept_frames(path, ply_before(t0)) end
      end
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
local function dumps_write(self, specs, t, force, where)
  for _, d in ipairs(specs) do
    if force or t >= d.next - 1e-9 * d.every then
      local path = d.path:format(d.state.count)
      if d.kind == "vtu" then
        -- under mpirun a .pvtu index of one piece per rank (docs/outputs.md)
        local file = output(where, "vtu", self._vtu_frame, self, path)
        d.state.list[#d.state.list + 1] = { t, file:match("([^/]*)$") }
        output(where, "vtu", core.write_atomic, d.pvd, pvd_text(d.state.list), "s:run{vtu = ...}")
      else
        output(where, "ply", self.ply, self, path, d.opts)
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

local function movie_write(st, mv, first, where)
  -- a later s:run with the same movie and frames continues it
  st.movie_first = st.movie_first or {}
  local key = mv.path .. "\0" .. mv.pattern
  st.movie_first[key] = st.movie_first[key] or first
  local from = st.movie_first[key]
  if st.frame > from then output(where, "movie", core.movie, mv.pattern, from, st.frame - from, mv.path, mv.fps) end
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
  local where = scene_where()
  local opts = core.options()
  local mv = movie_option(o, opts)
  local t0 = self:_time()
  local until_t = opts.until_t or o.until_t
  local cut = opts.until_t ~= nil -- the end is --until's (below: it gets a frame)
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
    -- every column says its unit in its name, as the shipped scenes' CSVs do (tests/scene_csv.py's rule): t_s and
    -- dt_s simulated seconds; the kinetic energy J in 3D, J per metre of depth in 2D (a plane scene's mass is per
    -- metre: #18, helper userfix7, where it read a bare "kinetic"); a probe's field with its unit (speed_m_s@x:y:z,
    -- a dimensionless field's name alone)
    local head = { "t_s", "step", "dt_s", "particles", st.dim == 2 and "kinetic_J_per_m" or "kinetic_J", "max_speed_m_s" }
    for _, p in ipairs(probes) do
      local v = check_vec(p[2], "s:run: probe point")
      local unit = core.field_unit(p[1])
      unit = (unit and unit ~= "1" and unit ~= "") and "_" .. unit:gsub("%^", ""):gsub("/", "_") or ""
      head[#head + 1] = ("%s%s@%g:%g:%g"):format(p[1], unit, v[1], v[2], v[3])
    end
    rows = { table.concat(head, ",") }
    st.csv_continued = st.csv_continued or {}
    if st.restored and not st.csv_continued[o.csv] then rows = continue_csv(o.csv, rows, t0) end
    st.csv_continued[o.csv] = true
  end
  local movie_from -- a movie of a continued series is the whole series', both legs', not the second leg's over it
  if o.png and st.restored and not st.png_continued then -- the first leg's frames stay (kept_frames above)
    local kept = kept_frames(o.png.path or "frame_%04d.png", png_before(self:stats().step))
    if kept > 0 and st.frame == 0 then st.frame, movie_from = kept, 0 end
  end
  if o.png then st.png_continued = true end
  local function frame()
    local stt = self:stats()
    local fr = setmetatable({ t = stt.t, index = st.frame, scene = self }, frame_mt)
    if o.png then
      local pf = o.png
      local field = pf.field or default_field(self)
      -- frames compare: a field without a fixed range (and no range given)
      -- keeps the range its frames have drawn so far, widened as needed
      st.png_range = st.png_range or {}
      local _, info = output(where, "png", self.png, self, field, frame_path(fr, pf.path or "frame_%04d.png"),
        { kind = pf.kind or "particles", width = pf.width, height = pf.height, axis = pf.axis, at = pf.at,
          range = pf.range, colormap = pf.colormap, grow = st.png_range[field], time_scale = pf.time_scale,
          label = pf.label, region = pf.region, depth = pf.depth })
      if info then st.png_range[field] = info.range end
    end
    if rows then
      local r = { ("%.9g"):format(stt.t), stt.step, ("%.6g"):format(stt.dt), stt.particles,
        ("%.9g"):format(stt.kinetic), ("%.9g"):format(stt.max_speed) }
      for _, p in ipairs(probes) do
        local v = output(where, "probes", self.probe, self, p[1], p[2])
        local m = v
        if type(v) == "table" then -- a vector's magnitude, a tensor's Frobenius norm
          m = 0
          for _, c in ipairs(v) do m = m + c * c end
          m = math.sqrt(m)
        end
        -- outside the material a probe reads NaN: an empty cell, "not measured", as the shipped scenes' CSVs write
        -- it (tests/scene_csv.py), where "nan" is text to some readers (#18, helper userview4)
        r[#r + 1] = m == m and ("%.9g"):format(m) or ""
      end
      rows[#rows + 1] = table.concat(r, ",")
      output(where, "csv", core.write_atomic, o.csv, table.concat(rows, "\n") .. "\n", "s:run{csv = ...}")
    end
    if o.on_frame then o.on_frame(fr) end
    st.frame = st.frame + 1
  end
  fire_events(self)
  -- the progress line's rate and ETA are this run's, not the process's (cookies.lua's second oven read 213 steps/s
  -- for its 1900)
  core.progress(self:_time(), until_t, self:stats().step, "start")
  local first_frame = st.frame
  frame()
  local dumps = run_dumps(self, o, opts, t0, every)
  dumps_write(self, dumps, t0, false, where)
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
    -- the end's frame: a run that started a step past a multiple of every (a scene's one s:step before its
    -- run, for an SPH density: 0.3 ms of 0.1 s frames) ends that sliver short of its last frame; a frame due
    -- within 1% of every after the end is the end's, or the run would show no end state. An end set by
    -- --until is the user's: it always gets its frame and dumps (the scenes take every from their own until_t,
    -- so --until 0.05 under 0.1 s frames showed t = 0 alone); one due there anyway is written once.
    local at_end = stt.t >= until_t - 1e-12 * math.max(1, until_t)
    local ends_frame = at_end and (cut or next_frame - until_t < 0.01 * every)
    if stt.t >= next_frame - 1e-9 * every or at_rest or ends_frame then
      frame() -- a run that stops at rest ends with a frame of the rest state
      next_frame = next_frame + every
    end
    dumps_write(self, dumps, stt.t, at_rest or (cut and at_end), where)
    core.progress(stt.t, until_t, stt.step, false)
  end
  local stt = self:stats()
  core.progress(stt.t, until_t, stt.step, true)
  if mv then movie_write(st, mv, movie_from or first_frame, where) end
  st.ran = true
  if rest then stt.at_rest = at_rest end
  return stt
end
end

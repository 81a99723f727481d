-- lua_events: s:at events (push, cut, press), collider motion functions,
-- and the query methods. Lines "check NAME ok|FAIL ..." are read by the test.
local h = require "hearth"
local P = h.params { push = 1.5 } -- m/s given to the resting ball
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, seed = 5 }
local jelly = h.material("elastic", { E = 3e4, nu = 0.3, density = 1000 })
local block = s:add { shape = h.box({ 0.15, 0.1 }, { 0.45, 0.3 }), material = jelly, ppc = 4 }
local ball = s:add { shape = h.disc({ 0.75, 0.25 }, 0.08), material = jelly, ppc = 4 }
s:collider { shape = h.plane({ 0, 0.1 }, { 0, 1 }), mode = "sticky" }
-- a press above the block: still until 0.03 s, then down at 0.5 m/s from its velocity function
local calls, last_call_t, backwards = 0, -1, false
local press = s:collider { shape = h.box({ 0.1, 0.36 }, { 0.5, 0.5 }), mode = "separate",
  velocity = function(t)
    calls = calls + 1
    if t < last_call_t - 1e-12 then backwards = true end
    last_call_t = t
    return t >= 0.03 and { 0, -0.5 } or { 0, 0 }
  end }

local function check(name, ok, detail)
  print(("check %s %s %s"):format(name, ok and "ok" or "FAIL", detail or ""))
end
local function top_of_block() -- highest particle within 2 cm of x = 0.3 (under the press)
  local x, top = s:positions(), 0
  for i = 1, #x, 3 do
    if math.abs(x[i] - 0.3) < 0.02 and x[i + 1] < 0.6 and x[i + 1] > top then top = x[i + 1] end
  end
  return top
end

local fired = {}
local function event(name, t_req, fn)
  s:at(t_req, function(sc)
    local st = sc:stats()
    fired[name] = (fired[name] or 0) + 1
    print(("event %s requested %.6f fired %.6f dt %.6g"):format(name, t_req, st.t, st.dt))
    check("time_" .. name, st.t >= t_req - 1e-9 and st.t - t_req <= st.dt + 1e-9,
      ("t = %.9g, requested %.9g, dt %.3g"):format(st.t, t_req, st.dt))
    fn(sc)
  end)
end

event("push", 0.01, function(sc)
  local ke_before = sc:stats().kinetic
  sc:push(ball, { P.push, 0 })
  local v = sc:probe("velocity", { 0.75, 0.25 })
  check("push_velocity", type(v) == "table" and math.abs(v[1] - P.push) < 1e-6 and #v == 3,
    ("v = %s"):format(type(v) == "table" and table.concat(v, ",") or tostring(v)))
  check("push_max_speed", sc:stats().max_speed >= P.push - 1e-9, tostring(sc:stats().max_speed))
  -- the ball (about 20 kg/m) now carries 1/2 m v^2: stats must count it (the guard's reference does)
  check("push_kinetic", sc:stats().kinetic > ke_before + 1, ("%.4g J before, %.4g J after"):format(ke_before,
    sc:stats().kinetic))
end)

event("cut", 0.02, function(sc)
  local before, before_block, before_ball = sc:stats().particles, sc:body_particles(block), sc:body_particles(ball)
  local n = sc:cut(h.box({ 0.15, 0.05 }, { 0.25, 0.5 }))
  local after = sc:stats().particles
  print(("cut removed %d: %d -> %d, block %d -> %d"):format(n, before, after, before_block, sc:body_particles(block)))
  check("cut_count", math.type(n) == "integer" and n > 0 and after == before - n, ("n = %s"):format(tostring(n)))
  check("cut_body", sc:body_particles(block) == before_block - n and sc:body_particles(ball) == before_ball)
  local n2 = sc:cut(h.box({ 0.15, 0.05 }, { 0.25, 0.5 }))
  check("cut_again_zero", n2 == 0, tostring(n2))
end)

local top_before_press
event("move", 0.03, function(sc)
  top_before_press = top_of_block()
  sc:move(press, { 0, -0.075 }) -- the press jumps down onto the block (2 cm in), then its velocity takes over
end)

local calls_at_stop
event("stop", 0.05, function(sc)
  sc:collider_velocity(press, { 0, 0 }) -- constant velocity: the function is no longer called
  calls_at_stop = calls
end)

-- an event in the past fires at once, and a step-driven scene fires events too
local stats0 = s:stats()
check("stats_keys", type(stats0.t) == "number" and math.type(stats0.step) == "integer" and type(stats0.dt) == "number"
  and math.type(stats0.particles) == "integer" and type(stats0.kinetic) == "number"
  and type(stats0.max_speed) == "number" and type(stats0.fields) == "table" and type(stats0.guard) == "string")
check("stats_initial", stats0.t == 0 and stats0.step == 0 and stats0.guard == "ok" and stats0.particles > 100
  and stats0.kinetic == 0, ("t=%g step=%d guard=%s particles=%d"):format(stats0.t, stats0.step, stats0.guard, stats0.particles))
local has = {}
for _, f in ipairs(stats0.fields) do has[f] = true end
check("stats_fields", has.velocity and has.speed and has.density and not has.temperature, table.concat(stats0.fields, " "))

local res = s:run { until_t = 0.07, every = 0.01 }
print(("run ended t=%.6f step=%d particles=%d"):format(res.t, res.step, res.particles))
for _, name in ipairs { "push", "cut", "move", "stop" } do
  check("fired_once_" .. name, fired[name] == 1, tostring(fired[name]))
end
local top_after = top_of_block()
print(("press: block top %.4f before, %.4f after; motion calls %d (at stop %d)"):format(top_before_press, top_after,
  calls, calls_at_stop))
check("press_moved_block", top_after < top_before_press - 0.01, ("%.4f -> %.4f"):format(top_before_press, top_after))
check("motion_called", calls > 0 and not backwards and last_call_t <= 0.05 + 1e-9, ("calls %d last t %.6g"):format(calls, last_call_t))
check("motion_stopped", calls == calls_at_stop, ("%d calls after collider_velocity"):format(calls - calls_at_stop))

-- step-driven: an event fires within one step of its time
local t_now = s:stats().t
event("stepped", t_now + 0.0025, function() end)
s:step(40)
check("fired_once_stepped", fired.stepped == 1, tostring(fired.stepped))

-- probes, lines and slices
local sp = s:probe("speed", { 0.3, 0.2 })
check("probe_scalar", type(sp) == "number" and sp == sp and sp >= 0, tostring(sp))
local empty = s:probe("speed", { 0.5, 0.9 })
check("probe_empty_nan", empty ~= empty, tostring(empty))
local line = s:line("velocity", { 0.1, 0.2 }, { 0.9, 0.2 }, 17)
check("line_shape", #line == 17 and type(line[1]) == "table" and #line[1] == 3, tostring(#line))
local dl = s:line("density", { 0.3, 0.15 }, { 0.3, 0.95 }, 9)
check("line_density", #dl == 9 and type(dl[1]) == "number" and dl[1] > 500 and dl[1] < 2000 and dl[9] ~= dl[9],
  ("first %s last %s"):format(tostring(dl[1]), tostring(dl[9])))
local sl = s:slice("density", { res = { 20, 10 } })
local width_ok = true
for r = 1, #sl do if #sl[r] ~= 20 then width_ok = false end end
check("slice_shape", #sl == 10 and width_ok, ("%d rows of %d"):format(#sl, #sl[1]))
local low_filled, high_empty = false, true
for c = 1, 20 do
  if sl[3][c] == sl[3][c] and sl[3][c] > 0 then low_filled = true end -- row 3: y ~ 0.25
  if sl[10][c] == sl[10][c] and sl[10][c] > 0 then high_empty = false end -- row 10: y ~ 0.95
end
check("slice_rows_low_first", low_filled and high_empty)
local ok, err = pcall(s.probe, s, "no_such_field", { 0.5, 0.5 })
check("probe_unknown", not ok and tostring(err):find("unknown field 'no_such_field'", 1, true) ~= nil, tostring(err))
local st = s:stats()
check("stats_final", st.step > 0 and st.t > 0.07 and st.dt > 0 and st.kinetic > 0 and st.max_speed > 0
  and st.guard == "ok" and st.bodies == 2, ("step=%d t=%g bodies=%s"):format(st.step, st.t, tostring(st.bodies)))
print("events done")

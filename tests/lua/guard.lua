-- lua_guard_exit: cfl = 4 breaks the wave CFL condition of a stiff block.
local h = require "hearth"
local P = h.params { guard = "stop" }
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, cfl = 4, guard = P.guard, max_rollbacks = 20 }
s:add { shape = h.box({ 0.3, 0.3 }, { 0.7, 0.6 }), material = h.material("elastic", { E = 1e5, nu = 0.3, density = 1000 }),
  velocity = { 0.5, -0.5 } }
s:collider { shape = h.plane({ 0, 0.1 }, { 0, 1 }), mode = "separate" }
s:run { until_t = 2, every = 1 } -- sparse frames: steps are limited by cfl only
local st = s:stats()
print(("done t=%.6g rollbacks=%d guard=%s"):format(st.t, st.rollbacks, st.guard))

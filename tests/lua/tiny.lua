-- lua_repl_pipe: a scene built but not run; the repl gets `s` and `h`.
local h = require "hearth"
s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
s:add { shape = h.box({ 0.4, 0.4 }, { 0.6, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
greeting = "hello from tiny"

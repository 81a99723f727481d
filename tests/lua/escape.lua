-- sandbox_write_escapes / sandbox_symlink_escape / sandbox_plugin_path: one
-- write (or plugin load) per run, chosen with --set call=NAME, to the path target.
local h = require "hearth"
local P = h.params { call = "none", target = "" }
local c, target = P.call, P.target
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
s:add { shape = h.box({ 0.4, 0.4 }, { 0.6, 0.6 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
if c == "vtu" then
  s:vtu(target)
elseif c == "ply" then
  s:ply(target)
elseif c == "png" then
  s:png("speed", target)
elseif c == "save" then
  s:save(target)
elseif c == "csv" then
  s:run { until_t = 0.001, csv = target }
elseif c == "frame_png" then
  s:run { until_t = 0.001, png = { path = target } }
elseif c == "write" then
  h.write(target, "text from a scene\n")
elseif c == "core_write" then
  -- the raw C function, around every check made in Lua
  package.loaded["hearth.core"].write_atomic(target, "text from a scene\n")
elseif c == "io_open" then
  local f = assert(io.open(target, "w"))
  f:write("text from a scene\n")
  f:close()
elseif c == "plugin_written" then
  -- native code the scene writes itself, then loads: by file name and by path
  h.write("hearth_x.so", "\127ELF not really")
  h.material(target, {})
elseif c == "plugin_name" then
  h.material(target, {})
end
print("done " .. c)

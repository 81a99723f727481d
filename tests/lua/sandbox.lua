-- lua_sandbox: one call per run, chosen with --set call=NAME (target = a path).
local h = require "hearth"
local P = h.params { call = "none", target = "" }
local c, target = P.call, P.target
if c == "execute" then
  os.execute("true")
elseif c == "popen" then
  io.popen("true")
elseif c == "loadlib" then
  package.loadlib(target, "luaopen_evil")
elseif c == "require_c" then
  -- a C module next to the scene's working folder: the C searchers must not try it
  package.cpath = "./?.so;" .. package.cpath
  require "evil"
elseif c == "open_out" then
  io.open(target, "w")
elseif c == "remove" then
  os.remove(target)
elseif c == "rename" then
  os.rename(target, target .. ".moved")
elseif c == "open_in" then
  local f = assert(io.open(target, "w"))
  f:write("written from a scene\n")
  f:close()
  print("open_in ok")
elseif c == "load_binary" then
  -- the start of a Lua 5.4 binary chunk (string.dump is refused in the sandbox)
  local ok, err = load("\27Lua\x54\0\x19\x93\r\n\x1a\n")
  print("load_binary", ok, err)
elseif c == "dump" then
  string.dump(function() return 42 end)
elseif c == "loadfile_binary" then
  -- bytecode-looking bytes written into the output folder, then loaded from a file
  local f = assert(io.open(target, "wb"))
  f:write("\27Lua\x54\0\x19\x93\r\n\x1a\n")
  f:close()
  local fn, err = loadfile(target)
  if not fn then error("loadfile refused: " .. tostring(err)) end
  print("loadfile_binary ran", fn())
elseif c == "trust_execute" then
  local ok = os.execute("touch " .. target)
  print("execute", ok)
end

-- sandbox_debug_unreachable: every known way from a scene to the real io, os,
-- debug, load or native code; each line prints "check NAME ok" or "check NAME FAIL why".
local function check(name, ok, why) print(("check %s %s%s"):format(name, ok and "ok" or "FAIL", ok and "" or (" " .. tostring(why)))) end
local function refused(name, fn, ...)
  local ok, e = pcall(fn, ...)
  check(name, not ok and tostring(e):find("--trust", 1, true), ok and "it ran" or e)
end
check("debug_global", debug == nil, debug)
check("debug_loaded", package.loaded.debug == nil, package.loaded.debug)
check("debug_require", not pcall(require, "debug"), "require 'debug' loaded something")
check("debug_preload", package.preload.debug == nil, "preload")
refused("string_dump", string.dump, function() end)
refused("string_meta_dump", getmetatable("").__index.dump, function() end)
check("string_meta_is_string", getmetatable("").__index == string, "string metatable")
refused("os_execute", os.execute, "true")
refused("os_exit", os.exit, 0)
refused("os_tmpname", os.tmpname)
refused("io_popen", io.popen, "true")
refused("io_output", io.output, "x.txt")
refused("io_input", io.input, "/etc/hostname")
refused("package_loadlib", package.loadlib, "libc.so.6", "*")
check("io_is_fresh", package.loaded.io == io, "package.loaded.io is another table")
check("os_is_fresh", package.loaded.os == os, "package.loaded.os is another table")
local allowed_io = { open = 1, lines = 1, read = 1, write = 1, type = 1, stdout = 1, stderr = 1, stdin = 1,
  popen = 1, output = 1, input = 1, close = 1, tmpfile = 1 }
for k in pairs(io) do check("io_field_" .. k, allowed_io[k], "unexpected io." .. k) end
local allowed_os = { clock = 1, date = 1, time = 1, difftime = 1, getenv = 1, remove = 1, rename = 1,
  execute = 1, exit = 1, tmpname = 1, setlocale = 1 }
for k in pairs(os) do check("os_field_" .. k, allowed_os[k], "unexpected os." .. k) end
-- the file handle's methods reach nothing beyond the file
local fh = io.stdout
local m = getmetatable(fh)
check("filehandle_meta", type(m) == "table" and m.__index.popen == nil and m.__index.open == nil, "file methods")
-- binary chunks: load, load with a reader, loadfile, dofile, require
local bc = "\27Lua\x54\0\x19\x93\r\n\x1a\n"
local f, e = load(bc)
check("load_binary", f == nil and tostring(e):find("binary", 1, true), e)
f, e = load(bc, "x", "b")
check("load_binary_mode_b", f == nil and tostring(e):find("binary", 1, true), e)
local parts = { bc }
f, e = load(function() return table.remove(parts, 1) end)
check("load_binary_reader", f == nil, e)
f, e = load("return 1 + 1", "t", "t", {})
check("load_text_env", f and f() == 2, e)
f, e = load("return x", "t", "t", { x = 7 })
check("load_text_env_value", f and f() == 7, e)
-- coroutines keep the same restrictions
local co = coroutine.wrap(function() return debug, string.dump end)
local d1, d2 = co()
check("coroutine_no_debug", d1 == nil, d1)
check("coroutine_dump_refuses", not pcall(d2, print), "string.dump ran in a coroutine")
-- collectgarbage cannot stop the collector
check("gc_stop_refused", not pcall(collectgarbage, "stop"), "collectgarbage('stop') ran")
check("gc_count", type(collectgarbage("count")) == "number", "collectgarbage('count')")
-- C searchers are gone, the cpath is empty
check("cpath_empty", package.cpath == "", package.cpath)
check("searchers", #package.searchers == 3, #package.searchers)
local ok, err = pcall(require, "socket.core")
check("require_c_module", not ok and tostring(err):find("C modules are not allowed", 1, true), err)
-- the hearth module's raw C table: its writers pass the same gate
require "hearth"
local core = package.loaded["hearth.core"]
check("core_reachable", type(core) == "table", "hearth.core")
ok, err = pcall(core.write_atomic, "/tmp/hearth_sandbox_probe_escape.txt", "x")
check("core_write_refused", not ok and tostring(err):find("--trust", 1, true), err)
print("probe done")

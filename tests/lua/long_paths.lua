-- path_refusals_quote_short: every writer's path refusal (too long, or
-- outside the output folder) with a 100 kB path, a 100 kB io.open mode, and a
-- 3 kB path outside the folder; one line a case: its name, the message's
-- length in bytes and the message (tests/lua_test.sh checks the lengths).
local h = require "hearth"
local s = h.scene { dim = 2, dx = 0.1, box = { { 0, 0 }, { 1, 1 } } }
s:add { shape = h.box({ 0.2, 0.2 }, { 0.4, 0.4 }), material = h.material("elastic", { E = 1e4, nu = 0.3, density = 1000 }) }
local long = string.rep("a", 100000)
local outside = "/" .. string.rep("b", 3000) .. "/x.vtu"
for _, case in ipairs {
  { "vtu_frame_long", function() return s:_vtu_frame(long .. ".vtu") end },
  { "vtu_frame_outside", function() return s:_vtu_frame(outside) end },
  { "vtu_outside", function() return s:vtu(outside) end },
  { "ply_long", function() return s:ply(long .. ".ply") end },
  { "save_outside", function() return s:save(outside) end },
  { "write_outside", function() return h.write(outside, "x") end },
  { "io_open_long", function() return io.open(long, "w") end },
  { "io_open_mode_long", function() return io.open("/x", "w" .. long) end },
  { "os_remove_long", function() return os.remove(long) end },
  { "os_rename_outside", function() return os.rename("x", outside) end },
} do
  local ok, e = pcall(case[2])
  e = tostring(e):gsub("\n", " ")
  print(("%s %s %d %s"):format(case[1], ok and "accepted" or "refused", #e, e))
end

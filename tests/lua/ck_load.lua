-- lua_checkpoint_roundtrip, part 2: load the checkpoint (resolved in the output folder), 50 steps.
local h = require "hearth"
local s = h.load("ck.bin")
print("at_load " .. s:hash() .. " t=" .. s:stats().t)
s:step(50)
print("B " .. s:hash() .. " t=" .. s:stats().t)

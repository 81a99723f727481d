-- lua_checkpoint_roundtrip, part 1: 50 steps, save, 50 more.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, seed = 3 }
local jelly = h.material("elastic", { E = 2e4, nu = 0.3, density = 1000 })
local soup = h.material("newtonian", { density = 1000, bulk = 2e4, viscosity = 0.5 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.5 }), material = jelly, ppc = 4, jitter = 0.5, velocity = { 0.2, 0 } }
s:add { shape = h.disc({ 0.5, 0.7 }, 0.1), material = soup, ppc = 4, jitter = 0.5 }
s:collider { shape = h.plane({ 0, 0.15 }, { 0, 1 }), mode = "separate", friction = 0.3 }
s:step(50)
print("saved " .. s:save("ck.bin"))
print("at_save " .. s:hash() .. " t=" .. s:stats().t)
s:step(50)
print("A " .. s:hash() .. " t=" .. s:stats().t)

-- h.library.sph.bread_roll: Table 4.1 of Rodriguez-Arenas 2011 for the maxwell_sph plugin.
local h = require "hearth"
local b = h.library.sph.bread_roll
local t = b.table
assert(t.T0 == 26 and t.Tc == 45 and t.Tf == 120 and t.C_lambda == 450 and t.epsf == 5, "Table 4.1 numbers")
assert(b.sph.xsph0 == 0.05 and b.sph.xsph_f == 0.5, "XSPH tuner eq. 4.4 (eps_f of the text of §4.3)")
b.table.T0 = 0
assert(h.library.sph.bread_roll.table.T0 == 26, "a fresh table on every access")
local ok, e = pcall(function() return h.library.sph.bagel end)
assert(not ok and e:find("valid: bread_roll"), "unknown preset names the valid ones: " .. tostring(e))
-- the preset runs in an MPM scene, mu_e following eq. 4.2 through the core's temperature curves
local s = h.scene { dim = 2, dx = 1 / 32 }
local m = h.material("maxwell_sph", b.material)
s:add { shape = h.disc({ 0.5, 0.3 }, 0.1), material = m, temperature = 45 }
s:step(5)
print("sph library ok")

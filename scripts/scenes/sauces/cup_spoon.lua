-- Mixing in a cup with a spoon (Nagasawa et al. 2019, section 6.4, Fig. 13),
-- seen from above in 2D (no gravity in the plane): a round cup half mayo,
-- half honey, stirred by a spoon that circles the cup's centre.
--   hearth run scripts/scenes/sauces/cup_spoon.lua [--set premixed=true --set blend=linear]
-- By default the two sauces keep their own parameters (fixed labels: the
-- dynamic mixing ratios of eq. 43-44 are a core field still to come).
-- premixed = true fills the cup with the 50:50 mixture instead, blended as
-- `blend` says: the state the spoon drives the cup towards, for comparing
-- the nonlinear model with linear blending (Fig. 13, middle and bottom).
-- stir.csv: the sauce's kinetic energy and mean speed over time: the same
-- spoon moves a thinner sauce more.
local h = require "hearth"
local P = h.params { blend = "nonlinear", premixed = false, dx = 0.003, radius = 0.04, rps = 1.0,
  until_t = 1.0, every = 0.05, png = true }

local R = P.radius
local cx, cy = 1.5 * R, 1.5 * R
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 3 * R, 3 * R } }, gravity = { 0, 0 }, blend = P.blend,
  name = "cup_spoon" }
-- the cup wall: everything outside the circle, sticky like a real cup
s:collider { shape = h.box({ -1, -1 }, { 1, 1 }) - h.disc({ cx, cy }, R), mode = "sticky" }
local mayo, honey = h.library.sauce.mayo, h.library.sauce.honey
if P.premixed then
  s:add { shape = h.disc({ cx, cy }, R - P.dx), material = h.mix { { mayo, 0.5 }, { honey, 0.5 } }, ppc = 4 }
else
  -- mayo on the left half (x < cx), honey on the right
  s:add { shape = h.disc({ cx, cy }, R - P.dx) * h.box({ -1, -1 }, { cx, 1 }), material = h.mix { { mayo, 1 } },
    ppc = 4 }
  s:add { shape = h.disc({ cx, cy }, R - P.dx) * h.box({ cx, -1 }, { 1, 1 }), material = h.mix { { honey, 1 } },
    ppc = 4 }
end
-- the spoon: a disc of radius R/6 on a circle of radius R/2, once every 1/rps seconds
local omega = 2 * math.pi * P.rps
s:collider { shape = h.disc({ cx + 0.5 * R, cy }, R / 6), mode = "sticky", omega = omega, pivot = { cx, cy } }

local rows = { "t,kinetic_J_per_m,mean_speed_m_s" }
local mass = nil
s:run { until_t = P.until_t, every = P.every,
  png = P.png and { field = "speed", path = "frames/speed_%04d.png" } or nil,
  on_frame = function(f)
    local st = f:stats()
    -- every particle has the same volume; densities differ by < 1% here, so mass ~ particles
    mass = mass or (st.particles * (P.dx / 2) ^ 2 * 1000)
    rows[#rows + 1] = ("%.4f,%.6g,%.6g"):format(st.t, st.kinetic, math.sqrt(2 * st.kinetic / mass))
    h.write("stir.csv", table.concat(rows, "\n") .. "\n")
  end }
local st = s:stats()
print(("cup with spoon (%s, %s): at t = %.2f s the sauce's mean speed is %.4f m/s (spoon %.4f m/s)"):format(
  P.premixed and "premixed 50:50" or "mayo | honey", P.blend, st.t, math.sqrt(2 * st.kinetic / mass), omega * 0.5 * R))

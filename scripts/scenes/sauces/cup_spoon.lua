-- Mixing in a cup with a spoon (Nagasawa et al. 2019, section 6.4, Fig. 13),
-- seen from above in 2D (no gravity in the plane): a round cup half mayo,
-- half honey, stirred by a spoon that circles the cup's centre.
--   hearth run scripts/scenes/sauces/cup_spoon.lua [--set premixed=true --set blend=linear] [--set mixing=fixed]
-- By default the two halves share one dynamic mixture (eq. 43-44): each
-- particle's parameters are the blend at the mixing ratios around it, so
-- where the spoon folds mayo into honey the sauce thins. mixing = fixed keeps
-- each half its own sauce.
-- premixed = true fills the cup with the 50:50 mixture instead, blended as
-- `blend` says: the state the spoon drives the cup towards, for comparing
-- the nonlinear model with linear blending (Fig. 13, middle and bottom).
-- stir.csv: the sauce's kinetic energy and mean speed over time: the same
-- spoon moves a thinner sauce more.
local h = require "hearth"
local P = h.params { blend = h.choice("nonlinear", h.blend_words),
  mixing = h.choice { "dynamic", dynamic = "the halves share one mixture whose ratios follow the particles (eq. 43-44; "
    .. "with blend = nonlinear, else fixed)", fixed = "each half keeps its own sauce" },
  premixed = h.flag { false, what = "one 50:50 mix in the cup, in place of mayo left and honey right" }, dx = h.number { 0.003, above = 0, unit = "m", what = "the grid spacing" },
  radius = h.number { 0.04, above = 0, unit = "m", what = "the cup's radius" },
  rps = h.number { 1.0, min = 0, max = 100, unit = "1/s", what = "the spoon's turns a second" },
  until_t = h.number { 1.0, min = 0, unit = "s", what = "the run's simulated time (0: the set-up alone, measured)" },
  every = h.number { 0.05, above = 0, unit = "s", what = "the time between frames" },
  png = h.flag { true, what = "PNG frames in frames/ (the mixing ratio, or the speed)" } }

local R = P.radius
local cx, cy = 1.5 * R, 1.5 * R
local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 3 * R, 3 * R } }, gravity = { 0, 0 }, blend = P.blend,
  mixing = P.blend == "nonlinear" and P.mixing or "fixed",
  name = "cup_spoon" }
-- the cup wall: everything outside the circle, sticky like a real cup
s:collider { shape = h.box({ -1, -1 }, { 1, 1 }) - h.disc({ cx, cy }, R), mode = "sticky" }
local mayo, honey = h.library.sauce.mayo, h.library.sauce.honey
if P.premixed then
  s:add { shape = h.disc({ cx, cy }, R - P.dx), material = h.mix { { mayo, 0.5 }, { honey, 0.5 } }, ppc = 4 }
else
  -- mayo on the left half (x < cx), honey on the right
  s:add { shape = h.disc({ cx, cy }, R - P.dx) * h.box({ -1, -1 }, { cx, 1 }), material = h.mix { { mayo, 1 }, { honey, 0 } },
    ppc = 4 }
  s:add { shape = h.disc({ cx, cy }, R - P.dx) * h.box({ cx, -1 }, { 1, 1 }), material = h.mix { { mayo, 0 }, { honey, 1 } },
    ppc = 4 }
end
-- the spoon: a disc of radius R/6 on a circle of radius R/2, once every 1/rps seconds
local omega = 2 * math.pi * P.rps
s:collider { shape = h.disc({ cx + 0.5 * R, cy }, R / 6), mode = "sticky", omega = omega, pivot = { cx, cy } }

local rows = { "t_s,kinetic_J_per_m,mean_speed_m_s,mixed_fraction" }
-- the share of sauce whose mayo ratio lies between 0.1 and 0.9 (dynamic mixing only)
local function mixed()
  if s:_state().dynamic == nil then return 0 end
  local r = s:mixing_ratios()
  local n = 0
  for i = 1, #r, 2 do if r[i] > 0.1 and r[i] < 0.9 then n = n + 1 end end
  return n / math.max(1, #r // 2)
end
local mass = nil
s:run { until_t = P.until_t, every = P.every,
  png = P.png and { field = s:_state().dynamic and "mixing_ratio" or "speed", path = "frames/cup_%04d.png" } or nil,
  on_frame = function(f)
    local st = f:stats()
    -- every particle has the same volume; densities differ by < 1% here, so mass ~ particles
    mass = mass or (st.particles * (P.dx / 2) ^ 2 * 1000)
    rows[#rows + 1] = ("%.4f,%.6g,%.6g,%.4f"):format(st.t, st.kinetic, math.sqrt(2 * st.kinetic / mass), mixed())
    h.write("stir.csv", table.concat(rows, "\n") .. "\n")
  end }
local st = s:stats()
print(("cup with spoon (%s, %s): at t = %.2f s the sauce's mean speed is %.4f m/s (spoon %.4f m/s); mixed fraction %.3f"):format(
  P.premixed and "premixed 50:50" or "mayo | honey", P.blend, st.t, math.sqrt(2 * st.kinetic / mass), omega * 0.5 * R, mixed()))

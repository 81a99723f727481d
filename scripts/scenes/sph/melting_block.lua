-- A block melting on a hot floor with the SPH solver (Rodriguez-Arenas 2011 Fig. 3.14).
--   hearth run scripts/scenes/sph/melting_block.lua [--set floor=150] [--set dx=0.003]
-- A stiff block (maxwell_sph whose viscosity and mu_e fall with temperature,
-- through h.curve) sits on a heated tray. Heat enters the particles touching
-- the tray (eq. 3.42) and diffuses (eq. 3.45-3.46); the bottom softens first
-- and its melt runs out into a pool around the shrinking block. Writes
-- height.csv (t_s, top_m: the top of the material above the tray over time) and
-- particles_NNNN.csv (x_m, y_m at each 0.1 s frame, NNNN = 0 at t = 0;
-- tests/sph_melt_measure.py measures the pool from them). heat_ext (eq. 3.42
-- per unit area, h / c in kg/(m^2 s), animation-scaled) is 6.1, the heat the
-- thesis's printed form gave with 3e8 at this dx (3e8 dx^3 / pi in 2D).
-- The tray is no-slip (mode "sticky": eq. 3.33 with beta_c = 0, which the
-- thesis names the non-slip condition): a viscous melt does not slide on a
-- plate, and the no-slip collider is a wall in eq. 3.19's viscous term
-- (sph_walls.c). On the free-slip tray the melt ran out from under the block
-- as single particles at up to 1 m/s, hit the box's walls and flew up to
-- 70 mm, and the block's bottom slid apart until it split down its middle at
-- 1.9 s (docs/validation.md "The melting block pools (#18, helper meltblock)").
-- What it shows (2D, dx 4 mm, 2 s; measured at commit 80e63bd, #18 helper userview2, with tests/sph_melt_measure.py):
-- one piece; the centre's top falls 56.0 -> 47.4 mm (height.csv, 59 -> 50 mm at the line it probes) and the melt
-- makes a foot 11 / 7 mm wide left / right of the block's footprint, one particle 9.9 mm up; its bottom rows read
-- 70-80 degC in frames/temperature_0020.png's colours, against the floor's 150. A block on its own melt, not yet a puddle.
-- meltblock's 25.5 / 21.5 mm foot and 43.8 mm top were measured before deadbread's sph_outer.c oshare, which gives
-- the block's crowded sides and corners a little less of the floor's heat (docs/validation.md "The bread of the
-- dead stays in one piece"). ~6 s of CPU.
local h = require "hearth"
local P = h.params {
  floor = h.number { 150, min = -273.15, max = 5000, unit = "degC", what = "the floor's temperature" },
  dx = h.number { 0.004, above = 0, unit = "m", what = "the grid spacing" } }

local s = h.scene { dim = 2, dx = P.dx, box = { { 0, 0 }, { 0.3, 0.15 } }, solver = "sph",
  sph = { heat_ext = 6.1, heat_int = 0.5, av_beta = 1, xsph0 = 0.1, xsph_f = 0.02, xsph_T0 = 20, xsph_Tf = 80 } }
local wax = h.material("maxwell_sph", {
  density = 900, bulk = 3e4, lambda = 5,
  viscosity = h.curve { { 20, 100 }, { 45, 20 }, { 70, 0.5 } },
  mu_e = h.curve { { 20, 2e3 }, { 45, 200 }, { 70, 1 } },
})
s:add { shape = h.box({ 0.11, 0.01 }, { 0.19, 0.07 }), material = wax, ppc = 1, jitter = 0, temperature = 20 }
s:collider { shape = h.plane({ 0, 0.01 }, { 0, 1 }), mode = "sticky", temperature = P.floor, beta = 0 }

local rows = { "t_s,top_m" }
local function top()
  local col = s:line("density", { 0.15, 0.01 }, { 0.15, 0.15 }, 141)
  local y = 0.01
  for i, d in ipairs(col) do if d == d then y = 0.01 + (i - 1) * 0.14 / 140 end end
  return y - 0.01
end
s:run { until_t = 2.0, every = 0.1, png = { field = "temperature", path = "frames/temperature_%04d.png" },
  on_frame = function(f)
    rows[#rows + 1] = ("%.3f,%.4f"):format(f.t, top())
    h.write("height.csv", table.concat(rows, "\n") .. "\n")
    local x, pos = s:positions(), { "x_m,y_m" }
    for i = 1, #x // 3 do pos[#pos + 1] = ("%.6g,%.6g"):format(x[3 * i - 2], x[3 * i - 1]) end
    h.write(("particles_%04d.csv"):format(#rows - 2), table.concat(pos, "\n") .. "\n")
  end }
print(("melting block: height %.3f m at t = %.2f s"):format(top(), s:stats().t))

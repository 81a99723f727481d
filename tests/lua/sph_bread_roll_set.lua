-- h.library.sph.bread_roll's mu_e (#18, helper rollset): soft until bread's set begins
-- and set by its end (McGee 2004: oven spring stops as the interior reaches 68-80 degC),
-- against eq. 4.2 of Table 4.1, which the preset keeps as .paper.mu_e. The numbers
-- below are the sources' and Table 4.1's, not read from the preset.
local h = require "hearth"
local b = h.library.sph.bread_roll
-- piecewise linear evaluation of a curve's points, constant beyond its ends (the core's rule)
local function at(c, T)
  if T <= c[1][1] then return c[1][2] end
  for i = 2, #c do
    if T <= c[i][1] then
      local a, z = c[i - 1], c[i]
      return a[2] + (T - a[1]) * (z[2] - a[2]) / (z[1] - a[1])
    end
  end
  return c[#c][2]
end
local mu = b.material.mu_e
local gas = 20e3 -- the bubbles' largest gauge pressure on the roll, 6-22 kPa (docs/validation.md)
-- raw: Table 4.1 x 100 (mu_e0 = 1, mu_ec = 10 at 26 and 45 degC)
assert(at(mu, 26) == 100 and at(mu, 45) == 1e3, ("raw end Table 4.1 x 100: %g, %g"):format(at(mu, 26), at(mu, 45)))
-- soft to 68 degC, McGee's start of the set: no stiffer than 1 kPa anywhere below it
for T = 26, 68, 0.5 do assert(at(mu, T) <= 1e3, ("soft to 68 degC: mu_e(%g) = %g Pa"):format(T, at(mu, T))) end
-- set at 80 degC, McGee's end: the crumb's cell wall, 1 MPa (0.5-1.5 MPa by Gibson & Ashby from crumb moduli)
assert(at(mu, 80) == 1e6, "set at 80 degC: " .. at(mu, 80))
-- log-linear over 68-80 degC: every 3 degC a factor 1000^(1/4) = 5.623 (the points rounded to three figures)
for T = 68, 77, 3 do
  local r = at(mu, T + 3) / at(mu, T)
  assert(math.abs(r / 1000 ^ 0.25 - 1) < 3e-3, ("log-linear step %g -> %g degC: x%.4f"):format(T, T + 3, r))
end
-- the gas's 20 kPa is passed between 71 and 74 degC, not below
local Tgas
for T = 26, 120, 0.01 do if at(mu, T) > gas then Tgas = T break end end
assert(Tgas > 71 and Tgas < 74, "the preset's crumb passes 20 kPa at " .. tostring(Tgas))
-- the crust's end: Table 4.1 x 100 at Tf (mu_ef = 5e4 at 120 degC)
assert(at(mu, 120) == 5e6, "dry end Table 4.1 x 100: " .. at(mu, 120))
-- eq. 4.2 as printed: linear from (45, 10) to (120, 5e4); x 100 it passes 20 kPa at
-- 45 + 75 (200 - 10) / (5e4 - 10) = 45.285 degC: the early set this curve replaces
local p = b.paper.mu_e
assert(at(p, 26) == 1 and at(p, 45) == 10 and at(p, 120) == 5e4, "paper: eq. 4.2 through Table 4.1's points")
local Tp
for T = 26, 120, 0.001 do if 100 * at(p, T) > gas then Tp = T break end end
assert(math.abs(Tp - (45 + 75 * (200 - 10) / (5e4 - 10))) < 2e-3, "eq. 4.2 x 100 passes 20 kPa at " .. Tp)
print(("sph bread roll set ok: the preset's crumb passes %g kPa at %.2f degC, eq. 4.2 x 100 at %.3f degC"):format(
  gas / 1e3, Tgas, Tp))

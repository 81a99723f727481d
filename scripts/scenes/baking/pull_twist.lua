-- Dough pull and twist (Ding et al. 2019, Fig. 6): the same pull and twist
-- applied to doughs of a 3 x 3 grid of yield stress tau_y (left to right,
-- rising) x viscosity eta (bottom to top, rising), all at room temperature
-- (no heat: the cam_clay_dough plugin with plain numbers).
-- Each dough is a strip (2D) or a cylinder (3D) whose ends are held by two
-- grips (colliders of mode "grip": the particles inside move rigidly with
-- them). The grips move apart at `speed` and turn the opposite ways at
-- `spin` rad/s: about z in 2D (the strip bends into an S), about the
-- strip's axis in 3D (a twist).
--   hearth run scripts/scenes/baking/pull_twist.lua [--set dim=3]
--   [--set taus=300,1000,3000] (Pa) [--set etas=1e6,1e8,1e10] (Pa^3 s, as the plugin's eta)
--   [--set speed=0.02] (m/s, each grip) [--set spin=0.5] (rad/s) [--set until_t=0.4] (s)
-- Writes, under hearth-out/pull_twist/: j_%04d.png (the volume ratio J:
-- where a dough dilates as it necks and tears) and pull_twist.csv, per
-- dough: its length (the extent of its material along the pull), the
-- thinnest section of its free part (the neck; 0 = torn through), how
-- far its free part sagged, gap_m (the widest step a chain of particles
-- from one grip to the other must take; an intact dough's particles lie
-- dx / 2 apart) and torn (1 when gap_m >= dx: the dough has parted
-- somewhere, at a grip's face too, and its neck reads 0).
-- What it shows (2D, dx 2 mm, 0.4 s, neck of the 12 mm strips; measured at
-- commit 76ac79a, #18 helper userview): at eta = 1e8 a 300 Pa dough flows along its
-- whole length and keeps a 10.2 mm neck, a 1000 Pa one necks next to its
-- grips (6.3 mm) and a 3000 Pa one nearly tears at one grip (4.4 mm); at
-- eta = 1e10 all three keep 10.0-10.7 mm (the viscous stress holds them); at
-- eta = 1e6 the 300 Pa one tears off both grips and falls (0, sagged 30 mm),
-- the 3000 Pa one tears off one grip and hangs from the other (0), and the
-- 1000 Pa one hangs 6.7 mm low from both grips by threads (8.8 mm: the neck
-- is read from two cells inside each grip's face, so a tear at the face
-- itself is not in it; look at j_0004.png; gap_m reads 1.9 mm there, under
-- dx: loose particles a little under a cell apart still join it to both
-- grips, where the intact doughs' widest steps are 1.4-1.5 mm and the two
-- torn ones' over 4 mm; #18 helper userfix4). (Before, at commit f8dc5d5, the
-- necks at eta = 1e8 were 10.2, 3.9 and 0 mm and all three tore at 1e6.)
-- The porous Cam-clay surface (eq. 12) yields in tension and dilates where
-- a dough necks, so the stiffer doughs localise. 3D (dx 4 mm, at f8dc5d5, not
-- measured since): the same order (eta = 1e8: 11.9, 0, 0 mm; 1e10: 11.9, 11.9, 0 mm).
-- Cost: 2D 9 s of CPU on one thread (25 s of wall on the loaded shared
-- machine; 60 s at f8dc5d5), 3D ~45 s at f8dc5d5.
-- The grips: a "sticky" collider holds only the grid nodes inside it, so a
-- dough's end in it was squeezed out to its surface and the dough peeled
-- off when pulled; a grip carries the particles inside it and holds the
-- nodes within a cell of its surface (core/sim/solver/colliders.c, mpm.c).
-- torn, 1 when the rope has come apart, has no unit (tests/scene_csv.py's unit rule):
-- pull_twist.csv has no unit: torn
local h = require "hearth"
local P = h.params { dim = h.number { 2, min = 2, max = 3, integer = true, what = "the space's dimensions" },
  dx = h.number { 0.002, above = 0, unit = "m", what = "the grid spacing" },
  until_t = h.number { 0.4, above = 0, unit = "s", what = "the run's simulated time" },
  frames = h.number { 4, min = 1, integer = true, unit = "frames", what = "PNG frames over the run" }, 
  -- cam_clay_dough's ranges of tau_y, [1e-6, 1e9] Pa, and of eta, [0, 1e12] Pa^3 s; at most a dozen of each, as
  -- cookies.lua's lists: each pair is a strip in the grid, so the cost grows with their product
  taus = h.number { { 300, 1000, 3000 }, list = true, max_count = 12, min = 1e-6, max = 1e9, unit = "Pa",
    what = "the doughs' yield stresses, one column each" },
  etas = h.number { { 1e6, 1e8, 1e10 }, list = true, max_count = 12, min = 0, max = 1e12, unit = "Pa^3 s",
    what = "the doughs' viscoplastic penalties eta, one row each" },
  speed = h.number { 0.02, min = 0, unit = "m/s", what = "each grip's pull speed (below the dough's wave speed)" },
  spin = h.number { 0.5, min = -100, max = 100, unit = "rad/s", what = "each grip's turn rate" },
  -- cam_clay_dough's range of E: [0.01, 1e12] Pa
  E = h.number { 4e4, min = 0.01, max = 1e12, unit = "Pa", what = "the dough's Young's modulus" } }
-- A grip pulls slower than the dough's elastic (P) wave speed, c = sqrt(E (1 - nu) / ((1 + nu) (1 - 2 nu)) / rho)
-- (nu 0.3, cam_clay_dough's default; rho 500 kg/m^3 below; 10.4 m/s at the default E): faster, the grip tears
-- its end away before the rest of the dough can feel the pull (an impact, not a pull), and the explicit step cannot
-- carry it: its first step is sized by the waves alone, and the guard stops a grip past c / cfl (at the cfl <= 1 the
-- waves allow, c at most). `--set speed=1e300` had been stopped by the guard at step 1 ("speed inf m/s ... lower
-- cfl or dt_max", advice that does not fit); now refused here, naming the range at the E given.
local RHO, NU = 500, 0.3
local wave = math.sqrt(P.E * (1 - NU) / ((1 + NU) * (1 - 2 * NU)) / RHO)
if not (P.speed < wave) then
  h.refuse(("speed = %g m/s at E = %g Pa: speed (each grip's pull speed) takes a number in [0, %.4g) m/s at this E, below "
    .. "the dough's elastic wave speed sqrt(E (1 - nu) / ((1 + nu) (1 - 2 nu)) / rho), nu %g, rho %g kg/m^3 (a faster "
    .. "grip tears its end away before the dough feels the pull); lower --set speed or raise --set E")
    :format(P.speed, P.E, wave, NU, RHO))
end
local d3 = P.dim == 3
local dx = h.dx_3d(P.dx, 0.004, d3) -- says so when it raises dx
local function v(x, y, z) return d3 and { x, y, z } or { x, y } end
local taus, etas = P.taus, P.etas

local CW, CH = 0.1, 0.07                 -- m: one dough's cell (width, height)
local L, T, G, LIP = 0.06, 0.012, 0.01, 0.004 -- m: dough length, thickness, grip depth on the dough, grip lip
local W, H, zc = CW * #taus, CH * #etas, 0.03
local s = h.scene { dim = P.dim, dx = dx, box = { v(0, 0, 0), v(W, H, 2 * zc) }, gravity = v(0, -9.81, 0),
  name = "pull_twist" }

local doughs = {}
for j, eta in ipairs(etas) do
  for i, tau in ipairs(taus) do
    local xc, yc = (i - 0.5) * CW, (j - 0.45) * CH
    local x0, x1 = xc - L / 2, xc + L / 2
    local m = h.material("cam_clay_dough", { E = P.E, tau_y = tau, eta = eta, density = RHO })
    local shape = d3 and h.cylinder(v(xc, yc, zc), { 1, 0, 0 }, T / 2, L / 2) or h.box(v(x0, yc - T / 2), v(x1, yc + T / 2))
    s:add { shape = shape, material = m, ppc = d3 and 8 or 4, jitter = 0 }
    local r = T / 2 + LIP
    -- in 3D the grips spin about the strip's axis (x); in 2D about z
    local function grip(xa, xb, sign)
      return s:collider { shape = h.box(v(xa, yc - r, zc - r), v(xb, yc + r, zc + r)), mode = "grip",
        velocity = v(sign * P.speed, 0, 0), omega = d3 and { -sign * P.spin, 0, 0 } or -sign * P.spin,
        pivot = v((xa + xb) / 2, yc, zc) }
    end
    grip(x0 - LIP, x0 + G, -1)
    grip(x1 - G, x1 + LIP, 1)
    doughs[#doughs + 1] = { tau = tau, eta = eta, xc = xc, yc = yc, x0 = x0, x1 = x1 }
  end
end

-- per dough: its extent along x and the mean height of its free part (from
-- the particles in its cell), and the neck: the thinnest vertical section
-- through the free part (density line probes, one every cell)
local function measure(t)
  local X = s:positions()
  for _, d in ipairs(doughs) do d.lo, d.hi, d.sy, d.n = math.huge, -math.huge, 0, 0 end
  for k = 1, #X, 3 do
    local x, y = X[k], X[k + 1]
    local i, j = math.floor(x / CW) + 1, math.floor(y / CH) + 1
    local d = doughs[(math.max(1, math.min(#etas, j)) - 1) * #taus + math.max(1, math.min(#taus, i))]
    d.lo, d.hi = math.min(d.lo, x), math.max(d.hi, x)
    local fa, fb = d.x0 + G - P.speed * t, d.x1 - G + P.speed * t
    if x > fa + dx and x < fb - dx then d.sy, d.n = d.sy + y, d.n + 1 end
  end
  -- gap: the widest step a chain of particles from one grip to the other must take (the smallest distance at which
  -- particles that close link the grips), searched up to 2 dx; torn: a gap of a grid cell dx or more, twice an intact
  -- dough's spacing (dx / 2 at 4 particles a cell in 2D and 8 in 3D): a hole in the dough, seen in the frames, whose
  -- particles are drawn about their own spacing across. (MPM still passes momentum across gaps of up to ~3 dx
  -- through the nodes two particles share, so a torn dough may still hang by the grid's reach: torn says the dough
  -- has parted.) A tear at a grip's face lies outside the neck's columns (two cells inside each face, below), which
  -- had read a dough whose grips only loose particles still join as necked (8.8 mm, tau_y 1000 Pa, eta 1e6; #18
  -- helpers userview3, userfix4).
  local reach = 2 * dx -- the search's cells: a gap up to reach is found among the 3 (x 3) x 3 next cells
  for _, d in ipairs(doughs) do d.at, d.cell, d.seeds, d.goal = {}, {}, {}, {} end
  local r = T / 2 + LIP + dx -- a grip's half height, and a cell: the particles it holds
  local function key(i, j, k) return (i + 1) + 4096 * ((j + 1) + 4096 * (k + 1)) end
  for k = 1, #X, 3 do
    local x, y = X[k], X[k + 1]
    local i, j = math.floor(x / CW) + 1, math.floor(y / CH) + 1
    local d = doughs[(math.max(1, math.min(#etas, j)) - 1) * #taus + math.max(1, math.min(#taus, i))]
    local c = key(math.floor(x / reach), math.floor(y / reach), d3 and math.floor(X[k + 2] / reach) or 0)
    d.cell[c] = d.cell[c] or {}
    table.insert(d.cell[c], k)
    d.at[k] = c
    if math.abs(y - d.yc) < r then
      if x < d.x0 + G - P.speed * t then d.seeds[#d.seeds + 1] = k end -- in grip A, left of its face
      if x > d.x1 - G + P.speed * t then d.goal[k] = true end          -- in grip B, right of its face
    end
  end
  local kz = d3 and 1 or 0
  local function links(d, within) -- do particles closer than within link the grips?
    local seen, queue = {}, {}
    for _, k in ipairs(d.seeds) do if not seen[k] then seen[k] = true; queue[#queue + 1] = k end end
    local head = 1
    while head <= #queue do
      local p = queue[head]
      head = head + 1
      if d.goal[p] then return true end
      for dk = -kz, kz do
        for dj = -1, 1 do
          for di = -1, 1 do
            for _, q in ipairs(d.cell[d.at[p] + di + 4096 * (dj + 4096 * dk)] or {}) do
              if not seen[q] then
                local ex, ey, ez = X[q] - X[p], X[q + 1] - X[p + 1], X[q + 2] - X[p + 2]
                if ex * ex + ey * ey + ez * ez < within * within then seen[q] = true; queue[#queue + 1] = q end
              end
            end
          end
        end
      end
    end
    return false
  end
  for _, d in ipairs(doughs) do
    if links(d, reach) then -- bisect the gap to a 2^-16 of reach
      local lo, hi = 0, reach
      for _ = 1, 16 do
        local mid = 0.5 * (lo + hi)
        if links(d, mid) then hi = mid else lo = mid end
      end
      d.gap = hi
    else
      d.gap = reach -- or wider
    end
    d.torn = d.gap >= dx
  end
  for _, d in ipairs(doughs) do
    local fa, fb = d.x0 + G - P.speed * t + 2 * dx, d.x1 - G + P.speed * t - 2 * dx
    local neck, ncol, nres = math.huge, math.max(2, math.floor((fb - fa) / dx)), 200
    -- a window of 21 mm below to 14 mm above the dough's line: a sagging
    -- dough stays in it, one that tore off and fell leaves it
    local ylo, yhi = d.yc - 0.3 * CH, d.yc + 0.2 * CH
    for k = 0, ncol do
      local x = fa + (fb - fa) * k / ncol
      local col = s:line("density", v(x, ylo, zc), v(x, yhi, zc), nres + 1)
      local c = 0
      for _, val in ipairs(col) do if val == val then c = c + 1 end end
      neck = math.min(neck, c * (yhi - ylo) / nres)
    end
    d.neck = d.torn and 0 or neck -- the header's 0 = torn through, wherever the tear is
    d.sag = d.n > 0 and d.yc - d.sy / d.n or 0 / 0
  end
end

-- J's colour runs over 1-1.5 (beyond it, the top colour): a necking dough dilates by tens of percent, while the
-- whole range ran to the one particle torn loose at a grip (J 27 at 0.4 s), which left every strip dark
-- The title names the grid (#18, helper userview3: the frames showed nine doughs with nothing to say which is which):
-- the yield stresses left to right and the penalties bottom to top, each with its unit (eta's is the plugin's, Pa^3
-- s; #18, helper userfix10), or, when the lists do not fit a label's 128 bytes (HEARTH_PICTURE_LABEL_MAX), which way
-- each rises.
local function list(t) local r = {} for i, x in ipairs(t) do r[i] = ("%g"):format(x) end return table.concat(r, ", ") end
local label = ("tau_y %s Pa across; eta %s Pa^3 s up"):format(list(taus), list(etas))
if #label > 128 then label = "tau_y (Pa) rises left to right, eta (Pa^3 s) bottom to top" end
s:run { until_t = P.until_t, every = P.until_t / P.frames,
  png = { field = "J", path = "j_%04d.png", range = { 1, 1.5 }, label = label } }
measure(s:stats().t)
local rows = { "tau_y_Pa,eta_Pa3s,length_m,neck_m,sag_m,gap_m,torn" }
for _, d in ipairs(doughs) do
  rows[#rows + 1] = ("%g,%g,%.5f,%.5f,%.5f,%.5f,%d"):format(d.tau, d.eta, d.hi - d.lo, d.neck, d.sag, d.gap,
    d.torn and 1 or 0)
  print(("tau_y %6g Pa, eta %6g Pa^3 s: length %.4f m, neck %.4f m (of %.3f), sag %.4f m, gap %.4f m%s"):format(d.tau,
    d.eta, d.hi - d.lo, d.neck, T, d.sag, d.gap, d.torn and ", torn" or ""))
end
h.write("pull_twist.csv", table.concat(rows, "\n") .. "\n")

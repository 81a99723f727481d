-- dumps_run.lua: a run writing VTU (with its .pvd) and PLY frames, and at
-- every VTU frame the scene's own per-particle values (by id) for the checks
-- in tests/vtk_check.py. Two blocks at different temperatures, so the
-- temperature varies; one falls on the other, so stress and ids move.
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("elastic", { E = 2e4, nu = 0.3, density = 1000, conductivity = 1e4, specific_heat = 500 })
s:add { shape = h.box({ 0.3, 0.1 }, { 0.7, 0.3 }), material = m, ppc = 4, temperature = 20 }
s:add { shape = h.box({ 0.4, 0.3 }, { 0.6, 0.45 }), material = m, ppc = 4, temperature = 80 }
s:collider { shape = h.plane({ 0, 0.1 }, { 0, 1 }), mode = "sticky" }
local frame = 0
local function record(t)
  local p = s:particles { fields = { "id", "x", "temperature", "stress" } }
  local lines = { ("t %.17g"):format(t) }
  for i = 1, p.n do
    local st = {}
    for k = 1, 9 do st[k] = ("%.17g"):format(p.stress[9 * (i - 1) + k]) end
    lines[#lines + 1] = ("%d %.17g %.17g %.17g %s"):format(p.id[i], p.x[3 * i - 2], p.x[3 * i - 1],
      p.temperature[i], table.concat(st, " "))
  end
  h.write(("check/frame_%04d.txt"):format(frame), table.concat(lines, "\n") .. "\n")
  frame = frame + 1
end
s:run { until_t = 0.06, every = 0.015, on_frame = function(fr) record(fr.t) end,
        vtu = { path = "vtu/run_%04d.vtu" },
        ply = { path = "ply/run_%04d.ply", color = "temperature", range = { 20, 80 }, colormap = "inferno" } }

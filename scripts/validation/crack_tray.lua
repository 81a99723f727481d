-- crack_tray.lua: bread.lua (by default its plain loaf, only = 1) on another tray, for
-- docs/validation.md ("The unscored crack with the loaf on its tray (#18, helper
-- crackback)"): how much of the crown's stretch comes from what holds the loaf's base?
-- It runs scripts/scenes/baking/bread.lua itself (same loaf, same measures, same
-- bread.csv, read by tests/bread_claims.py) with h.recipes.tray's contact changed by:
--   tray_mode      "separate" (bread.lua's tray, h.recipes.tray's default), "slip", "sticky"
--   tray_friction  the tray's friction coefficient (default 0.4, h.recipes.tray's)
--   grid_shift     the box's floor moved down by this much (m, [0, 0.02); default 0), so the grid's node rows
--                  fall elsewhere against the tray (y = 0.02; docs/validation.md, "The loaf's foot on its tray")
--   hearth run scripts/validation/crack_tray.lua --quiet [--set dx=0.004] [--set tray_friction=0] ...
-- from any folder (the scene is found beside this script: h.scene_path; or --set bread=PATH to bread.lua).
-- Besides bread.csv's row, every frame prints the plain loaf's base: the width of its
-- lowest half-cell row of particles, its overall width, and the height above the tray
-- of the lowest particle of its outermost one-cell column on each side (the foot),
-- against that particle's half-spacing h_p (the touch rule's reach,
-- core/sim/solver/mpm_touch.c), and where its cracked particles (damage 1) are.
local h = require "hearth"
local P = h.params { dim = 2, dx = 0.005, until_t = 2.5, frames = 5, slit_depth = 0.02, slit_width = 0.01, only = 1,
  tray_mode = h.choice("separate", h.contact_words), tray_friction = 0.4, grid_shift = 0,
  bread = h.scene_path("../scenes/baking/bread.lua") }
if not (P.grid_shift >= 0 and P.grid_shift < 0.02) then
  error(("crack_tray.lua: grid_shift %g m: expected [0, 0.02) (the box's floor moved down, below the tray)"):format(P.grid_shift))
end

-- bread.lua's own h.params sees the values parsed here (it declares a subset of these names)
h.pass_params(P)

local TRAY, X0 = 0.02, 0.07 -- bread.lua's tray height and its plain loaf's axis (m)
local tray = h.recipes.tray
h.recipes.tray = function(s, y, o)
  o.mode, o.friction = P.tray_mode, P.tray_friction
  return tray(s, y, o)
end

local scene = h.scene
h.scene = function(o)
  if P.grid_shift ~= 0 then o.box[1][2] = o.box[1][2] - P.grid_shift end
  local s = scene(o)
  local methods = getmetatable(s).__index
  local run = methods.run
  methods.run = function(self, r)
    local on_frame, v0 = r.on_frame, nil
    r.on_frame = function(f)
      on_frame(f)
      local p = self:particles { fields = { "x", "J", "damage" } }
      v0 = v0 or self:volume() / p.n
      local dx, ymin, lo, hi = P.dx, math.huge, math.huge, -math.huge
      for k = 1, p.n do
        local x = p.x[3 * k - 2] - X0
        if math.abs(x) < 0.07 then
          ymin, lo, hi = math.min(ymin, p.x[3 * k - 1]), math.min(lo, x), math.max(hi, x)
        end
      end
      local blo, bhi, foot, cracked = math.huge, -math.huge, { {}, {} }, {}
      for k = 1, p.n do
        local x, y = p.x[3 * k - 2] - X0, p.x[3 * k - 1]
        if math.abs(x) < 0.07 then
          if y < ymin + 0.5 * dx then blo, bhi = math.min(blo, x), math.max(bhi, x) end
          for side, edge in ipairs { lo, hi } do
            local F = foot[side]
            if math.abs(x - edge) < dx and (not F.y or y < F.y) then
              F.y, F.h = y, 0.5 * math.sqrt(p.J[k] * v0)
            end
          end
          if p.damage[k] >= 1 then cracked[#cracked + 1] = ("(%.0f,%.0f)"):format(x * 1e3, (y - TRAY) * 1e3) end
        end
      end
      print(("t %.3f  base row %.2f mm wide, loaf %.2f mm wide; foot left %.2f mm above the tray (h_p %.2f), "
        .. "right %.2f (h_p %.2f); cracked at (mm from the axis, above the tray): %s"):format(f.t, (bhi - blo) * 1e3,
        (hi - lo) * 1e3, (foot[1].y - TRAY) * 1e3, foot[1].h * 1e3, (foot[2].y - TRAY) * 1e3, foot[2].h * 1e3,
        table.concat(cracked, " ")))
    end
    return run(self, r)
  end
  return s
end

dofile(P.bread)

-- bread3d.lua: bread.lua in 3D, measured (docs/validation.md, "bread.lua in 3D").
-- It runs scripts/scenes/baking/bread.lua itself (same loaves, same measures,
-- same bread.csv) and adds:
--  * zw: the length (m) each loaf is extruded along z (the scene's 0.06). With
--    zw = 0.12 a loaf spans the whole box, its two ends against the box's slip
--    walls, so it cannot grow along its length, as a 2D (plane strain) loaf
--    cannot: only h.recipes.loaf_shape's length is changed.
--  * box_z: the box's length along z (m; the scene's 0.12), centred on the loaf's z = 0.06, so a loaf longer than
--    the scene's (zw up to box_z) keeps free ends: does a long loaf's middle stand as a 2D loaf?
--  * ends: "cut" (the scene's: the profile extruded, two flat cut ends) or "round" (a loaf a baker shapes, a batard:
--    the straight part zw long and each end the profile revolved about the vertical through the end of the straight
--    part, a half dome of the loaf's half width: the box's straight walls become a half cylinder standing on the tray
--    and the round top a quarter sphere, so the loaf is zw + its width long; docs/validation.md, "bread.lua's 3D
--    loaf: its ends and its yield"). The scene's slits (cut over z in [0, 0.12]) then run to ~1 cm from the tips.
--  * nu: the dough's Poisson ratio (the bread preset's 0.3 unless set): with nu = 0 a crumb held along z and one free
--    along it stretch alike in their cross-section under the same gas (docs/validation.md, "bread.lua's 3D loaf: its
--    ends and its yield": the check of plane strain's (1 + nu)).
--  * beta_scale: a factor on the oven's heat transfer coefficient (oven.beta, Ding et al. eq. 9's Robin boundary;
--    the tray's is kept), to heat a loaf with free ends as slowly as one with held ends.
--  * tray_mode, tray_friction: h.recipes.tray's contact ("separate", "slip", "sticky" or "grip", docs/lua.md;
--    friction 0.4 unless set): does the tray's hold on the loaf's foot decide how tall the 3D loaf stands?
--    (docs/validation.md, "The loaf's foot on its tray (#18, helper loaffoot)"). bread.lua's own `tray` ("separate"
--    or "sticky") is passed through as well; tray_mode, when set, overrides it (its default "" leaves bread.lua's).
--  * grid_shift: the box's floor moved down by this much (m, [0, 0.02); the scene's 0), so the grid's node rows fall
--    elsewhere against the tray (y = 0.02): does what a tray holds depend on where its rows fall?
--  * pictures of the raw and the baked loaf, cut through its middle: across it
--    (the plane z = 0.06: slice_z_raw.png, slice_z_end.png) and along it (the
--    plane x through the loaf's axis: slice_x_raw.png, slice_x_end.png), of the
--    field `field` (default J, the volume ratio) and of the damage at the end.
--   hearth run scripts/validation/bread3d.lua --set only=1 [--set zw=0.12] [--set dx=0.006 --set dx_min_3d=0.006]
local h = require "hearth"
local P = h.params { dim = 3, dx = 0.008, until_t = 2.5, frames = 10, slit_depth = 0.02, slit_width = 0.01, only = 1,
  dx_min_3d = 0.008, zw = 0.06, box_z = 0.12, beta_scale = 1, nu = 0.3, field = "J",
  ends = h.choice { "cut", cut = "cut faces at z = 0.06 +- zw/2 (bread.lua's 2D loaf extruded)",
    round = "rounded ends as a baker shapes them: the 2D profile turned about the loaf's axis at each end" },
  tray = "separate", -- bread.lua's own tray, passed on (h.pass_params: bread.lua's words hold)
  tray_mode = h.choice("", h.contact_words, { [""] = "bread.lua's tray (its --set tray)" }), tray_friction = 0.4, grid_shift = 0,
  bread = h.scene_path("../scenes/baking/bread.lua") }
if P.dim ~= 3 then error(("bread3d.lua: dim %d: expected 3 (bread.lua itself runs 2D)"):format(P.dim)) end
if not (P.box_z >= 0.12 and P.box_z <= 0.6) then error(("bread3d.lua: box_z %g m: expected [0.12, 0.6]"):format(P.box_z)) end
if not (P.zw > 0 and P.zw <= P.box_z) then
  error(("bread3d.lua: zw %g m: expected (0, box_z = %g] (the box's length in z)"):format(P.zw, P.box_z))
end
if P.ends == "round" and P.zw + 0.08 > P.box_z - 0.02 then -- 0.08: bread.lua's loaf width, the two half domes
  error(("bread3d.lua: zw %g m with ends = \"round\": the loaf is zw + 0.08 m long; expected zw <= box_z - 0.1 = %g "
    .. "(1 cm of room at each tip)"):format(P.zw, P.box_z - 0.1))
end
if not (P.nu >= 0 and P.nu < 0.5) then error(("bread3d.lua: nu %g: expected [0, 0.5)"):format(P.nu)) end
if not (P.beta_scale > 0 and P.beta_scale <= 10) then error(("bread3d.lua: beta_scale %g: expected (0, 10]"):format(P.beta_scale)) end
if not (P.tray_friction >= 0 and P.tray_friction <= 100) then
  error(("bread3d.lua: tray_friction %g: expected [0, 100] (Coulomb coefficient)"):format(P.tray_friction))
end
if not (P.grid_shift >= 0 and P.grid_shift < 0.02) then
  error(("bread3d.lua: grid_shift %g m: expected [0, 0.02) (the box's floor moved down, below the tray)"):format(P.grid_shift))
end
if P.only < 1 or P.only > 3 then error(("bread3d.lua: only %d: expected 1, 2 or 3 (one loaf)"):format(P.only)) end

if P.tray_mode ~= "" or P.tray_friction ~= 0.4 then -- the defaults leave h.recipes.tray untouched
  local tray = h.recipes.tray
  h.recipes.tray = function(s, y, o)
    o = o or {}
    if P.tray_mode ~= "" then o.mode = P.tray_mode end -- else bread.lua's own `tray`
    o.friction = P.tray_friction
    return tray(s, y, o)
  end
end

-- bread.lua's own h.params sees the values parsed here (it declares a subset of these names)
h.pass_params(P)
local loaf_shape = h.recipes.loaf_shape
h.recipes.loaf_shape = function(dim, x, tray, w, body, zc, _)
  if P.ends == "cut" then return loaf_shape(dim, x, tray, w, body, zc, P.zw) end
  local z0, z1, r = zc - P.zw / 2, zc + P.zw / 2, w / 2
  return (h.box({ x - r, tray, z0 }, { x + r, tray + body, z1 }) + -- the straight part's walls
    h.cylinder({ x, tray + body / 2, z0 }, { 0, 1, 0 }, r, body / 2) + -- each end's walls, revolved
    h.cylinder({ x, tray + body / 2, z1 }, { 0, 1, 0 }, r, body / 2) +
    h.capsule({ x, tray + body, z0 }, { x, tray + body, z1 }, r)) - -- the round top, its ends revolved
    h.box({ x - w, tray - w, z0 - w }, { x + w, tray, z1 + w })
end

if P.nu ~= 0.3 then
  local material = h.material
  h.material = function(plugin, params)
    if plugin == "cam_clay_dough" then params.nu = P.nu end
    return material(plugin, params)
  end
end

-- the scene bread.lua makes, behind a proxy whose run draws the slices before and after the bake
local xl = (P.only - 0.5) * 0.14 -- the loaf's axis (bread.lua: SPACING 0.14)
local function slices(s, tag)
  s:png(P.field, "slice_z_" .. tag .. ".png", { kind = "slice", axis = "z", at = 0.06, range = "frame" })
  s:png(P.field, "slice_x_" .. tag .. ".png", { kind = "slice", axis = "x", at = xl, range = "frame" })
end
local scene = h.scene
h.scene = function(def)
  if def.oven and P.beta_scale ~= 1 then def.oven.beta = def.oven.beta * P.beta_scale end
  if P.box_z ~= 0.12 then def.box[1][3], def.box[2][3] = 0.06 - P.box_z / 2, 0.06 + P.box_z / 2 end
  if P.grid_shift ~= 0 then def.box[1][2] = def.box[1][2] - P.grid_shift end
  local s = scene(def)
  return setmetatable({}, { __index = function(_, k)
    if k == "run" then
      return function(_, opts)
        slices(s, "raw")
        s:run(opts)
        slices(s, "end")
        s:png("damage", "damage_x_end.png", { kind = "slice", axis = "x", at = xl, range = { 0, 1 } })
      end
    end
    local f = s[k]
    if type(f) == "function" then return function(_, ...) return f(s, ...) end end
    return f
  end })
end
dofile(P.bread)

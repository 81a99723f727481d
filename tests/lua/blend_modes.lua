-- The scene's blend mode decides how a body made of h.mix{...} is simulated
-- (Nagasawa et al. Figs. 1b-d): the model, linearly blended parameters, or
-- random binary labels.
local h = require "hearth"
local mayo, honey = h.library.sauce.mayo, h.library.sauce.honey
local mix = h.mix { { mayo, 0.3 }, { honey, 0.7 } }
local lin = h.blend(mix, "linear")
for _, k in ipairs { "h", "eta", "sigma_y" } do
  local want = 0.3 * mayo[k] + 0.7 * honey[k]
  assert(math.abs(lin[k] - want) <= 1e-12 * want, ("linear %s = %g, want %g"):format(k, lin[k], want))
end
assert(mix.eta < 0.5 * lin.eta, "the model thins the mixture well below the linear blend")

local function body_params(mode)
  local s = h.scene { dim = 2, dx = 1 / 32, blend = mode }
  local m = h.material("von_mises_sauce", mix)
  local b = s:add { shape = h.box({ 0.25, 0.25 }, { 0.75, 0.75 }), material = m, ppc = 4 }
  return s, b, s:_state().mats[m]
end

-- nonlinear (the default) simulates the model's parameters
local s, _, id = body_params(nil)
local p = s:material_params(id)
assert(p.eta == mix.eta and p.h == mix.h and p.sigma_y == mix.sigma_y, "nonlinear uses h.mix's parameters")

-- linear simulates the mean parameters
s, _, id = body_params("linear")
p = s:material_params(id)
assert(p.eta == lin.eta and p.h == lin.h and p.sigma_y == lin.sigma_y, "linear uses the mean parameters")

-- labels: one material per constituent, drawn with the ratios
local b
s, b, id = body_params("labels")
assert(type(id) == "table" and #id == 2, "labels registers one material per constituent")
assert(s:material_params(id[1]).sigma_y == mayo.sigma_y and s:material_params(id[2]).eta == honey.eta,
  "labels keep the pure parameters")
local counts = s:_state().label_counts[b]
local n = s:body_particles(b)
assert(counts[1] + counts[2] == n, "every particle is labelled")
local frac = counts[1] / n
-- binomial: n = 1024 particles, sd = sqrt(0.21 / n) = 0.014; 4 sd
assert(math.abs(frac - 0.3) < 0.06, ("mayo fraction %.3f, want 0.3"):format(frac))
local again = select(1, body_params("labels"))
assert(again:hash() == s:hash(), "labels are deterministic for one seed")
s:step(3)

-- a bare h.mix table is accepted as a material, and a bad mode is named
s = h.scene { dim = 2, dx = 1 / 32, blend = "labels" }
s:add { shape = h.disc({ 0.5, 0.5 }, 0.1), material = mix }
local ok, e = pcall(h.scene, { dim = 2, blend = "linar" })
assert(not ok and e:find("blend = linar; valid: nonlinear, linear, labels", 1, true), tostring(e))
print(("blend modes ok: mayo fraction %.3f of %d particles"):format(frac, n))

-- The fields' own clock against the mechanical step (issue 20, fields/field_clock.c), in a shipped scene:
--   FIELD_SCENE=scripts/scenes/baking/cookies.lua hearth run scripts/bench/field_rates.lua --set until_t=0.2
-- runs the scene as it is (its own --set parameters pass through; --set field_steps=1 pins the old scheme) and
-- prints, for each scene it made, the last mechanical step dt, the fields' explicit limit (conduction, the oven's
-- and the tray's Robin terms, the latent sink, water), their ratio, and the cycle the last field update took.
local h = require "hearth"
local path = os.getenv("FIELD_SCENE") or error("field_rates.lua: set FIELD_SCENE to a scene file")
local made, scene0 = {}, h.scene
h.scene = function(def)
  local s = scene0(def)
  made[#made + 1] = s
  return s
end
dofile(path)
for i, s in ipairs(made) do
  local st = s:stats()
  print(("field_rates %s scene %d: t %.4g s, %d steps, dt %.3e s, field limit %.3e s (limit / dt %.1f), "
    .. "last field update %.3e s over %d steps"):format(path, i, st.t, st.step, st.dt, st.field_limit,
    st.field_limit / st.dt, st.field_dt, st.field_cycle))
end

-- lua_user_test.sh sph_particles_unmeasured_empty: h.write's rule for a CSV cell that is NaN (not measured: empty),
-- against the same text written to a file that is not a CSV (as written)
local h = require "hearth"
local text = ("a_m,b_m\n1,%g\n%g,2\n%.4g,banana\n"):format(0 / 0, -(0 / 0), 0 / 0)
h.write("x.csv", text)
h.write("x.txt", text)

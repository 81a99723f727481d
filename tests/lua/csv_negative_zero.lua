-- h.write of a CSV whose cells are negative zeros as %.6f, %g and %.3e print them (tests/lua_user_test.sh,
-- csv_negative_zero_written_0): each reads 0; a real negative number and a text cell stay as written.
local h = require "hearth"
local z = -0.0
h.write("zeros.csv", ("a_m,b_Pa,c_1,d_m,e\n%.6f,%g,%.3e,%.6f,-0 km\n%.6f,%d,%.2f,-0.5,x\n")
  :format(z, z, z, -1e-9, -2e-9, 0, -1e-4))
h.write("note.txt", ("%.6f\n"):format(z)) -- not a CSV: left as written

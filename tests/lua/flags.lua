-- params_flag_meaning: a true-or-false parameter declared with its meaning (h.flag) and --set.
local h = require "hearth"
local P = h.params { water = h.flag { true, what = "the batter carries its water" },
  baseline = h.flag { false, what = "Stomakhin's law in place of the dough's" }, png = true }
print(("water=%s baseline=%s png=%s"):format(tostring(P.water), tostring(P.baseline), tostring(P.png)))
for _, bad in ipairs { { 1 }, { "true", what = "x" }, { false }, { true, what = "x", wat = 1 } } do
  local ok, e = pcall(h.flag, bad)
  print("declaration refused: " .. tostring(not ok) .. " " .. tostring(e))
end

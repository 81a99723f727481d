-- params_number_declaration_errors: h.number's own refusals, each caught and printed with its line.
local h = require "hearth"
local function try(label, f)
  local ok, e = pcall(f)
  print(label .. ": " .. (ok and "accepted" or tostring(e)))
end
try("no what", function() local _ = h.number { 1, min = 0 }; return _ end)
try("no range", function() local _ = h.number { 1, what = "x" }; return _ end)
try("empty range", function() local _ = h.number { 1, above = 2, below = 1, what = "x" }; return _ end)
try("min and above", function() local _ = h.number { 1, min = 0, above = 0, what = "x" }; return _ end)
try("unknown key", function() local _ = h.number { 1, mn = 0, what = "x" }; return _ end)
try("bound not finite", function() local _ = h.number { 1, max = 1 / 0, what = "x" }; return _ end)
try("not a table", function() local _ = h.number(3); return _ end)
try("max_count without list", function() local _ = h.number { 1, min = 0, max_count = 3, what = "x" }; return _ end)
try("max_count not whole", function() local _ = h.number { { 1 }, list = true, min = 0, max_count = 2.5, what = "x" }; return _ end)

-- params_choice_declaration_errors: h.choice's own refusals, each at the call's line.
local h = require "hearth"
local function try(what, f)
  local ok, e = pcall(f)
  print(("%s: %s"):format(what, ok and "accepted" or tostring(e)))
end
try("one word", function() local c = h.choice { "a", a = "the only one" } return c end)
try("no description", function() local c = h.choice { "a", a = "first", b = true } return c end)
try("empty description", function() local c = h.choice { "a", a = "first", b = "" } return c end)
try("a second default", function() local c = h.choice { "a", "b", a = "first", b = "second" } return c end)
try("a word with a comma", function() local c = h.choice { "a", a = "first", ["b,c"] = "two" } return c end)
try("not a table", function() local c = h.choice "a" return c end)
try("shared words not a table", function() local c = h.choice("a", "b") return c end)
try("a word twice", function() local c = h.choice("slip", h.contact_words, { slip = "again" }) return c end)
try("no default", function() local c = h.choice { a = "first", b = "second" } return c end)
try("shared and own", function() local c = h.choice("", h.contact_words, { [""] = "the scene's own" }) return c end)

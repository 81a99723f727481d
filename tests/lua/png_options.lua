-- png_range_option, png_colormap_option, png_label_in_title: the options of s:png and s:run's png.
-- A jelly block at 20 degC in a 180 degC oven, on a tray.
local h = require "hearth"
local which = h.params { case = "range" }.case
local s = h.scene { dim = 2, dx = 0.01, box = { { 0, 0 }, { 0.2, 0.1 } }, oven = { temperature = 180, beta = 30 } }
local jelly = h.material("elastic", { E = 2e5, nu = 0.3, density = 1000 })
s:collider { shape = h.box({ 0, 0 }, { 0.2, 0.02 }), mode = "sticky" }
s:add { shape = h.box({ 0.05, 0.02 }, { 0.15, 0.05 }), material = jelly, temperature = 20 }

local function show(name, info)
  print(("%s range %g %g ticks %s colormap %s unit %s size %dx%d"):format(name, info.range[1], info.range[2],
    table.concat(info.ticks, ","), info.colormap, info.unit, info.width, info.height))
end
local function refused(opts)
  local ok, err = pcall(s.png, s, "temperature", "bad.png", opts)
  print("refused " .. tostring(not ok) .. " " .. tostring(err))
end

if which == "range" then
  local _, d = s:png("temperature", "default.png")
  show("default", d)
  local _, r = s:png("temperature", "range.png", { range = { 20, 200 } })
  show("given", r)
  local _, f = s:png("temperature", "frame.png", { range = "frame", kind = "particles" })
  show("frame", f)
  refused { range = { 200, 20 } }
  refused { range = { 20 } }
  refused { range = "all" }
  -- s:run passes the range to every frame
  s:run { until_t = 0.002, every = 0.001,
    png = { field = "temperature", path = "run_%04d.png", range = { 0, 250 }, kind = "slice" } }
  local ok, err = pcall(s.run, s, { until_t = s:stats().t + 0.001, png = { field = "temperature", rnage = { 0, 1 } } })
  print("run_typo " .. tostring(ok) .. " " .. tostring(err))
elseif which == "label" then
  -- the label goes first in the title, the time after it; without one the title is the time alone, as before
  local _, plain = s:png("temperature", "plain.png")
  print("plain title: " .. plain.title)
  local _, l = s:png("temperature", "label.png", { label = "oven 110 °C" })
  print("label title: " .. l.title)
  local _, ls = s:png("temperature", "label_scaled.png", { label = "oven 110 °C", time_scale = 50 })
  print("scaled title: " .. ls.title)
  -- the longest label, HEARTH_PICTURE_LABEL_MAX (64 bytes until helper userfix10 made it 128), whole in the title
  local _, long = s:png("temperature", "label_128.png", { label = ("x"):rep(128) })
  print("128-byte title length " .. #long.title)
  refused { label = ("x"):rep(129) }
  refused { label = "two\nlines" }
  -- long and with an escape: refused for the escape, so the length's message (which quotes the label's start)
  -- never carries it to the terminal
  refused { label = "ab\27[2J" .. ("x"):rep(70) }
  refused { label = 3 }
  s:run { until_t = 0.002, every = 0.001, png = { field = "temperature", path = "run_%04d.png", label = "oven 110 °C" } }
  local ok, err = pcall(s.run, s, { until_t = s:stats().t + 0.001, png = { field = "temperature", label = {} } })
  print("run_label_table " .. tostring(ok) .. " " .. tostring(err))
  ok, err = pcall(s.run, s, { until_t = s:stats().t + 0.001, png = { field = "temperature", label = ("y"):rep(129) } })
  print("run_label_long " .. tostring(ok) .. " " .. tostring(err))
elseif which == "region" then
  -- png_region_option (#18, helper userfix5): a close-up of the block, particles and slice, and a run's frames
  local _, d = s:png("temperature", "whole.png", { kind = "particles" })
  show("whole", d)
  local R = { { 0.04, 0.01 }, { 0.16, 0.06 } }
  local _, p = s:png("temperature", "close.png", { kind = "particles", region = R })
  show("close", p)
  local _, q = s:png("temperature", "close_slice.png", { region = R })
  show("close_slice", q)
  refused { region = { { 0.04, 0.01 }, { 0.26, 0.06 } } } -- beyond the domain's x
  refused { region = { { 0.16, 0.01 }, { 0.04, 0.06 } } } -- backwards
  refused { region = { 0.04, 0.01, 0.16, 0.06 } }         -- not two corners
  s:run { until_t = 0.002, every = 0.001, png = { field = "temperature", path = "run_%04d.png", region = R } }
  local ok, err = pcall(s.run, s, { until_t = s:stats().t + 0.001, png = { field = "temperature", regoin = R } })
  print("run_misspelt " .. tostring(ok) .. " " .. tostring(err))
else
  local _, c = s:png("temperature", "cividis.png", { colormap = "cividis" })
  show("cividis", c)
  local _, dv = s:png("velocity_x", "diverging.png", { colormap = "diverging", range = { -1, 1 } })
  show("diverging", dv)
  local _, b = s:png("temperature", "browning.png", { colormap = "browning" })
  show("browning", b)
  refused { colormap = "jet" }
  refused { colormap = 3 }
  local ok, err = pcall(s.run, s, { until_t = 0.001, png = { field = "temperature", colormap = "jett" } })
  print("run_bad_map " .. tostring(ok) .. " " .. tostring(err))
  s:run { until_t = 0.002, every = 0.001, png = { field = "temperature", path = "run_%04d.png", colormap = "cividis" } }
end

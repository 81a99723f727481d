-- params_time_frames_top_named: a number in seconds, frames or degC has the run's own top (s:run's 1e12 s, hearth run
-- --frames's 1e6, the core's 5000 degC), so 1e300 is refused by the parameter's name, not by what the scene made of it.
local h = require "hearth"
local P = h.params { until_t = h.number { 0.4, above = 0, unit = "s", what = "the run's simulated time" },
  lambda = h.number { 20, min = 1e-9, max = 1e9, unit = "s", what = "a relaxation time under the top" },
  wait = h.number { 1, min = 0, max = 1e15, unit = "s", what = "a wait declared past the top" },
  gap = h.number { 0, min = 0, below = 1e13, unit = "s", what = "a time with a strict end past the top",
    also = { [-1] = "none" } },
  frames = h.number { 4, min = 1, integer = true, unit = "frames", what = "PNG frames over the run" },
  pan = h.number { 180, min = -273.15, unit = "degC", what = "the pan's temperature" },
  dx = h.number { 0.002, above = 0, unit = "m", what = "the grid spacing" } }
print(("until_t=%g lambda=%g wait=%g gap=%g frames=%g pan=%g dx=%g"):format(P.until_t, P.lambda, P.wait, P.gap, P.frames,
  P.pan, P.dx))
-- the frames over the run, as the shipped scenes make them: s:run takes every in [1e-12, 1e12] s
print(("every=%g"):format(P.until_t / P.frames))

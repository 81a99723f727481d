#!/usr/bin/env bash
# sph_instructions.sh [DX...]: instructions per particle-step of the SPH
# dam break (scripts/bench/sph_dam_break.lua), one thread, under callgrind:
# the difference of a run with 2 more steps and one without, over 2 steps
# and the particles, so setup and the 2 warm-up steps cancel. Built without
# -march=native (valgrind does not decode AVX-512). Issue #20 measured
# 14.7k on its dam break; DualSPHysics does not run here.
#   scripts/bench/sph_instructions.sh               # dx 0.002 and 0.001: 20k and 80k particles
#   scripts/bench/sph_instructions.sh 0.004         # 5k, a quick look
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/scripts/bench/callgrind.sh"
[ $# -gt 0 ] || set -- 0.002 0.001
for dx in "$@"; do
    count() { refs "$nn_hearth" run "$root/scripts/bench/sph_dam_break.lua" --quiet --set dx="$dx" --set steps="$1"; }
    n=$(python3 -c "print(round(0.2 / $dx) * round(0.4 / $dx))")
    a=$(count 0) b=$(count 2)
    python3 -c "print('SPH dam break, %d particles (dx %s), 1 thread: %.0f instructions per particle-step' % ($n, '$dx', ($b - $a) / 2 / $n))"
done

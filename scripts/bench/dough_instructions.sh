#!/usr/bin/env bash
# dough_instructions.sh [DIM] [CELLS]: the cost of one cam_clay_dough step
# with all its fields against the elastic step on the same particles
# (scripts/bench/dough_step.lua), in instructions: callgrind counts repeat
# exactly where wall time on a shared machine does not. Counts a short and a
# long run of each and divides the difference, so setup cancels. Built
# without -march=native (valgrind does not decode AVX-512). Issue #5's
# target: at most 2.5x.
#   scripts/bench/dough_instructions.sh 2 64     # the default
#   scripts/bench/dough_instructions.sh 3 24
set -euo pipefail
dim=${1:-2} cells=${2:-64}
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/scripts/bench/callgrind.sh"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
count() { # count elastic|dough STEPS -> instructions
    refs "$nn_hearth" run "$root/scripts/bench/dough_step.lua" --quiet --out "$out" --set only="$1" --set steps="$2" \
        --set dim="$dim" --set cells="$cells"
}
short=2 long=$([ "$dim" = 3 ] && echo 5 || echo 12)
e=$(python3 -c "print(($(count elastic $long) - $(count elastic $short)) / ($long - $short))")
d=$(python3 -c "print(($(count dough $long) - $(count dough $short)) / ($long - $short))")
python3 -c "print('%sD, %s cells: elastic %.4g, cam_clay_dough with all fields %.4g instructions per step: %.2fx (target <= 2.5x)' % ('$dim', '$cells', $e, $d, $d / $e))"

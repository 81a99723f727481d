#!/usr/bin/env bash
# fields_instructions.sh [CELLS] [DIM]: what the mixture fields cost, in
# instructions. Wall time on a shared machine swings by tens of percent from
# run to run; callgrind's instruction counts do not. Counts one and four
# steps of the `hearth bench` block with no fields, with heat (an oven), and
# with heat, CO2 and water, and divides the difference by three, so setup
# cancels. Built without -march=native (valgrind does not decode AVX-512).
# Ding et al.'s mixture, issue #4's target: all fields at most 2x.
#   scripts/bench/fields_instructions.sh          # 24 cells, 3D
set -euo pipefail
cells=${1:-24} dim=${2:-3}
root=$(cd "$(dirname "$0")/../.." && pwd)
. "$root/scripts/bench/callgrind.sh"
count() { refs "$nn_hearth" bench --threads 1 --cells "$cells" --steps "$2" --dim "$dim" --fields "$1"; } # FIELDS STEPS
declare -A per
for f in none heat all; do
    per[$f]=$(python3 -c "print(($(count $f 4) - $(count $f 1)) / 3)")
done
for f in none heat all; do
    python3 -c "print('fields=%-5s %.4g instructions per step  ratio %.2f' % ('$f', ${per[$f]}, ${per[$f]} / ${per[none]}))"
done

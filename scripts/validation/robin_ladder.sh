#!/usr/bin/env bash
# robin_ladder.sh [BUILD]: the oven's Robin boundary on round bodies against
# the series solution (issue #17), on longer ladders than the suite runs: a
# disc at R = 8..64 dx and a ball at R = 4..16 dx, heat taken at Fo = 0.1,
# Bi = 1, with the measured surface and the observed order between levels.
# Also the turned square of `robin_square_rotations`. The output goes into
# docs/validation.md ("Oven surface measure").
#   scripts/validation/robin_ladder.sh build/release
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
unit=$build/tests/unit_heat
[ -x "$unit" ] || { echo "$(basename "$0"): no $unit (build first)" >&2; exit 2; }
export OMP_NUM_THREADS=1
run() { # LADDER CASE: every ladder runs; its verdict (ok, or FAIL: order below one at the last pair) is printed
    echo "== $2, R/dx = $1"
    local rc=0
    ROBIN_LADDER="$1" timeout 900 "$unit" "$2" || rc=$?
    echo "   exit status $rc"
}
echo "== robin_square_rotations"
timeout 300 "$unit" robin_square_rotations
run "8 16 32 64" robin_disc_converges
run "4 6 8 12 16" robin_ball_converges

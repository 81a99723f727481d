#!/usr/bin/env bash
# water_ladder.sh [BUILD]: water boundaries against Crank's plane sheet
# (issue #17), on a longer ladder than the suite runs (10, 20, 40, 80 cells
# across the half-thickness a): faces held by wet colliders (Crank eq. 4.18),
# a Robin exchange through wet colliders with beta_water and through the air
# toward a humid oven (eq. 4.54, L = 1), and the interior's sine mode between
# insulated faces. Each prints its errors and the observed orders between
# levels. The output goes into docs/validation.md ("Wet colliders and the
# humid oven").
#   scripts/validation/water_ladder.sh build/release
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
unit=$build/tests/unit_water
[ -x "$unit" ] || { echo "$(basename "$0"): no $unit (build first)" >&2; exit 2; }
export OMP_NUM_THREADS=1 WATER_LADDER=${WATER_LADDER:-"10 20 40 80"}
for case in water_sheet_fixed_surface_converges water_sheet_robin_converges water_interior_mode_second_order; do
    echo "== $case, cells across a: $WATER_LADDER"
    rc=0
    timeout 900 "$unit" "$case" || rc=$?
    echo "   exit status $rc"
done

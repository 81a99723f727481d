#!/usr/bin/env bash
# water_ladder.sh [BUILD]: water boundaries against Crank's plane sheet
# (issue #17), on a longer ladder than the suite runs (10, 20, 40, 80 cells
# across the half-thickness a): faces held by wet colliders (Crank eq. 4.18),
# a Robin exchange through wet colliders with beta_water and through the air
# toward a humid oven (eq. 4.54, L = 1: the strip 0.6 a high, refined with
# its thickness, and then 6 rows at every level, where the contact corners'
# share is fixed), the interior's sine mode between insulated faces, and fast
# drying into dry air against a fine 1D solution (L = 5, 10 to 40 cells).
# Each prints its errors and the observed orders between levels. The output
# goes into docs/validation.md ("Wet colliders and the humid oven").
#   scripts/validation/water_ladder.sh build/release
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
unit=$build/tests/unit_water
[ -x "$unit" ] || { echo "$(basename "$0"): no $unit (build first)" >&2; exit 2; }
export OMP_NUM_THREADS=1 WATER_LADDER=${WATER_LADDER:-"10 20 40 80"}
run() { # CASE [ENV=VALUE...]
    local case=$1
    shift
    echo "== $case $*, cells across a: $WATER_LADDER"
    rc=0
    env "$@" timeout 900 "$unit" "$case" || rc=$?
    echo "   exit status $rc"
}
for case in water_sheet_fixed_surface_converges water_sheet_robin_converges water_humid_oven_converges water_interior_mode_second_order; do
    run "$case"
done
# the oven's sheet 6 rows high at every level: prints, checks no order
run water_humid_oven_converges WATER_OVEN_ROWS=6
WATER_LADDER=${WATER_DRYING_LADDER:-"10 20 40"} run water_drying_fast_vs_fd

#!/usr/bin/env bash
# heat_collider_ladder.sh [BUILD]: heated colliders (Robin contact) and held
# temperatures (Dirichlet) on a slab against the series solution (issue #17),
# on longer ladders than the suite runs: L = 5..40 dx, heat taken at Fo = 0.1
# (Robin, Bi = 1 and 100) and Fo = 0.3 (held collider, held body), with the
# observed order between levels; the plate turned 30 degrees; CG iterations
# with held nodes eliminated against beta = 1e9. The output goes into
# docs/validation.md ("Heated colliders and fixed temperatures").
#   scripts/validation/heat_collider_ladder.sh build/release
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
unit=$build/tests/unit_heat_bc
[ -x "$unit" ] || { echo "$(basename "$0"): no $unit (build first)" >&2; exit 2; }
export OMP_NUM_THREADS=1
run() { # LADDER CASE: every ladder runs; its verdict is printed
    echo "== $2, L/dx = $1"
    local rc=0
    SLAB_LADDER="$1" timeout 900 "$unit" "$2" || rc=$?
    echo "   exit status $rc"
}
run "5 10 20 40" heat_collider_robin_converges
run "5 10 20 40" heat_dirichlet_slab_converges
echo "== heat_collider_turned_plate"
timeout 300 "$unit" heat_collider_turned_plate
echo "== heat_dirichlet_cg_iterations"
timeout 300 "$unit" heat_dirichlet_cg_iterations

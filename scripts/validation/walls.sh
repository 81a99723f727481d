#!/bin/sh
# walls.sh: the collider ladders of issue #17 (docs/validation.md, "Collider
# faces, grips and the base stress"): the Couette lid on a node row, the
# gripped cantilever to 8 cells through the thickness, the column's base stress.
# Usage: scripts/validation/walls.sh [BUILD_DIR]   (default build/release)
set -eu
b=${1:-build/release}
export HEARTH_PLUGIN_PATH="$b/plugins" OMP_NUM_THREADS=1
for t in couette_lid_on_node_row grip_cantilever_clamped_at_face column_base_stress; do
    HEARTH_LONG_LADDER=1 "$b/tests/unit_mpm_boundaries" "$t" || [ $? -eq 77 ]
done

#!/bin/sh
# periodic.sh: the periodic-axis and body-force ladders of issue #17
# (docs/validation.md, "Periodic axes and body forces"): the shear wave in a
# doubly periodic box to 64 cells a wavelength, momentum across the seam,
# and the column under a body force growing with height.
# Usage: scripts/validation/periodic.sh [BUILD_DIR]   (default build/release)
set -eu
b=${1:-build/release}
export HEARTH_PLUGIN_PATH="$b/plugins" OMP_NUM_THREADS=1
for t in mpm_periodic_shear_wave mpm_periodic_conserves_momentum; do
    HEARTH_LONG_LADDER=1 "$b/tests/unit_mpm_boundaries" "$t"
done
root=$(cd "$(dirname "$0")/../.." && pwd)
"$b/app/hearth" run "$root/tests/lua/body_force_field.lua" --quiet

#!/usr/bin/env bash
# front_instructions.sh [DX] [UNTIL_REAL] [BUILD]: what the boiling front
# (core/sim/fields/boil_front.c, water_boil_front: latent_heat on MPM) costs in
# scripts/scenes/baking/loaf_physical.lua, in instructions: the whole run's,
# water_boil_front's inclusive count and its share, and the tray's collider
# tests (collider_sdf inclusive). callgrind's counts repeat exactly where wall
# time on a shared machine does not. BUILD is a build directory without
# -march=native (valgrind does not decode AVX-512; default build/nn, made
# here when missing), so that another checkout's build can be counted
# against this one. Numbers only: no bar (docs/performance.md, "The boiling
# front's cost").
#   scripts/bench/front_instructions.sh                      # dx 5 mm, 2 real minutes
#   scripts/bench/front_instructions.sh 0.0025 60
#   scripts/bench/front_instructions.sh 0.005 120 /path/to/main/build/nn
set -euo pipefail
dx=${1:-0.005} until_real=${2:-120}
root=$(cd "$(dirname "$0")/../.." && pwd)
if [ -n "${3:-}" ]; then
    command -v valgrind >/dev/null || { echo "$(basename "$0"): needs valgrind" >&2; exit 2; }
    build=$(cd "$3" && pwd)
else
    . "$root/scripts/bench/callgrind.sh"
    build=$root/build/nn
fi
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT
OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1 HEARTH_PLUGIN_PATH="$build/plugins" \
    valgrind --tool=callgrind --callgrind-out-file="$out/cg.out" "$build/app/hearth" run \
    "$root/scripts/scenes/baking/loaf_physical.lua" --threads 1 --quiet --out "$out/run" \
    --set dx="$dx" --set until_real="$until_real" >/dev/null 2>&1
callgrind_annotate --inclusive=yes --threshold=100 "$out/cg.out" 2>/dev/null >"$out/incl.txt"
total=$(awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1; exit}' "$out/incl.txt")
fn() { awk -v f="$1" '$0 ~ ("[ :]" f " ") || $0 ~ ("[ :]" f "$") {gsub(",", "", $1); print $1; exit}' "$out/incl.txt"; }
front=$(fn water_boil_front) sdf=$(fn collider_sdf)
python3 -c "
t, f, c = $total, ${front:-0}, ${sdf:-0}
print('loaf_physical.lua dx %s m, %s real s: %.4g instructions; water_boil_front %.4g (%.1f%%); collider_sdf %.4g (%.1f%%)'
      % ('$dx', '$until_real', t, f, 100 * f / t, c, 100 * c / t))"

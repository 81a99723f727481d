#!/bin/sh
# fig17_grid.sh: Ding et al. 2019 Fig. 17 as hearth bakes it (#18): the
# Stomakhin-like baseline (top row, cookies.lua --set baseline=true) against
# the full model (bottom row), ovens 190, 150 and 110 degC from left to right,
# the leavened cookie (0.015) alone on its tray, 4 s (cookies.lua's real
# dough conductivity sets every cookie by 3.5 s at 150 degC), coloured by
# temperature. Prints each cookie's height and top curvature (probe;
# particles +- the fit's standard error, h.top_curvature) and writes the six
# last frames side by side as OUT (default docs/gallery/fig17_baseline_vs_dough.png).
# Usage: scripts/validation/fig17_grid.sh [BUILD_DIR] [DX] [OUT]   (defaults build/release 0.005)
set -eu
b=$(cd "${1:-build/release}" && pwd)
dx=${2:-0.005}
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${3:-$root/docs/gallery/fig17_baseline_vs_dough.png}
case $out in /*) ;; *) out=$(pwd)/$out ;; esac
export HEARTH_PLUGIN_PATH="$b/plugins" OMP_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for base in true false; do
    for T in 190 150 110; do
        d="$tmp/${base}_$T"
        mkdir -p "$d"
        (cd "$d" && "$b/app/hearth" run "$root/scripts/scenes/baking/cookies.lua" --quiet --set dx="$dx" \
            --set until_t=4 --set frames=1 --set ovens="$T" --set leaveners=0.015 --set baseline=$base |
            sed -n "s/^oven/baseline=$base: oven/p")
    done
done
# The last frame of each bake (heat_0001.png), baseline above, full model below.
python3 - "$tmp" "$out" "$root/scripts/validation" <<'PY'
import os, sys
sys.path.insert(0, sys.argv[3])
from png_rgb import read_png, write_png

tmp, out = sys.argv[1], sys.argv[2]
grid = [[read_png(os.path.join(tmp, f"{base}_{T}", "hearth-out", "cookies", f"oven_{T}", "heat_0001.png"))
         for T in (190, 150, 110)] for base in ("true", "false")]
gap = 6  # white pixels between pictures
w, h = grid[0][0][0], grid[0][0][1]
W, H = 3 * w + 2 * gap, 2 * h + gap
rows = []
for r, row in enumerate(grid):
    if r: rows += [b"\xff" * (3 * W)] * gap
    for y in range(h):
        rows.append((b"\xff" * (3 * gap)).join(pic[2][y] for pic in row))
write_png(out, rows)
print(f"wrote {out} ({W} x {H})")
PY

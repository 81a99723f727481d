#!/bin/sh
# muffin_dt.sh: muffins.lua's tear claim (tests/baking_test.sh,
# claim_muffin_top_tears: one cup, 1.5 s, 3 frames) over the time step (#18,
# helper crackdt), for docs/validation.md ("The crack over the time step"). cfl
# and dt_max are scene knobs every scene takes (`--set cfl=0.25`), so the scene
# runs as it is; each frame's notch is read as the claim's check reads its last
# (the same formula: a tenth of the height deep, two cells wide).
# A STEP may join several switches with + (cfl=0.5+transfer=pic: the scene's
# transfer too, as crack_dt.sh's STEPs do).
# Usage: scripts/validation/muffin_dt.sh [BUILD_DIR] [DX] [STEPS]
#   defaults build/release, 0.004, "cfl=0.5 cfl=0.25 cfl=0.125 cfl=0.4 cfl=0.6 cfl=0.75 dt_max=5e-5 dt_max=2.5e-5"
# One run at a time, single-threaded (the same bits at any thread count).
set -eu
b=$(cd "${1:-build/release}" && pwd)
dx=${2:-0.004}
steps=${3:-cfl=0.5 cfl=0.25 cfl=0.125 cfl=0.4 cfl=0.6 cfl=0.75 dt_max=5e-5 dt_max=2.5e-5}
root=$(cd "$(dirname "$0")/../.." && pwd)
export HEARTH_PLUGIN_PATH="$b/plugins" OMP_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for st in $steps; do
    d=$tmp/$st
    mkdir -p "$d"
    sets=$(echo "$st" | sed 's/+/ --set /g')
    # shellcheck disable=SC2086 # $sets: one --set per switch
    (cd "$d" && /usr/bin/time -o time.txt -f %U "$b/app/hearth" run "$root/scripts/scenes/baking/muffins.lua" --quiet \
        --set cups=1 --set dx="$dx" --set ppc=0 --set until_t=1.5 --set frames=3 --set $sets >out.txt)
    python3 - "$d/hearth-out/muffins/muffins.csv" "$dx" "$st" "$(cat "$d/time.txt")" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
dx = float(sys.argv[2])
BASE, RIM = 0.012, 0.042  # the cup's inner floor and rim (scripts/scenes/baking/muffins.lua)
for r in rows[1:]:
    height = RIM + float(r["top_above_rim_1_m"]) - BASE
    d, w = float(r["tear_depth_1_m"]), float(r["tear_width_1_m"])
    ok = "holds" if d >= 0.1 * height and w >= 2 * dx else "short"
    print(f"muffin dx {dx * 1e3:g} mm, {sys.argv[3]}, t {r['t_s']} s: notch {d * 1e3:.2f} mm (need {0.1 * height * 1e3:.2f}), "
          f"{w * 1e3:.0f} mm wide (need {2 * dx * 1e3:.0f}) {ok}; dome {float(r['centre_above_edge_1_m']) * 1e3:.2f} mm; "
          f"CPU {sys.argv[4]} s")
PY
done

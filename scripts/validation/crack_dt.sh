#!/bin/sh
# crack_dt.sh: bread.lua's unscored loaf over the time step (#18, helper crackdt),
# for docs/validation.md ("The crack over the time step"). Runs
# scripts/validation/crack_dt.lua (bread.lua with h.scene's cfl / dt_max set) for
# each DX and each STEP of a list and reads each run with the suite's own checks
# (tests/bread_claims.py: rises, dries, cracks) and where the crack is
# (scripts/validation/bread_grid.py where, last frame). A STEP is cfl=C (the CFL
# number; the heat and water limits still cap dt) or dt_max=T (a fixed largest
# step: uniform when below every limit), or several joined by + (dt_max=2.5e-5+field_steps=1:
# crack_dt.lua's other switches, transfer and field_steps). ONLY is bread.lua's only (1: the plain
# loaf alone, as the claims' tests run it; 0: the three loaves, as a user runs it).
# KEEP (a directory) keeps each run's printout, bread.csv and CPU time under KEEP/DX/STEP.
# Usage: scripts/validation/crack_dt.sh [BUILD_DIR] [DXS] [STEPS] [ONLY] [KEEP]
#   defaults build/release, "0.005 0.004", "cfl=0.5 cfl=0.25 cfl=0.125 dt_max=1e-4 dt_max=5e-5 dt_max=2.5e-5", 1, none
# One run at a time, single-threaded (the same bits at any thread count).
set -eu
b=$(cd "${1:-build/release}" && pwd)
dxs=${2:-0.005 0.004}
steps=${3:-cfl=0.5 cfl=0.25 cfl=0.125 dt_max=1e-4 dt_max=5e-5 dt_max=2.5e-5}
only=${4:-1}
keep=${5:-}
root=$(cd "$(dirname "$0")/../.." && pwd)
export HEARTH_PLUGIN_PATH="$b/plugins" OMP_NUM_THREADS=1
claims=$root/tests/bread_claims.py
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for dx in $dxs; do
    for st in $steps; do
        d=$tmp/$dx/$st
        mkdir -p "$d"
        sets=$(echo "$st" | sed 's/+/ --set /g')
        t0=$(date +%s)
        # shellcheck disable=SC2086 # $sets: one --set per switch
        (cd "$d" && /usr/bin/time -o time.txt -f %U "$b/app/hearth" run "$root/scripts/validation/crack_dt.lua" --quiet --set bread="$root/scripts/scenes/baking/bread.lua" \
            --set dx="$dx" --set $sets --set only="$only" >out.txt)
        echo "dx $dx, $st, only $only: $(($(date +%s) - t0)) s wall, $(tail -1 "$d/time.txt") s CPU; $(grep '^crack_dt:' "$d/out.txt")"
        csv=$d/hearth-out/crack_dt/bread.csv
        # shellcheck disable=SC2086 # each claim and its arguments, split
        for c in "rises $csv $dx plain" "dries $csv $dx" "cracks $csv $dx"; do
            r=0; python3 "$claims" $c >"$tmp/claim.txt" || r=$?
            echo "dx $dx, $st, ${c%% *}: exit $r: $(grep -v '^EXPECTED FAILURE' "$tmp/claim.txt" | tail -1)"
        done
        if [ -n "$keep" ]; then
            mkdir -p "$keep/$dx/$st"
            cp "$d/out.txt" "$d/time.txt" "$csv" "$keep/$dx/$st/"
        fi
        last=
        for f in "$d"/hearth-out/crack_dt/vtu/bread_*.vtu; do last=$f; done # the last frame (names sort by frame)
        python3 "$root/scripts/validation/bread_grid.py" where "$dx" "$last" | sed "s/^/dx $dx, $st, /"
    done
done

#!/bin/sh
# bread_grid.sh: every claim of bread.lua (#18) at each dx of a list, read by the
# test suite's own checks (tests/bread_claims.py, which tests/baking_test.sh
# calls at the scene's dx and one finer), for docs/validation.md ("bread.lua over
# dx (#18, helper breadgrid)"). Per dx, the runs the claims' tests make: the plain
# loaf (--set only=1, 5 frames: loaf_rises, surface_dries_first, unscored_cracks),
# the one-slit loaf (only=2, 5 frames: scored_loaf_rises) and the one-slit loaf at
# 10 frames (slit_widens; its test runs at 6 mm). Prints each claim's numbers and
# verdict (0 holds, 1 fails, 77 the crack's expected failure), each run's wall and CPU time,
# where the plain loaf's crack is at each frame (scripts/validation/bread_grid.py
# where), and writes the plain loaf's last damage.png at each dx side by side as OUT.
# EXTRA (environment, empty by default) adds scene switches to every run, several
# joined by + as crack_dt.sh's STEPs are (EXTRA=cfl=0.25+transfer=pic: the same
# runs at another step and transfer; helper flipcrack ran it with the APIC-FLIP
# transfer of branch tauflip); unset, the runs are as before. RUNS=plain makes only
# the plain loaf's run (its three claims, where the crack is, the damage strip):
# a third of the time, for a question about the unscored crack alone (helper
# nonlocal's damage_length ladder); the claims of a loaf not run are left out.
# Usage: [EXTRA=K=V+K=V] scripts/validation/bread_grid.sh [BUILD_DIR] [DXS] [OUT]
#   (defaults build/release, "0.005 0.0045 0.004 0.0035 0.003 0.0025 0.002",
#   docs/gallery/bread_damage_over_dx.png; the seven dx take ~20 minutes of one core)
# One run at a time, single-threaded (results are the same bits at any thread count).
set -eu
b=$(cd "${1:-build/release}" && pwd)
dxs=${2:-0.005 0.0045 0.004 0.0035 0.003 0.0025 0.002}
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${3:-$root/docs/gallery/bread_damage_over_dx.png}
case $out in /*) ;; *) out=$(pwd)/$out ;; esac
extra=
[ -z "${EXTRA:-}" ] || extra="--set $(echo "$EXTRA" | sed 's/+/ --set /g')"
export HEARTH_PLUGIN_PATH="$b/plugins" OMP_NUM_THREADS=1
claims=$root/tests/bread_claims.py
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
pngs=
for dx in $dxs; do
    runs="plain:1:5 scored:2:5 slit:2:10"
    [ "${RUNS:-}" != plain ] || runs=plain:1:5
    for run in $runs; do
        name=${run%%:*} rest=${run#*:}
        d=$tmp/$dx/$name
        mkdir -p "$d"
        t0=$(date +%s)
        # a run the guard stops (exit 3) is said so and the ladder goes on: its bread.csv holds the
        # frames written before the stop, which the claims below then read (a bake cut short)
        r=0
        # shellcheck disable=SC2086 # $extra: one --set per switch, or nothing
        (cd "$d" && /usr/bin/time -o time.txt -f %U "$b/app/hearth" run "$root/scripts/scenes/baking/bread.lua" --quiet --set dx="$dx" \
            --set only="${rest%:*}" --set frames="${rest#*:}" $extra >out.txt) || r=$?
        echo "dx $dx, $name loaf: $(($(date +%s) - t0)) s wall, $(tail -1 "$d/time.txt") s CPU$([ "$r" -eq 0 ] || echo ", STOPPED (exit $r): its claims read the frames before the stop")"
    done
    csv=$tmp/$dx/plain/hearth-out/bread/bread.csv
    # shellcheck disable=SC2086 # each claim and its arguments, split
    for c in "rises $csv $dx plain" "rises $tmp/$dx/scored/hearth-out/bread/bread.csv $dx one_slit" "dries $csv $dx" \
        "cracks $csv $dx" "slit_widens $tmp/$dx/slit/hearth-out/bread/bread.csv"; do
        # shellcheck disable=SC2086 # the claim's CSV is its second word
        set -- $c
        [ -f "$2" ] || continue # RUNS=plain: that loaf was not run
        r=0; python3 "$claims" $c >"$tmp/claim.txt" || r=$?
        echo "dx $dx, ${c%% *}: exit $r: $(grep -v '^EXPECTED FAILURE' "$tmp/claim.txt" | tail -2 | tr '\n' ' ')"
    done
    python3 "$root/scripts/validation/bread_grid.py" where "$dx" "$tmp/$dx"/plain/hearth-out/bread/vtu/bread_*.vtu | sed "s/^/dx $dx, /"
    [ ! -f "$tmp/$dx/plain/hearth-out/bread/damage.png" ] || pngs="$pngs $tmp/$dx/plain/hearth-out/bread/damage.png"
done
# shellcheck disable=SC2086 # one PNG per dx (none when every plain loaf was stopped)
[ -z "$pngs" ] || python3 "$root/scripts/validation/bread_grid.py" strip "$out" $pngs

#!/usr/bin/env bash
# fields_overhead.sh [CELLS] [STEPS] [DIM]: what the mixture fields cost.
# Runs `hearth bench` on the same elastic block with no fields, with heat (an
# oven), and with heat, CO2 and water, alternating three rounds so machine
# noise hits all three alike, and prints each one's best time and its ratio to
# the momentum-only step. Ding et al.'s target: all fields at most 2x.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
hearth=${HEARTH:-$root/build/release/core/app/hearth}
cells=${1:-48} steps=${2:-20} dim=${3:-3}
[ -x "$hearth" ] || { echo "fields_overhead: build first (scripts/hearth builds $hearth)" >&2; exit 2; }
declare -A best
for round in 1 2 3; do
    for f in none heat all; do
        secs=$("$hearth" bench --threads 1 --cells "$cells" --steps "$steps" --dim "$dim" --fields "$f" |
            python3 -c 'import json,sys; print(json.load(sys.stdin)["seconds"])')
        if [ -z "${best[$f]:-}" ] || python3 -c "import sys; sys.exit(0 if $secs < ${best[$f]} else 1)"; then best[$f]=$secs; fi
        echo "round $round: fields=$f $secs s" >&2
    done
done
for f in none heat all; do
    python3 -c "print('fields=%-5s best %.3f s  ratio %.2f' % ('$f', ${best[$f]}, ${best[$f]} / ${best[none]}))"
done

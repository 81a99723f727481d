#!/usr/bin/env bash
# fields_overhead.sh [CELLS] [STEPS] [DIM] [ROUNDS]: what the mixture fields
# cost in wall time. Runs `hearth bench` on the same elastic block with no
# fields, with heat (an oven), and with heat, CO2 and water, back to back in
# each round so machine noise hits the three alike. Prints each one's best
# time, the ratio of best times, and the median over rounds of the ratio
# within a round. Ding et al.'s mixture, issue #4's target: all fields at
# most 2x. On a shared machine also run fields_instructions.sh, which counts
# instructions and does not swing with load.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
hearth=${HEARTH:-$root/build/release/app/hearth}
cells=${1:-48} steps=${2:-20} dim=${3:-3} rounds=${4:-5}
[ -x "$hearth" ] || { echo "fields_overhead: build first (scripts/hearth builds $hearth)" >&2; exit 2; }
log=$(mktemp)
trap 'rm -f "$log"' EXIT
for round in $(seq "$rounds"); do
    for f in none heat all; do
        secs=$("$hearth" bench --threads 1 --cells "$cells" --steps "$steps" --dim "$dim" --fields "$f" |
            python3 -c 'import json,sys; print(json.load(sys.stdin)["seconds"])')
        echo "$round $f $secs" >>"$log"
        echo "round $round: fields=$f $secs s" >&2
    done
done
python3 - "$log" <<'PY'
import sys, statistics
runs = {}
for line in open(sys.argv[1]):
    r, f, t = line.split()
    runs.setdefault(f, {})[int(r)] = float(t)
best = {f: min(v.values()) for f, v in runs.items()}
for f in ("none", "heat", "all"):
    med = statistics.median(runs[f][r] / runs["none"][r] for r in runs[f])
    print("fields=%-5s best %.3f s  ratio of bests %.2f  median ratio within a round %.2f" % (f, best[f], best[f] / best["none"], med))
PY

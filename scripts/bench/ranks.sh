#!/usr/bin/env bash
# ranks.sh [BUILD]: strong and weak scaling of one MPM scene over MPI ranks
# (docs/scaling.md), from `hearth bench --ranks` (one JSON row per rank
# count; see `hearth bench --help`). Strong: the bench's elastic block at a
# fixed size on 1, 2 and 4 ranks of one thread, and on 1 rank of 2 threads.
# Weak (--weak): box and block N times as long along x, so every rank keeps
# the one-rank particle count. Each configuration runs 3 times and the table
# has the run with the shortest step time; the communication share (time
# inside MPI exchanges / step time) and the bytes received a step are each
# the largest over the ranks. Wall time, so the load average is printed next
# to the numbers. CELLS (default 32), STEPS (20), DIM (3) choose the problem.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
hearth=$build/app/hearth
cells=${CELLS:-32}
steps=${STEPS:-20}
dim=${DIM:-3}
export HEARTH_PLUGIN_PATH=$build/plugins OMP_WAIT_POLICY=passive
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi

# one KIND RANKS THREADS: the row (JSON) of the fastest of 3 runs
one() {
    local kind=$1 n=$2 th=$3 best="" row flag=""
    [ "$kind" = weak ] && flag=--weak
    for k in 1 2 3; do
        if [ "$n" = 1 ]; then
            row=$("$hearth" bench --ranks $flag --threads "$th" --dim "$dim" --cells "$cells" --steps "$steps" 2>/dev/null)
        else
            row=$(mpirun --oversubscribe -n "$n" "$hearth" bench --ranks $flag --threads "$th" --dim "$dim" --cells "$cells" --steps "$steps")
        fi
        [ -n "$row" ] || { echo "ranks.sh: $kind $n x $th failed" >&2; exit 1; }
        if [ -z "$best" ] || python3 -c 'import json,sys; sys.exit(0 if json.loads(sys.argv[1])["seconds"] < json.loads(sys.argv[2])["seconds"] else 1)' "$row" "$best"; then
            best=$row
        fi
    done
    echo "$best"
}

echo "# ranks.sh: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg), dim $dim, cells $cells, $steps steps"
echo "| kind | ranks x threads | particles | per rank | ms a step | comm share (max) | comm s | bytes received a step (max) | slab steps |"
echo "|---|---|---|---|---|---|---|---|---|"
# row JSON: the table's line
row() {
    python3 - "$1" <<'PY'
import json, sys
r = json.loads(sys.argv[1])
print("| %s | %d x %d | %d | %.0f | %.1f | %.0f%% | %.3f | %.0f | %d |" % (
    r["scaling"], r["ranks"], r["threads"], r["particles"], r["particles_per_rank"], r["ms_per_step"],
    100 * r["comm_share"], r["comm_seconds"], r["bytes_received_per_step"], r["slab_steps"]))
PY
}

for cfg in "strong 1 1" "strong 1 2" "strong 2 1" "strong 4 1" "weak 1 1" "weak 2 1" "weak 4 1"; do
    set -- $cfg
    row "$(one "$1" "$2" "$3")"
done

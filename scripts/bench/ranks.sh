#!/usr/bin/env bash
# ranks.sh [BUILD]: strong and weak scaling of one MPM scene over MPI ranks
# (docs/scaling.md). Strong: the 3D elastic block (ranks_block.lua) at a fixed
# size on 1, 2 and 4 ranks of one thread, and on 1 rank of 2 threads. Weak:
# the block widened with the rank count (particles per rank fixed). Each
# configuration runs 3 times; the table has the fastest wall time (rank 0's
# run.json: scene file to end, without mpirun's start-up), and rank
# 0's exchange traffic (MB received, and kB a step: all of it, and without
# whole-set gathers, i.e. the halo, the crossings and the step report) and
# seconds inside the exchanges (from `hearth run`'s rank report), with the
# mode the steps ran in (slabs or replicated). Wall time, so it says how busy
# the machine was (the load average) next to the numbers.
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
hearth=$build/app/hearth
scene=$root/scripts/bench/ranks_block.lua
cells=${CELLS:-40}
steps=${STEPS:-50}
export HEARTH_PLUGIN_PATH=$build/plugins HEARTH_RANKS_REPORT=1 OMP_WAIT_POLICY=passive
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# one RANKS THREADS WIDTH: "wall_s MB exchange_s particles kB_step halo_kB_step mode" of the fastest of 3 runs
one() {
    local n=$1 th=$2 w=$3 best="" line
    for k in 1 2 3; do
        if [ "$n" = 1 ]; then
            OMP_NUM_THREADS=$th "$hearth" run "$scene" --out "$tmp/o" --quiet --set cells=$cells --set width=$w --set steps=$steps >"$tmp/out" 2>"$tmp/err"
        else
            OMP_NUM_THREADS=$th mpirun --oversubscribe -n "$n" "$hearth" run "$scene" --out "$tmp/o" --quiet \
                --set cells=$cells --set width=$w --set steps=$steps >"$tmp/out" 2>"$tmp/err"
        fi
        local wall mb ex np
        wall=$(sed -n 's/.*"wall_s": \([0-9.e+-]*\),.*/\1/p' "$tmp/o/run.json") # rank 0's run, mpirun's start-up left out
        mb=$(sed -n 's/.*received \([0-9.e+-]*\) MB.*/\1/p' "$tmp/err")
        ex=$(sed -n 's/.* kB a step), \([0-9.e+-]*\) s inside.*/\1/p' "$tmp/err")
        kb=$(sed -n 's/.*MB in the exchanges (\([0-9.e+-]*\) kB a step).*/\1/p' "$tmp/err")
        halo=$(sed -n 's/.*the rest \([0-9.e+-]*\) kB a step.*/\1/p' "$tmp/err")
        mode=$(sed -n 's/.* \([0-9]*\) steps in slabs and \([0-9]*\) replicated.*/\1:\2/p' "$tmp/err")
        case "$mode" in "") mode=one ;; *:0) mode=slabs ;; 0:*) mode=replicated ;; *) mode=mixed ;; esac
        np=$(sed -n 's/^particles \([0-9]*\).*/\1/p' "$tmp/out")
        line="$wall ${mb:-0} ${ex:-0} $np ${kb:-0} ${halo:-0} $mode"
        if [ -z "$best" ] || [ "$(echo "$wall < ${best%% *}" | bc)" = 1 ]; then best=$line; fi
    done
    echo "$best"
}

echo "# ranks.sh: $(nproc) cores, load average $(cut -d' ' -f1-3 /proc/loadavg), cells $cells, $steps steps"
echo "# kind    ranks threads  particles  wall_s  per_step_ms  MB_rank0  kB_step  halo_kB_step  exchange_s  exchange_share  mode"
for cfg in "strong 1 1 1" "strong 1 2 1" "strong 2 1 1" "strong 4 1 1" "weak 1 1 1" "weak 2 1 2" "weak 4 1 4"; do
    set -- $cfg
    r=$(one "$2" "$3" "$4")
    set -- $cfg $r
    printf "%-8s %5s %7s %10s %7.2f %12.1f %9.2f %8.1f %13.1f %11.2f %15s  %s\n" "$1" "$2" "$3" "$8" "$5" \
        "$(echo "1000 * $5 / $steps" | bc -l)" "$6" "$9" "${10}" "$7" "$(echo "scale=2; 100 * $7 / $5" | bc)%" "${11}"
done

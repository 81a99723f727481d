#!/usr/bin/env bash
# ranks_instructions.sh: instructions per rank per step of the 3D elastic
# block (ranks_block.lua) on 1, 2 and 4 ranks of one thread, counted by
# callgrind inside mpm_step (docs/scaling.md). Wall time on a shared machine
# says more about the machine's load than about hearth; instructions do not.
# The exchanges are split out: inside MPI (the collectives, the neighbour
# messages and their Waitall: the copies, and the polling while a
# rank waits for the others, which depends on the load: reported, not
# compared) and the rest of the step (the work, load-independent).
# SCENE=dough counts tests/mpi/dough.lua in 3D instead (every field live:
# heat with the oven, water, evaporation, latent heat, CO2; HEAT=implicit for
# the CG solve), on slabs since issue #21's field halo (mpm_ranks_fields.c).
# Needs valgrind and a build without -march=native (build/nn, made here).
set -u
root=$(cd "$(dirname "$0")/../.." && pwd)
command -v valgrind >/dev/null || { echo "$(basename "$0"): needs valgrind" >&2; exit 2; }
# valgrind does not decode AVX-512: a build without -march=native (as callgrind.sh's), only what this needs
[ -f "$root/build/nn/build.ninja" ] || meson setup "$root/build/nn" "$root" --buildtype=release -Dnative=false >/dev/null
ninja -C "$root/build/nn" app/hearth plugins/hearth_elastic.so plugins/hearth_cam_clay_dough.so >/dev/null
nn_hearth=$root/build/nn/app/hearth
cells=${CELLS:-32}
steps=${STEPS:-10}
scene=$root/scripts/bench/ranks_block.lua
args="--set cells=$cells --set steps=$steps"
what="3D elastic block, cells $cells"
if [ "${SCENE:-block}" = dough ]; then
    scene=$root/tests/mpi/dough.lua
    args="--set dim=3 --set steps=$steps --set heat=${HEAT:-explicit}"
    what="3D dough with every field (tests/mpi/dough.lua, heat ${HEAT:-explicit})"
fi
export HEARTH_PLUGIN_PATH=$root/build/nn/plugins OMP_WAIT_POLICY=passive OMP_NUM_THREADS=1
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cg="valgrind --tool=callgrind --toggle-collect=mpm_step --callgrind-out-file=$tmp/cg.%q{CG_TAG}.%p"

echo "# ranks_instructions.sh: $what, $steps steps; millions of instructions per step"
echo "# ranks  rank  particles_total  in_mpm_step  in_MPI  work(step - MPI)"
for n in 1 2 4; do
    rm -f "$tmp"/cg.*
    if [ "$n" = 1 ]; then
        CG_TAG=r1 $cg "$nn_hearth" run "$scene" --out "$tmp/o" --quiet $args >"$tmp/out" 2>/dev/null
    else
        CG_TAG=r$n mpirun --oversubscribe -n "$n" $cg "$nn_hearth" run "$scene" --out "$tmp/o" --quiet $args >"$tmp/out" 2>/dev/null
    fi
    np=$(sed -n 's/^particles \([0-9]*\).*/\1/p; s/^steps [0-9]* particles \([0-9]*\).*/\1/p' "$tmp/out" | head -1)
    k=0
    for f in $(ls "$tmp"/cg.* | sort); do
        total=$(callgrind_annotate --inclusive=yes "$f" 2>/dev/null | awk '/PROGRAM TOTALS/ {gsub(",", "", $1); print $1}')
        mpi=$(callgrind_annotate --inclusive=yes "$f" 2>/dev/null | awk '/[ :](PMPI|MPI)_(Allgatherv|Allgather|Allreduce|Waitall|Isend|Irecv) / {gsub(",", "", $1); s += $1} END {print s + 0}')
        printf "%6s %5s %16s %12.2f %7.2f %16.2f\n" "$n" "$k" "$np" "$(echo "$total / $steps / 1000000" | bc -l)" \
            "$(echo "$mpi / $steps / 1000000" | bc -l)" "$(echo "($total - $mpi) / $steps / 1000000" | bc -l)"
        k=$((k + 1))
    done
done

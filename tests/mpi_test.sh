#!/usr/bin/env bash
# mpi_test.sh CASE HEARTH MPI: one MPM scene over MPI ranks (#21, docs/scaling.md).
# CASE ends in _2 or _4, the rank count. Every case skips (77) with a message
# when hearth was built without MPI (MPI = 0, from meson: -Dmpi=disabled or
# no libopenmpi-dev) or mpirun is missing. Each mpirun has its own timeout, so a
# rank that waits forever fails the test instead of hanging it.
here=$(cd "$(dirname "$0")" && pwd)
set -u
case_name=$1
hearth=$2
built=${3:-0}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

if [ "$built" != 1 ]; then
    echo "SKIP: hearth was built without MPI (meson -Dmpi=disabled, or libopenmpi-dev missing)"
    exit 77
fi
command -v mpirun >/dev/null 2>&1 || { echo "SKIP: no mpirun on PATH (Debian: openmpi-bin)"; exit 77; }
if [ "$(id -u)" = 0 ]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
export OMPI_MCA_rmaps_base_oversubscribe=1
ranks=${case_name##*_}
base=${case_name%_*}

# mp N OUT SCENE [args]: the scene over N ranks, at most 50 s
mp() {
    local n=$1 out=$2 scene=$3
    shift 3
    timeout 50 mpirun --oversubscribe -n "$n" "$hearth" run "$here/mpi/$scene" --out "$tmp/$out" --quiet "$@"
}

# against_one SCENE STEPS [--set ...]: the scene on one process and on $ranks
# ranks; both must take STEPS steps and their states agree to 1e-12 relative.
against_one() {
    local scene=$1 steps=$2
    shift 2
    "$hearth" run "$here/mpi/$scene" --out "$tmp/one" --quiet "$@" >"$tmp/one.txt" || fail "one-process run failed ($*)"
    mp "$ranks" many "$scene" "$@" >"$tmp/many.txt" || fail "$ranks-rank run failed (status $?; $*)"
    cat "$tmp/one.txt" "$tmp/many.txt"
    grep -q "^steps $steps " "$tmp/many.txt" || fail "the $ranks-rank run did not take $steps steps ($*)"
    python3 "$here/mpi_compare.py" "$tmp/one/state.csv" "$tmp/many/state.csv" 1e-12 ||
        fail "$ranks ranks differ from one process by more than 1e-12 ($scene $*)"
}

case "$base" in
mpi_elastic_matches_one_rank)
    # the standard elastic block, 100 steps: N ranks against one process
    against_one elastic_block.lua 100
    ;;
mpi_dough_matches_one_rank)
    # every field live (heat with the oven, water, evaporation, latent heat, CO2); heat explicit, then the CG solve
    for heat in explicit implicit; do
        against_one dough.lua 100 --set heat=$heat
    done
    ;;
mpi_collider_matches_one_rank)
    # a moving sticky plate (a Lua velocity function), a sticky floor and a grip
    against_one collider.lua 150
    ;;
mpi_elastic_3d_matches_one_rank)
    against_one elastic_block.lua 100 --set dim=3
    ;;
mpi_checkpoint_restores_on_other_ranks)
    # saved by N ranks (N = 2 in the case names); restored on 1 and on 4, as a
    # later `mpirun -n M` would: the same 50 steps as the saving run's own
    mp "$ranks" ck checkpoint.lua >"$tmp/save.txt" || fail "the $ranks-rank run that saves failed"
    cat "$tmp/save.txt"
    [ -s "$tmp/ck/ck.bin" ] || fail "no checkpoint in rank 0's output folder"
    ls "$tmp/ck" | grep -q "tmp" && fail "a temporary file was left in the output folder"
    for m in 1 4; do
        rm -f "$tmp/ck/state_loaded.csv"
        if [ $m = 1 ]; then "$hearth" run "$here/mpi/checkpoint.lua" --out "$tmp/ck" --quiet --set mode=load >"$tmp/load.txt"
        else mp $m ck checkpoint.lua --set mode=load >"$tmp/load.txt"; fi || fail "restoring on $m rank(s) failed"
        cat "$tmp/load.txt"
        grep -q "^load steps 100 " "$tmp/load.txt" || fail "the restored run on $m rank(s) is not at step 100"
        python3 "$here/mpi_compare.py" "$tmp/ck/state.csv" "$tmp/ck/state_loaded.csv" 1e-12 ||
            fail "restored on $m rank(s), the run differs from the $ranks-rank run that saved"
    done
    ;;
mpi_elastic_bit_identical)
    # two N-rank runs, the second with two threads per rank: the same bits
    mp "$ranks" a elastic_block.lua >"$tmp/a.txt" || fail "first run failed"
    OMP_NUM_THREADS=2 mp "$ranks" b elastic_block.lua >"$tmp/b.txt" || fail "second run failed"
    cat "$tmp/a.txt"
    cmp "$tmp/a.txt" "$tmp/b.txt" || fail "the hash and kinetic energy differ between two $ranks-rank runs"
    cmp "$tmp/a/state.csv" "$tmp/b/state.csv" || fail "the particle states differ between two $ranks-rank runs"
    ;;
mpi_discs_conserve_momentum)
    # two discs meet off-centre and spin away, crossing the ranks' runs of particles
    "$hearth" run "$here/mpi/discs.lua" --out "$tmp/one" --quiet >"$tmp/one.txt" || fail "one-process run failed"
    mp "$ranks" many discs.lua >"$tmp/many.txt" || fail "$ranks-rank run failed (status $?)"
    cat "$tmp/many.txt"
    python3 - "$tmp/many.txt" "$tmp/one.txt" <<'PY' || fail "momentum or particle count not conserved over $ranks ranks"
import sys
def read(path):
    d = {}
    for line in open(path):
        w = line.split()
        if w and w[0] in ("particles", "start", "end"):
            d[w[0]] = w[1:]
    return d
many, one = read(sys.argv[1]), read(sys.argv[2])
n, n1 = int(many["particles"][0]), int(one["particles"][0])
p0 = [float(many["start"][1]), float(many["start"][2])]
p1 = [float(many["end"][1]), float(many["end"][2])]
vsum = float(many["start"][6])
drift = max(abs(a - b) for a, b in zip(p0, p1)) / vsum
print(f"particles {n} (one process {n1}); momentum drift {drift:.3e} of sum |v| (limit 1e-12)")
sys.exit(0 if n == n1 and drift <= 1e-12 else 1)
PY
    python3 "$here/mpi_compare.py" "$tmp/one/state.csv" "$tmp/many/state.csv" 1e-12 || fail "$ranks ranks differ from one process"
    ;;
mpi_guard_stops_all_ranks)
    # only the last rank's particles turn NaN; every rank must stop, rank 0 with the diagnosis
    HEARTH_PLUGIN_PATH="${HEARTH_TEST_PLUGIN_DIR:-}:${HEARTH_PLUGIN_PATH:-}" mp "$ranks" g guard_one_rank.lua >"$tmp/out.txt" 2>"$tmp/err.txt"
    st=$?
    cat "$tmp/err.txt"
    [ $st -ne 124 ] || fail "the ranks hung after a guard stop (killed by the 50 s timeout)"
    [ $st -ne 0 ] || fail "the run ended with status 0 after a guard stop"
    grep -q "not stopped" "$tmp/out.txt" && fail "the scene ran past the guard stop"
    grep -q "stability guard stopped the run" "$tmp/err.txt" || fail "no guard diagnosis from rank 0"
    grep -q "nan_after" "$tmp/err.txt" || fail "the diagnosis does not name the material that failed"
    grep -q "Segmentation fault" "$tmp/err.txt" && fail "a process crashed on the way out"
    ;;
mpi_sph_refused)
    mp "$ranks" s sph.lua >"$tmp/out.txt" 2>"$tmp/err.txt" && fail "an SPH scene ran over $ranks ranks"
    cat "$tmp/err.txt"
    grep -q 'solver = "sph" runs in one process, and this run has '"$ranks"' MPI ranks' "$tmp/err.txt" || fail "no clear message"
    grep -q "created" "$tmp/out.txt" && fail "the SPH scene was created"
    grep -q "Segmentation fault" "$tmp/err.txt" && fail "a process crashed on the way out"
    ;;
*)
    fail "unknown case $case_name"
    ;;
esac
exit 0

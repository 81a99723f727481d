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

# state_count AWK_CONDITION: how many particles of the one-process state.csv
# meet it ($8 the temperature, $9 the saturation)
state_count() {
    awk -F, "$1 {n++} END {print n + 0}" "$tmp/one/state.csv"
}

# on_slabs STEPS: the N-rank run's record says every step ran on slabs
on_slabs() {
    grep -q "MPI ranks: $ranks; $1 steps with each rank holding its slab, 0 replicated" "$tmp/many/run.log" ||
        fail "the run record does not say the steps ran on slabs (run.log: $(grep 'MPI ranks' "$tmp/many/run.log"))"
}

# same_sums: stats()'s particle sums (heat, water, water lost, CO2, the oven's
# ledger) and the CG's iterations agree with one process's (1e-12 relative)
same_sums() {
    python3 - "$tmp/one.txt" "$tmp/many.txt" <<'PY' || fail "stats() over $ranks ranks differs from one process"
import sys
def read(path):
    for line in open(path):
        w = line.split()
        if w and w[0] == "sums":
            return dict(zip(w[1::2], w[2::2]))
    sys.exit(f"no sums line in {path}")
one, many = read(sys.argv[1]), read(sys.argv[2])
ok = one["cg"] == many["cg"]
for k in ("heat", "water", "lost", "gas", "oven"):
    a, b = float(one[k]), float(many[k])
    d = abs(a - b) / max(abs(a), 1e-300)
    print(f"stats {k}: one process {a!r}, ranks {b!r}, relative difference {d:.3e}")
    ok = ok and d <= 1e-12
print(f"CG iterations of the last step: one process {one['cg']}, ranks {many['cg']}")
sys.exit(0 if ok else 1)
PY
}

case "$base" in
mpi_elastic_matches_one_rank)
    # the standard elastic block, 100 steps: N ranks against one process
    against_one elastic_block.lua 100
    ;;
mpi_dough_matches_one_rank)
    # every field live (heat with the oven, water, evaporation, latent heat, CO2); heat explicit, then the CG solve;
    # then the pores' gas at the atmosphere (ambient_pressure, gas.h) as h.library.dough.bread has it
    for heat in explicit implicit; do
        against_one dough.lua 100 --set heat=$heat
    done
    against_one dough.lua 100 --set ambient=101325
    ;;
mpi_collider_matches_one_rank)
    # a moving sticky plate (a Lua velocity function), a sticky floor and a grip
    against_one collider.lua 150
    ;;
mpi_elastic_3d_matches_one_rank)
    against_one elastic_block.lua 100 --set dim=3
    ;;
mpi_dough_3d_matches_one_rank)
    # the 3D dough with every field live (explicit heat, the oven's surface,
    # water, evaporation, latent heat, CO2, a heated tray) on slabs: every step
    # with each rank holding its slab, the run record must say so. 2 ranks take
    # half the scene each, so 50 steps there keep the test within its time.
    n=100
    [ "$ranks" = 2 ] && n=50
    against_one dough.lua $n --set dim=3 --set steps=$n
    on_slabs $n
    same_sums
    ;;
mpi_dough_3d_cycle_matches_one_rank)
    # the fields' clock on slabs (core/sim/fields/field_clock.c): at the default
    # (automatic) the 3D dough above takes no field update in its steps, so here
    # its cycle is pinned: every step (field_steps=1: the halo layers every step)
    # and every 7th (field and plain steps interleaved: the halos move on the
    # field steps only); each must match one process and have taken the oven's
    # heat (a field update ran)
    n=70
    [ "$ranks" = 2 ] && n=35
    for k in 1 7; do
        against_one dough.lua $n --set dim=3 --set steps=$n --set field_steps=$k
        on_slabs $n
        same_sums
        awk '$1 == "sums" && $11 + 0 > 0 {ok = 1} END {exit !ok}' "$tmp/many.txt" ||
            fail "field_steps=$k: no oven heat over $ranks ranks, so no field update ran: $(grep '^sums' "$tmp/many.txt")"
    done
    ;;
mpi_implicit_heat_matches_one_rank)
    # the same dough with backward Euler heat: the CG's dot products over the
    # ranks (rank order), its matrix products through the halo layers
    n=100
    [ "$ranks" = 2 ] && n=50
    against_one dough.lua $n --set dim=3 --set heat=implicit --set steps=$n
    on_slabs $n
    same_sums
    ;;
mpi_dough_3d_bit_identical|mpi_implicit_heat_bit_identical)
    # two N-rank runs on slabs, the second with two threads per rank: the same bits
    heat=explicit
    [ "$base" = mpi_implicit_heat_bit_identical ] && heat=implicit
    mp "$ranks" a dough.lua --set dim=3 --set heat=$heat >"$tmp/a.txt" || fail "first run failed"
    OMP_NUM_THREADS=2 mp "$ranks" b dough.lua --set dim=3 --set heat=$heat >"$tmp/b.txt" || fail "second run failed"
    cat "$tmp/a.txt"
    grep -q "MPI ranks: $ranks; 100 steps with each rank holding its slab, 0 replicated" "$tmp/a/run.log" ||
        fail "the run did not step on slabs (run.log: $(grep 'MPI ranks' "$tmp/a/run.log"))"
    cmp "$tmp/a.txt" "$tmp/b.txt" || fail "the stats and hash differ between two $ranks-rank runs"
    cmp "$tmp/a/state.csv" "$tmp/b/state.csv" || fail "the particle states differ between two $ranks-rank runs"
    ;;
mpi_heat_matches_one_rank)
    # an elastic bar thrown through the slab seams onto a floor, warming in the
    # oven (the air surface meets the floor's contact at the seams)
    for heat in explicit implicit; do
        against_one heat_traffic.lua 100 --set heat=$heat --set state=1
        on_slabs 100
    done
    ;;
mpi_oven_walls_matches_one_rank)
    # heat_traffic.lua's bar in an oven whose walls radiate (250 degC, eps 0.9; fields/thermal.h): find_boundary's
    # face closure reads the nodes' temperature at each air-surface particle, on slabs the halo's (#18, helper ovenwall);
    # field_steps=1: at the automatic field clock the explicit run's 100 steps take no heat update (the same bits with
    # and without walls, seen at the first run)
    for heat in explicit implicit; do
        against_one heat_traffic.lua 100 --set heat=$heat --set state=1 --set field_steps=1 --set oven.wall_temperature=250 \
            --set oven.emissivity=0.9
        on_slabs 100
    done
    ;;
mpi_dough_boils_matches_one_rank)
    # the dough on a hot tray (250 degC through beta 1e5): its bottom rows reach 100 degC from step ~60 (2D: 2
    # particles at step 60, 39 at 100, 54 at 200; ~120 when the dough started 2 mm over the tray) and boil
    # through the boiling front (core/sim/fields/boil_front.c) from then on; 200 steps, none dried yet. The
    # front's gradient at a slab's first node row once read the cleared lower halo layer: 1.0e-3 in saturation.
    # The same 1e-12 as every case here; the run must have boiled (at least 10 particles held at 100 degC in the
    # one-process state), or it checks nothing of the front. Then the 3D dough the same way (2310 particles, its
    # slabs' halo layers planes of blocks; 5.5e-4 at 2 ranks and 1.4e-3 at 4 before the fix).
    for dim in 2 3; do
        against_one dough.lua 200 --set dim=$dim --set tray=250 --set tray_beta=1e5 --set steps=200
        on_slabs 200
        same_sums
        boiling=$(state_count '$8 == 100')
        echo "${dim}D: particles held at 100 degC (boiling) in the one-process state: $boiling"
        [ "$boiling" -ge 10 ] || fail "${dim}D: only $boiling particles at 100 degC: the scene no longer boils, so the case checks nothing"
    done
    ;;
mpi_dough_dries_matches_one_rank)
    # hotter still (450 degC through beta 1e5), 700 steps: the bottom row boils dry (39 particles under saturation
    # 1e-3, 27 before the dough was seeded on the tray) while the rows above boil (81 at 100 degC, 56 before). The run must have dried at least 10 particles and held at
    # least 10 at 100 degC, or it checks nothing of the dried row, and the same 1e-12 as every case here. A dried
    # particle's water sits on the saturation floor, and G2P's test of water to boil (spare > 0) compares it with a
    # floor taken by another rounding from a volume that differs by ulps between one process and the slabs, so its
    # spare is 0 or one ulp. The boiling front's shares scale with the room (core/sim/fields/boil_front.c) and G2P's
    # gas reads the temperature a sender keeps, so either gives the same answer to rounding; before, +1 ulp made the
    # particle a full receiver and its whole excess weighed in the front's rest (1.8e-3 in temperature at 2 ranks,
    # 3.5e-4 in saturation at 4), and with the front alone scaled its gas was made at T_b (7.4e-9, 1.0e-8 in a
    # velocity; docs/validation.md, "The front's shares scale with room").
    against_one dough.lua 700 --set tray=450 --set tray_beta=1e5 --set steps=700
    on_slabs 700
    same_sums
    dried=$(state_count '$9 < 1e-3')
    boiling=$(state_count '$8 == 100')
    echo "in the one-process state: $dried particles dried (saturation under 1e-3), $boiling held at 100 degC"
    [ "$dried" -ge 10 ] || fail "only $dried particles dried: the case no longer checks the dried row"
    [ "$boiling" -ge 10 ] || fail "only $boiling particles at 100 degC: the case no longer checks the boiling"
    ;;
mpi_heated_plate_across_slabs_matches_one_rank)
    # a hot plate across the slab axis, a jelly block seeded three cells into
    # it just above the ranks' cut: contact points whose stencils reach two
    # block layers past the slab below (mpm_ranks_fields_contacts); explicit
    # heat, then the CG solve. Before the contacts moved ranks: 5.7e-7.
    for heat in explicit implicit; do
        against_one hot_plate.lua 60 --set heat=$heat
        on_slabs 60
    done
    ;;
mpi_drawing_plate_across_slabs_matches_one_rank)
    # hot_plate.lua's plate as a sheet the blocks draw their heat from: each rank's contact points' heat is summed
    # over the ranks, so the plate's temperature, its books and every particle agree with one process to the
    # suite's 1e-12 (the books' sums run in rank order: their last digit may differ; a first bar of the same text
    # failed on drawn's 17th digit, 1.3e-16 relative)
    for heat in explicit implicit; do
        against_one hot_plate.lua 60 --set heat=$heat --set draw=1
        on_slabs 60
        one=$(grep '^plate ' "$tmp/one.txt") many=$(grep '^plate ' "$tmp/many.txt")
        [ -n "$one" ] && [ -n "$many" ] || fail "no plate line: one process '$one', $ranks ranks '$many'"
        python3 - "$one" "$many" <<'PY' || fail "the plate's sheet differs: one process '$one', $ranks ranks '$many'"
import sys
a, b = sys.argv[1].split(), sys.argv[2].split()
nums = lambda w: [float(w[i]) for i in (1, 4, 6)]  # temperature, drawn, oven_in
x, y = nums(a), nums(b)
assert x[1] > 0, "the plate drew nothing"
worst = max(abs(p - q) / max(abs(p), 1e-300) for p, q in zip(x, y))
print(f"the plate's temperature, drawn and oven_in: largest relative difference {worst:.3g}; tolerance 1e-12")
sys.exit(0 if worst <= 1e-12 else 1)
PY
    done
    ;;
mpi_wall_column_matches_one_rank)
    # a column against the box's far wall in an oven, the cut two layers
    # below the end layer: the surface search's domain-wall test reads the end
    # node (mpm_ranks_fields_wall); explicit heat, then the CG solve.
    # Before the end planes were shared: 5.7e-7. At 4 ranks the two right
    # ranks hold no particle (the column lies in layers 30-31): before zero
    # bytes stopped being "out of memory" (alloc.c) rank 3 crashed, and with
    # only the volumes' scratch fixed ranks 2 and 3 failed their heat scratch
    # alone and the others waited for them (issue #21).
    for heat in explicit implicit; do
        against_one wall_column.lua 60 --set heat=$heat
        on_slabs 60
    done
    ;;
mpi_empty_rank_elastic_matches_one_rank|mpi_empty_rank_heat_matches_one_rank|mpi_rank_empties_mid_run_matches_one_rank)
    # empty_rank.lua: a short block at the left end of a long box, so at 4
    # ranks the right end's rank holds no particle for the whole run (elastic;
    # heat, explicit and the CG), or, thrown along the box, ranks empty and
    # fill between the rebalances. Two N-rank runs byte-identical, and each
    # within 1e-12 of one process; every rank says how many particles it held.
    case "$base" in
    mpi_empty_rank_elastic*) runs=("100 --set heat=none") ;;
    mpi_empty_rank_heat*) runs=("100 --set heat=explicit" "100 --set heat=implicit") ;;
    *) runs=("200 --set heat=explicit --set vx=4 --set steps=200") ;;
    esac
    for run in "${runs[@]}"; do
        read -r steps args <<<"$run"
        # shellcheck disable=SC2086
        against_one empty_rank.lua "$steps" $args
        on_slabs "$steps"
        # shellcheck disable=SC2086
        HEARTH_RANKS_VERBOSE=1 HEARTH_RANKS_REPORT=1 mp "$ranks" again empty_rank.lua $args >"$tmp/again.txt" 2>"$tmp/held.txt" ||
            fail "second $ranks-rank run failed (status $?; $args)"
        cmp "$tmp/many/state.csv" "$tmp/again/state.csv" || fail "two $ranks-rank runs differ ($args)"
        [ "$(grep '^steps' "$tmp/many.txt")" = "$(grep '^steps' "$tmp/again.txt" | head -1)" ] || fail "two $ranks-rank runs print different sums or hashes ($args)"
        sed -n 's/.*rank \([0-9]*\) received.* it held \([0-9]*\) to \([0-9]*\) particles.*/rank \1 held \2 to \3 particles after a slab step/p' "$tmp/held.txt" | sort
        case "$base" in
        mpi_rank_empties*)
            # a rank that held particles and later none, or none and later some
            grep -Eq 'held 0 to [1-9]' "$tmp/held.txt" || fail "no rank emptied or filled mid-run: the test lost its point"
            ;;
        *)
            grep -q 'held 0 to 0 particles' "$tmp/held.txt" || fail "no rank was empty for the whole run: the test lost its point"
            ;;
        esac
    done
    ;;
mpi_rebalance_matches_one_rank)
    # a block thrown across a resting bar: the cuts move at every rebalance, at
    # 4 ranks by more than a slab (extra migration passes); 250 steps in slabs
    "$hearth" run "$here/mpi/drift.lua" --out "$tmp/one" --quiet >"$tmp/one.txt" || fail "one-process run failed"
    HEARTH_RANKS_REPORT=1 mp "$ranks" many drift.lua >"$tmp/many.txt" 2>"$tmp/err.txt" || fail "$ranks-rank run failed (status $?)"
    cat "$tmp/one.txt" "$tmp/many.txt" "$tmp/err.txt"
    grep -q "250 steps in slabs and 0 replicated" "$tmp/err.txt" || fail "not every step ran in slabs"
    passes=$(sed -n 's/.* \([0-9]*\) extra migration passes.*/\1/p' "$tmp/err.txt")
    [ "$ranks" = 2 ] || [ "${passes:-0}" -ge 1 ] || fail "no cut moved by more than a slab ($passes extra passes): the test lost its point"
    python3 "$here/mpi_compare.py" "$tmp/one/state.csv" "$tmp/many/state.csv" 1e-12 ||
        fail "$ranks ranks differ from one process by more than 1e-12 after rebalancing"
    ;;
mpi_halo_traffic_bounded|mpi_heat_halo_traffic_bounded)
    # bytes each rank receives per step, from each rank's own count: bounded by
    # the halo model (docs/scaling.md), not by the particle count. The bar is
    # run at two lengths, the second with twice the particles; the heat case's
    # bar warms in an oven (explicit heat with the air surface).
    scene=traffic.lua
    [ "$base" = mpi_heat_halo_traffic_bounded ] && scene=heat_traffic.lua
    for len in 0.6 1.2; do
        HEARTH_RANKS_REPORT=1 HEARTH_RANKS_VERBOSE=1 mp "$ranks" t$len $scene --set len=$len >"$tmp/t$len.txt" 2>&1 ||
            fail "$ranks-rank run at len $len failed (status $?)"
        grep "MPI ranks" "$tmp/t$len.txt"
    done
    python3 - "$tmp/t0.6.txt" "$tmp/t1.2.txt" "$ranks" "$scene" <<'PY' || fail "the traffic per rank is not bounded by the halo model"
import re, sys, math
def read(path):
    ranks, n = {}, 0
    for line in open(path):
        m = re.search(r"(\d+) steps in slabs and (\d+) replicated.*rank (\d+) received .*whole-set gathers ([0-9.e+-]+) MB, the rest ([0-9.e+-]+) kB a step", line)
        if m:
            ranks[int(m.group(3))] = (int(m.group(1)), int(m.group(2)), float(m.group(4)), float(m.group(5)) * 1e3)
        m = re.match(r"steps \d+ particles (\d+)", line)
        if m:
            n = int(m.group(1))
    return ranks, n
N = int(sys.argv[3])
short, n1 = read(sys.argv[1])
long_, n2 = read(sys.argv[2])
ok = len(short) == N and len(long_) == N and n2 > 1.9 * n1
# The model, from the scene's geometry (not from hearth): the slab axis is x
# (the box is 2 m by 0.5 m); a block layer's cross-section is at most
# ceil((0.5 / dx + 4) / 4) = 9 blocks of 16 nodes with 4 channels (8 bytes).
# Per step a rank receives the lower neighbour's marks (1 byte a block) and
# sums, the upper's values, the particles crossing its two faces (those
# within a cell of a face: 2 faces x 14 cells x 2 particles a cell
# (ppc 4 in 2D), 300 bytes each at most), N step reports (200 bytes) and a
# few counts (256 bytes).
dx, S = 1 / 64, math.ceil((0.5 * 64 + 4) / 4)
bound = S + 2 * S * 16 * 4 * 8 + 2 * 14 * 2 * 300 + N * 200 + 256
if sys.argv[4] == "heat_traffic.lua":
    # With heat every node carries 14 channels. Per step a rank receives the
    # ghost layer's sums and values (2 x S blocks x 14 channels), the fill of
    # both halo layers after P2G (2 x S x 14), the transport's two channels
    # summed and filled on both sides (4 x S x 2), the marks of both halo
    # layers and their surface flags (5 S bytes), the crossing particles (their
    # temperature, flags and heat columns: 400 bytes at most), N step reports
    # and the counts. No CG (explicit heat) and no reductions but stats' last.
    bound = 5 * S + S * 16 * 8 * (2 * 14 + 2 * 14 + 4 * 2) + 2 * 14 * 2 * 400 + N * 200 + 256
print(f"halo model bound {bound / 1e3:.1f} kB a step a rank; replicated particles alone would be {(1 - 1 / N) * n2 * 216 / 1e3:.0f} kB at {n2} particles")
for r in range(N):
    if r not in short or r not in long_:
        print(f"rank {r}: no report line"); ok = False; continue
    (s1, p1, g1, b1), (s2, p2, g2, b2) = short[r], long_[r]
    print(f"rank {r}: {b1 / 1e3:.2f} kB a step at {n1} particles, {b2 / 1e3:.2f} kB at {n2}; steps in slabs {s1}, {s2}; gathers {g1}, {g2} MB")
    if s1 != 100 or s2 != 100 or p1 or p2:
        print(f"rank {r}: not every step ran in slabs"); ok = False
    if g1 > 0 or g2 > 0:
        print(f"rank {r}: a whole-set gather during the steps"); ok = False
    if b1 > bound or b2 > bound:
        print(f"rank {r}: over the bound"); ok = False
    if b2 > 1.25 * b1 + 500:
        print(f"rank {r}: grows with the particle count ({b1:.0f} -> {b2:.0f} bytes a step)"); ok = False
sys.exit(0 if ok else 1)
PY
    ;;
mpi_vtu_pieces_read_as_one)
    # s:run's VTU frames over N ranks: a piece per rank and a .pvtu index, no
    # whole-set gather; VTK reads them as the one-process run's frames
    "$hearth" run "$here/mpi/pieces.lua" --out "$tmp/one" --quiet >"$tmp/one.txt" || fail "one-process run failed"
    HEARTH_RANKS_REPORT=1 mp "$ranks" frames pieces.lua >"$tmp/frames.txt" 2>"$tmp/err.txt" || fail "$ranks-rank run failed (status $?)"
    cat "$tmp/err.txt"
    grep -q "whole-set gathers 0 MB" "$tmp/err.txt" || fail "the VTU frames gathered the whole scene"
    mp "$ranks" many pieces.lua --set whole=1 >"$tmp/many.txt" || fail "$ranks-rank run with the gathered file failed (status $?)"
    py=python3
    for p in python3 /usr/bin/python3; do command -v $p >/dev/null 2>&1 && $p -c "import vtk" 2>/dev/null && { py=$p; break; }; done
    $py "$here/vtk_pieces.py" "$tmp/one" "$tmp/many" "$ranks"
    st=$?
    [ $st = 77 ] && exit 77
    [ $st = 0 ] || fail "the pieces do not read as the one-process frames"
    ;;
mpi_bench_ranks_prints_keys)
    # hearth bench --ranks: one JSON row for the rank count, strong and weak,
    # with its keys; plain (no mpirun) the one-rank row and a note saying so.
    # Nothing about speed is asserted (docs/scaling.md has the measured tables).
    "$hearth" bench --ranks --dim 2 --cells 32 --steps 4 >"$tmp/one.json" 2>"$tmp/one.err" || fail "bench --ranks without mpirun failed"
    grep -q "not started by mpirun" "$tmp/one.err" || fail "no note that the run without mpirun is the one-rank row: $(cat "$tmp/one.err")"
    "$hearth" bench --weak --dim 2 2>"$tmp/weak.err" && fail "--weak without --ranks was accepted"
    grep -q "goes with --ranks" "$tmp/weak.err" || fail "no clear message for --weak alone"
    for kind in strong weak; do
        flag=""
        [ $kind = weak ] && flag=--weak
        timeout 50 mpirun --oversubscribe -n "$ranks" "$hearth" bench --ranks $flag --dim 2 --cells 32 --steps 4 --threads 1 \
            >"$tmp/$kind.json" || fail "mpirun -n $ranks hearth bench --ranks $flag failed"
    done
    cat "$tmp/one.json" "$tmp/strong.json" "$tmp/weak.json"
    python3 - "$tmp/one.json" "$tmp/strong.json" "$tmp/weak.json" "$ranks" <<'PY' || fail "bench --ranks rows"
import json, sys
keys = ["ranks", "threads", "scaling", "dim", "cells", "particles", "particles_per_rank", "steps", "seconds",
        "ms_per_step", "particle_steps_per_s", "comm_share", "comm_seconds", "bytes_received_per_step",
        "slab_steps", "replicated_steps"]
rows = []
for path in sys.argv[1:4]:
    lines = [l for l in open(path) if l.strip()]
    if len(lines) != 1:
        sys.exit(f"{path}: {len(lines)} lines, want one row (rank 0's)")
    r = json.loads(lines[0])
    missing = [k for k in keys if k not in r]
    if missing:
        sys.exit(f"{path}: missing keys {missing}")
    rows.append(r)
one, strong, weak = rows
N = int(sys.argv[4])
ok = True
def check(cond, what):
    global ok
    if not cond:
        print("FAIL:", what); ok = False
check(one["ranks"] == 1 and one["comm_share"] == 0 and one["bytes_received_per_step"] == 0, "the one-rank row has no communication")
check(strong["ranks"] == N and weak["ranks"] == N, "ranks")
check(strong["scaling"] == "strong" and weak["scaling"] == "weak", "scaling")
check(strong["particles"] == one["particles"], "strong scaling keeps the one-rank problem")
check(abs(weak["particles_per_rank"] - one["particles"]) <= 0.05 * one["particles"], "weak scaling keeps the particles per rank")
for r in (strong, weak):
    check(r["slab_steps"] == 4 and r["replicated_steps"] == 0, "every timed step in slabs")
    check(0 < r["comm_share"] <= 1 and r["comm_seconds"] > 0, "a communication share in (0, 1]")
    check(r["bytes_received_per_step"] > 0, "bytes received")
sys.exit(0 if ok else 1)
PY
    ;;
mpi_checkpoint_restores_on_other_ranks)
    # saved by N ranks (2 or 4, in slabs); restored on 1 and on 4 (saved by 2)
    # or 2 (saved by 4), as a later `mpirun -n M` would: the same 50 steps as
    # the saving run's own
    mp "$ranks" ck checkpoint.lua >"$tmp/save.txt" || fail "the $ranks-rank run that saves failed"
    cat "$tmp/save.txt"
    [ -s "$tmp/ck/ck.bin" ] || fail "no checkpoint in rank 0's output folder"
    ls "$tmp/ck" | grep -q "tmp" && fail "a temporary file was left in the output folder"
    grep -q "MPI ranks: $ranks; 100 steps with each rank holding its slab, 0 replicated" "$tmp/ck/run.log" ||
        fail "the saving run did not step in slabs (run.log: $(grep 'MPI ranks' "$tmp/ck/run.log"))"
    others="1 4"
    [ "$ranks" = 4 ] && others="1 2"
    for m in $others; do
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
mpi_lone_failure_ends_every_rank)
    # here $hearth is tests/mpi_alone.c's program: the right end's rank fails a
    # step alone (an injected allocation failure when the thrown block first
    # reaches it); the run must end (non-zero, within the timeout), not hang in
    # the gather after the step call or in stats()' sums (#21)
    for mode in gather stats; do
        timeout 50 mpirun --oversubscribe -n "$ranks" "$hearth" "$mode" >"$tmp/$mode.txt" 2>&1
        st=$?
        cat "$tmp/$mode.txt"
        [ $st -ne 124 ] || fail "$mode: the ranks hung after one rank's failed step (killed by the 50 s timeout)"
        [ $st -ne 0 ] || fail "$mode: the run ended with status 0 after a failed step"
        grep -q "rank $((ranks - 1)) of $ranks ($mode): step call status [1-9].*out of memory" "$tmp/$mode.txt" ||
            fail "$mode: the last rank did not fail its step with 'out of memory' (the test lost its point)"
        grep -q "rank $((ranks - 1)): a further step: status [1-9].*takes part in no exchange" "$tmp/$mode.txt" ||
            fail "$mode: a further step on the failed rank was not refused"
        grep -q "Segmentation fault" "$tmp/$mode.txt" && fail "$mode: a process crashed on the way out"
    done
    ;;
mpi_lua_error_on_one_rank_ends)
    # the last rank alone raises a Lua error between two step calls; it must
    # not wait in its run record's collective stats() while the others wait in
    # their next step (#21): the run ends non-zero within the timeout, and
    # that rank's message reaches the user though only rank 0 prints
    mp "$ranks" s lua_error_one_rank.lua >"$tmp/out.txt" 2>"$tmp/err.txt"
    st=$?
    cat "$tmp/err.txt"
    [ $st -ne 124 ] || fail "the ranks hung after one rank's Lua error (killed by the 50 s timeout)"
    [ $st -ne 0 ] || fail "the run ended with status 0 after a Lua error"
    grep -q "hearth run (MPI rank $((ranks - 1))): .*an error raised on rank $((ranks - 1)) alone" "$tmp/err.txt" ||
        fail "the failed rank's message did not reach stderr"
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

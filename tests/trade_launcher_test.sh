#!/usr/bin/env bash
# trade_launcher_test.sh CASE HEARTH SOURCE_ROOT: `hearth trade --launcher
# slurm|mpi` and `--collect` against the local launcher. The Slurm case starts
# a real single-node Slurm (munged, slurmctld, slurmd from Debian's slurm-wlm
# and munge) in a temp folder, with a generated slurm.conf and free ports, and
# stops it on exit; it skips (77) where Slurm is missing or will not start.
set -u
case_name=$1 hearth=$2 root=$3
tmp=$(mktemp -d)
pids=()
cleanup() {
    local p
    for p in "${pids[@]}"; do kill "$p" 2>/dev/null; done
    for p in "${pids[@]}"; do
        for _ in $(seq 50); do kill -0 "$p" 2>/dev/null || break; sleep 0.1; done
        kill -9 "$p" 2>/dev/null
    done
    [ -n "${HEARTH_KEEP_TMP:-}" ] && cp -r "$tmp" "$HEARTH_KEEP_TMP"
    rm -rf "$tmp"
}
trap cleanup EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }
skip() { echo "SKIP: $*"; exit 77; }
knobs="$root/tests/trade/knobs.lua"
# the 4-run ladder every launcher runs: two block sizes, each at two dx (a refinement
# series, so references, errors and the order columns are all exercised)
ladder=("$knobs" --metric height --knob size=0.125,0.25 --knob dx=0.03125,0.015625 --quiet)
# the columns that do not depend on where or how fast a run ran (not wall_s,
# peak_mb, or pareto, which follows the wall times)
same_as_local() { # DIR: its trade.csv equals local/trade.csv in those columns
    python3 - local/trade.csv "$1/trade.csv" <<'PY' || fail "$1/trade.csv differs from the local launcher's"
import csv, sys
keep = ["run", "size", "dx", "status", "steps", "height", "reference", "error", "rel_error", "order", "note"]
a, b = ([[row[k] for k in keep] for row in csv.DictReader(open(p))] for p in sys.argv[1:])
if a != b or len(a) != 4:
    print("local:   ", a, "\nlauncher:", b, sep="\n", file=sys.stderr)
    sys.exit(1)
print(f"{len(a)} runs equal to the local launcher's in {', '.join(keep)}")
PY
}
run_local() {
    "$hearth" trade "${ladder[@]}" --jobs 2 --out local >local.txt 2>local.err || fail "local launcher: $(cat local.err)"
}
# table rows without the wall-time, peak-memory and pareto columns
table_rows() { grep -E '^ +[0-9]+ ' "$1" | awk '{print $1, $2, $3, $4, $6, $8, $9, $10, $NF == "reference" ? "ref" : ""}'; }

# ---- a local single-node Slurm ------------------------------------------------
start_slurm() {
    export PATH=$PATH:/usr/sbin:/sbin # the daemons
    for p in munged slurmctld slurmd sbatch squeue sinfo; do
        command -v "$p" >/dev/null 2>&1 ||
            skip "no $p: install Debian's slurm-wlm and munge (scripts/setup.sh does unless HEARTH_NO_SLURM=1)"
    done
    [ "$(id -u)" -eq 0 ] || skip "slurmd must run as root to start job tasks; run as root (as CI does)"
    # munged wants its socket folder and every parent searchable by all
    chmod 755 "$tmp"
    local c="$tmp/cluster"
    mkdir -p "$c/munge" "$c/state" "$c/spool" && chmod 755 "$c" "$c/munge"
    head -c 1024 /dev/urandom >"$c/munge/munge.key" && chmod 400 "$c/munge/munge.key"
    munged -F --key-file="$c/munge/munge.key" --socket="$c/munge/socket" --pid-file="$c/munge/pid" \
        --log-file="$c/munge/log" --seed-file="$c/munge/seed" &
    pids+=($!)
    for _ in $(seq 50); do [ -S "$c/munge/socket" ] && break; sleep 0.1; done
    [ -S "$c/munge/socket" ] || skip "munged did not start: $(tail -3 "$c/munge/log" 2>/dev/null)"
    local ports
    ports=$(python3 -c "
import socket
s = [socket.socket() for _ in range(2)]
for x in s: x.bind(('127.0.0.1', 0))
print(*[x.getsockname()[1] for x in s])")
    read -r p1 p2 <<<"$ports"
    local host
    host=$(hostname -s)
    cat >"$c/slurm.conf" <<EOF
ClusterName=hearthtest
SlurmctldHost=$host(127.0.0.1)
SlurmctldPort=$p1
SlurmdPort=$p2
SlurmUser=root
SlurmdUser=root
AuthType=auth/munge
CredType=cred/munge
AuthInfo=socket=$c/munge/socket
StateSaveLocation=$c/state
SlurmdSpoolDir=$c/spool
SlurmctldPidFile=$c/slurmctld.pid
SlurmdPidFile=$c/slurmd.pid
SlurmctldLogFile=$c/slurmctld.log
SlurmdLogFile=$c/slurmd.log
ProctrackType=proctrack/linuxproc
TaskPlugin=task/none
SelectType=select/cons_tres
SelectTypeParameters=CR_Core
SchedulerType=sched/builtin
# schedule at once (batch_sched_delay is 3 s by default), and run the whole
# 4-task array at once: the node claims 4 CPUs whatever it has (config_overrides)
SchedulerParameters=batch_sched_delay=0
MailProg=/bin/true
SlurmdParameters=config_overrides
AccountingStorageType=accounting_storage/none
JobCompType=jobcomp/none
JobAcctGatherType=jobacct_gather/none
MpiDefault=none
ReturnToService=2
InactiveLimit=0
KillWait=5
Waittime=0
NodeName=hearthnode NodeHostname=$host NodeAddr=127.0.0.1 CPUs=4 State=UNKNOWN
PartitionName=hearth Nodes=hearthnode Default=YES MaxTime=INFINITE State=UP
EOF
    # a test run inside a real Slurm job must not talk to that cluster
    unset $(env | sed -n 's/^\(SLURM_[A-Za-z_]*\)=.*/\1/p')
    export SLURM_CONF="$c/slurm.conf"
    slurmctld -D -i >"$c/slurmctld.out" 2>&1 &
    pids+=($!)
    slurmd -D -N hearthnode >"$c/slurmd.out" 2>&1 &
    pids+=($!)
    local why="did not start in 20 s"
    for _ in $(seq 100); do
        sinfo -h -o %t 2>/dev/null | grep -q idle && return 0
        kill -0 "${pids[1]}" 2>/dev/null && kill -0 "${pids[2]}" 2>/dev/null || { why="refused to start"; break; }
        sleep 0.2
    done
    skip "Slurm $why: $(for f in "$c"/slurmctld.log "$c"/slurmctld.out "$c"/slurmd.log "$c"/slurmd.out; do
        [ -f "$f" ] && tail -n 2 "$f"; done | tr '\n' ' ')"
}

case $case_name in
trade_slurm_array_matches_local)
    start_slurm
    echo "Slurm up: $(sinfo -h -o '%P %D %t %c CPUs')"
    run_local
    t0=$(date +%s.%N)
    "$hearth" trade "${ladder[@]}" --launcher slurm --out slurm >slurm.txt 2>slurm.err || fail "slurm launcher: exit $?: $(cat slurm.err)"
    echo "slurm ladder: $(python3 -c "import sys; print(f'{float(sys.argv[2]) - float(sys.argv[1]):.1f}')" "$t0" "$(date +%s.%N)") s"
    grep -q "4 runs as Slurm job array" slurm.err || fail "no job array: $(cat slurm.err)"
    job=$(cat slurm/slurm-job.txt)
    [ "$(ls slurm/slurm-"$job"_*.out | wc -l)" -eq 4 ] || fail "expected 4 task outputs: $(ls slurm)"
    grep -q -- "--worker slurm" slurm/slurm-array.sh || fail "batch script: $(cat slurm/slurm-array.sh)"
    same_as_local slurm
    [ "$(table_rows local.txt)" = "$(table_rows slurm.txt)" ] || fail "tables differ: $(cat local.txt slurm.txt)"
    # submit and log out, gather later
    "$hearth" trade "${ladder[@]}" --launcher slurm --no-wait --out later >later.txt 2>later.err || fail "--no-wait: $(cat later.err)"
    grep -q "hearth trade --collect $tmp/later" later.txt || fail "--no-wait says how to collect: $(cat later.txt)"
    [ ! -e later/trade.csv ] || fail "--no-wait should not gather"
    job=$(cat later/slurm-job.txt)
    for _ in $(seq 150); do squeue -h -j "$job" -o %t | grep -q . || break; sleep 0.2; done
    "$hearth" trade --collect later >collect.txt 2>collect.err || fail "--collect: exit $?: $(cat collect.err)"
    same_as_local later
    # a failing run: its task fails in Slurm, and the table says which run and why
    "$hearth" trade "$knobs" --metric not_a_number --knob size=0.1 --launcher slurm --out bad --quiet >bad.txt 2>bad.err
    [ $? -eq 1 ] || fail "a failed run should exit 1: $(cat bad.err)"
    grep -q "returned string, not a number" bad/trade.csv || fail "the failure is not in the CSV: $(cat bad/trade.csv)"
    job=$(cat bad/slurm-job.txt)
    for _ in $(seq 50); do squeue -h -t all -j "$job" -o %t | grep -q F && break; sleep 0.2; done
    squeue -h -t all -j "$job" -o %t | grep -q F || fail "the failed run's task should be FAILED in Slurm: $(squeue -h -t all -j "$job")"
    ;;
trade_mpi_ranks_match_local)
    command -v mpirun >/dev/null 2>&1 || skip "no mpirun: install openmpi-bin to run --launcher mpi"
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    run_local
    "$hearth" trade "${ladder[@]}" --launcher mpi --jobs 2 --launcher-arg --oversubscribe --out mpi >mpi.txt 2>mpi.err ||
        fail "mpi launcher: exit $?: $(cat mpi.err)"
    same_as_local mpi
    [ "$(table_rows local.txt)" = "$(table_rows mpi.txt)" ] || fail "tables differ: $(cat local.txt mpi.txt)"
    # every run ran exactly once, and both ranks took some
    [ "$(cat mpi/runs/*/claim | sort | uniq -c | wc -l)" -eq 2 ] || fail "runs per rank: $(cat mpi/runs/*/claim)"
    for r in 0 1 2 3; do grep -q "run 00$r " mpi.err || fail "no word from run $r: $(cat mpi.err)"; done
    ;;
trade_collect_names_missing_runs)
    # --collect on a ladder where one run left no record: the others are gathered, the
    # missing one is named with its Slurm task output (a fake job: no Slurm needed).
    # The folder has moved since (copied off the cluster) and the scene is gone.
    cp "$knobs" knobs.lua
    ladder[0]=knobs.lua
    run_local
    rm knobs.lua
    mv local moved
    rm moved/runs/002/run.txt
    echo 77 >moved/slurm-job.txt
    printf 'slurmstepd: error: *** JOB 77 ON hearthnode CANCELLED DUE TO TIME LIMIT ***\n' >moved/slurm-77_2.out
    "$hearth" trade --collect moved >collect.txt 2>collect.err
    [ $? -eq 1 ] || fail "--collect with a missing run should exit 1: $(cat collect.err)"
    grep -q "^2,0.25,0.03125,error,.*Slurm task 2 of job 77 left no record: slurmstepd: .*TIME LIMIT \*\*\*; see moved/slurm-77_2.out\"$" moved/trade.csv ||
        fail "missing run not named: $(cat moved/trade.csv)"
    [ "$(grep -c ',ok,' moved/trade.csv)" -eq 3 ] || fail "the 3 recorded runs: $(cat moved/trade.csv)"
    grep -q "^ *2 .* error .*left no record" collect.txt || fail "the table names the missing run: $(cat collect.txt)"
    ;;
trade_collect_refuses_bad_records)
    # records come from a folder someone else may have made: a number out of its range
    # or a record of noise makes that run an error naming the file and the field
    run_local
    sed -i 's/^wall .*/wall 1e308/' local/runs/001/run.txt
    head -c 3000 /dev/urandom >local/runs/002/run.txt
    "$hearth" trade --collect local >collect.txt 2>collect.err
    [ $? -eq 1 ] || fail "--collect with bad records should exit 1: $(cat collect.err)"
    grep -q "^ *1 .* error .*unreadable record local/runs/001/run.txt: bad wall (0 to 1e9 s)" collect.txt ||
        fail "the out-of-range wall time is not named: $(cat collect.txt)"
    grep -q "^ *2 .* error .*unreadable record local/runs/002/run.txt" collect.txt || fail "the noise record: $(cat collect.txt)"
    [ "$(grep -c ',ok,' local/trade.csv)" -eq 2 ] || fail "the 2 good runs: $(cat local/trade.csv)"
    ;;
trade_launcher_errors)
    # no sbatch / no mpirun on PATH: said before anything runs
    PATH=/nonexistent "$hearth" trade "${ladder[@]}" --launcher slurm --out s >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "needs Slurm's sbatch, and it is not on PATH" err.txt || fail "no sbatch: $(cat err.txt)"
    [ ! -e s/runs/000/run.txt ] || fail "nothing should have run"
    PATH=/nonexistent "$hearth" trade "${ladder[@]}" --launcher mpi --out m >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "needs mpirun" err.txt || fail "no mpirun: $(cat err.txt)"
    "$hearth" trade "${ladder[@]}" --launcher pbs >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "local, slurm or mpi, got 'pbs'" err.txt || fail "bad launcher: $(cat err.txt)"
    "$hearth" trade "${ladder[@]}" --no-wait >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "no-wait is for --launcher slurm" err.txt || fail "--no-wait local: $(cat err.txt)"
    "$hearth" trade "${ladder[@]}" --launcher-arg --oversubscribe >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "launcher-arg is for" err.txt || fail "--launcher-arg local: $(cat err.txt)"
    mkdir notrade
    "$hearth" trade --collect notrade >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "notrade/trade.args: No such file.*--out folder of a hearth trade" err.txt ||
        fail "--collect elsewhere: $(cat err.txt)"
    "$hearth" trade --collect >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "collect needs the results folder" err.txt || fail "--collect alone: $(cat err.txt)"
    # a worker outside mpirun or Slurm says what is missing
    run_local
    env -u OMPI_COMM_WORLD_RANK -u PMI_RANK -u PMIX_RANK "$hearth" trade --worker mpi local >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "no MPI rank in the environment" err.txt || fail "worker without rank: $(cat err.txt)"
    SLURM_ARRAY_TASK_ID=9 "$hearth" trade --worker slurm local >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "SLURM_ARRAY_TASK_ID is '9'; the ladder in local has runs 0..3" err.txt || fail "task 9: $(cat err.txt)"
    ;;
*) fail "unknown case $case_name" ;;
esac
echo ok

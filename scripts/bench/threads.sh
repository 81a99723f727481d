#!/usr/bin/env bash
# threads.sh: wall-clock speed-up of 2 threads over 1 (issue 20's targets:
# >= 1.8x in 2D at 128-1024 cells, >= 1.9x in 3D at 32-96 cells), for a quiet
# machine: on a loaded one the ratio measures the other jobs, not hearth.
#
#   scripts/bench/threads.sh [--pairs N] [--hearth PATH] [--quick]
#
# For each size, N (default 5) interleaved pairs of `hearth bench` runs, one
# thread then two, so both runs of a pair see the same machine; prints each
# pair's ratio, their median and spread, the load average when the script
# starts, and what other processes took of the CPUs while each size ran (all
# CPU time from /proc/stat less this script's runs', in cores: above 0.2,
# read the ratios with care, and the script says so). --quick runs the
# smallest size of each dimension only.
# Each pair also runs two one-thread benches at once, in separate processes
# that share nothing (the "twins"): how much slower each runs than one alone
# is what the machine itself takes from a second busy core (two virtual
# CPUs on one physical core, a shared cache or memory bus, clocks), and
# 2 / that slowdown is the two-thread ratio the machine allows (the ceiling
# column). A two-thread ratio near its ceiling has nothing left to win in
# hearth; one well below it has.
# The machine-independent side of the same question, the instructions the
# step leaves outside parallel regions, is report.sh's serial-share rows.
# Uses build/release/app/hearth (made when missing) unless --hearth is given.
# The runs get OMP_WAIT_POLICY=passive, what `hearth` itself sets (main.c):
# every region start and barrier then wakes a sleeping thread. GOMP_SPINCOUNT
# from the environment passes through (libgomp spins that many times before it
# sleeps; it overrides the policy's 0), to compare a bounded spin on a quiet
# machine; the header line names it. HEARTH_MPM_COLOUR_PHASES=1 passes through
# too (the step's P2G colour phases at 2 threads instead of the gather: the
# same bits, more barriers; named in the header). The synchronisations a step makes, which
# that cost multiplies, are threads_sync.sh's (callgrind: any machine).
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
pairs=5 hearth="" quick=0
while [ $# -gt 0 ]; do
    case $1 in
    --pairs) pairs=$2; shift ;;
    --hearth) hearth=$2; shift ;;
    --quick) quick=1 ;;
    -h | --help) sed -n 2,32p "$0"; exit 0 ;;
    *) echo "threads.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
case $pairs in '' | *[!0-9]* | 0) echo "threads.sh: --pairs needs a whole number >= 1, got '$pairs'" >&2; exit 2 ;; esac
if [ -z "$hearth" ]; then
    [ -f "$root/build/release/build.ninja" ] || meson setup "$root/build/release" "$root" --buildtype=release >/dev/null
    ninja -C "$root/build/release" app/hearth plugins/hearth_elastic.so >/dev/null
    hearth=$root/build/release/app/hearth
    export HEARTH_PLUGIN_PATH="$root/build/release/plugins"
fi
[ -x "$hearth" ] || { echo "threads.sh: $hearth is not an executable" >&2; exit 2; }
export THREADS_HEARTH=$hearth THREADS_PAIRS=$pairs THREADS_QUICK=$quick
exec python3 - <<'PY'
import json, os, resource, statistics, subprocess, sys, time

E = os.environ
hearth, pairs, quick = E["THREADS_HEARTH"], int(E["THREADS_PAIRS"]), E["THREADS_QUICK"] == "1"
sizes = [(2, 128), (2, 256), (2, 512), (2, 1024), (3, 32), (3, 64), (3, 96)]
if quick:
    sizes = [(2, 128), (3, 32)]

def bench(dim, cells, steps, threads):
    r = subprocess.run([hearth, "bench", "--threads", str(threads), "--dim", str(dim), "--cells", str(cells), "--steps", str(steps)],
                       capture_output=True, text=True, env=dict(E, OMP_WAIT_POLICY="passive"))
    if r.returncode:
        sys.exit(f"threads.sh: hearth bench --dim {dim} --cells {cells} failed: {r.stderr.strip()}")
    j = json.loads(r.stdout)
    if j["threads"] != threads:
        sys.exit(f"threads.sh: asked for {threads} threads, the bench ran {j['threads']} (an OpenMP build is needed)")
    return j

def twins(dim, cells, steps):
    """Two one-thread benches started together, as separate processes: the slower one's rate."""
    cmd = [hearth, "bench", "--threads", "1", "--dim", str(dim), "--cells", str(cells), "--steps", str(steps)]
    ps = [subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=dict(E, OMP_WAIT_POLICY="passive"))
          for _ in range(2)]
    rates = []
    for p in ps:
        out, err = p.communicate()
        if p.returncode:
            sys.exit(f"threads.sh: hearth bench --dim {dim} --cells {cells} (twins) failed: {err.strip()}")
        rates.append(json.loads(out)["particle_steps_per_s"])
    return min(rates)

def cpu_busy():
    """Seconds of CPU time the whole machine has spent busy (not idle or waiting on I/O), and this script's children's."""
    f = [int(x) for x in open("/proc/stat").readline().split()[1:]]
    hz = os.sysconf("SC_CLK_TCK")
    ch = resource.getrusage(resource.RUSAGE_CHILDREN)
    return (sum(f) - f[3] - f[4]) / hz, ch.ru_utime + ch.ru_stime

spin = f", GOMP_SPINCOUNT={E['GOMP_SPINCOUNT']}" if E.get("GOMP_SPINCOUNT") else ""
if E.get("HEARTH_MPM_COLOUR_PHASES"):
    spin += f", HEARTH_MPM_COLOUR_PHASES={E['HEARTH_MPM_COLOUR_PHASES']}"
print(f"threads.sh: {hearth}, {os.cpu_count()} cores, {pairs} interleaved pairs a size, OMP_WAIT_POLICY=passive{spin}; "
      f"load average {os.getloadavg()[0]:.1f} at the start", flush=True)
print("| dim | cells | particles | steps | 2 threads / 1 (median) | min-max | pairs | twins' slowdown (median) | ceiling | other processes' CPU (cores) |")
print("|---:|---:|---:|---:|---:|---:|---|---:|---:|---:|")
busy = False
for dim, cells in sizes:
    n = bench(dim, cells, 1, 1)["particles"]
    steps = max(5, int((3e6 if dim == 2 else 1.5e6) / n * 4))  # about a second a run at one thread
    m0, c0, t0 = *cpu_busy(), time.monotonic()
    ratios, slow = [], []
    for _ in range(pairs):
        a = bench(dim, cells, steps, 1)["particle_steps_per_s"]
        b = bench(dim, cells, steps, 2)["particle_steps_per_s"]
        ratios.append(b / a)
        slow.append(a / twins(dim, cells, steps))
    m1, c1, t1 = *cpu_busy(), time.monotonic()
    # the twins' own CPU is this script's children's too, so it is not counted as other processes'
    other = max(0.0, (m1 - m0) - (c1 - c0)) / (t1 - t0)
    busy |= other > 0.2
    sd = statistics.median(slow)
    print(f"| {dim}D | {cells} | {n} | {steps} | {statistics.median(ratios):.2f}x | {min(ratios):.2f}-{max(ratios):.2f} | "
          + " ".join(f"{r:.2f}" for r in ratios) + f" | {sd:.2f}x | {2 / sd:.2f}x | {other:.2f} |", flush=True)
if busy:
    print("threads.sh: other processes used more than 0.2 of a core while it ran: they shared the cores, so these "
          "ratios measure the machine as much as hearth")
PY

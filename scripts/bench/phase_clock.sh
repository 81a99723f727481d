#!/usr/bin/env bash
# phase_clock.sh: where 2 threads lose against 1, phase by phase, from each
# thread's own clocks (issue 20; docs/performance.md "Two threads, phase by
# phase"). A measuring build (build/phase: release with -DHEARTH_PHASE_CLOCK,
# core/sim/parallel/phase_clock.h) marks the MPM step's phase boundaries in
# every thread; each mark files the wall time (CLOCK_MONOTONIC) and the
# thread's CPU time (CLOCK_THREAD_CPUTIME_ID) since the thread's last mark,
# and team_wait.c's waits add their own, so each phase splits into work and
# waiting. For each size, N interleaved pairs of `hearth bench` at 1 and 2
# threads; per run the mean over its steps (the first dropped: what the
# bench's rate weighs; a phase that runs in some steps only, such as the
# permutation, counts at its share), then the median over runs. Prints per phase: 1 thread's CPU time; at 2 threads each
# thread's work (CPU time less the CPU its waits spun) and its waits' wall
# time; the work of both threads over 1 thread's (above 1: the same work
# costs more CPU on two cores); the step's wall time at 1 and 2 threads.
# Thread CPU time leaves out what other processes take while a thread is
# descheduled, so the work columns hold on a loaded machine; the wall and
# wait columns do not (--chrt runs the benches under `chrt -f 10`, a
# quiet-machine proxy that preempts other jobs; say so when quoting it).
#
#   scripts/bench/phase_clock.sh [--pairs N] [--steps S] [--chrt] [--json DIR] [--hearth PATH] [DIM:CELLS ...]
#
# Default sizes 2:128 3:32, 5 pairs, steps sized to about a second a run
# (threads.sh's). --hearth: another measuring build's hearth (a before and
# after; the plugins are build/phase's).
# The bench's OMP_WAIT_POLICY=passive is hearth's own (app/main.c);
# HEARTH_TEAM_SPIN and GOMP_SPINCOUNT pass through.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
pairs=5 steps=0 chrt="" json="" hearth="" sizes=()
while [ $# -gt 0 ]; do
    case $1 in
    --pairs) pairs=$2; shift ;;
    --steps) steps=$2; shift ;;
    --chrt) chrt="chrt -f 10" ;;
    --json) json=$2; shift ;;
    --hearth) hearth=$2; shift ;;
    -h | --help) sed -n 2,27p "$0"; exit 0 ;;
    [23]:[0-9]*) sizes+=("$1") ;;
    *) echo "phase_clock.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
case $pairs in '' | *[!0-9]* | 0) echo "phase_clock.sh: --pairs needs a whole number >= 1, got '$pairs'" >&2; exit 2 ;; esac
case $steps in '' | *[!0-9]*) echo "phase_clock.sh: --steps needs a whole number, got '$steps'" >&2; exit 2 ;; esac
[ ${#sizes[@]} -gt 0 ] || sizes=(2:128 3:32)
b=$root/build/phase
[ -f "$b/build.ninja" ] || meson setup "$b" "$root" --buildtype=release -Dwerror=true -Dc_args=-DHEARTH_PHASE_CLOCK >/dev/null
ninja -C "$b" app/hearth plugins/hearth_elastic.so >/dev/null
export HEARTH_PLUGIN_PATH="$b/plugins"
dir=${json:-$(mktemp -d)}
mkdir -p "$dir"
[ -n "$hearth" ] || hearth=$b/app/hearth
[ -x "$hearth" ] || { echo "phase_clock.sh: $hearth is not an executable" >&2; exit 2; }
export PC_HEARTH=$hearth PC_PAIRS=$pairs PC_STEPS=$steps PC_CHRT=$chrt PC_DIR=$dir PC_SIZES="${sizes[*]}"
exec python3 - <<'PY'
import json, os, statistics, subprocess, sys

E = os.environ
hearth, pairs, steps0, chrt, d = E["PC_HEARTH"], int(E["PC_PAIRS"]), int(E["PC_STEPS"]), E["PC_CHRT"].split(), E["PC_DIR"]
med = statistics.median

def bench(dim, cells, steps, threads, tag):
    out = os.path.join(d, f"{dim}d{cells}_{threads}t_{tag}.json")
    r = subprocess.run(chrt + [hearth, "bench", "--threads", str(threads), "--dim", str(dim), "--cells", str(cells), "--steps", str(steps)],
                       capture_output=True, text=True, env=dict(E, HEARTH_PHASE_CLOCK_OUT=out))
    if r.returncode:
        sys.exit(f"phase_clock.sh: hearth bench --dim {dim} --cells {cells} failed: {r.stderr.strip()}")
    j = json.loads(r.stdout)
    if j["threads"] != threads:
        sys.exit(f"phase_clock.sh: asked for {threads} threads, the bench ran {j['threads']}")
    return j, json.load(open(out))

def per_run(clk):
    """Per thread, phase and kind: the mean over the steps but the first; and the master's step wall."""
    rows = clk["steps"][1:-1]  # the last row lacks its 'outside'
    T, P = clk["threads"], len(clk["phases"])
    m = [[[statistics.fmean(r[t][p][k] for r in rows) / 1e3 for k in range(4)] for p in range(P)] for t in range(T)]
    step = statistics.fmean(sum(r[0][p][0] for p in range(P)) for r in rows) / 1e3
    return m, step

print(f"phase_clock.sh: {hearth}, {os.cpu_count()} cores, {pairs} interleaved pairs a size"
      f"{', under chrt -f 10' if chrt else ''}; load average {os.getloadavg()[0]:.1f} at the start; "
      f"HEARTH_TEAM_SPIN={E.get('HEARTH_TEAM_SPIN', 'unset')}; microseconds a step (mean over steps, median over runs)", flush=True)
for size in E["PC_SIZES"].split():
    dim, cells = map(int, size.split(":"))
    n = bench(dim, cells, 1, 1, "probe")[0]["particles"]
    steps = steps0 or max(20, int((3e6 if dim == 2 else 1.5e6) / n * 4))
    runs = {1: [], 2: []}
    rate = {1: [], 2: []}
    for i in range(pairs):
        for T in (1, 2):
            j, clk = bench(dim, cells, steps, T, str(i))
            runs[T].append(per_run(clk))
            rate[T].append(j["particle_steps_per_s"])
    phases = clk["phases"]
    def agg(T, t, p, k):
        return med(r[0][t][p][k] for r in runs[T])
    print(f"\n{dim}D {cells} cells, {n} particles, {steps} steps; 2 threads / 1 by the bench's rate: "
          f"{med(b / a for a, b in zip(rate[1], rate[2])):.2f}x (pairs " + " ".join(f"{b / a:.2f}" for a, b in zip(rate[1], rate[2])) + ")")
    print("| phase | 1 thread: CPU | 1 thread: wall | thread 0: work CPU | thread 0: waits (wall) | thread 1: work CPU | "
          "thread 1: waits (wall) | 2 threads' work / 1's | thread 0: wall | thread 1: wall |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    tot = [0.0] * 7
    for p, name in enumerate(phases):
        c1, w1 = agg(1, 0, p, 1), agg(1, 0, p, 0)
        wk = [agg(2, t, p, 1) - agg(2, t, p, 3) for t in (0, 1)]
        wt = [agg(2, t, p, 2) for t in (0, 1)]
        wl = [agg(2, t, p, 0) for t in (0, 1)]
        if name == "fork":  # a worker's CPU before its first mark is its idle time since the last region (spin or sleep)
            wk[1] = 0.0
        vals = [c1, w1, wk[0], wt[0], wk[1], wt[1]]
        tot = [a + b for a, b in zip(tot, vals + [0])]
        ratio = f"{(wk[0] + wk[1]) / c1:.3f}" if c1 > 5 else "-"
        print(f"| {name} | {c1:.1f} | {w1:.1f} | {wk[0]:.1f} | {wt[0]:.1f} | {wk[1]:.1f} | {wt[1]:.1f} | {ratio} | {wl[0]:.1f} | {wl[1]:.1f} |")
    print(f"| sum | {tot[0]:.1f} | {tot[1]:.1f} | {tot[2]:.1f} | {tot[3]:.1f} | {tot[4]:.1f} | {tot[5]:.1f} | "
          f"{(tot[2] + tot[4]) / tot[0]:.3f} | | |")
    s1, s2 = med(r[1] for r in runs[1]), med(r[1] for r in runs[2])
    print(f"step wall (master's marks): 1 thread {s1:.1f} us, 2 threads {s2:.1f} us: {s1 / s2:.2f}x")
PY

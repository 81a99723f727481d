#!/usr/bin/env bash
# threads_sync.sh: the machine-independent side of 2 threads against 1, for a
# loaded machine where wall clock is noise. For each size, callgrind with
# --separate-threads runs `hearth bench` at 2 threads for S and S + 10 steps;
# from the difference, per step:
#   - the parallel regions the second thread takes part in (its outlined
#     function calls), the barriers it waits at (GOMP_barrier and the ends of
#     loops without nowait) and the synchronisations that makes (a region's
#     start and end, and each barrier: with OMP_WAIT_POLICY=passive, what
#     hearth sets, each one wakes a sleeping thread, a futex round trip);
#   - each thread's instructions per particle-step and their max / mean;
#   - the master's instructions outside every region (serial, per particle-step).
# Dynamic schedules under valgrind follow valgrind's own thread switching (it
# runs one thread at a time), so the per-thread split measures the static
# parts only; the sync counts are exact.
#
#   scripts/bench/threads_sync.sh [--hearth PATH] [--steps S] [DIM:CELLS ...]
#
# Default sizes 2:128 3:32. Needs valgrind; uses build/nn (no -march=native:
# valgrind does not decode AVX-512), made when missing, unless --hearth.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
hearth="" steps=2 sizes=()
while [ $# -gt 0 ]; do
    case $1 in
    --hearth) hearth=$2; shift ;;
    --steps) steps=$2; shift ;;
    -h | --help) sed -n 2,20p "$0"; exit 0 ;;
    [23]:[0-9]*) sizes+=("$1") ;;
    *) echo "threads_sync.sh: unknown argument '$1' (see --help)" >&2; exit 2 ;;
    esac
    shift
done
case $steps in '' | *[!0-9]* | 0) echo "threads_sync.sh: --steps needs a whole number >= 1, got '$steps'" >&2; exit 2 ;; esac
[ ${#sizes[@]} -gt 0 ] || sizes=(2:128 3:32)
if [ -z "$hearth" ]; then
    source "$root/scripts/bench/callgrind.sh"
    hearth=$nn_hearth
fi
[ -x "$hearth" ] || { echo "threads_sync.sh: $hearth is not an executable" >&2; exit 2; }
export HEARTH_PLUGIN_PATH=${HEARTH_PLUGIN_PATH:-$(dirname "$(dirname "$hearth")")/plugins}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
echo "threads_sync.sh: $hearth, callgrind, 2 threads, OMP_WAIT_POLICY=passive; per step from $steps and $((steps + 10)) steps"
echo "| dim | cells | particles | regions | barriers | synchronisations | thread 1 / 2 instructions per particle-step | max / mean | serial per particle-step |"
echo "|---:|---:|---:|---:|---:|---:|---|---:|---:|"
for sz in "${sizes[@]}"; do
    dim=${sz%%:*} cells=${sz#*:}
    for st in "$steps" $((steps + 10)); do
        OMP_WAIT_POLICY=passive nice valgrind --tool=callgrind --separate-threads=yes --callgrind-out-file="$tmp/cg.$dim.$cells.$st" \
            "$hearth" bench --dim "$dim" --cells "$cells" --steps "$st" --threads 2 >"$tmp/out.$dim.$cells.$st" 2>"$tmp/err"
    done
    DIM=$dim CELLS=$cells A=$tmp/cg.$dim.$cells.$steps B=$tmp/cg.$dim.$cells.$((steps + 10)) J=$tmp/out.$dim.$cells.$steps python3 - <<'PY'
import collections, json, os, re, subprocess
E = os.environ

def parse(path):
    """calls to each callee, and each function's inclusive instructions (callgrind_annotate)"""
    names, calls, cur = {}, collections.Counter(), None
    for line in open(path):
        m = re.match(r'^c?fn=\((\d+)\)(?: (.*))?', line)
        if m:
            if m.group(2): names[m.group(1)] = m.group(2).strip()
            cur = names.get(m.group(1)) if line.startswith('cfn') else None
            continue
        if line.startswith('calls=') and cur:
            calls[cur] += int(line.split('=')[1].split()[0]); cur = None
    total = int(re.search(r'^summary: (\d+)', open(path).read(), re.M).group(1))
    incl = collections.Counter()
    out = subprocess.run(['callgrind_annotate', '--inclusive=yes', '--threshold=100', path], capture_output=True, text=True).stdout
    for line in out.splitlines():
        m = re.match(r'^\s*([\d,]+) \([^)]*\)\s+\S*:(\S+)', line)
        if m: incl[m.group(2)] += int(m.group(1).replace(',', ''))
    return calls, total, incl

n = json.load(open(E['J']))['particles']
files = {t: (parse(f"{E['A']}-0{t}"), parse(f"{E['B']}-0{t}")) for t in (1, 2)}
(c2a, t2a, _), (c2b, t2b, _) = files[2]
d = lambda key: (c2b[key] - c2a[key]) / 10
regions = sum(d(k) for k in set(c2a) | set(c2b) if '._omp_fn.' in k)
barriers = d('GOMP_barrier') + d('GOMP_loop_end')
(c1a, t1a, i1a), (c1b, t1b, i1b) = files[1]
ins = [(t1b - t1a) / 10 / n, (t2b - t2a) / 10 / n]
inside = sum(i1b[k] - i1a[k] for k in set(i1a) | set(i1b) if '._omp_fn.' in k) / 10 / n
serial = ins[0] - inside
print(f"| {E['DIM']}D | {E['CELLS']} | {n} | {regions:.0f} | {barriers:.0f} | {2 * regions + barriers:.0f} | "
      f"{ins[0]:.0f} / {ins[1]:.0f} | {max(ins) / (sum(ins) / 2):.3f} | {serial:.1f} |", flush=True)
PY
done

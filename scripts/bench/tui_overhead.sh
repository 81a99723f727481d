#!/usr/bin/env bash
# tui_overhead.sh: what the dashboard costs the simulation, in one run.
#
#   scripts/bench/tui_overhead.sh [cells=128] [steps=300]
#
# Steps the benchmark block (tui_bench.lua, the block of `hearth bench` in 2D)
# headless with `hearth run`, then the same in the dashboard in a 120x40 tmux
# pane (--play --exit-when-done), one thread each, alternating (3 times, or
# $HEARTH_BENCH_REPS), and prints the best wall times and their ratio, plus
# the dashboard's own split of its time into stepping and drawing. The
# issue's budget: the dashboard costs at most 5% of the step time; the script
# exits non-zero when drawing takes more than 5% of the stepping time.
set -euo pipefail
cells=${1:-128}
steps=${2:-300}
. "$(dirname "$0")/../setup.sh"
hearth_install_deps tmux
build=${HEARTH_BUILD:-build/release} # a release build; HEARTH_BUILD=build/dev to reuse another
hearth_build "$build" --buildtype=release
hearth="$HEARTH_ROOT/$build/app/hearth"
scene="$HEARTH_ROOT/scripts/bench/tui_bench.lua"
tmp=$(mktemp -d)
sock="hearth-tui-bench-$$"
trap 'status=$?; tmux -L "$sock" kill-server 2>/dev/null || true; rm -rf "$tmp"; exit $status' EXIT # the server may be gone already: that is not a failure
export OMP_NUM_THREADS=1 OMP_WAIT_POLICY=passive

now() { date +%s.%N; }
reps=${HEARTH_BENCH_REPS:-3}
headless=() dash=()
for ((r = 0; r < reps; r++)); do # alternate, so a busy spell on a shared machine hits both
    t0=$(now)
    "$hearth" run "$scene" --quiet --out "$tmp/headless" --set cells="$cells" --set steps="$steps"
    t1=$(now)
    headless+=("$(python3 -c "print($t1 - $t0)")")
    rm -f "$tmp/dash.end" "$tmp/dash.exit"
    tmux -L "$sock" -f /dev/null new-session -d -x 120 -y 40 -s "b$r" \
        "cd '$tmp' && env LANG=C.UTF-8 LC_ALL=C.UTF-8 TERM=tmux-256color XDG_STATE_HOME='$tmp/state' \
         '$hearth' '$scene' --play --exit-when-done --out '$tmp/dash' --set cells=$cells --set steps=$steps \
         2>'$tmp/dash.txt'; echo \$? > '$tmp/dash.exit'; date +%s.%N > '$tmp/dash.end'"
    t2=$(now)
    for _ in $(seq 6000); do [ -f "$tmp/dash.end" ] && break; sleep 0.05; done
    [ -f "$tmp/dash.end" ] || { echo "tui_overhead: the dashboard did not finish" >&2; exit 1; }
    [ "$(cat "$tmp/dash.exit")" = 0 ] || { echo "tui_overhead: the dashboard exited $(cat "$tmp/dash.exit")" >&2; cat "$tmp/dash.txt" >&2; exit 1; }
    dash+=("$(python3 -c "print($(cat "$tmp/dash.end") - $t2)")")
    echo "run $((r + 1)): headless ${headless[r]} s, dashboard ${dash[r]} s; $(grep 'steps while running' "$tmp/dash.txt" | sed 's/^hearth: //')"
done
# The dashboard's own split is the robust number: drawing time over stepping
# time within one process. Wall-time ratios on a shared machine swing by 20%.
python3 - "$(IFS=,; echo "${headless[*]}")" "$(IFS=,; echo "${dash[*]}")" "$tmp/dash.txt" "$steps" "$cells" <<'PY'
import re, sys
hl = [float(x) for x in sys.argv[1].split(",")]
db = [float(x) for x in sys.argv[2].split(",")]
m = re.search(r"([\d.]+) s stepping, ([\d.]+) s drawing", open(sys.argv[3]).read())
share = float(m.group(2)) / float(m.group(1))
print(f"{sys.argv[4]} steps of the {sys.argv[5]}-cell block, best of {len(hl)}: "
      f"headless {min(hl):.3f} s, dashboard {min(db):.3f} s, ratio {min(db) / min(hl):.3f}")
print(f"drawing / stepping inside the dashboard (last run): {100 * share:.2f}% (budget 5%)")
sys.exit(0 if share <= 0.05 else 1)
PY

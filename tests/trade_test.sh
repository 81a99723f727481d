#!/usr/bin/env bash
# trade_test.sh CASE HEARTH SOURCE_ROOT: `hearth trade` and the scene settings
# --set may change, as a user meets them. Every case runs in a fresh temp folder.
here=$(cd "$(dirname "$0")" && pwd) # png_check.py lives here
set -u
case_name=$1 hearth=$2 root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }
knobs="$root/tests/trade/knobs.lua" slab="$root/scripts/trade/heat_slab.lua"
# csv_field FILE ROW COLUMN: one cell of a CSV written by hearth trade (row 0 = first run)
csv_field() {
    python3 - "$@" <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
print(rows[int(sys.argv[2])][sys.argv[3]])
PY
}
png_ok() { python3 "$here/png_check.py" "$1" 860 580 >/dev/null || fail "$1 is not a whole 860 x 580 PNG"; }

case $case_name in
trade_heat_slab_order)
    # explicit heat over two dx against the analytic centre temperature: the
    # error halves with dx (first order, see docs/trade/README.md for why)
    "$hearth" trade "$slab" --metric centre_temperature --knob dx=0.004,0.002 --knob heat=explicit \
        --reference "analytic:120 - 100 * 0.7725263834238096^2" --jobs 2 --out o --quiet >out.txt 2>err.txt \
        || fail "exit $?: $(cat err.txt)"
    [ "$(wc -l <o/trade.csv)" -eq 3 ] || fail "trade.csv: $(cat o/trade.csv)"
    for r in 0 1; do
        [ "$(csv_field o/trade.csv $r status)" = ok ] || fail "run $r did not finish: $(cat o/trade.csv)"
        python3 -c "import sys; s, m = float(sys.argv[1]), float(sys.argv[2]); sys.exit(not (s > 0 and m > 0))" \
            "$(csv_field o/trade.csv $r steps)" "$(csv_field o/trade.csv $r peak_mb)" || fail "steps or peak memory missing"
    done
    order=$(csv_field o/trade.csv 1 order)
    e0=$(csv_field o/trade.csv 0 rel_error) e1=$(csv_field o/trade.csv 1 rel_error)
    echo "observed order $order (relative errors $e0 at dx 0.004, $e1 at dx 0.002)"
    python3 -c "import sys; p = float(sys.argv[1]); sys.exit(not (0.8 <= p <= 1.3))" "$order" \
        || fail "observed order $order, expected first order (0.8..1.3)"
    [ "$(csv_field o/trade.csv 0 order)" = nan ] || fail "the coarsest run has no order"
    png_ok o/trade.png
    grep -q "centre_temperature" out.txt || fail "no table printed: $(cat out.txt)"
    ;;
trade_honours_omp_num_threads)
    # #18 (helpers userview4, userfix8): hearth trade set every run's OMP_NUM_THREADS to cores / jobs over the user's
    # own (OMP_NUM_THREADS=1 ran 2 threads a run on a 2-core machine). Bar set before the run: with OMP_NUM_THREADS=3
    # and --jobs 1 (cores / jobs is the machine's cores, 3 only on a 3-core one) the start line and run.json give 3
    # threads a run; --threads 2 still wins over it; an OMP_NUM_THREADS that is not a whole number is said and left.
    OMP_NUM_THREADS=3 "$hearth" trade "$knobs" --metric particles --knob ppc=1 --set size=0.125 --jobs 1 --out o \
        >out.txt 2>err.txt || fail "exit $?: $(cat err.txt)"
    grep -F "1 at a time with 3 threads each" err.txt || fail "the start line: $(cat err.txt)"
    python3 -c "import json, sys; r = json.load(open('o/run.json')); sys.exit(r['threads'] != 3)" ||
        fail "run.json's threads: $(grep threads o/run.json)"
    OMP_NUM_THREADS=3 "$hearth" trade "$knobs" --metric particles --knob ppc=1 --set size=0.125 --jobs 1 --threads 2 \
        --out o2 >out.txt 2>err.txt || fail "--threads 2: exit $?: $(cat err.txt)"
    grep -qF "with 2 threads each" err.txt || fail "--threads 2 over OMP_NUM_THREADS: $(cat err.txt)"
    OMP_NUM_THREADS=4,2 "$hearth" trade "$knobs" --metric particles --knob ppc=1 --set size=0.125 --jobs 1 --out o3 \
        >out.txt 2>err.txt || fail "OMP_NUM_THREADS=4,2: exit $?: $(cat err.txt)"
    grep -qF "OMP_NUM_THREADS=4,2 is not a whole number in [1, 1024]" err.txt || fail "a list not said: $(cat err.txt)"
    ;;
run_record_for_trade)
    # hearth trade writes its own run.json beside trade.csv: the command line, --set, the
    # plugins its runs loaded, threads per run, jobs, all runs' steps, peak memory (its
    # own and the largest run's), the guard's verdict and the files (trade.csv, trade.png, runs/)
    "$hearth" trade "$knobs" --metric particles --knob ppc=1,4 --set size=0.125 --jobs 2 --out o --quiet >out.txt 2>err.txt \
        || fail "exit $?: $(cat err.txt)"
    python3 - o <<'PY' || fail "trade run.json: $(cat o/run.json)"
import csv, json, os, sys
out = sys.argv[1]
r = json.load(open(os.path.join(out, "run.json")))
rows = list(csv.DictReader(open(os.path.join(out, "trade.csv"))))
assert r["command"] == "trade" and r["sets"] == {"size": "0.125"} and "ppc=1,4" in r["argv"], r
assert r["runs"] == 2 and r["jobs"] == 2 and r["threads"] >= 1, r
assert "elastic" in [p["name"] for p in r["plugins"]] and all(p["abi"] >= 1 for p in r["plugins"]), r["plugins"]
assert r["steps"] == sum(int(x["steps"]) for x in rows) > 0, (r["steps"], [x["steps"] for x in rows])
assert r["peak_memory_mb"] > 1 and r["peak_memory_largest_run_mb"] >= max(float(x["peak_mb"]) for x in rows) - 0.1, r
assert r["guard"]["verdict"] == "ok" and r["status"] == 0 and r["git_revision"], r
files = [f["path"] for f in r["files"]]
assert {"trade.csv", "trade.png", "runs/000/run.json", "runs/001/run.json"} <= set(files), files
print(f"trade run.json: {r['runs']} runs, {r['steps']} steps, {len(files)} files, plugins {[p['name'] for p in r['plugins']]}")
PY
    ;;
trade_finest_reference)
    # the finest run is the reference: its error is 0; a knob without a
    # refinement measure (a scene parameter) gives no order
    "$hearth" trade "$knobs" --metric particles --knob ppc=1,4,9 --knob size=0.125,0.25 --out o --quiet >out.txt 2>err.txt \
        || fail "exit $?: $(cat err.txt)"
    [ "$(wc -l <o/trade.csv)" -eq 7 ] || fail "expected 6 runs: $(cat o/trade.csv)"
    grep -q '^[0-9]*,9,0.25,ok,.*reference (finest run)' o/trade.csv || fail "the reference is not ppc 9 size 0.25: $(cat o/trade.csv)"
    # particle counts follow ppc (rounded to k^2) and size: 1, 4, 9 per cell
    for r in 0 1 2 3 4 5; do csv_field o/trade.csv $r particles; done >counts.txt
    python3 - counts.txt <<'PY' || fail "particle counts do not follow ppc and size: $(cat counts.txt)"
import sys
c = [float(x) for x in open(sys.argv[1])]
# rows: (ppc 1, size .1), (1, .2), (4, .1), (4, .2), (9, .1), (9, .2)
assert c[2] == 4 * c[0] and c[4] == 9 * c[0], c
assert c[1] > 3.5 * c[0], c
PY
    png_ok o/trade.png
    ;;
trade_bad_usage)
    "$hearth" trade "$knobs" --knob dx=0.1 >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q -- "--metric NAME is required" err.txt || fail "no --metric: $(cat err.txt)"
    "$hearth" trade "$knobs" --metric particles --knob dx=0.1 --knob dx=0.2 >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "given twice" err.txt || fail "knob twice: $(cat err.txt)"
    "$hearth" trade "$knobs" --metric particles --knob size=0.1 --reference "analytic:1 +* 2" >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "reference analytic" err.txt && [ ! -d hearth-out ] || fail "bad expression: $(cat err.txt)"
    "$hearth" trade "$knobs" --metric particles --reference exact >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "finest' or 'analytic" err.txt || fail "bad reference: $(cat err.txt)"
    "$hearth" trade "$knobs" --metric particles --knob dx=fine,coarse >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "needs numbers" err.txt || fail "dx words: $(cat err.txt)"
    # a metric the scene lacks: the run fails and says which exist
    "$hearth" trade "$knobs" --metric partcles --knob size=0.1 --out o --quiet >out.txt 2>err.txt
    [ $? -eq 1 ] || fail "unknown metric: exit $?"
    grep -q "no such metric; did you mean 'particles'" o/trade.csv || fail "unknown metric note: $(cat o/trade.csv)"
    "$hearth" run "$knobs" --quiet --metric not_a_number >out.txt 2>err.txt
    [ $? -eq 1 ] && grep -q "returned string, not a number" err.txt || fail "string metric: $(cat err.txt)"
    "$hearth" run "$knobs" --quiet --metric water_lost >out.txt 2>err.txt
    [ $? -eq 1 ] && grep -q "no water field" err.txt || fail "water_lost: $(cat err.txt)"
    ;;
trade_scene_settings)
    # --set reaches scene settings the scene does not declare as parameters
    "$hearth" run "$knobs" --quiet --metric particles --set ppc=9 >out.txt 2>err.txt || fail "ppc: $(cat err.txt)"
    grep -q "metric particles = 576$" out.txt || fail "ppc=9 should give 576 particles: $(cat out.txt)"
    "$hearth" run "$knobs" --quiet --metric particles --set dx=0.015625 >out.txt 2>err.txt || fail "dx: $(cat err.txt)"
    grep -q "metric particles = 1024$" out.txt || fail "dx=1/64 should give 1024 particles: $(cat out.txt)"
    "$hearth" run "$knobs" --quiet --metric mixed_yield >out.txt 2>err.txt || fail "blend: $(cat err.txt)"
    nonlinear=$(sed -n 's/^metric mixed_yield = //p' out.txt)
    "$hearth" run "$knobs" --quiet --metric mixed_yield --set blend=linear >out.txt 2>err.txt || fail "linear: $(cat err.txt)"
    grep -q "metric mixed_yield = 25$" out.txt || fail "linear blend of 10 and 40 is 25: $(cat out.txt)"
    [ "$nonlinear" != 25 ] || fail "the nonlinear blend should differ from the linear one"
    "$hearth" run "$knobs" --quiet --metric particles --set transfer=pic --set heat_flip=0.5 >out.txt 2>err.txt ||
        fail "transfer=pic: $(cat err.txt)"
    "$hearth" run "$knobs" --quiet --set transfer=flip >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "transfer=flip: valid: apic, pic" err.txt || fail "transfer=flip: $(cat err.txt)"
    "$hearth" run "$knobs" --quiet --set dim=3 >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "no z extent" err.txt || fail "dim=3 on a flat box: $(cat err.txt)"
    "$hearth" run "$knobs" --quiet --set heat=sideways >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "heat=sideways: valid: explicit, implicit" err.txt || fail "heat: $(cat err.txt)"
    "$hearth" run "$knobs" --quiet --set sise=0.2 >out.txt 2>err.txt
    [ $? -eq 2 ] && grep -q "no parameter 'sise'" err.txt || fail "misspelt parameter: $(cat err.txt)"
    ;;
*) fail "unknown case $case_name" ;;
esac
echo ok

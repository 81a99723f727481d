#!/usr/bin/env bash
# cli_test.sh CASE HEARTH: the hearth command line as a user meets it.
here=$(cd "$(dirname "$0")" && pwd) # png_check.py lives here
set -u
case_name=$1
hearth=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

png_ok() { python3 "$here/png_check.py" "$1" >/dev/null; } # see png_check.py

case "$case_name" in
cli_help)
    "$hearth" --help | grep -q "hearth plugin check" || fail "--help lacks the subcommands"
    "$hearth" --version | grep -q "material ABI" || fail "--version"
    for sub in demo bench plugins; do "$hearth" $sub --help >/dev/null || fail "$sub --help"; done
    ;;
cli_rheometer_mpm)
    # the MPM shear-cell mode as a user runs it: --json, the CSV with the measured rate, a bad mode named
    out=$(cd "$tmp" && "$hearth" rheometer sauce.mayo --mode mpm --rates 10:10:1 --json) || fail "rheometer --mode mpm exited $?"
    echo "$out" | grep -qE '^\{"shear_rate":\[10\],"stress":\[1[45][0-9]\.[0-9]+\]\}$' || fail "mpm json: $out"
    head -1 "$tmp"/hearth-out/rheometer/sauce.mayo.csv | grep -qx "shear_rate,stress,hb_stress,measured_rate" ||
        fail "mpm CSV header: $(head -1 "$tmp"/hearth-out/rheometer/sauce.mayo.csv)"
    png_ok "$tmp"/hearth-out/rheometer/sauce.mayo.png || fail "mpm flow-curve PNG does not decode"
    "$hearth" rheometer --help | grep -q -- "--mode MODE" || fail "rheometer --help lacks --mode"
    err=$("$hearth" rheometer sauce.mayo --mode cone 2>&1) && fail "a bad --mode was accepted"
    echo "$err" | grep -qF -- "--mode cone; valid: homogeneous, mpm" || fail "bad --mode message: $err"
    ;;
cli_demo_frames)
    (cd "$tmp" && "$hearth" demo --until 0.02 --frames 2 --quiet) || fail "demo exited $?"
    n=$(ls "$tmp"/hearth-out/demo/frame_*.png 2>/dev/null | wc -l)
    [ "$n" -eq 3 ] || fail "expected 3 frames, found $n"
    for f in "$tmp"/hearth-out/demo/frame_*.png; do png_ok "$f" || fail "$f does not decode"; done
    ls "$tmp"/hearth-out/demo | grep -q tmp && fail "temp files left behind"
    # without a terminal, progress comes as plain lines on stderr
    (cd "$tmp" && "$hearth" demo --until 0.01 --frames 1 --out o2 2>err.txt) || fail "demo with progress"
    grep -q "progress: t = " "$tmp/err.txt" || fail "no plain progress line: $(cat "$tmp/err.txt")"
    ;;
cli_bench_json)
    out=$("$hearth" bench --cells 16 --steps 2 --dim 2 --threads 1) || fail "bench exited $?"
    python3 - "$out" <<'PY' || fail "bench JSON: $out"
import json, sys
j = json.loads(sys.argv[1])
for k in ("particles", "steps", "threads", "seconds", "particle_steps_per_s", "bytes_per_particle"):
    assert k in j, k
assert j["particles"] > 0 and j["steps"] == 2 and j["threads"] == 1 and j["particle_steps_per_s"] > 0
PY
    ;;
cli_plugins_list)
    out=$("$hearth" plugins) || fail "plugins exited $?"
    echo "$out" | grep -q "^elastic" || fail "elastic not listed"
    echo "$out" | grep -q "^newtonian" || fail "newtonian not listed"
    echo "$out" | grep -q "kg/m^3" || fail "no units in the table"
    ;;
cli_plugin_check_exit)
    "$hearth" plugin check "$HEARTH_PLUGIN_PATH/hearth_elastic.so" >"$tmp/ok.txt" || fail "elastic should pass: $(cat "$tmp/ok.txt")"
    [ "$(grep -c PASS "$tmp/ok.txt")" -eq 5 ] || fail "expected 5 PASS lines"
    "$hearth" plugin check "$HEARTH_TEST_PLUGIN_DIR/hearth_asym.so" >"$tmp/bad.txt" && fail "asym should fail"
    grep -q "symmetric *FAIL" "$tmp/bad.txt" || fail "asym: symmetric check should fail"
    "$hearth" plugin check /nonexistent/hearth_x.so 2>"$tmp/err.txt"; [ $? -eq 1 ] || fail "missing file exit"
    grep -q "not found" "$tmp/err.txt" || fail "missing file message: $(cat "$tmp/err.txt")"
    ;;
cli_bad_usage)
    "$hearth" frobnicate 2>/dev/null; [ $? -eq 2 ] || fail "unknown command should exit 2"
    "$hearth" bench --cells x 2>"$tmp/e"; [ $? -eq 2 ] || fail "bad number should exit 2"
    grep -q "\-\-cells needs a whole number" "$tmp/e" || fail "message: $(cat "$tmp/e")"
    ;;
*) fail "unknown case $case_name" ;;
esac
echo "ok"

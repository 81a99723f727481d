#!/usr/bin/env bash
# dumps_test.sh CASE HEARTH: VTU/PLY series from s:run read back by real
# readers (tests/vtk_check.py; VTK's cases skip with 77 where python3-vtk9 is
# missing), and the run options that write them.
here=$(cd "$(dirname "$0")" && pwd)
set -u
case_name=$1
hearth=$2
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }

# A Python that has VTK: the one on PATH, else Debian's (python3-vtk9 installs
# there, and a pyenv or venv python on PATH does not see it).
vtk_python() {
    for py in python3 /usr/bin/python3; do
        command -v "$py" >/dev/null 2>&1 && "$py" -c "import vtk" >/dev/null 2>&1 && { echo "$py"; return; }
    done
    echo python3
}

case "$case_name" in
pvd_lists_every_frame | vtk_reads_time_series | vtk_reads_tensor_and_ids | ply_fields_visible)
    "$hearth" run "$here/lua/dumps_run.lua" --out "$tmp/out" --quiet || fail "dumps_run.lua failed"
    py=python3
    [ "$case_name" = pvd_lists_every_frame ] || py=$(vtk_python)
    "$py" "$here/vtk_check.py" "$case_name" "$tmp/out"
    exit $?
    ;;
run_vtu_flag_and_options)
    cat >"$tmp/plain.lua" <<'LUA'
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("elastic", { E = 1e4, density = 1000 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m, ppc = 4 }
s:run { until_t = 0.02, every = 0.01 }
s:run { until_t = 0.04, every = 0.01 }
LUA
    # --vtu DIR: frames from every s:run, one collection continued by the second run
    "$hearth" run "$tmp/plain.lua" --out "$tmp/o" --vtu pv --quiet || fail "--vtu run failed"
    n=$(ls "$tmp/o/pv"/frame_*.vtu | wc -l)
    m=$(grep -c "<DataSet " "$tmp/o/pv/frame.pvd")
    echo "--vtu pv: $n VTU files, $m in frame.pvd"
    [ "$n" = 5 ] && [ "$m" = 5 ] || fail "expected 5 frames (t = 0 .. 0.04; the second run does not repeat 0.02) in files and frame.pvd, got $n and $m"
    python3 - "$tmp/o/pv/frame.pvd" <<'PY' || fail "frame.pvd times"
import sys, xml.etree.ElementTree as ET
t = [float(d.get("timestep")) for d in ET.parse(sys.argv[1]).getroot().iter("DataSet")]
print("frame.pvd times", t)
sys.exit(0 if all(b > a for a, b in zip(t, t[1:])) and abs(t[-1] - 0.04) < 1e-12 else 1)
PY
    # a misspelt option fails with a suggestion; a path without the frame number is refused
    sed 's/every = 0.01 }$/every = 0.01, vtu = { path = "a_%04d.vtu", evrey = 0.02 } }/' "$tmp/plain.lua" >"$tmp/bad.lua"
    err=$("$hearth" run "$tmp/bad.lua" --out "$tmp/b" --quiet 2>&1) && fail "a misspelt vtu option ran"
    echo "$err" | grep -q "did you mean 'every'" || fail "no suggestion: $err"
    sed 's/every = 0.01 }$/every = 0.01, ply = { path = "a.ply" } }/' "$tmp/plain.lua" >"$tmp/bad2.lua"
    err=$("$hearth" run "$tmp/bad2.lua" --out "$tmp/b" --quiet 2>&1) && fail "a ply path without %d ran"
    echo "$err" | grep -q "frame number" || fail "unclear message: $err"
    # its own every: ply every 0.02 s over two runs of 0.02 s writes t = 0, 0.02, 0.04
    sed 's/every = 0.01 }$/every = 0.01, ply = { path = "p_%02d.ply", every = 0.02, color = "speed" } }/' "$tmp/plain.lua" >"$tmp/ply.lua"
    "$hearth" run "$tmp/ply.lua" --out "$tmp/p" --quiet || fail "ply run failed"
    n=$(ls "$tmp/p"/p_*.ply | wc -l)
    echo "ply every 0.02 s over two runs of 0.02 s: $n files"
    [ "$n" = 3 ] || fail "expected 3 PLY files (t = 0, 0.02, 0.04), got $n: $(ls "$tmp/p")"
    ;;
*) fail "unknown case $case_name" ;;
esac

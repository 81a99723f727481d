#!/usr/bin/env bash
# lua_test.sh CASE HEARTH: Lua scenes as a user runs them (hearth run / hearth repl).
# The scene files are in tests/lua/; every case runs in a fresh temp folder, so
# default outputs land in ./hearth-out/<scene>/.
here=$(cd "$(dirname "$0")" && pwd) # png_check.py lives here
set -u
case_name=$1
hearth=$2
case "$hearth" in /*) ;; */*) hearth=$PWD/$hearth ;; esac # the cases cd to a temp folder
scenes=$(cd "$(dirname "$0")/lua" && pwd)
tmp=$(mktemp -d)
bg_pid=
trap '[ -n "$bg_pid" ] && kill -9 "$bg_pid" 2>/dev/null; rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

# run SCENE [ARGS...]: hearth run --quiet on tests/lua/SCENE; stdout in out.txt,
# stderr in err.txt, exit status in $rc
run() {
    local scene=$1
    shift
    "$hearth" run "$scenes/$scene" --quiet "$@" >out.txt 2>err.txt
    rc=$?
}
# expect_rc N WHAT: the last run exited N
expect_rc() {
    [ "$rc" -eq "$1" ] || fail "$2: exit $rc, expected $1; stderr: $(cat err.txt) stdout: $(cat out.txt)"
}
# has FILE TEXT WHAT: FILE contains TEXT (fixed string)
has() {
    grep -qF -- "$2" "$1" || fail "$3: '$2' not in $1: $(cat "$1")"
}
# has_msg TEXT WHAT: the error message in err.txt (without its stack traceback) contains TEXT
has_msg() {
    sed '/^stack traceback:/,$d' err.txt >msg.txt
    grep -qF -- "$1" msg.txt || fail "$2: '$1' not in the message: $(cat msg.txt)"
}

# png_check FILE [W H]: see png_check.py
png_check() { python3 "$here/png_check.py" "$@"; }

# whole_files DIR: every .vtu / .png / .csv / .ply in DIR is complete.
whole_files() {
    python3 - "$1" <<'PY' || return 1
import os, re, struct, sys
d, bad, counts = sys.argv[1], [], {}
for name in sorted(os.listdir(d)):
    p = os.path.join(d, name)
    ext = os.path.splitext(name)[1]
    if ".tmp." in name or not os.path.isfile(p):
        continue
    counts[ext] = counts.get(ext, 0) + 1
    b = open(p, "rb").read()
    if ext == ".vtu":
        if not b.startswith(b"<?xml") or not b.endswith(b"</VTKFile>\n"):
            bad.append(f"{name}: VTU does not end with </VTKFile> and a newline ({len(b)} bytes)")
    elif ext == ".png":
        if b[:8] != b"\x89PNG\r\n\x1a\n" or b[-12:] != b"\x00\x00\x00\x00IEND\xaeB`\x82":
            bad.append(f"{name}: PNG without signature or final IEND ({len(b)} bytes)")
    elif ext == ".csv":
        lines = b.decode().split("\n")
        if not b.endswith(b"\n") or len(lines) < 3:
            bad.append(f"{name}: CSV does not end with a newline or has no rows")
        else:
            cols = lines[0].count(",")
            if any(l.count(",") != cols for l in lines[1:-1]):
                bad.append(f"{name}: CSV rows with a different column count")
    elif ext == ".ply":
        end = b.find(b"end_header\n")
        head = b[:end].decode(errors="replace")
        m = re.search(r"element vertex (\d+)", head)
        sizes = {"double": 8, "float": 4, "int": 4, "uint": 4, "uchar": 1, "char": 1, "short": 2, "ushort": 2}
        props = re.findall(r"property (\w+) \w+", head)
        if end < 0 or not m or "binary_little_endian" not in head:
            bad.append(f"{name}: PLY header incomplete")
        elif len(b) != end + 11 + int(m.group(1)) * sum(sizes[t] for t in props):
            bad.append(f"{name}: PLY is {len(b)} bytes; its header promises {end + 11 + int(m.group(1)) * sum(sizes[t] for t in props)}")
if bad:
    sys.exit("\n".join(bad))
print(" ".join(f"{k}:{v}" for k, v in sorted(counts.items())))
PY
}

case "$case_name" in
lua_error_unknown_key)
    run bad_key.lua
    expect_rc 1 "h.scene{dxx=...}"
    has err.txt "bad_key.lua:3:" "file and line of the bad call"
    has err.txt "unknown field 'dxx'" "the bad field"
    has err.txt "did you mean 'dx'" "the suggestion"
    ;;
lua_error_messages)
    # each bad call in its own scene: exit 1, the scene line, and the message
    check() { # scene line text...
        local scene=$1 line=$2
        shift 2
        run "$scene"
        expect_rc 1 "$scene"
        has err.txt "$scene:$line:" "$scene: file:line of the bad call"
        for t in "$@"; do has err.txt "$t" "$scene"; done
    }
    check err_material_key.lua 2 "material 'elastic'" "unknown parameter 'Ee'" "did you mean 'E'"
    check err_range.lua 2 "'nu' = 0.7" "[0, 0.499]" "Poisson's ratio"
    grep -qE "\[0, 0\.499\] (1\b|\(dimensionless\))" err.txt || fail "nu: no unit after the range: $(cat err.txt)"
    check err_range_unit.lua 2 "'density' = 1e+09" "[0.001, 100000] kg/m^3"
    check err_curve.lua 2 "h.curve: temperatures must increase" "point 2: 50 after 100"
    check err_add_nomat.lua 3 "s:add: material = h.material(...) is required"
    check err_plugin.lua 2 "plugin not found" "hearth_no_such_plugin_xyz.so" "search path" "HEARTH_PLUGIN_PATH"
    if [ -n "${HEARTH_PLUGIN_PATH:-}" ]; then has err.txt "$HEARTH_PLUGIN_PATH" "plugin folders listed"; fi
    # the scene's own folder is searched only with --trust (an untrusted scene may have put a plugin there)
    grep -qE "(path: |, )$scenes[,;]" err.txt && fail "without --trust the scene's folder is on the plugin path: $(cat err.txt)"
    run err_plugin.lua --trust
    expect_rc 1 "err_plugin.lua --trust"
    grep -qE "(path: |, )$scenes[,;]" err.txt || fail "--trust: the scene's folder is not on the plugin path: $(cat err.txt)"
    check err_not_live.lua 5 "field 'temperature' is not live" "to enable it" "temperature = 20"
    has out.txt "speed" "a live field probes before the error"
    check err_runtime.lua 3 "attempt to call a nil value (field 'missing_function')" "stack traceback" \
        "err_runtime.lua:5: in main chunk"
    ;;
lua_determinism)
    hashes=()
    for i in 1 2 3; do
        threads=1
        [ "$i" -eq 3 ] && threads=3 # results must not depend on the thread count
        run determinism.lua --threads "$threads" --out "o$i"
        expect_rc 0 "determinism run $i"
        h=$(sed -n 's/^hash \([0-9a-f]\{16\}\)$/\1/p' out.txt)
        [ -n "$h" ] || fail "run $i printed no hash: $(cat out.txt)"
        hashes+=("$h")
        [ -s "o$i/series.csv" ] || fail "run $i wrote no series.csv"
        [ "$(wc -l <"o$i/series.csv")" -eq 7 ] || fail "series.csv: expected a header and 6 rows: $(cat "o$i/series.csv")"
    done
    echo "hashes: ${hashes[*]}"
    [ "${hashes[0]}" = "${hashes[1]}" ] || fail "same seed, different hashes: ${hashes[0]} ${hashes[1]}"
    cmp -s o1/series.csv o2/series.csv || fail "same seed, different CSV: $(diff o1/series.csv o2/series.csv)"
    [ "${hashes[0]}" = "${hashes[2]}" ] || fail "--threads 3 changed the hash: ${hashes[0]} ${hashes[2]}"
    cmp -s o1/series.csv o3/series.csv || fail "--threads 3 changed the CSV"
    run determinism.lua --set seed=8 --out o4
    expect_rc 0 "seed 8"
    h4=$(sed -n 's/^hash \([0-9a-f]\{16\}\)$/\1/p' out.txt)
    echo "seed 8: $h4"
    [ -n "$h4" ] && [ "$h4" != "${hashes[0]}" ] || fail "a different seed gave the same hash $h4"
    # the first line after the header is the initial state: the jitter differs too
    cmp -s o1/series.csv o4/series.csv && fail "a different seed gave the same CSV"
    ;;
lua_set_overrides)
    run params.lua
    expect_rc 0 "defaults"
    has out.txt "height=0.3 type=float" "default height"
    has out.txt "label=a" "default label"
    has out.txt "filled_at_0.35=true" "the block sits at the default height"
    run params.lua --set height=0.5 --set label=b
    expect_rc 0 "--set height=0.5 --set label=b"
    has out.txt "height=0.5 type=float" "--set height"
    has out.txt "label=b" "--set label"
    has out.txt "filled_at_0.35=false" "the block moved with --set height"
    has out.txt "sizes=1/2 n=2" "a number-list default"
    run params.lua --set sizes=0.5,3,1e2
    expect_rc 0 "--set sizes=0.5,3,1e2"
    has out.txt "sizes=0.5/3/100.0 n=3" "--set a number list"
    run params.lua --set sizes=1,x
    expect_rc 2 "--set sizes=1,x"
    has err.txt "--set sizes=1,x: expected numbers separated by commas" "a bad number list"
    run params.lua --set nope=1
    expect_rc 2 "--set nope=1"
    has err.txt "no parameter 'nope'" "unknown parameter"
    has err.txt "valid names: height, label, sizes" "the valid names"
    run params.lua --set height=abc
    expect_rc 2 "--set height=abc"
    has err.txt "--set height=abc: expected a number" "non-number"
    run params.lua --set height
    expect_rc 2 "--set without ="
    has err.txt "--set needs name=value" "--set without ="
    run no_params.lua --set height=1
    expect_rc 2 "--set on a scene without h.params"
    has err.txt "declares no parameters" "no h.params"
    ;;
lua_sandbox)
    printf 'not really a shared object' >evil.so # a C module in the working folder
    echo keep >victim.txt
    refused() { # call what: exit 1, the call named, --trust mentioned
        local call=$1 what=$2
        shift 2
        run sandbox.lua --set "call=$call" "$@"
        expect_rc 1 "sandbox: $call"
        has_msg "$what" "sandbox: $call names the call"
        has_msg "--trust" "sandbox: $call mentions --trust"
    }
    refused execute "os.execute is not allowed"
    refused popen "io.popen is not allowed"
    refused loadlib "package.loadlib is not allowed" --set "target=$tmp/evil.so"
    refused open_out "io.open('$tmp/outside.txt', 'w')" --set "target=$tmp/outside.txt"
    has_msg "output folder" "io.open outside: the reason"
    [ -e outside.txt ] && fail "io.open outside the output folder created the file"
    refused open_out "io.open('/tmp/x', 'w')" --set "target=/tmp/x"
    refused open_out "io.open('hearth-out/sandbox/../../escape.txt', 'w')" --set "target=hearth-out/sandbox/../../escape.txt"
    [ -e escape.txt ] && fail "io.open escaped the output folder with .."
    refused remove "os.remove('$tmp/victim.txt')" --set "target=$tmp/victim.txt"
    [ -e victim.txt ] || fail "os.remove outside the output folder removed the file"
    refused rename "os.rename" --set "target=$tmp/victim.txt"
    [ -e victim.txt ] || fail "os.rename outside the output folder moved the file"
    # writing inside the output folder works
    run sandbox.lua --set call=open_in --set target=hearth-out/sandbox/inside.txt
    expect_rc 0 "io.open inside the output folder"
    has out.txt "open_in ok" "io.open inside"
    has hearth-out/sandbox/inside.txt "written from a scene" "the file written inside"
    # load() of bytecode is refused (text chunks only), and string.dump is not there to make any
    run sandbox.lua --set call=load_binary
    expect_rc 0 "load of a binary chunk"
    has out.txt "attempt to load a binary chunk" "load(bytecode) refused"
    refused dump "string.dump is not allowed"
    # require of a C module: native code must not load, and the message must say so
    run sandbox.lua --set call=require_c
    expect_rc 1 "require of a C module"
    grep -q "evil.so" err.txt && fail "require tried the native module ./evil.so: $(cat err.txt)"
    has_msg "require" "require of a C module names the call"
    has_msg "--trust" "require of a C module mentions --trust"
    # bytecode from a file (loadfile / dofile / require of a .lua) is refused like load()
    run sandbox.lua --set call=loadfile_binary --set target=hearth-out/sandbox/chunk.luac
    [ "$rc" -ne 0 ] && grep -q "binary chunk" err.txt ||
        fail "loadfile of a bytecode file ran in the sandbox (exit $rc): $(cat out.txt) $(cat err.txt)"
    # with --trust the sandbox is lifted
    run sandbox.lua --trust --set call=trust_execute --set "target=$tmp/marker"
    expect_rc 0 "--trust os.execute"
    has out.txt "execute	true" "os.execute result"
    [ -e marker ] || fail "--trust: os.execute did not run the command"
    run sandbox.lua --trust --set call=require_c
    has err.txt "evil.so" "--trust: require should reach the C searcher"
    ;;
lua_atomic_output)
    # a big scene writing every frame, killed with SIGKILL in the middle of it
    "$hearth" run "$scenes/atomic_big.lua" --quiet >big_out.txt 2>big_err.txt &
    bg_pid=$!
    out="hearth-out/atomic_big"
    for _ in $(seq 100); do # wait for the first frames (up to 10 s)
        [ -e "$out/series.csv" ] && [ -e "$out/frame_00001.vtu" ] && break
        kill -0 "$bg_pid" 2>/dev/null || fail "the scene ended early: $(cat big_err.txt)"
        sleep 0.1
    done
    sleep 1
    kill -0 "$bg_pid" 2>/dev/null || fail "the scene ended before the kill: $(cat big_err.txt)"
    kill -9 "$bg_pid"
    wait "$bg_pid" 2>/dev/null
    killed=$bg_pid
    bg_pid=
    grep -q "^particles " big_out.txt || fail "no particle count: $(cat big_out.txt)"
    n=$(sed -n 's/^particles //p' big_out.txt)
    [ "$n" -ge 15000 ] || fail "expected a large scene, got $n particles"
    nvtu=$(ls "$out"/frame_*.vtu 2>/dev/null | wc -l)
    [ "$nvtu" -ge 2 ] || fail "expected at least 2 VTU frames before the kill, found $nvtu"
    summary=$(whole_files "$out") || fail "a truncated file after kill -9"
    echo "after kill -9 ($n particles): $summary"
    tmps=$(ls -a "$out" | grep '\.tmp\.' || true)
    others=$(echo "$tmps" | grep -v "\.tmp\.$killed\$" | grep . || true)
    [ -z "$others" ] || fail "temp files not of the killed process: $others"
    echo "temp files left by the killed process (pid $killed): $(echo "$tmps" | grep -c . || true) $(echo $tmps)"
    [ "$(echo "$tmps" | grep -c .)" -le 1 ] || fail "more than one temp file left: $tmps"
    # a Lua error after some frames: exit 1, whole files only, no temp files
    run atomic_error.lua
    expect_rc 1 "a Lua error in on_frame"
    has err.txt "deliberate failure at frame 4" "the error"
    has err.txt "atomic_error.lua:11:" "the error's line"
    out="hearth-out/atomic_error"
    summary=$(whole_files "$out") || fail "a truncated file after a Lua error"
    echo "after a Lua error: $summary"
    [ "$summary" = ".csv:1 .ply:5 .png:5 .vtu:5" ] || fail "expected frames 0-4 of each kind and the CSV, got $summary"
    [ "$(wc -l <"$out/series.csv")" -eq 6 ] || fail "series.csv: expected a header and 5 rows"
    ls -a "$out" | grep -q '\.tmp\.' && fail "temp files left after a Lua error: $(ls -a "$out")"
    ;;
lua_checkpoint_roundtrip)
    run ck_save.lua --out ck
    expect_rc 0 "save run"
    [ -s ck/ck.bin ] || fail "ck.bin not in the output folder: $(ls -a . ck)"
    [ -e ck.bin ] && fail "ck.bin written to the working folder, not the output folder"
    a=$(sed -n 's/^A \([0-9a-f]\{16\}\) .*/\1/p' out.txt)
    at_save=$(sed -n 's/^at_save \([0-9a-f]\{16\}\) .*/\1/p' out.txt)
    run ck_load.lua --out ck
    expect_rc 0 "load run"
    b=$(sed -n 's/^B \([0-9a-f]\{16\}\) .*/\1/p' out.txt)
    at_load=$(sed -n 's/^at_load \([0-9a-f]\{16\}\) .*/\1/p' out.txt)
    echo "A = $a, B = $b (at save $at_save, at load $at_load)"
    [ -n "$a" ] && [ -n "$b" ] || fail "no hashes printed"
    [ "$at_save" = "$at_load" ] || fail "the loaded state differs from the saved one: $at_save vs $at_load"
    [ "$a" = "$b" ] || fail "50 steps after loading differ from 50 steps after saving: $a vs $b"
    # a damaged checkpoint is an error with the file named, not a crash
    head -c 2000 ck/ck.bin >ck/bad.bin
    sed 's/"ck.bin"/"bad.bin"/' "$scenes/ck_load.lua" >bad_load.lua
    "$hearth" run bad_load.lua --quiet --out ck >out.txt 2>err.txt
    rc=$?
    expect_rc 1 "loading a truncated checkpoint"
    has err.txt "bad.bin" "the damaged file named"
    ;;
lua_png_outputs)
    run png.lua
    expect_rc 0 "png scene"
    out="hearth-out/png"
    for f in frame_slice.png frame_particles_01.png sub/scene_particles.png scene_slice.png default.png; do
        has out.txt "$out/$f" "png path returned (relative to the output folder)"
    done
    r=$(png_check "$out/frame_particles_01.png" 120 90) || fail "frame:png particles"
    echo "frame particles: $r"
    r=$(png_check "$out/sub/scene_particles.png" 200 150) || fail "s:png particles 200x150"
    echo "scene particles: $r"
    # a slice is width pixels wide; its height follows the domain (1 x 0.5): less than the width
    for spec in "frame_slice.png 160" "scene_slice.png 256" "default.png 800"; do
        set -- $spec
        r=$(png_check "$out/$1") || fail "slice $1"
        echo "slice $1: $r"
        set -- $r "$2"
        [ "$1" -eq "$4" ] || fail "slice width $1, expected $4"
        [ "$2" -ge 64 ] && [ "$2" -lt "$1" ] || fail "slice height $2 for width $1 of a 2:1 domain"
    done
    has out.txt "bad_kind false png: kind = 'pixels'; valid: 'slice', 'particles'" "a bad kind"
    ;;
lua_events)
    run events.lua
    cat out.txt
    expect_rc 0 "events scene"
    grep -q "FAIL" out.txt && fail "events: $(grep FAIL out.txt)"
    [ "$(grep -c '^check .* ok' out.txt)" -ge 30 ] || fail "events: too few checks ran"
    for e in push cut move stop stepped; do has out.txt "check time_$e ok" "event $e time"; done
    has out.txt "events done" "the scene's end"
    ;;
lua_guard_exit)
    run guard.lua
    expect_rc 3 "cfl = 4 with guard stop"
    has err.txt "stability guard" "guard stop message"
    has err.txt "CFL" "guard stop: the diagnosis"
    grep -q "stack traceback" err.txt && fail "a guard stop is not a script error: no traceback expected"
    grep -q "^done" out.txt && fail "the scene went on after the guard stopped it"
    run guard.lua --set guard=rollback
    expect_rc 0 "cfl = 4 with guard rollback"
    r=$(sed -n 's/^done t=\([^ ]*\) rollbacks=\([0-9]*\) guard=\([a-z_]*\)$/\1 \2 \3/p' out.txt)
    echo "rollback: $r"
    set -- $r
    [ "${1:-}" = 2 ] || fail "rollback run did not reach t = 2: $(cat out.txt)"
    [ "${2:-0}" -gt 0 ] || fail "no rollbacks counted: $(cat out.txt)"
    [ "${3:-}" = rolled_back ] || fail "guard state: $(cat out.txt)"
    ;;
lua_repl_pipe)
    echo 'print(s:stats().t)' | "$hearth" repl "$scenes/tiny.lua" >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "repl print"
    grep -qE '^0(\.0*)?$' out.txt || fail "repl: s:stats().t should print 0: $(cat out.txt)"
    # a scene that keeps its scene in a local: `s` is still the scene it built
    echo 'print(s:stats().t)' | "$hearth" repl "$scenes/no_params.lua" >out.txt 2>err.txt
    rc=$?
    expect_rc 0 "repl with a local scene"
    grep -qE '^0\.001$' out.txt || fail "repl: s after a run should be at t = 0.001: $(cat out.txt)"
    printf '%s\n' 'function twice(n)' '  local m = n * 2' '  return m' 'end' 'print("twice", twice(21))' \
        '1 + 2' 'greeting' 'x = = 1' 'print("after the error")' '_ = s:step(3)' 's:stats().step' 'nil_fn()' \
        'print("still here")' | "$hearth" repl "$scenes/tiny.lua" >out.txt 2>err.txt
    rc=$?
    [ "$rc" -eq 1 ] || fail "repl with errors from a pipe: exit $rc, expected 1"
    [ "$(cat out.txt)" = "$(printf 'twice\t42\n3\nhello from tiny\nafter the error\n3\nstill here')" ] ||
        fail "repl output: $(cat out.txt)"
    has err.txt "stdin:1: unexpected symbol near '='" "the syntax error"
    has err.txt "attempt to call a nil value (global 'nil_fn')" "the runtime error"
    printf '1 + 1\nh.version\n' | "$hearth" repl >out.txt 2>err.txt || fail "repl without a scene"
    [ "$(head -1 out.txt)" = 2 ] || fail "repl without a scene: $(cat out.txt)"
    [ -n "$(sed -n 2p out.txt)" ] || fail "repl: h is not at hand without a scene"
    ;;
lua_run_help)
    for sub in run repl; do
        "$hearth" $sub --help >out.txt 2>err.txt || fail "$sub --help exited $?"
        has out.txt "--set" "$sub --help"
        has out.txt "--trust" "$sub --help"
        has out.txt "usage: hearth $sub" "$sub --help"
    done
    "$hearth" run >out.txt 2>err.txt
    rc=$?
    expect_rc 2 "hearth run without a scene"
    has err.txt "which scene?" "no scene"
    "$hearth" run nowhere/missing.lua >out.txt 2>err.txt
    rc=$?
    expect_rc 2 "a missing scene file"
    has err.txt "nowhere/missing.lua" "the missing path"
    "$hearth" repl nowhere/missing.lua >out.txt 2>err.txt </dev/null
    rc=$?
    expect_rc 2 "repl of a missing scene file"
    has err.txt "nowhere/missing.lua" "repl: the missing path"
    run tiny.lua --frobnicate
    expect_rc 2 "an unknown option"
    has err.txt "unknown option '--frobnicate'" "unknown option"
    run tiny.lua --until abc
    expect_rc 2 "--until abc"
    ;;
lua_helpers)
    out=$("$hearth" run "$scenes/helpers.lua" --quiet 2>&1) || fail "helpers.lua: $out"
    echo "$out" | grep -q "helpers ok" || fail "helpers.lua did not finish: $out"
    ;;
lua_library)
    out=$("$hearth" run "$scenes/library.lua" --quiet 2>&1) || fail "library.lua: $out"
    echo "$out" | grep -q "library ok" || fail "library.lua did not finish: $out"
    ;;
lua_dough_library)
    out=$("$hearth" run "$scenes/dough_library.lua" --quiet 2>&1) || fail "dough_library.lua: $out"
    echo "$out" | grep -q "dough library ok" || fail "dough_library.lua did not finish: $out"
    ;;
lua_sph_library)
    out=$("$hearth" run "$scenes/sph_library.lua" --quiet 2>&1) || fail "sph_library.lua: $out"
    echo "$out" | grep -q "sph library ok" || fail "sph_library.lua did not finish: $out"
    ;;
lua_blend_modes)
    out=$("$hearth" run "$scenes/blend_modes.lua" --quiet 2>&1) || fail "blend_modes.lua: $out"
    echo "$out" | grep -q "blend modes ok" || fail "blend_modes.lua did not finish: $out"
    ;;
*) fail "unknown case $case_name" ;;
esac
echo "ok"

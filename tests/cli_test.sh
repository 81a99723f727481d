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
# block_scene PLUGIN: a small 2D block of a (test) plugin's material, stepped 0.05 s
block_scene() {
    cat <<EOF
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("$1", { E = 1e4, density = 1000 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m, ppc = 4 }
s:run { until_t = 0.05 }
EOF
}

# movie_scene 'RUN OPTIONS': block_scene's block with 6 PNG frames of odd size (161x121) and the options given
movie_scene() {
    cat <<EOF
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("elastic", { E = 1e4, density = 1000 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m, ppc = 4 }
s:run { until_t = 0.05, every = 0.01, png = { field = "speed", path = "f_%04d.png", width = 161, height = 121 }, $1 }
EOF
}

# soft_block_scene: E = 0.01 Pa (in range) with dt_max 0.5 s: gravity moves the
# block 12 cells in one step onto a floor that zeroes its speed, so the guard
# stops it (cli_guard_soft_block_jump, and the run record's guard verdict).
soft_block_scene() {
    cat <<'EOF'
local h = require "hearth"
local s = h.scene { dim = 2, dx = 0.2, box = { { 0, 0 }, { 4, 4 } }, dt_max = 0.5 }
local m = h.material("elastic", { E = 0.01, nu = 0.3, density = 1000 })
s:add { shape = h.box({ 1.6, 1.0 }, { 2.4, 1.6 }), material = m, ppc = 4 }
s:collider { shape = h.plane({ 0, 0.6 }, { 0, 1 }), mode = "separate", friction = 0.3 }
s:run { until_t = 0.5 }
EOF
}

case "$case_name" in
cli_man_covers_subcommands)
    # every subcommand `hearth --help` lists has a SYNOPSIS line and an entry in docs/hearth.1, and so has --movie
    man="$HEARTH_SOURCE_ROOT/docs/hearth.1"
    subs=$("$hearth" --help | sed -n 's/^  hearth \([a-z][a-z]*\).*/\1/p' | sort -u)
    [ "$(echo "$subs" | wc -l)" -ge 10 ] || fail "too few subcommands read from --help: $subs"
    for c in $subs; do
        grep -q "^\.B hearth $c\b" "$man" || fail "docs/hearth.1 SYNOPSIS lacks 'hearth $c'"
        grep -q "^\.B $c\b" "$man" || fail "docs/hearth.1 COMMANDS lacks an entry for '$c'"
    done
    grep -q '^\.BI \\-\\-movie' "$man" || fail "docs/hearth.1 OPTIONS lacks --movie"
    echo "docs/hearth.1 covers:" $subs
    ;;
cli_scenes_lists_shipped)
    # #18 (helpers userview4, userfix11): no command listed the shipped scenes (`hearth list` was "unknown command";
    # README's prose was the list). Bars set before the first run: `hearth scenes` exits 0; its first line names the
    # source tree's scripts/scenes; every .lua file below it is listed once, by its path there, each with a summary
    # other than "(no header comment)"; the folders' headings baking/, sauces/, sph/ are printed; the last line gives
    # their number; `hearth list` exits 2 suggesting 'scenes'.
    root="$HEARTH_SOURCE_ROOT/scripts/scenes"
    out=$(HEARTH_SCENES_DIR= "$hearth" scenes) || fail "hearth scenes exited $?"
    echo "$out" | head -4
    echo "$out" | head -1 | grep -qF "the shipped scenes in $root (the source tree" ||
        fail "first line: $(echo "$out" | head -1)"
    want=$(cd "$root" && find . -name '*.lua' | sed 's|^\./||' | sort)
    got=$(echo "$out" | sed -n 's/^  \([^ ]*\.lua\)  *.*$/\1/p' | sort)
    [ "$want" = "$got" ] || fail "listed: $(echo $got); shipped: $(echo $want)"
    echo "$out" | grep -E '^  [^ ]*\.lua +\(no header comment\)' && fail "a scene listed without its summary"
    for d in baking sauces sph; do echo "$out" | grep -qx "$d/" || fail "no heading $d/"; done
    n=$(echo "$want" | wc -l)
    echo "$out" | tail -1 | grep -qx "$n scenes" || fail "last line: $(echo "$out" | tail -1); $n shipped"
    "$hearth" list 2>"$tmp/err"
    [ $? -eq 2 ] || fail "hearth list: expected exit 2"
    grep -q "did you mean 'scenes'" "$tmp/err" || fail "hearth list: $(cat "$tmp/err")"
    echo "$n scenes listed; hearth list: $(cat "$tmp/err")"
    ;;
cli_scenes_own_folder_and_refusals)
    # #18 (helper userfix11): hearth scenes on a folder HEARTH_SCENES_DIR names. Bars set before the first run: a
    # scene's summary is its header's first sentence, a '.' inside parentheses not ending it, over a wrapped line;
    # a file that opens with code says "(no header comment)"; a subfolder is its own heading; a missing folder is
    # exit 1 naming it; an argument is exit 2; --help names HEARTH_SCENES_DIR.
    mkdir -p "$tmp/own/sub"
    printf -- '-- A test scene (Ding et al. 2019, Fig. 2): a wrapped\n-- first line. Its second sentence.\n' \
        >"$tmp/own/a.lua"
    printf 'local x = 1\n' >>"$tmp/own/a.lua"
    printf 'local h = require "hearth"\n' >"$tmp/own/sub/b.lua"
    out=$(HEARTH_SCENES_DIR="$tmp/own" "$hearth" scenes) || fail "hearth scenes on its own folder exited $?"
    echo "$out"
    echo "$out" | head -1 | grep -qF "in $tmp/own (\$HEARTH_SCENES_DIR)" || fail "first line"
    echo "$out" | grep -qxE '  a\.lua +A test scene \(Ding et al\. 2019, Fig\. 2\): a wrapped first line\.' ||
        fail "a.lua's line"
    echo "$out" | grep -qxE '  sub/b\.lua +\(no header comment\)' || fail "sub/b.lua's line"
    echo "$out" | grep -qx "sub/" || fail "no heading sub/"
    echo "$out" | tail -1 | grep -qx "2 scenes" || fail "the count"
    HEARTH_SCENES_DIR="$tmp/none" "$hearth" scenes 2>"$tmp/err" >/dev/null
    [ $? -eq 1 ] || fail "a missing folder: expected exit 1"
    grep -qF "HEARTH_SCENES_DIR = $tmp/none is not a folder" "$tmp/err" || fail "a missing folder: $(cat "$tmp/err")"
    "$hearth" scenes extra 2>/dev/null
    [ $? -eq 2 ] || fail "hearth scenes extra: expected exit 2"
    "$hearth" scenes --help | grep -q HEARTH_SCENES_DIR || fail "scenes --help does not name HEARTH_SCENES_DIR"
    ;;
readme_run_synopsis_as_help)
    # #18 (helper userview4): README's `hearth run` synopsis left out --movie, which `hearth run --help`'s usage gives.
    # Bar set before the run: the [--options] of README's synopsis line and of run --help's usage lines are one set.
    opts() { grep -oE '\[--[a-z-]+' | sort -u | tr '\n' ' '; }
    readme=$(grep -E '^- `hearth run SCENE.lua \[' "$HEARTH_SOURCE_ROOT/README.md" | head -1 | opts)
    help=$("$hearth" run --help 2>&1 | sed -n '1,/^Runs /p' | opts)
    echo "README: $readme; run --help: $help"
    [ "$(echo $help | wc -w)" -ge 10 ] || fail "too few options read from run --help: $help"
    [ "$readme" = "$help" ] || fail "README's hearth run synopsis gives $readme, hearth run --help $help"
    ;;
plot_png_title_text)
    # #18 (helper userview4): a plot's title is also its PNG's Title text, as a frame's is (io_png.c; the frames had
    # it, plot.c's canvas did not set it). Bar set before the run: hearth rheometer's PNG has the Title it draws.
    "$hearth" rheometer sauce.mayo --out "$tmp/r" >"$tmp/out" 2>&1 || fail "rheometer exited $?: $(cat "$tmp/out")"
    t=$(python3 "$here/png_title.py" "$tmp/r/sauce.mayo.png") || fail "png_title.py: $t"
    echo "$t"
    [ "$t" = "$tmp/r/sauce.mayo.png: flow curve: sauce.mayo, Mayonnaise (My)" ] || fail "the plot's Title text: $t"
    ;;
help_demo_options_as_demo_help)
    # #18 (helper userview4): `hearth --help`'s demo line left out --movie, which README ("hearth demo [--movie
    # demo.mp4]") and `hearth demo --help` give. Bar set before the run: the --options of the two lines are the same set.
    opts() { grep -oE '\[--[a-z-]+' | sort -u | tr '\n' ' '; }
    top=$("$hearth" --help 2>&1 | grep '^  hearth demo ' | opts)
    own=$("$hearth" demo --help 2>&1 | grep '^usage: hearth \[demo\]' | opts)
    echo "hearth --help: $top; hearth demo --help: $own"
    [ "$(echo $own | wc -w)" -ge 5 ] || fail "too few options read from hearth demo --help: $own"
    [ "$top" = "$own" ] || fail "hearth --help's demo line gives $top, hearth demo --help $own"
    ;;
run_help_exit_statuses_as_man)
    # #18 (helper userview4): `hearth run --help` gave the exit statuses 0, 1, 2, 3, 130, 143 and left out 4 (a plugin
    # crashed), which README and docs/hearth.1's EXIT STATUS give; a user scripting around hearth reads --help.
    # Bar set before the run: the numbers --help's "Exit status:" sentence gives equal those of the man page's.
    man="$HEARTH_SOURCE_ROOT/docs/hearth.1"
    "$hearth" run --help >"$tmp/help" 2>&1 || fail "run --help exited $?"
    statuses() { tr '\n' ' ' | sed 's/\. .*//' | grep -oE '(^|[ :;,]) ?[0-9]+ [a-zA-Z]' | grep -oE '[0-9]+' | sort -n | tr '\n' ' '; }
    from_help=$(sed -n '/^Exit status:/,$p' "$tmp/help" | statuses)
    from_man=$(sed -n '/^\.SH EXIT STATUS/,/^\.PP/p' "$man" | sed 1d | statuses)
    echo "run --help: $from_help; docs/hearth.1: $from_man"
    [ -n "$from_man" ] && [ "$(echo $from_man | wc -w)" -ge 6 ] || fail "too few statuses read from docs/hearth.1: $from_man"
    [ "$from_help" = "$from_man" ] || fail "run --help gives exit statuses $from_help, docs/hearth.1 $from_man"
    ;;
movie_written_with_ffmpeg)
    # s:run{movie = ...}: the run's PNG frames (odd sizes: padded to even for yuv420p) become an H.264 movie
    if ! command -v ffmpeg >/dev/null || ! command -v ffprobe >/dev/null; then
        echo "skip: ffmpeg/ffprobe not installed (Debian package ffmpeg)"; exit 77
    fi
    movie_scene 'movie = { path = "clip/bake.mp4", fps = 5 }' >"$tmp/m.lua"
    "$hearth" run "$tmp/m.lua" --out "$tmp/o" --quiet 2>"$tmp/err" || fail "movie run failed: $(cat "$tmp/err")"
    [ -f "$tmp/o/clip/bake.mp4" ] || fail "no movie: $(ls -R "$tmp/o")"
    ls -a "$tmp/o/clip" | grep -q tmp && fail "a temp file was left: $(ls -a "$tmp/o/clip")"
    n_png=$(ls "$tmp/o"/f_*.png | wc -l)
    probe=$(ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,width,height,codec_name,pix_fmt \
        -of default=nw=1 "$tmp/o/clip/bake.mp4") || fail "ffprobe cannot read the movie"
    echo "$n_png PNG frames; movie: $(echo $probe)"
    echo "$probe" | grep -qx "nb_read_frames=$n_png" || fail "movie frames != $n_png PNG frames: $probe"
    [ "$n_png" = 6 ] || fail "expected 6 frames (t = 0 .. 0.05 every 0.01), got $n_png"
    echo "$probe" | grep -qx "width=162" && echo "$probe" | grep -qx "height=122" || fail "size not padded to 162x122: $probe"
    echo "$probe" | grep -qx "codec_name=h264" && echo "$probe" | grep -qx "pix_fmt=yuv420p" || fail "codec: $probe"
    # --movie on the command line: the same, from a scene that names no movie
    movie_scene '' >"$tmp/p.lua"
    "$hearth" run "$tmp/p.lua" --out "$tmp/o2" --movie run.mp4 --quiet 2>"$tmp/err" || fail "--movie run failed: $(cat "$tmp/err")"
    ffprobe -v error -count_frames -show_entries stream=nb_read_frames -of default=nw=1 "$tmp/o2/run.mp4" | grep -qx "nb_read_frames=6" ||
        fail "--movie: not 6 frames"
    ;;
movie_without_ffmpeg_says_so)
    # no ffmpeg on PATH: the run still succeeds, says why there is no movie, and the frames stay
    movie_scene 'movie = "bake.mp4"' >"$tmp/m.lua"
    mkdir "$tmp/empty_bin"
    PATH="$tmp/empty_bin" "$hearth" run "$tmp/m.lua" --out "$tmp/o" --quiet 2>"$tmp/err"; rc=$?
    [ $rc -eq 0 ] || fail "exit $rc without ffmpeg, expected 0: $(cat "$tmp/err")"
    grep -qF "hearth: movie bake.mp4 not written: the ffmpeg program is not installed (Debian package ffmpeg); the frames are in $tmp/o" "$tmp/err" ||
        fail "message: $(cat "$tmp/err")"
    n=$(ls "$tmp/o"/f_*.png | wc -l)
    echo "without ffmpeg: exit $rc, $n PNG frames, message: $(cat "$tmp/err")"
    [ "$n" = 6 ] || fail "expected the 6 PNG frames, got $n"
    [ -e "$tmp/o/bake.mp4" ] && fail "a movie appeared without ffmpeg"
    ls -a "$tmp/o" | grep -q '\.tmp' && fail "a temp file was left: $(ls -a "$tmp/o")"
    ;;
movie_needs_png_output)
    # a movie is made of the PNG frames: a run without them is refused before it starts, naming the option
    block_scene elastic | sed 's/s:run { until_t = 0.05 }/s:run { until_t = 0.05, movie = "bake.mp4" }/' >"$tmp/m.lua"
    "$hearth" run "$tmp/m.lua" --out "$tmp/o" --quiet 2>"$tmp/err"; rc=$?
    [ $rc -eq 1 ] || fail "exit $rc, expected 1 (scene error): $(cat "$tmp/err")"
    grep -qF 's:run: movie = "bake.mp4" needs the run'"'"'s PNG frames: add png = {' "$tmp/err" || fail "message: $(cat "$tmp/err")"
    # the same from --movie, naming the flag
    block_scene elastic | sed 's/s:run { until_t = 0.05 }/s:run { until_t = 0.05, every = 0.01 }/' >"$tmp/p.lua"
    "$hearth" run "$tmp/p.lua" --out "$tmp/o" --movie x.mp4 --quiet 2>"$tmp/err"; rc=$?
    [ $rc -eq 1 ] || fail "--movie without png: exit $rc, expected 1"
    grep -qF -- '--movie = "x.mp4" needs the run'"'"'s PNG frames' "$tmp/err" || fail "--movie message: $(cat "$tmp/err")"
    # frames that overwrite one file cannot make a movie
    movie_scene 'movie = "b.mp4"' | sed 's/f_%04d.png/same.png/' >"$tmp/q.lua"
    "$hearth" run "$tmp/q.lua" --out "$tmp/o" --quiet 2>"$tmp/err"; rc=$?
    [ $rc -eq 1 ] && grep -qF 'must number its frames with one %d or %04d' "$tmp/err" || fail "unnumbered frames: exit $rc: $(cat "$tmp/err")"
    echo "refused: $(head -1 "$tmp/err")"
    # a movie path without an extension: ffmpeg could not pick a container
    movie_scene 'movie = { path = "clip", fps = 5 }' >"$tmp/r.lua"
    "$hearth" run "$tmp/r.lua" --out "$tmp/o" --quiet 2>"$tmp/err"; rc=$?
    [ $rc -eq 1 ] && grep -qF 'movie.path = "clip" needs an extension' "$tmp/err" || fail "no extension: exit $rc: $(cat "$tmp/err")"
    ;;
cli_did_you_mean_command)
    "$hearth" rn x.lua 2>"$tmp/e"; rc=$?
    [ $rc -eq 2 ] || fail "hearth rn: exit $rc, expected 2"
    grep -qF "hearth: unknown command 'rn'; did you mean 'run'?" "$tmp/e" || fail "message: $(cat "$tmp/e")"
    "$hearth" rheomter 2>"$tmp/e"; grep -qF "did you mean 'rheometer'?" "$tmp/e" || fail "rheomter: $(cat "$tmp/e")"
    # nothing near: no guess, the usage instead
    "$hearth" frobnicate 2>"$tmp/e"; [ $? -eq 2 ] || fail "frobnicate: exit"
    grep -q "did you mean" "$tmp/e" && fail "a far word got a guess: $(cat "$tmp/e")"
    grep -q "usage:" "$tmp/e" || fail "no usage after an unknown command"
    ;;
cli_run_did_you_mean_flag)
    block_scene elastic >"$tmp/s.lua"
    "$hearth" run "$tmp/s.lua" --frmes 3 2>"$tmp/e"; rc=$?
    [ $rc -eq 2 ] || fail "--frmes: exit $rc, expected 2"
    grep -qF "hearth run: unknown option '--frmes'; did you mean '--frames'?" "$tmp/e" || fail "message: $(cat "$tmp/e")"
    "$hearth" run "$tmp/s.lua" --moive a.mp4 2>"$tmp/e"; grep -qF "did you mean '--movie'?" "$tmp/e" || fail "--moive: $(cat "$tmp/e")"
    "$hearth" run "$tmp/s.lua" --zzzzzzzz 2>"$tmp/e"; [ $? -eq 2 ] || fail "--zzzzzzzz exit"
    grep -q "did you mean" "$tmp/e" && fail "a far flag got a guess: $(cat "$tmp/e")"
    grep -qF "unknown option '--zzzzzzzz'" "$tmp/e" || fail "--zzzzzzzz: $(cat "$tmp/e")"
    ;;
cli_help)
    "$hearth" --help | grep -q "hearth plugin check" || fail "--help lacks the subcommands"
    "$hearth" --version | grep -q "material ABI" || fail "--version"
    for sub in demo bench plugins; do "$hearth" $sub --help >/dev/null || fail "$sub --help"; done
    ;;
cli_lua_md_example_runs)
    # the first example of docs/lua.md runs as printed and writes its frames
    awk '/^```lua/{f=1;next} /^```/{if(f)exit} f' "$HEARTH_SOURCE_ROOT/docs/lua.md" >"$tmp/example.lua"
    [ -s "$tmp/example.lua" ] || fail "docs/lua.md has no lua example"
    (cd "$tmp" && "$hearth" run example.lua --quiet --until 0.1) || fail "docs/lua.md's example failed"
    ls "$tmp"/hearth-out/example/frames/speed_0000.png >/dev/null 2>&1 || fail "the example wrote no frames: $(ls -R "$tmp/hearth-out")"
    ;;
cli_lua_md_png_example_runs)
    # the Pictures example of docs/lua.md runs as printed: its frames, and the slice with the range it was given
    awk '/^## Pictures/{p=1} p&&/^```lua/{f=1;next} f&&/^```/{exit} f' "$HEARTH_SOURCE_ROOT/docs/lua.md" >"$tmp/pictures.lua"
    [ -s "$tmp/pictures.lua" ] || fail "docs/lua.md has no Pictures example"
    (cd "$tmp" && "$hearth" run pictures.lua --quiet >out.txt) || fail "docs/lua.md's Pictures example failed"
    cat "$tmp/out.txt"
    grep -q "heat_slice.png	20.0	200.0	50.0 100.0 150.0 200.0" "$tmp/out.txt" || fail "the example's slice: $(cat "$tmp/out.txt")"
    n=$(ls "$tmp"/hearth-out/pictures/heat_*.png 2>/dev/null | wc -l)
    [ "$n" -eq 7 ] || fail "expected 6 frames and the slice, got $n: $(ls -R "$tmp/hearth-out")"
    for f in "$tmp"/hearth-out/pictures/heat_*.png; do png_ok "$f" || fail "$f does not decode"; done
    ;;
cli_fit_plot_drawn)
    # hearth fit draws its data (blue dots) and the fitted curve (a red line) on the one plotting module
    printf 'shear_rate,stress\n' >"$tmp/hb.csv"
    for r in 1 2 5 10 20 50 100 200; do
        python3 -c "print('$r,%.6g' % (50 + 10 * $r ** 0.5))" >>"$tmp/hb.csv"
    done
    "$hearth" fit "$tmp/hb.csv" --out "$tmp/fit" >"$tmp/fit.txt" || fail "hearth fit failed: $(cat "$tmp/fit.txt")"
    grep -q "h          0.49999" "$tmp/fit.txt" || fail "the fit missed h = 0.5: $(cat "$tmp/fit.txt")"
    r=$(python3 "$here/png_check.py" "$tmp/fit/hb_fit.png" 760 520 --count 31,119,180 --count 214,39,40) ||
        fail "the fit's PNG: $r"
    echo "$r"
    dots=$(echo "$r" | sed -n 's/^31,119,180 //p') line=$(echo "$r" | sed -n 's/^214,39,40 //p')
    [ "$dots" -ge 8 ] || fail "data dots: $dots blue pixels for 8 points"
    [ "$line" -ge 200 ] || fail "fitted curve: $line red pixels"
    ;;
cli_help_scene)
    # every setting of the schema is listed with its unit, default and range; --help points there
    out=$("$hearth" help scene) || fail "hearth help scene failed"
    "$hearth" doc lua | sed -n 's/^| `\([^`]*\)`.*/\1/p' >"$tmp/names"
    [ "$(wc -l <"$tmp/names")" -gt 40 ] || fail "hearth doc lua lists too few settings: $(cat "$tmp/names")"
    while read -r name; do
        echo "$out" | grep -q "^  $name " || fail "hearth help scene lacks $name"
    done <"$tmp/names"
    echo "$out" | grep -qF "oven.beta          default 10 W/(m^2 K); valid [0, inf) W/(m^2 K)" || fail "oven.beta line: $out"
    "$hearth" --help | grep -q "hearth help scene" || fail "--help does not point to hearth help scene"
    "$hearth" help bogus 2>/dev/null
    [ $? -eq 2 ] || fail "hearth help bogus: expected exit 2"
    ;;
settings_docs_current)
    # the man page's and docs/lua.md's settings sections are what the schema prints now
    "$here/../scripts/settings_docs" "$hearth" --check || fail "docs out of date with the settings schema (diff above)"
    ;;
cli_rheometer_mpm)
    # the MPM shear-cell mode as a user runs it: --json, the CSV with the measured rate, a bad mode named
    out=$(cd "$tmp" && "$hearth" rheometer sauce.mayo --mode mpm --rates 10:10:1 --json) || fail "rheometer --mode mpm exited $?"
    echo "$out" | grep -qE '^\{"shear_rate":\[10\],"stress":\[1[45][0-9]\.[0-9]+\]\}$' || fail "mpm json: $out"
    head -1 "$tmp"/hearth-out/rheometer/sauce.mayo.csv | grep -qx "shear_rate_1_per_s,stress_Pa,hb_stress_Pa,measured_rate_1_per_s" ||
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
    [ "$(grep -c PASS "$tmp/ok.txt")" -eq 6 ] || fail "expected 6 PASS lines (elastic has stress_block: the batched check too)"
    grep -q "^batched *PASS" "$tmp/ok.txt" || fail "elastic: the batched check should pass"
    "$hearth" plugin check "$HEARTH_TEST_PLUGIN_DIR/hearth_asym.so" >"$tmp/bad.txt" && fail "asym should fail"
    grep -q "symmetric *FAIL" "$tmp/bad.txt" || fail "asym: symmetric check should fail"
    "$hearth" plugin check /nonexistent/hearth_x.so 2>"$tmp/err.txt"; [ $? -eq 1 ] || fail "missing file exit"
    grep -q "not found" "$tmp/err.txt" || fail "missing file message: $(cat "$tmp/err.txt")"
    ;;
cli_run_writes_log)
    # hearth run leaves run.log and run.json beside its outputs: "running" while
    # it runs (the scene reads it), then the command line, --set values,
    # plugins, threads, timings and the status; a failed run says why
    cat >"$tmp/log.lua" <<EOF
local h = require "hearth"
local P = h.params { E = 1e4 }
local f = assert(io.open("$tmp/o/run.json"))
local during = f:read("a")
f:close()
assert(during:find('"status_text": "running"', 1, true), "run.json during the run: " .. during)
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("elastic", { E = P.E, density = 1000 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m, ppc = 4 }
s:run { until_t = 0.02 }
if P.E > 5e4 then error("E too high for this test") end
EOF
    "$hearth" run "$tmp/log.lua" --out "$tmp/o" --quiet --threads 2 --set E=2e4 --trust || fail "the run failed"
    cat "$tmp/o/run.log"
    for want in "command: hearth run $tmp/log.lua --out $tmp/o --quiet --threads 2 --set E=2e4 --trust" "set: E=2e4" \
        "threads: 2" "plugin: elastic abi 1 " "status: 0 (done)" "steps: " "wall: "; do
        grep -qF "$want" "$tmp/o/run.log" || fail "run.log lacks '$want'"
    done
    python3 - "$tmp/o/run.json" <<'PY' || fail "run.json"
import json, sys
r = json.load(open(sys.argv[1]))
assert r["status"] == 0 and r["status_text"] == "done", r
assert r["sets"] == {"E": "2e4"} and r["threads"] == 2, r
assert [p["name"] for p in r["plugins"]] == ["elastic"] and r["plugins"][0]["abi"] >= 1, r
assert r["steps"] > 0 and r["wall_s"] > 0 and r["steps_per_s"] > 0 and r["particles"] > 0, r
assert abs(r["sim_time_s"] - 0.02) < 1e-12, r
print(f"run.json: {r['steps']} steps in {r['wall_s']:.3f} s ({r['steps_per_s']:.0f} steps/s)")
PY
    # a scene error: status 1 and the message, in both
    "$hearth" run "$tmp/log.lua" --out "$tmp/o" --quiet --set E=9e4 --trust 2>/dev/null && fail "the failing run passed"
    grep -q "status: 1 (scene error)" "$tmp/o/run.log" && grep -q "message: .*E too high" "$tmp/o/run.log" ||
        fail "run.log of a failed run: $(cat "$tmp/o/run.log")"
    python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert r["status"]==1 and "E too high" in r["message"], r' \
        "$tmp/o/run.json" || fail "run.json of a failed run"
    ls "$tmp/o" | grep -q '\.tmp\.' && fail "a temp file was left: $(ls "$tmp/o")"
    ;;
run_record_lists_outputs)
    # run.json lists every file the run wrote under its outputs (PNG frames, CSV,
    # VTU and .pvd, PLY, the movie, a checkpoint) with its size, and nothing older
    # (a file left by an earlier run); with version, git revision, peak memory and
    # the guard's verdict. A guard-stopped run records "stopped" and the diagnosis.
    cat >"$tmp/all.lua" <<'EOF'
local h = require "hearth"
local P = h.params { E = 1e4 }
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("elastic", { E = P.E, density = 1000 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m, ppc = 4 }
s:run { until_t = 0.02, every = 0.01, png = { path = "f_%04d.png", width = 160, height = 120 }, csv = "series.csv",
        vtu = { path = "vtu/p_%04d.vtu" }, ply = true, movie = "clip.mp4" }
s:save("end.h5")
EOF
    mkdir -p "$tmp/o" && echo old >"$tmp/o/stale.txt" && touch -d '1 hour ago' "$tmp/o/stale.txt"
    "$hearth" run "$tmp/all.lua" --out "$tmp/o" --quiet --set E=2e4 2>"$tmp/err" || fail "the run failed: $(cat "$tmp/err")"
    has_ffmpeg=0; command -v ffmpeg >/dev/null && has_ffmpeg=1
    python3 - "$tmp/o" $has_ffmpeg <<'PY' || fail "run.json: $(cat "$tmp/o/run.json")"
import json, os, sys
out, has_ffmpeg = sys.argv[1], sys.argv[2] == "1"
r = json.load(open(os.path.join(out, "run.json")))
listed = {f["path"]: f["bytes"] for f in r["files"]}
on_disk = {}
for d, _, names in os.walk(out):
    for n in names:
        p = os.path.relpath(os.path.join(d, n), out)
        if p not in ("run.json", "run.log", "stale.txt"):
            on_disk[p] = os.path.getsize(os.path.join(out, p))
want = {"f_0000.png", "f_0001.png", "f_0002.png", "series.csv", "vtu/p.pvd", "vtu/p_0000.vtu", "vtu/p_0002.vtu",
        "particles_0000.ply", "particles_0002.ply", "end.h5"} | ({"clip.mp4"} if has_ffmpeg else set())
assert want <= set(listed), f"missing from run.json: {sorted(want - set(listed))}"
assert listed == on_disk, f"run.json lists {sorted(listed.items())}, the folder holds {sorted(on_disk.items())}"
assert "stale.txt" not in listed, "a file older than the run is listed"
assert ("clip.mp4" in listed) == has_ffmpeg, "the movie is listed without ffmpeg, or missing with it"
assert r["command"] == "run" and r["sets"] == {"E": "2e4"}, r
assert r["hearth_version"] and isinstance(r["git_revision"], str) and r["git_revision"], r
assert 1 < r["peak_memory_mb"] < 4096, r["peak_memory_mb"]
assert r["guard"] == {"verdict": "ok", "rollbacks": 0, "diagnosis": ""}, r["guard"]
assert r["steps"] > 0 and r["status"] == 0, r
print(f"run.json lists {len(listed)} files ({'with' if has_ffmpeg else 'without'} ffmpeg), revision {r['git_revision']}, "
      f"peak {r['peak_memory_mb']:.1f} MB")
PY
    grep -q "^  f_0001.png ([0-9]* bytes)$" "$tmp/o/run.log" || fail "run.log does not list the frames: $(cat "$tmp/o/run.log")"
    grep -q "^peak memory: [0-9.]* MB$" "$tmp/o/run.log" || fail "run.log has no peak memory"
    grep -q "^hearth [0-9.]* (revision [^)]*) run record$" "$tmp/o/run.log" || fail "run.log's first line: $(head -1 "$tmp/o/run.log")"
    # the guard's verdict of a run it stopped (the soft block of cli_guard_soft_block_jump)
    soft_block_scene >"$tmp/g.lua"
    "$hearth" run "$tmp/g.lua" --out "$tmp/g" --quiet 2>/dev/null; rc=$?
    [ $rc -eq 3 ] || fail "the guard run exited $rc, expected 3"
    python3 -c 'import json,sys; g=json.load(open(sys.argv[1]))["guard"]; assert g["verdict"]=="stopped" and "CFL violated" in g["diagnosis"], g' \
        "$tmp/g/run.json" || fail "guard verdict: $(cat "$tmp/g/run.json")"
    grep -q "^guard: stopped, 0 rollbacks: .*CFL violated" "$tmp/g/run.log" || fail "run.log guard line: $(cat "$tmp/g/run.log")"
    ;;
run_record_for_demo)
    # hearth demo writes the same record: built-in scene (null), frames listed, steps, peak memory, guard
    "$hearth" demo --out "$tmp/d" --until 0.02 --frames 2 --threads 1 --quiet || fail "demo exited $?"
    python3 - "$tmp/d" <<'PY' || fail "demo run.json: $(cat "$tmp/d/run.json")"
import json, os, sys
r = json.load(open(os.path.join(sys.argv[1], "run.json")))
assert r["command"] == "demo" and r["scene"] is None and r["argv"][:2] == ["hearth", "demo"], r
assert [f["path"] for f in r["files"]] == ["frame_0000.png", "frame_0001.png", "frame_0002.png"], r["files"]
assert sorted(p["name"] for p in r["plugins"]) == ["elastic", "newtonian"], r["plugins"]
assert r["threads"] == 1 and r["steps"] > 0 and abs(r["sim_time_s"] - 0.02) < 1e-9 and r["particles"] > 1000, r
assert r["peak_memory_mb"] > 1 and r["guard"]["verdict"] == "ok" and r["status"] == 0 and r["git_revision"], r
print(f"demo run.json: {r['steps']} steps, {len(r['files'])} files, peak {r['peak_memory_mb']:.1f} MB")
PY
    grep -q "^hearth [0-9.]* (revision .*) demo record$" "$tmp/d/run.log" || fail "demo run.log: $(head -1 "$tmp/d/run.log")"
    ;;
demo_movie_written_with_ffmpeg)
    # hearth demo --movie: its frames become an H.264 movie (as hearth run --movie), listed in run.json
    if ! command -v ffmpeg >/dev/null || ! command -v ffprobe >/dev/null; then
        echo "skip: ffmpeg/ffprobe not installed (Debian package ffmpeg)"; exit 77
    fi
    "$hearth" demo --out "$tmp/d" --until 0.02 --frames 3 --movie clip/demo.mp4 --quiet 2>"$tmp/err" || fail "demo --movie: $(cat "$tmp/err")"
    ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames,codec_name -of default=nw=1 \
        "$tmp/d/clip/demo.mp4" >"$tmp/probe" || fail "ffprobe cannot read the movie"
    grep -qx "nb_read_frames=4" "$tmp/probe" && grep -qx "codec_name=h264" "$tmp/probe" || fail "movie: $(cat "$tmp/probe")"
    python3 -c 'import json,sys; r=json.load(open(sys.argv[1])); assert "clip/demo.mp4" in [f["path"] for f in r["files"]], r["files"]' \
        "$tmp/d/run.json" || fail "the movie is not in run.json"
    [ "$(ls "$tmp"/d/frame_*.png | wc -l)" -eq 4 ] || fail "the frames did not stay"
    "$hearth" demo --out "$tmp/d" --movie noext --quiet 2>"$tmp/err"; rc=$?
    [ $rc -eq 2 ] && grep -q "needs an extension naming the container" "$tmp/err" || fail "--movie noext: exit $rc: $(cat "$tmp/err")"
    ;;
demo_movie_without_ffmpeg_says_so)
    # no ffmpeg on PATH: the demo succeeds, says why there is no movie, and the frames stay
    mkdir "$tmp/empty_bin"
    PATH="$tmp/empty_bin" "$hearth" demo --out "$tmp/d" --until 0.02 --frames 2 --movie demo.mp4 --quiet 2>"$tmp/err"; rc=$?
    [ $rc -eq 0 ] || fail "exit $rc without ffmpeg, expected 0: $(cat "$tmp/err")"
    grep -qF "hearth demo: movie demo.mp4 not written: the ffmpeg program is not installed (Debian package ffmpeg); the frames are in $tmp/d" "$tmp/err" ||
        fail "message: $(cat "$tmp/err")"
    [ "$(ls "$tmp"/d/frame_*.png | wc -l)" -eq 3 ] || fail "expected the 3 PNG frames: $(ls "$tmp/d")"
    [ -e "$tmp/d/demo.mp4" ] && fail "a movie appeared without ffmpeg"
    ls -a "$tmp/d" | grep -q '\.tmp' && fail "a temp file was left: $(ls -a "$tmp/d")"
    echo "without ffmpeg: $(cat "$tmp/err")"
    ;;
cli_bad_usage)
    "$hearth" frobnicate 2>/dev/null; [ $? -eq 2 ] || fail "unknown command should exit 2"
    "$hearth" bench --cells x 2>"$tmp/e"; [ $? -eq 2 ] || fail "bad number should exit 2"
    grep -q "\-\-cells needs a whole number" "$tmp/e" || fail "message: $(cat "$tmp/e")"
    ;;
cli_bench_size_limits)
    # --cells is no longer held at 1024: past it the bench runs (2D, 1030 cells: 1.5M particles) ...
    out=$("$hearth" bench --dim 2 --cells 1030 --steps 1 2>"$tmp/e") || fail "1030 cells in 2D exited $?: $(cat "$tmp/e")"
    echo "$out" | grep -q '"cells": 1030' || fail "bench JSON: $out"
    # ... a size whose particles a scene cannot hold is refused before anything is made, naming the largest ...
    "$hearth" bench --dim 3 --cells 900 --steps 1 2>"$tmp/e"; [ $? -eq 2 ] || fail "900 cells in 3D should exit 2"
    grep -qF "hearth bench: --cells 900 in 3D gives about 1.26e+09 particles; a scene holds at most 1073741823, so --cells is at most 851 in 3D" "$tmp/e" ||
        fail "message: $(cat "$tmp/e")"
    # ... and one this machine's memory cannot hold is the library's refusal at seeding, with its numbers
    mem=$(awk '/^MemTotal/ {print $2 * 1024}' /proc/meminfo)
    if python3 -c "import sys; sys.exit(0 if $mem < 1.5e11 else 1)"; then
        "$hearth" bench --dim 2 --cells 27305 --steps 1 2>"$tmp/e"; [ $? -eq 1 ] || fail "27305 cells in 2D should exit 1"
        grep -qE "hearth bench: seed: 1.07.*e\+09 particles would need about .* GB \(.* bytes each\)(, beside .* already held \(grid tables, other scenes\))?; this machine has .* GB of memory" "$tmp/e" ||
            fail "message: $(cat "$tmp/e")"
    fi
    cat "$tmp/e"
    ;;
cli_check_segv_stress)
    # a plugin that segfaults in stress: the battery runs in a child, the parent names plugin and callback
    out=$("$hearth" plugin check "$HEARTH_TEST_PLUGIN_DIR/hearth_segv_stress.so" 2>&1); rc=$?
    [ $rc -ne 0 ] || fail "a crashing plugin passed: $out"
    echo "$out" | grep -q "^crash .*FAIL  plugin 'segv_stress' (.*hearth_segv_stress.so) crashed with SIGSEGV" ||
        fail "crash not named: $out"
    echo "$out" | grep -q "in its stress callback during check 'rest'" || fail "callback not named: $out"
    echo "$out" | grep -q "FAILED$" || fail "no FAILED verdict: $out"
    ;;
cli_check_abort_init)
    # abort() in init happens in the loader's wave-speed corners, before the battery
    out=$("$hearth" plugin check "$HEARTH_TEST_PLUGIN_DIR/hearth_abort_init.so" 2>&1) && fail "abort passed: $out"
    echo "$out" | grep -q "plugin 'abort_init' .* crashed with SIGABRT (abort) in its init callback" ||
        fail "abort not named: $out"
    ;;
cli_check_hang_stress)
    # a plugin that never returns: --timeout stops it and the child says where it was stuck
    start=$(date +%s)
    out=$("$hearth" plugin check --timeout 1 "$HEARTH_TEST_PLUGIN_DIR/hearth_hang_stress.so" 2>&1) && fail "hang passed: $out"
    took=$(( $(date +%s) - start ))
    [ "$took" -le 6 ] || fail "a 1 s timeout took $took s"
    echo "$out" | grep -q "^timeout .*plugin 'hang_stress' .* did not finish within 1 s in its stress callback" ||
        fail "hang not named: $out"
    "$hearth" plugin check --timeout 0 x.so 2>/dev/null; [ $? -eq 2 ] || fail "--timeout 0 should be a usage error"
    ;;
cli_check_exit_stress)
    # exit(0) inside a callback is a failure, not success
    out=$("$hearth" plugin check "$HEARTH_TEST_PLUGIN_DIR/hearth_exit_stress.so" 2>&1) && fail "exit(0) passed: $out"
    echo "$out" | grep -q "^exit .*plugin 'exit_stress' .* called exit() in its stress callback" ||
        fail "exit not named: $out"
    ;;
cli_check_truncated)
    # a .so cut short is a load failure with a reason, not a SIGBUS
    out=$("$hearth" plugin check "$HEARTH_TEST_PLUGIN_DIR/hearth_truncated.so" 2>&1); rc=$?
    [ $rc -eq 1 ] || fail "truncated plugin: exit $rc: $out"
    echo "$out" | grep -q "hearth_truncated.so: not loadable as a shared object: truncated" || fail "message: $out"
    echo "$out" | grep -q "SIG" && fail "a signal was involved: $out"
    ;;
cli_check_wave_corners)
    # wave speed NaN, inf, 0 or negative with E at its max: refused naming the values
    for mode in nan inf zero neg; do
        case $mode in nan) v=nan ;; inf) v=inf ;; zero) v=0 ;; neg) v=-1160.24 ;; esac
        out=$("$hearth" plugin check "$HEARTH_TEST_PLUGIN_DIR/hearth_wave_$mode.so" 2>&1) && fail "wave_$mode passed: $out"
        echo "$out" | grep -qF "material 'wave_$mode': wave_speed is $v m/s with E at its max (the rest at defaults) (E = 1e+09 Pa, nu = 0.3 1" ||
            fail "wave_$mode message: $out"
    done
    ;;
cli_check_bulk_modulus_nan | cli_check_bulk_modulus_negative)
    # an optional bulk_modulus that is NaN or -1 Pa (tests/plugins/misbehave.c): refused, naming the file, the
    # callback and the value (core/sim/plugin_check.c, check_bulk)
    case $case_name in *nan) mode=nan v=nan ;; *) mode=neg v=-1 ;; esac
    so="$HEARTH_TEST_PLUGIN_DIR/hearth_bulk_$mode.so"
    out=$("$hearth" plugin check "$so" 2>&1) && fail "bulk_$mode passed: $out"
    echo "$out"
    echo "$out" | grep -qF "bulk_modulus         FAIL  $so: bulk_modulus returned $v Pa at the defaults (fresh state from init); it must be finite and > 0" ||
        fail "bulk_$mode message: $out"
    [ "$(echo "$out" | grep -c "^[a-z_]* *FAIL  ")" -eq 1 ] || fail "only bulk_modulus should fail: $out"
    ;;
cli_check_bulk_modulus_off)
    # a bulk_modulus twice the law's (a neo-Hookean, E 1e4 Pa, nu 0.3: K = E / (3 (1 - 2 nu)) = 8333.33 Pa, which
    # never yields): the law's own mean stress under ln J = -3e-6 disagrees, and it is refused
    so="$HEARTH_TEST_PLUGIN_DIR/hearth_bulk_off.so"
    out=$("$hearth" plugin check "$so" 2>&1) && fail "bulk_off passed: $out"
    echo "$out"
    echo "$out" | grep -qF "bulk_modulus         FAIL  $so: bulk_modulus returned 16666.7 Pa at the defaults, but the law's mean stress under isotropic compression ln J = -3e-06 gives K = 8333.3" ||
        fail "bulk_off message: $out"
    ;;
cli_check_bulk_modulus_plastic_warns)
    # the right K (8333.33 Pa) on a law with no tensile strength (misbehave.c, bulk_plastic): compression agrees,
    # expansion flows (plastic_J = J) with mean stress 0 (to rounding); a warning, not a failure, and the check exits 0
    so="$HEARTH_TEST_PLUGIN_DIR/hearth_bulk_plastic.so"
    out=$("$hearth" plugin check "$so" 2>&1) || fail "bulk_plastic failed: $out"
    echo "$out"
    echo "$out" | grep -qF "bulk_modulus         WARN  K = 8333.33 Pa at the defaults;" || fail "no WARN line: $out"
    echo "$out" | grep -q "warning: under expansion the law flowed plastically (plastic_J moved) and its mean stress gives [-0-9.e]* Pa (off by 100%), so K could not be checked there" ||
        fail "warning text: $out"
    ;;
cli_add_bulk_modulus_nan)
    # a bulk_modulus that is NaN at the material's own parameters (misbehave.c, bulk_nan) is refused when s:add
    # adds the material with expansion > 0 (core/sim/material.c, check_bulk_at_params), naming the plugin, its
    # file, the value and the scene line (and no line of hearth's own modules), before any step; with expansion 0
    # K is never asked and the block runs
    export HEARTH_PLUGIN_PATH="$HEARTH_PLUGIN_PATH:$HEARTH_TEST_PLUGIN_DIR"
    for cl in 1 0; do
        cat >"$tmp/s.lua" <<EOF
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("bulk_nan", { E = 1e4, density = 1000, expansion = $cl })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m, ppc = 4, temperature = 60 }
s:run { until_t = 0.05 }
EOF
        (cd "$tmp" && rm -rf o && timeout 60 "$hearth" run s.lua --out o --quiet >out.txt 2>err.txt); rc=$?
        cat "$tmp/err.txt"
        if [ $cl = 0 ]; then
            [ $rc -eq 0 ] || fail "expansion 0: exit $rc, expected the run to complete: $(cat "$tmp/err.txt")"
            continue
        fi
        [ $rc -eq 1 ] || fail "exit $rc, expected the scene's error (1): $(cat "$tmp/err.txt")"
        grep -q "^hearth run: s.lua:4: material 'bulk_nan' (.*hearth_bulk_nan.so): bulk_modulus is nan Pa at these parameters (fresh state from init); it must be finite and > 0 for eq. 10's thermal expansion (expansion = 1 Pa/K" "$tmp/err.txt" ||
            fail "message: $(cat "$tmp/err.txt")"
        grep -q "guard" "$tmp/err.txt" && fail "a step ran: $(cat "$tmp/err.txt")"
    done
    ;;
cli_run_bulk_modulus_nan | cli_run_bulk_modulus_negative)
    # a heated run with expansion > 0 asks bulk_modulus for eq. 10's thermal strain: NaN or -1 Pa stops it with
    # the guard naming the plugin, its file and the value (exit 3), not a silent fall back to the pressure;
    # with expansion 0 K is never asked and the same block completes. The fixtures give the law's K at a fresh
    # state and turn bad once stress has advanced (after = 0: from step 2), so adding the material passes its
    # early check (cli_add_bulk_modulus_nan) and only the guard can see it
    export HEARTH_PLUGIN_PATH="$HEARTH_PLUGIN_PATH:$HEARTH_TEST_PLUGIN_DIR"
    case $case_name in *nan) mode=nan_after v=nan ;; *) mode=neg_after v=-1 ;; esac
    for cl in 1 0; do
        cat >"$tmp/s.lua" <<EOF
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("bulk_$mode", { E = 1e4, density = 1000, expansion = $cl, after = 0 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m, ppc = 4, temperature = 60 }
s:run { until_t = 0.05 }
EOF
        (cd "$tmp" && timeout 60 "$hearth" run s.lua --out o --quiet >out.txt 2>err.txt); rc=$?
        cat "$tmp/err.txt"
        if [ $cl = 0 ]; then
            [ $rc -eq 0 ] || fail "expansion 0: exit $rc, expected the run to complete: $(cat "$tmp/err.txt")"
            continue
        fi
        [ $rc -eq 3 ] || fail "exit $rc, expected a guard stop (3): $(cat "$tmp/err.txt")"
        grep -q "guard: step 2, .*material 'bulk_$mode' (#0): plugin 'bulk_$mode' (.*hearth_bulk_$mode.so): bulk_modulus returned $v Pa; it must be finite and > 0" "$tmp/err.txt" ||
            fail "message: $(cat "$tmp/err.txt")"
        [ "$(grep -c "bulk_modulus returned" "$tmp/err.txt")" -eq 1 ] || fail "said more than once: $(cat "$tmp/err.txt")"
        grep -q "^guard: stopped, .*plugin 'bulk_$mode' (.*hearth_bulk_$mode.so): bulk_modulus returned $v Pa" "$tmp/o/run.log" ||
            fail "run.log: $(cat "$tmp/o/run.log")"
    done
    ;;
cli_run_plugin_segv)
    # hearth run: a segfault inside stress names plugin and callback and exits 4
    export HEARTH_PLUGIN_PATH="$HEARTH_PLUGIN_PATH:$HEARTH_TEST_PLUGIN_DIR"
    block_scene segv_stress >"$tmp/s.lua"
    (cd "$tmp" && "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
    [ $rc -eq 4 ] || fail "exit $rc, expected 4: $(cat "$tmp/err.txt")"
    grep -q "plugin 'segv_stress' (.*hearth_segv_stress.so) crashed with SIGSEGV (segmentation fault) in its stress callback" "$tmp/err.txt" ||
        fail "message: $(cat "$tmp/err.txt")"
    ;;
cli_run_plugin_exit)
    export HEARTH_PLUGIN_PATH="$HEARTH_PLUGIN_PATH:$HEARTH_TEST_PLUGIN_DIR"
    block_scene exit_stress >"$tmp/s.lua"
    (cd "$tmp" && "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
    [ $rc -eq 4 ] || fail "exit $rc, expected 4: $(cat "$tmp/err.txt")"
    grep -q "plugin 'exit_stress' .* called exit() in its stress callback" "$tmp/err.txt" || fail "message: $(cat "$tmp/err.txt")"
    ;;
cli_run_wave_inf)
    # a wave speed that turns inf at run time: a guard stop naming the plugin, not dt = 0 forever
    export HEARTH_PLUGIN_PATH="$HEARTH_PLUGIN_PATH:$HEARTH_TEST_PLUGIN_DIR"
    block_scene wave_inf_after >"$tmp/s.lua"
    (cd "$tmp" && timeout 60 "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
    [ $rc -eq 3 ] || fail "exit $rc, expected 3 (124 is a hang): $(cat "$tmp/err.txt")"
    grep -q "material 'wave_inf_after' (#0): plugin 'wave_inf_after' (.*): wave_speed returned inf m/s" "$tmp/err.txt" ||
        fail "message: $(cat "$tmp/err.txt")"
    ;;
cli_guard_soft_block_jump)
    # E = 0.01 Pa (in range) with dt_max 0.5 s: gravity moves the block 12 cells in one step onto a floor that
    # zeroes its speed; the guard must judge the motion, not the end speed
    soft_block_scene >"$tmp/s.lua"
    (cd "$tmp" && "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
    [ $rc -eq 3 ] || fail "exit $rc, expected a guard stop (3): $(cat "$tmp/err.txt")"
    grep -q "step 1, t = 0.5 s: CFL violated: a particle moved 1[0-9].[0-9]* cells in one step of dt = 0.5 s" "$tmp/err.txt" ||
        fail "message: $(cat "$tmp/err.txt")"
    grep -q "a wall or collider stopped it" "$tmp/err.txt" || fail "message: $(cat "$tmp/err.txt")"
    ;;
cli_guard_expansion_named)
    # a plastic block heated to 400 degC with expansion 10 Pa/K: 3800 Pa of expansion pressure. snow_plastic (no
    # bulk_modulus, so the core adds eq. 10's term as a pressure after its stress) holds ~600 Pa of tension at its
    # critical stretch and dilates plastically without end: the guard names thermal expansion. cam_clay_dough
    # (tau_y 20 Pa) did the same until eq. 10 became a thermal strain for a plugin that gives its bulk modulus
    # (core/sim/material.h, material_thermal_split): ln J_th = 10 x 380 / K = 0.114, bounded, and it completes.
    # (An elastic block never burst: the pressure's free swelling exp(c lambda dT / K) is bounded.)
    # The cause snow_plastic's guard names is knife-edge on the floor's friction: with main's binary at 0.28, 0.295,
    # 0.305 or 0.4 (this test's 0.3) the same blow-up, at steps 161-205 against 169, is not named thermal expansion
    # (docs/validation.md, "Tried again: a hold for the resting body only"). A contact change that flips it has not
    # by that alone broken the guard; check the step it stops at and the cause over a few frictions.
    # So did the seeding's jitter: seeds 2-5 stopped it at steps 148-181 on a particle crushed against a wall
    # (x = 0.04 or 0.93 m), whose terms name nothing, while the block around it had swollen to det F ~ 1e47-1e59;
    # guard.c now weighs the terms at the material's most swollen particle then (guard_swollen_elsewhere), and the
    # claim is checked on seeds 1-5 (docs/validation.md, "Tests that flip with the seeding").
    for run in snow_plastic:1 snow_plastic:2 snow_plastic:3 snow_plastic:4 snow_plastic:5 cam_clay_dough:1 \
        cam_clay_dough:2 cam_clay_dough:3 cam_clay_dough:4 cam_clay_dough:5; do
        mat=${run%:*} seed=${run#*:}
        cat >"$tmp/s.lua" <<EOF
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 32, box = { { 0, 0 }, { 1, 1 } }, seed = $seed }
local m = h.material("$mat", { expansion = 10 })
s:add { shape = h.box({ 0.4, 0.15 }, { 0.6, 0.35 }), material = m, ppc = 4, temperature = 400 }
s:collider { shape = h.plane({ 0, 0.1 }, { 0, 1 }), mode = "separate", friction = 0.3 }
s:run { until_t = 0.5 }
local r = s:particles { fields = { "J" } }
local jmax = 0
for i = 1, r.n do jmax = math.max(jmax, r.J[i]) end
print(("$mat seed $seed completes: J max %.4g"):format(jmax))
EOF
        (cd "$tmp" && "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
        echo "seed $seed:"; cat "$tmp/out.txt" "$tmp/err.txt"
        if [ $mat = cam_clay_dough ]; then
            [ $rc -eq 0 ] || fail "cam_clay_dough at 400 degC, 10 Pa/K, seed $seed: exit $rc, expected it to complete: $(cat "$tmp/err.txt")"
            continue
        fi
        [ $rc -eq 3 ] || fail "seed $seed: exit $rc, expected a guard stop (3): $(cat "$tmp/err.txt")"
        # The temperature runs away here too, but after the motion: the block swells without end (F past 1e26 by
        # the stop), and the guard weighs the terms at a swollen particle whatever its temperature (guard.c
        # guard_cause; docs/validation.md, "A lone hot particle").
        grep -q "thermal expansion blew the material apart: its pressure c lambda (T - T_ref) = [0-9.e+]* Pa outweighs the plugin's stress" "$tmp/err.txt" ||
            fail "seed $seed: message: $(cat "$tmp/err.txt")"
    done
    ;;
cli_leavened_x10_cookie_heat_bounded)
    # a cookie (h.library.paper.cookie) leavened x10 (cookies.lua --set gas=10) with no pore cap, on the 150 degC
    # tray at dx 7.5 mm. Its swollen pores conducted over J V0 while storing heat by m c, J times the diffusivity
    # the explicit step's limit covers, so its temperature ran away (x4 a step, alternating in sign, from ~0.9486 s)
    # and the guard stopped the bake at 0.95 s; transport.c caps the conducting volume (COND_J_MARGIN), and the
    # guard's naming of such a runaway is unit_heat's guard_names_temperature_runaway. Now the 1.2 s bake completes.
    cat >"$tmp/s.lua" <<'EOF'
local h = require "hearth"
local oven = h.library.paper_oven.cookie
local s = h.scene { dim = 2, dx = 0.0075, box = { { 0, 0 }, { 0.12, 0.09 } }, oven = { temperature = 150, beta = oven.beta } }
h.recipes.tray(s, 0.02, { temperature = 150, beta = oven.pan_beta })
local d = h.library.paper.cookie
d.gas_rate = 0.015 * h.library.dough_scale.gas * 10
s:add { shape = h.shapes.cookie({ 0.06, 0.0325 }, 0.03, 0.025), material = h.material("cam_clay_dough", d),
  temperature = oven.dough_temperature, ppc = 4 }
s:run { until_t = 1.2 }
local T = s:particles { fields = { "temperature" } }.temperature
local lo, hi = math.huge, -math.huge
for _, t in ipairs(T) do lo, hi = math.min(lo, t), math.max(hi, t) end
print(string.format("t %.3f s: temperature %.2f .. %.2f degC", s:stats().t, lo, hi))
assert(lo >= 20 - 1e-9 and hi <= 150 + 1e-9, "a temperature outside the dough's 20 degC and the oven's 150")
EOF
    (cd "$tmp" && "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
    cat "$tmp/out.txt" "$tmp/err.txt"
    [ $rc -eq 0 ] || fail "exit $rc, expected the bake to complete: $(cat "$tmp/err.txt")"
    ;;
cli_scene_error_not_guard)
    # error({}) in a scene is a scene error (exit 1), never "the stability guard stopped the run: (null)"
    printf 'error({})\n' >"$tmp/s.lua"
    (cd "$tmp" && "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
    [ $rc -eq 1 ] || fail "exit $rc, expected 1: $(cat "$tmp/err.txt")"
    grep -q "stability guard" "$tmp/err.txt" && fail "reported as a guard stop: $(cat "$tmp/err.txt")"
    grep -q "the scene raised an error that is a table, not a message" "$tmp/err.txt" || fail "message: $(cat "$tmp/err.txt")"
    printf 'error({ guard = true, message = "looks like a guard stop" })\n' >"$tmp/s.lua"
    (cd "$tmp" && "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
    [ $rc -eq 1 ] || fail "a look-alike table: exit $rc, expected 1: $(cat "$tmp/err.txt")"
    ;;
cli_run_wave_inf_sph)
    # the same in an SPH scene: a guard stop naming the plugin, not a zero sound speed or a hang
    export HEARTH_PLUGIN_PATH="$HEARTH_PLUGIN_PATH:$HEARTH_TEST_PLUGIN_DIR"
    block_scene wave_inf_after | sed 's/box = { { 0, 0 }, { 1, 1 } } }/box = { { 0, 0 }, { 1, 1 } }, solver = "sph" }/' >"$tmp/s.lua"
    grep -q 'solver = "sph"' "$tmp/s.lua" || fail "the scene is not SPH: $(cat "$tmp/s.lua")"
    (cd "$tmp" && timeout 60 "$hearth" run s.lua --quiet >out.txt 2>err.txt); rc=$?
    [ $rc -eq 3 ] || fail "exit $rc, expected 3 (124 is a hang): $(cat "$tmp/err.txt")"
    grep -q "plugin 'wave_inf_after' (.*): wave_speed returned inf m/s" "$tmp/err.txt" || fail "message: $(cat "$tmp/err.txt")"
    ;;
*) fail "unknown case $case_name" ;;
esac
echo "ok"

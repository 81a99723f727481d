#!/usr/bin/env bash
# tui_test.sh CASE HEARTH SOURCE_ROOT: the dashboard driven through tmux as a
# user would: a detached pane of a fixed size, send-keys, capture-pane.
# Each case has its own tmux server (-L), so cases run in parallel safely.
here=$(cd "$(dirname "$0")" && pwd) # png_check.py lives here
set -u
case_name=$1
hearth=$(realpath "$2")
src=$3
scene="$src/tests/tui/bake.lua"
tmp=$(mktemp -d)
sock="hearth-tui-$case_name-$$"
cleanup() { tmux -L "$sock" kill-server 2>/dev/null; rm -rf "$tmp"; }
trap cleanup EXIT
fail() {
    echo "FAIL: $*" >&2
    echo "---- screen ----" >&2
    tmux -L "$sock" capture-pane -p -t t >&2
    echo "---- stderr ----" >&2
    cat "$tmp/stderr.txt" 2>/dev/null >&2
    [ -f "$tmp/exit.txt" ] && echo "exit status: $(cat "$tmp/exit.txt")" >&2
    exit 1
}
command -v tmux >/dev/null || { echo "FAIL: tmux is not installed (scripts/test installs it)" >&2; exit 1; }

# start ARGS...: hearth in a 120x40 pane; after it exits the pane records the
# terminal modes, then its exit status (exit.txt last, renamed into place, so
# a case that sees exit.txt also sees stty.txt whole) and stays open.
start() {
    local cmd="cd '$tmp' && env LANG=C.UTF-8 LC_ALL=C.UTF-8 ${TUI_ENV:-} TERM=${TUI_TERM:-tmux-256color} XDG_STATE_HOME='$tmp/state' '$hearth' $* 2>'$tmp/stderr.txt'; st=\$?; stty -a > '$tmp/stty.txt'; echo \$st > '$tmp/exit.tmp'; mv '$tmp/exit.tmp' '$tmp/exit.txt'; sleep 60"
    tmux -L "$sock" -f /dev/null new-session -d -x "${TUI_COLS:-120}" -y "${TUI_ROWS:-40}" -s t "$cmd" || fail "tmux did not start"
}
screen() { tmux -L "$sock" capture-pane -p -t t; }
# wait_for REGEX [SECONDS]: until the screen matches
wait_for() {
    local i n=$(( ${2:-10} * 10 ))
    for ((i = 0; i < n; i++)); do
        screen | grep -Eq -- "$1" && return 0
        sleep 0.1
    done
    fail "the screen never showed /$1/"
}
keys() { tmux -L "$sock" send-keys -t t "$@"; }
sim_time() { screen | sed -n '1s/.* t \([0-9.e+-]*\) s .*/\1/p'; }
alive() { [ ! -f "$tmp/exit.txt" ] || fail "hearth exited ($(cat "$tmp/exit.txt"))"; }

png_ok() { python3 "$here/png_check.py" "$1" >/dev/null; } # see png_check.py

case "$case_name" in
tui_colorterm_truecolor)
    # COLORTERM=truecolor under a 256-colour $TERM: 24-bit colour when a -direct
    # terminal description is installed (Debian ncurses-term), else a log line saying why not
    TUI_ENV=COLORTERM=truecolor TUI_TERM=xterm-256color start "'$scene'"
    wait_for "paused"
    if [ -e /usr/share/terminfo/x/xterm-direct ] || [ -e /lib/terminfo/x/xterm-direct ]; then
        wait_for "24-bit colour through the"
        tmux -L "$sock" capture-pane -e -p -t t | grep -q $'\e\[[0-9;]*38;2;' ||
            fail "the screen has no 24-bit colour sequences"
    else
        wait_for "no -direct terminal"
    fi
    ;;
tui_dimensionless_without_unit)
    # #18 (helper userview4): at 80x24 the probe panel read "J   1.034 1" and "saturation   0.2108 1", the
    # dimensionless unit "1" reading as a second number, and the colour bar "0.218 1". Bar set before the run: the
    # probe rows of J and saturation hold their name and one number, then the sparkline (no unit word); the
    # colour bar of the saturation view ends in its number; temperature and density keep degC and kg/m^3.
    TUI_COLS=80 TUI_ROWS=24 start "'$src/tests/tui/wet.lua'"
    wait_for "paused"
    wait_for "^saturation "
    screen | sed -n '/^probe at /,/^fields [0-9]/p' | tee "$tmp/panel.txt"
    for f in J saturation; do
        row=$(grep -E "^$f +" "$tmp/panel.txt" | cut -c1-36)
        [ -n "$row" ] || fail "no $f row in the probe panel"
        echo "$row" | grep -Eq "^$f +[-+0-9.e]+ *$" || fail "the $f row gives more than its number: '$row'"
    done
    grep -Eq "^temperature +[-+0-9.e]+ degC" "$tmp/panel.txt" || fail "temperature lost its unit"
    grep -Eq "^density +[-+0-9.e]+ kg/m\^3" "$tmp/panel.txt" || fail "density lost its unit"
    bar=$(screen | grep -E "^[-+0-9.e]+ .* degC " | head -1)
    echo "colour bars: $bar"
    echo "$bar" | grep -Eq "[0-9] *$" || fail "the saturation view's colour bar ends in a unit: '$bar'"
    ;;
tui_status_says_scene_clock)
    # #18 (helper userfix10; userview4's item 7): the status line gave "t 0.78914 s" where the physical loaf's frames
    # said "t = 4 min": the dashboard did not know the scene's clock. Bar set before the first run: a scene declaring
    # time_scale = 300 shows " t 0 s (0 s x 300)" at the start and, after s:run{until_t = 0.5} at the prompt,
    # " t 2.5 min (0.5 s x 300)" (real minutes past two of them, as a frame's title); the dashboard's default scene,
    # in Ding Table 2's animation units, shows "t 0 s (animation units)"; a scene that declares neither keeps "t 0 s".
    TUI_COLS=80 TUI_ROWS=24 start "'$src/tests/tui/clock.lua'"
    wait_for "paused"
    screen | sed -n 1p | grep -Fq " t 0 s (0 s x 300) " || fail "line 1 does not give the real time at t = 0"
    keys :
    wait_for "^lua>"
    keys "s:run{until_t = 0.5}" Enter
    wait_for "the scene's run finished" 30
    screen | sed -n 1p | grep -Eq " t 2\.5[0-9]* min \(0\.5[0-9]* s x 300\) " ||
        fail "line 1 does not give 2.5 real minutes at t = 0.5 s"
    tmux -L "$sock" kill-server 2>/dev/null
    sock="$sock-cookie" # a server of its own: a new session on the one just killed can race its exit
    TUI_COLS=80 TUI_ROWS=24 start "'$src/assets/cookie_bake.lua'"
    wait_for "paused" 20
    screen | sed -n 1p | grep -Fq " t 0 s (animation units) " || fail "the cookie's line 1 does not say animation units"
    tmux -L "$sock" kill-server 2>/dev/null
    sock="$sock-plain"
    TUI_COLS=80 TUI_ROWS=24 start "'$scene'"
    wait_for "paused"
    screen | sed -n 1p | grep -Eq " t 0 s   step 0 " || fail "a scene in real seconds lost its plain time"
    ;;
tui_probe_panel_scrolls)
    # a wet dough has more live fields than the probe panel has rows at 80x24:
    # the panel says which it shows and PgDn / PgUp (and > / <) page through
    # them, so every field, saturation and water_pressure included, can be read
    TUI_COLS=80 TUI_ROWS=24 start "'$src/tests/tui/wet.lua'"
    wait_for "paused"
    wait_for "fields 1-[0-9]+ of [0-9]+  PgUp/PgDn"
    total=$(screen | sed -n 's/.*fields 1-[0-9]* of \([0-9]*\) .*/\1/p' | head -1)
    seen="$tmp/seen.txt"
    : >"$seen"
    probe_names() { screen | sed -n '/^probe at /,/^fields [0-9]/p' | sed '1d;$d' | awk '{print $1}' >>"$seen"; }
    probe_names
    for _ in 1 2 3 4 5 6; do
        screen | grep -Eq "fields [0-9]+-$total of $total" && break
        keys NPage
        sleep 0.3
        probe_names
    done
    screen | grep -Eq "fields [0-9]+-$total of $total" || fail "PgDn never reached the last of $total fields"
    n=$(sort -u "$seen" | wc -l)
    echo "the panel showed $n of $total fields over its pages: $(sort -u "$seen" | tr '\n' ' ')"
    [ "$n" -eq "$total" ] || fail "the pages showed $n distinct fields, the panel counts $total"
    for f in temperature saturation water_pressure porosity; do
        grep -qx "$f" "$seen" || fail "field $f never shown (names cut?)"
    done
    keys PPage
    keys '<'
    keys '<'
    sleep 0.3
    wait_for "fields 1-[0-9]+ of $total"
    ;;
tui_80x24_layout)
    # the smallest screen the dashboard supports: the key bar keeps help and
    # quit, the run state does not overwrite the status line, and the floor
    # (a collider) is drawn under the block
    TUI_COLS=80 TUI_ROWS=24 start "'$scene'"
    wait_for "paused"
    screen | sed -n 24p | grep -q '? help  q quit *$' || fail "the key bar lost '? help  q quit' at 80x24"
    screen | sed -n 1p | grep -Eq 'oven 180 degC +\|\| paused *$' || fail "the status line's run state overlaps the oven"
    python3 - "$(screen)" <<'PY' || fail "no collider drawn under the block"
import sys
rows = sys.argv[1].split("\n")
bar = next(i for i, r in enumerate(rows) if "degC" in r and i > 3)  # the left view's colour bar line
floor = rows[bar - 1][:40]
n = floor.count("\u2580")
print(f"floor row: {n} upper half blocks in the left view")
sys.exit(0 if n >= 20 else 1)  # the view is 29 cells wide here; none before colliders were drawn
PY
    ;;
tui_space_advances_time)
    start "'$scene'"
    wait_for "paused"
    t0=$(sim_time)
    [ "$t0" = 0 ] || fail "the scene should start at t = 0, status shows '$t0'"
    keys Space
    wait_for "running"
    wait_for " t [0-9.]*[1-9][0-9.e-]* s " 10
    keys Space
    wait_for "paused"
    t1=$(sim_time)
    sleep 0.5
    t2=$(sim_time)
    python3 -c "import sys; t1, t2 = float('$t1'), float('$t2'); sys.exit(not (t1 > 0 and t1 == t2))" ||
        fail "time should advance while running and stop when paused: $t1 then $t2"
    keys n
    wait_for "step [0-9]+ " 5
    sleep 0.3
    t3=$(sim_time)
    python3 -c "import sys; sys.exit(not (float('$t3') > float('$t2')))" || fail "n should step once: $t2 -> $t3"
    ;;
tui_field_cycle)
    start "'$scene'"
    wait_for "^temperature  \(2D"
    keys f
    wait_for "^boundary  \(2D" 5
    keys F
    sleep 0.3
    right=$(screen | sed -n '3p' | awk '{print $NF}')
    screen | sed -n '3p' | grep -q "pressure  (2D" && fail "F should change the right view's field"
    keys f
    wait_for "^velocity_x  \(2D|^speed  \(2D" 5
    alive
    ;;
tui_prompt_changes_oven)
    start "'$scene'"
    wait_for "oven 180 degC"
    keys :
    wait_for "^lua>"
    keys "s:oven(120)" Enter
    wait_for "oven 120 degC" 5
    screen | grep -q "oven 180" && fail "the old oven temperature is still shown"
    # a run typed at the prompt runs while the screen goes on, then pauses
    keys "s:run{until_t = 0.05}" Enter
    wait_for "the scene's run finished at t = 0.05 s" 15
    wait_for "paused" 5
    # multi-line input and print to the log
    keys "print(greeting," Enter
    wait_for "^>>" 5
    keys "'and more')" Enter
    wait_for "hello from bake and more" 5
    # Tab completes hearth names
    keys "h.sce" Tab
    wait_for "^lua> h\.scene" 5
    keys C-u Escape
    # the history is kept across sessions
    grep -q "s:oven(120)" "$tmp/state/hearth/history" || fail "no history file with the command"
    ;;
tui_lua_error_survives)
    start "'$scene'"
    wait_for "paused"
    keys :
    keys "x = = 1" Enter
    wait_for "error: prompt:1: unexpected symbol near '='" 5
    keys "error('boom')" Enter
    wait_for "error: prompt:1: boom" 5
    keys "s:set_dt(99)" Enter
    wait_for "error: .*cfl" 5
    keys Escape Space
    wait_for "running" 5
    wait_for " t [0-9.]*[1-9][0-9.e-]* s " 10
    alive
    ;;
tui_save_png)
    start "'$scene'"
    wait_for "paused"
    keys n
    keys s
    wait_for "saved hearth-out/bake/left_" 10
    n=0
    for f in "$tmp"/hearth-out/bake/*.png; do
        [ -f "$f" ] || continue
        png_ok "$f" || fail "$f does not decode"
        n=$((n + 1))
    done
    [ "$n" -eq 2 ] || fail "expected 2 PNG files, found $n: $(ls "$tmp/hearth-out/bake")"
    keys c
    wait_for "checkpoint hearth-out/bake/checkpoint_" 5
    [ -s "$tmp/hearth-out/bake/checkpoint_000001.bin" ] || fail "no checkpoint file"
    ;;
tui_resize)
    start "'$scene'"
    wait_for "paused"
    tmux -L "$sock" resize-window -t t -x 60 -y 20 || fail "resize-window"
    wait_for "terminal too small: 60x20" 5
    screen | grep -q "paused" && fail "the dashboard is still drawn at 60x20"
    tmux -L "$sock" resize-window -t t -x 120 -y 40
    wait_for "paused" 5
    screen | grep -q "too small" && fail "the size message stayed at 120x40"
    screen | grep -q "^temperature  (2D" || fail "the views are not back"
    ;;
tui_quit_restores)
    start "'$scene'"
    wait_for "paused"
    keys n
    keys q
    wait_for "Quit\? y quits" 5
    keys x
    sleep 0.3
    alive
    keys q
    wait_for "Quit\? y quits" 5
    keys y
    for _ in $(seq 50); do [ -f "$tmp/exit.txt" ] && break; sleep 0.1; done
    [ -f "$tmp/exit.txt" ] || fail "hearth did not exit after q, y"
    [ "$(cat "$tmp/exit.txt")" = 0 ] || fail "exit status $(cat "$tmp/exit.txt")"
    sleep 0.2
    [ "$(tmux -L "$sock" display -p -t t '#{alternate_on}')" = 0 ] || fail "the alternate screen is still on"
    grep -Eq '(^| )icanon( |$)' "$tmp/stty.txt" && grep -Eq '(^| )echo( |$)' "$tmp/stty.txt" ||
        fail "terminal modes not restored: $(cat "$tmp/stty.txt")"
    ;;
tui_ctrl_c_restores)
    start "'$scene'"
    wait_for "paused"
    keys Space
    wait_for "running"
    keys C-c
    for _ in $(seq 50); do [ -f "$tmp/exit.txt" ] && break; sleep 0.1; done
    [ -f "$tmp/exit.txt" ] || fail "hearth did not exit on Ctrl-C"
    [ "$(cat "$tmp/exit.txt")" = 130 ] || fail "exit status $(cat "$tmp/exit.txt"), expected 130"
    [ "$(tmux -L "$sock" display -p -t t '#{alternate_on}')" = 0 ] || fail "the alternate screen is still on"
    grep -Eq '(^| )icanon( |$)' "$tmp/stty.txt" || fail "terminal modes not restored"
    ;;
tui_not_a_terminal)
    "$hearth" "$scene" >"$tmp/out.txt" 2>"$tmp/err.txt"
    st=$?
    [ $st -ne 0 ] || fail "hearth with stdout not a terminal should refuse"
    grep -q "hearth run SCENE.lua" "$tmp/err.txt" && grep -q "hearth repl" "$tmp/err.txt" ||
        fail "the refusal should point to hearth run and hearth repl: $(cat "$tmp/err.txt")"
    "$hearth" >"$tmp/out.txt" 2>"$tmp/err.txt" && fail "hearth (no scene) into a file should refuse too"
    ;;
tui_dumb_line_mode)
    TUI_TERM=dumb start "'$scene'"
    wait_for "line mode" 5
    wait_for "^t [0-9.e-]+ s  step [0-9]+ .*running" 5
    keys "print(greeting)" Enter
    wait_for "^hello from bake" 5
    keys "quit" Enter
    for _ in $(seq 50); do [ -f "$tmp/exit.txt" ] && break; sleep 0.1; done
    [ "$(cat "$tmp/exit.txt" 2>/dev/null)" = 0 ] || fail "quit should end line mode with status 0"
    ;;
tui_guard_pauses)
    # cfl = 4 breaks the wave CFL condition: the guard stops the scene's run
    start "'$src/tests/lua/guard.lua'"
    wait_for "paused"
    keys Space
    wait_for "the stability guard stopped the run \(paused\)" 15
    wait_for "guard STOPPED" 5
    wait_for "paused" 5
    keys :
    keys "print('still here')" Enter
    wait_for "^.*still here" 5
    alive
    ;;
tui_crash_restores)
    start "'$scene'"
    wait_for "paused"
    shell=$(tmux -L "$sock" display -p -t t '#{pane_pid}')
    pid=$(pgrep -P "$shell" | head -1)
    [ -n "$pid" ] || fail "no hearth process under the pane"
    kill -ABRT "$pid"
    for _ in $(seq 50); do [ -f "$tmp/exit.txt" ] && break; sleep 0.1; done
    [ "$(cat "$tmp/exit.txt" 2>/dev/null)" = 134 ] || fail "SIGABRT should end hearth with status 134"
    [ "$(tmux -L "$sock" display -p -t t '#{alternate_on}')" = 0 ] || fail "the alternate screen is still on"
    grep -Eq '(^| )icanon( |$)' "$tmp/stty.txt" && grep -Eq '(^| )echo( |$)' "$tmp/stty.txt" ||
        fail "terminal modes not restored after SIGABRT: $(cat "$tmp/stty.txt")"
    ;;
tui_plugin_crash_named)
    # a plugin that segfaults in its stress callback: the terminal is restored and
    # the plugin and callback are named (crash.c), exit status 4
    export HEARTH_PLUGIN_PATH="${HEARTH_PLUGIN_PATH:-}:$HEARTH_TEST_PLUGIN_DIR"
    cat >"$tmp/segv.lua" <<'EOF2'
local h = require "hearth"
local s = h.scene { dim = 2, dx = 1 / 16, box = { { 0, 0 }, { 1, 1 } } }
local m = h.material("segv_stress", { E = 1e4, density = 1000 })
s:add { shape = h.box({ 0.3, 0.3 }, { 0.6, 0.6 }), material = m, ppc = 4 }
EOF2
    start "'$tmp/segv.lua'"
    wait_for "paused"
    keys Space
    for _ in $(seq 100); do [ -f "$tmp/exit.txt" ] && break; sleep 0.1; done
    [ "$(cat "$tmp/exit.txt" 2>/dev/null)" = 4 ] || fail "a plugin crash should end the dashboard with status 4"
    grep -q "plugin 'segv_stress'" "$tmp/stderr.txt" && grep -q "in its stress callback" "$tmp/stderr.txt" ||
        fail "the plugin and its callback are not named"
    [ "$(tmux -L "$sock" display -p -t t '#{alternate_on}')" = 0 ] || fail "the alternate screen is still on"
    grep -Eq '(^| )icanon( |$)' "$tmp/stty.txt" || fail "terminal modes not restored after the plugin crash"
    ;;
*) fail "unknown case $case_name" ;;
esac
echo "ok"

#!/usr/bin/env bash
# baking_test.sh CASE HEARTH SOURCE_ROOT: the baking scenes (scripts/scenes/baking/)
# as a user runs them, and the paper's claims (Ding et al. 2019 §7.2, 7.3, 7.5)
# checked at coarse 2D resolution from the CSVs the scenes write.
# Exit 0 pass, 1 fail, 77 expected failure (prints the measured numbers and why).
# This file holds what every case shares; the cases live by food in tests/baking/: scenes.sh (the scenes as a user
# runs them, and the smaller scenes' claims), loaf.sh, cookie.sh, muffin.sh and tear_open.sh.
set -u
case_name=$1 hearth=$2 root=$3
scenes=$root/scripts/scenes/baking
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

# run SCENE ARGS...: hearth run --quiet; fails the case on a non-zero exit
run() {
    local sc=$1 rc
    shift
    shared_run "$sc" "$@"
    rc=$?
    [ $rc -eq 0 ] || fail "$sc $*: exit $rc: $(cat err.txt)"
    cat out.txt
}

# shared_run SCENE ARGS...: `"$hearth" run "$scenes/SCENE.lua" --quiet ARGS >out.txt 2>err.txt` here, with its exit
# status, made once for all the cases of one `meson test` run that ask for the very same run (the same hearth, scene
# and arguments). Several claims read one bake: tear_open's torn-open, cooked-inside and raw-against-baked claims the
# same baked muffin or loaf, bread.lua's rise, drying and crack claims the same plain loaf. The first case to ask makes
# the run under a lock in $HEARTH_TEST_RUN_SHARE (tests/meson.build: the build folder's tests/run_share) and keeps its
# folder (the outputs, out.txt, err.txt, the status); a case asking while it runs waits for it (less time than making
# it again), and each copies the folder into its own. The scenes are deterministic (the same hearth, scene and
# arguments write the same bytes), so a case reads what its own run would have written. A run is shared only within
# one meson process (the folder is named by its pid and start time; a later suite never reads an earlier one's runs,
# whatever was rebuilt), and only when that process started the case; otherwise, or without flock, the case runs alone.
shared_run() {
    local sc=$1 scope key dir lock rc
    shift
    if ! scope=$(share_scope) || ! command -v flock >/dev/null 2>&1; then
        "$hearth" run "$scenes/$sc.lua" --quiet "$@" >out.txt 2>err.txt
        return
    fi
    key=$(printf '%s\0' "$hearth" "$scenes/$sc.lua" "$@" | sha1sum | cut -c1-40)
    dir=$scope/$key
    exec {lock}>"$dir.lock"
    flock "$lock"
    if [ ! -f "$dir/.status" ]; then
        # made in a folder of its own and renamed when whole: a case killed mid-run (its timeout) leaves no half run
        rm -rf "$dir.part" && mkdir "$dir.part" &&
            (cd "$dir.part" && { "$hearth" run "$scenes/$sc.lua" --quiet "$@" >out.txt 2>err.txt; echo $? >.status; }) &&
            mv "$dir.part" "$dir"
    fi
    flock -u "$lock"
    exec {lock}>&-
    if [ ! -f "$dir/.status" ]; then # the share failed (disk?): run alone
        "$hearth" run "$scenes/$sc.lua" --quiet "$@" >out.txt 2>err.txt
        return
    fi
    cp -a "$dir/." . && rc=$(cat .status) && rm -f .status || return 1
    return "$rc"
}

# share_scope: the folder of this meson process's shared runs (made, and the folders of meson processes that have
# ended removed, on first use); fails when $HEARTH_TEST_RUN_SHARE is unset or the case was not started by meson.
share_scope() {
    local stat start scope d pid
    [ -n "${HEARTH_TEST_RUN_SHARE:-}" ] || return 1
    tr '\0' ' ' </proc/$PPID/cmdline 2>/dev/null | grep -q meson || return 1
    stat=$(cat /proc/$PPID/stat 2>/dev/null) || return 1
    start=$(echo "${stat##*) }" | cut -d' ' -f20) # field 22, the start time (fields from 3 follow the name's ')')
    scope=$HEARTH_TEST_RUN_SHARE/$PPID-$start
    [ -d "$scope" ] && { echo "$scope"; return 0; }
    mkdir -p "$scope" || return 1
    for d in "$HEARTH_TEST_RUN_SHARE"/*-*; do
        [ "$d" = "$scope" ] && continue
        pid=${d##*/}; pid=${pid%%-*}
        stat=$(cat /proc/"$pid"/stat 2>/dev/null) && [ "${d##*-}" = "$(echo "${stat##*) }" | cut -d' ' -f20)" ] && continue
        rm -rf "$d"
    done
    echo "$scope"
}

# the coarse cookie bake the claims use: dx 7.5 mm, 4 s (every cookie sets by then
# with cookies.lua's real dough conductivity: 3.5 s at 150 degC)
COARSE=(--set dx=0.0075 --set until_t=4 --set frames=1)

# The cases live by food in tests/baking/*.sh (each a `case` on $case_name); the first that knows the case runs it.
for part in scenes loaf cookie muffin tear_open; do
    unmatched=0
    # shellcheck source=/dev/null
    . "$root/tests/baking/$part.sh"
    [ "$unmatched" = 1 ] || { echo ok; exit 0; }
done
fail "unknown case $case_name"

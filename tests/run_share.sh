# run_share.sh: sourced by the shell drivers whose cases read one run between them (tests/baking_test.sh,
# tests/sph_cake_test.sh), not run. Needs $hearth, and the case's own folder as the working directory.
#
# shared_run_path SCENE_FILE ARGS...: `"$hearth" run SCENE_FILE --quiet ARGS >out.txt 2>err.txt` here, with its exit
# status, made once for all the cases of one `meson test` run that ask for the very same run (the same hearth, scene
# and arguments). Several claims read one bake: tear_open's torn-open, cooked-inside and raw-against-baked claims the
# same baked muffin or loaf, bread.lua's rise, drying and crack claims the same plain loaf, the angel food cake's rise
# and pale crumb the same cake. The first case to ask makes the run under a lock in $HEARTH_TEST_RUN_SHARE
# (tests/meson.build: the build folder's tests/run_share) and keeps its folder (the outputs, out.txt, err.txt, the
# status); a case asking while it runs waits for it (less time than making it again), and each copies the folder into
# its own. The scenes are deterministic (the same hearth, scene and arguments write the same bytes), so a case reads
# what its own run would have written. A run is shared only within one meson process (the folder is named by its pid
# and start time; a later suite never reads an earlier one's runs, whatever was rebuilt), and only when that process
# started the case; otherwise, or without flock, the case runs alone.
shared_run_path() {
    local sc=$1 scope key dir lock rc
    shift
    if ! scope=$(share_scope) || ! command -v flock >/dev/null 2>&1; then
        "$hearth" run "$sc" --quiet "$@" >out.txt 2>err.txt
        return
    fi
    key=$(printf '%s\0' "$hearth" "$sc" "$@" | sha1sum | cut -c1-40)
    dir=$scope/$key
    exec {lock}>"$dir.lock"
    flock "$lock"
    if [ ! -f "$dir/.status" ]; then
        # made in a folder of its own and renamed when whole: a case killed mid-run (its timeout) leaves no half run
        rm -rf "$dir.part" && mkdir "$dir.part" &&
            (cd "$dir.part" && { "$hearth" run "$sc" --quiet "$@" >out.txt 2>err.txt; echo $? >.status; }) &&
            mv "$dir.part" "$dir"
    fi
    flock -u "$lock"
    exec {lock}>&-
    if [ ! -f "$dir/.status" ]; then # the share failed (disk?): run alone
        "$hearth" run "$sc" --quiet "$@" >out.txt 2>err.txt
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

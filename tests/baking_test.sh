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

# shared_run SCENE ARGS...: tests/run_share.sh's shared_run_path on the baking scene SCENE (its folder, $scenes)
shared_run() {
    local sc=$1
    shift
    shared_run_path "$scenes/$sc.lua" "$@"
}
# shellcheck source=/dev/null
. "$root/tests/run_share.sh"

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

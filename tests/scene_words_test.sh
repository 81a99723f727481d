#!/usr/bin/env bash
# scene_words_test.sh CASE HEARTH SOURCE_ROOT: every shipped scene and script with a word-valued parameter
# (h.choice, lua/hearth/params.lua) refuses a misspelt word before it makes anything: exit 2 (a bad --set), the
# message naming the scene file and line, the --set, the word given, each valid word with its description, and the
# nearest word. The words each case expects are written here, from the scene's header, not read from the scene.
# Cheap: the refusal comes at h.params, before any step (bread_tray_refused in baking_test.sh is bread.lua's own).
set -u
case_name=$1 hearth=$2 root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

contact=(grip separate slip sticky) # s:collider's modes (h.contact_words)
blend=(labels linear nonlinear)     # h.scene's blend modes (h.blend_words)

# refused FILE NAME=WORD NEAREST WORDS...: FILE (under the source root) run with --set NAME=WORD exits 2 naming
# FILE:line, the --set and the word, suggests NEAREST ("" for none), and lists each of WORDS ("" the empty word)
# on its own line with a description; nothing but the run record (run.json, run.log) is written. The message names `at` instead of FILE when set (a
# wrapper's word refused by the scene it runs, h.pass_params); extra: more options (the wrapper's scene path).
at= extra=()
refused() {
    local file=$1 set=$2 near=$3
    shift 3
    local name=${set%%=*} word=${set#*=}
    "$hearth" run "$root/$file" --quiet --out out "${extra[@]}" --set "$set" >out.txt 2>err.txt
    local rc=$?
    cat err.txt
    [ $rc -eq 2 ] || fail "$file --set $set: exit $rc, expected 2 (a bad --set)"
    local where=${at:-$file}
    grep -q "^hearth run: .*$where:[0-9]*: --set $name=$word: $name takes one of the words below, not \"$word\"" err.txt ||
        fail "$file --set $set: the message does not name $where, its line, the --set and the word"
    if [ -n "$near" ]; then
        grep -qF "did you mean \"$near\"?" err.txt || fail "$file --set $set: no suggestion of \"$near\""
    else
        grep -q "did you mean" err.txt && fail "$file --set $set: a suggestion for a word near none"
    fi
    local n=0 w
    for w in "$@"; do
        grep -qE "^  \"$w\" +[^ ]" err.txt || fail "$file --set $set: the word \"$w\" and its description are not listed"
        n=$((n + 1))
    done
    [ "$(grep -cE '^  "[^"]*" +[^ ]' err.txt)" -eq $n ] || fail "$file --set $set: listed words other than $*"
    local made
    made=$(find out -type f ! -name run.json ! -name run.log 2>/dev/null | head -3) # the run record is every run's
    [ -z "$made" ] || fail "$file --set $set: wrote $made"
}

case "$case_name" in
word_refused_loaf_physical_tray) refused scripts/scenes/baking/loaf_physical.lua tray=seperate separate separate sticky ;;
word_refused_muffins_preset) refused scripts/scenes/baking/muffins.lua preset=phisical physical paper physical ;;
word_refused_muffins_wall_mode) refused scripts/scenes/baking/muffins.lua wall_mode=slipp slip "${contact[@]}" ;;
word_refused_cookies_preset) refused scripts/scenes/baking/cookies.lua preset=physcal physical paper physical ;;
word_refused_cookies_tray_mode) refused scripts/scenes/baking/cookies.lua tray_mode=stiky sticky "${contact[@]}" ;;
word_refused_tear_open_food) refused scripts/scenes/baking/tear_open.lua food=mufin muffin bread muffin ;;
word_refused_marshmallow_only) refused scripts/scenes/baking/marshmallow.lua only=rwa raw "" raw roasted ;;
word_refused_marshmallow_mode) refused scripts/scenes/baking/marshmallow.lua mode=glued "" "${contact[@]}" ;;
word_refused_pancake_spatula) refused scripts/scenes/baking/pancake.lua spatula=sticy sticky "${contact[@]}" ;;
word_refused_pancake_preset) refused scripts/scenes/baking/pancake.lua preset=phisical physical paper physical ;;
word_refused_pancake_turn) refused scripts/scenes/baking/pancake.lua turn=smoth smooth constant smooth ;;
word_refused_lava_cake_preset) refused scripts/scenes/baking/lava_cake.lua preset=pysical physical paper physical ;;
word_refused_sph_bread_roll_bubbles) refused scripts/scenes/sph/bread_roll.lua bubbles=centr centre centre dispersed even ;;
word_refused_sph_bread_roll_mu_e_curve) refused scripts/scenes/sph/bread_roll.lua mu_e_curve=tabel table sourced table ;;
word_refused_nozzle_blend) refused scripts/scenes/sauces/nozzle.lua blend=linar linear "${blend[@]}" ;;
word_refused_ternary_blend) refused scripts/scenes/sauces/ternary.lua blend=label labels "${blend[@]}" ;;
# before h.choice, mixing under a linear blend took any word silently (the scene sets fixed there)
word_refused_cup_spoon_mixing) refused scripts/scenes/sauces/cup_spoon.lua mixing=dynamc dynamic dynamic fixed ;;
word_refused_cookie_cutter_mask) refused scripts/scenes/cookie_cutter.lua mask=str star gingerbread star ;;
word_refused_celery_dip_sauce | word_refused_steak_sauce)
    # Table 1's 21 sauces (assets/sauces.csv's names) and the scene's "mix"
    sauces=($(tail -n +2 "$root/assets/sauces.csv" | grep -v '^#' | cut -d, -f1) mix)
    [ ${#sauces[@]} -eq 22 ] || fail "assets/sauces.csv: ${#sauces[@]} - 1 sauces, expected Table 1's 21"
    sc=${case_name#word_refused_}
    sc=${sc%_sauce}
    refused "scripts/scenes/sauces/$sc.lua" sauce=myo mayo "${sauces[@]}"
    ;;
# validation scripts: rise_loaf's soft, slump_dt's material and marshmallow_skin's only passed any word silently
word_refused_rise_loaf_soft) refused scripts/validation/rise_loaf.lua soft=bth both both eta tau ;;
word_refused_slump_dt_material) refused scripts/validation/slump_dt.lua material=elastik elastic dough elastic ;;
word_refused_marshmallow_skin_only) refused scripts/validation/marshmallow_skin.lua only=roastd roasted "" raw roasted ;;
word_refused_bread3d_ends) refused scripts/validation/bread3d.lua ends=rund round cut round ;;
word_refused_bread3d_tray_mode) refused scripts/validation/bread3d.lua tray_mode=stiky sticky "" "${contact[@]}" ;;
# a wrapper's word passed on by h.pass_params is refused by the scene that declares it, naming that scene
word_refused_passed_to_bread)
    at=scripts/scenes/baking/bread.lua extra=(--set "bread=$root/$at")
    refused scripts/validation/bread3d.lua tray=stiky sticky separate sticky ;;
word_refused_passed_to_loaf_physical)
    at=scripts/scenes/baking/loaf_physical.lua extra=(--set "loaf=$root/$at")
    refused scripts/validation/loaf_whatif.lua tray=glue "" separate sticky ;;
word_refused_passed_to_muffins)
    at=scripts/scenes/baking/muffins.lua extra=(--set "muffins=$root/$at")
    refused scripts/validation/muffin_tear.lua wall_mode=slipp slip "${contact[@]}" ;;
*) fail "unknown case $case_name" ;;
esac
echo ok

#!/usr/bin/env bash
# lua_params_test.sh CASE HEARTH: a scene's numeric parameters declared with their valid range, h.number
# (lua/hearth/params.lua), as a user meets them through --set and --params, and through a wrapper's h.pass_params.
# The scene files are in tests/lua/; the helpers in lua_fixture.sh, shared with lua_test.sh.
. "$(dirname "$0")/lua_fixture.sh" "$@"

case "$case_name" in
params_number_set_in_range)
    # values inside the range, on its closed ends, and a declared extra value (also) all run
    run numbers.lua
    expect_rc 0 "the defaults"
    has out.txt "dx=0.005 cups=3 vent=5 height=0.3" "the defaults"
    run numbers.lua --set dx=0.05 --set cups=12 --set vent=-1 --set height=-7
    expect_rc 0 "the closed ends, also's -1, a plain number's any value"
    has out.txt "dx=0.05 cups=12 vent=-1 height=-7" "the values given"
    run numbers.lua --set cups=1 --set vent=0
    expect_rc 0 "the closed low ends"
    has out.txt "cups=1 vent=0" "the low ends"
    ;;
params_number_out_of_range_refused)
    # a value outside the range is a usage error (exit 2) at the scene's h.params line, naming the parameter,
    # what it means, the value and the range with its unit; nothing runs
    refuse() { # WHAT TEXT --set...
        local what=$1 text=$2
        shift 2
        run numbers.lua "$@"
        expect_rc 2 "$what"
        has_msg "numbers.lua:3: $text" "$what"
        grep -q "dx=" out.txt && fail "$what: the scene ran on past the refused value"
        return 0
    }
    refuse "dx at the strict bound" "--set dx=0: dx (the grid spacing) takes a number in (0, 0.05] m, not 0" --set dx=0
    refuse "dx negative" "--set dx=-1: dx (the grid spacing) takes a number in (0, 0.05] m, not -1" --set dx=-1
    refuse "dx past max" "--set dx=0.06: dx (the grid spacing) takes a number in (0, 0.05] m, not 0.06" --set dx=0.06
    refuse "a fraction of a count" "--set cups=2.5: cups (muffin cups in a row) takes a whole number in [1, 12], not 2.5" \
        --set cups=2.5
    refuse "below min" "--set cups=0: cups (muffin cups in a row) takes a whole number in [1, 12], not 0" --set cups=0
    refuse "neither in range nor also" \
        "--set vent=-2: vent (the CO2 vent velocity) takes a number in [0, inf) m/s; or -1: the preset's, not -2" --set vent=-2
    refuse "not a number" "--set dx=abc: dx (the grid spacing) takes a number in (0, 0.05] m, not abc" --set dx=abc
    refuse "infinite" "--set dx=1e999: dx (the grid spacing) takes a number in (0, 0.05] m, not inf" --set dx=1e999
    ;;
params_number_bad_default_refused)
    # the scene author's default outside its own range is the scene's error (exit 1), not the user's
    run numbers_bad_default.lua
    expect_rc 1 "a default outside the range"
    has_msg "numbers_bad_default.lua:3: h.params: cups's default: cups (muffin cups in a row) takes a whole number in [1, 12], not 0" \
        "the scene file, line, parameter, default and range"
    grep -q "ran with" out.txt && fail "the scene ran on past its bad default"
    run numbers_bad_default.lua --set cups=2
    expect_rc 1 "a default outside the range, even when --set gives a good value"
    ;;
params_number_declaration_errors)
    # h.number's own refusals name the call's line and what is wrong
    run number_errors.lua
    expect_rc 0 "number_errors.lua"
    has out.txt "no what: $scenes/number_errors.lua:7: h.number: what = \"a short meaning\" is required" "no what"
    has out.txt "no range: $scenes/number_errors.lua:8: h.number: give a range" "no range"
    has out.txt "empty range: $scenes/number_errors.lua:9: h.number: the range from 2 to 1 is empty" "empty range"
    has out.txt "min and above: $scenes/number_errors.lua:10: h.number: give min or above, not both" "min and above"
    has out.txt "unknown key: $scenes/number_errors.lua:11: h.number: unknown key mn" "unknown key"
    has out.txt "bound not finite: $scenes/number_errors.lua:12: h.number: max = inf is not a finite number" "infinite bound"
    has out.txt "not a table: $scenes/number_errors.lua:13: h.number: expected" "not a table"
    ;;
run_params_lists_ranges)
    # --params lists each numeric parameter's meaning, range and unit, and stops
    run numbers.lua --params
    expect_rc 0 "--params"
    has out.txt "  dx = 0.005" "dx's default"
    has out.txt "      the grid spacing: a number in (0, 0.05] m" "dx's meaning, range and unit"
    has out.txt "      muffin cups in a row: a whole number in [1, 12]" "a count's range"
    has out.txt "      the CO2 vent velocity: a number in [0, inf) m/s; or -1: the preset's" "an open end and also"
    has out.txt "  height = 0.3" "a plain number listed as before"
    grep -q "dx=" out.txt && fail "--params ran the scene"
    ;;
params_number_passed_through_refused)
    # h.pass_params: the scene's ranges hold for what a wrapper passes: the wrapper's own default the scene does
    # not take is the wrapper's error (exit 1) at the scene's h.params line; a --set passed on is a usage error (2)
    run numbers_wrapper.lua --set scene="$scenes/numbers.lua"
    expect_rc 1 "the wrapper's default the scene does not take"
    has_msg "numbers.lua:3: cups = 0, passed by the script's h.pass_params: cups (muffin cups in a row) takes a whole number in [1, 12], not 0" \
        "the scene file and line, the parameter, the value and the range"
    run numbers_wrapper.lua --set scene="$scenes/numbers.lua" --set cups=4
    expect_rc 0 "values the scene takes"
    has out.txt "dx=0.01 cups=4 vent=5 height=0.3" "passed on"
    run numbers_wrapper.lua --set scene="$scenes/numbers.lua" --set cups=4 --set dx=-1
    expect_rc 2 "a --set the scene refuses, passed on"
    has_msg "numbers.lua:3: --set dx=-1: dx (the grid spacing) takes a number in (0, 0.05] m, not -1" \
        "the scene file and line, the --set and the range"
    ;;
*)
    fail "unknown case $case_name"
    ;;
esac
echo "ok: $case_name"

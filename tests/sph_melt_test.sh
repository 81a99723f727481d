#!/usr/bin/env bash
# sph_melt_test.sh CASE HEARTH SOURCE_ROOT: the SPH melting block (#18; scripts/scenes/sph/melting_block.lua,
# Rodriguez-Arenas 2011 Fig. 3.14) run as a user runs it (its 2 s), measured from its particle positions
# alone (tests/sph_melt_measure.py). Wax or chocolate on a hot plate melts from below into a pool around a
# shrinking block. When the bars were set (7 Dec 2026, docs/validation.md "The melting block pools (#18, helper
# meltblock)"): the measures (links and heights of 2 DX, the 2 DX margin) before the no-slip tray first ran; the
# thresholds on rise, dip and spread after one 4 mm run of it with an earlier form of the wall drag and before
# any 3 mm run or the final form; the brief's four criteria, made precise:
#   claim_sph_melting_block_stays_whole[_fine]  the block slumps and spreads, it does not split: the centre
#       column's top never rises more than DX/2 from one 0.1 s frame to the next (the top of a particle
#       column moves by less than a spacing as it settles), at 2 s it is within 2 DX of the highest column
#       over the block's footprint (the split of main's free-slip tray left 11 mm at the centre beside
#       41 mm halves), and the largest piece reaches at least DX beyond the footprint on both sides
#   claim_sph_melting_block_pools[_fine]  at 2 s the material is one piece (particles linked within 2 DX)
#       and no particle beyond 2 DX outside the footprint stands more than 2 DX above the tray
# _fine runs at dx 3 mm instead of the scene's 4 mm. Exit 0 pass, 1 fail, 77 expected failure (prints
# the measured numbers and the cause).
here=$(cd "$(dirname "$0")" && pwd)
set -u
case_name=$1 hearth=$2 root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

dx=0.004 # the scene's default
case "$case_name" in *_fine) dx=0.003 ;; esac
"$hearth" run "$root/scripts/scenes/sph/melting_block.lua" --quiet --set dx=$dx >out.txt 2>err.txt ||
    fail "melting_block dx=$dx: exit $?: $(cat err.txt)"
cat out.txt
m=$(python3 "$here/sph_melt_measure.py" $dx hearth-out/melting_block) || fail "measure: $m"
echo "$m"
read -r _ n _ pieces _ share _ high _ highest _ rise _ dip _ left _ right <<<"$(head -1 <<<"$m")"
ok() { python3 -c "import sys; sys.exit(0 if ($1) else 1)"; }
dxmm=$(python3 -c "print($dx * 1e3)")
case "$case_name" in
claim_sph_melting_block_stays_whole*)
    ok "$rise <= 0.5 * $dxmm" || fail "the centre's top rose $rise mm between two frames (bar: DX/2)"
    ok "$dip <= 2 * $dxmm" || fail "at 2 s the centre's top is $dip mm below the footprint's highest column (bar: 2 DX): split"
    ok "$left >= $dxmm and $right >= $dxmm" ||
        fail "the material reaches $left mm left and $right mm right of the block's footprint (bar: DX = $dxmm mm each)"
    echo "PASS: $case_name: rise $rise mm, dip $dip mm, spread $left / $right mm beyond the footprint" ;;
claim_sph_melting_block_pools*)
    if [ "$pieces" = 1 ] && [ "$high" = 0 ]; then
        echo "PASS: $case_name: one piece, none high outside the footprint"
        exit 0
    fi
    msg="$pieces piece(s), the largest holding $share of the $n particles; $high particle(s) more than 2 DX above the tray beyond the footprint (the highest $highest mm)"
    # Expected failure, cause measured (docs/validation.md "The melting block pools"): at the melt's front
    # particles clump (at 4 mm three within 0.5-1.8 mm of each other at 1.91-1.93 s) and burst apart,
    # throwing one up at 0.42 m/s: the cubic spline's pressure gradient vanishes as r -> 0, the clustering
    # the thesis's spiky kernel for pressure (eq. 3.5-3.6, §3.1.1) avoids, not built here; and the melt's
    # mound at the block's foot stands a little over 2 DX. Both pieces beyond the largest are such loners.
    echo "XFAIL: $case_name: $msg. Cause: clumps at the melt's front burst (the cubic spline's pressure gradient vanishes at r -> 0; the thesis's spiky kernel, eq. 3.5-3.6, is not built), and the melt's mound at the foot stands just over 2 DX"
    exit 77 ;;
*) fail "unknown case $case_name" ;;
esac

#!/usr/bin/env bash
# sph_roll_test.sh CASE HEARTH SOURCE_ROOT: the SPH bread roll (#18;
# scripts/scenes/sph/bread_roll.lua, Rodriguez-Arenas 2011 Figs. 4.3-4.4, 4.8)
# run as a user runs it, measured from its particle positions alone
# (tests/sph_roll_measure.py: the dough's area with its closed gas cells, the
# torn share of its envelope, and the pieces linked at two raw spacings).
# A frame is whole when the roll is one piece and at most 2% of its envelope
# is torn (docs/validation.md "SPH bread roll (#18)", "A rise measure that
# excludes tears").
#   claim_sph_bread_roll_rises[_fine]      the rise's peak over the frames while the roll is whole >= 1.3x the raw roll's
#   claim_sph_bread_roll_one_piece[_fine]  every frame whole
#   claim_sph_bread_roll_sits_on_tray      from 0.5 s (settled) to 2 s, the largest gap under the middle 60% of
#                                          the roll's width (tests/sph_roll_base.py) under one raw spacing DX
# _fine runs at dx 1.5 mm instead of the scene's 2 mm. Exit 0 pass, 1 fail,
# 77 expected failure (prints the measured numbers and the cause).
here=$(cd "$(dirname "$0")" && pwd)
set -u
case_name=$1 hearth=$2 root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

dx=0.002 # the scene's default
case "$case_name" in *_fine) dx=0.0015 ;; esac
# 2 s of the 3 s bake: the roll's disc area passes 1.3x by 1.2 s (docs/validation.md "SPH
# bread roll (#18)"), and the hot dough's viscous step makes the last second cost minutes more
until=2
"$hearth" run "$root/scripts/scenes/sph/bread_roll.lua" --quiet --set dx=$dx --until $until >out.txt 2>err.txt ||
    fail "bread_roll dx=$dx: exit $?: $(cat err.txt)"
cat out.txt
d=hearth-out/bread_roll
# every frame (0.1 s apart) against the raw roll: the peak rise while whole, the first frame not whole
torn_max=0.02
peak=0 broken=
for f in $(ls $d/particles_*.csv | sort); do
    m=$(python3 "$here/sph_roll_measure.py" $dx $d/particles_0000.csv "$f") || fail "measure $f: $m"
    read -r _ ratio _ pieces _ share _ torn _ void <<<"$m"
    echo "$(basename "$f"): $m"
    [ -n "$broken" ] && continue
    if [ "$pieces" != 1 ] || python3 -c "import sys; sys.exit(0 if $torn > $torn_max else 1)"; then
        k=$(basename "$f" .csv) k=$((10#${k#particles_}))
        # particles_0000 is the raw roll, particles_NNNN (NNNN >= 1) the frame at t = (NNNN - 1) x 0.1 s
        broken="t = $(python3 -c "print(round(max($k - 1, 0) * 0.1, 1))") s ($(basename "$f")): $pieces piece(s), the largest holding $share of the particles, $torn of the envelope torn, the largest torn void $void raw particle areas"
        continue
    fi
    python3 -c "import sys; sys.exit(0 if $ratio > $peak else 1)" && peak=$ratio
done
# the base: every frame from 0.5 s (particles_0006; the raw disc touches the tray at one point and
# has settled onto it by then) to the last
gap_max=0 gap_at=
for f in $(ls $d/particles_*.csv | sort); do
    k=$(basename "$f" .csv) k=$((10#${k#particles_}))
    [ "$k" -lt 6 ] && continue
    b=$(python3 "$here/sph_roll_base.py" $dx 0.01 "$f") || fail "base $f: $b"
    read -r _ gap _ mean _ contact _ span <<<"$b"
    t=$(python3 -c "print(round(($k - 1) * 0.1, 1))")
    echo "t = $t s base: $b"
    python3 -c "import sys; sys.exit(0 if $gap > $gap_max else 1)" && gap_max=$gap gap_at=$t
done
case "$case_name" in
claim_sph_bread_roll_rises*)
    echo "dx $dx: peak rise $peak while whole by t = $until s; first frame not whole: ${broken:-none}"
    python3 -c "import sys; sys.exit(0 if $peak >= 1.3 else 1)" && exit 0
    echo "EXPECTED FAILURE: peak rise $peak < 1.3 at dx $dx while the roll was whole (first frame not whole: ${broken:-none}):" \
        "the dough films between the expanded bubbles are stretched thinner than a particle spacing and open" \
        "before the bubbles hold 1.3x the raw volume" >&2
    exit 77
    ;;
claim_sph_bread_roll_one_piece*)
    echo "dx $dx: first frame not whole to t = $until s: ${broken:-none}"
    [ -z "$broken" ] && exit 0
    echo "EXPECTED FAILURE: at dx $dx, ${broken}: the films between bubbles hold since the gas law's density sums" \
        "rest volumes, and the outline and tray side read no false skin since the preset renormalises that sum by" \
        "the kernel's filled part (sph.renormalised_density: whole to 2 s at 2 mm and at 1.5 mm, where the sum's" \
        "skin had slit it from 0.5 s); what tears now was not seen (docs/validation.md \"The films' tension\"," \
        "\"The roll's skin, renormalised\")" >&2
    exit 77
    ;;
claim_sph_bread_roll_sits_on_tray)
    echo "dx $dx: largest gap under the base $gap_max m (at t = $gap_at s) from 0.5 to $until s; one spacing is $dx m"
    python3 -c "import sys; sys.exit(0 if $gap_max < $dx else 1)" && exit 0
    echo "EXPECTED FAILURE: the roll's base lifts $gap_max m off the tray at t = $gap_at s (more than one spacing," \
        "$dx m): the dough of its bottom rows reads the hot bubbles beside it as a squeeze (the gas law's density" \
        "sums rest volumes, and a bubble the set dough holds below its gas volume spreads the difference over its" \
        "kernel) and holds 0.03-1.1 MPa (medians, 1.3-2.0 s at 2 mm) while its own det F says it is 13-43% expanded," \
        "beside bubbles at their own gas's 6-16 kPa; the tray only clips (eq. 3.33: no adhesion, no friction), so it" \
        "carries the roll's weight W = 21 N/m over a contact W / p wide (a tyre's law), 2 mm at the core's 10 kPa" \
        "(1.3 s), 0.06 mm at its 354 kPa (2 s): the set base arches off between two feet. Read by each particle's" \
        "own volume (sph.continuity_density) the roll keeps its base flat (within 1.2 mm to 1.5 s) but rises 1.14x" \
        "(docs/validation.md \"Why the roll's base leaves its tray\")" >&2
    exit 77
    ;;
*) fail "unknown case $case_name" ;;
esac

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
#   claim_sph_bread_roll_sits_on_tray[_fine] from 0.5 s (settled) to 2 s, the largest gap under the middle 60% of
#                                          the roll's width (tests/sph_roll_base.py) under one raw spacing DX
#   claim_sph_bread_roll_one_piece_whole_bake  every frame whole over the scene's whole 3 s bake (the others stop at 2 s)
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
# _whole_bake: the scene's own 3 s (what a user who runs it sees at the end; ~9 minutes at 2 mm)
case "$case_name" in *_whole_bake) until=3 ;; esac
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
    # whole to 2 s but short of 1.3x: not seen with the preset's set (MU_E_SET, helper rollset)
    [ -z "$broken" ] || fail "peak rise $peak < 1.3 at dx $dx, and the roll was not whole: $broken"
    echo "EXPECTED FAILURE: peak rise $peak < 1.3 at dx $dx, whole to $until s: the bubbles follow their gas" \
        "volume V_b(T) (eq. 3.49-3.50 with the vapour of eq. 2.42-2.43) only until the crumb sets; with the preset's" \
        "set (soft to 68 degC, 1 MPa at 80: McGee 2004's 68-80 degC) the roll rose 1.4281x at 2 mm and 1.4326x at" \
        "1.5 mm, whole; with eq. 4.2 of Table 4.1 x 100 (--set mu_e_curve=table), which passes the gas's 20 kPa at" \
        "45.3 degC, 1.14x (docs/validation.md \"The roll's set\", \"The roll's base: its own squeeze\")" >&2
    exit 77
    ;;
claim_sph_bread_roll_one_piece_whole_bake)
    echo "dx $dx: first frame not whole to t = $until s: ${broken:-none}"
    [ -z "$broken" ] && exit 0
    echo "EXPECTED FAILURE: at dx $dx, ${broken}. (With --set hourglass=1, sph.hourglass's damping of the" \
        "pairs' motion eq. 3.27 misses, the 2 mm roll was whole to 3 s, at most 1.17% torn at 1.4 s, but the" \
        "1.5 mm roll tore 2.08% at 2.0 s, so the preset leaves it off: helper sphhourglass.)" \
        "At 2 mm 2.02% of the outline is torn at 2.4 s (3.15% at 3 s)" \
        "because the bottom-centre bubble spot (8 bubbles at the gas law's cap V_b = 4, 1-2 dough rows above the" \
        "tray) splits sideways while the roll bounces on its tray (1.67-1.87 s, up to 1.5 mm in the air) and its" \
        "base bends with the ends off the tray: the spot's particles' x spread grows from 4.4 mm (1.7 s) to 6.9" \
        "(2.0 s), leaving a void from the tray up through it (4.2 raw particle areas at 2.0 s, 10.9 at 3 s); from" \
        "2.2 s spots inside the crumb open cavities too (4.4-7.9). A spot's gas carries no tension, and from 2.0 s" \
        "no pressure: past the dough's boiling point (101.5 degC at a_w 0.95) the gas law's stiffness P_a - a_w" \
        "P_sat(T) is 0 and the roll, which carries no water, passes it. The bounce is the roll's own noise on a" \
        "point contact, not the step control or the tray (helper sphbounce): from 1.3 s the convex base stands on" \
        "1-3 particles, and from 1.45 s single particles of the hot dough move at 0.25-0.6 m/s (20 in 1.5-1.8 s," \
        "fourteen of sixteen dough ones at p = 0 with a summed density 1.1-1.5x rest, many with a neighbour within" \
        "0.3-0.8 spacings: sph.own_squeeze takes the squeeze from det F, which does not see particles close, the" \
        "unit test sph_own_squeeze_resists_pairing); the tray, which takes only approach speeds, rectifies them." \
        "dt is the viscous limit's in every step (force and CFL limits 6x and 1.6x the step; a frame costs two half" \
        "steps; half the step with half XSPH's epsilons hopped 1.98 mm); frames every 20 ms seed another trajectory" \
        "that hopped 0.63 mm (0.1 s: 1.55 mm), and with" \
        "own_squeeze off the fast particles nearly vanish and the roll does not hop. Frames every 5 ms (sphtear) and" \
        "the 1.5 mm roll stayed whole to 3 s (at most 1.36% torn). Tried, not kept: the stiffness held at its" \
        "100 degC value (5.07 kPa) stayed whole to 3 s but its base lifted 13.6 mm; at its 95 degC value (20.8" \
        "kPa) a cavity opened at 2.1 s; with the dough's water (--set crust=true, the dough held at 100 degC)" \
        "cavities opened from 1.7 s and 2.05% was torn at 2.4 s; own_squeeze charging its own volumes' overlap" \
        "(det F drifts from the positions, median 9% by 1.5 s: the roll hopped at 1.8-2.0 s instead). No physical," \
        "shared fix found (docs/validation.md \"The roll's base tears after 2 s\", \"The roll's bounce on its tray\")" >&2
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
claim_sph_bread_roll_sits_on_tray | claim_sph_bread_roll_sits_on_tray_fine)
    echo "dx $dx: largest gap under the base $gap_max m (at t = $gap_at s) from 0.5 to $until s; one spacing is $dx m"
    python3 -c "import sys; sys.exit(0 if $gap_max < $dx else 1)" && exit 0
    echo "EXPECTED FAILURE: at dx $dx the roll's base lifts $gap_max m off the tray at t = $gap_at s, more than one" \
        "spacing: with the preset's set (soft to 68 degC, 1 MPa at 80, helper rollset) the roll rises 1.42-1.43x," \
        "and from 1.6 s (coolest particle 75 degC) its base turns convex under the set crust: the middle stays on" \
        "the tray, the ends lift (2 mm: 1.63 mm at 1.6 s, 3.83 at 1.9 s, 5.52 at 2.0 s, and with --set" \
        "hourglass=1, which stops the roll hopping, 2.28 mm at 1.9 s; 1.5 mm: 1.66 mm at 1.6 s," \
        "7.85 at 2.0 s, a slit up through the base crust):" \
        "the crumb's closed bubbles go on pushing their gas inside a set shell. A real crumb's cells open at the" \
        "set and its pressure leaves (McGee 2004); the model's bubbles stay closed. Opened at the set (tried, not" \
        "kept): at 80 degC, where mu_e is set, the base still lifted 3.35 mm (1.9 s) at a 1.3691x rise; at 74" \
        "degC it stayed on (0.83 mm) but the roll rose 1.2974x; opened as the dough round each cell sets (its" \
        "neighbours' mean mu_e at 1 MPa) the tray side's and crust's cells vented first, yet the base tilted 2.44" \
        "mm (1.7 s) at 1.3651x. The tray is a slip plane that never pulls: a tray that pulls 3 kPa per contact" \
        "area (tried with a body force, not kept: no measured baked-on adhesion was found) holds it within 1.83 mm" \
        "at 1.4087x; friction (beta_c 0.5: 6.31 mm) and the sticky tray (no slip, no pull: 10.25 mm, torn) lift" \
        "it more. With eq. 4.2 of Table 4.1 x 100" \
        "(--set mu_e_curve=table: the crumb set before 50 degC) the base stayed within 1.30 mm at 2 mm (2.43 mm at" \
        "1.5 mm) and the roll rose 1.14x (docs/validation.md \"The roll's set\", \"The roll's cells open at the" \
        "set\", \"The roll's cells open as their walls set\", \"The roll on a tray that holds\", \"The roll's base: its" \
        "own squeeze\")" >&2
    exit 77
    ;;
*) fail "unknown case $case_name" ;;
esac

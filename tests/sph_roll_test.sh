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
    # a plain test since the preset's sph.hourglass = 0.5 (helper rollglass): before it the claims' run tore
    # 2.02% at 2.4 s (the bottom-centre spot split while the roll hopped on its tray: helpers sphtear, sphbounce)
    fail "at dx $dx, ${broken}: with the preset's sph.hourglass = 0.5 the roll was whole to 3 s in all 4 runs" \
        "of an ensemble (--set shift=0,1,2 and warm=1e-6: at most 0.36, 1.81, 0.89, 1.71% torn), so a tear here is" \
        "either a change of the physics or a chance the ensemble did not see (docs/validation.md \"The hourglass" \
        "control over an ensemble\", \"The roll's base tears after 2 s\")"
    ;;
claim_sph_bread_roll_one_piece*)
    echo "dx $dx: first frame not whole to t = $until s: ${broken:-none}"
    [ -z "$broken" ] && exit 0
    echo "EXPECTED FAILURE: at dx $dx, ${broken}: the films between bubbles hold since the gas law's density sums" \
        "rest volumes, and the outline and tray side read no false skin since the preset renormalises that sum by" \
        "the kernel's filled part (sph.renormalised_density: whole to 2 s at 2 mm and at 1.5 mm, where the sum's" \
        "skin had slit it from 0.5 s); what tears now was not seen (docs/validation.md \"The films' tension\"," \
        "\"The roll's skin, renormalised\"). Seen since the oven's flux crosses the film (helper sphflux): at 1.5 mm" \
        "the roll tore 2.69% at 1.6 s. Traced (helper rolltear): the tear is one of the base's bubble spots, which" \
        "the seeding and the raw slump put on the 180 degC tray with 0-2 dough particles under them, opening onto" \
        "the tray as a void 9.4 mm tall whose bubbles keep their gas (the cells stay closed: sits_on_tray's cause)," \
        "not a base that lifts; the film (1/1.017 of the flux off the tray, none by it) keeps the spots within 0.1 K" \
        "to 1 s and changes whether that spot's floor of 2-5 particles gives way: with it the floor went (2.69%; 2.70%" \
        "with a 1e-6 K warmer seed, which shares the first 1.3 s), yet with a 0.3 K warmer seed, the film's own size, it held" \
        "(whole to 1.7 s, 1.18%): chance, not the film; without it no spot opened and the base's left" \
        "third arched 4.3-5.9 mm instead (0.86% torn) (docs/validation.md \"The 1.5 mm roll's tear traced\")." \
        "With the cells on the outer surface venting (--set vent=true, sph.surface_vent, off in the preset; helper" \
        "sphvent) the 1.5 mm roll was whole to 2 s (at most 0.83% torn, rise 1.3655x), while the 2 mm roll rocked" \
        "6.29 mm off its tray (\"Cells open to the air vent\"); with the tray side not venting (helper ventrock)" \
        "one 2 mm run stayed level (3.42 mm) and one (--set warm=0.3) tore its top 2.51% at 2.0 s; of two 1.5 mm" \
        "runs one was whole (0.82%) and one (--set" \
        "warm=0.3) tore 2.87% at 2.0 s at that base spot, open onto the air gap under the lifted base, which a" \
        "cell within h of the tray does not vent into (\"The vented roll rocked because its tray side vented\")" >&2
    exit 77
    ;;
claim_sph_bread_roll_sits_on_tray | claim_sph_bread_roll_sits_on_tray_fine)
    echo "dx $dx: largest gap under the base $gap_max m (at t = $gap_at s) from 0.5 to $until s; one spacing is $dx m"
    python3 -c "import sys; sys.exit(0 if $gap_max < $dx else 1)" && exit 0
    echo "EXPECTED FAILURE: at dx $dx the roll's base lifts $gap_max m off the tray at t = $gap_at s, more than one" \
        "spacing: with the preset's set (soft to 68 degC, 1 MPa at 80, helper rollset) the roll rises 1.42-1.43x," \
        "and from 1.6 s (coolest particle 75 degC) its base turns convex under the set crust: the middle stays on" \
        "the tray, the ends lift (with the preset's sph.hourglass = 0.5, 2 mm: 2.56 mm at 1.6 s, 4.46 at 1.9 s," \
        "5.94 at 2.0 s; with the oven's heat on the outer surface (sph_outer.c, helper angelheat) 7.92 at 2.0 s; with" \
        "eq. 3.51 stopped at the gas's volume and each outer particle's share of the face (helper deadbread) 3.96 mm" \
        "at 1.7 s, 2.53 at 2.0 s, a 1.4167x rise (the same run read by claim_sph_bread_roll_rises);" \
        "1.5 mm: 6.24 mm at 1.4 s, 2.8-4.3 after; before it, 2 mm: 1.63 mm at 1.6 s, 5.52 at 2.0 s;" \
        "1.5 mm: 1.66 mm at 1.6 s, 7.85 at 2.0 s, a slit up through the base crust; helper rollglass):" \
        "the crumb's closed bubbles go on pushing their gas inside a set shell. A real crumb's cells open at the" \
        "set and its pressure leaves (McGee 2004); the model's bubbles stay closed. Measured before the hourglass" \
        "control: opened at the set (tried, not kept): at 80 degC, where mu_e is set, the base still lifted 3.35 mm (1.9 s) at a 1.3691x rise; at 74" \
        "degC it stayed on (0.83 mm) but the roll rose 1.2974x; opened as the dough round each cell sets (its" \
        "neighbours' mean mu_e at 1 MPa) the tray side's and crust's cells vented first, yet the base tilted 2.44" \
        "mm (1.7 s) at 1.3651x. The tray is a slip plane that never pulls: a tray that pulls 3 kPa per contact" \
        "area (tried with a body force, not kept: no measured baked-on adhesion was found) holds it within 1.83 mm" \
        "at 1.4087x; friction (beta_c 0.5: 6.31 mm) and the sticky tray (no slip, no pull: 10.25 mm, torn) lift" \
        "it more. With eq. 4.2 of Table 4.1 x 100" \
        "(--set mu_e_curve=table: the crumb set before 50 degC) the base stayed within 1.30 mm at 2 mm (2.43 mm at" \
        "1.5 mm) and the roll rose 1.14x (docs/validation.md \"The roll's set\", \"The roll's cells open at the" \
        "set\", \"The roll's cells open as their walls set\", \"The roll on a tray that holds\", \"The roll's base: its" \
        "own squeeze\"). At 1.5 mm with the oven's film the largest gap (9.4 mm at 1.6 s) is a base bubble spot open" \
        "onto the tray, a void whose bubbles keep their gas, not a lift; without the film, the base's left third" \
        "arching 4.3-5.9 mm (\"The 1.5 mm roll's tear traced\"). With the cells on the outer surface venting" \
        "(--set vent=true, sph.surface_vent, off in the preset; helper sphvent) the gap was 3.88 mm at 1.9 s at" \
        "1.5 mm (no spot opened) and 6.29 mm at 2.0 s at 2 mm, the roll rocking on its tray: the core's closed" \
        "cells still push (\"Cells open to the air vent\"). The rocking was the tray side's cells venting (the" \
        "bottom fifth's gas 0.53 of raw at 2 s): with them closed (helper ventrock) 3.42 mm at 1.7 s at 2 mm, level," \
        "and 4.42 / 8.12 mm at 1.5 mm (\"The vented roll rocked because its tray side vented\")" >&2
    exit 77
    ;;
*) fail "unknown case $case_name" ;;
esac

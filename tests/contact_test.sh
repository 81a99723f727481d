#!/usr/bin/env bash
# contact_test.sh CASE HEARTH SOURCE_ROOT: a body rests on what it touches (#18, helper traygap). A block of
# h.library.dough.bread (4 x 2 cm, 0.25 s) released at rest `lift` cells above a face (tests/contact/drop.lua) must come to rest
# with its lowest particle at its half-spacing h_p = dx/4 (2D's 4 particles a cell): where a lattice-seeded
# body's lowest row sits on a face. Bars, set before the runs: within 0.05 dx of h_p (a cell's twentieth: the
# defect left it 0.6-0.8 dx above h_p), and stopped: the lowest particle moves less than 0.01 dx over the last
# 40% of the run (a bounce or a creep moves it more; before the fix the 1 dx drop onto the tray still moved
# 0.014 dx there at 5 mm). A block seeded on the face (lift 0, its jittered lowest particle at ~0.126 dx) must
# stay where it is: within 0.01 dx of its start, and stopped as above.
# Exit 0 pass, 1 fail.
set -u
case_name=$1 hearth=$2 root=$3
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
bad=0

# drop LIFT ARGS...: run the drop and judge it; a lift of 0 is the resting block
drop() {
    local lift=$1
    shift
    "$hearth" run "$root/tests/contact/drop.lua" --quiet --set lift="$lift" --set t=0.25 --set w=0.04 --set ht=0.02 "$@" >out.txt 2>err.txt ||
        { echo "FAIL: drop.lua lift=$lift $*: exit $?: $(cat err.txt)" >&2; exit 1; }
    python3 - out.txt "$lift" "$*" <<'PY' || bad=1
import re, sys
lines = open(sys.argv[1]).read().splitlines()
lift, args = float(sys.argv[2]), sys.argv[3]
start = float(re.search(r"t 0.00 lowest (\S+)", lines[0]).group(1))
r = dict(kv.split("=") for kv in lines[-1].split()[1:])
low, spread, hp = float(r["lowest"]), float(r["spread"]), float(r["hp"])
if lift == 0:
    ok = abs(low - start) < 0.01 and spread < 0.01
    print(f"{args} resting: lowest particle {start:.4f} -> {low:.4f} dx, moving {spread:.4f} dx late "
          f"(need within 0.01 of its start, < 0.01): {'ok' if ok else 'FAIL'}")
else:
    ok = abs(low - hp) <= 0.05 and spread < 0.01
    print(f"{args} dropped {lift:g} dx: rests with its lowest particle {low:.4f} dx above the face, moving {spread:.4f} "
          f"dx late (need {hp - 0.05:.2f}..{hp + 0.05:.2f}, < 0.01): {'ok' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
}

case "$case_name" in
drop_rests_on_separate_tray) for l in 1 2; do drop $l; done ;;
drop_rests_on_separate_tray_fine) for l in 1 2; do drop $l --set dx=0.0025; done ;;
drop_rests_on_floor_wall) for l in 1 2; do drop $l --set face=wall; done ;;
drop_rests_on_floor_wall_fine) for l in 1 2; do drop $l --set face=wall --set dx=0.0025; done ;;
resting_block_stays_on_tray_and_floor) drop 0; drop 0 --set face=wall; drop 0 --set mode=slip ;;
drop_rests_on_slip_tray) drop 1 --set mode=slip; drop 1 --set mode=slip --set dx=0.0025 ;;
# a sticky face holds what has touched it (mpm_touch.c's glue): the same bars (set before the runs); before glue
# the 1 and 2 dx drops stayed caught at 1.000 and 0.980 dx (main 9c8120c)
drop_rests_on_sticky_tray) for l in 1 2; do drop $l --set mode=sticky; done ;;
drop_rests_on_sticky_tray_fine) for l in 1 2; do drop $l --set mode=sticky --set dx=0.0025; done ;;
drop_rests_on_sticky_floor_wall) for l in 1 2; do drop $l --set mode=sticky --set face=wall; done ;;
resting_block_stays_on_sticky_tray_and_floor) drop 0 --set mode=sticky; drop 0 --set mode=sticky --set face=wall ;;
drop_rests_on_separate_tray_between_rows | drop_rests_on_separate_tray_between_rows_fine)
    # The separate tray between node rows (#18, helper restinghold): drop_rests_on_separate_tray's drops (1 and 2 dx,
    # the same bars, set before these runs) with the tray `off` cells above the node row under it (drop.lua's off;
    # the on-row cases above are off 0). Main's separate face holds only the rows on or inside it, so the block's
    # weight rests on rows f dx under the face and its foot sinks: lowest particle 0.149 and 0.094 dx at off 0.75
    # (5 mm, lift 1 and 2), 0.123 and 0.068 at 2.5 mm, against h_p = 0.25. Holding the first row above the face where
    # the body touches it (touchrows' SEPARATE_NEAR_BAND, reverted) rested every drop at 0.250-0.251 dx.
    dx=0.005; [ "$case_name" = drop_rests_on_separate_tray_between_rows_fine ] && dx=0.0025
    for off in 0.25 0.5 0.75; do for l in 1 2; do drop $l --set off=$off --set dx=$dx; done; done
    if [ $bad -ne 0 ]; then
        echo "EXPECTED FAILURE: a separate face holds only the node rows on or inside it, so a body resting on a tray" \
            "f dx above the row under it is held up through the rows f dx and more under the face: its foot sinks" \
            "below its half-spacing, the more the larger f (the lines above). The fix that met these bars (holding" \
            "the first row above the face where the body touches it, SEPARATE_NEAR_BAND) was reverted: it failed the" \
            "stability matrix's newtonian drop at cfl 1 (docs/validation.md, 'The separate tray between node rows')"
        exit 77
    fi
    ;;
drop_rests_in_3d) # a 3 x 1.5 x 3 cm block at 5 mm (8 particles a cell, 1728 particles)
    drop 1 --set dim=3 --set w=0.03 --set ht=0.015; drop 2 --set dim=3 --set w=0.03 --set ht=0.015 --set face=wall ;;
glued_sheet_passes_second_sticky_face)
    # glue is per face (mpm_touch.c): a sheet glued under a sticky plate moving sideways at 5 cm/s, its lower row
    # 0.75 dx over a sticky tray it never touches (its glued upper row within the stencil of the tray's face row),
    # is carried with the plate: its mean x displacement and its lower row's over 0.2 s each within 0.01 of the
    # plate's (bar set before the run: an elastic sheet, E = 1e6 Pa, carried unhindered, lags by nothing at this
    # scale; a tray that held any glued particle's stencil would drag the lower row), and the lower row stays put
    # in height (within 0.01 dx: the tray does not grab it)
    "$hearth" run "$root/tests/contact/two_faces.lua" --quiet >out.txt 2>err.txt ||
        { echo "FAIL: two_faces.lua: exit $?: $(cat err.txt)" >&2; exit 1; }
    python3 - out.txt <<'PY' || bad=1
import sys
r = dict(kv.split("=") for kv in open(sys.argv[1]).read().split("result")[-1].split())
a, l = float(r["carried"]), float(r["lower"])
y0, y1 = (float(v) for v in r["lower_row_dx"].split("->"))
ok = abs(a - 1) <= 0.01 and abs(l - 1) <= 0.01 and abs(y1 - y0) <= 0.01
print(f"sheet carried {a:.4f} of the plate's travel, its lower row {l:.4f}, that row {y0:.4f} -> {y1:.4f} dx over the "
      f"tray (need 0.99..1.01, 0.99..1.01, within 0.01): {'ok' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
    ;;
thin_plate_holds_pressed_block | thin_plate_holds_pressed_block_3d)
    # A thin plate presses a soft block (helper marshfall, tests/contact/thin_plate.lua): marshmallow.lua's crackers are
    # 4 mm, two cells at its 2D dx and one at its 3D dx, and a thin MPM collider could let particles through (a plate
    # under a cell may hold no node inside it, and collider_project_particle sends a particle past its mid-plane out of
    # the far face). Bars: no particle past the plate's mid-plane at any of 20 samples, and the plate pressed the block
    # (its top came down at least press - dx, the plate in contact throughout: not a pass by missing it). Set after
    # probe runs on main that held (plates 0.25 to 1 dx, 0.02 to 0.5 m/s, on and off the node rows): a guard of what
    # the marshmallow's fall was found not to be (docs/validation.md, "Particles below the marshmallow's crackers").
    runs=("--set thick=0.25" "--set thick=1" "--set thick=0.25 --set mode=slip" "--set thick=1 --set mode=slip")
    [ "$case_name" = thin_plate_holds_pressed_block_3d ] &&
        runs=("--set dim=3 --set dx=0.004 --set thick=1" "--set dim=3 --set dx=0.004 --set thick=0.25 --set mode=slip")
    for a in "${runs[@]}"; do
        # shellcheck disable=SC2086 # each entry is its --set words
        "$hearth" run "$root/tests/contact/thin_plate.lua" --quiet $a >out.txt 2>err.txt ||
            { echo "FAIL: thin_plate.lua $a: exit $?: $(cat err.txt)" >&2; exit 1; }
        python3 - out.txt "$a" <<'PY' || bad=1
import re, sys
args = sys.argv[2]
r = dict(kv.split("=") for kv in open(sys.argv[1]).read().split("result")[-1].split())
past, hi, pressed = int(r["past"]), float(r["highest"]), float(r["pressed"])
dx = float(re.search(r"dx=(\S+)", args).group(1)) if "dx=" in args else 0.002
need = 0.008 - dx
ok = past == 0 and pressed >= need
print(f"{args}: {past} particles past the plate's mid-plane at most, the block pressed {pressed * 1e3:.2f} mm, its top "
      f"{hi:.3f} dx over the plate's face at the end (need 0, >= {need * 1e3:.1f} mm): {'ok' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
    done
    ;;
drop_same_bits_threads)
    # the grid update's touch test reads particles only: the same bits at 1 and 2 threads (an 8 x 4 cm block at
    # 2 mm: 3200 particles, past SCENE_PARALLEL_MIN, so 2 threads take the gather's one-region step)
    for t in 1 2; do
        "$hearth" run "$root/tests/contact/drop.lua" --quiet --threads $t --set lift=1 --set t=0.04 --set w=0.08 \
            --set ht=0.04 --set dx=0.002 >o$t.txt 2>err.txt || { echo "FAIL: drop.lua --threads $t: $(cat err.txt)" >&2; exit 1; }
    done
    a=$(tail -1 o1.txt) b=$(tail -1 o2.txt)
    echo "1 thread: $a"; echo "2 threads: $b"
    [ "$a" = "$b" ] || bad=1
    ;;
drop_rests_across_periodic_seam)
    # tests/contact/seam.lua: a block split across the seam of a box periodic in x lands on the separate floor
    # from 1 and 2 cells up; its lowest particle within 6 mm of the seam must rest within 0.05 dx of its
    # half-spacing, as anywhere else (the bar of the drops above, set before the run)
    for l in 1 2; do
        "$hearth" run "$root/tests/contact/seam.lua" --quiet --set lift=$l >out.txt 2>err.txt ||
            { echo "FAIL: seam.lua lift=$l: exit $?: $(cat err.txt)" >&2; exit 1; }
        python3 - out.txt $l <<'PY' || bad=1
import sys
r = dict(kv.split("=") for kv in open(sys.argv[1]).read().split("result")[-1].split())
low, seam, hp = float(r["lowest"]), float(r["seam"]), float(r["hp"])
ok = abs(seam - hp) <= 0.05 and abs(low - hp) <= 0.05
print(f"dropped {sys.argv[2]} dx across the periodic seam: lowest {low:.4f} dx, by the seam {seam:.4f} dx "
      f"(need {hp - 0.05:.2f}..{hp + 0.05:.2f}): {'ok' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
    done
    ;;
separate_tray_slide_stops_between_rows | separate_tray_spread_same_between_rows)
    # The separate tray between node rows (#18, helper touchrows; tests/contact/spread.lua): the tray `off` cells
    # above the node row under it, off 0 (a row on the tray), 0.25, 0.5, 0.75, at 5 and 2.5 mm. Bars:
    #  - slide: a 6 x 2 cm elastic block given 0.2 m/s along the tray (friction 0.4) stops, its mean move within 5%
    #    of a rigid block's Coulomb stop u^2 / (2 mu g) = 5.097 mm at every offset (the reference is not the code's;
    #    5%: the on-row runs' own error is 1.5%). Before SEPARATE_NEAR_BAND: 5.76 mm (+13%) at off 0.5, 6.00 (+18%)
    #    at off 0.75 (2.5 mm).
    #  - spread: the block pushed outward by a body force (A = 200 s^-2) comes to rest; its base's edge moves out
    #    by the on-row run's amount within 0.2 of the top edge's on-row move (~0.1 mm: the foot's hold must not
    #    depend on the offset by more than a fifth of what the block spreads) at each dx, and the lowest particle
    #    rests within 0.05 dx of its half-spacing (dx / 8 at 16 particles a cell; the drops' bar above). Before
    #    SEPARATE_NEAR_BAND the base moved 0.018 mm on a row and 0.136 at off 0.75 (5 mm), the foot sank to 0.084 dx.
    #  Both bars were set after the defect's runs on main (docs/validation.md says which numbers came first).
    #  Expected failures: the band that met them (SEPARATE_NEAR_BAND) moved the stability matrix and was reverted.
    mode=spread; [ "$case_name" = separate_tray_slide_stops_between_rows ] && mode=slide
    : >all.txt
    for dx in 0.005 0.0025; do
        for off in 0 0.25 0.5 0.75; do
            extra="--set A=200"; [ $mode = slide ] && extra="--set mode=slide --set t=0.15"
            "$hearth" run "$root/tests/contact/spread.lua" --quiet --set dx=$dx --set off=$off $extra >out.txt 2>err.txt ||
                { echo "FAIL: spread.lua dx=$dx off=$off: exit $?: $(cat err.txt)" >&2; exit 1; }
            echo "dx=$dx off=$off $(tail -1 out.txt)" >>all.txt
        done
    done
    python3 - all.txt $mode <<'PY'
import sys
mode, ok = sys.argv[2], True
rows = []
for line in open(sys.argv[1]):
    a, b = line.split("result")
    r = dict(kv.split("=") for kv in (a + b).split())
    rows.append({k: float(v) for k, v in r.items()})
stop = 0.2 ** 2 / (2 * 0.4 * 9.81) * 1000
for dx in sorted({r["dx"] for r in rows}, reverse=True):
    rs = [r for r in rows if r["dx"] == dx]
    on = next(r for r in rs if r["off"] == 0)
    for r in rs:
        if mode == "slide":
            good = abs(r["slid"] / stop - 1) <= 0.05
            print(f"dx {dx * 1000:g} mm, tray {r['off']:.2f} dx above a row: slid {r['slid']:.3f} mm "
                  f"(Coulomb stop {stop:.3f}, need within 5%: {100 * (r['slid'] / stop - 1):+.1f}%): {'ok' if good else 'FAIL'}")
        else:
            dev = abs(r["base"] - on["base"])
            good = dev <= 0.2 * on["top"] and abs(r["lowest"] - 0.125) <= 0.05
            print(f"dx {dx * 1000:g} mm, tray {r['off']:.2f} dx above a row: base edge out {r['base']:.4f} mm (on a row "
                  f"{on['base']:.4f}; off by {dev:.4f}, need <= {0.2 * on['top']:.4f}), top {r['top']:.4f} mm, lowest "
                  f"{r['lowest']:.4f} dx (need 0.075..0.175): {'ok' if good else 'FAIL'}")
        ok = ok and good
if ok:
    sys.exit(0)
print("EXPECTED FAILURE: a separate face holds only the node rows on or inside it, so with the tray f dx above the "
      "row under it a foot particle resting dx/8 over it is held through 0.80 of its B-spline weight on a row, 0.61 / "
      "0.38 / 0.20 at f = 0.25 / 0.5 / 0.75, and the free row above gives it its sliding velocity: the foot slides "
      "further and the block overshoots Coulomb's stop between rows (the rows above). Holding the first row above a "
      "face between rows where the body touches it (SEPARATE_NEAR_BAND 0.99 dx, helper touchrows) met both bars "
      "(slide within 1.7%, base within 0.015 mm) but was reverted: in the stability matrix the newtonian block "
      "dropped at cfl 1 then stopped late on the CFL guard, and the 400 degC snow_plastic block's guard named an "
      "inverted F instead of thermal expansion (cli_guard_expansion_named) (docs/validation.md, 'The separate tray "
      "between node rows')")
sys.exit(77)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || bad=1
    ;;
drop_rests_on_pebbles)
    # A block rests on what it touches when that is another body (helper pancakeheat, #18; tests/contact/pebble.lua):
    # an elastic block released a cell above two one-particle pebbles lying on a separate tray must come to rest on
    # them: its lowest particle over them within 0.25 dx of where touching puts it (a pebble's top plus the block's
    # half-spacing). The bar set before pebble.lua's first run (after one trial of a block tipping on a single
    # pebble, 1.28 dx over the contact height at 2 mm). The pancake's physical preset lands on such pebbles, the
    # strands its raw side dripped (docs/validation.md, "The pancake's middle at 2 mm"). An expected failure (77)
    # while the block stays a cell up; the released height beside it (--set lift=0.25) is printed for contrast.
    "$hearth" run "$root/tests/contact/pebble.lua" --quiet >out.txt 2>err.txt ||
        { echo "FAIL: pebble.lua: exit $?: $(cat err.txt)" >&2; exit 1; }
    "$hearth" run "$root/tests/contact/pebble.lua" --quiet --set lift=0.25 >near.txt 2>err.txt ||
        { echo "FAIL: pebble.lua --set lift=0.25: exit $?: $(cat err.txt)" >&2; exit 1; }
    python3 - out.txt near.txt <<'PY'
import sys
def result(path):
    line = [l for l in open(path).read().splitlines() if l.startswith("result ")][-1]
    return {k: float(v) for k, v in (kv.split("=") for kv in line.split()[1:])}
r, n = result(sys.argv[1]), result(sys.argv[2])
print(f"dx 2 mm, released 1 dx above two one-particle pebbles: the block rests {r['over']:.4f} dx above the tray over "
      f"them, {r['away']:.4f} dx midway; touching them it would stand at {r['contact']:.4f} dx (need within 0.25 of "
      f"it); released 0.25 dx above them: {n['over']:.4f} dx")
if abs(r["over"] - r["contact"]) <= 0.25:
    sys.exit(0)
print(f"EXPECTED FAILURE: the block stays {r['over'] - r['contact']:.2f} dx above the pebbles it never touches. MPM "
      "with one velocity field couples two bodies through the grid nodes their stencils share, up to 1.5 dx apart: "
      "the pebble lies on the tray, which holds the node row on its face, and the block's lowest row shares the row "
      "above it with the pebble, so the block's weight goes through that row into the pebble, which the tray holds. Colliders hold a node only where a particle touches them "
      "(core/sim/solver/mpm_touch.c); two bodies have no such test (a second velocity field where they meet, "
      "Bardenhagen et al. 2000, would be one)")
sys.exit(77)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || bad=1
    ;;
drop_rests_on_pebbles_two_field)
    # drop_rests_on_pebbles's drops (released 1 and 0.25 dx above the pebbles) with two_field = true (helper
    # bodycontact, #18): a node two bodies' stencils share is split by body, and the bodies push on each other only
    # where they touch (core/sim/solver/mpm_two_field.c). The bar is drop_rests_on_pebbles's, set before its first run:
    # the block's lowest particle over the pebbles within 0.25 dx of where touching puts it, both drops.
    for l in 1 0.25; do
        "$hearth" run "$root/tests/contact/pebble.lua" --quiet --set two_field=true --set lift=$l >out.txt 2>err.txt ||
            { echo "FAIL: pebble.lua --set two_field=true --set lift=$l: exit $?: $(cat err.txt)" >&2; exit 1; }
        python3 - out.txt $l <<'PY' || bad=1
import sys
line = [l for l in open(sys.argv[1]).read().splitlines() if l.startswith("result ")][-1]
r = {k: float(v) for k, v in (kv.split("=") for kv in line.split()[1:])}
ok = abs(r["over"] - r["contact"]) <= 0.25
print(f"dx 2 mm, two fields, released {sys.argv[2]} dx above two one-particle pebbles: the block rests {r['over']:.4f} dx "
      f"above the tray over them, {r['away']:.4f} dx midway, the pebbles' top {r['pebble']:.4f} dx; touching them it "
      f"would stand at {r['contact']:.4f} dx (need within 0.25 of it): {'ok' if ok else 'FAIL'}")
sys.exit(0 if ok else 1)
PY
    done
    ;;
*) echo "unknown case $case_name" >&2; exit 1 ;;
esac
[ $bad -eq 0 ] || { echo "FAIL: $case_name (numbers above)" >&2; exit 1; }

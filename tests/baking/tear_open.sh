# shellcheck shell=bash
# tests/baking/tear_open.sh: tear_open.lua: baked muffins and loaves torn open by hand (Figs. 2 and 16): cooked
# inside, stretched before tearing when raw, two halves.
# Sourced by tests/baking_test.sh, whose variables (case_name, hearth, root, scenes, COARSE) and
# functions (run, fail) it uses. An arm exits with its verdict or falls through to the driver's "ok"; any other
# case leaves `unmatched` set for the next part.
case "$case_name" in
# #18, Ding Figs. 2 and 16 (helper tearopen): a muffin and a loaf torn open after baking. tear_open.lua bakes one
# muffin (3 s, muffins.lua's whole bake) or one plain loaf (2.5 s, bread.lua's), takes it out (oven off, cup or tray
# away) and pulls its outer thirds straight apart at 0.05 m/s each for 0.4 s (40 mm). Torn through: the intact
# material (damage below 1) in two pieces or more (its `pieces`), by the end of the pull. The torn interior is
# cooked: every particle the pull exposed (face_particles) reached the food's set temperature at some frame (the
# lowest face_peak_min_degC over the pull, a lower bound since frames sample the peak): the muffin's 55 degC, where
# its batter leaves its melted value and starts to set (lua/hearth/dough.lua MUFFIN_SET, wheat starch's
# gelatinisation onset), the bread's 70 degC, Fig. 8's theta_4, where its tau_y reaches the set x20 and its crumb's
# stretch to fracture 0.15 (dough.lua THETA, SET). At the scene's dx and one finer (muffin 4 / 3 mm, bread 5 / 4).
claim_muffin_tears_open | claim_muffin_tears_open_fine | claim_bread_tears_open | claim_bread_tears_open_fine | \
claim_muffin_torn_interior_cooked | claim_muffin_torn_interior_cooked_fine | claim_bread_torn_interior_cooked | \
claim_bread_torn_interior_cooked_fine)
    food=muffin dx=0.004 set=55
    case $case_name in *bread*) food=bread dx=0.005 set=70 ;; esac
    case $case_name in *muffin*_fine) dx=0.003 ;; *bread*_fine) dx=0.004 ;; esac
    what=tears
    case $case_name in *cooked*) what=cooked ;; esac
    run tear_open --set food=$food --set dx=$dx >/dev/null
    python3 - hearth-out/tear_open/tear_open.csv $food $dx $set $what <<'PY'
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
food, dx, theta, what = sys.argv[2], float(sys.argv[3]), float(sys.argv[4]), sys.argv[5]
pull = [r for r in rows if float(r["separation_m"]) > 0]
torn = [r for r in pull if int(r["pieces"]) >= 2]
first = f"{float(torn[0]['separation_m']) * 1e3:.1f} mm" if torn else "never"
end = rows[-1]
print(f"baked {food}, dx {dx * 1e3:.0f} mm: torn through (two pieces) first at {first} of separation; at the end "
      f"({float(end['separation_m']) * 1e3:.0f} mm) {end['pieces']} pieces, neck {float(end['neck_m']) * 1e3:.1f} mm, "
      f"{end['cracked']} cracked; peak force through the middle {max(float(r['force_mid_N_per_m']) for r in pull):.1f} N/m")
if what == "tears":
    sys.exit(0 if int(end["pieces"]) >= 2 else 1)
faces = [r for r in pull if int(r["face_particles"]) > 0]
low = min((float(r["face_peak_min_degC"]) for r in faces), default=math.nan)
print(f"the torn faces: up to {max((int(r['face_particles']) for r in faces), default=0)} particles a frame, the "
      f"coolest's peak {low:.2f} degC (need >= {theta:g} degC, the {food}'s set)")
sys.exit(0 if torn and faces and low >= theta else 1)
PY
    [ $? -eq 0 ] || fail "the baked $food does not tear open cooked ($what; numbers above)"
    ;;
# #18 (helper tearopen): the baker's contrast, raw dough is extensible and baked crumb tears. The same pull of the
# same shape unbaked (tear_open.lua --set raw=true: into the grips at its own temperature, at t = 0) parts only at
# twice the separation the baked one parts at, or not within the pull (40 mm). Twice, from the two laws: the set
# crumb cracks where its stretch reaches 0.15 (dough.lua SET), so across the free third (27 mm of loaf, 17 of
# muffin) it parts within a few mm; the raw dough never cracks (its stretch to fracture is 100) and parts only by
# flowing thin (Cam-clay's porous yield in tension, pull_twist.lua). The bread is the baker's dough; the muffin's
# raw batter (20 Pa) cannot carry its own free third (rho g L / 2 ~ 40 Pa on each face) and flows down as it is
# pulled, so _batter_ is the same contrast in a batter.
#
# #18 (helper seedrobust): the bread's claim at 4 mm holds on main's seeding (seed 1) and not on seeds 2 and 4 of 1-5
# (baked 14 / 12 mm against raw 20 / 22), nor on 3 of 5 with smooth_surface: the baked loaf's parting spread over 6-20
# mm across the ten samplings, the raw one's over 20-30 mm or never (docs/validation.md, "Tests that flip with the
# seeding"). The baked crumb cracks from the grips' feet and leaves an intact strip in the middle whose ligament (12-16
# mm of intact rows, ~30 N/m through the middle at 16 mm with seed 2) holds or lets go as the sampling has it: one
# velocity field shares the nodes across the cracked band. The _seedN cases run the claim on those seeds as expected
# failures (exit 77, the numbers printed) and fail once the claim holds there.
claim_raw_dough_stretches_before_tearing | claim_raw_dough_stretches_before_tearing_fine | \
claim_raw_dough_stretches_before_tearing_fine_seed2 | claim_raw_dough_stretches_before_tearing_fine_seed4 | \
claim_raw_batter_stretches_before_tearing | claim_raw_batter_stretches_before_tearing_fine)
    food=bread dx=0.005 seed=1
    case $case_name in *batter*) food=muffin dx=0.004 ;; esac
    case $case_name in *batter*_fine) dx=0.003 ;; *dough*_fine*) dx=0.004 ;; esac
    case $case_name in *_seed*) seed=${case_name##*_seed} ;; esac
    # seed 1 is the setting's default: the baked run is then the very one the claims above make, and shares it
    # (baking_test.sh's shared_run)
    seeded=()
    [ "$seed" = 1 ] || seeded=(--set "seed=$seed")
    run tear_open --set food=$food --set dx=$dx "${seeded[@]}" >/dev/null
    run tear_open --set food=$food --set dx=$dx "${seeded[@]}" --set raw=true --out raw >/dev/null
    python3 - hearth-out/tear_open/tear_open.csv raw/tear_open.csv $food $dx $seed <<'PY'
import csv, sys
def parted(path):
    rows = [r for r in csv.DictReader(open(path)) if float(r["separation_m"]) > 0]
    torn = [float(r["separation_m"]) for r in rows if int(r["pieces"]) >= 2]
    return (torn[0] if torn else None), float(rows[-1]["separation_m"]), max(float(r["force_mid_N_per_m"]) for r in rows)
(b, _, fb), (r, rmax, fr) = parted(sys.argv[1]), parted(sys.argv[2])
food, dx, seed = sys.argv[3], float(sys.argv[4]), int(sys.argv[5])
text = lambda v: "never" if v is None else f"{v * 1e3:.1f} mm"
print(f"{food}, dx {dx * 1e3:.0f} mm, seed {seed}: the baked one parts at {text(b)} of separation (peak force {fb:.1f} "
      f"N/m), the raw one at {text(r)} (peak force {fr:.1f} N/m; need >= twice the baked, or not within {rmax * 1e3:.0f} mm)")
holds = b is not None and (r is None or r >= 2 * b)
if seed != 1:  # an expected failure on this seed
    if holds:
        print(f"seed {seed}: the claim holds now; make this a plain test")
        sys.exit(1)
    print(f"expected failure (seed {seed}): the baked loaf's parting turns on its sampling (6-20 mm over ten at 4 mm): "
          "the intact middle strip's ligament across the one-field cracked band")
    sys.exit(77)
sys.exit(0 if holds else 1)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "the raw $food does not stretch further than the baked one before it parts (numbers above)"
    ;;
# #18 (helper tearclean): a torn muffin is two halves with rough faces (Ding Fig. 2), not a heap of crumbs. With
# the muffin's two velocity fields (--set two_field=true) the cracked faces stay on their halves and the
# gap between them is clear: from 20 mm of separation to the end (40 mm), every frame's particles, cracked or not,
# form exactly two bodies (one-cell bins joined to their eight neighbours, each with 5% of the particles or more:
# crumbs left between the halves would bridge them into one) and at most 5% of the particles lie outside them
# (crumbs fallen clear). Limits set before the runs. With one field (the scene's default) it fails at 4 mm (the
# crumbs bridge the halves at 3 of the 11 frames) but passes at 3 mm, where the crumbs fall clear (4.0% loose at
# most, under the 5%; two fields 0.4 / 0.2%): docs/validation.md, "Torn open after baking". At 4 / 3 mm.
claim_muffin_tears_into_two_halves | claim_muffin_tears_into_two_halves_fine)
    dx=0.004
    case $case_name in *_fine) dx=0.003 ;; esac
    run tear_open --set dx=$dx --set two_field=true >/dev/null
    python3 - hearth-out/tear_open/tear_open.csv $dx <<'PY'
import csv, sys
rows = [r for r in csv.DictReader(open(sys.argv[1])) if float(r["separation_m"]) >= 0.02 - 1e-9]
bad = [r for r in rows if int(r["bodies"]) != 2 or float(r["loose_share"]) > 0.05]
print(f"baked muffin, dx {float(sys.argv[2]) * 1e3:.0f} mm, from 20 to 40 mm of separation: bodies "
      f"{sorted(set(int(r['bodies']) for r in rows))} (need 2 at every frame), loose share at most "
      f"{max(float(r['loose_share']) for r in rows):.3f} (need <= 0.05); {len(bad)} of {len(rows)} frames fail")
sys.exit(0 if rows and not bad else 1)
PY
    [ $? -eq 0 ] || fail "the baked muffin does not tear into two clean halves (numbers above)"
    ;;
# tear_open.lua as a user runs it, shortly: its CSV's cells are numbers (the faces' columns empty before the pull, and
# crack_from_face_m while the pull has cracked nothing: the raw batter never cracks),
# its frames written, and a scene it cannot build (dim=3, an unknown food, two_field neither true nor false, a pull
# of no frames; the food's words are its h.choice's: "muffin", "bread")
# refused with the parameter and its range.
baking_scene_tear_open)
    run tear_open --set raw=true --set pull=0.1 --set frames=5 >/dev/null
    n=$(find hearth-out/tear_open -name '*.png' | wc -l)
    [ "$n" -ge 4 ] || fail "tear_open wrote $n PNG frames, expected at least 4"
    python3 - hearth-out/tear_open/tear_open.csv <<'PY' || fail "tear_open.csv has non-numeric cells or too few rows"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert len(rows) == 6, len(rows)
for r in rows:
    for k, c in r.items():
        if c == "" and (k.startswith("face_peak") or k == "crack_from_face_m"):
            continue  # not measured (no torn face yet, nothing cracked): tear_open.lua declares these may be empty
        v = float(c)
        assert math.isfinite(v), (k, c)
PY
    # every cell a finite number, or empty in a column the scene declares may be (#18, helper userview4: "nan" before)
    python3 "$root/tests/scene_csv.py" hearth-out/tear_open/tear_open.csv "$scenes/tear_open.lua" ||
        fail "tear_open.csv has a cell that is neither a finite number nor empty in a declared column"
    # its time column names its unit (t_s; #18, helper userfix6: it wrote a bare t), every other column its own (userfix7)
    python3 "$root/tests/scene_csv.py" --units "$scenes/tear_open.lua" hearth-out/tear_open/tear_open.csv ||
        fail "tear_open.csv's time column or another column gives no unit"
    for bad in "dim=3:dim (the space's dimensions; the tear is measured over the plane's columns) takes only 2, not 3" "food=cake:food takes one of the words below, not \"cake\"" "two_field=yes:two_field (two velocity fields where a crack runs (Homel & Herbold 2017), so its sides part) takes true or false" \
               "frames=0:frames (PNG frames over the pull) takes a whole number in .1, 10000., not 0"; do
        "$hearth" run "$scenes/tear_open.lua" --quiet --set "${bad%%:*}" >out.txt 2>err.txt && fail "--set ${bad%%:*} ran"
        grep -q "${bad#*:}" err.txt || fail "--set ${bad%%:*}: the message does not say '${bad#*:}': $(cat err.txt)"
    done
    ;;
*) unmatched=1 ;;
esac

#!/usr/bin/env bash
# sph_cake_test.sh CASE HEARTH SOURCE_ROOT: the SPH angel food cake (#18;
# scripts/scenes/sph/angel_food_cake.lua, Rodriguez-Arenas 2011 Fig. 4.11)
# run as a user runs it, at the scene's dx (3 mm) and at 2 mm, to t = 0.5 s
# (13 min of its 40 min bake), read from the scene's bands.csv (mean
# temperatures of its top, crumb and bottom bands, away from the pan's walls)
# and volume.csv (the particles' mean temperature).
#   sph_cake_crumb_coolest  at 0.5 s, at each dx, the crumb band is at least
#                           5 degC cooler than the top band and the bottom
#                           band (a body heated only through its surface is
#                           coolest inside); and the particles' mean
#                           temperatures at the two dx agree within 3 degC
#                           (the oven's heat per unit area does not depend on
#                           dx). Before sph_outer.c (eq. 3.42's heat at the
#                           colour field's surface particles) the crumb band
#                           was 17 degC hotter than the top at 3 mm and the
#                           means were 83.3 and 99.9 degC: 16.6 apart.
# The 5 and 3 degC bars were set after the first runs of the fix (28-33 and
# 0.01 degC): they stand for "clearly cooler" and "the same heat", far from
# both the fixed and the old numbers.
#   claim_sph_angel_cake_rises[_fine]  the whole run (1.5 s bake, cooled in
#       its pan to 3.5 s) at the scene's dx (3 mm; _fine 2 mm), read from the
#       scene's last line (the density slice's relative volume) and its
#       particles at the bake's end and at 3.5 s (tests/sph_cake_rise.py):
#       (a) it rises at least 1.3x by the end of the bake (its highest in the
#           oven, as the scene prints it): issue #18's bar for
#           the SPH roll's rise; dry air alone (eq. 3.50 in Kelvin) gives at
#           most 0.6 + 0.4 x 1.48 = 1.19 here at 180 degC, so it takes the
#           batter's steam (an angel food cake is a steam-raised foam);
#       (b) cooled upright in its pan it loses part of what it gained and
#           keeps part (thesis §4.5, Fig. 4.11: "loose part of the volume it
#           gained"): at least a tenth of the gain lost, at least a tenth kept;
#       (c) each side of the tube stays one piece, baked and cooled;
#           particles link across one raw spacing of gap between their own
#           extents: two batter particles closer than 2 DX, as before; a
#           bubble particle is its gas (thesis §3.3.3), sqrt(V_b) DX across,
#           so it reaches (sqrt(V_b) - 1) DX / 2 further (helper angelpieces:
#           at a fixed 2 DX a bubble at the cap in the middle of the cavity
#           its gas fills stood apart; sph_cake_rise_bubble_fills_its_cavity);
#       (d) no bubble runs away: at the bake's end no bubble's own volume J
#           exceeds 1.2x its gas's (eq. 2.42-2.43, 3.50, written in the
#           measure, not read from the solver).
#   claim_sph_angel_cake_crumb_pale[_fine]  the same run (shared with the rise
#       claim when one meson process runs both: tests/run_share.sh), its
#       bands.csv (the batter's mean browning and saturation in the top, crumb
#       and bottom bands, and on the outer surface where the oven's heat
#       enters): an angel food cake's crumb is pale and holds its water near
#       the boiling point while the crust browns (#18: "only the surface
#       browns; the crumb stays pale", the crumb "plateaus near 100 degC
#       while it holds water"). The scene's batter carries its recipe's water
#       (its WATER note; helper sphcrumb):
#       (a) as the bake ends (the row at t = 1.5 s, the scene's bake) the
#           crumb band's batter browns less than 0.1 (before the water: 0.4-0.6);
#       (b) at every frame in the oven while the crumb band's batter holds at
#           least half its raw water (mean saturation at least half the first
#           row's), the band's mean temperature is at most 103 degC (boiling at
#           100, 3 K for a band that averages a few particles that dried);
#       (c) as the bake ends the crumb band's batter holds at least half its
#           raw water;
#       (d) as the bake ends the outer surface's batter browns at least twice
#           as much as the crumb band's, and at least 0.01 more.
#   These four bars were set on 2026-12-07 at 09:44 UTC (helper sphcrumb),
#   before any run of the cake with its water past 0.21 s.
#   These bars were set on 2026-12-07 (helper angelsteam) before any run of
#   the cake with its steam (it then rose 1.205x and fell to 0.993). (b)
#   failed with the steam alone (0.902, 0.884: the vented cells contracted as
#   closed ones); it holds since the cake's cells stay open at the gas law's
#   cap (sph.bubble_stays_open), and is now a plain requirement. (c) was the
#   expected failure (exit 77) until its measure took each bubble's own
#   extent (helper angelpieces, 2026-12-07: the link rule was set from the
#   thesis's bubble before the scene was measured with it; the cake's physics
#   and numbers unchanged): every side was then one piece at 3 and 2 mm, baked
#   and cooled, and (c) is a plain requirement too.
# Exit 0 pass, 1 fail.
set -u
case_name=$1 hearth=$2 root=$3
tmp=$(mktemp -d)
here=$(cd "$(dirname "$0")" && pwd)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }
# shellcheck source=/dev/null
. "$root/tests/run_share.sh"
aw=0.94 # the scene's default water_activity, passed so the measure's gas is the scene's
# whole_run DX: the whole default run (1.5 s bake, cooled to 3.5 s) at DX into ./cake, shared by the rise and the
# crumb claims (tests/run_share.sh)
whole_run() {
    shared_run_path "$root/scripts/scenes/sph/angel_food_cake.lua" --set dx="$1" --set water_activity=$aw --out cake ||
        fail "angel_food_cake dx=$1: exit $?: $(cat err.txt)"
}

case "$case_name" in
sph_cake_crumb_coolest)
    for dx in 0.003 0.002; do
        "$hearth" run "$root/scripts/scenes/sph/angel_food_cake.lua" --quiet --set dx=$dx --until 0.51 \
            --out cake_$dx >out.txt 2>err.txt || fail "angel_food_cake dx=$dx: exit $?: $(cat err.txt)"
    done
    python3 - <<'PY' || fail "the cake's crumb is not its coolest band, or the two dx heat differently"
import csv
ok, means = True, {}
for dx in ("0.003", "0.002"):
    bands = [r for r in csv.DictReader(open(f"cake_{dx}/bands.csv")) if abs(float(r["t_s"]) - 0.5) < 0.01]
    vol = [r for r in csv.DictReader(open(f"cake_{dx}/volume.csv")) if abs(float(r["t_s"]) - 0.5) < 0.01]
    if not bands or not vol:
        print(f"dx {dx}: no frame at t = 0.5 s"); ok = False; continue
    b, v = bands[0], vol[0]
    top, crumb, bottom = float(b["T_top_degC"]), float(b["T_crumb_degC"]), float(b["T_bottom_degC"])
    means[dx] = 0.5 * (float(v["T_left_degC"]) + float(v["T_right_degC"]))
    good = crumb <= top - 5 and crumb <= bottom - 5
    print(f"dx {dx} t = {b['t_s']} s: top band {top:.2f}, crumb band {crumb:.2f}, bottom band {bottom:.2f} degC "
          f"(top {b['top_mm']} mm); particles' mean {means[dx]:.2f} degC: crumb {'coolest' if good else 'NOT coolest'}")
    ok = ok and good
if len(means) == 2:
    gap = abs(means["0.003"] - means["0.002"])
    print(f"mean temperature 3 mm - 2 mm: {means['0.003'] - means['0.002']:.3f} degC (bound 3)")
    ok = ok and gap <= 3
raise SystemExit(0 if ok else 1)
PY
    ;;
claim_sph_angel_cake_rises | claim_sph_angel_cake_rises_fine)
    dx=0.003
    [ "$case_name" = claim_sph_angel_cake_rises_fine ] && dx=0.002
    whole_run $dx
    cat out.txt
    line=$(grep "angel food cake: relative volume" out.txt) || fail "no volume line in the scene's output"
    read -r peak cool <<<"$(sed -n 's/.*relative volume \([0-9.]*\) at its highest in the oven (.*), \([0-9.]*\) at t = .*/\1 \2/p' <<<"$line")"
    m=$(python3 "$here/sph_cake_rise.py" $dx $aw cake/particles_baked.csv cake/particles_end.csv) || fail "measure: $m"
    echo "$m"
    python3 - "$peak" "$cool" "$m" "$dx" <<'PY'
import sys
peak, cool, m, dx = float(sys.argv[1]), float(sys.argv[2]), sys.argv[3].split(), sys.argv[4]
half = m.index("pieces_left", 1)
baked, end = dict(zip(m[:half:2], m[1:half:2])), dict(zip(m[half::2], m[half + 1::2]))
gain = peak - 1
lo, hi = 1 + 0.1 * gain, peak - 0.1 * gain
one = lambda d: d["pieces_left"] == d["pieces_right"] == "1"
# every part must hold (exit 1); (c)'s link rule: tests/sph_cake_rise.py's docstring
checks = [
    ("a", peak >= 1.3, f"risen {peak:.3f}x at its highest in the oven (bar 1.3)"),
    ("b", lo <= cool <= hi, f"cooled to {cool:.3f}x (bar [{lo:.3f}, {hi:.3f}]: a tenth of the gain kept, a tenth lost)"),
    ("c", one(baked) and one(end),
     f"pieces left / right of the tube: baked {baked['pieces_left']} / {baked['pieces_right']} (outside the largest: "
     f"{baked['off_batter']} batter, {baked['off_bubbles']} bubble particles), cooled {end['pieces_left']} / "
     f"{end['pieces_right']} ({end['off_batter']} batter, {end['off_bubbles']} bubble) (bar 1 each)"),
    ("d", float(baked["worst_bubble_over_gas"]) <= 1.2,
     f"the largest bubble at {float(baked['worst_bubble_over_gas']):.3f}x its gas's volume at the bake's end "
     f"(bar 1.2)"),
]
for k, ok, what in checks:
    print(f"dx {dx}: {'ok  ' if ok else 'FAIL'} ({k}) {what}")
sys.exit(1 if any(not ok for _, ok, _ in checks) else 0)
PY
    rc=$?
    [ $rc = 1 ] && fail "the cake at dx $dx does not rise on its steam as claimed"
    exit $rc
    ;;
claim_sph_angel_cake_crumb_pale | claim_sph_angel_cake_crumb_pale_fine)
    dx=0.003
    [ "$case_name" = claim_sph_angel_cake_crumb_pale_fine ] && dx=0.002
    whole_run $dx
    grep "angel food cake" out.txt
    python3 - "$dx" cake/bands.csv "$root/tests" <<'PY'
import csv, math, sys
sys.path.insert(0, sys.argv[3])
from sph_crumb_measure import crumb_bars
dx, path = sys.argv[1], sys.argv[2]
BAKE = 1.5  # the scene's default bake (s), which the run keeps
rows = [{k: float(v) for k, v in r.items()} for r in csv.DictReader(open(path))]
need = ("B_crumb", "S_crumb", "B_outer")
if not rows or any(k not in rows[0] for k in need) or math.isnan(rows[0]["S_crumb"]):
    print(f"dx {dx}: bands.csv has no batter saturation (the scene's water off?)"); sys.exit(1)
s_raw = rows[0]["S_crumb"]
oven = [r for r in rows if r["t_s"] < BAKE + 0.05]  # the last is the frame the cake leaves the oven in
end = oven[-1]
for r in oven:
    print(f"dx {dx} t = {r['t_s']:.2f} s: crumb {r['T_crumb_degC']:.1f} degC, browning {r['B_crumb']:.4f}, saturation "
          f"{r['S_crumb']:.4f}; top {r['T_top_degC']:.1f} degC, browning {r['B_top']:.4f}; outer surface's batter "
          f"browning {r['B_outer']:.4f}, saturation {r['S_outer']:.4f}")
wet = [(f"t = {r['t_s']:.2f} s", r["T_crumb_degC"]) for r in oven if r["S_crumb"] >= 0.5 * s_raw]
ok = crumb_bars(dx, "the crumb band", f"as the bake ends (t = {end['t_s']:.2f} s)", s_raw, wet,
                (end["B_crumb"], end["S_crumb"]), end["B_outer"])
sys.exit(0 if ok else 1)
PY
    rc=$?
    [ $rc = 1 ] && fail "the cake's crumb at dx $dx is not pale and wet under a browner crust as claimed"
    exit $rc
    ;;
*) fail "unknown case $case_name" ;;
esac

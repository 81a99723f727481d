#!/usr/bin/env bash
# baking_test.sh CASE HEARTH SOURCE_ROOT: the baking scenes (scripts/scenes/baking/)
# as a user runs them, and the paper's claims (Ding et al. 2019 §7.2, 7.3, 7.5)
# checked at coarse 2D resolution from the CSVs the scenes write.
# Exit 0 pass, 1 fail, 77 expected failure (prints the measured numbers and why).
set -u
case_name=$1 hearth=$2 root=$3
scenes=$root/scripts/scenes/baking
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cd "$tmp" || exit 1
fail() { echo "FAIL: $*" >&2; exit 1; }

# run SCENE ARGS...: hearth run --quiet; fails the case on a non-zero exit
run() {
    local sc=$1
    shift
    "$hearth" run "$scenes/$sc.lua" --quiet "$@" >out.txt 2>err.txt || fail "$sc $*: exit $?: $(cat err.txt)"
    cat out.txt
}

# the coarse cookie bake the claims use: dx 7.5 mm, 4 s (every cookie sets by then
# with cookies.lua's real dough conductivity: 3.5 s at 150 degC)
COARSE=(--set dx=0.0075 --set until_t=4 --set frames=1)

case "$case_name" in
baking_scene_cookies | baking_scene_bread | baking_scene_muffins | baking_scene_drying | baking_scene_pancake | baking_scene_marshmallow | baking_scene_lava_cake | baking_scene_pull_twist)
    sc=${case_name#baking_scene_}
    extra=()
    [ "$sc" = cookies ] && extra=(--set ovens=150 --set leaveners=0.015,0)
    until=0.1
    [ "$sc" = pancake ] && until=0.3   # the first batter lands at ~0.15 s
    [ "$sc" = pull_twist ] && extra=(--set dx=0.004 --set taus=300,3000 --set etas=1e8)
    run "$sc" --until $until --frames 2 "${extra[@]}" >/dev/null
    n=$(find "hearth-out/$sc" -name '*.png' | wc -l)
    [ "$n" -ge 3 ] || fail "$sc wrote $n PNG frames, expected at least 3"
    csv=$(find "hearth-out/$sc" -name "$sc.csv" | head -1)
    [ -n "$csv" ] || fail "$sc wrote no $sc.csv"
    # the shipped scene that writes ParaView/Blender series (README): 3 frames in its .pvd, 3 PLY
    if [ "$sc" = bread ]; then
        [ "$(grep -c '<DataSet ' hearth-out/bread/vtu/bread.pvd)" = 3 ] && [ "$(ls hearth-out/bread/ply/*.ply | wc -l)" = 3 ] ||
            fail "bread wrote no VTU/PLY series of 3 frames: $(ls -R hearth-out/bread)"
    fi
    rows=$(wc -l <"$csv")
    [ "$rows" -ge 2 ] || fail "$csv has $rows lines"
    python3 - "$csv" <<'PY' || fail "$csv has non-numeric or non-finite cells"
import csv, math, sys
rows = list(csv.reader(open(sys.argv[1])))
for r in rows[1:]:
    for c in r:
        v = float(c)
        assert math.isfinite(v), c
PY
    ;;

# The physical loaf (h.library.dough.bread, #18) as a user runs it, for two real
# minutes: it says its units, writes its CSV and pictures, and its crust
# (the top particle) is already hotter than its crumb, which is still near
# the dough's 25 degC. The plateau itself is tests/unit_latent.c's.
baking_scene_loaf_physical)
    run loaf_physical --set until_real=120 --set frames=2 >/dev/null
    grep -q "h.library.dough.bread, physical, heat and water 300 times fast" out.txt ||
        fail "the summary line does not give the units: $(head -1 out.txt)"
    for f in loaf.csv temperature.png saturation.png browning.png; do
        [ -n "$(find hearth-out/loaf_physical -name "$f" | head -1)" ] || fail "loaf_physical wrote no $f"
    done
    python3 - "$(find hearth-out/loaf_physical -name loaf.csv | head -1)" <<'PY' || fail "loaf.csv: $(cat hearth-out/loaf_physical/loaf.csv)"
import csv, math, sys
rows = list(csv.DictReader(open(sys.argv[1])))
last = rows[-1]
print("after %s real min: crumb %s degC, crust %s degC (saturation %s)" % (last["t_real_min"], last["centre_T_degC"],
      last["top_T_degC"], last["top_s"]))
assert abs(float(last["t_real_min"]) - 2.0) < 1e-6
assert float(last["centre_T_degC"]) < 30 and float(last["top_T_degC"]) > 45
PY
    ;;

# #18: "only the surface browns; the crumb stays pale", and a baker expects a golden-brown top after the 25 minute
# bake at 200 degC: the physical loaf (h.library.dough.bread) baked whole, its top particle on the loaf's axis
# browned past 0.5 (the browning index b = Delta E / Delta E_inf of fields/browning.c: half of the crust's colour
# difference from the raw dough, golden), its crumb below 0.1 (fields/browning.c: a crumb held at 100 degC reaches
# 0.05 in 20 minutes). At dx 5 mm (_fine: 2.5 mm). A crumb that browns fails; a top that stays pale is an expected
# failure that prints the numbers and the cause measured (docs/validation.md "A dried crust holds less heat").
claim_loaf_top_browns | claim_loaf_top_browns_fine)
    dx=0.005
    [ "$case_name" = claim_loaf_top_browns_fine ] && dx=0.0025
    run loaf_physical --set dx=$dx --set frames=5 >/dev/null
    python3 - "$(find hearth-out/loaf_physical -name loaf.csv | head -1)" $dx <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
dx = float(sys.argv[2])
for r in rows:
    print(f"  {r['t_real_min']} min: top {r['top_T_degC']} degC (s {r['top_s']}), browning top {r['top_browning']}, "
          f"base {r['base_browning']}, centre {r['centre_browning']}; centre {r['centre_T_degC']} degC; water left {r['water_left']}")
last = rows[-1]
top, base, centre = float(last["top_browning"]), float(last["base_browning"]), float(last["centre_browning"])
print(f"dx {dx * 1e3:.1f} mm after {last['t_real_min']} min: top browning {top:.3f} (golden: > 0.5), crumb {centre:.3f} "
      f"(pale: < 0.1), base {base:.3f}")
if centre >= 0.1:
    print("FAIL: the crumb browns")
    sys.exit(1)
if top > 0.5:
    sys.exit(0)
print("EXPECTED FAILURE: the top browns short of golden (> 0.5), and what holds it is the physics of this bake, not the "
      "numerics. An independent fine 1D reference of the top from the loaf's 25 degC start (scripts/validation/top_reference.c: "
      "the model's heat, water, boiling, evaporation closure and surface browning in real time, converged to 2e-4 at h 0.1 mm) "
      "browns the face 0.111 under a flat top and 0.160 under a round top of the loaf's radius (40 mm, heated all round); the "
      "same flat column in the model browns 0.112, 0.110 at 5, 2.5 mm (loaf_top_follows_reference), and the loaf 0.136, 0.154, "
      "0.151 at 5, 2.5, 1.25 mm (within 0.01 of the round top's 0.160 at 2.5 and 1.25 mm; measured after the boiling front's "
      "shares came to scale with room, helper frontroom), 0.158 and 0.187 at 5 and 2.5 mm since the loaf rises (its pores' "
      "gas at the atmosphere, helper physrise: a wider, taller top), 0.166 and 0.187 since its base rests on the "
      "tray (helper traygap), and 0.155 and 0.178 since the loaf is seeded with smooth_surface (helper loafbase: the top "
      "particle read sits on the lattice, 1.25 and 0.625 mm under the top, where the jittered one sat 1.107 and 0.563 mm "
      "under it). The Stefan form's 0.28 holds the crumb "
      "at 100 degC from t = 0: the 25 degC start (the surface reaches 100 degC at 4-6 min) and the cold crumb under the front, "
      "which takes heat the form boils, bring it to 0.115 in the flat column; the water's evaporation and diffusion move it "
      "by -0.003; the round top adds +0.049. Golden needs more heat at the top: the round top reaches 0.5 near beta = 60 "
      "W/(m^2 K), 0.26 with the oven at 220 degC, 0.38 with h_c 10 + radiation from 250 degC walls (docs/validation.md, "
      "helper topref). Presets and the bar are unchanged.")
sys.exit(77)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "$case_name: the crumb browns (numbers above)"
    ;;

# #18 (helper basefoot): a baker's loaf sits flat on its tray; the physical loaf's base must not leave it. Over the raw
# base's middle 80% (16 columns of 4 mm), no column's lowest particle edge (y - h_p, h_p = (V0 J)^(1/2) / 2, the
# half-extent the tray's contact reads: mpm_touch.c) may stand more than 0.5 mm above the tray (loaf.csv's
# base_gap_m, each real minute) over the bake's first 2 real minutes, when the bottom rows pass 25..70 degC on the
# 200 degC tray. Bar set before the run (basefoot's), from what is seen: a base off its tray by half a mm shows a gap
# in its browned band; a fifth of a 2.5 mm cell. At dx 5 mm (~2 s); _fine at 2.5 mm (~11 s).
# Until traygap the claim read base_lift_m, each column's rise off its start: that also counts the seeding's jitter
# (the lowest particles start up to 0.12 dx inside their half-extent and rest at it once the contact holds) and the
# bottom particles' own swelling, neither of which is the base leaving the tray; it is still printed.
# Until loafbase this was an expected failure at 5 mm (1.10 mm at 2 min): the jittered base was as rough as its
# particles' lower edges (spread over 0.25 dx, 1.25 mm), and the bottom rows' gas swelling (5-15 real s, 35-60 degC)
# pushed the deepest ones out of the tray to rest at their half-spacing, lifting the base around them by up to 0.6 mm
# so the highest edges stood 0.9-1.1 mm off. Switches measured it (docs/validation.md, "The physical loaf's base
# lifts: traced"): jitter 0, 0.03 mm; the pores' gas off, 0.15 mm; thermal expansion off, 1.09 mm. The scene now seeds
# the loaf with smooth_surface (its outer layer on the lattice) and the claim is a plain test at both dx.
claim_loaf_physical_base_on_tray | claim_loaf_physical_base_on_tray_fine)
    dx=0.005
    [ "$case_name" = claim_loaf_physical_base_on_tray_fine ] && dx=0.0025
    run loaf_physical --set dx=$dx --set until_real=120 --set frames=2 >/dev/null
    python3 - "$(find hearth-out/loaf_physical -name loaf.csv | head -1)" $dx <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
dx = float(sys.argv[2])
gap = [float(r["base_gap_m"]) for r in rows]
lift = [float(r["base_lift_m"]) for r in rows]
j = max(range(len(gap)), key=lambda i: gap[i])
print(f"dx {dx * 1e3:.1f} mm: the base's largest gap to the tray over its middle 80% {gap[j] * 1e3:.2f} mm at "
      f"{rows[j]['t_real_min']} min (need <= 0.5 mm); at the start {gap[0] * 1e3:.2f} mm (the seeding's); the largest "
      f"rise of a column's lowest particle off its start {max(lift) * 1e3:.2f} mm")
sys.exit(0 if gap[j] <= 0.5e-3 else 1)
PY
    [ $? -eq 0 ] || fail "$case_name: the base leaves its tray (numbers above)"
    ;;

# #18: the physical loaf (h.library.dough.bread, its pores' gas at the atmosphere: ambient_pressure, gas.h) rises in
# its oven as a baker's loaf springs: the issue's bread bar, set before the run and the same as bread.lua's
# (claim_bread_loaf_rises): its area (V0 J summed, loaf.csv's area_m2) grows >= 15% from raw to its peak and keeps
# >= 10% at the end of the 25 minute bake, and it ends at least as tall as raw (height_m). At dx 5 mm (_fine: 2.5
# mm). Before the gas stood at the atmosphere the loaf went 71.6 -> 68.6 mm and froze (docs/gallery/crumb_plateau.md).
claim_loaf_physical_rises | claim_loaf_physical_rises_fine)
    dx=0.005
    [ "$case_name" = claim_loaf_physical_rises_fine ] && dx=0.0025
    run loaf_physical --set dx=$dx >/dev/null
    python3 - "$(find hearth-out/loaf_physical -name loaf.csv | head -1)" $dx <<'PY' || fail "$case_name: the physical loaf does not rise (numbers above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
dx = float(sys.argv[2])
a = [float(r["area_m2"]) for r in rows]
h = [float(r["height_m"]) for r in rows]
k = max(range(len(a)), key=lambda i: a[i])
for r in rows:
    print(f"  {r['t_real_min']} min: area {float(r['area_m2']) / a[0] - 1:+.1%}, height {float(r['height_m']) * 1e3:.1f} mm, "
          f"crumb {r['centre_T_degC']} degC")
peak, end = a[k] / a[0] - 1, a[-1] / a[0] - 1
print(f"dx {dx * 1e3:.1f} mm: area {a[0]:.5g} -> peak {a[k]:.5g} m^2 at {rows[k]['t_real_min']} min ({peak:+.1%}, need >= +15%), "
      f"end {a[-1]:.5g} ({end:+.1%}, need >= +10%); height {h[0] * 1e3:.1f} -> peak {max(h) * 1e3:.1f} -> end "
      f"{h[-1] * 1e3:.1f} mm (need end >= raw)")
sys.exit(0 if peak >= 0.15 and end >= 0.10 and h[-1] >= h[0] else 1)
PY
    ;;

# §7.3: "Too much leavening agent would produce a very tall cookie, while no
# leavener at all yields a flat one." Height rises with alpha^g at one oven,
# and the unleavened top is flat: over the middle third of the cookie its
# parabola sags less than a quarter cell (the resolution of the measure) and
# less than the most leavened cookie's. The flat top at the claims' coarse dx
# (7.5 mm), the scene's dx (_fine, 5 mm) and one finer level (_finer, 3.75
# mm, suite campaign), as #18 asks; each cookie must be read alone (cookies.lua's
# column alone: it touches neither the box's wall nor its neighbour). A plain
# test at all three since helper flat3 (cookies.lua's oven bakes a real dough's
# conductivity, so the base and rim set first, and its dough is 17.5 mm thick);
# the bake runs 4 s, by which every cookie has set (3.5 s at 150 degC).
claim_cookie_height_leavener | claim_cookie_flat_without_leavener | claim_cookie_flat_without_leavener_fine | \
    claim_cookie_flat_without_leavener_finer)
    lv=0.015,0.0075,0 dx=0.0075
    case $case_name in claim_cookie_flat_without_leavener*) lv=0.015,0 ;; esac # the flat claim needs only these two
    [ "$case_name" = claim_cookie_flat_without_leavener_fine ] && dx=0.005
    [ "$case_name" = claim_cookie_flat_without_leavener_finer ] && dx=0.00375
    run cookies --set dx=$dx --set until_t=4 --set frames=1 --set ovens=150 --set leaveners=$lv
    python3 - hearth-out/cookies/cookies.csv "$case_name" $dx <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
h = {float(r["leavener"]): float(r["height_m"]) for r in rows}
k = {float(r["leavener"]): float(r["top_curvature_1_per_m"]) for r in rows}
kp = {float(r["leavener"]): float(r["top_curvature_particles_1_per_m"]) for r in rows}
se = {float(r["leavener"]): float(r["top_curvature_particles_se_1_per_m"]) for r in rows}
w = {float(r["leavener"]): float(r["spread_m"]) for r in rows}
print("heights by leavener:", h, "curvatures:", k, "spreads:", w)
print("particles' top curvature +- the fit's standard error (h.top_curvature of the displacements since placing; "
      "a static flat top reads its settling, under 0.12 1/m, docs/validation.md 'Fig. 17 at 3.75 mm: the jitter, "
      "read and removed'):",
      ", ".join(f"{a}: {kp[a]:.2f} +- {se[a]:.2f}" for a in sorted(kp, reverse=True)))
if not all(r["alone"] == "1" for r in rows):
    print("a cookie touches the box's wall or its neighbour (cookies.lua's alone column): its readings are not its own")
    sys.exit(1)
if sys.argv[2] == "claim_cookie_height_leavener":
    sys.exit(0 if h[0.015] > h[0.0075] > h[0.0] else 1)
dx = float(sys.argv[3])
sag = abs(k[0.0]) / 2 * (w[0.0] / 6) ** 2
print(f"dx {dx * 1e3:.2f} mm: unleavened sag over the middle third {sag * 1e3:.3f} mm (flat: < dx/4 = {dx / 4 * 1e3:.3f} "
      f"mm); |curvature| {abs(k[0.0]):.2f} vs most leavened {abs(k[0.015]):.2f} 1/m (particles: {abs(kp[0.0]):.2f} vs "
      f"{abs(kp[0.015]):.2f})")
if sag < dx / 4 and abs(k[0.0]) < abs(k[0.015]):
    sys.exit(0)
print("FAIL: the unleavened top is domed (and/or not flatter than the leavened one's). Until #18 helper flat3 this "
      "was an expected failure at every dx: with Table 2's kappa the cookie baked evenly (Biot ~0.01) and spread as a "
      "puddle whose base the tray held, which domes (Huppert 1982) by a fraction of H, not of dx. cookies.lua now bakes "
      "a real dough's conductivity (x0.01, Biot ~1: the base and rim set first, the unleavened dough sets flat on them, "
      "the leavened centre rises inside its set rim) and a 17.5 mm dough: check its oven and dough against "
      "docs/validation.md 'The unleavened cookie's top: a real dough's heat'")
sys.exit(1)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "$case_name does not hold (numbers above)"
    ;;

# Issue #18, why the unleavened top is domed (docs/validation.md "The unleavened
# cookie's top: traced"): it spreads as a gravity current whose base the tray
# holds, and such a current's top is domed however fine the grid. The same
# dough on a free-slip tray (friction 0) spreads as a plug, in extension,
# where a thicker part thins faster, so its top sets flat: cookies.lua's
# unleavened dough alone (scripts/validation/cookie_top_trace.lua, dx 5 mm,
# 2.5 s, 150 degC) must end set (every particle past 78 degC), with the flat
# claim's sag (the density probe's parabola over the middle third, |k|/2
# (w/6)^2) under dx/4, and its top at two thirds of the half-width within 10%
# of the centre's (the particles' top; a no-slip Newtonian current's is 0.822
# of it, Huppert 1982; the shipped tray's measures 0.81).
cookie_top_flat_on_slipping_tray)
    "$hearth" run "$root/scripts/validation/cookie_top_trace.lua" --quiet --set dx=0.005 --set friction=0 --set png=false \
        --set frames=5 >out.txt 2>err.txt || fail "cookie_top_trace.lua: exit $?: $(cat err.txt)"
    cat out.txt
    python3 - out.txt <<'PY' || fail "the unleavened dough on a free-slip tray does not set flat (numbers above)"
import csv, sys
last = list(csv.DictReader(open(sys.argv[1])))[-1]
dx, w, H = 0.005, float(last["w_mm"]) * 1e-3, float(last["H_mm"])
sag = abs(float(last["k_probe"])) / 2 * (w / 6) ** 2
r = float(last["h_two_thirds"])
print(f"free-slip tray, dx 5 mm, t {last['t_s']} s: {H:.1f} mm tall, {w * 1e3:.1f} mm wide, set {last['set78']}; "
      f"probe sag over the middle third {sag * 1e3:.3f} mm (need < {dx / 4 * 1e3:.3f}); top at 2/3 of the half-width "
      f"{r:.3f} of the centre's (need >= 0.9); particle curvature {last['k_particles']} 1/m")
sys.exit(0 if float(last["set78"]) == 1 and sag < dx / 4 and r >= 0.9 else 1)
PY
    ;;

# §7.2: "With the temperature being too high, the dough gets heated up very
# quickly, so the cookie does not get enough time to spread": at fixed
# leavener, the final spread falls as the oven temperature rises (each
# cookie alone in its slot, so the spread is its own: cookies.lua's alone).
claim_cookie_spread_oven)
    run cookies "${COARSE[@]}" --set ovens=190,150,110 --set leaveners=0.0075
    python3 - hearth-out/cookies/cookies.csv <<'PY' || fail "spread does not fall with oven temperature (numbers above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
w = {float(r["oven_degC"]): float(r["spread_m"]) for r in rows}
print("spread by oven temperature:", w, "each alone in its slot:", [r["alone"] for r in rows])
sys.exit(0 if w[190] < w[150] < w[110] and all(r["alone"] == "1" for r in rows) else 1)
PY
    ;;

# §7.5, Fig. 17: the full model's cookie is domed; the Stomakhin-like
# baseline (the snow_plastic plugin: Stomakhin et al. 2013's clamped
# fixed-corotated law with the snow paper's theta_c, theta_s and xi and the
# cookie's E, nu and density; no gas, no viscoplasticity, no thermal
# expansion) is flat or dented. Both measures of the top (the density probe's
# and the particles', h.top_curvature; see cookies.lua) must say so, each
# against the particles' sampling noise sigma: a reading of a top's curvature
# scatters by about 2 1/m from one jittered sampling of the same dough to the
# next (five samplings at each dx, docs/validation.md "Fig. 17: the top's
# curvature and its noise"), so domed is k < -2 sigma and flat or dented is
# k >= -2 sigma. (Until #18 helper fig17 the limits were k < 0 and k >= 0: a
# flat top read with either sign.) At the claims' coarse dx (7.5 mm), the
# scene's own dx (_fine, 5 mm) and one finer level (_finer, 3.75 mm), as #18
# asks; the paper's three ovens are scripts/validation/fig17_grid.sh. _finer
# was an expected failure from helper flat3 (cookies.lua's dough thinned to
# 17.5 mm) to helper fig17c: the baseline's static capsule read -3.21 1/m by
# the probe (five samplings: -3.21 .. +2.46), and 0 with the seeding's jitter
# off. Since fig17c both measures read the top's change since the dough was
# placed (the probe less the raw dough's height where the material on top
# was placed; the particles by their displacements, h.top_curvature's rest),
# so the jitter the static capsule keeps cancels; the bands below are unchanged (docs/validation.md
# "Fig. 17 at 3.75 mm: the jitter, read and removed").
claim_cookie_domed_vs_baseline | claim_cookie_domed_vs_baseline_fine | claim_cookie_domed_vs_baseline_finer)
    dx=0.0075
    [ "$case_name" = claim_cookie_domed_vs_baseline_fine ] && dx=0.005
    [ "$case_name" = claim_cookie_domed_vs_baseline_finer ] && dx=0.00375
    run cookies --set dx=$dx --set until_t=4 --set frames=1 --set ovens=150 --set leaveners=0.015 >/dev/null
    cp hearth-out/cookies/cookies.csv full.csv
    run cookies --set dx=$dx --set until_t=4 --set frames=1 --set ovens=150 --set leaveners=0.015 --set baseline=true >/dev/null
    python3 - full.csv hearth-out/cookies/cookies.csv $dx <<'PY'
import csv, sys
full = list(csv.DictReader(open(sys.argv[1])))[0]
base = list(csv.DictReader(open(sys.argv[2])))[0]
dx = float(sys.argv[3])
cols = ("top_curvature_1_per_m", "top_curvature_particles_1_per_m")
kf = [float(full[c]) for c in cols]
kb = [float(base[c]) for c in cols]
se = [float(r["top_curvature_particles_se_1_per_m"]) for r in (full, base)]
# sigma: the standard deviation of each cookie's particle reading (h.top_curvature
# from heights) over five jitter samplings of the 25 mm dough's bake (cookies.lua
# --set seed=1..5; docs/validation.md, "Fig. 17: the top's curvature and its
# noise"), full model and baseline; the probe's reading is held to the same
# sigma. Kept as the bands since helper fig17c changed both measures to read
# the top's change since placing: their scatter over five samplings of today's
# 17.5 mm bake is then 0.01-0.03 1/m for the baseline (its elastic settling,
# -0.003 to -0.11 1/m, is what remains) and 1.5-7 1/m for the full model (the
# coarse bake's own, probe and particles alike); docs/validation.md "Fig. 17 at
# 3.75 mm: the jitter, read and removed"
sf, sb = {0.0075: (2.06, 2.20), 0.005: (1.86, 2.12), 0.00375: (0.43, 1.33)}[dx]
print(f"dx {dx * 1e3:.2f} mm, top curvature (probe, particles +- the fit's standard error): full model {kf[0]:.3f}, "
      f"{kf[1]:.3f} +- {se[0]:.3f} 1/m; baseline {kb[0]:.3f}, {kb[1]:.3f} +- {se[1]:.3f} 1/m (each the change since "
      f"placing); sigma (the 25 mm dough's sampling noise of the heights' reading, kept as the bands) "
      f"{sf:.2f} and {sb:.2f} 1/m: domed needs k < {-2 * sf:.2f}, flat or dented k >= {-2 * sb:.2f}")
domed, flat = all(k < -2 * sf for k in kf), all(k >= -2 * sb for k in kb)
print(f"full model domed beyond noise: {domed}; baseline flat or dented within noise: {flat}")
sys.exit(0 if domed and flat else 1)
PY
    [ $? -eq 0 ] || fail "the full model's cookie is not domed beyond noise, or the baseline's top is not flat within it (numbers above)"
    ;;

# A press that would drive the crackers through each other is refused up
# front, naming the parameters and the largest press time at that speed
# (unchecked, 15 mm/s for 1 s crushed the marshmallow to inverted particles).
baking_marshmallow_press_refused)
    "$hearth" run "$scenes/marshmallow.lua" --quiet --set speed=0.015 >out.txt 2>err.txt && fail "the over-closing press ran"
    grep -q "marshmallow.lua:[0-9]*: --set speed=0.015, press=1: the crackers would close 30.0 mm" err.txt ||
        fail "unexpected message: $(cat err.txt)"
    grep -q "press <= 0.8 s" err.txt || fail "the message does not give the largest press: $(cat err.txt)"
    ;;

# Issue #18: the marshmallow at its preset's expansion (h.library.paper.smore, c lambda = 2 Pa/K, 20x the scene's
# default 0.1) bakes and is pressed to the end. Eq. 10's term as a pressure after the yield stopped it (guard, lone
# molten particles swelling without end, t = 0.855 s); as a thermal strain (core/sim/material.h) it completes.
# A press of 0.5 s (to t = 1.1 s, past the old stop) keeps it to about half the full scene's cost.
baking_marshmallow_paper_expansion_completes)
    "$hearth" run "$scenes/marshmallow.lua" --quiet --set expansion=2 --set press=0.5 --set frames=2 >out.txt 2>err.txt ||
        fail "marshmallow.lua at expansion 2 stopped: $(tail -3 err.txt)"
    cat out.txt
    grep -q "^after the press: raw 0.0[0-9]* m thick .*, roasted 0.0[0-9]* m thick" out.txt ||
        fail "no thicknesses after the press: $(cat out.txt)"
    ;;

# §7.4, Fig. 15: a scored loaf's slit opens while the loaf rises: from the
# loaf's lowest height (after the dough settles) to the end of the bake, the
# height grows and so does the slit's gap.
claim_bread_slit_widens)
    run bread --set only=2 --set dx=0.006 --set until_t=2.5 --set frames=10 >/dev/null
    python3 "$root/tests/bread_claims.py" slit_widens hearth-out/bread/bread.csv ||
        fail "the slit does not widen while the loaf rises (numbers above)"
    ;;
# #18, Ding §7.4 ("breads expand in size and the slits open up"): a loaf of
# bread.lua rises: its area (2D: V0 J summed over its particles) grows by at
# least 15% from the raw dough to its peak, keeps at least 10% at the end of
# the bake, and the loaf stands at least as tall as the raw dough; a scored
# loaf's slit ends open (gap > one cell) and wider than it started. The plain
# loaf and the one-slit loaf, each at the scene's dx (5 mm) and one finer (4
# mm). Before eta carried the square of bread's tau_y factor
# (lua/hearth/dough.lua) the loaves spread under their own weight: plain area
# +13.4%, 71.6 -> 55.5 mm; one slit +12.2%, 66.2 -> 56.3 mm.
claim_bread_loaf_rises | claim_bread_loaf_rises_fine | claim_bread_scored_loaf_rises | claim_bread_scored_loaf_rises_fine)
    dx=0.005 only=1 col=plain
    case $case_name in *_fine) dx=0.004 ;; esac
    case $case_name in *scored*) only=2 col=one_slit ;; esac
    run bread --set only=$only --set dx=$dx --set frames=5 >/dev/null
    python3 "$root/tests/bread_claims.py" rises hearth-out/bread/bread.csv $dx $col || fail "the loaf does not rise (numbers above)"
    ;;
# #18 in 3D (helper bread3d): the same claim on bread.lua --set dim=3, each loaf extruded 6 cm along z: its volume
# (V0 J summed: bread.csv's area_ column holds the volume in 3D) grows >= 15% from raw to peak and keeps >= 10% at
# the end, the loaf stands at least as tall as the raw dough (the density probe on its axis, z = 0.06), and the
# scored loaf's slit ends open (gap > one cell) and wider than it started: the 2D bars, set before the run
# (tests/bread_claims.py rises, the same columns the 2D claims read). The plain and the one-slit loaf at the scene's
# 3D dx (8 mm) and one finer (6 mm: bread.lua's dx_min_3d lowered to it). Each bake takes 1.5-2 (8 mm: 110 and 87 s
# through meson) and 22-23 (6 mm) minutes of wall time on the loaded machine: suite campaign. When the volume holds and the height or the slit
# does not, the case prints the measured numbers and the cause found (docs/validation.md, "bread.lua in 3D") and
# exits 77; a volume short of its bars is a failure.
claim_bread3d_loaf_rises | claim_bread3d_loaf_rises_fine | claim_bread3d_scored_loaf_rises | claim_bread3d_scored_loaf_rises_fine)
    dx=0.008 only=1 col=plain
    case $case_name in *_fine) dx=0.006 ;; esac
    case $case_name in *scored*) only=2 col=one_slit ;; esac
    run bread --set dim=3 --set only=$only --set dx=$dx --set dx_min_3d=$dx --set frames=10 >/dev/null
    python3 "$root/tests/bread_claims.py" rises hearth-out/bread/bread.csv $dx $col 3 && exit 0
    python3 - hearth-out/bread/bread.csv $col <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
v = [float(r["area_" + sys.argv[2]]) for r in rows]
if max(v) / v[0] < 1.15 or v[-1] / v[0] < 1.10:
    sys.exit(1)
print("EXPECTED FAILURE: the volume grows as the bars ask (plain +21.8% / +16.3% at 8 mm, +19.2% / +14.8% at 6 "
      "mm) but the loaf ends below its raw height (plain 72.7 -> 67.6 mm at 8 mm, 71.9 -> 68.2 at 6 mm; one slit "
      "66.8 -> 62.5, 67.1 -> 64.1), because a loaf with free ends is not in plane strain: the gas's pressure, which "
      "the solid carries in tension in every direction, stretches its middle along z as much as across (elastic "
      "strain along z 0.134 at the end at 8 mm against 0.002 with its ends held; its middle's material 13.5% longer) "
      "and plane strain, as in 2D, puts 1 + nu = 1.3 times more of the same gas into the cross-section (measured "
      "per unit gas pressure on an 18 cm loaf, held over free: 1.30 at nu 0.3, 0.94 at nu 0). "
      "The tray is part of the rest: on bread.lua's tray (separate, friction 0.4) the plain loaf's foot slides out "
      "6.4 mm a side at 8 mm; held on a sticky tray (bread.lua --set tray=sticky) it stays and the loaf ends 72.7 -> "
      "70.4 mm at 8 mm and 71.9 -> 69.2 mm at 6 mm, still low; and at 8 mm the foot's slide depends on where the "
      "node rows fall against the tray: with a row on it (bread3d.lua --set grid_shift=0.004) the plain loaf ends "
      "73.0 -> 70.2 mm on the same tray (docs/validation.md, 'The loaf's foot on its tray'). A separate tray "
      "that also held the first node row above a face between rows (SEPARATE_NEAR_BAND, helper touchrows; tried and "
      "reverted, it moved the stability matrix) gave 72.7 -> 70.7 mm at 8 mm (its foot out 3.6 mm a side) and "
      "71.9 -> 69.7 mm at 6 mm, still low (docs/validation.md, 'The separate tray between node rows'). "
      "Extruded 6 cm with two flat free ends the loaf also lengthens at its foot (60 -> 74 mm at 8 mm) and its slit "
      "barely opens (8 mm: 7.8 -> 7.8 mm, between particles 14.4 -> 14.3 mm; 6 mm: 7.6 -> 8.8 mm; 2D 6.8 -> 19.7 "
      "mm). Held by the box's slip walls along z (scripts/validation/bread3d.lua --set zw=0.12) it rises as in 2D: "
      "plain +29.3% / +29.1%, 72.0 -> 73.7 mm; one slit +27.6% / +26.6%, 67.7 -> 72.5 mm, slit 7.2 -> 17.1 mm; 6 "
      "mm plain +28.7% / +28.5%, 71.8 -> 73.8 mm (bread3d_ends_held_loaf_rises and _fine). An 18 cm free loaf "
      "heated as the held one ends 72.6 -> 71.0 mm (6 mm: 72.1 -> 71.0): its middle stretches 8.8% along z (6 mm: "
      "6.7%) and its section gains +19.6% (6 mm: +19.6%; held +29.4%, +28.7%). A loaf with rounded ends as a baker shapes it (bread3d.lua --set ends=round, 14 cm long: "
      "bread3d_round_loaf_rises) comes closer and still ends low: 8 mm plain +27.2% / +22.9%, 71.6 -> 68.5 mm; one "
      "slit +25.1% / +21.1%, 67.6 -> 67.4 mm, its slit open 7.8 -> 15.0 mm; 6 mm plain +24.2% / +21.6%, 72.0 -> "
      "70.1 mm; 6 mm one slit meets every bar, +22.0% / +19.2%, 66.6 -> 67.7 mm, slit 6.0 -> 14.4 mm. The free ends also heat the 6 cm loaf ~1.3x faster (middle 71 degC at 1.25 s, held 57, 2D 55), so "
      "its gas stops sooner and its volume falls from the peak; heated as slowly (bread3d.lua --set beta_scale=0.55) "
      "it gets its volume back (+28.2% / +23.5%) and still ends low (72.7 -> 68.0 mm). "
      "docs/validation.md, 'bread.lua in 3D' and 'bread.lua's 3D loaf: its ends and its yield'")
sys.exit(77)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    fail "$case_name: the loaf's volume does not grow (numbers above)"
    ;;
# The cause of claim_bread3d_*'s expected failure, checked (helper bread3d): the plain loaf extruded over the whole box
# (scripts/validation/bread3d.lua --set zw=0.12), its two ends against the box's slip walls so it cannot grow along its
# length, as a 2D (plane strain) loaf cannot, meets the 2D bars at the scene's 3D dx (8 mm) and at 6 mm (_fine): volume
# +15% at peak, +10% at the end, at least as tall as the raw dough. 104 s (8 mm) and ~15 min (6 mm) of wall time under
# load: campaign.
bread3d_ends_held_loaf_rises | bread3d_ends_held_loaf_rises_fine)
    dx=0.008
    [ "$case_name" = bread3d_ends_held_loaf_rises_fine ] && dx=0.006
    "$hearth" run "$root/scripts/validation/bread3d.lua" --quiet --set bread="$scenes/bread.lua" --set only=1 \
        --set zw=0.12 --set dx=$dx --set dx_min_3d=$dx >out.txt 2>err.txt || fail "bread3d.lua: exit $?: $(cat err.txt)"
    python3 "$root/tests/bread_claims.py" rises hearth-out/bread3d/bread.csv $dx plain 3 ||
        fail "the loaf with its ends held does not rise (numbers above)"
    ;;
# A loaf a baker shapes (helper loaf3d): bread.lua's plain and one-slit loaves with rounded ends instead of two flat
# cut faces (scripts/validation/bread3d.lua --set ends=round: the scene's 6 cm straight part, each end the 2D profile
# revolved, a half dome; 14 cm long, its ends free in a box 24 cm long), at the scene's 3D dx (8 mm) and one finer
# (6 mm, _fine), against the 2D bars set before the run (tests/bread_claims.py rises: volume +15% at the peak, +10% at
# the end, at least as tall as raw; the slit's gap > one cell at the end and wider than at the start). 8 mm: 1.5-6.5
# min of wall time under load; 6 mm: 16-41 min: campaign. Every bar met is a pass; when the volume holds and the
# height does not, the case prints the numbers and the cause found (docs/validation.md, "bread.lua's 3D loaf: its ends
# and its yield") and exits 77; a volume short of its bars is a failure.
# The loaf's foot on its tray (#18, helper loaffoot): *_sticky_tray_* is the plain rounded loaf on a sticky tray
# (bread.lua --set tray=sticky: the foot held where it touched, as on an unlined steel tray the dough has wetted),
# against the same bars. On bread.lua's separate tray (friction 0.4) the same loaf's foot slides out 10 mm a side and
# it ends 3.1 / 1.9 mm low; held, it meets every bar at 8 mm (with the scene's grid and with a node row on the tray).
# 8 mm: 51-90 s of wall time; 6 mm: 4.5-5.5 min: campaign.
bread3d_round_loaf_rises | bread3d_round_loaf_rises_fine | bread3d_round_scored_loaf_rises | bread3d_round_scored_loaf_rises_fine | \
bread3d_round_loaf_sticky_tray_rises | bread3d_round_loaf_sticky_tray_rises_fine)
    dx=0.008 only=1 col=plain tray=separate
    case $case_name in *_fine) dx=0.006 ;; esac
    case $case_name in *scored*) only=2 col=one_slit ;; esac
    case $case_name in *sticky_tray*) tray=sticky ;; esac
    "$hearth" run "$root/scripts/validation/bread3d.lua" --quiet --set bread="$scenes/bread.lua" --set only=$only \
        --set ends=round --set box_z=0.24 --set tray=$tray --set dx=$dx --set dx_min_3d=$dx >out.txt 2>err.txt ||
        fail "bread3d.lua: exit $?: $(cat err.txt)"
    python3 "$root/tests/bread_claims.py" rises hearth-out/bread3d/bread.csv $dx $col 3 && exit 0
    python3 - hearth-out/bread3d/bread.csv $col $tray <<'PY'
import csv, sys
v = [float(r["area_" + sys.argv[2]]) for r in csv.DictReader(open(sys.argv[1]))]
if max(v) / v[0] < 1.15 or v[-1] / v[0] < 1.10:
    sys.exit(1)
if sys.argv[3] == "separate":
    print("EXPECTED FAILURE: the rounded loaf's volume grows as the bars ask (plain 8 mm +27.2% / +22.9%, 6 mm +24.2% "
          "/ +21.6%; one slit 8 mm +25.1% / +21.1%) but it ends below its raw height (plain 71.6 -> 68.5 mm at 8 mm, 72.0 "
          "-> 70.1 at 6 mm; one slit 67.6 -> 67.4 at 8 mm, its slit open 7.8 -> 15.0 mm; at 6 mm the one-slit loaf "
          "meets every bar: 66.6 -> 67.7 mm, slit 6.0 -> 14.4 mm), because its free ends leave it out of plane strain: "
          "the gas stretches its middle along z as much as across (the plain loaf's middle 11.0% longer at 8 mm, 8.3% at "
          "6 mm; elastic strain along z 0.119, across 0.136 and up 0.041 at 8 mm) where 2D and a loaf held at its ends "
          "along z put 1 + nu = 1.3 times more of the same gas into the cross-section; its middle section gains +13.0% "
          "(8 mm) and +14.3% (6 mm) against the held loaf's +29.4%. "
          "On a sticky tray (bread.lua --set tray=sticky), its foot held instead of sliding out 10 mm a side, the plain "
          "rounded loaf meets every bar at 8 mm (71.6 -> 72.5 mm) and ends 72.0 -> 71.9 mm at 6 mm "
          "(bread3d_round_loaf_sticky_tray_rises; docs/validation.md, 'The loaf's foot on its tray'). A separate tray "
          "that also held the first node row above a face between rows (SEPARATE_NEAR_BAND, helper touchrows; tried and "
          "reverted, it moved the stability matrix) stood the plain rounded loaf at its raw height at 8 and 6 mm "
          "(71.6 -> 71.6, 72.0 -> 72.0 mm, nothing to spare) and the one-slit one 67.6 -> 70.7 mm at 8 mm, slit 7.8 -> "
          "16.2 mm (docs/validation.md, 'The separate tray between node rows'). "
          "docs/validation.md, 'bread.lua's 3D loaf: its ends and its yield'")
else:
    print("EXPECTED FAILURE: on a sticky tray the rounded loaf's volume grows as the bars ask (6 mm +22.7% / +18.9%) "
          "and it stands 72.0 -> 71.9 mm, one probe step (0.12 mm) short of its raw height (8 mm: 71.6 -> 72.5 mm, a "
          "pass), having stood 72.5 mm at 2.25 s, because the held foot's gain depends on where the grid's rows fall "
          "against the tray and its middle is still out of plane strain: with the scene's rows 2 mm under the tray the "
          "hold gives 1.8 mm (separate 72.0 -> 70.1 mm), with a row on the tray (bread3d.lua --set grid_shift=0.004) "
          "it ends 72.1 -> 73.0 mm (separate 71.3); above the held foot (its edge 1.8 mm out against 9.1 on the "
          "separate tray) the gas still stretches the middle 6.6% along z (separate 8.3%). "
          "docs/validation.md, 'The loaf's foot on its tray (#18, helper loaffoot)'")
sys.exit(77)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    fail "$case_name: the rounded loaf's volume does not grow on a $tray tray (numbers above)"
    ;;
# bread.lua's tray (helper loaffoot) takes "separate" or "sticky"; another value is refused with a message naming
# the parameter and what it takes, before any step (its h.choice: lua/hearth/params.lua; a bad --set, exit 2).
bread_tray_refused)
    "$hearth" run "$scenes/bread.lua" --quiet --set tray=glue >out.txt 2>err.txt
    rc=$?
    [ $rc -eq 2 ] || fail "bread.lua with tray=glue exited $rc, expected 2: $(cat err.txt)"
    grep -q 'bread.lua:[0-9]*: --set tray=glue: tray takes one of the words below, not "glue"' err.txt ||
        fail "unexpected message: $(cat err.txt)"
    grep -q '^  "separate" *friction 0.4' err.txt || fail "separate and its friction not listed: $(cat err.txt)"
    grep -q '^  "sticky" *the foot held where it touched' err.txt || fail "sticky and what it does not listed: $(cat err.txt)"
    ;;
# #18, "the surface dries faster than the crumb": bread.lua's plain loaf, whose
# dough carries water (lua/hearth/dough.lua, WATER), at the scene's dx 5 mm and
# at 4 mm. At every frame after the start its top particle on the axis holds
# less of its water (X/X0) than the crumb's centre; at the end the top has lost
# more than 5 times the centre's share of its water, is below X/X0 0.5 (X =
# 0.41 kg/kg, where the dry crust's stiffening starts) and the centre keeps at
# least 85 % (a loaf loses about a tenth of its water in a bake).
claim_bread_surface_dries_first | claim_bread_surface_dries_first_fine)
    dx=0.005
    [ "$case_name" = claim_bread_surface_dries_first_fine ] && dx=0.004
    run bread --set only=1 --set dx=$dx --set frames=5 >/dev/null
    python3 "$root/tests/bread_claims.py" dries hearth-out/bread/bread.csv $dx ||
        fail "the loaf's surface does not dry before its crumb (numbers above)"
    ;;
# #18, Ding Fig. 16 ("the bread without an initial slit also cracked on the top
# surface"): at the end of the bake the plain loaf's top has a crack: a notch
# in the top of its intact material (bread.lua's crack_depth_m, crack_width_m:
# particles with damage 1 are the crack, not its surface) at least two cells
# wide and a tenth of the loaf's height deep. At the scene's dx (5 mm) and one
# finer (4 mm, release_only). The 4 mm pass is one of two rungs, 4 and 3 mm,
# where the crown cracks; at 4.5, 3.5 and 2.5 mm it does not, and at 2 mm (or 4
# mm with 9 particles a cell) a shoulder cracks instead, and at 4 mm with the
# other two loaves in the run (sharing its time step) the crown does not crack
# (0.16 mm): the crack is not converged in dx (scripts/validation/bread_grid.sh,
# docs/validation.md "bread.lua over dx"), so the default stays 5 mm. Nor in dt:
# the 4 mm pass holds for steps around the scene's default (cfl 0.4-0.6) only; at
# cfl 0.25, 0.75 or a uniform step of 1e-4 s and less the crown holds and a flank
# cracks, and at 5 mm no step cracks the top (scripts/validation/crack_dt.sh, docs/validation.md
# "The crack over the time step").
claim_bread_unscored_cracks | claim_bread_unscored_cracks_fine)
    dx=0.005
    [ "$case_name" = claim_bread_unscored_cracks_fine ] && dx=0.004
    run bread --set only=1 --set dx=$dx --set frames=5 >/dev/null
    python3 "$root/tests/bread_claims.py" cracks hearth-out/bread/bread.csv $dx
    exit $?
    ;;
# scripts/validation/crack_heat.lua (docs/validation.md, "The unscored crack at
# 5 mm") runs bread.lua itself with the preset's heat switchable: at its
# defaults it writes the same bread.csv as bread.lua's plain loaf (0.5 s), so
# its table reads the scene; with a real Biot number (conductivity 0.0234)
# the loaf's top is warmer than its centre by more than 10 degC at 0.5 s,
# and with Table 2's heat (Biot 0.04) within 2 degC: a slab's surface leads
# its centre by about Bi / 2 of the oven's lead on the surface, 0.02 x 73 K.
validation_crack_heat_matches_bread)
    quick=(--set only=1 --set until_t=0.5 --set frames=1)
    run bread "${quick[@]}" >/dev/null
    cp hearth-out/bread/bread.csv scene.csv
    for k in 1 0.0234; do
        "$hearth" run "$root/scripts/validation/crack_heat.lua" --quiet "${quick[@]}" --set conductivity=$k \
            --set bread="$scenes/bread.lua" >"heat_$k.txt" 2>err.txt || fail "crack_heat.lua: exit $?: $(cat err.txt)"
        cp hearth-out/crack_heat/bread.csv "csv_$k.csv"
    done
    cmp -s scene.csv csv_1.csv || fail "crack_heat.lua at its defaults differs from bread.lua: $(diff scene.csv csv_1.csv)"
    python3 - heat_1.txt heat_0.0234.txt <<'PY' || fail "crack_heat.lua's conductivity knob does not act (numbers above)"
import re, sys
def last(f):
    rows = [l for l in open(f) if l.startswith("t ")]
    top, ctr = map(float, re.search(r"T top (\S+), .* centre (\S+), bottom", rows[-1]).groups())
    print(f"{f}: {rows[-1].strip()}")
    return top, ctr
t1, c1 = last(sys.argv[1])
t2, c2 = last(sys.argv[2])
sys.exit(0 if abs(t1 - c1) < 2 and t2 - c2 > 10 else 1)
PY
    ;;
# scripts/validation/muffin_tear.lua (docs/validation.md, "The muffin's tear")
# runs muffins.lua itself with the muffin's crust switchable: at its defaults
# it writes the same muffins.csv as muffins.lua (one cup, 0.75 s), so its
# table reads the scene. By 0.75 s the rise has cracked a skin brittle by its
# water alone (heat_set = 0: more than 10 particles), and nothing has cracked
# with the preset's heat-set (the dried skin waits for its set: helper crisp)
# nor with dry_fracture = 0 (the stretch to fracture over water taken away).
# The skin's drying stiffness acts on the rise by then: without it
# (skin_dry = 0) the centre stands less far above the edge, and a crust
# depth's reading (crust_depth = 0.002, a stiffer skin at 4 mm) holds the
# centre's top lower (helper muffin3). band and fracture act only once the
# crown cracks, past 1 s (their numbers: docs/validation.md, "The muffin's
# tear over dx"), so they are not run here.
validation_muffin_tear_matches_muffins)
    quick=(--set cups=1 --set until_t=0.75 --set frames=1)
    run muffins "${quick[@]}" >/dev/null
    cp hearth-out/muffins/muffins.csv scene.csv
    for k in preset "heat_set=0" "dry_fracture=0" "skin_dry=0" "crust_depth=0.002"; do
        knob=()
        [ "$k" != preset ] && knob=(--set "$k")
        "$hearth" run "$root/scripts/validation/muffin_tear.lua" --quiet "${quick[@]}" "${knob[@]}" \
            --set muffins="$scenes/muffins.lua" >/dev/null 2>err.txt || fail "muffin_tear.lua: exit $?: $(cat err.txt)"
        cp hearth-out/muffin_tear/muffins.csv "csv_${k%%=*}.csv"
    done
    cmp -s scene.csv csv_preset.csv || fail "muffin_tear.lua at its defaults differs from muffins.lua: $(diff scene.csv csv_preset.csv)"
    python3 - csv_preset.csv csv_heat_set.csv csv_dry_fracture.csv <<'PY' || fail "muffin_tear.lua's knobs do not act (numbers above)"
import csv, sys
n, nh, nd = (int(list(csv.DictReader(open(f)))[-1]["cracked_1"]) for f in sys.argv[1:4])
print(f"cracked particles at 0.75 s: the preset {n} (need 0), heat_set = 0 {nh} (need > 10), dry_fracture = 0 {nd} "
      f"(need 0)")
sys.exit(0 if n == 0 and nh > 10 and nd == 0 else 1)
PY
    python3 - csv_preset.csv csv_skin_dry.csv csv_crust_depth.csv <<'PY' || fail "muffin_tear.lua's skin knobs do not act (numbers above)"
import csv, sys
p, s, c = (list(csv.DictReader(open(f)))[-1] for f in sys.argv[1:4])
ce = lambda r: float(r["centre_above_edge_1_m"]) * 1e3
top = lambda r: float(r["top_above_rim_1_m"]) * 1e3
print(f"at 0.75 s: centre above the edge {ce(p):.2f} mm, skin_dry = 0 {ce(s):.2f} mm (need less); centre's top from "
      f"the rim {top(p):.2f} mm, crust_depth = 0.002 {top(c):.2f} mm (need lower)")
sys.exit(0 if ce(s) < ce(p) and top(c) < top(p) else 1)
PY
    ;;
# scripts/validation/muffin_heat_slab.lua (docs/validation.md, "The muffin's
# tear: the heat under the crown"): the muffin preset's heat through an oven
# top against the half-space's closed form (Carslaw & Jaeger §2.7). Is the
# heat per area the same over dx? At 4, 3 and 2 mm, from 0.5 s (at 0.25 s the
# thermal layer, 3.5 mm, is thinner than a 4 mm cell: 0.87 there), each
# frame's heat taken in per area is within 10% of the closed form, and the
# 2 mm slab has taken in at least as much as the 4 mm one: a finer grid does
# not bring the heat to the crumb later (helper muffin4: 0.93-1.05).
validation_muffin_heat_slab_per_area)
    for dx in 0.004 0.003 0.002; do
        "$hearth" run "$root/scripts/validation/muffin_heat_slab.lua" --quiet --set dx=$dx --set until_t=1 \
            --set frames=4 >"slab_$dx.txt" 2>err.txt || fail "muffin_heat_slab.lua dx=$dx: exit $?: $(cat err.txt)"
    done
    python3 - slab_0.004.txt slab_0.003.txt slab_0.002.txt <<'PY' || fail "the oven top's heat per area is off the closed form (numbers above)"
import re, sys
ok, last = True, []
for f in sys.argv[1:]:
    rows = [(float(t), float(q)) for t, q in re.findall(r"t ([\d.]+) s: heat in per area ([\d.]+)", open(f).read())]
    print(f"{f}: " + ", ".join(f"{t:.2f} s {q:.4f}" for t, q in rows))
    ok &= len(rows) == 4 and all(abs(q - 1) <= 0.1 for t, q in rows if t >= 0.5)
    last.append(rows[-1][1] if rows else 0)
print(f"heat in at 1 s over the closed form: 4 mm {last[0]:.4f}, 2 mm {last[2]:.4f} (need 2 mm >= 4 mm)")
sys.exit(0 if ok and last[2] >= last[0] else 1)
PY
    ;;
# #18, Ding §7.3 ("too much leavening agent would produce a very tall cookie,
# while no leavener at all yields a flat one"): in cookies.lua's 150 degC oven
# the most leavened cookie (0.015) ends at least 1.3x as tall as the
# unleavened one, and domed (both measures of its top curve down). At the
# claims' coarse dx (7.5 mm), the scene's (_fine, 5 mm) and one finer
# (_finer, 3.75 mm, suite campaign). Passes since the cookie sets at its
# gluten's glass transition, 71-78 degC (lua/hearth/dough.lua, COOKIE_SET;
# docs/validation.md "The cookie's set"): before, 1.068x and 1.049x. At all
# three levels since the porosity is the gas volume fraction and open surface
# pores vent ("The cookie's skin"): 1.364 / 1.354 / 1.330; _finer was an
# expected failure at 1.291 before, and is now a plain test. Since helper
# flat3 (cookies.lua bakes a real dough's conductivity and a 17.5 mm dough):
# 1.649 / 1.559 / 1.542.
claim_cookie_leavened_taller | claim_cookie_leavened_taller_fine | claim_cookie_leavened_taller_finer)
    dx=0.0075
    [ "$case_name" = claim_cookie_leavened_taller_fine ] && dx=0.005
    [ "$case_name" = claim_cookie_leavened_taller_finer ] && dx=0.00375
    run cookies --set dx=$dx --set until_t=4 --set frames=1 --set ovens=150 --set leaveners=0.015,0 >/dev/null
    python3 - hearth-out/cookies/cookies.csv $dx "$case_name" <<'PY'
import csv, sys
rows = {float(r["leavener"]): r for r in csv.DictReader(open(sys.argv[1]))}
h = {k: float(r["height_m"]) for k, r in rows.items()}
k = [float(rows[0.015][c]) for c in ("top_curvature_1_per_m", "top_curvature_particles_1_per_m")]
se = float(rows[0.015]["top_curvature_particles_se_1_per_m"])
ratio = h[0.015] / h[0.0]
print(f"dx {float(sys.argv[2]) * 1e3:.2f} mm: leavened {h[0.015] * 1e3:.1f} mm, unleavened {h[0.0] * 1e3:.1f} mm, "
      f"ratio {ratio:.3f} (need >= 1.3); leavened top curvature {k[0]:.2f}, {k[1]:.2f} +- {se:.2f} 1/m (probe, "
      "particles +- the fit's standard error; domed: both < 0)")
if ratio < 1.3:
    print("the ratio was 1.068x / 1.049x (dx 7.5 / 5 mm) while the cookie set from 35 degC on bread's Fig. 8 "
          "curve (docs/validation.md, 'The cookie, measured again' to 'The cookie's CO2 traced'): check "
          "h.library.paper.cookie's tau_y and eta curves (lua/hearth/dough.lua, COOKIE_SET); and 1.322 / 1.306 / "
          "1.291 (7.5 / 5 / 3.75 mm) while the porosity was the linear J^P - 1 + n0, whose clamp at 1 let the skin "
          "swell (docs/validation.md, 'The cookie's skin': core/sim/fields/gas.h, gas_porosity; gas_vent)")
sys.exit(0 if ratio >= 1.3 and all(x < 0 for x in k) else 1)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "the leavened cookie is not 1.3x as tall and domed (numbers above)"
    ;;
# §7 and Fig. 2: muffins rise into a dome. The tin sets the batter at its
# walls and floor while the centre still rises with gas, so at the end of a
# coarse bake (2D, dx 4 mm, one cup, 1.5 s: the rise is over by ~1.3 s) the
# centre's top stands more than one grid cell above the top at the walls, the
# top's parabola curves down, and the centre rose from where it started.
# _fine: the same bake at dx 3 mm (#18: each claim at the scene's dx and one finer).
claim_muffin_domes | claim_muffin_domes_fine)
    dx=0.004
    [ "$case_name" = claim_muffin_domes_fine ] && dx=0.003
    run muffins --set cups=1 --set dx=$dx --set until_t=1.5 --set frames=3 >/dev/null
    python3 - hearth-out/muffins/muffins.csv $dx <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
dx = float(sys.argv[2])
top0, top1 = float(rows[0]["top_above_rim_1_m"]), float(rows[-1]["top_above_rim_1_m"])
ce, k = float(rows[-1]["centre_above_edge_1_m"]), float(rows[-1]["top_curvature_1_1_per_m"])
for r in rows:
    print(f"  t = {r['t']} s: centre {float(r['centre_above_edge_1_m']) * 1e3:.2f} mm above the edge, curvature "
          f"{float(r['top_curvature_1_1_per_m']):.2f} 1/m, notch {float(r['tear_depth_1_m']) * 1e3:.2f} mm, {r['cracked_1']} cracked")
print(f"dx {dx * 1e3:.0f} mm, t = {rows[-1]['t']} s: centre {ce * 1e3:.2f} mm above the edge (need > dx = {dx * 1e3:.1f} mm), "
      f"top curvature {k:.2f} 1/m (need < 0); centre top {top0 * 1e3:.2f} -> {top1 * 1e3:.2f} mm from the rim")
if ce > dx and k < 0 and top1 > top0:
    sys.exit(0)
if dx == 0.004:
    sys.exit(1)
print("EXPECTED FAILURE: at 3 mm the muffin domes by 1.0 s (the rows above: curvature -45 1/m, centre 10.5 mm above "
      "the edge) and then its crown tears at both shoulders (cracked one-cell bins -4..-2 and +2..+4 from the axis at "
      "1.5 s: docs/validation.md, 'The crown's crack: a bulge three cells wide'), the crumb between them bulging up "
      "into a flat top, so the fit over 0.6 R turns positive though the centre stands 17.7 mm above the edge; with "
      "nothing able to crack (scripts/validation/muffin_tear.lua --set fracture=0) the same bake reads -40.0 1/m at "
      "1.5 s, so the tear, not the rise, flattens it. The "
      "same missing piece as claim_muffin_top_tears_fine: a crack that localises and opens, not a zone that spreads.")
sys.exit(77)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "the muffin does not dome (numbers above)"
    ;;
# #18: the muffin's dome with the physical batter (muffins.lua --set preset=physical: h.library.dough.muffin, its
# measured density, heat capacity and conductivity, latent heat and boiling; 22 s stand for a 22 minute bake at
# 180 degC). The same bars as claim_muffin_domes, set for the paper batter before this run: at the end of the bake
# the centre's top stands more than one cell above the top at the walls, the top's parabola over 0.6 R curves down,
# and the centre rose from where it started. At dx 4 mm (the scene's) and 3 mm (_fine, suite campaign for its cost).
# The physical batter has no crust fracture (it domes, it does not tear): Fig. 2's tear is the paper batter's claim.
claim_muffin_physical_domes | claim_muffin_physical_domes_fine)
    dx=0.004
    [ "$case_name" = claim_muffin_physical_domes_fine ] && dx=0.003
    run muffins --set cups=1 --set preset=physical --set dx=$dx --set frames=4 >/dev/null
    python3 - hearth-out/muffins/muffins.csv $dx <<'PY' || fail "$case_name: the physical muffin does not dome (numbers above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
dx = float(sys.argv[2])
top0, top1 = float(rows[0]["top_above_rim_1_m"]), float(rows[-1]["top_above_rim_1_m"])
ce, k = float(rows[-1]["centre_above_edge_1_m"]), float(rows[-1]["top_curvature_1_1_per_m"])
for r in rows:
    print(f"  t = {float(r['t']):.1f} s: centre top {float(r['top_above_rim_1_m']) * 1e3:+.2f} mm from the rim, "
          f"{float(r['centre_above_edge_1_m']) * 1e3:.2f} mm above the edge, curvature {float(r['top_curvature_1_1_per_m']):.2f} 1/m")
print(f"dx {dx * 1e3:.0f} mm, t = {float(rows[-1]['t']):.0f} s (the preset's 60 times fast: {float(rows[-1]['t']):.0f} min): centre {ce * 1e3:.2f} mm above the edge (need > dx = "
      f"{dx * 1e3:.1f} mm), top curvature {k:.2f} 1/m (need < 0); centre top {top0 * 1e3:.2f} -> {top1 * 1e3:.2f} mm from the rim "
      f"(need a rise)")
sys.exit(0 if ce > dx and k < 0 and top1 > top0 else 1)
PY
    ;;
# #18, Ding §7.3 with the physical cookie (cookies.lua --set preset=physical: h.library.dough.cookie, a sugar-snap
# dough's measured or composition-predicted density, heat capacity and conductivity, latent heat, boiling and
# browning on; 13.2 s stand for 11 minutes at 190 degC, h.library.oven.cookie's bake). The same bar as
# claim_cookie_leavened_taller, set before this was run: the most leavened cookie (0.015) ends at least 1.3x as tall
# as the unleavened one, and domed (both measures of its top curve down). In the preset's own 190 degC oven, at the
# scene's dx 5 mm and one finer (_fine, 3.75 mm, suite campaign). Expected failures (1.07x, 1.14x) until the preset's
# CO2 took its formula's two shares, each on its own bell (helper sodatwo: the NH4Cl share at 60 degC, before the 78
# degC set; the leftover soda at 100): 1.545x and 1.814x (docs/validation.md, "The physical cookie's two shares").
# At 5 mm the particles' curvature (-0.26 +- 3.57 1/m) does not resolve its sign; the probe's does (-10.4).
claim_cookie_physical_leavened_taller | claim_cookie_physical_leavened_taller_fine)
    dx=0.005
    [ "$case_name" = claim_cookie_physical_leavened_taller_fine ] && dx=0.00375
    run cookies --set preset=physical --set dx=$dx --set frames=1 --set ovens=190 --set leaveners=0.015,0 >/dev/null
    python3 - hearth-out/cookies/cookies.csv $dx <<'PY'
import csv, sys
rows = {float(r["leavener"]): r for r in csv.DictReader(open(sys.argv[1]))}
h = {k: float(r["height_m"]) for k, r in rows.items()}
w = {k: float(r["spread_m"]) for k, r in rows.items()}
k = [float(rows[0.015][c]) for c in ("top_curvature_1_per_m", "top_curvature_particles_1_per_m")]
se = float(rows[0.015]["top_curvature_particles_se_1_per_m"])
ratio = h[0.015] / h[0.0]
print(f"dx {float(sys.argv[2]) * 1e3:.2f} mm, 11 min at 190 degC: leavened {h[0.015] * 1e3:.1f} mm tall, {w[0.015] * 1e3:.1f} mm "
      f"wide; unleavened {h[0.0] * 1e3:.1f} mm, {w[0.0] * 1e3:.1f} mm; ratio {ratio:.3f} (need >= 1.3); leavened top curvature "
      f"{k[0]:.2f}, {k[1]:.2f} +- {se:.2f} 1/m (probe, particles +- the fit's standard error; domed: both < 0)")
sys.exit(0 if ratio >= 1.3 and all(x < 0 for x in k) else 1)
PY
    [ $? -eq 0 ] || fail "the physical leavened cookie is not 1.3x as tall and domed (numbers above)"
    ;;
# cookies.lua --set preset=physical refuses a lever on Table 2's cookie (here conductivity, a factor on Table 2's
# kappa): exit non-zero before baking, the message naming the scene's file and line, the parameter and the preset
# it belongs to.
cookies_physical_lever_refused)
    "$hearth" run "$scenes/cookies.lua" --quiet --set preset=physical --set conductivity=1 >out.txt 2>err.txt &&
        fail "cookies.lua took --set conductivity=1 with preset=physical"
    grep -q "cookies.lua:[0-9]*:.*--set conductivity=1: .*preset=paper only" err.txt ||
        fail "the refusal does not name the file, line, parameter and preset: $(cat err.txt)"
    [ -d hearth-out/cookies ] && [ -n "$(find hearth-out/cookies -name '*.png')" ] && fail "it baked before refusing"
    cat err.txt
    ;;
# #18, Ding Fig. 2: the muffin's top tears as it domes. A tear is a notch in
# the top of the intact batter (muffins.lua's tear_depth, tear_width over
# one-cell bins of the highest particle with damage below 1) at least two
# cells wide and a tenth of the muffin's height (its centre top above the
# cup's floor) deep, at the end of claim_muffin_domes' bake (2D, one cup,
# 1.5 s): at dx 4 mm, and at 3 mm (_fine, in suite campaign for its cost: tests/meson.build).
# At 4 mm the notch is a V the crown opens by flow (4.69 mm deep with nothing
# able to crack; its 2 cracked particles make it two cells wide), deep enough
# from ~1.45 to ~1.7 s (docs/validation.md, "The muffin's tear over dx"), and
# that V is the risen crumb parting along one column of particles at 4 a cell
# (none at 9 a cell, nor at dx 3.8 or 4.2 mm: helper muffin4, "The muffin's
# tear: the heat under the crown, and particles a cell"), so _ppc9 asks the
# claim of the same 4 mm bake with 9 particles a cell (suite campaign: 36 s, a finding rather than a regression check).
# The 4 mm pass holds at the scene's default step only: at cfl 0.125-0.75 but
# 0.5, or a uniform step of 5e-5 s and less, the V reads one cell wide (at cfl
# 0.25 1.50 mm deep); the 3 mm notch reads 3.80-4.00 mm at every step tried
# (scripts/validation/muffin_dt.sh, docs/validation.md "The crack over the time step").
claim_muffin_top_tears | claim_muffin_top_tears_fine | claim_muffin_top_tears_ppc9)
    dx=0.004 ppc=0
    [ "$case_name" = claim_muffin_top_tears_fine ] && dx=0.003
    [ "$case_name" = claim_muffin_top_tears_ppc9 ] && ppc=9
    run muffins --set cups=1 --set dx=$dx --set ppc=$ppc --set until_t=1.5 --set frames=3 >/dev/null
    python3 - hearth-out/muffins/muffins.csv $dx $ppc <<'PY'
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))[-1]
dx, ppc = float(sys.argv[2]), int(sys.argv[3])
BASE, RIM = 0.012, 0.042  # the cup's inner floor and rim (scripts/scenes/baking/muffins.lua)
height = RIM + float(r["top_above_rim_1_m"]) - BASE
d, w = float(r["tear_depth_1_m"]), float(r["tear_width_1_m"])
print(f"dx {dx * 1e3:.0f} mm, {ppc or 4} particles a cell, t = {r['t']} s: deepest notch in the top {d * 1e3:.2f} mm deep (need >= "
      f"{0.1 * height * 1e3:.2f} mm), {w * 1e3:.0f} mm wide (need >= {2 * dx * 1e3:.0f} mm); dome "
      f"{float(r['centre_above_edge_1_m']) * 1e3:.2f} mm")
if d >= 0.1 * height and w >= 2 * dx:
    sys.exit(0)
print("EXPECTED FAILURE: the notch in the crown is short of a tenth of the height. The skin's drying brittleness "
      "waits for its heat-set (cam_clay_dough's fracture_unset, 1 at 55 degC to 0 at 70: lua/hearth/dough.lua "
      "HEAT_SET), so the dried skin stretches unharmed through the rise and its crown cracks once it sets, late in "
      "the rise (0.875-1.125 s), and the crumb under it, not yet set (40-55 degC 3-5 mm under it at 1.25 s), rises "
      "into the crack: at 4 particles a cell the notch at 1.5 s is 3.33 / 3.85 / 2.92 mm at dx 3.5 / 3 / 2.5 mm "
      "(deepest 3.2-5.3 mm during the rise) (docs/validation.md 'The muffin's tear: the heat-set', 'over dx'). "
      "Helper muffin4 ('The muffin's tear: the heat under the crown, and particles a cell'): not a heat error over "
      "dx (an oven top's heat per area is within 13 / 6 / 5 % of the half-space's closed form at 4 / 3 / 2 mm, "
      "scripts/validation/muffin_heat_slab.lua; the crumb 2-10 mm under the crown is within ~5 degC at 4 / 3 / 2.5 mm at 1.25 s), "
      "nor the crack's air (cracked particles taken out of the oven's volume fraction: 3.85 -> 3.86 mm at 3 mm). "
      "The 4 mm pass (4.70 mm) is the risen crumb parting along one column of particles at 4 a cell (4.69 mm with "
      "nothing able to crack; 0.00 at 9 a cell and at dx 3.8 and 4.2 mm, where the preset reads 2.59 and 1.25 mm). "
      "At 9 particles a cell the 4 and 3 mm tops agree (10.7 / 10.4 mm above the rim) and the crown cracks "
      "(12 / 20 particles) without one opening: notch 1.52 / 0.31 mm at 1.5 s, deepest 1.52 / 2.30 mm over the "
      "bake. The missing piece is a crack that localises in the set crown, not the grid. Helper crownband ('The "
      "crown's crack: a bulge three cells wide'): the first crack is a zone three cells wide (the quadratic "
      "B-spline's support) at 9 and 16 a cell and at 3 and 4 mm; its neighbours do not unload (206 -> 333 Pa) and "
      "the crumb bulges up under it (top 10.7 mm above the rim against 6.9 with nothing able to crack), so the zone "
      "spreads a bin a side at a time; no crack band (1.50 mm at 4 mm, 9 a cell), E x10 once set (1.14), two "
      "velocity fields (0.77) or softening from the first damage (0.50) narrows it; a set crumb brittle in "
      "proportion to its set deepens the crack (3 mm, 4 a cell: 5.44 mm) but does not localise it (9 a cell: 1.39) "
      "and turns the 4 mm dome's curvature positive, so it is not adopted; a crack-tracking exclusion (a core "
      "experiment, taken out) localises it to one column but one cell wide (2.66 mm at 4 mm, 9 a cell; 3 mm: 5.35 mm "
      "deep, 3 mm wide). Helper cracktrack ('The crown's crack: tracked, with two fields', a core probe taken "
      "out): tracking with two velocity fields and set_prop parts the tracked crack's faces (4 mm, 9 a cell: two "
      "lobes, a notch two cells wide) but the unset crumb under it (50-58 degC a few mm down) rises into the "
      "opening: 3.59 mm (need 4.01), 3 mm 4 a cell 3.42 (4.01), 3 mm 9 a cell 1.50 (3.98); it takes this 4 mm "
      "claim from 4.70 to 3.74 mm and turns the 4 mm, 9 a cell dome's curvature positive (+3.0 1/m), so it is not "
      "built; without set_prop the crack stays a column (1.73 mm at 4 mm, 9 a cell)")
sys.exit(77)
PY
    exit $?
    ;;
# §7.1, Figs. 9 and 13: a drying body loses volume as it loses water,
# monotonically: over a coarse drying run, sampled every 0.1 s, the water left
# falls at every sample and so does the volume (s:volume()).
claim_drying_volume_monotone)
    run drying --set dx=0.004 --set until_t=0.6 --set frames=6 >/dev/null
    python3 - hearth-out/drying/drying.csv <<'PY' || fail "volume does not fall monotonically with the water (numbers above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
w = [float(r["water_fraction"]) for r in rows]
v = [float(r["volume"]) for r in rows]
print("water fraction:", w)
print("volume:", v)
ok = len(rows) >= 5 and all(w[k + 1] < w[k] and v[k + 1] < v[k] for k in range(len(rows) - 1))
sys.exit(0 if ok else 1)
PY
    ;;
# Fig. 11: the pancake is flipped: after the flip event the spatula lifts
# the batter (its mean height rises well above its resting height), carries
# it over the pivot and lays it down on the far side, where it rests again.
# Before the thermal expansion stress used the elastic J (core/sim/solver/mpm.c),
# the guard stopped this run mid-turn.
claim_pancake_flips)
    run pancake --set dx=0.004 --set until_t=1.2 --set frames=12 >/dev/null
    python3 - hearth-out/pancake/pancake.csv <<'PY' || fail "the pancake was not flipped over (numbers above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
before = [r for r in rows if r["flipped"] == "0"]
during = [r for r in rows if r["flipped"] == "1"]
XP = 0.165  # the spatula's pivot x (scripts/scenes/baking/pancake.lua)
h0, x0 = float(before[-1]["mean_height_m"]), float(before[-1]["mean_x_m"])
hmax = max(float(r["mean_height_m"]) for r in during)
h1, x1 = float(rows[-1]["mean_height_m"]), float(rows[-1]["mean_x_m"])
print(f"before the flip: mean height {h0*1e3:.2f} mm at x {x0:.4f} m; highest during it {hmax*1e3:.2f} mm; "
      f"at the end {h1*1e3:.2f} mm at x {x1:.4f} m (pivot x {XP})")
sys.exit(0 if x0 < XP < x1 and hmax > 5 * h0 and h1 < 2 * h0 else 1)
PY
    ;;

# Fig. 4: the lava cake's molten centre flows out once the cut opens it: the
# material reaches further right along the plate at the end than just after
# the cut (by at least two cells). Before the thermal expansion fix the guard
# stopped the run 0.06 s after the cut.
claim_lava_cake_flows_out)
    run lava_cake --set dx=0.004 --set dt_max=0 --set frames=9 >/dev/null
    python3 - hearth-out/lava_cake/lava_cake.csv <<'PY' || fail "the centre does not flow out after the cut (numbers above)"
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
cut = 1.2  # bake 0.8 s + lift 0.4 s (scripts/scenes/baking/lava_cake.lua)
after = [r for r in rows if float(r["t_s"]) >= cut - 1e-9]
r0, r1 = float(after[0]["reach_right_m"]), float(rows[-1]["reach_right_m"])
print(f"reach right of the centre: {r0*1e3:.1f} mm at the cut (t = {after[0]['t_s']} s), {r1*1e3:.1f} mm at t = {rows[-1]['t_s']} s")
sys.exit(0 if len(after) >= 3 and r1 > r0 + 2 * 0.004 else 1)
PY
    ;;

# Fig. 6, our claim (the paper shows the grid without a stated trend): after
# the same pull, at eta = 1e8 Pa^3 s a low-yield dough (300 Pa) flows along
# its length and keeps a thicker neck than a 1000 Pa dough, which necks next
# to its grips; and at tau_y = 1000 Pa a more viscous dough (1e10) necks less
# than the 1e8 one.
claim_pull_twist_neck)
    run pull_twist --set dx=0.004 --set until_t=0.3 --set taus=300,1000 --set etas=1e8,1e10 >/dev/null
    python3 - hearth-out/pull_twist/pull_twist.csv <<'PY' || fail "the necks do not order as claimed (numbers above)"
import csv, sys
neck = {(float(r["tau_y_Pa"]), float(r["eta_Pa3s"])): float(r["neck_m"]) for r in csv.DictReader(open(sys.argv[1]))}
print("neck (m) by (tau_y, eta):", neck)
sys.exit(0 if neck[(300, 1e8)] > neck[(1000, 1e8)] and neck[(1000, 1e10)] > neck[(1000, 1e8)] else 1)
PY
    ;;
# #18, Ding Fig. 18: "after roasting a crust forms on the exterior and the
# interior is melted. When pressed the crust breaks and the inside oozes out."
# marshmallow.lua as a user runs it (2D, dx 2 mm; _fine 1.5 mm): the roasted
# one held in Table 2's s'more flame (its skin dries into a brittle crust, its
# inside melts), the raw one in room air, both then pressed 20 mm between
# sticking crackers. ooze is the fraction of the pressed marshmallow's outline
# (the outermost particle on each side, in each band of height dx) that is
# inside material (particles that started more than 4 mm from the surface).
# An intact skin stays the outline however it is squashed; the inside reaches
# it only through an opening. Claim: the roasted marshmallow's outline is at
# least a tenth inside material at the end of the press, and the raw one's
# (the control, pressed alike) under 2%.
claim_marshmallow_oozes | claim_marshmallow_oozes_fine)
    dx=0.002
    [ "$case_name" = claim_marshmallow_oozes_fine ] && dx=0.0015
    run marshmallow --set dx=$dx --set frames=2 >/dev/null
    python3 - hearth-out/marshmallow/marshmallow.csv $dx <<'PY'
import csv, sys
r = list(csv.DictReader(open(sys.argv[1])))[-1]
raw, roast = float(r["ooze_raw"]), float(r["ooze_roasted"])
print(f"dx {float(sys.argv[2]) * 1e3:.1f} mm, t = {r['t_s']} s (0.1 s after the press): ooze (inside material on the "
      f"outline) roasted {roast:.3f} (need >= 0.1), raw {raw:.3f} (need < 0.02); thickness roasted "
      f"{float(r['thickness_roasted_m']) * 1e3:.1f} mm, raw {float(r['thickness_raw_m']) * 1e3:.1f} mm; centre "
      f"roasted {float(r['centre_temperature_roasted_degC']):.1f} degC")
if roast >= 0.1 and raw < 0.02:
    sys.exit(0)
print("FAIL: the roasted crust did not let the inside out, or the raw one's skin opened too "
      "(docs/validation.md, 'The marshmallow's ooze (#18)': with slip crackers the cracked crust is pushed out "
      "whole at this press; pressed deeper the raw one curls over the crackers' edges too)")
sys.exit(1)
PY
    exit $?
    ;;
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
claim_raw_dough_stretches_before_tearing | claim_raw_dough_stretches_before_tearing_fine | \
claim_raw_batter_stretches_before_tearing | claim_raw_batter_stretches_before_tearing_fine)
    food=bread dx=0.005
    case $case_name in *batter*) food=muffin dx=0.004 ;; esac
    case $case_name in *batter*_fine) dx=0.003 ;; *dough*_fine) dx=0.004 ;; esac
    run tear_open --set food=$food --set dx=$dx --out baked >/dev/null
    run tear_open --set food=$food --set dx=$dx --set raw=true --out raw >/dev/null
    python3 - baked/tear_open.csv raw/tear_open.csv $food $dx <<'PY'
import csv, sys
def parted(path):
    rows = [r for r in csv.DictReader(open(path)) if float(r["separation_m"]) > 0]
    torn = [float(r["separation_m"]) for r in rows if int(r["pieces"]) >= 2]
    return (torn[0] if torn else None), float(rows[-1]["separation_m"]), max(float(r["force_mid_N_per_m"]) for r in rows)
(b, _, fb), (r, rmax, fr) = parted(sys.argv[1]), parted(sys.argv[2])
food, dx = sys.argv[3], float(sys.argv[4])
text = lambda v: "never" if v is None else f"{v * 1e3:.1f} mm"
print(f"{food}, dx {dx * 1e3:.0f} mm: the baked one parts at {text(b)} of separation (peak force {fb:.1f} N/m), the raw "
      f"one at {text(r)} (peak force {fr:.1f} N/m; need >= twice the baked, or not within {rmax * 1e3:.0f} mm)")
sys.exit(0 if b is not None and (r is None or r >= 2 * b) else 1)
PY
    [ $? -eq 0 ] || fail "the raw $food does not stretch further than the baked one before it parts (numbers above)"
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
# tear_open.lua as a user runs it, shortly: its CSV's cells are numbers (the faces' columns nan before the pull, and
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
        v = float(c)
        assert math.isfinite(v) or k.startswith("face_peak") or k == "crack_from_face_m", (k, c)
PY
    for bad in "dim=3:only dim=2" "food=cake:food takes one of the words below, not \"cake\"" "two_field=yes:expected true or false" \
               "frames=0:a whole number of frames"; do
        "$hearth" run "$scenes/tear_open.lua" --quiet --set "${bad%%:*}" >out.txt 2>err.txt && fail "--set ${bad%%:*} ran"
        grep -q "${bad#*:}" err.txt || fail "--set ${bad%%:*}: the message does not say '${bad#*:}': $(cat err.txt)"
    done
    ;;
*) fail "unknown case $case_name" ;;
esac
echo ok

# shellcheck shell=bash
# tests/baking/cookie.sh: cookies.lua: leavened against unleavened, flat tops, spread by oven, Fig. 17's dome; the
# physical cookie (Ding et al. 2019 §7.3).
# Sourced by tests/baking_test.sh, whose variables (case_name, hearth, root, scenes, COARSE) and
# functions (run, fail) it uses. An arm exits with its verdict or falls through to the driver's "ok"; any other
# case leaves `unmatched` set for the next part.
case "$case_name" in

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
# #18 (helper userfix5; userview3's item 5): each cookie's printed line says which curvature the claims read and what
# its particles' reading resolves. The bar, set before the first run: every cookie's line gives the probe's and the
# particles' curvature as cookies.csv holds them (to the printed 3 decimals), says "the claims need both", and calls the
# particles' reading "flat within noise" exactly when |k| < 2 standard errors, else domed (k < 0) or dented; the
# probe's domed (k < 0) or dented. A short coarse bake (0.3 s, dx 7.5 mm, ~1 s).
cookie_line_says_which_curvature)
    run cookies --set dx=0.0075 --set until_t=0.3 --set frames=1 --set ovens=150 --set leaveners=0.015,0 >out_run.txt
    python3 - out_run.txt hearth-out/cookies/cookies.csv <<'PY' || fail "a cookie's line does not say what its curvatures read (above)"
import csv, re, sys
lines = [l for l in open(sys.argv[1]) if l.startswith("oven ") and "height" in l]
rows = list(csv.DictReader(open(sys.argv[2])))
pat = re.compile(r"the claims need both\): probe ([-+]?[0-9.]+) 1/m, (domed|dented|flat); particles ([-+]?[0-9.]+) \+- "
                 r"([0-9.]+) 1/m, (flat within noise, \|k\| < 2 standard errors|domed|dented);")
ok = len(lines) == len(rows) >= 2
for l, r in zip(lines, rows):
    print(l.rstrip())
    m = pat.search(l)
    if not m:
        print("  no 'probe K 1/m, verdict; particles K +- SE 1/m, verdict' after 'the claims need both'")
        ok = False
        continue
    k, kp, se = float(r["top_curvature_1_per_m"]), float(r["top_curvature_particles_1_per_m"]), \
        float(r["top_curvature_particles_se_1_per_m"])
    want_p = "domed" if k < 0 else "dented" if k > 0 else "flat"
    want = "flat within noise" if abs(kp) < 2 * se else "domed" if kp < 0 else "dented"
    got = (float(m.group(1)), m.group(2), float(m.group(3)), float(m.group(4)), m.group(5))
    good = abs(got[0] - k) < 6e-4 and abs(got[2] - kp) < 6e-4 and abs(got[3] - se) < 6e-4 and got[1] == want_p \
        and got[4].startswith(want)
    print(f"  csv: probe {k}, particles {kp} +- {se}: want {want_p}, {want}; {'ok' if good else 'MISMATCH'}")
    ok = ok and good
sys.exit(0 if ok else 1)
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
# At 5 mm the particles' curvature (-0.26 +- 3.57 1/m) does not resolve its sign; the probe's does (-10.4). Since
# open pores vent toward the atmosphere (helper cookiecool) it reads +2.40 +- 3.96 there: an expected failure (exit
# 77) while the ratio holds, the probe reads a dome and the particles' reading is within two standard errors of 0;
# any reading the measures resolve as not domed fails. _fine passes (1.826x; -23.0, -19.6 +- 2.9 1/m).
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
if ratio >= 1.3 and all(x < 0 for x in k): sys.exit(0)
if ratio >= 1.3 and k[0] < 0 and abs(k[1]) < 2 * se:
    print("EXPECTED FAILURE (#18, helper cookiecool): taller, and domed by the probe, but the particles' curvature is "
          "within two standard errors of 0, so its sign is not resolved at this dx. Since open pores vent toward the "
          "atmosphere (core/sim/fields/gas.c) the 5 mm reading was +2.40 +- 3.96 1/m (was -0.26 +- 3.57); over the "
          "particles' samplings (--set seed=1..4) it read +2.40, -20.76, +2.27, -15.43 (before -0.26, -7.04, -0.77, "
          "-18.12), a coin flip of the sampling, with the sheet at the oven's temperature from the first step; since "
          "the sheet goes in cold, -17.16 +- 2.73, -32.63, -34.74, -12.99 +- 3.51 (docs/validation.md 'A tray that "
          "goes in cold'); at 3.75 mm both measures read it clearly "
          "(docs/validation.md 'The physical cookie in the cooler ovens (#18, helper cookiecool)')")
    sys.exit(77)
sys.exit(1)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "the physical leavened cookie is not 1.3x as tall and domed (numbers above)"
    ;;
# #18 (helper cookiecool): the physical cookie ends in one piece in each of Fig. 17's ovens. cookies.lua --set
# preset=physical bakes the three leaveners (0.015, 0.0075, 0) in the 190, 150 and 110 degC ovens; each cookie's
# particles are linked when within two seeded spacings (dx), and at most 1% of them may lie outside the largest
# linked group (cookies.lua's shed column). The bar was set before the fix was run. Before, the most leavened cookie
# shed 10-11 particles (6-7%) at 150 and 110 degC (5 mm): open surface pores vented their CO2 to nothing, so their
# pores fell tens of kPa under the atmosphere while the dough was still soft (70-78 degC), the skin collapsed and the
# crumb it squeezed burst (docs/validation.md "The physical cookie in the cooler ovens (#18, helper cookiecool)").
# Since the vent exchanges a pore's gas with the air toward the atmosphere's pressure (core/sim/fields/gas.c) the
# 190 and 150 degC cookies are whole at 5 mm. Still short, so an expected failure (exit 77) while only the most
# leavened cookie misses: at 110 degC its foam swelled to a median J ~3.5 while eq. 14's bell had no depletion (the
# slow bake made 0.056 mol/kg of the NH4Cl share, the formula holds 0.042); since each share stops at its amount
# (gas_amount, gas_amount_2; helper depletion) it makes 0.042 and swells to a median J 3.3, and 10 of its 158
# particles (57 before; 141 of 280 at 3.75 mm, 195 before) still stand beyond the link, whose particle spacing dx/2
# sqrt(J) it nears; at 3.75 mm a few of its rim's outer particles slide down the flank to the tray, a link off the
# body, at 190 and 150 degC.
# Since the sheet goes in cold (h.library.dough.cookie's pan_start_temperature, a lumped sheet warming over 40 s;
# docs/validation.md "A tray that goes in cold") the base stays soft longer and the foams of the cooler ovens swell
# more before they set: 5 mm, 150 degC 0.015: 9 of 158; 110 degC 0.015: 18 of 158, 0.0075: 5 of 157 (none before);
# 3.75 mm, 150 degC 0.015: 4 of 280, 110 degC 0.015: 15 of 280 (141 before), 0.0075: 9 of 278; none at 190 degC at
# either dx, none of them by the stretched link. So the expected failure now reads: every miss is a leavened cookie
# in a cooler oven (150 or 110 degC), and the 190 degC oven's cookies are whole (which the old rule let the most
# leavened one miss). Since the dough draws its heat from the sheet (#18, helper traydraw: 2430 J/(m^2 K), the
# sheet at 127 degC at 1 min where it stood at 152 by the oven alone) the misses are 5 mm: 150 degC 0.015: 31 of 158,
# 110 degC 0.015: 32 of 158; 3.75 mm: 110 degC 0.015: 163 of 280; the 0.0075 cookies and the 3.75 mm 150 degC 0.015
# one whole; the 190 degC oven's whole (5 mm 0.015: 1 of 158, under the bar); the rule unchanged.
# shed_swollen (the link stretched by each pair's J, read after the bar was seen) is printed, not judged. Any other
# cookie past the bar fails (exit 1). At the scene's dx 5 mm and one finer (_fine, 3.75 mm, suite campaign).
claim_cookie_physical_whole_in_each_oven | claim_cookie_physical_whole_in_each_oven_fine)
    dx=0.005
    [ "$case_name" = claim_cookie_physical_whole_in_each_oven_fine ] && dx=0.00375
    run cookies --set preset=physical --set dx=$dx --set frames=1 --set ovens=190,150,110 >/dev/null
    python3 - hearth-out/cookies/cookies.csv $dx <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
bad = []
print(f"dx {float(sys.argv[2]) * 1e3:.2f} mm: particles beyond two spacings (dx) of each cookie's largest piece "
      "(need <= 1% of its particles; in brackets the same with the link stretched by J, not judged)")
for r in rows:
    n, off, offs = int(r["particles"]), int(r["shed"]), int(r["shed_swollen"])
    ok = off <= 0.01 * n
    print(f"  oven {r['oven_degC']} degC, leavener {r['leavener']}: {off} of {n} ({100 * off / n:.1f}%) [{offs}], height "
          f"{float(r['height_m']) * 1e3:.1f} mm, spread {float(r['spread_m']) * 1e3:.1f} mm{'' if ok else '  NOT WHOLE'}")
    if not ok: bad.append(r)
if len(rows) != 9:
    print(f"expected 9 cookies (3 ovens x 3 leaveners), read {len(rows)}")
    sys.exit(1)
if not bad: sys.exit(0)
if all(float(r["leavener"]) > 0 and float(r["oven_degC"]) < 190 for r in bad):
    print("EXPECTED FAILURE (#18, helpers cookiecool, depletion; the cold sheet): only leavened cookies in the cooler "
          "ovens miss; the 190 degC oven's are whole. Since the sheet goes in cold (a lumped sheet warming over 40 s) "
          "their bases stay soft longer and their foams swell more before they set: the 0.0075 cookie at 110 degC "
          "joined the 0.015 ones (5 mm: 5 of 157; 3.75 mm: 9 of 278), none of them by the stretched link. At 110 degC each "
          "CO2 share now stops at its amount (the NH4Cl share's 0.042 mol/kg, where eq. 14's bell alone made 0.056), but "
          "the foam it makes still swells to a median J ~3.3 (3.6 before): its particles stand dx/2 sqrt(J) ~0.9 dx apart, "
          "near the link (5 mm: 10 of 158 beyond it, 57 before; 3.75 mm: 141 of 280, 195 before; none by the stretched "
          "link; at 5 mm 8 of the 10 are one group on the top's shoulder, a swollen layer a little more than dx off the crumb, "
          "and 2 the rim's tip). At 3.75 mm a few of the rim's outer particles slide down the flank to the tray, a link off the body, at "
          "190 and 150 degC. With the dough drawing its heat from the sheet (helper traydraw) the 0.0075 cookies are whole "
          "again and the 0.015 ones miss more (5 mm: 31 of 158 at 150 degC, 32 at 110; 3.75 mm: 163 of 280 at 110 degC), "
          "but no particle leaves (helper cookiecool2): each count is a piece of the foam (median J 2.9-3.4, its "
          "particles dx/2 sqrt(J) ~0.9 dx apart) cut off by a seam of pairs just over dx apart (3.75 mm: 1.01-1.10 dx, "
          "through the cookie's middle; 5 mm: the crown at 150 degC, the right flank at 110), within the 1% bar at "
          "a link of 1.04-1.07 dx (3.75 mm: 1 of 280 beyond 1.05 dx, none beyond 1.1); the cooler sheet leaves the 110 degC "
          "core unset at the end (68 of 280 under 78 degC against 21, J 3.39 against 3.28), no gas pressure builds (under "
          "2.7 kPa), and which seam crosses is the seeding's (3.75 mm, 110 degC, seeds 1-5: 163/138/120/127/24 on the "
          "drawing sheet, 15/146/12/76/15 without). docs/validation.md 'The physical cookie in the cooler ovens (#18, helper cookiecool)', 'A leavener runs out (#18, "
          "helper depletion)', 'The sheet gives the food its heat (#18, helper traydraw)' and 'The cool oven's cookie on "
          "the drawing sheet: a seam at the link, not particles leaving (#18, helper cookiecool2)'")
    sys.exit(77)
sys.exit(1)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "a physical cookie sheds more than 1% of its particles in one of the ovens (numbers above)"
    ;;
# #18 (helper cookiespread): the physical sugar-snap cookie spreads as its fat melts and sets at its gluten's glass
# transition (h.library.dough.cookie, lua/hearth/dough_physical.lua). The unleavened cookie (leavener 0: its spread is
# the dough's own, no gas) in each of Fig. 17's 190, 150 and 110 degC ovens. The bar, set at 09:50 UTC on helper
# cookiespread's day before any run with its melted dough (COOKIE_SPREAD, not merged: branch cookiespread2-dough), and
# brought unchanged onto the drawing sheet by helper cookiespread2 (main's dough, an expected failure): (a) it ends at least 1.15x as wide as its raw dough (the same probe, raw.csv): the
# smaller of the two flours' growth to the set that Miller & Hoseney 1997 (Cereal Chem. 74:330, abstract) measured,
# 161 / 137.5 mm (hard) and 184 / 138.8 (soft), reading their linear spread back to the oven's start; (b) it ends at most
# 0.9x as tall as its raw dough (a spread, not a puff); (c) a cooler oven spreads it wider (it sets later): 110 degC at
# least 1.5 mm (two of the probe's samples) wider than 150, and 150 than 190. At the scene's dx 5 mm and one finer
# (_fine, 3.75 mm).
claim_cookie_physical_spreads | claim_cookie_physical_spreads_fine)
    dx=0.005
    [ "$case_name" = claim_cookie_physical_spreads_fine ] && dx=0.00375
    run cookies --set preset=physical --set dx=$dx --set frames=1 --set ovens=190,150,110 --set leaveners=0 >/dev/null
    python3 - hearth-out/cookies/raw.csv hearth-out/cookies/cookies.csv $dx <<'PY'
import csv, sys
raw = {float(r["oven_degC"]): r for r in csv.DictReader(open(sys.argv[1]))}
baked = {float(r["oven_degC"]): r for r in csv.DictReader(open(sys.argv[2]))}
ok = len(raw) == 3 and len(baked) == 3
print(f"dx {float(sys.argv[3]) * 1e3:.2f} mm, the unleavened physical cookie, 11 min (need width >= 1.15x raw, height "
      "<= 0.90x raw, and 110 >= 150 + 1.5 mm >= 190 + 3 mm wide)")
w = {}
for T in sorted(baked, reverse=True):
    w0, h0 = float(raw[T]["spread_m"]), float(raw[T]["height_m"])
    w[T], hb = float(baked[T]["spread_m"]), float(baked[T]["height_m"])
    good = w[T] >= 1.15 * w0 and hb <= 0.9 * h0 and baked[T]["alone"] == "1"
    print(f"  oven {T:g} degC: raw {w0 * 1e3:.1f} mm wide, {h0 * 1e3:.1f} mm tall; baked {w[T] * 1e3:.1f} mm wide "
          f"({w[T] / w0:.3f}x), {hb * 1e3:.1f} mm tall ({hb / h0:.3f}x), W/T {w[T] / hb:.2f}, alone {baked[T]['alone']}"
          f"{'' if good else '  MISSES'}")
    ok = ok and good
order = len(w) == 3 and w[110] - w[150] >= 0.0015 and w[150] - w[190] >= 0.0015
print(f"  cooler wider: 110 - 150 = {(w.get(110, 0) - w.get(150, 0)) * 1e3:.1f} mm, 150 - 190 = "
      f"{(w.get(150, 0) - w.get(190, 0)) * 1e3:.1f} mm{'' if order else '  MISSES'}")
if ok and order: sys.exit(0)
# the cause found (docs/validation.md "The physical cookie spreads as its fat melts (#18, helper cookiespread)" and
# "Does the physical cookie spread on the drawing sheet? (#18, helper cookiespread2)"): an
# expected failure while every cookie reads alone, no narrower than its raw dough and the coolest oven's no narrower
# than the hottest's; anything else fails
if len(w) == 3 and all(baked[T]["alone"] == "1" and w[T] >= float(raw[T]["spread_m"]) for T in w) and w[110] >= w[190]:
    print("EXPECTED FAILURE (#18, helpers cookiespread, cookiespread2): the unleavened cookie keeps its shape. "
          "h.library.dough.cookie's melted plateau (In et al.'s 61.5 Pa in shear, helper cookieyield) holds the 17.5 mm "
          "disc: a yield-stress puddle of 61.5 Pa stands 17.7 mm on a 30 mm half-width. With a melted dough bounded from "
          "the AACC disc's spread (16.6 Pa, 1.3e4 Pa s; branch cookiespread2-dough) on the drawing sheet it reaches 1.13-"
          "1.23x wide and stays 0.99-1.03x tall: the tray's friction (0.4) holds the base, which sets at 2.0 min at 190 "
          "degC (3.5 at 110) before the centre melts (2.5; 4.0), and over a held base the melted dough hardly flows (all "
          "at 50 degC, nothing set: 84-86 mm, 15.7 mm tall, stopped by 1 min; on a frictionless tray 154 mm, 8.8 mm): "
          "its rest shape reads a yield stress of 34 Pa in shear against 9.6, less at dx 2.5 mm (26) and without "
          "flow_stress (19; 13 at 2.5 mm), so the grid's held base layer and flow_stress hold it, not the sheet. "
          "docs/validation.md 'Does the physical cookie spread on the drawing sheet? (#18, helper cookiespread2)'")
    sys.exit(77)
sys.exit(1)
PY
    rc=$?
    [ $rc -eq 77 ] && exit 77
    [ $rc -eq 0 ] || fail "the physical unleavened cookie does not spread as a sugar-snap cookie does (numbers above)"
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
*) unmatched=1 ;;
esac

#!/usr/bin/env python3
"""bread_claims.py CLAIM CSV [DX [COL]]: bread.lua's claims (#18) read from its bread.csv.

One copy of each check, so that tests/baking_test.sh (the claims at the scene's dx and one
finer) and a run at any other dx (docs/validation.md, "bread.lua over dx") read the same
numbers the same way. Prints the measured numbers; exits 0 when the claim holds, 1 when
it fails, 77 for the unscored crack's expected failure (with its cause).
  slit_widens CSV        the scored loaf's slit opens while the loaf rises (Ding §7.4, Fig. 15)
  rises CSV DX COL [3]   a loaf (COL plain or one_slit) grows in area (volume: a 3D run's CSV, 3) and stands at least as tall
  dries CSV DX           the plain loaf's surface dries before its crumb
  cracks CSV DX          the plain loaf's top has a crack (Ding Fig. 16)"""
import csv, sys


def slit_widens(path):
    """From the loaf's lowest height (after the dough settles) to the end of the bake, the
    height grows and so does the slit's gap."""
    rows = list(csv.DictReader(open(path)))
    hs = [float(r["height_one_slit_m"]) for r in rows]
    gs = [float(r["gap_one_slit_m"]) for r in rows]
    i = min(range(len(hs)), key=lambda k: hs[k])
    print(f"lowest height {hs[i]:.5f} m at t = {rows[i]['t_s']} s with gap {gs[i]:.5f} m; end: height {hs[-1]:.5f} m, gap {gs[-1]:.5f} m")
    return 0 if i < len(hs) - 1 and hs[-1] > hs[i] and gs[-1] > gs[i] else 1


def size(row, col):
    """a loaf's size in a bread.csv row: area_<loaf>_m2 (2D) or volume_<loaf>_m3 (3D); #18, helper userfix7: one
    column area_<loaf> had held both without a unit"""
    return row["area_" + col + "_m2"] if "area_" + col + "_m2" in row else row["volume_" + col + "_m3"]


def rises(path, dx, col, dim=2):
    """Area (2D: V0 J summed; 3D: the volume, the same column) +15% from raw to peak, +10% at the
    end, height at least the raw dough's; a scored loaf's slit ends open (gap > one cell) and wider
    than it started."""
    rows = list(csv.DictReader(open(path)))
    a = [float(size(r, col)) for r in rows]
    h = [float(r["height_" + col + "_m"]) for r in rows]
    peak, end = max(a) / a[0] - 1, a[-1] / a[0] - 1
    what, unit = ("volume", "m^3") if dim == 3 else ("area", "m^2")
    print(f"{col} loaf, dx {dx * 1e3:.1f} mm: {what} {a[0]:.5g} -> peak {max(a):.5g} {unit} ({peak:+.1%}, need >= +15%), "
          f"end {a[-1]:.5g} ({end:+.1%}, need >= +10%); height {h[0] * 1e3:.1f} -> {h[-1] * 1e3:.1f} mm (need >= raw)")
    ok = peak >= 0.15 and end >= 0.10 and h[-1] >= h[0]
    if col == "one_slit":
        g = [float(r["gap_one_slit_m"]) for r in rows]
        print(f"slit gap {g[0] * 1e3:.2f} -> {g[-1] * 1e3:.2f} mm (need > {dx * 1e3:.1f} mm and wider than at the start)")
        ok = ok and g[-1] > dx and g[-1] > g[0]
    return 0 if ok else 1


def dries(path, dx):
    """At every frame after the start the top particle on the axis holds less of its water
    (X/X0) than the crumb's centre; at the end the top has lost more than 5 times the
    centre's share, is below X/X0 0.5 and the centre keeps at least 85 %."""
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        print(f"dx {dx * 1e3:g} mm, t = {r['t_s']} s: X/X0 top {float(r['moisture_top']):.4f}, centre {float(r['moisture_centre']):.4f}")
    top = [float(r["moisture_top"]) for r in rows]
    ctr = [float(r["moisture_centre"]) for r in rows]
    ok = len(rows) >= 4 and all(t < c for t, c in zip(top[1:], ctr[1:]))
    ok = ok and 1 - top[-1] > 5 * (1 - ctr[-1]) and top[-1] < 0.5 and ctr[-1] >= 0.85
    return 0 if ok else 1


def cracks(path, dx):
    """At the end of the bake a notch in the top of the intact material (bread.lua's
    crack_depth_m, crack_width_m) at least two cells wide and a tenth of the loaf's height
    deep; without one, the expected failure and its cause (77)."""
    r = list(csv.DictReader(open(path)))[-1]
    d, w, h = float(r["crack_depth_m"]), float(r["crack_width_m"]), float(r["height_plain_m"])
    print(f"dx {dx * 1e3:g} mm, t = {r['t_s']} s: deepest notch in the top of the intact crust {d * 1e3:.2f} mm deep "
          f"(need >= {0.1 * h * 1e3:.2f} mm), {w * 1e3:.1f} mm wide (need >= {2 * dx * 1e3:g} mm); "
          f"{r['cracked']} cracked particles, top X/X0 {float(r['moisture_top']):.3f}")
    if d >= 0.1 * h and w >= 2 * dx:
        return 0
    print("EXPECTED FAILURE: no crack starts in the crust at this dx; at 4 mm the crown reads 0.26 mm (4 mm wide, 9 "
          "cracked, top X/X0 0.213; 9.96 mm before the tray held only where the loaf touches it), because the crack "
          "was made by the tray's friction holding the loaf's base: the old contact held the nodes under the loaf's "
          "foot, whose lowest particles stand 1.0-2.6 mm above the tray from 1 s on (the touch reach h_p is 1.0 mm), with friction, so the base stopped spreading "
          "(93 mm wide at 2 s; now 97) and the rise went into the crown's stretch (top_arc_m 74.9 mm at 2 s; now 70.0); "
          "on a frictionless tray neither contact cracks the crown at 5 or 4 mm (0.33, 0.29 mm deep) nor 3 mm (1.45 mm; "
          "15.51 mm with friction), a touch "
          "reach 0.25 dx longer brings the 4 mm crack back (8.08 mm), 0.5 dx its old depth (9.96 mm), 1 dx the old run's numbers, and a stuck tray "
          "(sticky, or friction 1) cracks the 4 mm crown (32, 36 mm) but not 5 mm (0.24, 0.18 mm), whose skin is "
          "stretched as much (74.8 mm) but wetter (docs/validation.md, 'The unscored crack with the loaf on its tray "
          "(#18, helper crackback)', scripts/validation/crack_tray.lua). Before that: under the stretch rule (cam_clay_dough's "
          "fracture_stretch = 1) the rise stretches the top (top_arc_m +12% between 0.5 and 1.3 s) while its one cell "
          "of crust is still wet: the top particle stands for the top cell, whose water leaves through the next cell "
          "at a rate ~D/dx^2, so at 5 mm its X is 0.28-0.31 kg/kg during the rise (stretch to fracture 0.13-0.21) "
          "against 0.22-0.25 (0.05-0.08) at 4 mm; the top's damage peaks at 0.29 here and 0.80 at 4 mm, where the "
          "crown cracks and the set crumb (fracture_strain_set 0.15) carries it 8 mm down. Not the heat: Table 2's "
          "heat is isothermal (Biot 0.04), but a real Biot number (kappa x0.0234, Bi 1.7) keeps 5 mm uncracked and "
          "loses the 4 mm crack, and a real 200 degC oven sets the crust first but the set shell holds the gas (the "
          "loaf no longer rises) and its base cracks. Not particles per cell: ppc 9 and 16 at 5 mm crack 1 and 7 "
          "particles, no notch (docs/validation.md, 'The unscored crack at 5 mm: heat or resolution?', "
          "scripts/validation/crack_heat.lua). Not the crack band (it acts only past the fracture strain). Not fixed by "
          "reading the brittleness at the face's water (the evaporation's surface saturation): the calibrated "
          "evaporation dries every face at once and the whole skin cracked (580 particles by 0.5 s; 4 mm stopped by "
          "the guard), so it was taken out (docs/validation.md, 'The crack band, and the face's water'). Nor by reading "
          "the skin's water below its cell on the drying profile the evaporation assumes (s^2 linear from the face to the "
          "particle's sample, 0.57 dx deep) at a fixed crust depth of 1.75-2.5 mm: that dries the 5 mm top's reading by "
          "sqrt(z / d) = 0.78-0.94; brittle enough, the 5 mm skin cracks at its flanks and base (up to 9 particles, notch "
          "<= 1.35 mm) and the crown stays whole, and the 4 mm crown crack is lost (0.4-2.0 mm deep): as with a uniform "
          "dry shift, the crown is not where a brittle 5 mm skin cracks first; the 5 mm skin stretches as much as the 4 "
          "mm one but most at a shoulder (1.22 against the crown's 1.13 at 1.8 s; 4 mm: the crown 1.15, then it "
          "cracks) (docs/validation.md, 'The crust's water "
          "below the cell (#18, loaf5)'; taken out). Nor by the muffin's heat-set (cam_clay_dough's fracture_unset: the "
          "water's brittleness in proportion to the set, 35-70 degC for the bread): Table 2's bread heats evenly, so its "
          "crust sets with its crumb at the rise's end; 5 mm stays at 0.25 mm and the 4 mm crack is lost (0.38 mm), so "
          "the bread preset does not take it; with a real Biot number as well (crack_heat.lua conductivity 0.0234) 5 mm "
          "reads 0.29 mm and 4 mm 3.94 mm (lua/hearth/dough.lua, HEAT_SET). Nor by a set crumb brittle in proportion "
          "to its set (crack_heat.lua set_prop: 5 mm 0.25 mm, 0 cracked; 4 mm 9.92 mm; helper crownband, 'The crown's "
          "crack'). Nor by crack tracking with two velocity fields: the top's damage never reaches the peak 0.5 beside "
          "which the exclusion acts (at most 0.15 at crack_heat.lua's frames), and the fields split only at a cracked "
          "point (helper cracktrack, 'The crown's crack: tracked, with two fields'). Nor by a finer default: the crack "
          "converges at no dx from 5 to 2 mm (scripts/validation/bread_grid.sh): the crown cracks at 4 and 3 mm "
          "(8.05, 14.31 mm deep) and not at 4.5, 3.5 or 2.5 mm (0.26, 0.15, 2.29 mm), where nothing or a shoulder "
          "cracks, and at 2 mm, or 4 mm with 9 particles a cell, a shoulder does; at 4 mm with bread.lua's three "
          "loaves in one run (one time step) the crown does not crack (0.16 mm); the top particle's X/X0 falls "
          "with dx (0.231 at 5 mm, 0.100 at 2 mm: 0.045-0.054 per mm of dx) while the profile below it converges, so "
          "the skin the rise stretches is as brittle as its cell is thin, and where it breaks first is the grid's "
          "(cracked particles 0, 1, 14, 14, 34, 75, 131 from 5 to 2 mm; docs/validation.md, 'bread.lua over dx'). Nor "
          "by another time step: at 5 mm no step from cfl 1 down to a uniform 1.25e-5 s cracks the top (notch 0.25 -> "
          "0.17 mm), and the 4 mm crown crack holds for cfl 0.4-0.6 only (cfl 0.25, 0.75 or a uniform 1e-4 s and "
          "less: 0.13-0.69 mm, a flank cracks); the step changes the loaf's elastic ringing, which the MPM transfer damps "
          "by the step count, not the time (docs/validation.md, 'The crack over the time step', "
          "scripts/validation/crack_dt.sh)")
    return 77


if __name__ == "__main__":
    claim, args = sys.argv[1], sys.argv[2:]
    if claim == "slit_widens":
        sys.exit(slit_widens(args[0]))
    if claim == "rises":
        sys.exit(rises(args[0], float(args[1]), args[2], int(args[3]) if len(args) > 3 else 2))
    if claim == "dries":
        sys.exit(dries(args[0], float(args[1])))
    if claim == "cracks":
        sys.exit(cracks(args[0], float(args[1])))
    sys.exit(f"bread_claims.py: unknown claim '{claim}' (slit_widens, rises, dries, cracks)")

#!/usr/bin/env python3
"""The lava cake's claims (#18; Ding et al. 2019 Fig. 4) from scripts/scenes/baking/lava_cake.lua's outputs.

    lava_cake_check.py stands|flows OUT_DIR DX [CAUSE]

OUT_DIR holds lava_cake.csv (a row a frame) and lava_cake_times.csv (when the bake ends, the cut and the end, in
simulated seconds: the paper preset's 0.8, 1.2 and 1.8 s; the physical preset's from its recipe), so one measure
serves both presets. The bars (helper lavacake's, set before its runs; the physical preset's claims take them
unchanged, helper lavaphys):
  stands: from the end of the bake to the end of the run the uncut (left) side's edge along the plate
          (reach_left_m) moves less than two cells, and the height on the axis at the cut (the ring gone) keeps at
          least 75% of its height at the end of the bake;
  flows:  the material reaches further right along the plate at the end than at the cut, by more than two cells,
          with at least three frames from the cut on.
Prints the measured numbers. Exit 0 when the bar holds; when it does not, 77 with "EXPECTED FAILURE: CAUSE" if a
cause is given (an expected failure), else 1.
"""
import csv
import os
import sys


def read(out):
    rows = list(csv.DictReader(open(os.path.join(out, "lava_cake.csv"))))
    times = next(csv.DictReader(open(os.path.join(out, "lava_cake_times.csv"))))
    return rows, float(times["bake_end_s"]), float(times["cut_s"])


def stands(rows, bake, cut, dx):
    at = lambda t: min(rows, key=lambda r: abs(float(r["t_s"]) - t))
    b, c, e = at(bake), at(cut), rows[-1]
    moved = float(e["reach_left_m"]) - float(b["reach_left_m"])
    kept = float(c["height_m"]) / float(b["height_m"])
    print(f"dx {dx*1e3:g} mm: uncut edge {float(b['reach_left_m'])*1e3:.1f} mm left of the centre at {b['t_s']} s, "
          f"{float(e['reach_left_m'])*1e3:.1f} mm at {e['t_s']} s (moved {moved*1e3:.1f} mm; bar < {2*dx*1e3:.0f}); "
          f"height {float(b['height_m'])*1e3:.1f} mm -> {float(c['height_m'])*1e3:.1f} mm at {c['t_s']} s "
          f"({kept*100:.0f}%; bar >= 75%)")
    return moved < 2 * dx and kept >= 0.75


def flows(rows, bake, cut, dx):
    after = [r for r in rows if float(r["t_s"]) >= cut - 1e-9]
    if not after:
        print(f"dx {dx*1e3:g} mm: no frame from the cut (t = {cut} s) on")
        return False
    r0, r1 = float(after[0]["reach_right_m"]), float(rows[-1]["reach_right_m"])
    print(f"dx {dx*1e3:g} mm: reach right of the centre: {r0*1e3:.1f} mm at the cut (t = {after[0]['t_s']} s), "
          f"{r1*1e3:.1f} mm at t = {rows[-1]['t_s']} s")
    return len(after) >= 3 and r1 > r0 + 2 * dx


def main():
    mode, out, dx = sys.argv[1], sys.argv[2], float(sys.argv[3])
    cause = sys.argv[4] if len(sys.argv) > 4 else None
    rows, bake, cut = read(out)
    ok = {"stands": stands, "flows": flows}[mode](rows, bake, cut, dx)
    if ok:
        return 0
    if cause:
        print("EXPECTED FAILURE: " + cause)
        return 77
    return 1


if __name__ == "__main__":
    sys.exit(main())

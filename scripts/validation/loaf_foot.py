#!/usr/bin/env python3
"""loaf_foot.py DIR X0: the foot of one loaf of a 3D bread.lua (or bread3d.lua) run on its tray, from its VTU frames
(DIR: the run's vtu/ folder; X0 the loaf's axis, m: 0.07 for loaf 1). docs/validation.md, "The loaf's foot on its
tray (#18, helper loaffoot)". Per frame:
  footprint: the extent of the particles now within one raw particle spacing s0 of the tray (the raw base layer
    stands s0/2 above it): across (x) in the middle slab |z - 0.06| < 10 mm, and along (z) within 10 mm of the axis;
  loaf: its largest width (x) and length (z);
  edge moved: the raw base layer's outermost particles (within s0 of the raw footprint's edge), followed by id: the
    mean of how far they moved outward along x (the two sides, middle slab) and along z (the two ends, near the
    axis), and their mean height above the tray now (a foot that curls up lifts them);
  top: the highest particle above the tray within s0 of the loaf's axis in the middle slab.
s0 is the cube root of the first frame's median particle volume (V0 J with J = 1). Python's standard library only."""
import glob
import os
import statistics
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bread3d_vtu import read_vtu  # noqa: E402

TRAY, ZC, BAND = 0.02, 0.06, 0.01


def mean(v):
    return sum(v) / len(v) if v else float("nan")


def main():
    d, x0 = sys.argv[1], float(sys.argv[2])
    raw = None
    for f in sorted(glob.glob(d + "/*_[0-9][0-9][0-9][0-9].vtu")):
        a = read_vtu(f)
        p, vol, ids = a["Points"], a["volume"], a["id"]
        X, Y, Z = p[0::3], p[1::3], p[2::3]
        k1 = [k for k in range(len(vol)) if abs(X[k] - x0) < 0.07]
        at = {ids[k]: k for k in k1}
        if raw is None:
            s0 = statistics.median(vol[k] for k in k1) ** (1 / 3)
            base = [k for k in k1 if Y[k] < TRAY + s0]
            bx = [k for k in base if abs(Z[k] - ZC) < BAND]
            bz = [k for k in base if abs(X[k] - x0) < BAND]
            xlo, xhi = min(X[k] for k in bx), max(X[k] for k in bx)
            zlo, zhi = min(Z[k] for k in bz), max(Z[k] for k in bz)
            raw = (s0, [(ids[k], -1, 0) for k in bx if X[k] < xlo + s0 / 2] +
                   [(ids[k], 1, 0) for k in bx if X[k] > xhi - s0 / 2] +
                   [(ids[k], -1, 2) for k in bz if Z[k] < zlo + s0 / 2] +
                   [(ids[k], 1, 2) for k in bz if Z[k] > zhi - s0 / 2],
                   {ids[k]: (X[k], Y[k], Z[k]) for k in base})
        s0, edge, x_raw = raw
        foot = [k for k in k1 if Y[k] < TRAY + s0]
        fx = [X[k] for k in foot if abs(Z[k] - ZC) < BAND]
        fz = [Z[k] for k in foot if abs(X[k] - x0) < BAND]
        moved, lift = {0: [], 2: []}, {0: [], 2: []}
        for i, sign, axis in edge:
            if i in at:
                k = at[i]
                now = (X[k], Y[k], Z[k])
                moved[axis].append(sign * (now[axis] - x_raw[i][axis]))
                lift[axis].append(now[1] - TRAY)
        top = max(Y[k] for k in k1 if abs(X[k] - x0) < s0 and abs(Z[k] - ZC) < BAND) - TRAY
        print(f"t {a['TimeValue'][0]:.3f} s: footprint x {(max(fx) - min(fx)) * 1e3:.1f} mm, z {(max(fz) - min(fz)) * 1e3:.1f} mm"
              f" ({len(foot)} particles); loaf x {(max(X[k] for k in k1) - min(X[k] for k in k1)) * 1e3:.1f} mm, z "
              f"{(max(Z[k] for k in k1) - min(Z[k] for k in k1)) * 1e3:.1f} mm; edge moved out x {mean(moved[0]) * 1e3:+.1f} mm"
              f" (up {mean(lift[0]) * 1e3:.1f}), z {mean(moved[2]) * 1e3:+.1f} mm (up {mean(lift[2]) * 1e3:.1f}); "
              f"top {top * 1e3:.1f} mm (s0 {s0 * 1e3:.1f} mm)")


if __name__ == "__main__":
    main()

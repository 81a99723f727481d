#!/usr/bin/env python3
"""sph_roll_vent.py DX NDOUGH DIR: where the vented SPH bread roll's cells vent, left and right of its axis, frame by
frame (#18, helper ventrock; docs/validation.md "The vented roll rocks"), from the trace_NNNN.csv files that
scripts/scenes/sph/bread_roll.lua --set trace=true --set vent=true writes (NDOUGH: the first bubble id, which the
run prints; the trace then carries gas_left, the share of each bubble's own gas still in its cell).

The axis is the frame's mean particle x. A bubble is on the tray side when it lies within 2 DX of the tray (y =
0.01 m), else on the crust (or inside). Per frame, for each half (L, R):
  open     bubbles on the outer surface now (the flood fill's flag: their gauge is 0), tray side + crust
  vented   bubbles that have lost gas (gas_left < 1), of the half's bubbles
  reclosed of those, the ones closed again (not outer) and their mean pressure (kPa; under 0 pulls)
  gas      the half's bubbles' summed gas_left over their count (1: no gas gone)
  end      the height of the half's lowest particle within 2 DX of the roll's outer end (mm above the tray)
  base     the largest column gap (tests/sph_roll_base.py's columns, DX apart over the middle 60% of the width) in
           that half of the base (mm)
Prints one line a frame."""
import csv, math, os, sys

TRAY = 0.01


def load(path):
    with open(path) as f:
        return [{k: float(v) for k, v in r.items()} for r in csv.DictReader(f)]


def frame(dx, nd, rows):
    ax = sum(r["x_m"] for r in rows) / len(rows)
    x0, x1 = min(r["x_m"] for r in rows), max(r["x_m"] for r in rows)
    a, b = x0 + 0.2 * (x1 - x0), x1 - 0.2 * (x1 - x0)
    out = {}
    for side in ("L", "R"):
        mine = [r for r in rows if (r["x_m"] < ax) == (side == "L")]
        bub = [r for r in mine if r["id"] >= nd]
        tray = [r for r in bub if r["outer"] > 0 and r["y_m"] - TRAY < 2 * dx]
        crust = [r for r in bub if r["outer"] > 0 and r["y_m"] - TRAY >= 2 * dx]
        g = [r["gas_left"] if r["gas_left"] == r["gas_left"] else 1.0 for r in bub]
        vented = [r for r, v in zip(bub, g) if v < 1]
        reclosed = [r for r in vented if r["outer"] <= 0]
        pre = sum(r["p_Pa"] for r in reclosed) / len(reclosed) / 1e3 if reclosed else float("nan")
        xe = x0 if side == "L" else x1
        end = min(r["y_m"] for r in mine if abs(r["x_m"] - xe) < 2 * dx) - TRAY
        gaps = []
        k = 0
        while a + k * dx <= b:
            xc = a + k * dx
            k += 1
            if (xc < ax) != (side == "L"):
                continue
            near = [r["y_m"] - TRAY for r in rows if abs(r["x_m"] - xc) < dx]
            gaps.append(min(near) if near else max(r["y_m"] for r in rows) - TRAY)
        out[side] = (len(tray), len(crust), len(vented), len(bub), len(reclosed), pre, sum(g) / len(g), end * 1e3,
                     max(gaps) * 1e3 if gaps else float("nan"))
    return ax, out


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__)
    dx, nd, d = float(argv[1]), int(argv[2]), argv[3]
    k = 1
    while os.path.exists(os.path.join(d, "trace_%04d.csv" % k)):
        rows = load(os.path.join(d, "trace_%04d.csv" % k))
        if "gas_left" not in rows[0]:
            sys.exit(f"{d}: trace_{k:04d}.csv has no gas_left column (run the scene with --set vent=true)")
        ax, o = frame(dx, nd, rows)
        line = f"t {(k - 1) * 0.1:.1f} s axis {ax * 1e3:.2f} mm"
        for s in ("L", "R"):
            t, c, v, n, rc, pre, gas, end, base = o[s]
            line += (f" | {s} open {t}+{c} vented {v}/{n} reclosed {rc} p {pre:.2f} kPa gas {gas:.4f}"
                     f" end {end:.2f} base {base:.2f}")
        print(line)
        k += 1


if __name__ == "__main__":
    main(sys.argv)

#!/usr/bin/env python3
"""sph_melt_measure.py DX DIR: the SPH melting block (scripts/scenes/sph/melting_block.lua) measured from
its particle positions alone (DIR/particles_NNNN.csv, x_m, y_m columns (m), NNNN = 0 at t = 0 and one
frame each 0.1 s), not through the solver's density field.

The block stood on the tray (y = 0.01 m) over x in [0.11, 0.19] m, 60 mm tall.
  pieces, share   particles closer than 2 DX are linked (union-find, as tests/sph_roll_measure.py): at
                  rest the nearest neighbours are DX apart, so a particle with none within 2 DX has left
                  the material. share: the largest piece's part of all particles. At the last frame.
  high, highest   particles more than 2 DX above the tray and more than 2 DX beyond the block's
                  footprint (the block's own sides may bulge that far as it slumps; a pool beyond is at
                  most two particles deep), at the last frame; highest: the highest of them above the tray
  tops            the centre column's top (the highest particle within DX of x = 0.15) above the tray at
                  each frame; rise: the largest increase from one frame to the next
  dip             at the last frame, the highest column of the largest piece over the footprint (columns
                  DX wide) minus the centre column's top: 0 for a block or a mound, large for a split one
  left, right     how far the largest piece reaches beyond the footprint on each side at the last frame
Prints 'particles N pieces P share S high K highest H rise R dip D left L right R' (lengths in mm) and a
line with the tops."""
import csv, glob, os, sys

FLOOR, X0, X1, XC = 0.01, 0.11, 0.19, 0.15


def load(path):
    with open(path) as f:
        return [(float(r["x_m"]), float(r["y_m"])) for r in csv.DictReader(f)]


def pieces(pts, link):
    par = list(range(len(pts)))

    def find(a):
        while par[a] != a:
            par[a] = par[par[a]]
            a = par[a]
        return a
    cell = {}
    for i, (x, y) in enumerate(pts):
        cell.setdefault((int(x // link), int(y // link)), []).append(i)
    for i, (x, y) in enumerate(pts):
        cx, cy = int(x // link), int(y // link)
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                for j in cell.get((cx + a, cy + b), ()):
                    if j > i and (pts[j][0] - x) ** 2 + (pts[j][1] - y) ** 2 < link * link:
                        par[find(i)] = find(j)
    groups = {}
    for i in range(len(pts)):
        groups.setdefault(find(i), []).append(i)
    return sorted(groups.values(), key=len, reverse=True)


def centre_top(pts, dx):
    ys = [y for x, y in pts if abs(x - XC) < dx]
    return max(ys) - FLOOR if ys else 0.0


def measure(dx, files):
    tops = [centre_top(load(p), dx) for p in files]
    pts = load(files[-1])
    ps = pieces(pts, 2 * dx)
    big = [pts[i] for i in ps[0]]
    high = [y - FLOOR for x, y in pts if (x < X0 - 2 * dx or x > X1 + 2 * dx) and y - FLOOR > 2 * dx]
    cols = {}
    for x, y in big:
        if X0 <= x < X1:
            k = int((x - X0) // dx)
            cols[k] = max(cols.get(k, 0.0), y - FLOOR)
    return {"particles": len(pts), "pieces": len(ps), "share": len(ps[0]) / len(pts), "high": len(high),
            "highest": max(high or [0.0]), "rise": max([b - a for a, b in zip(tops, tops[1:])] or [0.0]),
            "dip": max(cols.values()) - tops[-1] if cols else 0.0,
            "left": X0 - min(x for x, _ in big), "right": max(x for x, _ in big) - X1, "tops": tops}


if __name__ == "__main__":
    dx = float(sys.argv[1])
    files = sorted(glob.glob(os.path.join(sys.argv[2], "particles_*.csv")))
    if not files:
        sys.exit("sph_melt_measure.py: no particles_NNNN.csv in %s" % sys.argv[2])
    m = measure(dx, files)
    print("particles %d pieces %d share %.4f high %d highest %.1f rise %.1f dip %.1f left %.1f right %.1f" % (
        m["particles"], m["pieces"], m["share"], m["high"], 1e3 * m["highest"], 1e3 * m["rise"], 1e3 * m["dip"],
        1e3 * m["left"], 1e3 * m["right"]))
    print("centre top (mm) each 0.1 s: " + " ".join("%.1f" % (1e3 * t) for t in m["tops"]))

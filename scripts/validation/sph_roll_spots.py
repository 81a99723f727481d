#!/usr/bin/env python3
"""sph_roll_spots.py DX NDOUGH DIR: the SPH bread roll's bubble spots by its tray, frame by frame (#18, helper
rolltear; docs/validation.md "The 1.5 mm roll's tear traced"), from the trace_NNNN.csv files that
scripts/scenes/sph/bread_roll.lua --set trace=true writes (NDOUGH: the first bubble id, which the run prints).

The spots are told from the raw roll (trace_0001.csv, t = 0): bubble particles within 1.6 DX of each other are one
spot (the scene's spots lie 9 mm apart, their particles one raw spacing). A base spot is one whose lowest particle
is within 2 DX of the tray (y = 0.01 m) at 0.5 s (trace_0006.csv), when the raw roll has settled. Per frame and base
spot: its mean x (mm), the gap under its lowest particle (mm), its particles on the outer surface (the oven's heat
enters there: open to the outside) of its count, the dough particles under it (between its x-span and the tray: its
floor), its mean pressure (kPa) and temperature (degC). Then the widest run of columns (DX apart over the
middle 60% of the roll's width, as tests/sph_roll_base.py) whose lowest particle is over 2 DX above the tray, its x
span and its height (mm): a base that arches off the tray and a spot open onto it alike (tell them by the spot's
outer count and floor, or a picture). Prints one line a frame."""
import csv, math, os, sys

TRAY = 0.01
# the trace's columns say their units (tests/scene_csv.py's rule); read here by the quantity's short name
NAMES = {"x_m": "x", "y_m": "y", "vx_m_s": "vx", "vy_m_s": "vy", "T_degC": "T", "p_Pa": "p", "rho_kg_m3": "rho",
         "syy_Pa": "syy"}


def load(d, k):
    with open(os.path.join(d, "trace_%04d.csv" % k)) as f:
        return {int(float(r["id"])): {NAMES.get(c, c): float(v) for c, v in r.items()} for r in csv.DictReader(f)}


def spots_of(raw, nd, dx):
    bub = [i for i in raw if i >= nd]
    par = {i: i for i in bub}

    def root(i):
        while par[i] != i:
            par[i] = par[par[i]]
            i = par[i]
        return i

    for a, i in enumerate(bub):
        for j in bub[a + 1:]:
            if math.hypot(raw[i]["x"] - raw[j]["x"], raw[i]["y"] - raw[j]["y"]) < 1.6 * dx:
                par[root(i)] = root(j)
    out = {}
    for i in bub:
        out.setdefault(root(i), []).append(i)
    return list(out.values())


def off_tray(fr, dx):
    xs = [p["x"] for p in fr.values()]
    x0, x1 = min(xs), max(xs)
    a, b = x0 + 0.2 * (x1 - x0), x1 - 0.2 * (x1 - x0)
    best, run = (0, 0.0, 0.0, 0.0), []
    for k in range(int((b - a) / dx) + 2):
        xc = a + k * dx
        near = [p["y"] - TRAY for p in fr.values() if abs(p["x"] - xc) < dx]
        g = min(near) if near else max(p["y"] for p in fr.values()) - TRAY
        if g > 2 * dx:
            run.append((xc, g))
            if len(run) > best[0]:
                best = (len(run), run[0][0], run[-1][0], max(v for _, v in run))
        else:
            run = []
    return best


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__)
    dx, nd, d = float(argv[1]), int(argv[2]), argv[3]
    raw, settled = load(d, 1), load(d, 6)
    base = [s for s in spots_of(raw, nd, dx) if min(settled[i]["y"] for i in s) - TRAY < 2 * dx]
    base.sort(key=lambda s: sum(raw[i]["x"] for i in s))
    k = 1
    while os.path.exists(os.path.join(d, "trace_%04d.csv" % k)):
        fr = load(d, k)
        cols = []
        for s in base:
            P = [fr[i] for i in s]
            lo, hi = min(p["x"] for p in P), max(p["x"] for p in P)
            low = min(p["y"] for p in P)
            floor = sum(1 for i, p in fr.items() if i < nd and lo <= p["x"] <= hi and p["y"] < low)
            cols.append("x %.1f gap %.2f outer %d/%d floor %d p %.1f T %.1f" % (
                1e3 * sum(p["x"] for p in P) / len(P), 1e3 * (low - TRAY), sum(p["outer"] > 0 for p in P), len(P),
                floor, 1e-3 * sum(p["p"] for p in P) / len(P), sum(p["T"] for p in P) / len(P)))
        n, a, b, g = off_tray(fr, dx)
        sl = "off the tray none"
        if n:
            sl = "off the tray %d columns x %.1f-%.1f up to %.2f" % (n, 1e3 * a, 1e3 * b, 1e3 * g)
        print("t %.1f | %s | %s" % (round(max(k - 1, 0) * 0.1, 1), " | ".join(cols), sl))
        k += 1


if __name__ == "__main__":
    main(sys.argv)

#!/usr/bin/env python3
"""sph_roll_measure_check.py CASE: tests/sph_roll_measure.py (the SPH bread
roll's rise and tear measure, #18) on particle sets whose answer is known
without it: a disc of dough on a square lattice of spacing DX, radius 25 DX.
  expanded  the same lattice spread uniformly by k = 1.3 (area k^2 = 1.69, no
            gap between discs of radius DX since 1.3 < sqrt 2): whole (torn 0),
            the rise between the band-corrected bounds below and never above k^2
  slit      three columns of particles taken out from the top to the centre,
            an open slit 2 DX wide: torn, its area within 15% of 2 x 25 DX^2
  cell      a 2x2 block of particles taken out at the centre: a closed void
            of under 4 DX^2 (one bubble at the cap), a gas cell: not torn, and
            the rise kept
  cavity    a 5x5 block taken out: a closed void of some 17 DX^2, larger than
            any one bubble, torn, its area within 10% of the void's own
            (counted on a fine grid straight from its definition)
Exit 0 pass, 1 fail (prints the numbers)."""
import math, os, subprocess, sys, tempfile

DX, RAD = 0.002, 25


def lattice(k=1.0, drop=lambda i, j: False):
    pts = []
    for j in range(-RAD, RAD + 1):
        for i in range(-RAD, RAD + 1):
            if i * i + j * j <= RAD * RAD and not drop(i, j):
                pts.append((0.08 + k * i * DX, 0.05 + k * j * DX))
    return pts


def run(p0, p1, measure="sph_roll_measure.py"):
    """The measure script's 'key value ...' output on the two particle sets (sph_dead_measure_check.py reads
    sph_dead_measure.py through it)."""
    with tempfile.TemporaryDirectory() as d:
        paths = []
        for name, pts in (("a.csv", p0), ("b.csv", p1)):
            path = os.path.join(d, name)
            with open(path, "w") as f:
                f.write("x_m,y_m\n" + "".join("%.9g,%.9g\n" % p for p in pts))
            paths.append(path)
        here = os.path.dirname(os.path.abspath(__file__))
        out = subprocess.run([sys.executable, os.path.join(here, measure), str(DX)] + paths,
                             capture_output=True, text=True, check=True).stdout.split()
    return {out[i]: float(out[i + 1]) for i in range(0, len(out), 2)}


def hole_area(side, lo, out):
    """The void left by a block taken out, in DX^2, straight from its definition:
    the points farther than DX from every particle left, counted on a grid of
    DX/50 around the block (not through the measure's raster or closing)."""
    n, g, count = 50, 1.0 / 50, 0
    left = [(i, j) for j in range(lo - 2, lo + side + 2) for i in range(lo - 2, lo + side + 2) if not out(i, j)]
    for b in range(int((side + 1) * n)):
        y = lo - 1 + (b + 0.5) * g
        for a in range(int((side + 1) * n)):
            x = lo - 1 + (a + 0.5) * g
            if all((x - i) ** 2 + (y - j) ** 2 > 1 for i, j in left):
                count += 1
    return count * g * g


def check(ok, what, m):
    print(("ok  " if ok else "FAIL ") + what + ": " + " ".join("%s %g" % kv for kv in m.items()))
    return ok


def main():
    case = sys.argv[1]
    raw = lattice()
    if case == "expanded":
        k = 1.3
        m = run(raw, lattice(k))
        # the band of about DX/2 beyond the outer row counts in both: the ratio lies
        # between ((k R + DX/2) / (R + DX/2))^2 - 2% and k^2 (R = RAD DX)
        lo = ((k * RAD + 0.5) / (RAD + 0.5)) ** 2 * 0.98
        good = m["torn"] == 0 and m["pieces"] == 1 and lo <= m["ratio"] <= k * k
        return check(good, "expanded k 1.3: torn 0, one piece, rise in [%.4f, %.4f]" % (lo, k * k), m)
    if case == "slit":
        w = 1  # |i| <= 1: three columns of particles, from the centre up
        p1 = lattice(drop=lambda i, j: abs(i) <= w and j >= 0)
        m = run(raw, p1)
        # columns |i| <= w out: the discs of the columns left at |i| = w + 1 reach to
        # |x| = w DX, so the slit is 2 w DX wide and RAD DX deep: 2 w RAD DX^2
        slit = 2 * w * RAD
        env = math.pi * (RAD + 0.5) ** 2  # the raw disc's envelope, DX^2
        good = m["torn"] > 0.02 and abs(m["void"] - slit) <= 0.15 * slit and abs(m["torn"] - slit / env) <= 0.15 * slit / env
        return check(good, "slit 2 DX wide to the centre: torn > 0.02, the void within 15%% of %d DX^2 and %.4f of the envelope" %
                     (slit, slit / env), m)
    if case in ("cell", "cavity"):
        side = 2 if case == "cell" else 5  # a side x side block of particles taken out at the centre
        lo = -((side - 1) // 2)
        out = lambda i, j: lo <= i < lo + side and lo <= j < lo + side
        m = run(raw, lattice(drop=out))
        hole = hole_area(side, lo, out)
        if case == "cell":  # under one capped bubble's 4 DX^2: a gas cell, kept in the rise
            good = hole <= 4 and m["torn"] == 0 and m["ratio"] >= 0.995
            return check(good, "2x2 block out: a closed void of %.2f DX^2 (<= 4), torn 0, rise >= 0.995" % hole, m)
        good = hole > 4 and m["torn"] > 0 and abs(m["void"] - hole) <= 0.1 * hole
        return check(good, "5x5 block out: a closed void of %.2f DX^2 (> 4), torn, its area within 10%%" % hole, m)
    sys.exit("unknown case " + case)


if __name__ == "__main__":
    sys.exit(0 if main() else 1)

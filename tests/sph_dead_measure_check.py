#!/usr/bin/env python3
"""sph_dead_measure_check.py CASE: tests/sph_dead_measure.py (the SPH bread of
the dead's pieces and inner gaps, #18) on particle sets whose answer is known
without it: a disc of dough on a square lattice of spacing DX, radius 25 DX.
  whole    the lattice spread by 1.3 (under sqrt 2: discs of radius DX still
           close every gap): one piece, no closed void past the claim's bar
           of DX^2 (a raster cell, DX^2 / 16, may read as a hole)
  slit     two columns of particles taken out inside the disc, 10 rows long,
           a gap 3 DX between the particles left: one piece still, a closed
           void of 8-15 DX^2 (1 DX wide between the discs' edges and 9.3 long
           at its middle, the lens-shaped ends of the rows above and below
           cut off; plus up to a raster cell, DX/4, on each long side: 5)
  part     a knuckle of 3 x 3 particles moved 2.5 DX off the disc's side:
           two pieces, the largest holding all but 9 particles
Exit 0 pass, 1 fail (prints the numbers)."""
import os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import sph_roll_measure_check as roll_check  # noqa: E402  (its run(), at the same DX)

DX, RAD = roll_check.DX, 25


def lattice(k=1.0, drop=lambda i, j: False):
    return [(0.08 + k * i * DX, 0.05 + k * j * DX) for j in range(-RAD, RAD + 1) for i in range(-RAD, RAD + 1)
            if i * i + j * j <= RAD * RAD and not drop(i, j)]


def run(p0, p1):
    return roll_check.run(p0, p1, "sph_dead_measure.py")


def main():
    case, raw = sys.argv[1], lattice()
    if case == "whole":
        m = run(raw, lattice(1.3))
        ok = m["pieces"] == 1 and m["closed_void"] <= 1
        what = "spread 1.3: one piece, no closed void past DX^2"
    elif case == "slit":
        m = run(raw, lattice(drop=lambda i, j: i in (0, 1) and -5 <= j < 5))
        ok = m["pieces"] == 1 and 8 <= m["closed_void"] <= 15
        what = "slit 3 DX wide, 10 rows: one piece, a closed void of 8-15 DX^2"
    elif case == "part":
        body = lattice()
        knuckle = [(0.08 + (RAD + 2.5 + a) * DX, 0.05 + b * DX) for a in range(3) for b in range(-1, 2)]
        m = run(body + knuckle, body + knuckle)
        ok = m["pieces"] == 2 and abs(m["largest_share"] - len(body) / (len(body) + 9)) < 1e-4
        what = "knuckle 2.5 DX off: two pieces, the largest %d of %d" % (len(body), len(body) + 9)
    else:
        sys.exit("unknown case " + case)
    print(("ok  " if ok else "FAIL ") + what + ": " + " ".join("%s %g" % kv for kv in m.items()))
    return 0 if ok else 1


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""sph_dead_measure.py DX START.csv END.csv: is the SPH bread of the dead
(scripts/scenes/sph/bread_of_the_dead.lua) one piece, with no gap inside it,
measured from its particles alone (x,y columns, metres)?

Pieces: particles closer than 2 DX are linked (union-find), as the roll's
measure links them (tests/sph_roll_measure.py): the raw loaf's nearest
neighbours stand DX apart, and its bubbles (eq. 3.51, V proportional to the
absolute temperature: 1.31x at 120 degC) move them under 1.2 DX apart.

Inner gaps: the dough is the union of discs of radius DX about the particles
(rasterised at DX/4), the envelope its closing by a disc of R0/4 (R0 the raw
loaf's equivalent radius), both as tests/sph_roll_measure.py makes them. A
closed void is a connected part of the envelope outside the dough that no
cell of the envelope's outside borders: a hole inside the loaf. Discs of
radius DX leave a hole only where particles stand more than 2 DX apart
around it, so a closed void is a gap wider than two raw spacings (a slit, a
tear under a topping). One larger than DX^2 (a raw particle's area; a
bubble here holds its gas's V_b(T) DX^2, 1.36 at the loaf's mean 134 degC
at 1.2 s, spread over its neighbours' spacing) is counted. Open voids (notches between the toppings and the body,
6.4 DX^2 on the raw loaf at 2 mm, 15.4 at 1.5 mm) are printed, not judged.
Prints 'pieces P largest_share S closed_void V open_void W' (V, W the
largest, in DX^2)."""
import math, os, sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from sph_roll_measure import Raster, discs, load, pieces, void_parts  # noqa: E402


def voids(pts, dx, rc):
    """The largest closed and the largest open void (m^2)."""
    ras, _, _, parts = void_parts(pts, dx, rc)
    closed_max = open_max = 0.0
    for comp, closed in parts:
        a = len(comp) * ras.g * ras.g
        if closed:
            closed_max = max(closed_max, a)
        else:
            open_max = max(open_max, a)
    return closed_max, open_max


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    dx = float(sys.argv[1])
    p0, p1 = load(sys.argv[2]), load(sys.argv[3])
    if not p0 or not p1:
        sys.exit("sph_dead_measure: %s has %d particles, %s %d" % (sys.argv[2], len(p0), sys.argv[3], len(p1)))
    ras = Raster(p0, dx / 4, 2 * dx)
    rc = math.sqrt(sum(discs(p0, dx, ras)) * (dx / 4) ** 2 / math.pi) / 4  # the raw loaf's equivalent radius / 4
    closed, opened = voids(p1, dx, rc)
    n, share = pieces(p1, 2 * dx)
    print("pieces %d largest_share %.4f closed_void %.2f open_void %.2f" % (n, share, closed / dx ** 2, opened / dx ** 2))


if __name__ == "__main__":
    main()

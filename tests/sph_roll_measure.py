#!/usr/bin/env python3
"""sph_roll_measure.py DX START.csv END.csv: the SPH bread roll measured from its
particles alone (x,y columns, metres), not through the solver's density field.

Area: the union of discs of radius DX (the raw dough's particle spacing) around
the particles, rasterised at DX/8. A disc of radius DX covers the gaps of a
lattice whose spacing grows up to sqrt(2) DX (a local area gain of 2x), and
on a body it adds a band about DX/2 wide beyond the particles' outer row in
both the raw and the risen roll: so the ratio END/START understates a rise
(the band is a larger share of the smaller roll), never overstates it.

Pieces: particles closer than 2 DX are linked (union-find). At rest the
nearest neighbours are DX apart, and a bubble particle that grows by V_b
moves its neighbours out by about sqrt(V_b) DX, under 2 DX for V_b < 4; a
torn roll leaves a gap with no particle within two raw spacings.
Prints 'ratio R pieces P largest_share S'."""
import csv, math, sys


def load(path):
    with open(path) as f:
        return [(float(r["x"]), float(r["y"])) for r in csv.DictReader(f)]


def area(pts, R):
    g = R / 8
    cells = set()
    k = int(math.ceil(R / g))
    for x, y in pts:
        ix, iy = int(math.floor(x / g)), int(math.floor(y / g))
        for a in range(-k, k + 1):
            for b in range(-k, k + 1):
                cx, cy = (ix + a + 0.5) * g, (iy + b + 0.5) * g
                if (cx - x) ** 2 + (cy - y) ** 2 <= R * R:
                    cells.add((ix + a, iy + b))
    return len(cells) * g * g


def pieces(pts, L):
    parent = list(range(len(pts)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    grid = {}
    for i, (x, y) in enumerate(pts):
        grid.setdefault((int(x // L), int(y // L)), []).append(i)
    for (cx, cy), members in grid.items():
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                for j in grid.get((cx + a, cy + b), ()):
                    for i in members:
                        if i < j and (pts[i][0] - pts[j][0]) ** 2 + (pts[i][1] - pts[j][1]) ** 2 < L * L:
                            ri, rj = find(i), find(j)
                            if ri != rj:
                                parent[ri] = rj
    sizes = {}
    for i in range(len(pts)):
        r = find(i)
        sizes[r] = sizes.get(r, 0) + 1
    return len(sizes), max(sizes.values()) / len(pts)


def main():
    dx = float(sys.argv[1])
    p0, p1 = load(sys.argv[2]), load(sys.argv[3])
    if not p0 or len(p0) != len(p1):
        sys.exit("sph_roll_measure: %s has %d particles, %s %d" % (sys.argv[2], len(p0), sys.argv[3], len(p1)))
    n, share = pieces(p1, 2 * dx)
    print("ratio %.4f pieces %d largest_share %.4f" % (area(p1, dx) / area(p0, dx), n, share))


if __name__ == "__main__":
    main()

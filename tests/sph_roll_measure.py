#!/usr/bin/env python3
"""sph_roll_measure.py DX START.csv END.csv [--png OUT.png]: the SPH bread roll measured from its
particles alone (x,y columns, metres), not through the solver's density field.

Dough: the union of discs of radius DX (the raw dough's particle spacing)
around the particles, rasterised at DX/4. A disc of radius DX covers the gaps
of a lattice whose spacing grows up to sqrt(2) DX (a local area gain of 2x),
and on a body it adds a band about DX/2 wide beyond the particles' outer row
in both the raw and the risen roll, so a ratio of two such areas understates
a rise, never overstates it.

Voids (#18: the old ratio counted the discs and passed a roll whose frames
showed a ring of torn crust around a fissured crumb). The roll's envelope is
the morphological closing of the dough by a disc of radius R0 / 4, R0 the raw
roll's equivalent radius (the closing fills every opening narrower than R0 / 2,
12.5 mm for the scene's 25 mm roll, whatever dx; a smooth convex roll gains
nothing from it). A void is a connected part of the envelope outside the
dough. A void entirely surrounded by dough and no larger than one bubble
particle at the gas law's cap (4 DX^2, sph.bubble_vmax = 4: the most gas one
particle holds) is a closed gas cell and counts as dough. An open void no
larger than one raw particle (DX^2) is the notch between two neighbouring
surface discs (two discs of radius DX 2 DX apart leave (2 - pi/2) DX^2 =
0.43 DX^2 under their common tangent) and counts as neither. Every other
void, open to the outside or larger than any one bubble, is torn: a fissure,
a gap between a crust and its crumb, a crust flap lifted off.

  rise   = (dough + closed gas cells) / the same on START
  torn   = torn voids / envelope (0 for a whole roll)
  void   = the largest torn void, in raw particle areas DX^2

Pieces: particles closer than 2 DX are linked (union-find). At rest the
nearest neighbours are DX apart, and a bubble particle that grows by V_b
moves its neighbours out by about sqrt(V_b) DX, under 2 DX for V_b < 4; a
torn roll leaves a gap with no particle within two raw spacings.
Prints 'ratio R pieces P largest_share S torn F void V'; --png draws what was
counted (dough brown, gas cells blue, torn red, notches grey, particles black)."""
import collections, csv, math, sys

BIG = 1e18


def load(path):
    with open(path) as f:
        return [(float(r["x_m"]), float(r["y_m"])) for r in csv.DictReader(f)]


class Raster:
    """A boolean image over the particles' bounding box with a margin wide
    enough that the closing never reaches its border."""

    def __init__(self, pts, g, margin):
        self.g = g
        self.x0 = min(p[0] for p in pts) - margin
        self.y0 = min(p[1] for p in pts) - margin
        self.nx = int(math.ceil((max(p[0] for p in pts) + margin - self.x0) / g)) + 1
        self.ny = int(math.ceil((max(p[1] for p in pts) + margin - self.y0) / g)) + 1


def discs(pts, R, ras):
    """Cells whose centre lies within R of a particle."""
    g, nx = ras.g, ras.nx
    on = bytearray(nx * ras.ny)
    k = int(math.ceil(R / g)) + 1
    for x, y in pts:
        ix, iy = int((x - ras.x0) / g), int((y - ras.y0) / g)
        for b in range(-k, k + 1):
            cy = (iy + b + 0.5) * g + ras.y0 - y
            for a in range(-k, k + 1):
                cx = (ix + a + 0.5) * g + ras.x0 - x
                if cx * cx + cy * cy <= R * R:
                    on[(iy + b) * nx + ix + a] = 1
    return on


def edt1d(f, n):
    """Squared distance transform of one row (Felzenszwalb & Huttenlocher 2012)."""
    d, v, z = [0.0] * n, [0] * n, [0.0] * (n + 1)
    k, z[0], z[1] = 0, -BIG, BIG
    for q in range(1, n):
        while True:
            p = v[k]
            s = ((f[q] + q * q) - (f[p] + p * p)) / (2 * q - 2 * p)
            if s > z[k]:
                break
            k -= 1
        k += 1
        v[k], z[k], z[k + 1] = q, s, BIG
    k = 0
    for q in range(n):
        while z[k + 1] < q:
            k += 1
        d[q] = (q - v[k]) ** 2 + f[v[k]]
    return d


def sqdist(on, nx, ny):
    """Each cell's squared distance (in cells) to the nearest set cell."""
    cols = [[0.0 if on[j * nx + i] else BIG for j in range(ny)] for i in range(nx)]
    cols = [edt1d(c, ny) for c in cols]
    out = [0.0] * (nx * ny)
    for j in range(ny):
        row = edt1d([cols[i][j] for i in range(nx)], nx)
        out[j * nx:(j + 1) * nx] = row
    return out


def closing(on, nx, ny, r):
    """Dilate by a disc of r cells, then erode by it."""
    d = sqdist(on, nx, ny)
    dil = bytearray(1 if v <= r * r else 0 for v in d)
    d = sqdist(bytearray(1 - v for v in dil), nx, ny)
    return bytearray(1 if v > r * r else 0 for v in d)


def components(mask, nx, ny):
    """4-connected components of the set cells: lists of cell indices."""
    seen, comps = bytearray(nx * ny), []
    for start in range(nx * ny):
        if not mask[start] or seen[start]:
            continue
        seen[start], stack, comp = 1, [start], []
        while stack:
            c = stack.pop()
            comp.append(c)
            i, j = c % nx, c // nx
            for nb, ok in ((c - 1, i > 0), (c + 1, i < nx - 1), (c - nx, j > 0), (c + nx, j < ny - 1)):
                if ok and mask[nb] and not seen[nb]:
                    seen[nb] = 1
                    stack.append(nb)
        comps.append(comp)
    return comps


def void_parts(pts, dx, rc):
    """The body's raster (Raster at dx/4), its dough (discs of radius dx), its envelope (the dough's closing by
    rc), and each connected part of the envelope outside the dough with whether it is closed (no cell of it borders
    a cell outside the envelope): a hole inside, not a notch in the outline. sph_dead_measure.py reads the same."""
    g = dx / 4
    ras = Raster(pts, g, dx + rc + 4 * g)
    nx, ny = ras.nx, ras.ny
    dough = discs(pts, dx, ras)
    env = closing(dough, nx, ny, rc / g)
    void = bytearray(1 if env[c] and not dough[c] else 0 for c in range(nx * ny))
    parts = [(comp, all(env[c - 1] and env[c + 1] and env[c - nx] and env[c + nx] for c in comp))
             for comp in components(void, nx, ny)]
    return ras, dough, env, parts


def measure(pts, dx, rc, picture=None):
    """(dough + closed gas cells, envelope, torn area, largest torn void) in m^2.
    With picture (a path), also a PNG of what it counted: dough brown, gas cells
    blue, torn voids red, surface notches grey, particles black."""
    ras, dough, env, parts = void_parts(pts, dx, rc)
    cell, cap = ras.g * ras.g, 4 * dx * dx
    gas = torn = biggest = 0.0
    kind = bytearray(dough)  # 0 outside, 1 dough, 2 gas cell, 3 notch, 4 torn
    for comp, closed in parts:
        a = len(comp) * cell
        if closed and a <= cap:
            gas, k = gas + a, 2
        elif a <= dx * dx:
            k = 3  # a notch between two surface particles (under (2 - pi/2) DX^2 at 2 DX apart)
        else:
            torn, k = torn + a, 4
            biggest = max(biggest, a)
        for c in comp:
            kind[c] = k
    if picture:
        write_png(picture, ras, kind, pts)
    return sum(dough) * cell + gas, sum(env) * cell, torn, biggest


def write_png(path, ras, kind, pts, scale=3):
    """The classified raster as an RGB PNG (zlib only), written atomically."""
    import os, struct, zlib
    rgb = [(240, 240, 240), (200, 150, 90), (70, 70, 255), (170, 170, 170), (230, 0, 0)]
    nx, ny, g = ras.nx, ras.ny, ras.g
    px = [rgb[k] for k in kind]
    for x, y in pts:
        px[int((y - ras.y0) / g) * nx + int((x - ras.x0) / g)] = (0, 0, 0)
    rows = []
    for j in range(ny - 1, -1, -1):
        row = b"\x00" + b"".join(bytes(px[j * nx + i]) * scale for i in range(nx))
        rows.append(row * scale)

    def chunk(t, d):
        return struct.pack(">I", len(d)) + t + d + struct.pack(">I", zlib.crc32(t + d) & 0xFFFFFFFF)

    data = (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", nx * scale, ny * scale, 8, 2, 0, 0, 0)) +
            chunk(b"IDAT", zlib.compress(b"".join(rows))) + chunk(b"IEND", b""))
    with open(path + ".tmp", "wb") as f:
        f.write(data)
    os.replace(path + ".tmp", path)


def piece_labels(pts, L, reach=None):
    """Each particle's piece (the root of its union-find set): particles closer than L are linked.
    reach (optional, one per particle, m): how much further particle i's own rest extent reaches than a raw
    particle's, so i and j link closer than L + reach[i] + reach[j] (tests/sph_cake_rise.py: a bubble particle
    whose gas has grown; a raw particle's reach is 0, and without reach every pair links at L as before)."""
    parent = list(range(len(pts)))

    def find(i):
        while parent[i] != i:
            parent[i] = parent[parent[i]]
            i = parent[i]
        return i

    far = L + 2 * max(reach, default=0.0) if reach else L  # the longest link: the grid's cell
    grid = {}
    for i, (x, y) in enumerate(pts):
        grid.setdefault((int(x // far), int(y // far)), []).append(i)
    for (cx, cy), members in grid.items():
        for a in (-1, 0, 1):
            for b in (-1, 0, 1):
                for j in grid.get((cx + a, cy + b), ()):
                    for i in members:
                        Lij = L + reach[i] + reach[j] if reach else L
                        if i < j and (pts[i][0] - pts[j][0]) ** 2 + (pts[i][1] - pts[j][1]) ** 2 < Lij * Lij:
                            ri, rj = find(i), find(j)
                            if ri != rj:
                                parent[ri] = rj
    return [find(i) for i in range(len(pts))]


def piece_sizes(labels):
    """piece_labels' pieces: ({piece: particle count}, the largest piece; the first met of equal ones)."""
    sizes = collections.Counter(labels)
    return sizes, max(sizes, key=sizes.get)


def pieces(pts, L):
    sizes, big = piece_sizes(piece_labels(pts, L))
    return len(sizes), sizes[big] / len(pts)


def main():
    args = sys.argv[1:]
    picture = None
    if len(args) == 5 and args[3] == "--png":
        picture = args.pop()
        args.pop()
    if len(args) != 3:
        sys.exit(__doc__)
    dx = float(args[0])
    p0, p1 = load(args[1]), load(args[2])
    if not p0 or not p1:
        sys.exit("sph_roll_measure: %s has %d particles, %s %d" % (args[1], len(p0), args[2], len(p1)))
    ras = Raster(p0, dx / 4, 2 * dx)
    rc = math.sqrt(sum(discs(p0, dx, ras)) * (dx / 4) ** 2 / math.pi) / 4  # the raw roll's equivalent radius / 4
    a0 = measure(p0, dx, rc)[0]
    a1, env1, torn, biggest = measure(p1, dx, rc, picture)
    n, share = pieces(p1, 2 * dx)
    print("ratio %.4f pieces %d largest_share %.4f torn %.4f void %.1f" % (a1 / a0, n, share, torn / env1, biggest / (dx * dx)))


if __name__ == "__main__":
    main()

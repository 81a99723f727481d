#!/usr/bin/env python3
"""sph_roll_base.py DX TRAY_Y FRAME.csv: how the SPH bread roll sits on its tray, from its
particles alone (x,y columns, metres; tests/sph_roll_test.sh, #18).

The roll's base is the middle 60% of its width (the particles' x-extent in this frame): a
roll that sits on its tray touches it over at least that much (the settled 2 mm roll
touches over 61-65 mm of its 80-86 mm at 1.0-1.5 s, docs/validation.md "The roll's skin,
renormalised"), while its rounded ends rise off it whatever the physics. The base is
sampled every DX; the gap at x is the height above the tray of the lowest particle within
DX of x (a window two raw spacings wide always holds a particle column of the lattice,
which spreads to at most 2 DX as the bubbles grow to the gas law's cap; a particle resting
on the slip collider sits on its plane: gap 0).
  gap      the largest column gap over the base (m)
  mean     the mean column gap over the base (m)
  contact  particles within 0.75 DX of the tray, and the x-span they cover (m)
Prints 'gap G mean M contact N span S'."""
import csv, math, sys


def measure(dx, tray, pts):
    x0, x1 = min(p[0] for p in pts), max(p[0] for p in pts)
    a, b = x0 + 0.2 * (x1 - x0), x1 - 0.2 * (x1 - x0)
    ncol = max(1, int(math.floor((b - a) / dx)) + 1)
    gaps = []
    for k in range(ncol):
        xc = a + k * dx
        near = [y - tray for x, y in pts if abs(x - xc) < dx]
        # no particle within DX of x: a hole through the roll down to the tray; the gap is
        # then the whole height of the roll above x, which is no contact at all
        gaps.append(min(near) if near else max(y for _, y in pts) - tray)
    touch = [x for x, y in pts if y - tray < 0.75 * dx]
    span = max(touch) - min(touch) if touch else 0.0
    return max(gaps), sum(gaps) / len(gaps), len(touch), span


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__)
    dx, tray = float(argv[1]), float(argv[2])
    with open(argv[3]) as f:
        pts = [(float(r["x_m"]), float(r["y_m"])) for r in csv.DictReader(f)]
    if not pts:
        sys.exit(f"{argv[3]}: no particles")
    g, m, n, s = measure(dx, tray, pts)
    print(f"gap {g:.6g} mean {m:.6g} contact {n} span {s:.6g}")


if __name__ == "__main__":
    main(sys.argv)

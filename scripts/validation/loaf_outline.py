#!/usr/bin/env python3
"""loaf_outline.py OUT.png X0 RAW.vtu END_A.vtu [END_B.vtu]: one 3D loaf's outline, seen from its side (along x: its
length z across the picture) and from its end (along z: its width x across), raw against baked, for
docs/gallery/rise.md ("The loaf's foot on its tray", helper loaffoot). X0: the loaf's axis (m; 0.07 for loaf 1).
Each particle is drawn as a square of its own size ((V0 J)^(1/3)) at its place, projected, so a view is the
loaf's silhouette. Colours: the raw loaf filled light grey, END_A's outline blue, END_B's outline red (two pixels
wide), the tray a dark line; 0.25 mm a pixel, 10 mm ticks on the tray. Python's standard library only."""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from bread3d_vtu import read_vtu  # noqa: E402
from png_rgb import write_png  # noqa: E402

TRAY, PX = 0.02, 0.00025
VIEWS = (("z", -0.04, 0.16), ("x", None, None))  # the side view's z range; the end view's x range is X0 +- 0.065
TOP = 0.085  # m above the tray shown


def silhouette(path, x0, axis, lo, hi):
    a = read_vtu(path)
    p, vol = a["Points"], a["volume"]
    w, hgt = int(round((hi - lo) / PX)), int(round(TOP / PX))
    on = [[False] * w for _ in range(hgt)]
    col = 2 if axis == "z" else 0
    for k in range(len(vol)):
        if abs(p[3 * k] - x0) > 0.07:
            continue
        r = vol[k] ** (1 / 3) / 2
        u, y = p[3 * k + col], p[3 * k + 1] - TRAY
        for j in range(max(0, int((y - r) / PX)), min(hgt, int((y + r) / PX) + 1)):
            row = on[hgt - 1 - j]
            for i in range(max(0, int((u - r - lo) / PX)), min(w, int((u + r - lo) / PX) + 1)):
                row[i] = True
    return on


def outline(on):
    hgt, w = len(on), len(on[0])
    out = [[False] * w for _ in range(hgt)]
    for j in range(hgt):
        for i in range(w):
            if on[j][i] and any(not (0 <= j + dj < hgt and 0 <= i + di < w and on[j + dj][i + di])
                                for dj in (-2, -1, 0, 1, 2) for di in (-2, -1, 0, 1, 2)):
                out[j][i] = True
    return out


def main():
    out, x0, raw, ends = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4:]
    panels = []
    for axis, lo, hi in VIEWS:
        if lo is None:
            lo, hi = x0 - 0.065, x0 + 0.065
        base = silhouette(raw, x0, axis, lo, hi)
        lines = [outline(silhouette(e, x0, axis, lo, hi)) for e in ends]
        hgt, w = len(base), len(base[0])
        rows = []
        for j in range(hgt):
            row = bytearray()
            for i in range(w):
                c = (226, 226, 226) if base[j][i] else (255, 255, 255)
                for line, colour in zip(lines, ((40, 80, 220), (220, 40, 40))):
                    if line[j][i]:
                        c = colour
                row += bytes(c)
            rows.append(row)
        tray = bytearray()  # the tray, ticked every 10 mm
        for i in range(w):
            u = lo + i * PX
            tray += bytes((60, 60, 60))
        rows += [tray] * 6
        ticks = bytearray()
        for i in range(w):
            u = lo + (i + 0.5) * PX
            ticks += bytes((60, 60, 60)) if abs(u * 100 - round(u * 100)) < PX * 100 else bytes((255, 255, 255))
        rows += [ticks] * 12
        panels.append(rows)
    gap = 40
    hgt = max(len(r) for r in panels)
    rows = []
    for j in range(hgt):
        row = bytearray()
        for n, pr in enumerate(panels):
            w = len(pr[0]) // 3
            row += pr[j - (hgt - len(pr))] if j >= hgt - len(pr) else bytes((255, 255, 255)) * w
            if n + 1 < len(panels):
                row += bytes((255, 255, 255)) * gap
        rows.append(row)
    write_png(out, rows)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""bread_grid.py: the two readings of bread.lua's runs that bread.csv does not carry, for
scripts/validation/bread_grid.sh (docs/validation.md, "bread.lua over dx (#18, helper
breadgrid)").

  where DX VTU...    per frame (hearth's raw-appended VTU), where the plain loaf's crack is:
                     the deepest notch in the top of its intact material, found as bread.lua's
                     crack() finds it (its depth printed beside the CSV's, so a reader sees the
                     two agree) and its x from the loaf's axis; and the cracked particles
                     (damage 1) of the loaf's upper half counted per 10 mm of x from the axis,
                     so a crown crack (within the crown's middle 20 mm either side) reads apart
                     from a shoulder's
  strip OUT PNG...   the plain loaf's part of each damage.png (x < 0.145 m: the loaf stands at
                     x = 70 mm of the 420 mm box), four to a row in the order given, into one PNG"""
import math
import re
import struct
import sys

from png_rgb import read_png, write_png

TRAY, WIDTH, X0 = 0.02, 0.08, 0.07  # bread.lua: tray top, loaf width, the plain loaf's axis (m)


def read_vtu(path):
    """{name: values} of a VTU with raw appended data (hearth's writer: a UInt64 byte count
    before each array); a vector array is a list of tuples"""
    b = open(path, "rb").read()
    start = b.index(b"<AppendedData")
    base = b.index(b"_", start) + 1
    out = {}
    for m in re.finditer(rb'<DataArray type="(\w+)" Name="([^"]+)" NumberOfComponents="(\d+)"[^>]*offset="(\d+)"',
                         b[:start]):
        kind, name, nc, off = m.group(1).decode(), m.group(2).decode(), int(m.group(3)), int(m.group(4))
        nbytes = struct.unpack_from("<Q", b, base + off)[0]
        fmt = {"Float64": "d", "Float32": "f", "Int32": "i", "Int64": "q", "UInt8": "B"}[kind]
        vals = struct.unpack_from("<%d%s" % (nbytes // struct.calcsize(fmt), fmt), b, base + off + 8)
        out[name] = [vals[i:i + nc] for i in range(0, len(vals), nc)] if nc > 1 else list(vals)
    return out


def where(dx, path):
    v = read_vtu(path)
    pts, dmg = v["Points"], v["damage [1]"]
    # bread.lua's crack(): one-cell columns over the loaf's middle 80 %, each column's top its highest
    # intact particle; a column's depth is how far it lies below the lower of the highest tops within
    # 15 mm (whole cells) to its left and right
    lo, n, w = X0 - 0.4 * WIDTH, int(math.floor(0.8 * WIDTH / dx + 0.5)), int(math.floor(0.015 / dx + 0.5))
    top = [0.0] * (n + 1)
    for (x, y, _), d in zip(pts, dmg):
        c = int(math.floor((x - lo) / dx)) + 1
        if 1 <= c <= n and d < 1:
            top[c] = max(top[c], y - TRAY)
    depth = [0.0] * (n + 1)
    for k in range(1, n + 1):
        depth[k] = min(max(top[max(1, k - w):k + 1]), max(top[k:min(n, k + w) + 1])) - top[k]
    kmax = 1
    for k in range(2, n + 1):
        if depth[k] > depth[kmax]:
            kmax = k
    xc = lo + (kmax - 0.5) * dx - X0
    mine = [(x - X0, y - TRAY, d) for (x, y, _), d in zip(pts, dmg) if abs(x - X0) < 0.07]
    height = max(y for _, y, _ in mine)
    bins, low = {}, 0
    for x, y, d in mine:
        if d < 1:
            continue
        if y > 0.5 * height:
            b = int(math.floor(x / 0.01))
            bins[b] = bins.get(b, 0) + 1
        else:
            low += 1
    crown = sum(c for b, c in bins.items() if -2 <= b < 2)
    spread = " ".join(f"{10 * b:+d}..{10 * b + 10:+d}:{c}" for b, c in sorted(bins.items()))
    print(f"{path.rsplit('/', 1)[-1]}: notch {depth[kmax] * 1e3:.2f} mm deep at x {xc * 1e3:+.1f} mm from the axis; "
          f"cracked, upper half: crown (|x| < 20 mm) {crown}, by x (mm) {spread or '-'}; lower half {low}")


def strip(out, paths):
    crops = []
    for p in paths:
        w, h, rows = read_png(p)
        x1 = int(w * 0.36)  # the plain loaf and the axis labels: x < 0.145 m of the 0.42 m box
        crops.append([r[:3 * x1] for r in rows])
    h, cw = min(len(c) for c in crops), min(len(c[0]) for c in crops)
    per_row = min(4, len(crops))
    crops += [[b"\xff" * cw] * h] * (-len(crops) % per_row)  # the last row padded white
    rows = []
    for i in range(0, len(crops), per_row):
        rows += [b"".join(c[y][:cw] for c in crops[i:i + per_row]) for y in range(h)]
    w, h = write_png(out, rows)
    print(f"wrote {out} ({w} x {h}: {len(paths)} frames)")


if __name__ == "__main__":
    if len(sys.argv) < 4 or sys.argv[1] not in ("where", "strip"):
        sys.exit(__doc__)
    if sys.argv[1] == "where":
        for f in sys.argv[3:]:
            where(float(sys.argv[2]), f)
    else:
        strip(sys.argv[2], sys.argv[3:])

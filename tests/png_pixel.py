#!/usr/bin/env python3
"""png_pixel.py FILE X Y [MAP]: print the colour of a hearth PNG's pixel (X, Y) (from its top left corner, rounded
to the pixel that holds that point) as "rgb R,G,B"; with MAP ("R,G,B R,G,B ...": a colour map at n evenly spaced
values of 0..1, as h.colormap gives it), also "reads T": the map's value whose colour lies nearest (sum of squares),
what a reader matching the picture against its colour bar reads there. Shared by the test scripts."""
import os
import struct
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png_read  # noqa: E402


def pixels(path):
    chunks = png_read.chunks(path)
    w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", chunks[0][1])
    if depth != 8 or ctype not in (2, 6) or interlace:
        sys.exit(f"{path}: unexpected format depth {depth} colour type {ctype} interlace {interlace}")
    bpp = 3 if ctype == 2 else 4
    raw = zlib.decompress(b"".join(d for k, d in chunks if k == b"IDAT"))
    return w, h, bpp, list(png_read.rows(path, raw, w, h, bpp))


w, h, bpp, rows = pixels(sys.argv[1])
x, y = int(float(sys.argv[2])), int(float(sys.argv[3]))
if not (0 <= x < w and 0 <= y < h):
    sys.exit(f"{sys.argv[1]}: pixel ({x}, {y}) outside its {w} x {h}")
rgb = tuple(rows[y][bpp * x:bpp * x + 3])
print("rgb %d,%d,%d" % rgb)
if len(sys.argv) > 4:
    cmap = [tuple(int(v) for v in c.split(",")) for c in sys.argv[4].split()]
    k = min(range(len(cmap)), key=lambda k: sum((cmap[k][j] - rgb[j]) ** 2 for j in range(3)))
    print("reads %.4f" % (k / (len(cmap) - 1)))

#!/usr/bin/env python3
"""png_pixel.py FILE X Y [MAP]: print the colour of a hearth PNG's pixel (X, Y) (from its top left corner, rounded
to the pixel that holds that point) as "rgb R,G,B"; with MAP ("R,G,B R,G,B ...": a colour map at n evenly spaced
values of 0..1, as h.colormap gives it), also "reads T": the map's value whose colour lies nearest (sum of squares),
what a reader matching the picture against its colour bar reads there. Shared by the test scripts."""
import struct
import sys
import zlib


def pixels(path):
    b = open(path, "rb").read()
    if b[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG signature")
    pos, ihdr, idat = 8, None, []
    while pos + 8 <= len(b):
        n, kind = struct.unpack(">I4s", b[pos:pos + 8])
        data = b[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            ihdr = struct.unpack(">IIBBBBB", data)
        elif kind == b"IDAT":
            idat.append(data)
        pos += 12 + n
    w, h, depth, ctype, _, _, interlace = ihdr
    if depth != 8 or ctype not in (2, 6) or interlace:
        sys.exit(f"{path}: unexpected format depth {depth} colour type {ctype} interlace {interlace}")
    bpp = 3 if ctype == 2 else 4
    raw, stride, rows, prev = zlib.decompress(b"".join(idat)), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            c = prev[i - bpp] if i >= bpp else 0
            up = prev[i]
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + up) & 255
            elif f == 3: line[i] = (line[i] + (a + up) // 2) & 255
            elif f == 4:
                p = a + up - c
                pa, pb, pc = abs(p - a), abs(p - up), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else up if pb <= pc else c)) & 255
            elif f != 0: sys.exit(f"{path}: bad filter type {f} in row {y}")
        rows.append(line)
        prev = line
    return w, h, bpp, rows


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

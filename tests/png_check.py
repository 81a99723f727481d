#!/usr/bin/env python3
"""png_check.py FILE [W H] [--count R,G,B]...: a whole PNG (signature, chunk
CRCs, IHDR first and IEND last), its image data inflates to the right size and
(its first 60k pixels) unfilters, and the picture is not one flat colour.
Prints "W H COLOURS"; with W and H the size must match. Each --count unfilters
the whole picture and prints "R,G,B N": how many pixels have exactly that
colour (a plot's series colours, say). Shared by the test scripts."""
import os, struct, sys, zlib
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png_read  # noqa: E402
counts = []
while "--count" in sys.argv:
    i = sys.argv.index("--count")
    counts.append(tuple(int(v) for v in sys.argv[i + 1].split(",")))
    del sys.argv[i:i + 2]
path = sys.argv[1]
chunks = png_read.chunks(path)
if not chunks or chunks[0][0] != b"IHDR" or chunks[-1][0] != b"IEND":
    sys.exit(f"{path}: no IHDR first / IEND last")
w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", chunks[0][1])
if depth != 8 or ctype not in (0, 2, 6) or interlace:
    sys.exit(f"{path}: unexpected format depth {depth} colour type {ctype} interlace {interlace}")
bpp = {0: 1, 2: 3, 6: 4}[ctype]
raw = zlib.decompress(b"".join(d for k, d in chunks if k == b"IDAT"))
stride = w * bpp
if len(raw) != h * (stride + 1):
    sys.exit(f"{path}: image data is {len(raw)} bytes, expected {h * (stride + 1)}")
colours, found = set(), {c: 0 for c in counts}
# pure Python: unfilter about 60k pixels unless counting
for line in png_read.rows(path, raw, w, h if counts else min(h, max(1, 60000 // w)), bpp):
    for x in range(0, stride, bpp):
        colours.add(bytes(line[x:x + bpp]))
        if counts and tuple(line[x:x + 3]) in found:
            found[tuple(line[x:x + 3])] += 1
if len(colours) < 3:
    sys.exit(f"{path}: only {len(colours)} colour(s): a blank picture")
if len(sys.argv) > 3 and (w, h) != (int(sys.argv[2]), int(sys.argv[3])):
    sys.exit(f"{path}: {w} x {h}, expected {sys.argv[2]} x {sys.argv[3]}")
print(w, h, len(colours))
for c in counts:
    print("%d,%d,%d %d" % (c + (found[c],)))

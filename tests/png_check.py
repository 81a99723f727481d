#!/usr/bin/env python3
"""png_check.py FILE [W H] [--count R,G,B]...: a whole PNG (signature, chunk
CRCs, IHDR first and IEND last), its image data inflates to the right size and
(its first 60k pixels) unfilters, and the picture is not one flat colour.
Prints "W H COLOURS"; with W and H the size must match. Each --count unfilters
the whole picture and prints "R,G,B N": how many pixels have exactly that
colour (a plot's series colours, say). Shared by the test scripts."""
import struct, sys, zlib
counts = []
while "--count" in sys.argv:
    i = sys.argv.index("--count")
    counts.append(tuple(int(v) for v in sys.argv[i + 1].split(",")))
    del sys.argv[i:i + 2]
path = sys.argv[1]
b = open(path, "rb").read()
if b[:8] != b"\x89PNG\r\n\x1a\n":
    sys.exit(f"{path}: not a PNG signature")
pos, chunks = 8, []
while pos < len(b):
    if pos + 8 > len(b):
        sys.exit(f"{path}: truncated chunk header at {pos}")
    n, kind = struct.unpack(">I4s", b[pos:pos + 8])
    data = b[pos + 8:pos + 8 + n]
    if len(data) != n or pos + 12 + n > len(b):
        sys.exit(f"{path}: truncated {kind!r} chunk")
    crc, = struct.unpack(">I", b[pos + 8 + n:pos + 12 + n])
    if zlib.crc32(kind + data) != crc:
        sys.exit(f"{path}: bad CRC in {kind!r}")
    chunks.append((kind, data))
    pos += 12 + n
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
prev, colours, found = bytearray(stride), set(), {c: 0 for c in counts}
for y in range(h if counts else min(h, max(1, 60000 // w))):  # pure Python: unfilter about 60k pixels unless counting
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
    for x in range(0, stride, bpp):
        colours.add(bytes(line[x:x + bpp]))
        if counts and tuple(line[x:x + 3]) in found:
            found[tuple(line[x:x + 3])] += 1
    prev = line
if len(colours) < 3:
    sys.exit(f"{path}: only {len(colours)} colour(s): a blank picture")
if len(sys.argv) > 3 and (w, h) != (int(sys.argv[2]), int(sys.argv[3])):
    sys.exit(f"{path}: {w} x {h}, expected {sys.argv[2]} x {sys.argv[3]}")
print(w, h, len(colours))
for c in counts:
    print("%d,%d,%d %d" % (c + (found[c],)))

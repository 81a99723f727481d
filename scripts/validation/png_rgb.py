"""png_rgb.py: read and write the 8-bit RGB PNGs hearth's frames are, for the validation scripts that put
frames side by side (bread_grid.py, fig17_grid.sh). Rows are bytes of R, G, B per pixel; an alpha channel, if
any, is dropped on reading."""
import struct
import sys
import zlib


def read_png(path):
    """(width, height, rows of RGB bytes) of an 8-bit RGB or RGBA, non-interlaced PNG"""
    b = open(path, "rb").read()
    pos, idat, hdr = 8, b"", None
    while pos + 8 <= len(b):
        n, kind = struct.unpack(">I4s", b[pos:pos + 8])
        data = b[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            hdr = struct.unpack(">IIBBBBB", data)
        if kind == b"IDAT":
            idat += data
        pos += 12 + n
    if hdr is None:
        sys.exit(f"{path}: not a PNG (no IHDR)")
    w, h, depth, ctype, interlace = hdr[0], hdr[1], hdr[2], hdr[3], hdr[6]
    if depth != 8 or ctype not in (2, 6) or interlace:
        sys.exit(f"{path}: only 8-bit RGB(A) non-interlaced PNGs (depth {depth}, colour type {ctype}, "
                 f"interlace {interlace})")
    bpp = 3 if ctype == 2 else 4
    raw, stride, rows, prev = zlib.decompress(idat), w * bpp, [], bytearray(w * bpp)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):  # PNG's five row filters
            a = line[i - bpp] if i >= bpp else 0
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1:
                line[i] = (line[i] + a) & 255
            elif f == 2:
                line[i] = (line[i] + prev[i]) & 255
            elif f == 3:
                line[i] = (line[i] + (a + prev[i]) // 2) & 255
            elif f == 4:
                p = a + prev[i] - c
                pa, pb, pc = abs(p - a), abs(p - prev[i]), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else prev[i] if pb <= pc else c)) & 255
        rows.append(bytes(line) if bpp == 3 else bytes(line[k] for k in range(stride) if k % 4 < 3))
        prev = line
    return w, h, rows


def write_png(path, rows):
    """rows (equal-length bytes of RGB) as an 8-bit RGB PNG at path"""
    w, h = len(rows[0]) // 3, len(rows)

    def chunk(kind, data):
        return struct.pack(">I", len(data)) + kind + data + struct.pack(">I", zlib.crc32(kind + data) & 0xffffffff)
    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(b"".join(b"\x00" + r for r in rows), 9)) + chunk(b"IEND", b"")
    open(path, "wb").write(png)
    return w, h

"""png_read: the PNG reading the test scripts share (png_check.py, png_pixel.py, png_title.py): chunks(path), each
(kind, data) with the signature, truncation and every chunk's CRC checked, and rows(raw, w, h, bpp), each row of the
inflated image data unfiltered (filters 0-4), as a generator so a caller can stop early."""
import struct
import sys
import zlib


def chunks(path):
    b = open(path, "rb").read()
    if b[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG signature")
    pos, out = 8, []
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
        out.append((kind, data))
        pos += 12 + n
    return out


def rows(path, raw, w, h, bpp):
    stride, prev = w * bpp, bytearray(w * bpp)
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
        yield line
        prev = line

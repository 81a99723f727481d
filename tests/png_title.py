#!/usr/bin/env python3
"""png_title.py FILE...: print each PNG's "Title" text (hearth writes a picture's title as an uncompressed iTXt
chunk, core/sim/io/io_png.c), one line a file: "FILE: TITLE", or "FILE: (no title)". Shared by the test scripts."""
import struct
import sys
import zlib


def title(path):
    b = open(path, "rb").read()
    if b[:8] != b"\x89PNG\r\n\x1a\n":
        sys.exit(f"{path}: not a PNG signature")
    pos = 8
    while pos + 8 <= len(b):
        n, kind = struct.unpack(">I4s", b[pos:pos + 8])
        data = b[pos + 8:pos + 8 + n]
        if zlib.crc32(kind + data) != struct.unpack(">I", b[pos + 8 + n:pos + 12 + n])[0]:
            sys.exit(f"{path}: bad CRC in {kind!r}")
        if kind == b"iTXt":
            key, rest = data.split(b"\0", 1)
            flag, _method = rest[0], rest[1]
            _lang, rest = rest[2:].split(b"\0", 1)
            _lkey, text = rest.split(b"\0", 1)
            if key == b"Title":
                return zlib.decompress(text).decode() if flag else text.decode()
        if kind == b"tEXt":
            key, text = data.split(b"\0", 1)
            if key == b"Title":
                return text.decode("latin-1")
        pos += 12 + n
    return None


for p in sys.argv[1:]:
    t = title(p)
    print(f"{p}: {t if t is not None else '(no title)'}")

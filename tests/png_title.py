#!/usr/bin/env python3
"""png_title.py [--key KEY] FILE...: print each PNG's "Title" text (hearth writes a picture's title as an
uncompressed iTXt chunk, core/sim/io/io_png.c), one line a file: "FILE: TITLE", or "FILE: (no title)"; with --key,
that text instead (hearth run's "Source": the command line that drew it), "(no KEY)" when absent. Shared by the
test scripts."""
import os
import sys
import zlib

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import png_read  # noqa: E402


def title(path, want=b"Title"):
    for kind, data in png_read.chunks(path):
        if kind == b"iTXt":
            key, rest = data.split(b"\0", 1)
            flag, _method = rest[0], rest[1]
            _lang, rest = rest[2:].split(b"\0", 1)
            _lkey, text = rest.split(b"\0", 1)
            if key == want:
                return zlib.decompress(text).decode() if flag else text.decode()
        if kind == b"tEXt":
            key, text = data.split(b"\0", 1)
            if key == want:
                return text.decode("latin-1")
    return None


args, want = sys.argv[1:], "Title"
if args[:1] == ["--key"]:
    want, args = args[1], args[2:]
for p in args:
    t = title(p, want.encode())
    print(f"{p}: {t if t is not None else '(no title)' if want == 'Title' else '(no ' + want + ')'}")

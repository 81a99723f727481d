#!/bin/sh
# fig17_grid.sh: Ding et al. 2019 Fig. 17 as hearth bakes it (#18): the
# Stomakhin-like baseline (top row, cookies.lua --set baseline=true) against
# the full model (bottom row), ovens 190, 150 and 110 degC from left to right,
# the leavened cookie (0.015) alone on its tray, 4 s (cookies.lua's real
# dough conductivity sets every cookie by 3.5 s at 150 degC), coloured by
# temperature. Prints each cookie's height and top curvature (probe;
# particles +- the fit's standard error, h.top_curvature) and writes the six
# last frames side by side as OUT (default docs/gallery/fig17_baseline_vs_dough.png).
# Usage: scripts/validation/fig17_grid.sh [BUILD_DIR] [DX] [OUT]   (defaults build/release 0.005)
set -eu
b=$(cd "${1:-build/release}" && pwd)
dx=${2:-0.005}
root=$(cd "$(dirname "$0")/../.." && pwd)
out=${3:-$root/docs/gallery/fig17_baseline_vs_dough.png}
case $out in /*) ;; *) out=$(pwd)/$out ;; esac
export HEARTH_PLUGIN_PATH="$b/plugins" OMP_NUM_THREADS=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for base in true false; do
    for T in 190 150 110; do
        d="$tmp/${base}_$T"
        mkdir -p "$d"
        (cd "$d" && "$b/app/hearth" run "$root/scripts/scenes/baking/cookies.lua" --quiet --set dx="$dx" \
            --set until_t=4 --set frames=1 --set ovens="$T" --set leaveners=0.015 --set baseline=$base |
            sed -n "s/^oven/baseline=$base: oven/p")
    done
done
# The last frame of each bake (heat_0001.png), baseline above, full model below.
python3 - "$tmp" "$out" <<'PY'
import os, struct, sys, zlib

def read(path):
    b = open(path, "rb").read()
    pos, idat, hdr = 8, b"", None
    while pos < len(b):
        n, kind = struct.unpack(">I4s", b[pos:pos + 8])
        data = b[pos + 8:pos + 8 + n]
        if kind == b"IHDR": hdr = struct.unpack(">IIBBBBB", data)
        if kind == b"IDAT": idat += data
        pos += 12 + n
    w, h, depth, ctype = hdr[:4]
    assert depth == 8 and ctype == 2, f"{path}: expected 8-bit RGB"
    raw, stride, rows, prev = zlib.decompress(idat), 3 * w, [], bytearray(3 * w)
    for y in range(h):
        f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
        for i in range(stride):
            a = line[i - 3] if i >= 3 else 0
            c = prev[i - 3] if i >= 3 else 0
            up = prev[i]
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + up) & 255
            elif f == 3: line[i] = (line[i] + (a + up) // 2) & 255
            elif f == 4:
                p = a + up - c
                pa, pb, pc = abs(p - a), abs(p - up), abs(p - c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else up if pb <= pc else c)) & 255
        rows.append(bytes(line))
        prev = line
    return w, h, rows

tmp, out = sys.argv[1], sys.argv[2]
grid = [[read(os.path.join(tmp, f"{base}_{T}", "hearth-out", "cookies", f"oven_{T}", "heat_0001.png"))
         for T in (190, 150, 110)] for base in ("true", "false")]
gap = 6  # white pixels between pictures
w, h = grid[0][0][0], grid[0][0][1]
W, H = 3 * w + 2 * gap, 2 * h + gap
rows = []
for r, row in enumerate(grid):
    if r: rows += [b"\xff" * (3 * W)] * gap
    for y in range(h):
        rows.append((b"\xff" * (3 * gap)).join(pic[2][y] for pic in row))
ihdr = struct.pack(">IIBBBBB", W, H, 8, 2, 0, 0, 0)
data = zlib.compress(b"".join(b"\x00" + r for r in rows), 9)
chunk = lambda k, d: struct.pack(">I", len(d)) + k + d + struct.pack(">I", zlib.crc32(k + d))
open(out, "wb").write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", ihdr) + chunk(b"IDAT", data) + chunk(b"IEND", b""))
print(f"wrote {out} ({W} x {H})")
PY

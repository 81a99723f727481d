#!/usr/bin/env python3
"""bread3d_vtu.py DIR X0 [SLIT_X,...]: one loaf of a 3D bread.lua (or bread3d.lua) run, measured from its VTU
frames (DIR: the run's vtu/ folder; X0 the loaf's axis, m: 0.07, 0.21, 0.35 for loaves 1-3). Per frame: its
volume (V0 J summed, as bread.csv), its length along z and width along x at their largest, its highest particle above
the tray, the area of its middle cross-section (the volume of its particles within 10 mm of z = 0.06, over 20 mm), its
and (helper loaf3d) that of the middle's material: the particles that started in that slab, followed by id, their
volume over the slab's thickness now (20 mm times the axial stretch, the distance between the mean z of its first and
last particle layer over that distance at the start). The first counts whole particle layers, so it misses a stretch
along z smaller than a layer's share of the slab (at 8 mm, 5 layers 4 mm apart in 20 mm: a middle stretched 8% along z
still holds its 5 layers, and the loaf's section reads 8% high); the second does not. Then its fully damaged
particles (damage 1) and where they are; with SLIT_X, each slit's particle gap: in the slab
|z - 0.06| < 10 mm, between 4 and 12 mm below the highest particle 8-20 mm either side of the slit, the distance
between the nearest particles left and right of the slit's centre (centre to centre: the raw 10 mm slit reads ~14 mm
at 8 mm, one particle spacing more). docs/validation.md, "bread.lua in 3D". Needs only Python's standard library."""
import glob
import re
import struct
import sys

TRAY, ZC, BAND = 0.02, 0.06, 0.01


def read_vtu(path):
    """{name: values} of a hearth VTU written with raw appended data (UInt64 block headers)"""
    b = open(path, "rb").read()
    head, _, data = b.partition(b'<AppendedData encoding="raw">')
    data = data[data.index(b"_") + 1:]
    out = {}
    for m in re.finditer(rb'<DataArray type="(\w+)" Name="([^"]+)" NumberOfComponents="\d+"[^>]*?offset="(\d+)"', head):
        kind, name, off = m.group(1).decode(), m.group(2).decode(), int(m.group(3))
        n = struct.unpack_from("<Q", data, off)[0]
        fmt = {"Float64": "d", "Int32": "i", "Int64": "q", "UInt8": "B"}[kind]
        out[name.split(" ")[0]] = struct.unpack_from("<%d%s" % (n // struct.calcsize(fmt), fmt), data, off + 8)
    return out


def main():
    d, x0 = sys.argv[1], float(sys.argv[2])
    slits = [float(s) for s in sys.argv[3].split(",")] if len(sys.argv) > 3 else []
    slab = None  # the middle's material: ids of the particles in the slab at the start, and its first and last layer
    for f in sorted(glob.glob(d + "/*_[0-9][0-9][0-9][0-9].vtu")):
        a = read_vtu(f)
        p, vol, dmg = a["Points"], a["volume"], a["damage"]
        X, Y, Z = p[0::3], p[1::3], p[2::3]
        k1 = [k for k in range(len(vol)) if abs(X[k] - x0) < 0.07]
        mid = [k for k in k1 if abs(Z[k] - ZC) < BAND]
        at = {a["id"][k]: k for k in k1}
        if slab is None:
            zlo, zhi = min(Z[k] for k in mid), max(Z[k] for k in mid)
            lo = [k for k in mid if Z[k] < zlo + 1e-4]
            hi = [k for k in mid if Z[k] > zhi - 1e-4]
            slab = ([a["id"][k] for k in mid], [a["id"][k] for k in lo], [a["id"][k] for k in hi],
                    sum(Z[k] for k in hi) / len(hi) - sum(Z[k] for k in lo) / len(lo))
        lo = [Z[at[i]] for i in slab[1] if i in at]
        hi = [Z[at[i]] for i in slab[2] if i in at]
        stretch = (sum(hi) / len(hi) - sum(lo) / len(lo)) / slab[3]
        row = (f"t {a['TimeValue'][0]:.3f} s: volume {sum(vol[k] for k in k1):.5g} m^3, length "
               f"{(max(Z[k] for k in k1) - min(Z[k] for k in k1)) * 1e3:.1f} mm, width "
               f"{(max(X[k] for k in k1) - min(X[k] for k in k1)) * 1e3:.1f} mm, top {(max(Y[k] for k in k1) - TRAY) * 1e3:.1f} mm, "
               f"middle section {sum(vol[k] for k in mid) / (2 * BAND) * 1e6:.0f} mm^2, its material's "
               f"{sum(vol[at[i]] for i in slab[0] if i in at) / (2 * BAND * stretch) * 1e6:.0f} mm^2 (stretched {stretch:.3f} "
               "along z)")
        for xs in slits:
            zb = [k for k in mid if abs(X[k] - xs) < 0.03]
            yt = max(Y[k] for k in zb if 0.008 < abs(X[k] - xs) < 0.02)
            band = [X[k] for k in zb if yt - 0.012 < Y[k] < yt - 0.004]
            lo = max([x for x in band if x <= xs], default=float("nan"))
            hi = min([x for x in band if x > xs], default=float("nan"))
            row += f", gap at {xs * 1e3:.0f} mm {(hi - lo) * 1e3:.1f} mm"
        cracked = [k for k in k1 if dmg[k] >= 1]
        row += f", cracked {len(cracked)}"
        if cracked:
            row += " (" + "; ".join(f"{X[k] * 1e3:.0f},{(Y[k] - TRAY) * 1e3:.0f},{Z[k] * 1e3:.0f}" for k in cracked[:6]) + \
                   (" ..." if len(cracked) > 6 else "") + " mm: x, above the tray, z)"
        print(row)


if __name__ == "__main__":
    main()

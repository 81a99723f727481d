#!/usr/bin/env python3
"""pancake_middle_measure.py DX LANDED.csv: what lies under the physical pancake's middle once it has landed
(pancake.lua's landed.csv: x, y, J and temperature of every particle at the end), and what a 1D slab of the sheet's
thickness would reach there.
pancake_middle_measure.py --slab L: the 1D slab alone, for a sheet L metres thick.

The centre line: the particles within DX / 2 of x = 2 XP - (X0 + X1) / 2 (the pour's centre mirrored about the
spatula's pivot, where pancake.lua's `inside()` reads its middle particle after the flip), sorted by height above the
pan. At 4 particles a cell they stand DX / 2 apart, so a gap wider than DX between two consecutive heights is at least
one missing layer: air. The sheet's base is the particle just above the widest such gap below the line's midpoint
(the lowest particle when there is none); the particles below it are what the sheet rests on (dripped strands of the
raw side, helper pancakeflip's "Left"). The sheet's thickness is its top particle's height minus its base's plus their
own half-extents (sqrt(J) DX / 4 each).

The slab (helper pancakeheat): 1D, explicit, cell-centred, the preset's numbers (lua/hearth/dough_physical.lua's
pancake, real time): rho 1050 kg/m^3, c 3000 J/(kg K) wet and 0.46 x 1650 dry (the mixture rule on the water held),
kappa 0.41 W/(m K), water 567 kg/m^3 (saturation 0.567), L = 2.26 MJ/kg at a 100 degC boiling point (the scene's
latent_heat and boiling: heat past 100 degC boils water first), 20 degC batter; its lower face on the 190 degC
pan through 1700 W/(m^2 K), its upper face in 25 degC air through 10 W/(m^2 K) (no evaporation from it: the
scene's top face dries and cools a little more). On its first face until `first` s, turned over (its profile
reversed), in the air on both faces until `landed` s, then on its second face to `end` s. pancake.lua's
physical preset flips at 120 s and its turn spans 30 s (0.5 s x 60) on the heated spatula: the two brackets are
first = landed = 150 s (heated through the turn) and first = 120, landed = 150 (the turn in the air)."""
import csv, math, sys

PAN, XP, X0, X1 = 0.01, 0.165, 0.045, 0.105  # m: pancake.lua's pan top, spatula pivot x and the spout's path
XC = 2 * XP - (X0 + X1) / 2                   # the centre line after the flip

PRESET = dict(k=0.41, rho=1050.0, c=3000.0, cdry=0.46 * 1650, water=567.0, Lh=2.26e6, Tb=100.0, T0=20.0,
              Tpan=190.0, hpan=1700.0, Tair=25.0, hair=10.0)


def centre_column(rows, dx, xc=XC):
    """rows: (x, y, J, T). The centre line's particles from the pan up, the widest gap under its midpoint and the
    sheet above it: a dict of heights (m above the pan), the gap (m), the base's index, the sheet's thickness and the
    temperature of the particle nearest the sheet's own middle."""
    col = sorted((r[1] - PAN, r[2], r[3]) for r in rows if abs(r[0] - xc) < dx / 2 and r[1] > PAN)
    if not col:
        return None
    ys = [c[0] for c in col]
    mid = 0.5 * (ys[0] + ys[-1])
    base, gap = 0, 0.0
    for i in range(1, len(ys)):
        g = ys[i] - ys[i - 1]
        if ys[i - 1] < mid and g > dx and g > gap:
            base, gap = i, g
    top = len(ys) - 1
    thick = ys[top] - ys[base] + (math.sqrt(col[top][1]) + math.sqrt(col[base][1])) * dx / 4
    centre = 0.5 * (ys[base] + ys[top])
    m = min(range(base, top + 1), key=lambda i: abs(ys[i] - centre))
    return dict(heights=ys, temps=[c[2] for c in col], gap=gap, base=base, under=base, thickness=thick,
                sheet_middle_T=col[m][2], sheet_middle_y=ys[m])


def read_landed(path):
    return [(float(r["x_m"]), float(r["y_m"]), float(r["J"]), float(r["temperature_degC"]))
            for r in csv.DictReader(open(path))]


def slab(L, first=150.0, landed=150.0, end=210.0, n=40, p=PRESET, boil=True, times=()):
    """The 1D slab's temperature at its middle at `end` s (and at each of `times`): a dict time -> degC. With
    boil False there is no boiling and the capacity stays the wet one (the series check)."""
    dz = L / n
    T, w = [p["T0"]] * n, [p["water"]] * n
    cwet, cdry = p["rho"] * p["c"], p["rho"] * (p["cdry"] if boil else p["c"])
    k = p["k"]
    dt = 0.4 * dz * dz * min(cwet, cdry) / k
    steps = int(math.ceil(end / dt))
    dt = end / steps
    marks = {int(round(t / dt)): t for t in times}
    out, flipped = {}, False

    def face(h):  # the face's coefficient through half a cell of the slab
        return 0.0 if h == 0 else 1.0 / (1.0 / h + 0.5 * dz / k)
    for s in range(steps):
        t = s * dt
        if not flipped and t >= first:
            T.reverse(); w.reverse(); flipped = True
        on_pan = t < first or t >= landed
        q = [0.0] * (n + 1)  # heat flux upward through the faces, W/m^2
        for i in range(1, n):
            q[i] = -k * (T[i] - T[i - 1]) / dz
        q[0] = face(p["hpan"] if on_pan else p["hair"]) * ((p["Tpan"] if on_pan else p["Tair"]) - T[0])
        q[n] = face(p["hair"]) * (T[-1] - p["Tair"])
        for i in range(n):
            cap = cdry + (cwet - cdry) * w[i] / p["water"]
            Tn = T[i] + (q[i] - q[i + 1]) / dz * dt / cap
            if boil and Tn > p["Tb"] and w[i] > 0:
                heat = (Tn - p["Tb"]) * cap
                b = min(w[i], heat / p["Lh"])
                w[i] -= b
                Tn = p["Tb"] + (heat - b * p["Lh"]) / (cdry + (cwet - cdry) * w[i] / p["water"])
            T[i] = Tn
        if s + 1 in marks:
            out[marks[s + 1]] = middle(T)
    out[end] = middle(T)
    return out


def middle(T):
    n = len(T)
    return T[n // 2] if n % 2 else 0.5 * (T[n // 2 - 1] + T[n // 2])


def series_middle(L, t, alpha, T0, Tf, terms=200):
    """A slab 0 < z < L at T0, its face z = 0 held at Tf from t = 0 and its face z = L insulated: the temperature at
    z = L / 2 (Carslaw & Jaeger, Conduction of Heat in Solids, 2nd ed., §3.3, the slab 0 < z < 2L heated on both
    faces: (T - T0) / (Tf - T0) = 1 - (4 / pi) sum (-1)^m / (2m + 1) exp(-(2m + 1)^2 pi^2 alpha t / (4 L^2))
    cos((2m + 1) pi (L - z) / (2 L)))"""
    s = 0.0
    for m in range(terms):
        a = (2 * m + 1) * math.pi / (2 * L)
        s += (-1) ** m / (2 * m + 1) * math.exp(-a * a * alpha * t) * math.cos(a * (L - L / 2))
    return Tf - (Tf - T0) * 4 / math.pi * s


def brackets(L):
    """the middle at 210 s for the two brackets: (heated through the turn, the turn in the air)"""
    return slab(L, 150.0, 150.0)[210.0], slab(L, 120.0, 150.0)[210.0]


def describe(dx, path):
    c = centre_column(read_landed(path), dx)
    if c is None:
        print(f"pancake_middle_measure: no particle on the centre line x = {XC:.4f} m in {path}")
        return None
    ys = c["heights"]
    hot, cool = brackets(c["thickness"])
    c["slab"] = (hot, cool)
    line = " ".join(f"{y * 1e3:.2f}({t:.0f})" for y, t in zip(ys, c["temps"]))
    print(f"  the centre line at the end (mm above the pan (degC)): {line}")
    print(f"dx {dx * 1e3:g} mm: under the middle, {c['under']} particle(s) on the pan below a gap of "
          f"{c['gap'] * 1e3:.2f} mm ({c['gap'] / dx:.2f} dx; 0: none wider than dx); the sheet's base "
          f"{ys[c['base']] * 1e3:.2f} mm above the pan, its thickness {c['thickness'] * 1e3:.2f} mm, its own middle "
          f"{c['sheet_middle_T']:.1f} degC at {c['sheet_middle_y'] * 1e3:.2f} mm; a 1D slab that thick on the pan "
          f"(tests/pancake_middle_measure.py) reaches {cool:.1f}-{hot:.1f} degC at its middle by 3.5 min")
    return c


def main():
    a = sys.argv[1:]
    if len(a) == 2 and a[0] == "--slab":
        L = float(a[1])
        hot, cool = brackets(L)
        print(f"slab {L * 1e3:.2f} mm: middle at 210 s {hot:.1f} degC (heated through the turn), {cool:.1f} degC "
              f"(the turn in the air)")
        return
    if len(a) != 2:
        sys.exit(__doc__)
    describe(float(a[0]), a[1])


if __name__ == "__main__":
    main()

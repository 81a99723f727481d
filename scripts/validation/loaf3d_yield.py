#!/usr/bin/env python3
"""loaf3d_yield.py DIR X0 [ZMID [NU]]: the stress and the Cam-clay yield (Ding et al. 2019 eq. 12) of one bread.lua
loaf's middle, from its VTU frames (DIR: the run's vtu/ folder; X0: the loaf's axis, m; ZMID: 3D, the middle slab's z,
default 0.06; a 2D run: the whole loaf). docs/validation.md, "bread.lua's 3D loaf: its ends and its yield". Per frame
and per height band of the middle slab (|z - ZMID| < 10 mm): the mean solid Cauchy stress sigma_xx, sigma_yy, sigma_zz
(Pa, tension positive: the VTU's stress, which is the plugin's own, core/sim/probe.c), the gas pressure (eq. 13, the
VTU's gas_pressure), the total sigma_zz (the solid's less the gas and water pressures the core adds after the plugin,
core/sim/material_batch.c), the solid's Kirchhoff stress J sigma as eq. 12 sees it: its p = -tr/3, q = sqrt(3/2)
|dev|, M(n^p) p^2 + q^2 over tau_y(T)^2 (the yield ratio: above 1 the dough flows, at the rate (1/eta) f of section
5.3), the share of particles above 1, J and J^P = (1 - n_0) / (1 - n^p) (plugins/cam_clay_dough.c; n_0 = 0.1,
lua/hearth/dough.lua). tau_y(T) is the bread preset's Fig. 8 curve (200 Pa x 1, 0.8, 0.3, 20 at 5, 20, 35, 70 degC,
lua/hearth/dough.lua), read at the particle's temperature (the curve is irreversible: its highest temperature, the
same in a loaf that only heats); the drying factor on tau_y is left out (the middle's crumb stays near its raw water).
And the elastic Hencky strain the solid's stress stands for, eps = ((1 + nu) tau - nu tr(tau) I) / E (section 5.2's
Psi; E 2 kPa, nu 0.3: the bread preset, whose E only its drying factor moves; NU: the run's Poisson ratio,
bread3d.lua's nu), its xx, yy and zz components: the stretch the gas holds the crumb at. Needs only Python's standard
library."""
import glob
import math
import sys

sys.path.insert(0, __file__.rsplit("/", 1)[0])
from bread3d_vtu import read_vtu  # noqa: E402

TRAY, BAND, N0 = 0.02, 0.01, 0.1
THETA, TAU = (5, 20, 35, 70), (200, 160, 60, 4000)
E, NU = 2e3, 0.3


def tau_y(T):
    if T <= THETA[0]:
        return TAU[0]
    for i in range(1, len(THETA)):
        if T <= THETA[i]:
            u = (T - THETA[i - 1]) / (THETA[i] - THETA[i - 1])
            return TAU[i - 1] + u * (TAU[i] - TAU[i - 1])
    return TAU[-1]


def M_of(n):
    if not n > 0:
        return 0.0
    l = math.log(1 / n)
    return 9.0 / (4.0 * l * l * (3.5 * n + 1.0))


def main():
    d, x0 = sys.argv[1], float(sys.argv[2])
    zmid = float(sys.argv[3]) if len(sys.argv) > 3 else 0.06
    nu = float(sys.argv[4]) if len(sys.argv) > 4 else NU
    bands = ((0, 0.2), (0, 0.025), (0.025, 0.05), (0.05, 0.2))  # the whole slab, then its foot, middle and crown
    print("t | band (mm above tray) | n | solid sxx syy szz | p_gas | total szz, solid tau p | q | yield ratio (mean, share >1) | "
          "J | J^P | T | elastic strain xx yy zz")
    for f in sorted(glob.glob(d + "/*_[0-9][0-9][0-9][0-9].vtu")):
        a = read_vtu(f)
        P, S = a["Points"], a["stress"]
        X, Y, Z = P[0::3], P[1::3], P[2::3]
        d3 = any(abs(z) > 0 for z in Z[:100])
        ks = [k for k in range(len(X)) if abs(X[k] - x0) < 0.07 and (not d3 or abs(Z[k] - zmid) < BAND)]
        for lo, hi in bands:
            kb = [k for k in ks if lo <= Y[k] - TRAY < hi]
            if not kb:
                continue
            acc = [0.0] * 15
            for k in kb:
                s = S[9 * k:9 * k + 9]
                J, n, T = a["J"][k], a["porosity"][k], a["temperature"][k]
                pg = a["gas_pressure"][k] if "gas_pressure" in a else 0.0
                pw = a["water_pressure"][k] if "water_pressure" in a else 0.0
                pg = pg if pg == pg else 0.0
                pw = pw if pw == pw else 0.0
                ss = [J * s[i] for i in range(9)]  # the solid's Kirchhoff stress
                p = -(ss[0] + ss[4] + ss[8]) / 3
                dev = [ss[i] + (p if i in (0, 4, 8) else 0) for i in range(9)]
                q = math.sqrt(1.5 * sum(v * v for v in dev))
                ty = tau_y(T)
                r = (M_of(n) * p * p + q * q) / (ty * ty)
                jp = (1 - N0) / (1 - n) if n == n else float("nan")
                for i, v in enumerate((s[0], s[4], s[8], pg, s[8] - pg - pw, p, q, r, 1.0 if r > 1 else 0.0, J, jp, T,
                                       *(((1 + nu) * ss[i] + 3 * nu * p) / E for i in (0, 4, 8)))):
                    acc[i] += v
            m = [v / len(kb) for v in acc]
            print(f"{a['TimeValue'][0]:.2f} | {lo * 1e3:.0f}-{min(hi, 0.2) * 1e3:.0f} | {len(kb)} | {m[0]:.0f} {m[1]:.0f} "
                  f"{m[2]:.0f} | {m[3]:.0f} | {m[4]:.0f}, {m[5]:.0f} | {m[6]:.0f} | {m[7]:.2f}, {m[8] * 100:.0f}% | "
                  f"{m[9]:.3f} | {m[10]:.3f} | {m[11]:.1f} | {m[12]:.3f} {m[13]:.3f} {m[14]:.3f}")


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
"""dead_crust_slab.py [KSCALE [DZ_MM]] [hc=H Tw=T eps=E]: the crust of scripts/scenes/sph/bread_of_the_dead.lua's dough as a 1D
reference (#18, helper deadcrust; docs/validation.md, "The bread of the dead's crust is pale because its oven is").

A wet bread-dough slab 30 mm deep (insulated below; the loaf's radius) at 26 degC in a 180 degC oven, the oven's
Robin flux h (T_o - T_s) at its top, h = 30 W/(m^2 K) (the scene's, Baik et al. 1999). The dough is the scene's:
1100 kg/m^3, 0.45 of it water (495 kg/m^3), kappa 0.51 W/(m K) wet and 0.23 dried, c 2700 J/(kg K) wet and 907.5
dried, both linear in the water left (Zanoni et al. 1995; Choi & Okos; lua/hearth/dough_physical.lua's bread).
Enthalpy form, explicit: the water leaves only by boiling at 100 degC (L = 2.257e6 J/kg): no evaporation below it
and no transport, which dries the top no sooner than the scene's surface evaporation does. Pair conductance: the
harmonic mean. The surface: h (T_o - T_s) = kappa_0 (T_s - T_0) / (dz / 2). Its browning: Zanoni et al. 1995's
kinetics times (1 - W / W0) (core/sim/fields/browning.c). KSCALE multiplies both kappas (the scene's heat_int over
S kappa / c: 0.5 / 0.283 = 1.765 before the fix). DZ_MM the cell (default 0.5; 0.25 and 0.125 converge).

Then the quasi-steady dried front (the brief's closed form, an upper bound: all the oven's flux boils water at the
front, none conducts inward): rho_w L dd/dt = (T_o - 100) / (1/h + d/kappa_dry), T_s from h (T_o - T_s) =
kappa_dry (T_s - 100) / d, the surface dry (water factor 1), from 0, 5 and 14.5 min (when the slab's surface reaches
100 degC with the physical kappa) to 30 min.

With Tw= (helper ovenwall; docs/validation.md, "An oven's hot walls"): the oven's walls at Tw degC radiate, the
surface's flux h_c (T_o - T_s) + eps sigma (T_w^4 - T_s^4) (T in K; h_c from hc=, default 10; eps= default 0.9), T_s
solved by Newton from that flux = kappa_0 (T_s - T_0) / (dz / 2); the front is not run then."""
import math, sys

To, T0, h, rho, L = 180.0, 26.0, 30.0, 1100.0, 2.257e6
RAD = None  # (eps sigma, T_w in K) with Tw=
W0, cdry, cw = 495.0, 907.5, 2700.0


def zanoni(Ts):
    return 42000 * math.exp(-64151 / (8.314 * (Ts + 273.15)))


def slab(ks, dz):
    kw, kd = 0.51 * ks, 0.23 * ks
    n = int(round(0.03 / dz))
    T, W, bs = [T0] * n, [W0] * n, 0.0
    kap = lambda w: kd + (kw - kd) * w / W0
    C = lambda w: rho * cdry + (rho * cw - rho * cdry) * w / W0
    dt, t, nxt = 0.2 * dz * dz * C(0) / kw, 0.0, 0.0
    while True:
        g = kap(W[0]) / (dz / 2)
        Ts = (h * To + g * T[0]) / (h + g)
        if RAD:  # the walls: Newton on h (To - Ts) + r (w^4 - (Ts + 273.15)^4) = g (Ts - T[0])
            r, w = RAD
            for _ in range(30):
                a = Ts + 273.15
                f = h * (To - Ts) + r * (w ** 4 - a ** 4) - g * (Ts - T[0])
                Ts -= f / (-h - 4 * r * a ** 3 - g)
        if t >= nxt - 1e-9:
            dried = dz * sum(1 for w in W if w < 0.5 * W0)
            print("t %5.1f min  T_s %6.1f degC  top cell %6.1f  s/s0 top %.3f  dried %.2f mm  browning %.4f"
                  % (t / 60, Ts, T[0], W[0] / W0, dried * 1000, bs))
            nxt += 300
            if t >= 1800 - 1e-9: return
        step = min(dt, nxt - t)
        bs += step * zanoni(Ts) * (1 - W[0] / W0) * (1 - bs)
        k = [kap(w) for w in W]
        q = [g * (Ts - T[0])] + [2 * k[i] * k[i + 1] / (k[i] + k[i + 1]) * (T[i] - T[i + 1]) / dz
                               for i in range(n - 1)] + [0.0]
        for i in range(n):
            Ci = C(W[i])
            T[i] += (q[i] - q[i + 1]) * step / dz / Ci
            if T[i] > 100 and W[i] > 0:
                ex = (T[i] - 100) * Ci
                b = min(W[i], ex / L)
                W[i] -= b
                T[i] = 100 + (ex - b * L) / C(W[i])
        t += step


def front(t0_min, kd=0.23):
    d, b, t, dt, Ts = 0.0, 0.0, t0_min * 60, 0.5, 100.0
    while t < 1800:
        Ts = (h * To + kd / d * 100) / (h + kd / d) if d > 0 else 100.0
        b += dt * zanoni(Ts) * (1 - b)
        d += dt * (To - 100) / (1 / h + d / kd) / (W0 * L)
        t += dt
    print(f"front from {t0_min:g} min: at 30 min d = {d * 1000:.2f} mm, T_s = {Ts:.1f} degC, browning {b:.3f}")


if __name__ == "__main__":
    kw = dict(a.split("=", 1) for a in sys.argv[1:] if "=" in a)
    pos = [a for a in sys.argv[1:] if "=" not in a]
    ks = float(pos[0]) if len(pos) > 0 else 1.0
    dz = (float(pos[1]) if len(pos) > 1 else 0.5) * 1e-3
    if "Tw" in kw:
        h, RAD = float(kw.get("hc", 10)), (float(kw.get("eps", 0.9)) * 5.670374419e-8, float(kw["Tw"]) + 273.15)
        print(f"slab, kappa x {ks:g}, dz {dz * 1000:g} mm, h_c {h:g} + walls {kw['Tw']} degC, eps {RAD[0] / 5.670374419e-8:g}:")
        slab(ks, dz)
        sys.exit(0)
    print(f"slab, kappa x {ks:g}, dz {dz * 1000:g} mm:")
    slab(ks, dz)
    print("quasi-steady dried front (upper bound), kappa_dry 0.23:")
    for t0 in (0, 5, 14.5): front(t0)

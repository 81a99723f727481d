#!/usr/bin/env python3
"""sph_surface_fv.py: the face temperature an outer row reads, in a 1D finite-volume model of SPH's Robin slab
(#18, helper sphsurface; docs/validation.md "SPH's crust browns at its surface's temperature").

The plane wall of tests/unit_sph_heat.c's sph_heat_ext_slab_converges (2L across, Bi = h L / kappa = 1, theta* = 1
at t = 0, the oven at 0) as N cells whose outer cell takes the oven's flux at its own temperature, h (T_ext - T_1),
as sph_heat.c's eq. 3.42 does; with --film the flux is moved in by half a cell, h (T_ext - T_1) / (1 + h dx / (2
kappa)), as MPM's boundary does (thermal.c's find_boundary). At Fo = 0.05 and 0.3 it prints, against the series at
the face, the error of the outer cell's own value and of the face the air-film closure reads from it (thermal.h's
thermal_face_temperature over d = dx / 2). Plain Python, no packages; ~10 s."""
import math
import sys


def root(f, lo, hi):
    for _ in range(200):
        m = 0.5 * (lo + hi)
        if f(lo) * f(m) <= 0:
            hi = m
        else:
            lo = m
    return 0.5 * (lo + hi)


def series(Fo, Bi, xi):
    """theta* = sum C_n exp(-z_n^2 Fo) cos(z_n xi), z tan z = Bi (Incropera's slab)."""
    s = 0.0
    for n in range(80):
        z = root(lambda z: z * math.tan(z) - Bi, n * math.pi + 1e-9, n * math.pi + math.pi / 2 - 1e-9)
        s += 4 * math.sin(z) / (2 * z + math.sin(2 * z)) * math.exp(-z * z * Fo) * math.cos(z * xi)
    return s


def slab(N, Fo, Bi, film):
    dx = 2.0 / N
    T, t, dt = [1.0] * N, 0.0, 0.2 * dx * dx
    r = 1 / (1 + Bi * dx / 2) if film else 1.0
    while t < Fo - 1e-12:
        d = min(dt, Fo - t)
        q = [0.0] * N
        for i in range(N - 1):
            f = (T[i + 1] - T[i]) / dx**2
            q[i] += f
            q[i + 1] -= f
        q[0] -= r * Bi * T[0] / dx
        q[-1] -= r * Bi * T[-1] / dx
        T = [T[i] + d * q[i] for i in range(N)]
        t += d
    return T


if __name__ == "__main__":
    film = "--film" in sys.argv
    Bi = 1.0
    print("flux at the outer cell's own value" if not film else "flux moved in by half a cell (MPM's)")
    for Fo in (0.05, 0.3):
        face = series(Fo, Bi, 1.0)
        for N in (10, 20, 40):
            T1 = slab(N, Fo, Bi, film)[-1]
            read = T1 / (1 + Bi * 1.0 / N)  # thermal_face_temperature(0, T1, 1 / (1 + Bi d)), d = dx / 2 = 1 / N
            print("Fo %.2f, %d across: face %.5f; error of the outer cell read as the face %+.5f, of the closure's face "
                  "%+.5f" % (Fo, N, face, T1 - face, read - face))

/* water_reference.h: closed forms and a 1D reference for the water tests of
 * both solvers (unit_water.c, unit_latent.c: MPM; unit_sph_water.c: SPH). */
#ifndef HEARTH_WATER_REFERENCE_H
#define HEARTH_WATER_REFERENCE_H
#include <math.h>
#include <stdlib.h>

#include "hearth/hearth.h" /* HEARTH_LATENT_HEAT */

#ifndef PI
#define PI 3.14159265358979323846
#endif

/* Crank (1975) eq. 4.54: a sheet exchanging through its faces with
 * -D dC/dx = alpha (C_s - C_0) (a sheet of thickness 2a), L = a alpha / D, at Fo = D t / a^2; beta_n
 * the roots of beta tan beta = L (eq. 4.55), one in each (n pi, n pi + pi/2). */
static inline double crank_sheet_robin(double Fo, double L) {
    double sum = 0;
    for (int n = 0; n < 400; n++) {
        double lo = n * PI, hi = n * PI + 0.5 * PI; /* b tan b - L rises from -L to +inf there */
        for (int it = 0; it < 80; it++) {
            const double b = 0.5 * (lo + hi);
            if (b * tan(b) - L < 0) lo = b;
            else hi = b;
        }
        const double b = 0.5 * (lo + hi);
        sum += 2 * L * L * exp(-b * b * Fo) / (b * b * (b * b + L * L + L));
    }
    return 1 - sum;
}

/* The 1D drying problem on [0, a]: rho0 ds/dt = d/dx(rho0 K theta s ds/dx),
 * no flux at 0, q.n = beta theta s at a. Cell-centred finite volumes,
 * backward Euler with Picard iterations on the nonlinear diffusivity.
 * Returns the remaining water fraction at each of nt times; dt the time step. */
static inline void drying_fd(int N, double a, double Kth, double bth, double rho0, double s0, const double *times, int nt,
                             double *frac, double dt) {
    const double h = a / N;
    double *s = malloc(sizeof(double) * N), *sn = malloc(sizeof(double) * N), *lo = malloc(sizeof(double) * N),
           *di = malloc(sizeof(double) * N), *up = malloc(sizeof(double) * N), *rhs = malloc(sizeof(double) * N);
    for (int i = 0; i < N; i++) s[i] = s0;
    double t = 0;
    for (int k = 0; k < nt; k++) {
        while (t < times[k] - 1e-12) {
            const double step = fmin(dt, times[k] - t);
            for (int i = 0; i < N; i++) sn[i] = s[i];
            for (int it = 0; it < 4; it++) { /* Picard: coefficients from the latest iterate */
                for (int i = 0; i < N; i++) {
                    const double cw = i > 0 ? Kth * 0.5 * (sn[i] + sn[i - 1]) / (h * h) : 0;
                    const double ce = i < N - 1 ? Kth * 0.5 * (sn[i] + sn[i + 1]) / (h * h) : 0;
                    lo[i] = -step * cw;
                    up[i] = -step * ce;
                    di[i] = 1 + step * (cw + ce) + (i == N - 1 ? step * bth / (rho0 * h) : 0);
                    rhs[i] = s[i];
                }
                for (int i = 1; i < N; i++) { /* Thomas algorithm */
                    const double m = lo[i] / di[i - 1];
                    di[i] -= m * up[i - 1];
                    rhs[i] -= m * rhs[i - 1];
                }
                sn[N - 1] = rhs[N - 1] / di[N - 1];
                for (int i = N - 2; i >= 0; i--) sn[i] = (rhs[i] - up[i] * sn[i + 1]) / di[i];
            }
            for (int i = 0; i < N; i++) s[i] = sn[i];
            t += step;
        }
        double w = 0;
        for (int i = 0; i < N; i++) w += s[i];
        frac[k] = w / (N * s0);
    }
    free(s), free(sn), free(lo), free(di), free(up), free(rhs);
}

/* A wet slab's boiling front by a 1D enthalpy-method reference (unit_latent.c,
 * unit_sph_water.c): n cells across the half thickness H, Robin (beta, oven
 * Tov) at the outer face through half a cell, symmetry at the centre,
 * density rho, heat capacity c, conductivity k, water w0 kg/m^3, from 20
 * degC; forward Euler, each cell boiling at 100 degC as water.c's water_boil
 * does. Returns when the innermost cell is half dry; *surf the outer face's
 * temperature then. */
static inline double boil_front_fd(int n, double H, double rho, double c, double k, double w0, double Tov, double beta,
                                   double *surf) {
    const double dx = H / n, dt = 0.2 * rho * c * dx * dx / k;
    double T[400], W[400], q[401] = {0}, t = 0;
    for (int i = 0; i < n; i++) T[i] = 20, W[i] = w0;
    while (W[n - 1] > 0.5 * w0 && t < 1e5) {
        q[0] = (Tov - T[0]) / (1.0 / beta + 0.5 * dx / k);
        for (int i = 1; i < n; i++) q[i] = k * (T[i - 1] - T[i]) / dx;
        q[n] = 0;
        for (int i = 0; i < n; i++) {
            T[i] += dt * (q[i] - q[i + 1]) / (rho * c * dx);
            if (T[i] > 100 && W[i] > 0) {
                const double e = rho * c * (T[i] - 100) / HEARTH_LATENT_HEAT;
                if (e < W[i]) W[i] -= e, T[i] = 100;
                else T[i] -= W[i] * HEARTH_LATENT_HEAT / (rho * c), W[i] = 0;
            }
        }
        t += dt;
    }
    *surf = T[0] + 0.5 * dx * q[0] / k;
    return t;
}

/* The wet-bulb temperature (degC) of a wet surface with latent heat and the
 * vapour-driven evaporation of issue #18 (water.h, water_vapour_factor): the
 * surface temperature T where the oven's Robin heat equals what the vapour
 * carries away at surface saturation excess ds = s - s_amb,
 *     beta (T_oven - T) = L beta^w theta ds P_sat(theta) / P_sat(theta_b)   (theta = T + 273.15),
 * the ratio capped at 1. P_sat by Clausius-Clapeyron through 101325 Pa at
 * 100 degC with Delta H_v = 40.66 kJ/mol (Rodriguez-Arenas 2011 eq. 2.43),
 * written out here, not read from the core. The right side rises with T and
 * the left falls, so bisection on [-273.15, T_oven] finds the one root. */
static inline double wet_bulb_vapour(double beta, double T_oven, double bw, double ds, double Tb) {
    const double hr = 40660.0 / 8.314462618, thb = Tb + 273.15;
    double lo = -273.15, hi = T_oven;
    for (int it = 0; it < 200; it++) {
        const double T = 0.5 * (lo + hi), th = T + 273.15;
        const double f = th > 0 ? fmin(1.0, exp(-hr * (1.0 / th - 1.0 / thb))) : 0.0;
        if (beta * (T_oven - T) > HEARTH_LATENT_HEAT * bw * th * ds * f) lo = T;
        else hi = T;
    }
    return 0.5 * (lo + hi);
}

#endif

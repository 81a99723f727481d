/* base_reference.c: a fine 1D finite-volume reference for a wet slab on a hot
 * tray (docs/validation.md, "The base on the tray"; helper basecontact).
 * The slab starts at T0 everywhere; the tray (TP, BETA) heats its face y = 0;
 * its top is insulated. Per cell: temperature T and moisture ratio X;
 * C(X) dT/dt = d/dy (k(X) dT/dy), C and k linear in X between bread's dry and
 * wet values (hearth's material_conductivity / dry_specific_heat rule); a wet
 * cell past TB boils its excess C (T - TB) as hearth's water_boil does (latent
 * heat L per kg of water, 1000 s kg/m^3 of it). The face's temperature closes
 * the Robin flux over the first half cell. Browning: browning.c's rate
 * (Zanoni et al. 1995) times 1 - X, at the face and at heights y.
 *   cc -O2 -o base_reference base_reference.c -lm && ./base_reference T0 h_mm */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

static const double RHO = 484, CW = 2700, CD = 907.5, KW = 0.51, KD = 0.23, SAT = 0.218, TP = 200, TB = 100, BETA = 100,
                    LAT = 2.26e6, H = 0.03, TEND = 1500;

static double kbr(double T) { return 42000 * exp(-64151 / (8.314 * (T + 273.15))); }

int main(int argc, char **argv) {
    const double T0 = argc > 1 ? atof(argv[1]) : 100, h = (argc > 2 ? atof(argv[2]) : 0.025) * 1e-3;
    const int n = (int)lround(H / h);
    const double W = 1000 * SAT * LAT, ys[4] = {1.25e-3, 0.625e-3, 0.3125e-3, 0.15625e-3};
    double *T = malloc(sizeof(double) * n), *X = malloc(sizeof(double) * n), *q = malloc(sizeof(double) * (n + 1));
    for (int i = 0; i < n; i++) T[i] = T0, X[i] = 1;
    long nst = (long)ceil(TEND / (0.2 * h * h * RHO * CD / KW));
    const double dt = TEND / nst;
    double b[4] = {0}, bf = 0, boiled = 0, Tf = T0, tface = -1;
    for (long s = 0; s < nst; s++) {
        const double k0 = KD + (KW - KD) * X[0];
        Tf = (BETA * TP + 2 * k0 / h * T[0]) / (BETA + 2 * k0 / h);
        q[0] = BETA * (TP - Tf), q[n] = 0;
        for (int i = 1; i < n; i++) {
            const double ka = KD + (KW - KD) * X[i - 1], kb = KD + (KW - KD) * X[i];
            q[i] = -2 * ka * kb / (ka + kb) * (T[i] - T[i - 1]) / h;
        }
        for (int i = 0; i < n; i++) {
            const double C = RHO * (CD + (CW - CD) * X[i]);
            T[i] += dt * (q[i] - q[i + 1]) / (h * C);
            if (T[i] > TB && X[i] > 0) {
                const double e = C * (T[i] - TB), dX = fmin(X[i], e / W);
                X[i] -= dX, boiled += dX * h;
                T[i] = TB + (e - dX * W) / (RHO * (CD + (CW - CD) * X[i]));
            }
        }
        if (tface < 0 && X[0] < 0.01) tface = (s + 1) * dt;
        for (int j = 0; j < 4; j++) { /* cell-centred values interpolated to y */
            const double u = ys[j] / h - 0.5;
            const int i = u < 0 ? 0 : (int)u;
            const double f = u < 0 ? 0 : u - i, Ty = T[i] + f * (T[i + 1] - T[i]), Xy = X[i] + f * (X[i + 1] - X[i]);
            b[j] -= (1 - b[j]) * expm1(-kbr(Ty) * (1 - Xy) * dt);
        }
        bf -= (1 - bf) * expm1(-kbr(Tf) * (1 - X[0]) * dt);
        const long every = (long)lround(300 / dt); /* the loaf's CSV rows at 4, 9, 14, 19, 24 min */
        if ((s + 1 + (long)lround(60 / dt)) % every == 0)
            printf("  %.1f min: face %.2f degC, b %.4f; b at y %.4g / %.4g / %.4g / %.4g mm: %.4f / %.4f / %.4f / %.4f\n",
                   (s + 1) * dt / 60, Tf, bf, ys[0] * 1e3, ys[1] * 1e3, ys[2] * 1e3, ys[3] * 1e3, b[0], b[1], b[2], b[3]);
    }
    printf("T0 %g degC, h %g mm: boiled %.4f mm; face %.2f degC, browning %.4f (first cell dry at %.1f s)", T0, h * 1e3, boiled * 1e3,
           Tf, bf, tface);
    for (int j = 0; j < 4; j++) {
        const double u = ys[j] / h - 0.5;
        const int i = (int)u;
        const double f = u - i;
        printf("; y %.4g mm: %.2f degC, b %.4f", ys[j] * 1e3, T[i] + f * (T[i + 1] - T[i]), b[j]);
    }
    printf("\n");
    return 0;
}

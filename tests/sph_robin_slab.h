/* sph_robin_slab.h: the SPH Robin slab and its series, shared by unit_sph_heat.c (the profile and the heat taken,
 * sph_heat_ext_slab_converges) and unit_sph_surface.c (the face temperature browning reads,
 * sph_surface_temperature_slab_matches_series). */
#ifndef HEARTH_SPH_ROBIN_SLAB_H
#define HEARTH_SPH_ROBIN_SLAB_H
#include <math.h>
#include <stdio.h>

#include "hearth/hearth.h"
#include "scene.h"
#include "solver.h"
#include "sph_fixture.h"

/* Plane wall with Robin faces on both sides (half-thickness L, centre plane
 * a symmetry plane: Incropera's slab), theta* = (T - T_ext) / (T0 - T_ext) =
 * sum C_n exp(-z_n^2 Fo) cos(z_n xi), z tan z = Bi, C_n = 4 sin z / (2 z +
 * sin 2z), xi = y / L from the centre; the heat taken over its maximum is
 * 1 - sum C_n sin(z_n) / z_n exp(-z_n^2 Fo). */
static inline void slab_series(double Bi, double xi, double Fo, double *theta, double *taken) {
    const double pi = 3.14159265358979323846;
    double th = 0, q = 0;
    for (int n = 0; n < 200; n++) {
        double a = n * pi + 1e-12, b = n * pi + pi / 2 - 1e-12;
        for (int it = 0; it < 200; it++) { /* z tan z = Bi in (n pi, n pi + pi/2), by bisection */
            const double mid = 0.5 * (a + b);
            if (mid * tan(mid) - Bi > 0) b = mid;
            else a = mid;
        }
        const double z = 0.5 * (a + b), C = 4 * sin(z) / (2 * z + sin(2 * z)), e = exp(-z * z * Fo);
        th += C * e * cos(z * xi);
        q += C * sin(z) / z * e;
    }
    *theta = th, *taken = 1 - q;
}

static inline double robin_slab_sum_mT(const hearth_scene *s) {
    const double *T = pcold(&s->ps, PC_TEMPERATURE), *m = pcold(&s->ps, PC_MASS);
    double E = 0;
    for (int i = 0; i < s->ps.n; i++) E += m[i] * T[i];
    return E;
}

/* What the slab's outer particles read at its end (robin_slab's face, in theta* = (T - T_ext) / (T0 - T_ext)):
 * over the particles the solver gives a face temperature ("surface_temperature", not NaN), the mean |error| against
 * the series at the face (xi = +-1) of that reading (face_err) and of the particle's own temperature (own_err), and
 * of its own against the series at its own depth (depth_err); the mean signed error of the face reading (face_bias:
 * > 0 nearer T0 than the series, < 0 nearer the oven); n of them, and the series' face value. */
typedef struct robin_slab_face {
    double face_err, own_err, depth_err, face_bias, series_face;
    int n;
} robin_slab_face;

/* The slab in SPH: a pinned lattice N particles across 2L = 20 mm, periodic
 * along x (8 columns), free faces at top and bottom heated by eq. 3.42
 * (k_h,ext = h / c) and conducting by eq. 3.45 (k_h,int = kappa / c), Bi = h
 * L / kappa = k_h,ext L / k_h,int = 1, diffusivity D = k_h,int / rho. At Fo
 * = D t / L^2 = 0.3: err the worst |theta* - series| over the particles, and
 * the heat taken over its maximum against the series (rel, signed). dt is
 * held at 0.01 h^2 / D, as sph_heat_conduction_converges does. face (may be
 * NULL): the outer particles' face readings, above. */
static inline int robin_slab(int N, double *err, double *taken, double *taken_exact, robin_slab_face *face) {
    const double L = 0.01, dx = 2 * L / N, rho = 1000, D = 1e-2, Bi = 1, T0 = 26, Text = 180, y0 = 4 * dx;
    const double lo[3] = {0, 0, 0}, hi[3] = {8 * dx, 2 * L + 8 * dx, 0};
    hearth_scene_def d = sph_def(2, dx, lo, hi);
    d.gravity[1] = 0;
    d.sph.periodic[0] = 1;
    d.sph.heat_int = D * rho;
    d.sph.heat_ext = Bi * d.sph.heat_int / L;
    d.oven_temperature = Text;
    d.oven_beta = 0;
    d.dt_max = 0.01 * (d.sph.h_factor * dx) * (d.sph.h_factor * dx) / D;
    d.browning = face != NULL; /* the face temperatures are browning's: a scene that does not brown makes none */
    hearth_scene *s = hearth_scene_create(&d, NULL);
    if (!s) return -1;
    const int m = newtonian(s, rho, 1e4, 1.0);
    const double blo[3] = {0, y0, 0}, bhi[3] = {hi[0], y0 + 2 * L, 0};
    int rc = m >= 0 && sph_box(s, m, blo, bhi, 1, T0) >= 0 ? 0 : -1;
    const double E0 = robin_slab_sum_mT(s), t = 0.3 * L * L / D;
    hearth_error e;
    if (!rc && hearth_scene_advance(s, t, &e)) {
        fprintf(stderr, "%s\n", e.msg);
        rc = -1;
    }
    const double Fo = D * s->t / (L * L), *x = hearth_scene_positions(s), *T = pcold(&s->ps, PC_TEMPERATURE);
    const double *mass = pcold(&s->ps, PC_MASS);
    double worst = 0, M = 0, th, q;
    for (int i = 0; i < s->ps.n && !rc; i++) {
        slab_series(Bi, (x[3 * i + 1] - y0 - L) / L, Fo, &th, &q);
        if (!isfinite(T[i])) rc = -1;
        worst = fmax(worst, fabs((T[i] - Text) / (T0 - Text) - th));
        M += mass[i];
    }
    if (face && !rc) {
        const double *ts = s->solver->particle_values(s, "surface_temperature");
        double thf;
        slab_series(Bi, 1, Fo, &thf, &q);
        *face = (robin_slab_face){0, 0, 0, 0, thf, 0};
        for (int i = 0; ts && i < s->ps.n; i++) {
            if (isnan(ts[i])) continue;
            slab_series(Bi, (x[3 * i + 1] - y0 - L) / L, Fo, &th, &q);
            const double own = (T[i] - Text) / (T0 - Text);
            face->face_err += fabs((ts[i] - Text) / (T0 - Text) - thf);
            face->face_bias += (ts[i] - Text) / (T0 - Text) - thf;
            face->own_err += fabs(own - thf);
            face->depth_err += fabs(own - th);
            face->n++;
        }
        if (face->n) face->face_err /= face->n, face->own_err /= face->n, face->depth_err /= face->n, face->face_bias /= face->n;
        else rc = -1;
    }
    slab_series(Bi, 0, Fo, &th, &q);
    *err = worst;
    *taken = (robin_slab_sum_mT(s) - E0) / (M * (Text - T0));
    *taken_exact = q;
    hearth_scene_destroy(s);
    return rc;
}
#endif

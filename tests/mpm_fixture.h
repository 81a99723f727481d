/* mpm_fixture.h: small helpers for building scenes in the MPM tests. */
#ifndef HEARTH_MPM_FIXTURE_H
#define HEARTH_MPM_FIXTURE_H
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "hearth/hearth.h"
#include "mpm.h" /* scene.h, and the MPM phases some tests run one by one */
#include "test.h"

static inline hearth_scene *fx_scene(int dim, double dx, double lo, double hi) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dim = dim;
    d.dx = dx;
    for (int k = 0; k < 3; k++) {
        d.lo[k] = lo;
        d.hi[k] = hi;
    }
    hearth_error err;
    hearth_scene *s = hearth_scene_create(&d, &err);
    if (!s) fprintf(stderr, "scene: %s\n", err.msg);
    return s;
}

static inline hearth_scene *fx_scene_def(const hearth_scene_def *d) {
    hearth_error err;
    hearth_scene *s = hearth_scene_create(d, &err);
    if (!s) fprintf(stderr, "scene: %s\n", err.msg);
    return s;
}

/* The oven the heat and water tests bake pinned blocks in: a 100 x 60 mm box from the origin, no gravity, the
 * oven's air at oven_T (degC) through beta (W/(m^2 K)); the caller sets the rest (latent_heat, heat_implicit, ...). */
static inline hearth_scene_def fx_oven_def(double dx, double oven_T, double beta) {
    hearth_scene_def d = hearth_default_scene_def();
    d.dx = dx;
    d.gravity[1] = 0;
    d.lo[0] = d.lo[1] = 0;
    d.hi[0] = 0.1;
    d.hi[1] = 0.06;
    d.oven_temperature = oven_T;
    d.oven_beta = beta;
    return d;
}

/* A pinned box of material m centred at c with half sizes h, unjittered, at T0 (degC) and saturation sat (NaN:
 * the material's). Returns the body id, or -1 after printing why. */
static inline int fx_pinned_box(hearth_scene *s, int m, const double c[3], const double h[3], double T0, double sat) {
    hearth_shape *box = hearth_shape_box(c, h);
    hearth_body_def bd = hearth_default_body_def();
    bd.shape = box, bd.material = m, bd.jitter = 0, bd.fixed = 1;
    bd.temperature = T0, bd.saturation = sat;
    hearth_error err;
    const int id = hearth_scene_add_body(s, &bd, &err);
    if (id < 0) fprintf(stderr, "body: %s\n", err.msg);
    hearth_shape_free(box);
    return id;
}

/* The elastic material's stored energy over the scene, compressible neo-Hookean (plugins/elastic.c's law):
 * rotating_disc and the transfer's loss over dt read it. */
static inline double neo_hookean_energy(const hearth_scene *s, double mu, double lam) {
    double E = 0;
    for (int i = 0; i < s->ps.n; i++) {
        double F[9];
        particles_F3(&s->ps, i, F);
        double tr = 0;
        for (int a = 0; a < 9; a++) tr += F[a] * F[a];
        const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) + F[2] * (F[3] * F[7] - F[4] * F[6]);
        const double lj = log(J);
        E += pcold(&s->ps, PC_VOL0)[i] * (0.5 * mu * (tr - 3) - mu * lj + 0.5 * lam * lj * lj);
    }
    return E;
}

static inline int fx_elastic(hearth_scene *s, double E, double nu, double rho) {
    const char *n[] = {"E", "nu", "density"};
    const double v[] = {E, nu, rho};
    hearth_error err;
    int m = hearth_scene_add_material(s, "elastic", n, v, 3, &err);
    if (m < 0) fprintf(stderr, "material: %s\n", err.msg);
    return m;
}

/* Path of a test fixture plugin (tests/plugins), built next to the tests. */
static inline const char *fx_test_plugin(const char *name) {
    static char buf[4096];
    const char *dir = getenv("HEARTH_TEST_PLUGIN_DIR");
    snprintf(buf, sizeof buf, "%s/hearth_%s.so", dir ? dir : "tests/plugins", name);
    return buf;
}

static inline int fx_box(hearth_scene *s, int mat, const double c[3], const double h[3], int ppc, const double v[3]) {
    hearth_shape *b = hearth_shape_box(c, h);
    hearth_error err;
    int n = hearth_scene_seed_shape(s, mat, b, ppc, 0.0, v, &err);
    if (n < 0) fprintf(stderr, "seed: %s\n", err.msg);
    hearth_shape_free(b);
    return n;
}
/* A box collider of centre c and half sizes h in the given contact mode,
 * moving at vx along x; returns its id (-1 with the message on stderr). */
static inline int fx_box_collider(hearth_scene *s, const double c[3], const double h[3], hearth_contact mode, double vx) {
    hearth_shape *b = hearth_shape_box(c, h);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = b;
    cd.mode = mode;
    cd.velocity[0] = vx;
    hearth_error err;
    const int id = hearth_scene_add_collider(s, &cd, &err);
    if (id < 0) fprintf(stderr, "collider: %s\n", err.msg);
    hearth_shape_free(b);
    return id;
}
/* A body force (hearth_scene_set_body_force) of *ud m/s^2 along +y: 9.81 cancels gravity. */
static inline void fx_antigravity(void *ud, double t, const double x[3], double acc[3]) {
    (void)t;
    (void)x;
    acc[1] = *(const double *)ud;
}
#endif

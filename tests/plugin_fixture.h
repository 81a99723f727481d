/* plugin_fixture.h: what the material-plugin unit tests share: loading a
 * plugin by name through the public API, `hearth plugin check` with the
 * schema rules, a norm, and a seeded random source for trial states and
 * rotations. Include after test.h (it uses CHECK). A test file defines
 * PLUGIN_FIXTURE_SEED before including this, so each file keeps its own
 * fixed sequence of cases. */
#ifndef HEARTH_TESTS_PLUGIN_FIXTURE_H
#define HEARTH_TESTS_PLUGIN_FIXTURE_H
#include <math.h>
#include <stdint.h>
#include <stdio.h>

#include "hearth/hearth.h"
#include "hearth/material.h"
#include "tensor.h"

/* The plugin's material table, or NULL with the loader's message on stderr. */
static inline const hearth_material *load_material(const char *name) {
    hearth_error err = {0};
    const hearth_plugin *pl = hearth_plugin_load(name, &err);
    if (!pl) {
        fprintf(stderr, "%s\n", err.msg);
        return NULL;
    }
    return hearth_plugin_material(pl);
}

static inline void fixture_note(void *ud, const char *name, int passed, const char *detail) {
    (void)ud;
    printf("  %-20s %s  %s\n", name, passed ? "PASS" : "FAIL", detail);
}

/* `hearth plugin check` on the built plugin (each check printed), and its
 * schema: every parameter has a unit, a help line, and a default inside its
 * range. Returns the material for the caller's own checks, or NULL. */
static inline const hearth_material *check_built_plugin(const char *name) {
    hearth_error err = {0};
    const hearth_plugin *pl = hearth_plugin_load(name, &err);
    CHECK(pl != NULL);
    if (!pl) return NULL;
    CHECK(hearth_plugin_check(hearth_plugin_file(pl), fixture_note, NULL, &err) == 0);
    const hearth_material *m = hearth_plugin_material(pl);
    for (int i = 0; i < m->nparams; i++) {
        CHECK(m->params[i].unit && *m->params[i].unit);
        CHECK(m->params[i].help && *m->params[i].help);
        CHECK(m->params[i].min <= m->params[i].def && m->params[i].def <= m->params[i].max);
    }
    return m;
}

/* One step from rest (the plugin's init state) with F = f, so grad_v =
 * (f - I)/dt, at porosity n and temperature T (NAN: the field is off).
 * Returns the plugin's code; tau is NaN-filled first, so a plugin that
 * leaves it unwritten shows. */
static inline int step_from_rest(const hearth_material *m, const double *p, const double f[9], double dt, double n,
                                 double T, double *state, double tau[9]) {
    hearth_point pt;
    m->init(p, state);
    for (int i = 0; i < 9; i++) pt.grad_v[i] = (f[i] - (i % 4 == 0)) / dt, pt.F[i] = f[i];
    pt.dt = dt;
    pt.temperature = T;
    pt.porosity = n;
    pt.saturation = NAN;
    pt.p = p;
    pt.state = state;
    for (int i = 0; i < 9; i++) tau[i] = NAN;
    return m->stress(&pt, tau);
}

/* Lame parameters mu and lambda from Young's modulus E and Poisson's ratio nu. */
static inline void lame_from(double E, double nu, double *mu, double *lambda) {
    *mu = E / (2 * (1 + nu));
    *lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
}

/* Frobenius norm of a 3x3 tensor. */
static inline double norm9(const double *a) {
    double s = 0;
    for (int i = 0; i < 9; i++) s += a[i] * a[i];
    return sqrt(s);
}

/* xorshift64: uniform in [0, 1), the same sequence on every machine. */
static uint64_t rng = PLUGIN_FIXTURE_SEED;
static inline double uni(void) {
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1.0p-53;
}
static inline void random_rotation(double R[9]) {
    double u[3] = {uni(), uni(), uni()};
    t3_random_rotation(u, R);
}
#endif

/* plugin_fixture.h: what the material-plugin unit tests share: loading a
 * plugin by name through the public API, a norm, and a seeded random
 * source for trial states and rotations. A test file defines
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

/* nan_after.c: test fixture for the stability guard. A neo-Hookean solid
 * (as plugins/elastic.c) that counts its own advancing stress calls in its
 * one state slot and, once the count exceeds `after`, returns NaN stress
 * with status 0: a silent blow-up only the guard can catch. */
#include <hearth/material.h>
#include <math.h>

#include <hearth/tensor.h>

enum { P_E, P_NU, P_DENSITY, P_AFTER, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_E] = {"E", "Pa", "Young's modulus", 1e4, 1e-2, 1e12},
    [P_NU] = {"nu", "1", "Poisson's ratio", 0.3, 0, 0.499},
    [P_DENSITY] = {"density", "kg/m^3", "mass density", 1000, 1e-3, 1e5},
    [P_AFTER] = {"after", "1", "stress calls (dt > 0) before the stress turns NaN", 3, 0, 1e9},
};

static void init(const double *p, double *state) {
    (void)p;
    state[0] = 0;
}

static int stress(hearth_point *pt, double tau[9]) {
    if (pt->dt > 0) pt->state[0] += 1; /* dt == 0 only evaluates: not a step */
    if (pt->state[0] > pt->p[P_AFTER]) {
        for (int i = 0; i < 9; i++) tau[i] = NAN;
        return 0;
    }
    double J = hearth_t3_det(pt->F), b[9], mu, lambda;
    if (!(J > 0)) return 1;
    hearth_lame(pt->p[P_E], pt->p[P_NU], &mu, &lambda);
    hearth_t3_mul_abt(pt->F, pt->F, b);
    for (int i = 0; i < 9; i++) tau[i] = mu * (b[i] - (i % 4 == 0)) + (i % 4 == 0 ? lambda * log(J) : 0.0);
    return 0;
}

static double wave_speed(const double *p, const double *state) {
    (void)state;
    double mu, lambda;
    hearth_lame(p[P_E], p[P_NU], &mu, &lambda);
    return sqrt((lambda + 2 * mu) / p[P_DENSITY]);
}

static const char *describe_error(int code) {
    return code == 1 ? "inverted element (det F <= 0)" : "unknown error";
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "nan_after",
    .summary = "fixture: neo-Hookean that returns NaN stress after `after` steps",
    .params = params,
    .nparams = P_COUNT,
    .state_size = 1,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

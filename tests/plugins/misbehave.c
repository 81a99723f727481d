/* misbehave.c: test fixtures for isolation and the wave-speed checks. One
 * neo-Hookean solid (as plugins/elastic.c), compiled once per MISBEHAVE mode
 * (tests/plugins/meson.build), each failing in one way a real plugin might:
 *   segv_stress   dereferences NULL in stress (the first step that advances)
 *   abort_init    calls abort() in init
 *   hang_stress   loops forever in stress
 *   exit_stress   calls exit(0) in stress
 *   wave_nan, wave_inf, wave_zero, wave_neg
 *                 wave_speed is NaN, inf, 0 or negative when E is at its max
 *                 (a corner of the schema; fine at the defaults)
 *   wave_inf_after
 *                 wave_speed turns inf once stress has advanced `after` times
 *                 (the loader's corners are fine; only the run sees it)
 *   bulk_nan, bulk_neg, bulk_off
 *                 give the optional bulk_modulus (MISBEHAVE_BULK, set by
 *                 tests/plugins/meson.build): NaN, -1 Pa, or twice the law's
 *                 K = lambda + 2/3 mu, everywhere (a neo-Hookean never yields,
 *                 so `plugin check` must refuse all three)
 *   bulk_nan_after, bulk_neg_after
 *                 the law's K at a fresh state, NaN or -1 Pa once stress has
 *                 advanced `after` times: adding the material passes its
 *                 early K check (material.c), and only the run's guard sees it
 *   bulk_plastic  the right K, but no tensile strength: once J > 1 the mean
 *                 stress flows to 0 (only the deviatoric part stays) and
 *                 plastic_J reports J^P = J, so `plugin check` can only warn
 *                 that K was not checked under expansion */
#include <hearth/material.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include <hearth/tensor.h>

#define MODE_IS(x) (strcmp(MISBEHAVE, x) == 0)

enum { P_E, P_NU, P_DENSITY, P_AFTER, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_E] = {"E", "Pa", "Young's modulus", 1e4, 1e-2, 1e9},
    [P_NU] = {"nu", "1", "Poisson's ratio", 0.3, 0, 0.45},
    [P_DENSITY] = {"density", "kg/m^3", "mass density", 1000, 1, 1e5},
    [P_AFTER] = {"after", "1", "advancing stress calls before wave_inf_after misbehaves", 2, 0, 1e9},
};

static void init(const double *p, double *state) {
    (void)p;
    if (MODE_IS("abort_init")) abort();
    state[0] = 0;
}

/* volatile so the compiler keeps the faulting load and the endless loop */
static volatile int *volatile g_null;
static volatile int g_spin = 1;

/* The faulting load is the point of segv_stress: UndefinedBehaviorSanitizer
 * would stop the process at it before the signal that crash.c must name. */
static double fault(void) __attribute__((no_sanitize_undefined, noinline));
static double fault(void) { return *g_null; }

static int stress(hearth_point *pt, double tau[9]) {
    if (pt->dt > 0) {
        pt->state[0] += 1;
        if (MODE_IS("segv_stress")) tau[0] = fault();
        if (MODE_IS("hang_stress"))
            while (g_spin) {}
        if (MODE_IS("exit_stress")) exit(0);
    }
    double J = hearth_t3_det(pt->F), b[9], mu, lambda;
    if (!(J > 0)) return 1;
    hearth_lame(pt->p[P_E], pt->p[P_NU], &mu, &lambda);
    hearth_t3_mul_abt(pt->F, pt->F, b);
    for (int i = 0; i < 9; i++) tau[i] = mu * (b[i] - (i % 4 == 0)) + (i % 4 == 0 ? lambda * log(J) : 0.0);
    if (MODE_IS("bulk_plastic") && J > 1) { /* flowed: the mean stress is gone, J^P = J kept as -J */
        const double mean = (tau[0] + tau[4] + tau[8]) / 3;
        tau[0] -= mean, tau[4] -= mean, tau[8] -= mean;
        pt->state[0] = -J;
    }
    return 0;
}

static double wave_speed(const double *p, const double *state) {
    double mu, lambda;
    hearth_lame(p[P_E], p[P_NU], &mu, &lambda);
    const double c = sqrt((lambda + 2 * mu) / p[P_DENSITY]);
    if (p[P_E] >= params[P_E].max) {
        if (MODE_IS("wave_nan")) return NAN;
        if (MODE_IS("wave_inf")) return INFINITY;
        if (MODE_IS("wave_zero")) return 0;
        if (MODE_IS("wave_neg")) return -c;
    }
    if (MODE_IS("wave_inf_after") && state && state[0] > p[P_AFTER]) return INFINITY;
    return c;
}

#ifdef MISBEHAVE_BULK
static double bulk_modulus(const double *p, const double *state) {
    (void)state;
    double mu, lambda;
    hearth_lame(p[P_E], p[P_NU], &mu, &lambda);
    if (MODE_IS("bulk_nan")) return NAN;
    if (MODE_IS("bulk_neg")) return -1;
    const int late = state && state[0] > p[P_AFTER]; /* fine at a fresh state, so the material is added */
    if (MODE_IS("bulk_nan_after")) return late ? NAN : lambda + 2 * mu / 3;
    if (MODE_IS("bulk_neg_after")) return late ? -1 : lambda + 2 * mu / 3;
    if (MODE_IS("bulk_plastic")) return lambda + 2 * mu / 3;
    return 2 * (lambda + 2 * mu / 3); /* bulk_off */
}

static double plastic_J(const double *p, const double *state) {
    (void)p;
    return MODE_IS("bulk_plastic") && state && state[0] < 0 ? -state[0] : 1.0;
}
#endif

static const char *describe_error(int code) {
    return code == 1 ? "inverted element (det F <= 0)" : "unknown error";
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = MISBEHAVE,
    .summary = "fixture: a neo-Hookean solid that misbehaves (tests/plugins/misbehave.c)",
    .params = params,
    .nparams = P_COUNT,
    .state_size = 1,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
#ifdef MISBEHAVE_BULK
    .bulk_modulus = bulk_modulus,
    .plastic_J = plastic_J,
#endif
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

/* asym.c: test fixture. tau = k (F - I): zero at rest and finite, but not
 * symmetric under shear, so `hearth plugin check` must fail `symmetric`
 * (and the rest of the battery shows it is the only real defect besides
 * frame indifference, which F - I also breaks). */
#include <hearth/material.h>
#include <math.h>

enum { P_DENSITY, P_STIFFNESS, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_DENSITY] = {"density", "kg/m^3", "mass density", 1000, 1e-3, 1e5},
    [P_STIFFNESS] = {"stiffness", "Pa", "modulus k of tau = k (F - I)", 1e4, 1, 1e9},
};

static void init(const double *p, double *state) {
    (void)p;
    (void)state;
}

static int stress(hearth_point *pt, double tau[9]) {
    for (int i = 0; i < 9; i++) tau[i] = pt->p[P_STIFFNESS] * (pt->F[i] - (i % 4 == 0));
    return 0;
}

static double wave_speed(const double *p, const double *state) {
    (void)state;
    return sqrt(p[P_STIFFNESS] / p[P_DENSITY]);
}

static const char *describe_error(int code) {
    (void)code;
    return "unknown error";
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "asym",
    .summary = "fixture: non-symmetric stress",
    .params = params,
    .nparams = P_COUNT,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

/* err_code.c: test fixture for error reporting. Evaluating (dt == 0) gives
 * a linear elastic stress; every advancing step (dt > 0) fails with code 7,
 * as a plastic law whose return mapping did not converge would. */
#include <hearth/material.h>
#include <math.h>

enum { P_DENSITY, P_STIFFNESS, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_DENSITY] = {"density", "kg/m^3", "mass density", 1000, 1e-3, 1e5},
    [P_STIFFNESS] = {"stiffness", "Pa", "shear modulus of the evaluate-only response", 1e4, 1, 1e9},
};

static void init(const double *p, double *state) {
    (void)p;
    (void)state;
}

static int stress(hearth_point *pt, double tau[9]) {
    if (pt->dt > 0) return 7;
    const double *F = pt->F;
    double k = pt->p[P_STIFFNESS];
    /* small-strain 2 k sym(F - I): symmetric, zero at rest */
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) tau[3 * r + c] = k * (F[3 * r + c] + F[3 * c + r] - 2.0 * (r == c));
    return 0;
}

static double wave_speed(const double *p, const double *state) {
    (void)state;
    return sqrt(2 * p[P_STIFFNESS] / p[P_DENSITY]);
}

static const char *describe_error(int code) {
    return code == 7 ? "err_code test plugin: return mapping did not converge" : "unknown error";
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "err_code",
    .summary = "fixture: stress fails with code 7 on every step",
    .params = params,
    .nparams = P_COUNT,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

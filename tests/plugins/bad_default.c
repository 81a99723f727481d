/* bad_default.c: test fixture. The schema's "viscosity" defaults to 5 Pa s
 * but allows only [0, 1]; the loader must name the parameter, the default,
 * the range and the unit. */
#include <hearth/material.h>

static const hearth_param params[] = {
    {"density", "kg/m^3", "mass density", 1000, 1, 1e4},
    {"viscosity", "Pa s", "dynamic viscosity", 5, 0, 1},
};

static void init(const double *p, double *state) {
    (void)p;
    (void)state;
}
static int stress(hearth_point *pt, double tau[9]) {
    (void)pt;
    for (int i = 0; i < 9; i++) tau[i] = 0;
    return 0;
}
static double wave_speed(const double *p, const double *state) {
    (void)p;
    (void)state;
    return 1;
}
static const char *describe_error(int code) {
    (void)code;
    return "none";
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "bad_default",
    .summary = "fixture: default outside its range",
    .params = params,
    .nparams = 2,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

/* bad_abi.c: test fixture. A well-formed plugin that claims material ABI 99,
 * as if built against a future <hearth/material.h>; the loader must refuse
 * it before reading anything past real_size. */
#include <hearth/material.h>

static const hearth_param params[] = {{"density", "kg/m^3", "mass density", 1000, 1, 1e4}};

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
    .abi_version = 99,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "bad_abi",
    .summary = "fixture: wrong ABI version",
    .params = params,
    .nparams = 1,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

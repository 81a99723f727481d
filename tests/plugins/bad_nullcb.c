/* bad_nullcb.c: test fixture. Everything valid except the required stress
 * callback, which is NULL; the loader must name the missing callback. */
#include <hearth/material.h>

static const hearth_param params[] = {{"density", "kg/m^3", "mass density", 1000, 1, 1e4}};

static void init(const double *p, double *state) {
    (void)p;
    (void)state;
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
    .name = "bad_nullcb",
    .summary = "fixture: stress callback missing",
    .params = params,
    .nparams = 1,
    .init = init,
    .stress = 0, /* the defect under test */
    .wave_speed = wave_speed,
    .describe_error = describe_error,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

/* bad_reserved.c: test fixture. The schema declares "porosity", a name the
 * core reserves for its own per-material parameter (the initial gas porosity,
 * hearth_core_params). Accepting it would let the plugin's entry silently hide
 * the core's; the loader must refuse it, naming both and the reserved list. */
#include <hearth/material.h>

static const hearth_param params[] = {
    {"density", "kg/m^3", "mass density", 1000, 1, 1e4},
    {"porosity", "1", "the plugin's own idea of porosity", 0.2, 0, 0.9},
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
    .name = "bad_reserved",
    .summary = "fixture: a parameter named like a core parameter",
    .params = params,
    .nparams = 2,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

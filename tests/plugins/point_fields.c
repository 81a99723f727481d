/* point_fields.c: fixtures that report, through their stress's return
 * code, what the solver put in the point; one source, one plugin per
 * mode, chosen by -DPOINT_VISCOSITY, -DPOINT_POROSITY, -DPOINT_SATURATION or
 * -DPOINT_DIM with -DPOINT_NAME (tests/plugins/meson.build):
 *   point_viscosity   stress fails with code 1 when it sees a nonzero
 *                     `viscosity` parameter (SPH passes 0: material.h rule 3)
 *   point_porosity    needs the porosity; fails with code 2 when it is not
 *                     a number in [0, 1]
 *   point_saturation  needs the saturation (which SPH does not carry)
 *   point_dim         needs the dimension (<hearth/material.h> rule 8); its
 *                     stress, and its stress_block, fail with code 3 when the
 *                     point's dim is not the parameter `dim`
 * Otherwise the stress is zero: the body falls as dust, or as the SPH fluid
 * its Tait pressure makes it. */
#include <hearth/material.h>
#include <math.h>
#include <string.h> /* memset */

#if defined(POINT_VISCOSITY) + defined(POINT_POROSITY) + defined(POINT_SATURATION) + defined(POINT_DIM) != 1 || \
    !defined(POINT_NAME)
#error "build with one of -DPOINT_VISCOSITY, -DPOINT_POROSITY, -DPOINT_SATURATION, -DPOINT_DIM, and -DPOINT_NAME"
#endif
#if defined(POINT_POROSITY)
#define POINT_NEEDS HEARTH_NEEDS_POROSITY
#elif defined(POINT_SATURATION)
#define POINT_NEEDS HEARTH_NEEDS_SATURATION
#elif defined(POINT_DIM)
#define POINT_NEEDS HEARTH_NEEDS_DIM
#else
#define POINT_NEEDS 0u
#endif

enum { P_DENSITY, P_BULK, P_VISCOSITY, P_DIM, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_DENSITY] = {"density", "kg/m^3", "mass density", 1000, 1e-3, 1e5},
    [P_BULK] = {"bulk", "Pa", "sets the wave speed sqrt(bulk / density)", 1e4, 1, 1e9},
    [P_VISCOSITY] = {"viscosity", "Pa s", "never applied: point_viscosity checks what it is passed", 1, 0, 1e4},
    [P_DIM] = {"dim", "1", "point_dim: the dimension the points must report", 3, 2, 3},
};

static void init(const double *p, double *state) {
    (void)p;
    (void)state;
}

static int stress(hearth_point *pt, double tau[9]) {
    memset(tau, 0, 9 * sizeof(double));
    (void)pt;
#if defined(POINT_VISCOSITY)
    if (pt->dt > 0 && pt->p[P_VISCOSITY] != 0) return 1;
#elif defined(POINT_POROSITY)
    if (!(pt->porosity >= 0 && pt->porosity <= 1)) return 2;
#elif defined(POINT_DIM)
    if (pt->dim != (int)pt->p[P_DIM]) return 3;
#endif
    return 0;
}

#if defined(POINT_DIM)
static int stress_block(const hearth_block *b, double *const tau[9], int *code) {
    int bad = 0;
    for (int j = 0; j < b->n; j++) {
        for (int c = 0; c < 9; c++) tau[c][j] = 0;
        code[j] = b->dim != (int)hearth_block_param(b, P_DIM, j) ? 3 : 0;
        bad += code[j] != 0;
    }
    return bad;
}
#endif

static double wave_speed(const double *p, const double *state) {
    (void)state;
    return sqrt(p[P_BULK] / p[P_DENSITY]);
}

static const char *describe_error(int code) {
    return code == 1   ? "point_viscosity: the stress was passed a nonzero viscosity"
           : code == 2 ? "point_porosity: the porosity is not a number in [0, 1]"
           : code == 3 ? "point_dim: the point's dim is not the parameter dim"
                       : "unknown error";
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = POINT_NAME,
    .summary = "fixture: reports what the solver put in the point",
    .params = params,
    .nparams = P_COUNT,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
    .needs = POINT_NEEDS,
#if defined(POINT_DIM)
    .stress_block = stress_block,
#endif
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

/* newtonian.c: weakly compressible Newtonian fluid (water, thin syrups, oil).
 *
 * Kirchhoff stress tau = J (-p I + 2 eta dev(D)), D = sym(grad_v), with the
 * pressure p = -K ln J.
 *
 * Why p = -K ln J and not the alternatives:
 *   - K (1 - J) agrees to first order but stays finite as J -> 0, so a hard
 *     impact can crush a particle to zero volume;
 *   - Tait's equation (Rodriguez-Arenas eq. 3.17, gamma = 7) is stiffer in
 *     compression than in tension and needs an extra exponent parameter;
 *   - -K ln J is smooth, symmetric in compression and tension at small
 *     strain, and grows without bound as J -> 0.
 * "Weakly compressible" means K is chosen well below the real bulk modulus
 * (about 100x the largest squared flow speed times rho), trading a little
 * volume error for a much larger explicit time step.
 */
#include <hearth/material.h>
#include <math.h>

#include <hearth/tensor.h>

enum { P_DENSITY, P_BULK, P_VISCOSITY, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_DENSITY] = {"density", "kg/m^3", "mass density at rest", 1000, 1e-3, 1e5},
    [P_BULK] = {"bulk", "Pa", "bulk modulus K (sets the sound speed sqrt(K/rho))", 1e5, 1, 1e10},
    [P_VISCOSITY] = {"viscosity", "Pa s", "dynamic viscosity eta", 1e-3, 0, 1e6},
};

/* No state: J comes from the core's F, the rate from grad_v. */
static void init(const double *p, double *state) {
    (void)p;
    (void)state;
}

static int stress(hearth_point *pt, double tau[9]) {
    double J = hearth_t3_det(pt->F);
    if (!(J > 0)) return 1;
    const double *L = pt->grad_v;
    double K = pt->p[P_BULK], eta = pt->p[P_VISCOSITY];
    double p = -K * log(J);
    double trd = (L[0] + L[4] + L[8]) / 3;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            /* (L_rc + L_cr)/2 is bitwise symmetric, so tau is exactly symmetric. */
            double dev = 0.5 * (L[3 * r + c] + L[3 * c + r]) - (r == c ? trd : 0.0);
            tau[3 * r + c] = J * (2 * eta * dev - (r == c ? p : 0.0));
        }
    return 0;
}

/* Sound speed sqrt(K/rho). Viscosity adds no wave speed; its diffusive
 * step limit (dt < rho dx^2 / eta) is the solver's business, not the CFL's. */
static double wave_speed(const double *p, const double *state) {
    (void)state;
    return sqrt(p[P_BULK] / p[P_DENSITY]);
}

static const char *describe_error(int code) {
    return code == 1 ? "inverted element (det F <= 0)" : "unknown error";
}

/* The viscous stress is explicit in the velocity gradient: the core keeps
 * dt below rho dx^2 / (2 dim eta). */
static double viscosity(const double *p, const double *state) {
    (void)state;
    return p[P_VISCOSITY];
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "newtonian",
    .summary = "weakly compressible Newtonian fluid, p = -K ln J",
    .params = params,
    .nparams = P_COUNT,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
    .viscosity = viscosity,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void); /* for -Wmissing-prototypes */
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

/* maxwell_sph.c: the nonlinear (corotational) Maxwell stress-rate law of
 * Rodriguez-Arenas 2011, eq. 3.20-3.26 (after Mao and Yang), used there for
 * doughs in SPH. It is an ordinary ABI plugin, so the same law runs in MPM.
 *
 * ---- the law ---------------------------------------------------------------
 *   dS/dt = R + mu_e D' - S / lambda                                   (3.20)
 *   R     = 1/2 (S omega - omega S)                                    (3.21)
 *   omega^{ab} = dv^b/dx^a - dv^a/dx^b                                 (3.22-3.23)
 *   D     = grad v + grad v^T                                          (3.25-3.26)
 *   D'    = 1/2 D - tr(D)/c I                                          (3.24)
 * With L = grad_v (L_ij = dv_i/dx_j, hearth's convention), the thesis's
 * omega is L^T - L = -2 W with W = (L - L^T)/2 the spin, so
 * R = W S - S W: exactly the Jaumann (corotational) rate, which is what
 * makes the law frame indifferent. The thesis calls D' traceless; eq. 3.24
 * is traceless only for c = 2 d, and we take that: D' = dev(sym L), with
 * d = 3 always (2D scenes are plane strain: the zz rate is zero but the
 * deviator is still the 3D one).
 *
 * Zero-shear viscosity: in steady simple shear at rate g, sym L has xy = g/2,
 * so the steady linear solution is S_xy = mu_e lambda g / 2: eta0 =
 * mu_e lambda / 2 (the shear modulus is mu_e / 2). The corotational term
 * gives the steady shear stress eta0 g / (1 + (lambda g)^2).
 *
 * ---- integration over one step -----------------------------------------
 * Strang splitting, each part exact: half a step of rigid rotation
 * S <- Q S Q^T with Q = exp(W dt/2) (Rodrigues), a full step of the linear
 * part dS/dt = mu_e D' - S/lambda solved exactly
 *   S <- e^{-dt/lambda} S + mu_e lambda (1 - e^{-dt/lambda}) D',
 * and the second half rotation. Stable for any dt / lambda (a stiff
 * relaxation needs no sub-steps) and second order in dt.
 *
 * ---- volume ------------------------------------------------------------
 * S is the deviatoric (extra) stress. The law has no volume response, which
 * the SPH solver supplies with its own equation of state (Tait, eq. 3.17)
 * and therefore takes only the deviator of tau. MPM needs one from the
 * plugin: tau = J S + bulk/2 (J^2 - 1) I, the same volumetric term as the
 * sauce plugin.
 *
 * ---- viscosity (eq. 3.19, 4.1) ------------------------------------------
 * The thesis adds a Newtonian viscous force (eq. 3.19) next to the Maxwell
 * stress. Here it is the parameter `viscosity`, a dashpot in parallel:
 * tau gets + 2 J viscosity dev(sym L). The SPH solver knows this name and
 * applies it with the thesis's Laplacian form (eq. 3.19) instead, calling the
 * plugin with viscosity 0, so the two solvers see the same law.
 *
 * ---- temperature (eq. 4.2, 4.3) ----------------------------------------
 * mu_e (eq. 4.2) and the viscosity (eq. 4.1) are piecewise linear in T with
 * three points: give them as core temperature curves, h.curve{...}. The
 * relaxation time's arctan law (eq. 4.3) is not piecewise linear, so it is a
 * parameter mode: C_lambda > 0 replaces lambda by
 *   lambda(T) = C_lambda [2/pi arctan((T - 65)/2) + 1] + 2   (seconds),
 * and then needs the temperature field (error code E_NO_TEMPERATURE when the
 * scene has none). State: the six components of S (xx, yy, zz, xy, yz, zx). */
#include <hearth/material.h>
#include <hearth/tensor.h>
#include <math.h>
#include <string.h>

enum { P_MU_E, P_LAMBDA, P_C_LAMBDA, P_VISCOSITY, P_BULK, P_DENSITY, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_MU_E] = {"mu_e", "Pa", "elasticity constant of eq. 3.20 (shear modulus mu_e/2); eq. 4.2 as a temperature curve",
                1e3, 1e-3, 1e10},
    [P_LAMBDA] = {"lambda", "s", "relaxation time of eq. 3.20 (zero-shear viscosity mu_e lambda / 2)", 1.0, 1e-9,
                  1e9},
    [P_C_LAMBDA] = {"C_lambda", "s",
                    "0 = use lambda; > 0 = eq. 4.3 arctan law lambda(T) = C_lambda [2/pi atan((T-65)/2) + 1] + 2 "
                    "(needs temperature)",
                    0.0, 0.0, 1e9},
    [P_VISCOSITY] = {"viscosity", "Pa s",
                     "Newtonian viscosity in parallel (eq. 3.19, 4.1 as a curve); MPM adds 2 eta dev D, SPH applies eq. 3.19",
                     0.0, 0.0, 1e9},
    [P_BULK] = {"bulk", "Pa", "bulk modulus of the volume response (MPM; SPH uses its Tait pressure instead)", 1e5,
                1e-3, 1e12},
    [P_DENSITY] = {"density", "kg/m^3", "mass density at rest", 1000, 1e-3, 1e5},
};

enum { S_XX = HEARTH_SYM_XX, S_YY = HEARTH_SYM_YY, S_ZZ = HEARTH_SYM_ZZ, S_XY = HEARTH_SYM_XY, S_YZ = HEARTH_SYM_YZ,
       S_ZX = HEARTH_SYM_ZX, S_COUNT };
enum { E_INVERTED = 1, E_STEP, E_STATE, E_NO_TEMPERATURE };

static void init(const double *p, double *state) {
    (void)p;
    for (int i = 0; i < S_COUNT; i++) state[i] = 0;
}

/* Q = exp(t W) for antisymmetric W (Rodrigues): W = [w]_x with axis w. */
static void rotation(const double W[9], double t, double Q[9]) {
    double w[3] = {W[7] * t, W[2] * t, W[3] * t}; /* W = [[0,-wz,wy],[wz,0,-wx],[-wy,wx,0]] */
    double th = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    double K[9] = {0, -w[2], w[1], w[2], 0, -w[0], -w[1], w[0], 0};
    double a, b; /* sin(th)/th, (1 - cos th)/th^2 with series near 0 */
    if (th < 1e-4) {
        a = 1 - th * th / 6;
        b = 0.5 - th * th / 24;
    } else {
        a = sin(th) / th;
        b = (1 - cos(th)) / (th * th);
    }
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double K2 = K[3 * r] * K[c] + K[3 * r + 1] * K[3 + c] + K[3 * r + 2] * K[6 + c];
            Q[3 * r + c] = (r == c) + a * K[3 * r + c] + b * K2;
        }
}

static void rotate(const double Q[9], double S[9]) {
    double T[9], R[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) T[3 * r + c] = Q[3 * r] * S[c] + Q[3 * r + 1] * S[3 + c] + Q[3 * r + 2] * S[6 + c];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) R[3 * r + c] = T[3 * r] * Q[3 * c] + T[3 * r + 1] * Q[3 * c + 1] + T[3 * r + 2] * Q[3 * c + 2];
    memcpy(S, R, sizeof R);
}

/* Relaxation time: lambda, or eq. 4.3 when C_lambda > 0. */
static int relaxation_time(const double *p, double T, double *lambda) {
    if (p[P_C_LAMBDA] > 0) {
        if (!isfinite(T)) return E_NO_TEMPERATURE;
        *lambda = p[P_C_LAMBDA] * (0.63661977236758134 * atan((T - 65) / 2) + 1) + 2; /* eq. 4.3 */
    } else
        *lambda = p[P_LAMBDA];
    return 0;
}

static int stress(hearth_point *pt, double tau[9]) {
    const double *p = pt->p, *F = pt->F;
    double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
               F[2] * (F[3] * F[7] - F[4] * F[6]);
    if (!(J > 0) || !isfinite(J)) return E_INVERTED;
    for (int i = 0; i < S_COUNT; i++)
        if (!isfinite(pt->state[i])) return E_STATE;
    double S[9];
    hearth_sym_to_full(pt->state, S);
    if (pt->dt > 0) {
        const double *L = pt->grad_v;
        for (int i = 0; i < 9; i++)
            if (!isfinite(L[i])) return E_STEP;
        double lambda;
        int rc = relaxation_time(p, pt->temperature, &lambda);
        if (rc) return rc;
        double W[9], Dp[9], Q[9];
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) {
                W[3 * r + c] = 0.5 * (L[3 * r + c] - L[3 * c + r]);
                Dp[3 * r + c] = 0.5 * (L[3 * r + c] + L[3 * c + r]); /* 1/2 D, eq. 3.25 */
            }
        double tr = (Dp[0] + Dp[4] + Dp[8]) / 3;
        Dp[0] -= tr, Dp[4] -= tr, Dp[8] -= tr; /* eq. 3.24 with c = 2d: traceless */
        rotation(W, 0.5 * pt->dt, Q);
        rotate(Q, S);
        double e = exp(-pt->dt / lambda), g = p[P_MU_E] * lambda * -expm1(-pt->dt / lambda);
        for (int i = 0; i < 9; i++) S[i] = e * S[i] + g * Dp[i];
        rotate(Q, S);
        for (int i = 0; i < 9; i++)
            if (!isfinite(S[i])) return E_STATE;
        hearth_full_to_sym(S, pt->state);
        hearth_sym_to_full(pt->state, S); /* exactly symmetric */
    }
    double vol = 0.5 * p[P_BULK] * (J * J - 1);
    for (int i = 0; i < 9; i++) tau[i] = J * S[i] + (i % 4 == 0 ? vol : 0.0);
    if (p[P_VISCOSITY] > 0 && pt->dt > 0) { /* dt = 0 evaluates the elastic state only */
        const double *L = pt->grad_v, eta2 = 2 * J * p[P_VISCOSITY];
        double trd = (L[0] + L[4] + L[8]) / 3;
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++)
                tau[3 * r + c] += eta2 * (0.5 * (L[3 * r + c] + L[3 * c + r]) - (r == c ? trd : 0.0));
    }
    return 0;
}

/* P-wave speed sqrt((bulk + 4/3 G)/rho) with the shear modulus G = mu_e/2:
 * the instantaneous (elastic) response bounds the stiffness from above. */
static double wave_speed(const double *p, const double *state) {
    (void)state;
    return sqrt((p[P_BULK] + 4.0 / 3.0 * 0.5 * p[P_MU_E]) / p[P_DENSITY]);
}

/* The parallel dashpot is explicit in the velocity gradient: the core keeps
 * dt below rho dx^2 / (2 dim viscosity) (the Maxwell element itself is split
 * exactly and needs no limit). */
static double viscosity(const double *p, const double *state) {
    (void)state;
    return p[P_VISCOSITY];
}

static const char *describe_error(int code) {
    switch (code) {
    case E_INVERTED: return "inverted element (det F <= 0)";
    case E_STEP: return "velocity gradient is not finite";
    case E_STATE: return "Maxwell stress S is not finite";
    case E_NO_TEMPERATURE:
        return "C_lambda > 0 (eq. 4.3 arctan law) needs the temperature field: give the body a temperature or the "
               "scene an oven, or set C_lambda = 0";
    default: return "unknown error";
    }
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "maxwell_sph",
    .summary = "corotational Maxwell stress-rate law dS/dt = R + mu_e D' - S/lambda (Rodriguez-Arenas 2011, eq. 3.20)",
    .params = params,
    .nparams = P_COUNT,
    .state_size = S_COUNT,
    .needs = 0,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
    .viscosity = viscosity,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

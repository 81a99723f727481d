/* elastic.c: compressible neo-Hookean solid -- and the template for writing
 * a hearth material plugin. Copy this file, rename, change the physics.
 *
 * Build out of tree (the only headers you need are <hearth/material.h>, the
 * contract, and <hearth/tensor.h>, header-only 3x3 helpers):
 *
 *     cc -shared -fPIC $(pkg-config --cflags hearth) elastic.c -o hearth_elastic.so
 *
 * (log and sqrt need no -lm here: hearth itself links libm, so the symbols
 * are already in the process when the plugin is loaded.)
 *
 * The file name matters: a material called `foo` lives in hearth_foo.so.
 * Put it in a folder on $HEARTH_PLUGIN_PATH (or next to your scene), then
 * check it before trusting it in a scene:
 *
 *     hearth plugin check ./hearth_elastic.so
 *
 * <hearth/tensor.h> is all static inline (here for the Lame constants), so
 * the plugin links no helper library and the command above is all it takes.
 */
#include <hearth/material.h>
#include <hearth/tensor.h>
#include <math.h>

/* ---- parameters ----------------------------------------------------------
 * The schema: name, SI unit, one-line help, default, min, max. The core
 * validates user values against [min, max] and passes them to every callback
 * as p[] in this order, with temperature curves already evaluated. Every
 * plugin needs "density" (kg/m^3): the core gives particles mass from it. */
enum { P_E, P_NU, P_DENSITY, P_COUNT };

static const hearth_param params[P_COUNT] = {
    [P_E] = {"E", "Pa", "Young's modulus", 1e4, 1e-2, 1e12},
    /* Up to 0.499, not 0.5: lambda grows like 1/(1 - 2 nu). */
    [P_NU] = {"nu", "1", "Poisson's ratio", 0.3, 0.0, 0.499},
    [P_DENSITY] = {"density", "kg/m^3", "mass density at rest", 1000, 1e-3, 1e5},
};

/* ---- callbacks ------------------------------------------------------------ */

/* Called once per particle at rest (F = I), with its resolved parameters.
 * This material keeps no state of its own (state_size 0): the core already
 * carries the deformation gradient F, so there is nothing to set. A plugin
 * with state (plastic strain, a damage variable...) writes its rest values here. */
static void init(const double *p, double *state) {
    (void)p;
    (void)state;
}

/* The core calls this once per particle per step, in parallel, so it must
 * only touch pt and tau. pt holds (all 3x3 row-major, a[3*row + col]):
 *   pt->F       deformation gradient at the END of the step (already updated)
 *   pt->grad_v  velocity gradient over the step (1/s), for rate-dependent laws
 *   pt->dt      step (s); 0 means "evaluate only, do not advance state"
 *   pt->p       the parameters above; pt->state your state_size doubles
 *   pt->temperature etc.: NaN unless `needs` asks for them.
 *   pt->dim     2 or 3; 2 is plane strain (F[2] = F[5] = F[6] = F[7] = 0),
 *               which a law may use to skip zero terms (set HEARTH_NEEDS_DIM).
 * Write all nine entries of the Kirchhoff stress tau = J sigma (Pa), which
 * must be symmetric. Return 0, or a positive code that describe_error explains:
 * the core's guard stops the run and shows that text. */
static int stress(hearth_point *pt, double tau[9]) {
    const double *F = pt->F;
    double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
               F[2] * (F[3] * F[7] - F[4] * F[6]);
    if (!(J > 0)) return 1; /* ln J below would be NaN; let the guard say why */
    double mu, lambda;
    hearth_lame(pt->p[P_E], pt->p[P_NU], &mu, &lambda);
    /* tau = mu (F F^T - I) + lambda ln(J) I: zero at rest, symmetric by
     * construction, and objective because F F^T turns with the observer. */
    double vol = lambda * log(J);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double b = F[3 * r] * F[3 * c] + F[3 * r + 1] * F[3 * c + 1] + F[3 * r + 2] * F[3 * c + 2];
            tau[3 * r + c] = mu * (b - (r == c)) + (r == c ? vol : 0.0);
        }
    return 0;
}

/* Optional: the same stress for a block of points at once (<hearth/material.h>
 * rule 7), which the core calls instead of stress when it is there. The block
 * holds columns: entry c of point j's F is b->F[c][j]. It must give the same
 * bits as stress, point by point (`hearth plugin check` compares them), so
 * each point's arithmetic below is stress's, in the same order; what changes
 * is that the loops run across points, which the compiler vectorises (log is
 * a call, so it has a scalar loop of its own), and that the Lame constants of
 * parameters the whole block shares are computed once. A plugin that only
 * wants simplicity leaves this out. */
static int stress_block(const hearth_block *b, double *const tau[9], int *code) {
    const int n = b->n;
    const double *const *F = b->F;
    double J[HEARTH_BLOCK_MAX], vol[HEARTH_BLOCK_MAX], mu[HEARTH_BLOCK_MAX], lambda[HEARTH_BLOCK_MAX];
    /* A 2D point is plane strain (rule 8): F[2] = F[5] = F[6] = F[7] = 0, so
     * the 3x3 formula's terms in them are signed zeros, and adding a zero to
     * a nonzero sum changes no bit: the shorter 2D arithmetic below gives
     * stress's bits (`hearth plugin check` compares them on dim 2 blocks).
     * It saves 5 of the 9 products of b and most of det F in a 2D scene. */
    const int plane = b->dim == 2;
    if (plane)
        for (int j = 0; j < n; j++) J[j] = F[0][j] * (F[4][j] * F[8][j]) - F[1][j] * (F[3][j] * F[8][j]);
    else
        for (int j = 0; j < n; j++)
            J[j] = F[0][j] * (F[4][j] * F[8][j] - F[5][j] * F[7][j]) - F[1][j] * (F[3][j] * F[8][j] - F[5][j] * F[6][j]) +
                   F[2][j] * (F[3][j] * F[7][j] - F[4][j] * F[6][j]);
    if (!b->p_col[P_E] && !b->p_col[P_NU]) { /* uniform: once for the block */
        double m, l;
        hearth_lame(b->p[P_E], b->p[P_NU], &m, &l);
        for (int j = 0; j < n; j++) mu[j] = m, lambda[j] = l;
    } else {
        for (int j = 0; j < n; j++) hearth_lame(hearth_block_param(b, P_E, j), hearth_block_param(b, P_NU, j), &mu[j], &lambda[j]);
    }
    int bad = 0;
    for (int j = 0; j < n; j++) { /* scalar: log is a call */
        code[j] = !(J[j] > 0);
        bad += code[j];
        vol[j] = code[j] ? 0.0 : lambda[j] * log(J[j]);
    }
    /* tau = mu (F F^T - I) + lambda ln(J) I, as stress writes it (x + 0.0 included: it turns -0 into +0) */
    if (plane) { /* the in-plane block, tau_zz, and +0 for the out-of-plane shears (what the 3x3 loop gives) */
        const double *F0 = F[0], *F1 = F[1], *F3 = F[3], *F4 = F[4], *F8 = F[8];
        for (int j = 0; j < n; j++) tau[0][j] = mu[j] * ((F0[j] * F0[j] + F1[j] * F1[j]) - 1) + vol[j];
        for (int j = 0; j < n; j++) tau[1][j] = tau[3][j] = mu[j] * ((F0[j] * F3[j] + F1[j] * F4[j]) - 0) + 0.0;
        for (int j = 0; j < n; j++) tau[4][j] = mu[j] * ((F3[j] * F3[j] + F4[j] * F4[j]) - 1) + vol[j];
        for (int j = 0; j < n; j++) tau[8][j] = mu[j] * (F8[j] * F8[j] - 1) + vol[j];
        for (int j = 0; j < n; j++) tau[2][j] = tau[5][j] = tau[6][j] = tau[7][j] = 0.0;
        return bad;
    }
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            const double *Fr0 = F[3 * r], *Fr1 = F[3 * r + 1], *Fr2 = F[3 * r + 2];
            const double *Fc0 = F[3 * c], *Fc1 = F[3 * c + 1], *Fc2 = F[3 * c + 2];
            double *t = tau[3 * r + c];
            if (r == c)
                for (int j = 0; j < n; j++) t[j] = mu[j] * ((Fr0[j] * Fc0[j] + Fr1[j] * Fc1[j] + Fr2[j] * Fc2[j]) - 1) + vol[j];
            else
                for (int j = 0; j < n; j++) t[j] = mu[j] * ((Fr0[j] * Fc0[j] + Fr1[j] * Fc1[j] + Fr2[j] * Fc2[j]) - 0) + 0.0;
        }
    return bad;
}

/* Upper bound of the wave speed (m/s) for the CFL step limit: here the
 * small-strain P-wave speed sqrt((lambda + 2 mu) / rho). Underestimating it
 * makes the simulation blow up; `hearth plugin check` compares it with the
 * stiffness it measures. */
static double wave_speed(const double *p, const double *state) {
    (void)state;
    double mu, lambda;
    hearth_lame(p[P_E], p[P_NU], &mu, &lambda);
    return sqrt((lambda + 2 * mu) / p[P_DENSITY]);
}

/* Text for each code stress can return (static strings, shown to the user). */
static const char *describe_error(int code) {
    switch (code) {
    case 1: return "inverted element (det F <= 0)";
    default: return "unknown error";
    }
}

/* ---- the descriptor -------------------------------------------------------
 * Static, never freed. abi_version, struct_size and real_size let the loader
 * refuse a plugin built against another <hearth/material.h> or another float
 * width before touching anything else. Optional callbacks (blend, plastic_J,
 * viscosity, damage, stress_block) left out are NULL. */
static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "elastic", /* must match the file name hearth_<name>.so */
    .summary = "compressible neo-Hookean solid (template plugin)",
    .params = params,
    .nparams = P_COUNT,
    .state_size = 0,
    .needs = HEARTH_NEEDS_DIM, /* reads dim (stress_block's plane strain path); no temperature, porosity or saturation */
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
    .stress_block = stress_block, /* optional: leave it out and the core calls stress per point */
};

/* The one exported symbol. Declared before it is defined only to keep
 * -Wmissing-prototypes quiet. */
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void);
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

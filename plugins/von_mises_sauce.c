/* von_mises_sauce.c: sauces as an elastic Herschel-Bulkley material with von
 * Mises yield (Yue et al. 2015, as summarised in Nagasawa et al. 2019,
 * "Mixing Sauces", section 5), plus the paper's nonlinear blending model
 * (section 4.5, eq. 28-31) as the `blend` callback.
 *
 * ---- state: the isochoric elastic left Cauchy-Green tensor b̄^e ------------
 * Six doubles (xx, yy, zz, xy, yz, zx) of b̄^e = J^{-2/3} b^e, det b̄^e = 1.
 * Why b^e and not F^e:
 *   - the model is isotropic, so the stress (eq. 40) and the flow rule
 *     (L_v b^e = -2/3 tr(b^e) gamma_dot ŝ, section 5.3) are written in b^e;
 *     F^e would carry a rotation that nothing needs;
 *   - its update from grad_v alone (b^e_trial = f b^e f^T, or the linear
 *     form used below) is objective as it stands: no polar decomposition,
 *     no rotation bookkeeping;
 *   - it is symmetric: 6 doubles per particle instead of 9.
 * Why only the isochoric part: plastic flow is volume preserving
 * (det F^p = 1), so det b^e = J^2 with J = det F, and the core already
 * carries F. Taking J from pt->F and keeping det b̄^e = 1 means the
 * volume lives in one place and the two can never drift apart.
 *
 * ---- elasticity (eq. 39, 40) -------------------------------------------
 *   W = 1/2 kappa [1/2 (J^2 - 1) - ln J] + 1/2 mu (tr b̄^e - 3)       (39)
 *   tau = kappa/2 (J^2 - 1) I + mu dev(b̄^e)                         (40)
 *
 * ---- yield and flow (eq. 41, 42), and the shear calibration ------------
 * The paper writes, for s = |dev tau| (Frobenius norm),
 *   Phi(s) = s - sqrt(2/3) sigma_Y3                                   (41)
 *   gamma_dot = max(0, Phi / eta3)^(1/h)                              (42)
 * and the flow rule L_v b̄^e = -2/3 tr(b̄^e) gamma_dot ŝ. Taken literally
 * with Table 1's numbers, a simple shear test would give a steady shear
 * stress sigma_Y/sqrt(3) + 2^{-(1+h)/2} eta rate^h, not Table 1's own
 * Herschel-Bulkley law sigma = sigma_Y + eta rate^h (eq. 1), because Table 1
 * was fitted to rheometer (simple shear) data. This plugin's parameters
 * sigma_y and eta ARE the rheometer values (eq. 1, Table 1), and are mapped
 * onto the tensorial eq. 41-42 with the standard von Mises shear factors:
 *   sigma_Y3 = sqrt(3) sigma_y   so that sqrt(2/3) sigma_Y3 = sqrt(2) sigma_y
 *                                is the yield |dev tau| of a pure shear sigma_y,
 *   eta3 = 2^{(1+h)/2} eta       so that the steady simple-shear stress is
 *                                exactly sigma_y + eta rate^h (small elastic strain).
 * With this, sigma_y = 0 and h = 1 is a Maxwell fluid with viscosity eta and
 * relaxation time eta/mu (seed eq. 38), and mu -> infinity a Newtonian fluid
 * with viscosity eta (section 5.2).
 *
 * ---- the return map (Simo and Hughes 1998, box 9.1; Yue et al. 2015) ---
 * Per step, with L̄ = dev grad_v (the isochoric part: J comes from F):
 *   b̄_tr = b̄_n + dt (L̄ b̄_n + b̄_n L̄^T),  s_tr = mu dev(b̄_tr),
 *   mū = mu Ī, Ī = tr(b̄_n)/3.
 * This trial is the first-order form of f̄ b̄ f̄^T (f = I + dt grad_v,
 * f̄ = det(f)^{-1/3} f) without its dt^2 L̄ b̄ L̄^T term: together with the
 * implicit return below it is an IMEX Euler step whose fixed points are
 * exactly the continuous steady states, so the steady shear stress does not
 * depend on dt. With f̄ b̄ f̄^T the dt^2 term adds normal stress and lowers
 * the steady shear stress of a yield-dominated sauce by O(rate dt / elastic
 * strain) -- measured 0.1-0.35% at 100x the CFL step for sigma_y = 1e4 Pa,
 * enough to make the flow curve decrease with the rate. When the linear form
 * is not positive definite (a huge step on a strongly stretched state) the
 * step falls back to f̄ b̄ f̄^T, positive definite by construction.
 * If Phi(|s_tr|) > 0 the flow over the step is implicit (backward Euler):
 * with u = gamma_dot at the END of the step and Delta gamma = u dt,
 *   |s_{n+1}| = |s_tr| - 2 mū u dt   and   |s_{n+1}| = sqrt(2) sigma_y + eta3 u^h,
 * i.e. the scalar equation
 *   g(u) = eta3 u^h + 2 mū dt u - Phi_tr = 0.
 * It is solved in t = ln u, where g is a sum of two increasing convex
 * exponentials: Newton started from the upper end of the bracket
 *   u in [min(Phi/(2a), (Phi/(2 eta3))^{1/h}), min(Phi/a, (Phi/eta3)^{1/h})],
 *   a = 2 mū dt,
 * (each term alone must carry at least half of Phi, and neither more than
 * all of it) decreases monotonically to the root; a step that leaves the
 * bracket or is not finite is replaced by bisection. The bracket is at most
 * ln(2^{1/h}) wide, so any dt, any h in range and any eta converge in a few
 * iterations, and large dt stays stable (the update is implicit).
 * Then s_{n+1} = (sqrt(2) sigma_y + eta3 u^h) ŝ_tr (the viscous side, free of
 * the cancellation |s_tr| - 2 mū Delta gamma suffers when dt is large), and
 * b̄_{n+1} = x I + s_{n+1}/mu with x chosen so that det b̄_{n+1} = 1.
 * A step whose increment |dt grad_v| exceeds 0.05 is split into equal
 * sub-steps (see SUBSTEP_STRAIN).
 *
 * dt = 0 evaluates the stress of the stored state without advancing it.
 */
#include <hearth/material.h>
#include <math.h>
#include <string.h>

#include <hearth/tensor.h>

enum { P_KAPPA, P_MU, P_SIGMA_Y, P_ETA, P_H, P_DENSITY, P_COUNT };

/* Defaults: the moduli the paper assumed for every sauce (section 4.6) and
 * the Herschel-Bulkley triple of mayo (My, Table 1). */
static const hearth_param params[P_COUNT] = {
    [P_KAPPA] = {"kappa", "Pa", "bulk modulus (eq. 39); the paper uses 1e6 for every sauce", 1e6, 1, 1e12},
    [P_MU] = {"mu", "Pa", "shear modulus (eq. 39); the paper uses 1e5; large mu -> Newtonian", 1e5, 1e-2, 1e12},
    [P_SIGMA_Y] = {"sigma_y", "Pa", "yield stress in simple shear (Herschel-Bulkley, eq. 1; Table 1)", 70.8, 0, 1e8},
    [P_ETA] = {"eta", "Pa s^h", "consistency in simple shear (Herschel-Bulkley, eq. 1; Table 1)", 30.5, 1e-6, 1e8},
    [P_H] = {"h", "1", "flow index (eq. 1, 42): 1 Bingham, < 1 shear thinning", 0.442, 0.1, 1.1},
    [P_DENSITY] = {"density", "kg/m^3", "mass density at rest", 1000, 1e-3, 1e5},
};

enum { S_XX = HEARTH_SYM_XX, S_YY = HEARTH_SYM_YY, S_ZZ = HEARTH_SYM_ZZ, S_XY = HEARTH_SYM_XY, S_YZ = HEARTH_SYM_YZ,
       S_ZX = HEARTH_SYM_ZX, S_COUNT };

enum {
    E_INVERTED = 1, /* det F <= 0 */
    E_STEP = 2,     /* grad_v not finite, or det(I + dt/n grad_v) <= 0 */
    E_STATE = 3,    /* stored b̄^e is not positive definite or not finite */
    E_SOLVE = 4,    /* the flow-rate equation has no finite solution */
    E_BLEND_K = 10, E_BLEND_ALPHA = 11, E_BLEND_PARAM = 12
};

static const double SQRT2 = 1.41421356237309504880, LN2 = 0.69314718055994530942;

static double sym_det(const double *s) {
    return s[S_XX] * (s[S_YY] * s[S_ZZ] - s[S_YZ] * s[S_YZ]) - s[S_XY] * (s[S_XY] * s[S_ZZ] - s[S_YZ] * s[S_ZX]) +
           s[S_ZX] * (s[S_XY] * s[S_YZ] - s[S_YY] * s[S_ZX]);
}

/* Frobenius norm of the deviatoric part of a symmetric tensor. */
static double sym_dev_norm(const double *s) {
    double m = (s[S_XX] + s[S_YY] + s[S_ZZ]) / 3;
    double a = s[S_XX] - m, b = s[S_YY] - m, c = s[S_ZZ] - m;
    return sqrt(a * a + b * b + c * c + 2 * (s[S_XY] * s[S_XY] + s[S_YZ] * s[S_YZ] + s[S_ZX] * s[S_ZX]));
}

/* ---- the scalar flow-rate solve ------------------------------------------ */

/* Solve eta3 u^h + a u = phi (phi > 0, a > 0, eta3 > 0, 0 < h) for u > 0 in
 * t = ln u, safeguarded Newton (see the header comment). Returns u, or a
 * negative number when no finite root could be bracketed. The function of t,
 * divided by phi, is A(t) + B(t) - 1 with A = exp(le + h t - lp) and
 * B = exp(la + t - lp); working with logs keeps (phi/eta3)^{1/h} from
 * overflowing for small h. */
static double solve_rate(double phi, double a, double eta3, double h) {
    const double lp = log(phi), la = log(a), le = log(eta3);
    /* u_visc = (phi/eta3)^{1/h}: all of phi on the viscous side; u_el = phi/a: all on the elastic side. */
    const double tv = (lp - le) / h, te = lp - la;
    const double tv2 = (lp - LN2 - le) / h, te2 = lp - LN2 - la;
    double hi = fmin(tv, te), lo = fmin(tv2, te2);
    if (!isfinite(hi) || !isfinite(lo)) return -1;
    double t = hi;
    for (int it = 0; it < 200; it++) {
        double A = exp(le + h * t - lp), B = exp(la + t - lp);
        double g = A + B - 1, dg = h * A + B;
        if (g > 0) hi = t;
        else if (g < 0) lo = t;
        else return exp(t);
        double tn = t - g / dg;
        if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi); /* safeguard: bisection */
        if (fabs(tn - t) <= 1e-15 * fmax(1.0, fabs(t)) || hi - lo <= 1e-15 * fmax(1.0, fabs(t))) {
            t = tn;
            break;
        }
        t = tn;
    }
    return exp(t);
}

/* ---- callbacks ------------------------------------------------------------ */

static void init(const double *p, double *state) {
    (void)p;
    state[S_XX] = state[S_YY] = state[S_ZZ] = 1;
    state[S_XY] = state[S_YZ] = state[S_ZX] = 0;
}

static void kirchhoff(const double *p, double J, const double *bbar, double tau[9]) {
    double kappa = p[P_KAPPA], mu = p[P_MU];
    double vol = 0.5 * kappa * (J * J - 1); /* eq. 40, volumetric part */
    double m = (bbar[S_XX] + bbar[S_YY] + bbar[S_ZZ]) / 3;
    double B[9];
    hearth_sym_to_full(bbar, B);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) tau[3 * r + c] = mu * (B[3 * r + c] - (r == c ? m : 0.0)) + (r == c ? vol : 0.0);
}

/* Leading principal minors > 0 (Sylvester): the symmetric s is positive definite. */
static int sym_spd(const double *s) {
    return s[S_XX] > 0 && s[S_XX] * s[S_YY] - s[S_XY] * s[S_XY] > 0 && sym_det(s) > 0;
}

/* One return-mapped update of b̄ (6 doubles, in place) over dt with the
 * velocity gradient L (see the header comment). */
static int advance(const double *p, const double L[9], double dt, double *bs) {
    const double mu = p[P_MU], sy = p[P_SIGMA_Y], h = p[P_H];
    /* eta3 = 2^{(1+h)/2} eta: the shear calibration of eq. 42 (header). */
    const double eta3 = exp2(0.5 * (1 + h)) * p[P_ETA];

    /* Trial state, isochoric: with L̄ = dev L,
     *   b̄_tr = b̄ + dt (L̄ b̄ + b̄ L̄^T),
     * the explicit half of an IMEX Euler step whose implicit half is the
     * return map below. Its fixed points satisfy the continuous steady
     * equation L̄ b̄ + b̄ L̄^T = plastic flow exactly, so a steady flow's stress
     * does not depend on dt. (f̄ b̄ f̄^T, f̄ = det(f)^{-1/3} f, would add the
     * term dt^2 L̄ b̄ L̄^T, whose normal-stress excess lowers the steady shear
     * stress of a yield-dominated sauce by O(dt rate / elastic strain).) When
     * the linear form is not positive definite (a huge step on a strongly
     * stretched state) f̄ b̄ f̄^T, positive definite by construction, is used. */
    double Lb[9], B[9], LB[9], btr[S_COUNT];
    double tl = (L[0] + L[4] + L[8]) / 3;
    for (int i = 0; i < 9; i++) Lb[i] = L[i] - (i % 4 == 0 ? tl : 0.0);
    hearth_sym_to_full(bs, B);
    hearth_t3_mul(Lb, B, LB); /* L̄ b̄ + (L̄ b̄)^T = L̄ b̄ + b̄ L̄^T since b̄ is symmetric */
    btr[S_XX] = bs[S_XX] + dt * 2 * LB[0];
    btr[S_YY] = bs[S_YY] + dt * 2 * LB[4];
    btr[S_ZZ] = bs[S_ZZ] + dt * 2 * LB[8];
    btr[S_XY] = bs[S_XY] + dt * (LB[1] + LB[3]);
    btr[S_YZ] = bs[S_YZ] + dt * (LB[5] + LB[7]);
    btr[S_ZX] = bs[S_ZX] + dt * (LB[2] + LB[6]);
    if (!sym_spd(btr)) {
        double f[9], fB[9], Btr[9];
        for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + dt * L[i];
        double jf = hearth_t3_det(f);
        if (!(jf > 0) || !isfinite(jf)) return E_STEP;
        double sc = cbrt(jf);
        for (int i = 0; i < 9; i++) f[i] /= sc;
        hearth_t3_mul(f, B, fB);
        hearth_t3_mul_abt(fB, f, Btr);
        hearth_full_to_sym(Btr, btr);
    }

    /* mū = mu Ī with Ī = tr(b̄_n)/3 of the state the step starts from (the
     * flow rule's tr b^e, eq. above 42); with the trial's trace instead, the
     * steady flow rate would pick up an O(dt) factor 1 + dt tr(L̄ b̄ + b̄ L̄^T)/(3 Ī). */
    double Ibar = (bs[S_XX] + bs[S_YY] + bs[S_ZZ]) / 3;
    double mtr = (btr[S_XX] + btr[S_YY] + btr[S_ZZ]) / 3;
    if (!(Ibar > 0) || !isfinite(Ibar) || !isfinite(mtr)) return E_STATE;
    double snorm = mu * sym_dev_norm(btr); /* |s_tr| = |mu dev b̄_tr| */
    double phi = snorm - SQRT2 * sy;       /* eq. 41 with sqrt(2/3) sigma_Y3 = sqrt(2) sigma_y */
    double ratio = 1;                      /* s_{n+1} = ratio s_tr: the radial return */
    if (phi > 0 && snorm > 0) {
        double u = solve_rate(phi, 2 * mu * Ibar * dt, eta3, h);
        if (!(u >= 0) || !isfinite(u)) return E_SOLVE;
        /* |s_{n+1}| from the flow law at the solution (eq. 42 inverted), capped by |s_tr|. */
        ratio = fmin(snorm, SQRT2 * sy + eta3 * pow(u, h)) / snorm;
    }
    double D[S_COUNT]; /* dev b̄_{n+1} */
    D[S_XX] = ratio * (btr[S_XX] - mtr);
    D[S_YY] = ratio * (btr[S_YY] - mtr);
    D[S_ZZ] = ratio * (btr[S_ZZ] - mtr);
    D[S_XY] = ratio * btr[S_XY];
    D[S_YZ] = ratio * btr[S_YZ];
    D[S_ZX] = ratio * btr[S_ZX];
    /* det b̄ = 1 (the plastic flow is isochoric) through the isotropic part
     * only, so the deviator -- the stress -- is exactly what the return map
     * gave (Simo and Hughes 1998, box 9.1, remark): b̄_{n+1} = x I + D with
     * x the largest root of det(x I + D) = x^3 - (|D|^2/2) x + det D = 1. At
     * that root every x + d_i > 0, so b̄ stays positive definite. Newton from
     * x0 = 1 + |D| (where det >= 1) descends monotonically onto it (the cubic
     * is convex and increasing there). Scaling the whole tensor by
     * det^{-1/3} instead would shrink the deviator by an O(dt^2) factor every
     * step and bias a steady flow. */
    double nD2 = D[S_XX] * D[S_XX] + D[S_YY] * D[S_YY] + D[S_ZZ] * D[S_ZZ] +
                 2 * (D[S_XY] * D[S_XY] + D[S_YZ] * D[S_YZ] + D[S_ZX] * D[S_ZX]);
    double a = 0.5 * nD2, c = sym_det(D) - 1, x = 1 + sqrt(nD2);
    if (!isfinite(x)) return E_STATE;
    for (int it = 0; it < 100; it++) {
        double pv = x * x * x - a * x + c, dp = 3 * x * x - a;
        if (!(dp > 0)) break;
        double xn = x - pv / dp;
        if (!(xn < x)) break; /* converged: monotone descent has stopped */
        x = xn;
    }
    bs[S_XX] = x + D[S_XX];
    bs[S_YY] = x + D[S_YY];
    bs[S_ZZ] = x + D[S_ZZ];
    bs[S_XY] = D[S_XY];
    bs[S_YZ] = D[S_YZ];
    bs[S_ZX] = D[S_ZX];
    if (!sym_spd(bs)) return E_STATE;
    return 0;
}

/* Largest |dt grad_v| (Frobenius) of one sub-step. A step with a larger
 * increment is split into n equal sub-steps of dt/n with the same grad_v
 * (objective for any flow). This keeps the trial close to the state it
 * starts from, so the linear trial stays positive definite and a transient
 * (start-up, impact) is followed closely even at 100x the CFL step; steps of
 * an MPM scene under its CFL limit rarely need more than one. */
#define SUBSTEP_STRAIN 0.05
#define SUBSTEP_MAX 4096

static int stress(hearth_point *pt, double tau[9]) {
    const double *p = pt->p;
    double J = hearth_t3_det(pt->F);
    if (!(J > 0) || !isfinite(J)) return E_INVERTED;
    double *bs = pt->state;
    for (int i = 0; i < S_COUNT; i++)
        if (!isfinite(bs[i])) return E_STATE;
    if (pt->dt > 0) { /* dt = 0: evaluate only */
        const double *L = pt->grad_v;
        double gn = 0;
        for (int i = 0; i < 9; i++) gn += L[i] * L[i];
        gn = sqrt(gn) * pt->dt;
        if (!isfinite(gn)) return E_STEP;
        int n = gn > SUBSTEP_STRAIN ? (int)fmin(ceil(gn / SUBSTEP_STRAIN), SUBSTEP_MAX) : 1;
        double dts = pt->dt / n;
        double work[S_COUNT]; /* the state changes only when every sub-step succeeded */
        memcpy(work, bs, sizeof work);
        for (int k = 0; k < n; k++) {
            int rc = advance(p, L, dts, work);
            if (rc) return rc;
        }
        memcpy(bs, work, sizeof work);
    }
    kirchhoff(p, J, bs, tau);
    return 0;
}

/* Small-strain P-wave speed sqrt((kappa + 4/3 mu Ī)/rho): at rest Ī = 1 and
 * rho c^2 is exactly the uniaxial-strain modulus of eq. 40; a stretched
 * elastic state stiffens the shear part by Ī = tr(b̄^e)/3 >= 1. */
static double wave_speed(const double *p, const double *state) {
    double I = 1;
    if (state) {
        double t = (state[S_XX] + state[S_YY] + state[S_ZZ]) / 3;
        if (isfinite(t) && t > 1) I = t;
    }
    return sqrt((p[P_KAPPA] + 4.0 / 3.0 * p[P_MU] * I) / p[P_DENSITY]);
}

static const char *describe_error(int code) {
    switch (code) {
    case E_INVERTED: return "inverted element (det F <= 0)";
    case E_STEP: return "grad_v is not finite, or a sub-step inverts: det(I + dt/n grad_v) <= 0";
    case E_STATE: return "elastic state b^e is not finite or not positive definite";
    case E_SOLVE: return "the Herschel-Bulkley flow-rate equation (eq. 42) has no finite solution";
    case E_BLEND_K: return "blend: k must be at least 1";
    case E_BLEND_ALPHA: return "blend: mixing ratios must be finite, >= 0 and sum to a positive number";
    case E_BLEND_PARAM: return "blend: a constituent has a non-finite parameter, h outside [0.1, 1.1], eta <= 0 or sigma_y < 0";
    default: return "unknown error";
    }
}

/* ---- blending (section 4.5) -----------------------------------------------
 * Eq. 18: M_C = F^{-1}(sum_i alpha_i F(M_i)), with eq. 30
 *   F((h, eta, sigma_Y)) = (h^q, eta^{f(h)}, ln sigma_Y),
 * q = 1.4 (eq. 29, the absolute-error optimum the paper selects) and
 *   f(h) = 0.116 - 3.2 h + 2.7 h^2                                    (31)
 * so that
 *   h_M^q = sum alpha_i h_i^q                                         (29)
 *   eta_M^{f(h_M)} = sum alpha_i eta_i^{f(h_i)}                       (30)
 *   ln sigma_Y,M = sum alpha_i ln sigma_Y,i     (eq. 28 with p = 0, App. B)
 * and eq. 18's linear (identity-F) blend for kappa, mu and density, which
 * the paper does not blend (it uses the same moduli for every sauce, 4.6).
 *
 * f has roots at h = 0.0374 and 1.1478 and is negative between (f(1) =
 * -0.384, the Refutas exponent of eq. 23), so the schema's h range
 * [0.1, 1.1] keeps f(h) in [-0.832, -0.137], away from 0, and the eta
 * component invertible; h_M lies between the constituents' h.
 *
 * sigma_Y = 0 (a yield-free liquid) has no logarithm. It is floored at
 * SIGMA_Y_FLOOR = 1e-7 Pa inside the log: below every Table 1 value (the
 * smallest is honey's 4.06e-7 Pa) and of the size the paper's own fits
 * return for yield-free liquids, so such a constituent blends like the
 * paper's honey does. A blended value at or below the floor comes back as 0.
 *
 * Exactness: constituents with zero weight are dropped, so the zero law
 * (eq. 12, 13) returns the remaining set bitwise; a component on which all
 * remaining constituents agree is copied bitwise, so the identity law
 * (eq. 15) is exact; every weighted sum adds its terms in sorted order, so
 * the result does not depend on the order of the constituents (commutative
 * law, eq. 11) to the last bit. The associative law (eq. 14) holds to
 * rounding, because the blend is linear in F-space. The blended eta is
 * clamped to the schema range (only reachable at extreme combinations,
 * where associativity then holds only up to the clamp). */

#define BLEND_MAX 64
static const double BLEND_Q = 1.4;
static const double SIGMA_Y_FLOOR = 1e-7;

static double blend_f(double h) { return 0.116 - 3.2 * h + 2.7 * h * h; } /* eq. 31 */

static int cmp_double(const void *a, const void *b) {
    double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sum of n terms in ascending order: independent of the order given. */
static double sorted_sum(double *v, int n) {
    /* insertion sort: n <= BLEND_MAX and usually 2..8 */
    for (int i = 1; i < n; i++) {
        double x = v[i];
        int j = i - 1;
        while (j >= 0 && cmp_double(&v[j], &x) > 0) {
            v[j + 1] = v[j];
            j--;
        }
        v[j + 1] = x;
    }
    double s = 0;
    for (int i = 0; i < n; i++) s += v[i];
    return s;
}

static int blend(int k, const double *alpha, const double *const *pk, double *out) {
    if (k < 1 || k > BLEND_MAX) return E_BLEND_K;
    double tmp[BLEND_MAX], w[BLEND_MAX];
    const double *set[BLEND_MAX];
    for (int i = 0; i < k; i++) {
        if (!(alpha[i] >= 0) || !isfinite(alpha[i])) return E_BLEND_ALPHA;
        tmp[i] = alpha[i];
    }
    double total = sorted_sum(tmp, k);
    if (!(total > 0) || !isfinite(total)) return E_BLEND_ALPHA;
    int n = 0;
    for (int i = 0; i < k; i++)
        if (alpha[i] > 0) { /* the zero law: a constituent of zero mass has no effect (eq. 5) */
            const double *q = pk[i];
            for (int j = 0; j < P_COUNT; j++)
                if (!isfinite(q[j])) return E_BLEND_PARAM;
            if (!(q[P_H] >= params[P_H].min && q[P_H] <= params[P_H].max) || !(q[P_ETA] > 0) || !(q[P_SIGMA_Y] >= 0))
                return E_BLEND_PARAM;
            set[n] = q;
            w[n] = alpha[i] / total;
            n++;
        }
    if (n == 1) {
        memcpy(out, set[0], sizeof(double) * P_COUNT);
        return 0;
    }
    int same[P_COUNT];
    for (int j = 0; j < P_COUNT; j++) {
        same[j] = 1;
        for (int i = 1; i < n; i++)
            if (set[i][j] != set[0][j]) same[j] = 0;
    }
    /* linear components: kappa, mu, density */
    static const int lin[] = {P_KAPPA, P_MU, P_DENSITY};
    for (int l = 0; l < 3; l++) {
        int j = lin[l];
        if (same[j]) {
            out[j] = set[0][j];
            continue;
        }
        for (int i = 0; i < n; i++) tmp[i] = w[i] * set[i][j];
        double v = sorted_sum(tmp, n);
        out[j] = fmin(fmax(v, params[j].min), params[j].max);
    }
    /* h: eq. 29 */
    double hM;
    if (same[P_H]) hM = set[0][P_H];
    else {
        for (int i = 0; i < n; i++) tmp[i] = w[i] * pow(set[i][P_H], BLEND_Q);
        hM = pow(sorted_sum(tmp, n), 1 / BLEND_Q);
        hM = fmin(fmax(hM, params[P_H].min), params[P_H].max);
    }
    out[P_H] = hM;
    /* eta: eq. 30-31, eta^{f(h)} with each constituent's own h */
    if (same[P_ETA] && same[P_H]) out[P_ETA] = set[0][P_ETA];
    else {
        for (int i = 0; i < n; i++) tmp[i] = w[i] * exp(blend_f(set[i][P_H]) * log(set[i][P_ETA]));
        double S = sorted_sum(tmp, n);
        double eM = exp(log(S) / blend_f(hM));
        if (isnan(eM)) return E_BLEND_PARAM; /* +inf and 0 are clamped below */
        out[P_ETA] = fmin(fmax(eM, params[P_ETA].min), params[P_ETA].max);
    }
    /* sigma_Y: eq. 28 with p = 0 (multiplicative), with the documented floor */
    if (same[P_SIGMA_Y]) out[P_SIGMA_Y] = set[0][P_SIGMA_Y];
    else {
        for (int i = 0; i < n; i++) tmp[i] = w[i] * log(fmax(set[i][P_SIGMA_Y], SIGMA_Y_FLOOR));
        double s = exp(sorted_sum(tmp, n));
        out[P_SIGMA_Y] = s <= SIGMA_Y_FLOOR * (1 + 1e-12) ? 0.0 : fmin(s, params[P_SIGMA_Y].max);
    }
    return 0;
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = "von_mises_sauce",
    .summary = "sauce: elastic Herschel-Bulkley, von Mises yield (Yue et al. 2015); nonlinear blend (Nagasawa et al. 2019)",
    .params = params,
    .nparams = P_COUNT,
    .state_size = S_COUNT,
    .needs = 0,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .blend = blend,
    .describe_error = describe_error,
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void); /* for -Wmissing-prototypes */
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

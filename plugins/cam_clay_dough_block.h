/* cam_clay_dough_block.h: cam_clay_dough's batched callbacks, included once by
 * cam_clay_dough.c after the one-point law (stress_law and the scalars), whose
 * functions they use: a plugin is one translation unit, built as one file.
 * Moved out of cam_clay_dough.c by a move, not a rewrite, when the file passed
 * 1000 lines. */
#ifndef CAM_CLAY_DOUGH_BLOCK_H
#define CAM_CLAY_DOUGH_BLOCK_H

/* ---- the batched stress (<hearth/material.h> rule 7) ------------------------
 * A 2D (plane-strain) block's usual point is inside the surface: its step is
 * the trial, the one-rotation eigen-decomposition, three logs, the log-free
 * bound of return_map, J^P's exp and the rebuild of tau. That path runs
 * across the block's columns, each loop with no branch per point, so the
 * compiler can vectorise the arithmetic; the logs and the exp stay scalar
 * loops (a vector log would not give stress's bits). Every other point (3D,
 * a trial the bound does not clear, a porosity of 0 or NaN, any of
 * stress_law's error tests, out-of-plane shear) goes through stress_law
 * from its untouched state, as stress would. Each point's arithmetic is
 * stress_law's, in its order (the build does not contract into FMA), so a
 * block gives the same bits as stress point by point (`hearth plugin
 * check`). The loops vectorise only as this file is built
 * (plugins/meson.build): with -fno-math-errno (else each sqrt is a call
 * behind an errno test) and -fno-trapping-math (else GCC will not execute
 * eigen_plane's divisions and square roots, which it sinks under the
 * rotation test, for every lane); neither changes a value. Built without
 * them the results are the same, only slower (2D dough step 17.62M
 * against 18.44M instructions). Before it the dough shipped without a block: a loop through
 * stress_law cost more than it saved (2D dough step 20.86M against 20.02M
 * instructions), as each point moved between the columns and the law. */

/* log(x) through a point's memo (<hearth/material.h> rule 10): m[0] the last argument, m[1] its log. Between
 * the fields' updates a plane-strain point's b_zz does not move (f_zz = 1 + dt grad_v_zz, and the core's
 * thermal split leaves grad_v_zz at +0 while the temperature holds), so one of the block's three logs a
 * point has the argument of the step before: 47 instructions of libm's log, and the call, for a compare.
 * A cache keyed on the argument: called only with x > 0 finite (the fast path's test), where x == m[0]
 * holds only for the same bits, and a zeroed entry (m[0] = 0) misses; the value is log's own, whoever
 * wrote it. So any memo this function wrote, or zeros, gives log(x)'s bits. */
static inline double log_memo(double *m, double x) {
    if (m[0] == x) return m[1];
    const double l = log(x);
    m[0] = x, m[1] = l;
    return l;
}

/* Point j through stress_law, as stress would (F is read through J only). */
static int block_point(const hearth_block *b, int j, double J, double mu, double lambda, double *q, double *const tau[9]) {
    hearth_point pt;
    for (int c = 0; c < 9; c++) pt.grad_v[c] = b->grad_v[c][j];
    pt.p = q;
    pt.dt = b->dt;
    pt.state = b->state + (size_t)j * b->state_stride;
    pt.temperature = b->temperature ? b->temperature[j] : NAN;
    pt.porosity = b->porosity ? b->porosity[j] : NAN;
    pt.saturation = NAN;
    pt.dim = b->dim;
    double t[9];
    const int code = stress_law(&pt, J, mu, lambda, t);
    for (int c = 0; c < 9; c++) tau[c][j] = t[c];
    return code;
}

/* stress_block's last loop: the state of each fast point's elastic step (the trial b^E, J^P and the
 * damage), every other point through stress_law; returns the count of points whose code is not 0.
 * Always inlined with cracks and fast's nullness constants, so stress_block holds it three times:
 * with cracks 0 (no point's fracture_strain is > 0) the fracture tests and fracture_update fold
 * away, which GCC left in the loop as a run-time test (9 instructions a point); with fast NULL (no
 * point took the plane-strain path: 3D, among others) every point goes to stress_law without a
 * test, where a column of zeros cost its stores and a test a point. vk comes as a pointer to its
 * array, not to its first entry: its bound P_COUNT lets GCC unroll the copy of the varying
 * parameters, as it did while the loop was stress_block's own (through an int *, 3D 24 cells
 * 90.62M -> 90.76M a step). */
static inline __attribute__((always_inline)) int write_back(const hearth_block *b, int n, double *const tau[9], int *code,
                                                            const int cracks, const double *fast, const double *J,
                                                            const double *B0, const double *B1, const double *B4,
                                                            const double *B8, const double *EV, const double *E0,
                                                            const double *E1, const double *E2, const double *MU,
                                                            const double *LA, double *q, int (*vk)[P_COUNT], int nv) {
    const double *ef_c = b->p_col[P_FRACTURE_STRAIN], *fs_c = b->p_col[P_FRACTURE_STRETCH];
    double *const st = b->state;
    const int stride = b->state_stride;
    int bad = 0;
    for (int j = 0; j < n; j++) {
        double ef = 0;
        int stretch = 0;
        if (cracks) {
            ef = ef_c ? ef_c[j] : b->p[P_FRACTURE_STRAIN];
            /* the stretch rule (fracture_stretch = 1) reads the eigenvectors and grad_v: stress_law's path */
            stretch = ef > 0 && (fs_c ? fs_c[j] : b->p[P_FRACTURE_STRETCH]) > 0.5;
        }
        if (fast && fast[j] != 0 && !stretch) {
            double *s = st + (size_t)j * stride;
            s[S_XX] = B0[j], s[S_YY] = B4[j], s[S_ZZ] = B8[j];
            s[S_XY] = 0.5 * (B1[j] + B1[j]); /* hearth_full_to_sym's; S_YZ and S_ZX stay as they were */
            s[S_JP] = J[j] / exp(EV[j]);
            if (ef > 0) fracture_update(ef, s, fmax(E0[j], fmax(E1[j], E2[j])));
            code[j] = 0;
        } else {
            for (int v = 0; v < nv; v++) q[(*vk)[v]] = b->p_col[(*vk)[v]][j];
            code[j] = block_point(b, j, J[j], MU[j], LA[j], q, tau);
            bad += code[j] != 0;
        }
    }
    return bad;
}

static int stress_block(const hearth_block *b, double *const tau[9], int *code) {
    const int n = b->n;
    const double *const *F = b->F;
    double J[HEARTH_BLOCK_MAX], q[P_COUNT], MU[HEARTH_BLOCK_MAX], LA[HEARTH_BLOCK_MAX];
    for (int j = 0; j < n; j++)
        J[j] = F[0][j] * (F[4][j] * F[8][j] - F[5][j] * F[7][j]) - F[1][j] * (F[3][j] * F[8][j] - F[5][j] * F[6][j]) +
               F[2][j] * (F[3][j] * F[7][j] - F[4][j] * F[6][j]);
    int vk[P_COUNT], nv = 0; /* the parameters that vary by point (curves) */
    for (int k = 0; k < P_COUNT; k++) {
        q[k] = b->p[k];
        if (b->p_col[k]) vk[nv++] = k;
    }
    if (!b->p_col[P_E] && !b->p_col[P_NU]) { /* the Lame constants once for the block */
        double mu, lambda;
        hearth_lame(b->p[P_E], b->p[P_NU], &mu, &lambda);
        for (int j = 0; j < n; j++) MU[j] = mu, LA[j] = lambda;
    } else {
        const double *Ec = b->p_col[P_E], *Nc = b->p_col[P_NU];
        for (int j = 0; j < n; j++) hearth_lame(Ec ? Ec[j] : b->p[P_E], Nc ? Nc[j] : b->p[P_NU], &MU[j], &LA[j]);
    }
    const double dt = b->dt;
    const double *P = b->porosity;
    double *const st = b->state;
    const int stride = b->state_stride;
    /* fast[j]: 1 where point j takes the elastic plane-strain path below, 0 where it goes through
     * stress_law. A double, like the columns: a loop that mixes bytes with doubles does not vectorise.
     * A point the tests below send to stress_law needlessly only costs time (stress_law gives stress's
     * bits for any point), so a test may be stricter than stress_law's own, never looser. */
    double fast[HEARTH_BLOCK_MAX];
    double B0[HEARTH_BLOCK_MAX], B1[HEARTH_BLOCK_MAX], B4[HEARTH_BLOCK_MAX], B8[HEARTH_BLOCK_MAX];
    double L0[HEARTH_BLOCK_MAX], L1[HEARTH_BLOCK_MAX], QC[HEARTH_BLOCK_MAX], QS[HEARTH_BLOCK_MAX], QM[HEARTH_BLOCK_MAX];
    double E0[HEARTH_BLOCK_MAX], E1[HEARTH_BLOCK_MAX], E2[HEARTH_BLOCK_MAX], EV[HEARTH_BLOCK_MAX];
    if (b->dim == 2 && dt > 0 && P) {
        /* the state as columns (a strided gather: the one loop here that does not vectorise), and its
         * tests: every entry finite (their sum minus itself is 0: a NaN or an infinity makes it NaN, and a
         * finite state whose sum overflows only goes to stress_law) and no out-of-plane shear (is_plane:
         * a sum of |x| is 0 only when every x is +-0, NaN for a NaN) */
        double SXX[HEARTH_BLOCK_MAX], SYY[HEARTH_BLOCK_MAX], SZZ[HEARTH_BLOCK_MAX], SXY[HEARTH_BLOCK_MAX];
        double BAD[HEARTH_BLOCK_MAX];
        for (int j = 0; j < n; j++) {
            const double *s = st + (size_t)j * stride;
            double sum = 0;
            for (int i = 0; i < S_COUNT; i++) sum += s[i];
            SXX[j] = s[S_XX], SYY[j] = s[S_YY], SZZ[j] = s[S_ZZ], SXY[j] = s[S_XY];
            BAD[j] = (sum - sum) + (fabs(s[S_YZ]) + fabs(s[S_ZX]));
        }
        const double *g0 = b->grad_v[0], *g1 = b->grad_v[1], *g3 = b->grad_v[3], *g4 = b->grad_v[4], *g8 = b->grad_v[8];
        const double *g2 = b->grad_v[2], *g5 = b->grad_v[5], *g6 = b->grad_v[6], *g7 = b->grad_v[7];
        for (int j = 0; j < n; j++) { /* stress_law's tests, is_plane, trial_plane and eigen_plane, across the columns */
            const double nj = P[j];
            const double off = fabs(g2[j]) + fabs(g5[j]) + fabs(g6[j]) + fabs(g7[j]); /* is_plane's grad_v half */
            const double b0 = SXX[j], b1 = SXY[j], b4 = SYY[j];
            const double f0 = 1 + dt * g0[j], f1 = dt * g1[j], f3 = dt * g3[j], f4 = 1 + dt * g4[j], f8 = 1 + dt * g8[j];
            const double h0 = f0 * b0 + f1 * b1, h1 = f0 * b1 + f1 * b4;
            const double h3 = f3 * b0 + f4 * b1, h4 = f3 * b1 + f4 * b4;
            const double t0 = h0 * f0 + h1 * f1, t1 = h0 * f3 + h1 * f4, t4 = h3 * f3 + h4 * f4, t8 = SZZ[j] * (f8 * f8);
            const double jf = (f0 * f4 - f1 * f3) * f8;
            const double h = 0.5 * (t4 - t0), r = sqrt(h * h + t1 * t1), w = fabs(h) + r;
            const double sb = h >= 0 ? t1 : -t1, tb = sb * t1 / w;
            const double c = sqrt(w / (2 * r)), sn = sb / sqrt(2 * r * w);
            const int rot = t1 != 0;
            const double l0 = rot ? t0 - tb : t0, l1 = rot ? t4 + tb : t4;
            B0[j] = t0, B1[j] = t1, B4[j] = t4, B8[j] = t8;
            L0[j] = l0, L1[j] = l1;
            QC[j] = rot ? c : 1, QS[j] = rot ? sn : 0, QM[j] = rot ? -sn : 0; /* eigen_plane's Q (+0 off a rotation) */
            const double lsum = l0 + l1 + t8;
            /* x - x is 0 for a finite x, else NaN: J's, det f's and the eigenvalues' tests */
            const double z = BAD[j] + off + (J[j] - J[j]) + (jf - jf) + (lsum - lsum);
            /* J, det f, l0, l1 and t8 all > 0 as their least > 0: where one is NaN, z is NaN already (a select
             * that drops a NaN changes nothing), and a < b ? a : b is one vector min (two compares fewer a point) */
            const double m0 = J[j] < jf ? J[j] : jf, m1 = l0 < l1 ? l0 : l1, m2 = m0 < m1 ? m0 : m1, lo = m2 < t8 ? m2 : t8;
            fast[j] = (z == 0) & (lo > 0) & (nj > 0) & (nj < 1) ? 1.0 : 0.0;
        }
        double *const memo = b->memo;
        if (memo) { /* log b_zz through the point's memo (log_memo: rule 10) */
            const int ms = b->memo_stride;
            for (int j = 0; j < n; j++) /* the logs: scalar (libm) */
                if (fast[j] != 0)
                    E0[j] = 0.5 * log(L0[j]), E1[j] = 0.5 * log(L1[j]), E2[j] = 0.5 * log_memo(memo + (size_t)j * ms, B8[j]);
                else E0[j] = E1[j] = E2[j] = 0;
        } else
            for (int j = 0; j < n; j++) /* the logs: scalar (libm) */
                if (fast[j] != 0) E0[j] = 0.5 * log(L0[j]), E1[j] = 0.5 * log(L1[j]), E2[j] = 0.5 * log(B8[j]);
                else E0[j] = E1[j] = E2[j] = 0;
        double TY[HEARTH_BLOCK_MAX];
        const double *ty_c = b->p_col[P_TAU_Y];
        if (!ty_c) {
            for (int j = 0; j < n; j++) TY[j] = b->p[P_TAU_Y];
            ty_c = TY;
        }
        /* tau's in-plane entries into local columns, copied out after: the loop cannot know that the
         * block's columns do not alias (<hearth/material.h>), and would not vectorise */
        double T0[HEARTH_BLOCK_MAX], T1[HEARTH_BLOCK_MAX], T4[HEARTH_BLOCK_MAX], T8[HEARTH_BLOCK_MAX];
        for (int j = 0; j < n; j++) { /* the deviator, return_map's log-free bound, and tau of an elastic step */
            const double mu = MU[j], lambda = LA[j];
            const double ev = E0[j] + E1[j] + E2[j];
            const double e0 = E0[j] - ev / 3, e1 = E1[j] - ev / 3, e2 = E2[j] - ev / 3;
            double s2 = 0;
            s2 += e0 * e0;
            s2 += e1 * e1;
            s2 += e2 * e2;
            const double K = lambda + 2.0 / 3.0 * mu;
            const double pt = -K * ev, qt = 2 * mu * sqrt(1.5 * s2);
            const double ty = ty_c[j], ty2 = ty * ty;
            const double u = 1 - P[j], Mb = 9.0 * (1 + 1e-7) / (4.0 * u * u * (3.5 * P[j] + 1.0));
            fast[j] = Mb * pt * pt + qt * qt - ty2 > 0 ? 0.0 : fast[j];
            const double tv = lambda * ev;
            const double d0 = tv + 2 * mu * (ev / 3 + e0), d1 = tv + 2 * mu * (ev / 3 + e1);
            const double d2 = tv + 2 * mu * (ev / 3 + e2);
            const double qc = QC[j], qs = QS[j], qm = QM[j];
            T0[j] = qc * d0 * qc + qs * d1 * qs;
            T1[j] = qc * d0 * qm + qs * d1 * qc;
            T4[j] = qm * d0 * qm + qc * d1 * qc;
            T8[j] = d2;
            EV[j] = ev, E0[j] = e0, E1[j] = e1, E2[j] = e2; /* for J^P and the damage */
        }
        const size_t bytes = sizeof(double) * (size_t)n;
        memcpy(tau[0], T0, bytes), memcpy(tau[1], T1, bytes), memcpy(tau[3], T1, bytes);
        memcpy(tau[4], T4, bytes), memcpy(tau[8], T8, bytes);
        for (int c = 2; c < 8; c += c == 2 ? 3 : 1) memset(tau[c], 0, bytes); /* 2, 5, 6, 7 */
    } else /* no point takes the plane-strain path: every one goes through stress_law */
        return write_back(b, n, tau, code, 0, NULL, J, B0, B1, B4, B8, EV, E0, E1, E2, MU, LA, q, &vk, nv);
    /* where no point's fracture_strain is > 0, ef is 0 and the stretch rule off at every point */
    if (b->p_col[P_FRACTURE_STRAIN] || b->p[P_FRACTURE_STRAIN] > 0)
        return write_back(b, n, tau, code, 1, fast, J, B0, B1, B4, B8, EV, E0, E1, E2, MU, LA, q, &vk, nv);
    return write_back(b, n, tau, code, 0, fast, J, B0, B1, B4, B8, EV, E0, E1, E2, MU, LA, q, &vk, nv);
}

/* ---- the batched scalars (<hearth/material.h> rule 9) ------------------------
 * What the core asks per point around the stress (J^P and K before it; the
 * wave speed, J^P and the damage after), for the block in one call: each
 * column through the one-point function's own arithmetic (p_wave_speed,
 * p_bulk_modulus), so the same bits by construction (`hearth plugin check`
 * compares them). The wave speed's sqrt and divisions vectorise
 * (-fno-math-errno, plugins/meson.build); per point one-at-a-time they were
 * four indirect calls and the parameters patched in twice (the door,
 * core/sim/material_batch.c). */
static void scalars_block(const hearth_block *b, double *const out[HEARTH_SCALAR_COUNT]) {
    const int n = b->n, ss = b->state_stride;
    const double *st = b->state;
    double *w = out[HEARTH_SCALAR_WAVE_SPEED], *k = out[HEARTH_SCALAR_BULK_MODULUS];
    double *jp = out[HEARTH_SCALAR_PLASTIC_J], *d = out[HEARTH_SCALAR_DAMAGE];
    const double *Ec = b->p_col[P_E], *Nc = b->p_col[P_NU], *Rc = b->p_col[P_DENSITY];
    const double E0 = b->p[P_E], N0 = b->p[P_NU], R0 = b->p[P_DENSITY];
    if (w)
        for (int j = 0; j < n; j++) w[j] = p_wave_speed(Ec ? Ec[j] : E0, Nc ? Nc[j] : N0, Rc ? Rc[j] : R0);
    if (k)
        for (int j = 0; j < n; j++) k[j] = p_bulk_modulus(Ec ? Ec[j] : E0, Nc ? Nc[j] : N0);
    if (jp && st) { /* plastic_J: a strided gather, four points a turn (one load and one store each, the index
                     * and the test shared: 7 instructions a point as a loop of one) */
        const double *sj = st + S_JP;
        int j = 0;
        for (; j + 4 <= n; j += 4) {
            const double a0 = sj[(size_t)j * ss], a1 = sj[(size_t)(j + 1) * ss], a2 = sj[(size_t)(j + 2) * ss],
                         a3 = sj[(size_t)(j + 3) * ss];
            jp[j] = a0, jp[j + 1] = a1, jp[j + 2] = a2, jp[j + 3] = a3;
        }
        for (; j < n; j++) jp[j] = sj[(size_t)j * ss];
    } else if (jp)
        for (int j = 0; j < n; j++) jp[j] = 1.0;
    if (d)
        for (int j = 0; j < n; j++) /* damage */
            d[j] = st ? st[(size_t)j * ss + S_DAMAGE] : hearth_block_param(b, P_FRACTURE_STRAIN, j) > 0;
}
#endif

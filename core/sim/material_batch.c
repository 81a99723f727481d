/* material_batch.c: the batched door (material.h, material_run_eval): a run of
 * consecutive particles of one material, their stresses from the plugin's
 * stress_block in one call when it has one (<hearth/material.h> rule 7), else
 * point by point, then per point what MPM's P2G did after the stress: the wave
 * speed of the next step's limit, the viscosity, the core's coupling terms.
 *
 * Both paths give the same bits: the one-point path is material_point_stress
 * as P2G called it, and the block carries the same values in columns (the
 * parameters resolved by the same material_params_resolve, the porosity by
 * the same gas_porosity of the plugin's plastic_J). `hearth plugin check`
 * holds the plugin to its half (plugin_check.c), and the test
 * batch_scene_matches_one_point runs scenes both ways.
 *
 * The block's columns are a transpose of the particles' 3x3 rows: 18 loads
 * and stores a point, against the plugin's stress of 60 (elastic) to a few
 * hundred (cam_clay_dough) instructions, which the plugin may now vectorise. */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "exp_memo.h"
#include "material.h"

/* More distinct parameters with curves than this and the run goes point by
 * point (every in-tree use has one or two). */
#define RUN_MAX_VARYING 8

/* What P2G did after the plugin's stress, for one point: the next step's
 * wave speed, the viscosity, and the core's terms (the door's second half).
 * The limits come from the state the plugin just wrote and the parameters it
 * used: here both are in cache, and G2P need not evaluate the temperature
 * curves a second time. */
static inline void run_after(const material_slot *ms, hearth_point *pt, const material_env *env, double tau[9],
                             double *wave, double *numax) {
    const hearth_material *m = ms->m;
    double c = ms->wave_speed;
    if (ms->wave_per_point) {
        plugin_call_enter(m, "wave_speed");
        c = m->wave_speed(pt->p, pt->state);
    }
    *wave = c;
    if (m->viscosity) {
        plugin_call_enter(m, "viscosity");
        const double nu = m->viscosity(pt->p, m->state_size > 0 ? pt->state : NULL) / pt->p[ms->density_index];
        if (nu > *numax) *numax = nu;
    }
    double stiff; /* eq. 13 over the atmosphere: its stiffness in the wave speed (gas.h), 0 without */
    material_point_couple(m, ms->core, pt, env, tau, &stiff);
    *wave = material_gas_wave(*wave, stiff, env->J, pt->p[ms->density_index]);
}

static material_env run_env(const material_run *r, int j, unsigned flags) {
    return (material_env){
        .flags = flags,
        .J = r->J[j],
        .temperature = r->temperature ? r->temperature[j] : NAN,
        .saturation = r->saturation ? r->saturation[j] : NAN,
        .porosity = NAN,
        .gas = r->gas,
        .saturation0 = r->saturation0,
        .index = r->i0 + j,
        .dim = r->dim,
    };
}

/* out = x s (+ d, when d is not NULL), entry by entry: the thermal split's products on a column
 * (material_thermal_split's x * s, then + d). restrict: the block's scratch columns never overlap the
 * run's, and without it GCC checks the overlap at run time before each column's vector loop. */
static inline void scale_column(double *restrict out, const double *restrict x, const double *restrict s,
                                const double *restrict d, int n) {
    if (d)
        for (int j = 0; j < n; j++) out[j] = x[j] * s[j] + d[j];
    else
        for (int j = 0; j < n; j++) out[j] = x[j] * s[j];
}

/* scale_column on four columns at once (x * s), and on three with + d (the diagonal of L): the plane strain
 * block's products, each entry the same operation on the same values, in one pass over s (and d) */
static inline void scale_columns4(double *restrict o0, double *restrict o1, double *restrict o2, double *restrict o3,
                                  const double *restrict x0, const double *restrict x1, const double *restrict x2,
                                  const double *restrict x3, const double *restrict s, const double *restrict unused, int n) {
    (void)unused;
    for (int j = 0; j < n; j++) o0[j] = x0[j] * s[j], o1[j] = x1[j] * s[j], o2[j] = x2[j] * s[j], o3[j] = x3[j] * s[j];
}
static inline void scale_columns3(double *restrict o0, double *restrict o1, double *restrict o2, const double *restrict x0,
                                  const double *restrict x1, const double *restrict x2, const double *restrict s,
                                  const double *restrict d, int n) {
    for (int j = 0; j < n; j++) o0[j] = x0[j] * s[j] + d[j], o1[j] = x1[j] * s[j] + d[j], o2[j] = x2[j] * s[j] + d[j];
}

/* material_thermal_scales (material.h) over a block, given each point's K (its bulk_modulus, which the
 * caller asked point by point: K may read the state): split[j], the scales sF[j], sL[j] and dL[j], and
 * the strain stored in e_store[j] when dt > 0, each the value material_thermal_scales gives the point
 * alone, bit for bit (batch_scene_matches_one_point runs the one against the other). The arithmetic runs
 * over the columns, and libm only where its value is not known already: below |x| = 2^-54, exp(x) is
 * 1.0 and expm1(x) is x, correctly rounded, and glibc returns exactly these (1.0 + x, and x). r, the
 * step's change of the strain, is that small wherever the temperature did not move over the step (a
 * body's inside early in a bake): 44-57% of the points a step of scripts/bench/dough_step.lua's cookie
 * (2D, 64 cells). glibc's early return there is cheap already, so this saves about 9 instructions a
 * point over the per-point scalars (material_thermal_scales). A point the split leaves alone gets x = 0
 * and r = -0.0: 1, 1 and -0.0, as material_thermal_scales gives it. */
/* Returns THERMAL_NONFINITE when a scale is not finite (exp's: >= +0, inf or NaN), THERMAL_STILL when
 * every sL is 1.0 (no point's r took libm: the temperatures held over the step, as between the fields'
 * updates), where L's off-diagonal entries come through the split as they are (x * 1.0 is x), and
 * THERMAL_ALL_SPLIT when every split[j] is 1 (the caller's count of the others, 3 instructions a point over
 * split's bytes, is then 0 without it: the flag is picked from the compare the picks loop makes anyway). */
enum { THERMAL_NONFINITE = 1, THERMAL_STILL = 2, THERMAL_ALL_SPLIT = 4 };
__attribute__((noinline)) /* inlined, its arrays and loops cost the elastic step's door 2 instructions a point */
static int thermal_scales_block(const double *core, int n, const double *restrict K, const double *restrict T,
                                 double *restrict e_store, double *restrict memo, double dt, signed char *restrict split,
                                 double *restrict sF, double *restrict sL, double *restrict dL) {
    const double cl = core[CP_EXPANSION], Tr = core[CP_REFERENCE_T];
    double X[HEARTH_BLOCK_MAX], R[HEARTH_BLOCK_MAX];
    double all = 1.0; /* every split[j] 1: a flag picked, as the others below (a sum of doubles stays in order) */
    if (dt > 0) {
        /* the step's usual case in loops of doubles alone, every quotient taken and the values picked by selects,
         * so that they vectorise (split's bytes in the same loop, and the quotients under the tests, kept it
         * scalar: 25 instructions a point); split's bytes after, from the doubles */
        double SP[HEARTH_BLOCK_MAX], EQ[HEARTH_BLOCK_MAX], XQ[HEARTH_BLOCK_MAX], RQ[HEARTH_BLOCK_MAX], E0[HEARTH_BLOCK_MAX];
        for (int j = 0; j < n; j++) {
            const double k = K[j], t = T[j], e0 = e_store[j];
            /* material_thermal_scales' returns; one compare a select: two under one select became branches */
            const double k0 = k > 0 ? 1.0 : -1.0, k1 = k < INFINITY ? k0 : -1.0;
            const double e = cl * (t - Tr) / k;
            SP[j] = t == t ? k1 : 0.0;
            EQ[j] = e, XQ[j] = -e / 3, RQ[j] = (e0 - e) / 3, E0[j] = e0;
        }
        /* the picks, apart: with the quotients in the same loop GCC sinks them under the selects, and a select
         * that may keep an entry as it was is a conditional store, either of which keeps a loop scalar */
        for (int j = 0; j < n; j++) {
            const double sp = SP[j];
            X[j] = sp == 1.0 ? XQ[j] : 0.0;
            R[j] = sp == 1.0 ? RQ[j] : -0.0;
            e_store[j] = sp == 1.0 ? EQ[j] : E0[j];
            all = sp == 1.0 ? all : 0.0;
        }
        for (int j = 0; j < n; j++) split[j] = (signed char)SP[j];
    } else
        for (int j = 0; j < n; j++) {
            const double k = K[j], t = T[j], e0 = e_store[j];
            const int sp = !(t == t) ? 0 : (k > 0) & (k < INFINITY) ? 1 : -1; /* material_thermal_scales' returns */
            split[j] = (signed char)sp;
            X[j] = sp == 1 ? -e0 / 3 : 0.0; /* dt = 0: the stored strain, nothing written */
            R[j] = -0.0;
        }
    /* x holds between the fields' updates (the temperature does, and K with it): its exp once a cycle (exp_memo.h);
     * the scales' finiteness counted in the loops that make them (a loop of its own over sF and sL cost 10
     * instructions a point) */
    long inf = 0, moved = 0;
    if (memo) {
        /* the memo's hits (exp_memo's test, m[0] == x and m[1] != 0) read in a loop of selects that vectorises,
         * every point between the fields' updates; then exp_memo itself only where one missed (7 instructions a
         * point as a loop of calls) */
        double miss = 0, infd = 0;
        for (int j = 0; j < n; j++) {
            const double x = X[j], k = memo[2 * j], v = memo[2 * j + 1];
            const double small = fabs(x) < 0x1p-54 ? 1.0 : 0.0, hit = k == x && v != 0 ? 1.0 : 0.0;
            const double f = small == 1.0 ? 1.0 : hit == 1.0 ? v : 0.0;
            sF[j] = f;
            miss = small == 1.0 || hit == 1.0 ? miss : 1.0; /* flags picked, not summed: a sum of doubles */
            infd = f <= DBL_MAX ? infd : 1.0;                /* stays in order, one scalar add a point */
        }
        inf += infd > 0;
        for (int j = 0; j < n && miss > 0; j++)
            if (!(fabs(X[j]) < 0x1p-54) && !(memo[2 * j] == X[j] && memo[2 * j + 1] != 0)) {
                sF[j] = exp_memo(memo + 2 * j, X[j]);
                inf += !(sF[j] <= DBL_MAX);
            }
    } else
        for (int j = 0; j < n; j++) {
            sF[j] = fabs(X[j]) < 0x1p-54 ? 1.0 : exp(X[j]);
            inf += !(sF[j] <= DBL_MAX);
        }
    if (dt > 0) {
        /* every point's small-r values first, in a loop with no branch (one vector division), then libm where
         * r is not small: the values the branch per point gave, which was 11 instructions a point */
        /* big: the points whose r is not small, none between the fields' updates, where the scan below is
         * skipped; a flag in a double, picked (a long counted beside the doubles kept the loop scalar, and a
         * double summed stays in order) */
        double big = 0;
        for (int j = 0; j < n; j++) {
            sL[j] = 1.0, dL[j] = R[j] / dt;
            big = fabs(R[j]) < 0x1p-54 ? big : 1.0;
        }
        for (int j = 0; j < n && big > 0; j++) {
            const double r = R[j];
            if (!(fabs(r) < 0x1p-54)) {
                sL[j] = exp(r), dL[j] = expm1(r) / dt;
                inf += !(sL[j] <= DBL_MAX);
                moved++;
            }
        }
    } else {
        for (int j = 0; j < n; j++) sL[j] = 1.0, dL[j] = -0.0;
        all = 0.0; /* dt = 0 (no step's strain: a rare call): the caller counts */
    }
    return (inf ? THERMAL_NONFINITE : 0) | (moved ? 0 : THERMAL_STILL) | (all == 1.0 ? THERMAL_ALL_SPLIT : 0);
}

/* The particles' thermal strain column when eq. 10 is a strain for this run
 * (material.h, material_thermal_split), else NULL: the pressure is added. */
static double *thermal_column(const material_slot *ms, const particles *ps, const material_run *r, unsigned flags) {
    if (!(flags & MATERIAL_EXPANSION) || !(ms->core[CP_EXPANSION] > 0) || !ms->m->bulk_modulus || !r->temperature ||
        !(ps->enabled & (1u << PC_THERMAL)))
        return NULL;
    return pcold(ps, PC_THERMAL);
}

/* A run's parameters (material.h, material_run_params): material_params_resolve's
 * values and bits, without its per-point copy of every parameter. The uniform
 * ones are copied once per run and each point rewrites only the parameters
 * its curves move, in material_params_resolve's order (the temperature
 * curve's value, then times its parameter's moisture factor;
 * material_curve_check allows one curve of each kind per parameter). The
 * moisture ratio is computed once per point, not once per curve, and the
 * factors only when the ratios differ from the last point's: without a
 * water field every ratio is 1 (material_moisture_ratio), so they are
 * evaluated once per run. For the cookie dough's five curves resolving was
 * 1.75M of a 20.0M-instruction step (2D, 64 cells). */
void material_run_params_init(material_run_params *rp, const material_slot *ms, const particles *ps) {
    const int nc = ms->ncurves;
    memcpy(rp->q, ms->params, sizeof(double) * (size_t)ms->m->nparams);
    int nt = 0;
    while (nt < nc && ms->curves[nt].of == CURVE_OF_TEMPERATURE) nt++;
    rp->nt = nt;
    rp->T = pcold(ps, PC_TEMPERATURE);
    rp->Tmax = pcold(ps, PC_TEMP_MAX);
    rp->dried = ps->enabled & (1u << PC_DRIED) ? pcold(ps, PC_DRIED) : NULL;
    rp->r = rp->rd = NAN; /* no ratio equals it: the first point evaluates */
    for (int k = nt; k < nc; k++) {
        rp->mp[k - nt] = 0;
        for (int t = 0; t < nt; t++) rp->mp[k - nt] |= ms->curves[t].param == ms->curves[k].param;
    }
}

/* Point i's moisture ratio (*r) and, returned, the ratio its irreversible
 * curves read: the lower of r and 1 - dried. fmin's value without the call
 * where it is r's bits: r below, or equal and not a zero. */
static inline double moisture_ratios(const material_run_params *rp, const material_slot *ms, const particles *ps, int i,
                                     double *r) {
    *r = material_moisture_ratio(ms, ps, i);
    const double d = rp->dried ? 1.0 - rp->dried[i] : *r;
    return *r <= d && *r != 0 ? *r : fmin(*r, d);
}

const double *material_run_params_at(material_run_params *rp, const material_slot *ms, const particles *ps, int i) {
    const int nt = rp->nt, nc = ms->ncurves;
    double *q = rp->q;
    for (int t = 0; t < nt; t++) {
        const curve *c = &ms->curves[t];
        q[c->param] = curve_eval(c, c->irreversible ? rp->Tmax[i] : rp->T[i]);
    }
    if (nt < nc) {
        double r;
        const double rd = moisture_ratios(rp, ms, ps, i, &r);
        const int fresh = !(r == rp->r && rd == rp->rd);
        rp->r = r, rp->rd = rd;
        for (int k = nt; k < nc; k++) {
            /* a parameter with no temperature curve keeps the last point's value when the
             * factors stand: only this loop writes it (one moisture curve a parameter) */
            if (!fresh && !rp->mp[k - nt]) continue;
            const curve *c = &ms->curves[k];
            if (fresh) rp->f[k - nt] = curve_eval(c, c->irreversible ? rd : r);
            if (!rp->mp[k - nt]) q[c->param] = ms->params[c->param];
            q[c->param] *= rp->f[k - nt];
        }
    }
    return q;
}

/* Same bits: x and y are one double (curve_eval is a function of its argument's bits, -0.0 and NaNs included). */
static inline int same_bits(double x, double y) {
    uint64_t a, b;
    memcpy(&a, &x, sizeof a);
    memcpy(&b, &y, sizeof b);
    return a == b;
}

/* The first temperature curves' columns (up to CURVE_MEMO_WIDTH - 3 of them) through the particles' curve memo
 * (PC_CURVE_MEMO): between the fields' updates a particle's T and T_max hold (field_clock.c), so its curves
 * give the values of the step before, which the memo keeps with their key (the slot's curve stamp, T and
 * T_max, bit for bit); a point whose key differs evaluates the curves (curve_eval: curve_eval_column's values)
 * and writes its entry. A cache keyed on everything the values are a function of, as exp_memo.h's: nothing
 * invalidates it (a field step, a held body, a restore, the sort, a curve added: a new stamp), and it is
 * neither hashed nor saved. Returns how many curves it gave (0: the material has no temperature curve).
 * In the 2D dough bench (scripts/bench/dough_step.lua) the cookie's two curves cost 55 instructions a point
 * a step through curve_eval_column. */
enum { CURVE_MEMO_VALUES = CURVE_MEMO_WIDTH - 3 };
static inline __attribute__((always_inline)) void curve_memo_loop(const material_slot *ms, const material_run_params *rp,
                                                                  double *memo, int i0, int n, int nm,
                                                                  double *const col[CURVE_MEMO_VALUES], int byT,
                                                                  int byTmax) {
    const double stamp = ms->curve_stamp, *T = rp->T + i0, *Tmax = rp->Tmax + i0;
    double *m = memo + (size_t)i0 * CURVE_MEMO_WIDTH;
    for (int j = 0; j < n; j++, m += CURVE_MEMO_WIDTH) {
        const double t = T[j], tm = Tmax[j];
        /* a key the memo's curves do not read need not match: their values do not depend on it */
        if (__builtin_expect(m[0] == stamp && (!byT || same_bits(m[1], t)) && (!byTmax || same_bits(m[2], tm)), 1)) {
            for (int k = 0; k < nm; k++) col[k][j] = m[3 + k];
            continue;
        }
        m[0] = stamp, m[1] = t, m[2] = tm;
        for (int k = 0; k < nm; k++) {
            const curve *c = &ms->curves[k];
            col[k][j] = m[3 + k] = curve_eval(c, c->irreversible ? tm : t);
        }
    }
}

static int curve_memo_columns(const material_slot *ms, const material_run_params *rp, double *memo, int i0, int n,
                              const int *col_of, double (*vcol)[HEARTH_BLOCK_MAX]) {
    const int nm = rp->nt < CURVE_MEMO_VALUES ? rp->nt : CURVE_MEMO_VALUES;
    double *col[CURVE_MEMO_VALUES] = {0};
    for (int t = 0; t < nm; t++) col[t] = vcol[col_of[ms->curves[t].param]];
    /* the loop for the usual count, the memo's full two, with its copies unrolled (22 instructions a point
     * through the general loop) */
    int byT = 0, byTmax = 0; /* which of the key's temperatures the memo's curves read */
    for (int t = 0; t < nm; t++) byTmax |= ms->curves[t].irreversible, byT |= !ms->curves[t].irreversible;
    if (nm == CURVE_MEMO_VALUES && !byT) curve_memo_loop(ms, rp, memo, i0, n, CURVE_MEMO_VALUES, col, 0, 1); /* Fig. 8's */
    else if (nm == CURVE_MEMO_VALUES) curve_memo_loop(ms, rp, memo, i0, n, CURVE_MEMO_VALUES, col, byT, byTmax);
    else if (nm > 0) curve_memo_loop(ms, rp, memo, i0, n, nm, col, byT, byTmax);
    return nm;
}

/* Column v as the uniform value it stands for (run_params_columns), where it is still uniform and so unwritten. */
static inline void uniform_fill(double (*vcol)[HEARTH_BLOCK_MAX], const unsigned char *uniform, int v, const material_slot *ms,
                                const int *vk, int n) {
    if (uniform[v])
        for (int j = 0; j < n; j++) vcol[v][j] = ms->params[vk[v]];
}

/* The varying parameters of points i0 .. i0 + n - 1 as columns (vcol[v] for
 * parameter vk[v]): the values material_run_params_at gives point by point, to
 * the bit, computed curve by curve over the block. A parameter's value is its
 * temperature curve's (or its uniform value), times its moisture curve's
 * factor; the factors are evaluated again only where material_run_params_at
 * would (the ratios differ from the last point's), so they are its values. */
static void run_params_columns(material_run_params *rp, const material_slot *ms, const particles *ps, int i0, int n,
                               int nv, const int *vk, double (*vcol)[HEARTH_BLOCK_MAX], unsigned char *uniform) {
    const int nt = rp->nt, nc = ms->ncurves;
    int col_of[MATERIAL_MAX_PARAMS];
    unsigned char by_T[RUN_MAX_VARYING] = {0}; /* column v is a temperature curve's (written whole below) */
    for (int v = 0; v < nv; v++) col_of[vk[v]] = v;
    for (int t = 0; t < nt; t++) by_T[col_of[ms->curves[t].param]] = 1;
    /* uniform[v]: column v stands for ms->params[vk[v]] at every point (no temperature curve, and its moisture
     * factors left it unmultiplied). Such a column is left unwritten (the caller hands the value itself to the
     * plugin, and fills it with uniform_fill where a per-point path reads it): written by uniform_fill just
     * before a factor multiplies it (3 instructions a point for every uniform column, the cookie's E) */
    for (int v = 0; v < nv; v++) uniform[v] = !by_T[v];
    const int nm = ps->enabled & (1u << PC_CURVE_MEMO) ? curve_memo_columns(ms, rp, pcold(ps, PC_CURVE_MEMO), i0, n, col_of, vcol) : 0;
    for (int t = nm; t < nt; t++) {
        const curve *c = &ms->curves[t];
        const double *x = (c->irreversible ? rp->Tmax : rp->T) + i0;
        curve_eval_column(c, x, n, vcol[col_of[c->param]]);
    }
    if (nt == nc) return;
    /* without a water field every ratio is 1 (material_moisture_ratio), and a point that never dried
     * (dried <= 0: 1 - dried >= 1) reads 1 for its irreversible curves too (moisture_ratios): a block of
     * such points has one set of factors, the ones at 1, without the per-point ratios below */
    if (!(ps->enabled & (1u << PC_WATER))) {
        int undried = 1;
        if (rp->dried) {
            /* whether a point dried (a count over every point in an int, vectorised, cost 7 instructions a point in
             * a block that never dried; a scan ending at the first, 9) */
            const double *dr = rp->dried + i0;
            double dried = 0; /* a flag picked in a loop that vectorises: 9 instructions a point as a scan */
            /* 1 - d >= 1 as d <= 2^-54, the same at every d (round to nearest: 1 - 2^-54 is a tie that goes to
             * 1.0, anything above it rounds below 1; NaN fails both): one operation a point fewer */
            for (int j = 0; j < n; j++) dried = dr[j] <= 0x1p-54 ? dried : 1.0;
            undried = dried == 0;
        }
        if (undried) {
            if (!(rp->r == 1.0 && rp->rd == 1.0))
                for (int k = nt; k < nc; k++) rp->f[k - nt] = curve_eval(&ms->curves[k], 1.0);
            rp->r = rp->rd = 1.0;
            for (int k = nt; k < nc; k++) {
                double *col = vcol[col_of[ms->curves[k].param]];
                const double f = rp->f[k - nt];
                if (f != 1.0) { /* x * 1.0 is x: a dry curve's factor at the raw dough's ratio 1 leaves the column */
                    uniform_fill(vcol, uniform, col_of[ms->curves[k].param], ms, vk, n);
                    uniform[col_of[ms->curves[k].param]] = 0;
                    for (int j = 0; j < n; j++) col[j] *= f;
                }
            }
            return;
        }
    }
    /* each point's factors, then each parameter's column times them: one moisture curve a parameter
     * (material_curve_check), so one product an entry, in any order; nc - nt <= nv. Where the factors
     * stand over the block (no water field: every ratio is 1), the column times one number. */
    double fcol[RUN_MAX_VARYING][HEARTH_BLOCK_MAX];
    int varies = 0; /* the factors changed after the block's first point: fcol holds them (else rp->f does) */
    for (int j = 0; j < n; j++) {
        const int i = i0 + j;
        double r;
        const double rd = moisture_ratios(rp, ms, ps, i, &r);
        if (!(r == rp->r && rd == rp->rd)) {
            if (j > 0 && !varies) { /* the points before this one had the factors rp->f still holds */
                varies = 1;
                for (int k = nt; k < nc; k++)
                    for (int jj = 0; jj < j; jj++) fcol[k - nt][jj] = rp->f[k - nt];
            }
            for (int k = nt; k < nc; k++) rp->f[k - nt] = curve_eval(&ms->curves[k], ms->curves[k].irreversible ? rd : r);
        }
        rp->r = r, rp->rd = rd;
        if (varies)
            for (int k = nt; k < nc; k++) fcol[k - nt][j] = rp->f[k - nt];
    }
    for (int k = nt; k < nc; k++) {
        double *col = vcol[col_of[ms->curves[k].param]];
        if (varies) {
            const double *f = fcol[k - nt];
            uniform_fill(vcol, uniform, col_of[ms->curves[k].param], ms, vk, n);
            uniform[col_of[ms->curves[k].param]] = 0;
            for (int j = 0; j < n; j++) col[j] *= f[j];
        } else {
            const double f = rp->f[k - nt];
            if (f != 1.0) { /* x * 1.0 is x (the columns are finite parameters) */
                uniform_fill(vcol, uniform, col_of[ms->curves[k].param], ms, vk, n);
                uniform[col_of[ms->curves[k].param]] = 0;
                for (int j = 0; j < n; j++) col[j] *= f;
            }
        }
    }
}

/* Point by point: P2G's own calls, with the parameters resolved per run (above). */
static double run_points(const material_table *t, const particles *ps, const material_run *r, unsigned flags,
                         double *const tau[9], int *code, double *wave) {
    const material_slot *ms = &t->slot[r->mat];
    double *state = pcold(ps, PC_STATE), pscratch[MATERIAL_MAX_PARAMS], numax = 0;
    const int stride = ps->state_stride;
    const int by_run = !ms->mix_k && ms->ncurves > 0;
    double *th = thermal_column(ms, ps, r, flags);
    material_run_params rp;
    if (by_run) material_run_params_init(&rp, ms, ps);
    for (int j = 0; j < r->n; j++) {
        const int i = r->i0 + j;
        hearth_point pt;
        for (int c = 0; c < 9; c++) {
            pt.grad_v[c] = r->grad_v[c][j];
            pt.F[c] = r->F[c][j];
        }
        pt.dt = r->dt;
        pt.p = by_run ? material_run_params_at(&rp, ms, ps, i) : material_params(t, ps, r->mat, i, pscratch);
        pt.state = state ? state + (size_t)i * stride : NULL;
        unsigned fl = flags;
        const int split = th ? material_thermal_split(ms->m, ms->core, pt.p, pt.state, r->temperature[j], th + i, r->dt,
                                                      pt.F, pt.grad_v)
                             : 0;
        if (split) fl &= ~(unsigned)MATERIAL_EXPANSION; /* in F and grad_v, not a pressure (nor one in a bad K's place) */
        const material_env env = run_env(r, j, fl);
        double tj[9] = {0};
        code[j] = material_point_stress(ms->m, ms->core, &pt, &env, tj);
        if (__builtin_expect(split < 0, 0)) { /* bulk_modulus not finite > 0: the point fails (material.h) */
            code[j] = MATERIAL_BAD_BULK;
            if (flags & MATERIAL_ZERO_FAILED) memset(tj, 0, sizeof tj);
        }
        run_after(ms, &pt, &env, tj, &wave[j], &numax);
        for (int c = 0; c < 9; c++) tau[c][j] = tj[c];
    }
    plugin_call_leave();
    return numax;
}

/* run_after for a block, on its columns: per point the plugin's calls (wave_speed,
 * viscosity, damage, the gas term's plastic_J: the order run_after makes them,
 * each with the point's parameters q patched from vcol), then the core's terms
 * (material_point_couple_terms) column by column: the water pressure, the gas
 * pressure and the thermal pressure added to tau's diagonal in that order, each
 * entry the same operations on the same values as the point's own tj, so the
 * same bits. A cracked point (damage >= 1) gets the tension cut-off instead, as
 * material_point_couple gives it. P: the porosity at the start of the step
 * (NULL: NaN); split: the points whose thermal strain was taken out of F and L
 * (NULL: none), which get no thermal pressure; all_split: every point was (the
 * usual block of a plugin with bulk_modulus: no thermal pressure loop). q holds ms->params when nv > 0
 * (the door copied them). Per point this was 120-odd instructions of copies
 * and branches (pt, env, tj) around the calls. */
static double run_after_block(const material_slot *ms, const material_run *r, unsigned flags, double *q, int nv,
                              const int *vk, double (*vcol)[HEARTH_BLOCK_MAX], const hearth_block *b,
                              const double *P, const signed char *split, int all_split, double *const tau[9],
                              double *wave) {
    double *state = b->state;
    const int stride = b->state_stride;
    const hearth_material *m = ms->m;
    const double *core = ms->core;
    const int n = r->n;
    const double *gas = r->gas, *s0 = r->saturation0;
    const int damage = (flags & MATERIAL_DAMAGE) && m->damage;
    const int terms = gas || s0 || (flags & MATERIAL_EXPANSION);
    const int gas_JP = m->plastic_J && gas;
    double numax = 0, JP1[HEARTH_BLOCK_MAX];
    unsigned char cracked[HEARTH_BLOCK_MAX];
    int ncracked = 0;
    const double *p = nv ? q : ms->params;
    if (m->scalars_block) { /* rule 9: the same values in one call, as columns (no parameters patched per point) */
        double V[HEARTH_BLOCK_MAX], D[HEARTH_BLOCK_MAX];
        double *out[HEARTH_SCALAR_COUNT] = {0};
        if (ms->wave_per_point) out[HEARTH_SCALAR_WAVE_SPEED] = wave;
        if (m->viscosity) out[HEARTH_SCALAR_VISCOSITY] = V;
        if (damage) out[HEARTH_SCALAR_DAMAGE] = D;
        if (terms && gas_JP) out[HEARTH_SCALAR_PLASTIC_J] = JP1; /* a cracked point's is not read */
        if (ms->wave_per_point || m->viscosity || damage || (terms && gas_JP)) {
            plugin_call_enter(m, "scalars_block");
            m->scalars_block(b, out);
        }
        /* each of the three in its own loop, none when not asked (the cookie: its wave speed came per point, it
         * has no viscosity, and a block without a crack counts none in one loop that vectorises) */
        if (!ms->wave_per_point)
            for (int j = 0; j < n; j++) wave[j] = ms->wave_speed;
        if (m->viscosity)
            for (int j = 0; j < n; j++) {
                const double nu = V[j] / hearth_block_param(b, ms->density_index, j);
                if (nu > numax) numax = nu;
            }
        memset(cracked, 0, sizeof cracked);
        if (damage) {
            double dmax = 0; /* the largest damage, in a loop of selects (NaN is not >= 1: not cracked, as below) */
            for (int j = 0; j < n; j++) dmax = D[j] >= 1 ? 1.0 : dmax;
            if (dmax != 0)
                for (int j = 0; j < n; j++) {
                    cracked[j] = D[j] >= 1;
                    ncracked += cracked[j];
                }
        }
    } else
    for (int j = 0; j < n; j++) {
        for (int v = 0; v < nv; v++) q[vk[v]] = vcol[v][j];
        const double *st = state ? state + (size_t)j * stride : NULL;
        double c = ms->wave_speed;
        if (ms->wave_per_point) {
            plugin_call_enter(m, "wave_speed");
            c = m->wave_speed(p, st);
        }
        wave[j] = c;
        if (m->viscosity) {
            plugin_call_enter(m, "viscosity");
            const double nu = m->viscosity(p, m->state_size > 0 ? st : NULL) / p[ms->density_index];
            if (nu > numax) numax = nu;
        }
        cracked[j] = 0;
        if (damage) {
            plugin_call_enter(m, "damage");
            cracked[j] = m->damage(p, st) >= 1;
            ncracked += cracked[j];
        }
        if (terms && gas_JP && !cracked[j]) {
            plugin_call_enter(m, "plastic_J");
            JP1[j] = m->plastic_J(p, st);
        }
    }
    if (ncracked)
        for (int j = 0; j < n; j++)
            if (cracked[j]) {
                double tj[9];
                for (int c = 0; c < 9; c++) tj[c] = tau[c][j];
                material_tension_cutoff(tj);
                for (int c = 0; c < 9; c++) tau[c][j] = tj[c];
            }
    if (!terms) return numax;
    double *t0 = tau[0], *t4 = tau[4], *t8 = tau[8];
    const double *T = r->temperature;
    if (s0 && core[CP_WATER_STIFFNESS] > 0) { /* water pressure (eq. 14) */
        const double cw = core[CP_WATER_STIFFNESS], *s0j = s0 + r->i0;
        for (int j = 0; j < n; j++) {
            if (cracked[j]) continue;
            const double tw = -r->J[j] * cw * ((r->saturation ? r->saturation[j] : NAN) - s0j[j]);
            t0[j] += tw, t4[j] += tw, t8[j] += tw;
        }
    }
    if (gas && core[CP_AMBIENT_PRESSURE] > 0) { /* eq. 13 over the atmosphere (gas.h), its stiffness in the wave speed */
        const double *gj = gas + r->i0, n0 = core[CP_POROSITY0], rho0 = ms->params[ms->density_index];
        for (int j = 0; j < n; j++) {
            if (cracked[j]) continue;
            const double sj = r->saturation ? r->saturation[j] : NAN;
            double stiff;
            const double tg = gas_tau_ambient(gj[j], T ? T[j] : NAN, r->J[j], sj > 0, core[CP_AMBIENT_PRESSURE], n0,
                                              core[CP_REFERENCE_T], core[CP_OPEN_TEMPERATURE], &stiff);
            t0[j] += tg, t4[j] += tg, t8[j] += tg;
            wave[j] = material_gas_wave(wave[j], stiff, r->J[j], rho0);
        }
    } else if (gas) { /* gas pressure (eq. 13), with the porosity after this step's plastic flow */
        const double *gj = gas + r->i0, n0 = core[CP_POROSITY0];
        if (!ncracked && m->plastic_J && T) { /* the usual block: the same arithmetic without a test per point */
            /* into a local column first: the compiler cannot know tau's columns do not alias gas, T or JP1, and
             * with the sums in the same loop it kept the two divisions and the clamps scalar (26 instructions a
             * point in the 2D dough bench) */
            double TG[HEARTH_BLOCK_MAX];
            for (int j = 0; j < n; j++) TG[j] = gas_tau(gj[j], T[j], gas_porosity(JP1[j], n0));
            for (int j = 0; j < n; j++) t0[j] += TG[j], t4[j] += TG[j], t8[j] += TG[j];
        } else
            for (int j = 0; j < n; j++) {
                if (cracked[j]) continue;
                const double np = m->plastic_J ? gas_porosity(JP1[j], n0) : P ? P[j] : NAN;
                const double tg = gas_tau(gj[j], T ? T[j] : NAN, np);
                t0[j] += tg, t4[j] += tg, t8[j] += tg;
            }
    }
    const double cl = core[CP_EXPANSION];
    if ((flags & MATERIAL_EXPANSION) && cl > 0 && !all_split) /* the thermal pressure, where the strain was not taken out */
        for (int j = 0; j < n; j++) {
            if (cracked[j] || (split && split[j])) continue;
            const double th = cl * ((T ? T[j] : NAN) - core[CP_REFERENCE_T]);
            t0[j] -= th, t4[j] -= th, t8[j] -= th;
        }
    return numax;
}

double material_run_eval(const material_table *t, const particles *ps, const material_run *r, double *const tau[9],
                         int *code, double *wave) {
    const material_slot *ms = &t->slot[r->mat];
    const hearth_material *m = ms->m;
    const unsigned flags = r->flags | (m->needs & HEARTH_NEEDS_POROSITY ? MATERIAL_POROSITY_PLASTIC : 0u) |
                           (ms->fracture ? MATERIAL_DAMAGE : 0u);
    /* the parameters that curves move: one column each */
    int vk[RUN_MAX_VARYING], nv = 0;
    for (int c = 0; c < ms->ncurves && nv <= RUN_MAX_VARYING; c++) {
        int seen = 0;
        for (int k = 0; k < nv; k++) seen |= vk[k] == ms->curves[c].param;
        if (!seen && nv < RUN_MAX_VARYING) vk[nv] = ms->curves[c].param;
        nv += !seen;
    }
    if (!m->stress_block || ms->mix_k || nv > RUN_MAX_VARYING) return run_points(t, ps, r, flags, tau, code, wave);

    const int n = r->n, i0 = r->i0, np = m->nparams, stride = ps->state_stride;
    double *state = pcold(ps, PC_STATE);
    if (state) state += (size_t)i0 * stride;
    const int porous = (flags & MATERIAL_POROSITY_PLASTIC) != 0;
    const unsigned needs = m->needs;
    double nan_col[HEARTH_BLOCK_MAX], P[HEARTH_BLOCK_MAX], vcol[RUN_MAX_VARYING][HEARTH_BLOCK_MAX];
    const int need_nan = (!r->temperature && (needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_THERMAL_EXPANSION))) ||
                         (!r->saturation && (needs & HEARTH_NEEDS_SATURATION)) || (!porous && (needs & HEARTH_NEEDS_POROSITY));
    if (need_nan)
        for (int j = 0; j < n; j++) nan_col[j] = NAN;
    /* point j's whole parameter set: the uniform ones once, the curves' patched in per point */
    double q[MATERIAL_MAX_PARAMS];
    const double *pcolumn[MATERIAL_MAX_PARAMS];
    for (int k = 0; k < np; k++) pcolumn[k] = NULL;
    for (int v = 0; v < nv; v++) pcolumn[vk[v]] = vcol[v];
    if (nv) {
        memcpy(q, ms->params, sizeof(double) * (size_t)np);
        material_run_params rp; /* the curves once per run, as run_points resolves them, curve by curve */
        material_run_params_init(&rp, ms, ps);
        unsigned char uniform[RUN_MAX_VARYING];
        run_params_columns(&rp, ms, ps, i0, n, nv, vk, vcol, uniform);
        /* a column that holds the slot's own value at every point goes to the plugin as that value (b.p is
         * ms->params): the same values, and the plugin hoists what it computes from them (the cookie's E, whose
         * dry curve is 1 at the raw dough's ratio: its Lame constants, wave speed and K once a block) */
        for (int v = 0; v < nv; v++)
            if (uniform[v]) pcolumn[vk[v]] = NULL;
        /* without scalars_block, the per-point paths below (and run_after_block's) patch q from every column */
        if (!m->scalars_block)
            for (int v = 0; v < nv; v++) uniform_fill(vcol, uniform, v, ms, vk, n);
    }
    const double *pj = nv ? q : ms->params; /* no curve: the slot's own parameters, uncopied */
    /* eq. 10 as a strain: the block gets F_M and L_M, as run_points hands each point. Each point's scalars
     * first (its own bulk_modulus: K may read the state, <hearth/material.h>), then material_thermal_split's
     * products column by column, straight from the run's columns into the block's: the same operations on
     * the same values, without two 3x3 copies a point, and a loop the compiler vectorises. A point left
     * alone gets 1, 1 and -0.0 (material_thermal_scales): its F and L come through bit for bit. */
    double *th = thermal_column(ms, ps, r, flags), Fm[9][HEARTH_BLOCK_MAX], Lm[9][HEARTH_BLOCK_MAX];
    signed char split[HEARTH_BLOCK_MAX]; /* material_thermal_scales: 1, 0 or -1 (bad K) */
    double sF[HEARTH_BLOCK_MAX], sL[HEARTH_BLOCK_MAX], dL[HEARTH_BLOCK_MAX];
    const int porous_J = porous && m->plastic_J;
    int finite = 1; /* every point's F and L scales finite */
    int still = 0;  /* every point's L scale 1.0 (thermal_scales_block) */
    int all_split = 0; /* every point's split 1 (thermal_scales_block) */
    if (porous && !m->plastic_J)
        for (int j = 0; j < n; j++) P[j] = gas_porosity(1.0, ms->core[CP_POROSITY0]);
    /* per point, one pass with its parameters patched once: J^P at the start of the step (as
     * material_point_stress) and K for the thermal split's scalars (thermal_scales_block, after). Both
     * callbacks only read p and the state. */
    double K[HEARTH_BLOCK_MAX];
    /* the block as the plugin's batched callbacks see it: its scalars (rule 9) read these fields only; the
     * stress's fields are filled below */
    hearth_block b = {
        .n = n,
        .dim = r->dim == 2 ? 2 : 3,
        .dt = r->dt,
        .p = ms->params,
        .p_col = pcolumn,
        .state = state,
        .state_stride = stride,
    };
    if (m->memo_size > 0 && (ps->enabled & (1u << PC_PLUGIN_MEMO))) /* rule 10: the plugin's cache, never state */
        b.memo = pcold(ps, PC_PLUGIN_MEMO) + (size_t)i0 * ps->memo_stride, b.memo_stride = ps->memo_stride;
    if ((porous_J || th) && m->scalars_block) { /* rule 9: J^P and K in one call */
        double JP0[HEARTH_BLOCK_MAX];
        double *out[HEARTH_SCALAR_COUNT] = {0};
        if (porous_J) out[HEARTH_SCALAR_PLASTIC_J] = JP0;
        if (th) out[HEARTH_SCALAR_BULK_MODULUS] = K;
        plugin_call_enter(m, "scalars_block");
        m->scalars_block(&b, out);
        if (porous_J)
            for (int j = 0; j < n; j++) P[j] = gas_porosity(JP0[j], ms->core[CP_POROSITY0]);
    } else if (porous_J || th)
        for (int j = 0; j < n; j++) {
            for (int v = 0; v < nv; v++) q[vk[v]] = vcol[v][j];
            const double *st = state ? state + (size_t)j * stride : NULL;
            if (porous_J) {
                plugin_call_enter(m, "plastic_J");
                P[j] = gas_porosity(m->plastic_J(pj, st), ms->core[CP_POROSITY0]);
            }
            if (th) {
                plugin_call_enter(m, "bulk_modulus");
                K[j] = m->bulk_modulus(pj, st);
            }
        }
    if (th) { /* the split's scalars, then whether every point's are finite */
        double *memo = ps->enabled & (1u << PC_THERMAL_MEMO) ? pcold(ps, PC_THERMAL_MEMO) + 2 * (size_t)i0 : NULL;
        const int how = thermal_scales_block(ms->core, n, K, r->temperature, th + i0, memo, r->dt, split, sF, sL, dL);
        finite = !(how & THERMAL_NONFINITE);
        still = (how & THERMAL_STILL) != 0;
        all_split = (how & THERMAL_ALL_SPLIT) != 0;
    }
    /* the block's F and L: the run's own columns, or the split's products */
    const double *Fb[9], *Lb[9];
    for (int c = 0; c < 9; c++) Fb[c] = r->F[c], Lb[c] = r->grad_v[c]; /* dt = 0: L as it is */
    if (th) {
        /* a plane strain embedding's zeros: +0.0 times a finite scale >= +0 is +0.0, the entry itself */
        const int skip = r->plane && finite;
        if (skip) {
            /* the in-plane four in one loop (one load of the scale for four products), and F_zz, which the
             * embedding makes 1.0 at every point: 1.0 * s is s, so its column is sF itself */
            scale_columns4(Fm[0], Fm[1], Fm[3], Fm[4], r->F[0], r->F[1], r->F[3], r->F[4], sF, NULL, n);
            Fb[0] = Fm[0], Fb[1] = Fm[1], Fb[3] = Fm[3], Fb[4] = Fm[4], Fb[8] = sF;
        } else
            for (int c = 0; c < 9; c++) scale_column(Fm[c], r->F[c], sF, NULL, n), Fb[c] = Fm[c];
        if (r->dt > 0 && skip && still) { /* the diagonal alone (x * 1.0 is x off it), in one loop */
            scale_columns3(Lm[0], Lm[4], Lm[8], r->grad_v[0], r->grad_v[4], r->grad_v[8], sL, dL, n);
            Lb[0] = Lm[0], Lb[4] = Lm[4], Lb[8] = Lm[8];
        } else if (r->dt > 0) /* the diagonal: L c * exp(r), then + expm1(r) / dt (-std=c17: never contracted to an fma) */
            for (int c = 0; c < 9; c++)
                if (!(skip && (c == 2 || c == 5 || c == 6 || c == 7)) && !(still && c % 4 != 0)) /* still: x * 1.0 */
                    scale_column(Lm[c], r->grad_v[c], sL, c % 4 == 0 ? dL : NULL, n), Lb[c] = Lm[c];
    }
    b.temperature = needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_THERMAL_EXPANSION) ? (r->temperature ? r->temperature : nan_col) : NULL;
    b.porosity = needs & HEARTH_NEEDS_POROSITY ? (porous ? P : nan_col) : NULL;
    b.saturation = needs & HEARTH_NEEDS_SATURATION ? (r->saturation ? r->saturation : nan_col) : NULL;
    for (int c = 0; c < 9; c++) {
        b.grad_v[c] = Lb[c];
        b.F[c] = Fb[c];
        memset(tau[c], 0, sizeof(double) * (size_t)n); /* as P2G's tau = {0}: an unwritten entry reads the same both ways */
    }
    plugin_call_enter(m, "stress_block");
    m->stress_block(&b, tau, code);

    /* non-finite entries: x - x is 0 for a finite x and NaN otherwise (material_finite9's test), over
     * the nine columns at once (a loop the compiler vectorises): a sum of zeros is 0, and a NaN makes it NaN */
    /* and whether any point needs the fix-up below, in the same loop, with no branch per point: almost never */
    double z[HEARTH_BLOCK_MAX];
    long trouble = 0, unsplit = 0; /* unsplit: the points whose strain was not taken out (no temperature, bad K) */
    {
        const double *t0 = tau[0], *t1 = tau[1], *t2 = tau[2], *t3 = tau[3], *t4 = tau[4], *t5 = tau[5], *t6 = tau[6],
                     *t7 = tau[7], *t8 = tau[8];
        for (int j = 0; j < n; j++) {
            z[j] = (t0[j] - t0[j]) + (t1[j] - t1[j]) + (t2[j] - t2[j]) + (t3[j] - t3[j]) + (t4[j] - t4[j]) +
                   (t5[j] - t5[j]) + (t6[j] - t6[j]) + (t7[j] - t7[j]) + (t8[j] - t8[j]);
            trouble += (code[j] != 0) | !(z[j] == 0);
        }
    }
    if (th && !all_split)
        for (int j = 0; j < n; j++) unsplit += split[j] != 1;
    trouble += unsplit;
    for (int j = 0; j < n && trouble; j++) {
        if (__builtin_expect(!code[j] && !(z[j] == 0), 0)) code[j] = MATERIAL_NONFINITE;
        if (__builtin_expect(th && split[j] < 0, 0)) code[j] = MATERIAL_BAD_BULK; /* as run_points */
        if (__builtin_expect(code[j] != 0, 0) && (flags & MATERIAL_ZERO_FAILED))
            for (int c = 0; c < 9; c++) tau[c][j] = 0;
    }
    /* nothing per point after the stress (elastic in a scene without fields): the cached wave speed */
    const int after = ms->wave_per_point || m->viscosity || (flags & (MATERIAL_DAMAGE | MATERIAL_EXPANSION)) || r->gas ||
                      r->saturation0;
    if (!after) {
        for (int j = 0; j < n; j++) wave[j] = ms->wave_speed;
        plugin_call_leave();
        return 0;
    }
    const double numax = run_after_block(ms, r, flags, q, nv, vk, vcol, &b, porous ? P : NULL, th ? split : NULL,
                                         th && !unsplit, tau, wave);
    plugin_call_leave();
    return numax;
}

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
#include <string.h>

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
    material_point_couple(m, ms->core, pt, env, tau);
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

/* The varying parameters of points i0 .. i0 + n - 1 as columns (vcol[v] for
 * parameter vk[v]): the values material_run_params_at gives point by point, to
 * the bit, computed curve by curve over the block. A parameter's value is its
 * temperature curve's (or its uniform value), times its moisture curve's
 * factor; the factors are evaluated again only where material_run_params_at
 * would (the ratios differ from the last point's), so they are its values. */
static void run_params_columns(material_run_params *rp, const material_slot *ms, const particles *ps, int i0, int n,
                               int nv, const int *vk, double (*vcol)[HEARTH_BLOCK_MAX]) {
    const int nt = rp->nt, nc = ms->ncurves;
    int col_of[MATERIAL_MAX_PARAMS];
    for (int v = 0; v < nv; v++) {
        col_of[vk[v]] = v;
        for (int j = 0; j < n; j++) vcol[v][j] = ms->params[vk[v]]; /* rewritten below where a temperature curve is */
    }
    for (int t = 0; t < nt; t++) {
        const curve *c = &ms->curves[t];
        const double *x = (c->irreversible ? rp->Tmax : rp->T) + i0;
        double *col = vcol[col_of[c->param]];
        for (int j = 0; j < n; j++) col[j] = curve_eval(c, x[j]);
    }
    if (nt == nc) return;
    for (int j = 0; j < n; j++) {
        const int i = i0 + j;
        double r;
        const double rd = moisture_ratios(rp, ms, ps, i, &r);
        if (!(r == rp->r && rd == rp->rd))
            for (int k = nt; k < nc; k++) rp->f[k - nt] = curve_eval(&ms->curves[k], ms->curves[k].irreversible ? rd : r);
        rp->r = r, rp->rd = rd;
        for (int k = nt; k < nc; k++) vcol[col_of[ms->curves[k].param]][j] *= rp->f[k - nt];
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
    if (nv || porous) {
        memcpy(q, ms->params, sizeof(double) * (size_t)np);
        material_run_params rp; /* the curves once per run, as run_points resolves them, curve by curve */
        if (nv) {
            material_run_params_init(&rp, ms, ps);
            run_params_columns(&rp, ms, ps, i0, n, nv, vk, vcol);
        }
        if (porous)
            for (int j = 0; j < n; j++) { /* as material_point_stress: J^P at the start of the step */
                double JP = 1.0;
                if (m->plastic_J) {
                    for (int v = 0; v < nv; v++) q[vk[v]] = vcol[v][j];
                    plugin_call_enter(m, "plastic_J");
                    JP = m->plastic_J(q, state ? state + (size_t)j * stride : NULL);
                }
                P[j] = gas_porosity(JP, ms->core[CP_POROSITY0]);
            }
    }
    /* eq. 10 as a strain: the block gets F_M and L_M, as run_points hands each point. Each point's scalars
     * first (its own bulk_modulus: K may read the state, <hearth/material.h>), then material_thermal_split's
     * products column by column, straight from the run's columns into the block's: the same operations on
     * the same values, without two 3x3 copies a point, and a loop the compiler vectorises. A point left
     * alone gets 1, 1 and -0.0 (material_thermal_scales): its F and L come through bit for bit. */
    double *th = thermal_column(ms, ps, r, flags), Fm[9][HEARTH_BLOCK_MAX], Lm[9][HEARTH_BLOCK_MAX];
    signed char split[HEARTH_BLOCK_MAX]; /* material_thermal_scales: 1, 0 or -1 (bad K) */
    if (th) {
        double sF[HEARTH_BLOCK_MAX], sL[HEARTH_BLOCK_MAX], dL[HEARTH_BLOCK_MAX], qs[MATERIAL_MAX_PARAMS], s3[3];
        const double *pj = ms->params; /* no curve: the slot's own parameters, uncopied */
        if (nv) memcpy(qs, ms->params, sizeof(double) * (size_t)np), pj = qs;
        plugin_call_enter(m, "bulk_modulus");
        for (int j = 0; j < n; j++) {
            for (int v = 0; v < nv; v++) qs[vk[v]] = vcol[v][j];
            split[j] = (signed char)material_thermal_scales(m, ms->core, pj, state ? state + (size_t)j * stride : NULL,
                                                              r->temperature[j], th + i0 + j, r->dt, s3);
            sF[j] = s3[0], sL[j] = s3[1], dL[j] = s3[2];
        }
        for (int c = 0; c < 9; c++)
            for (int j = 0; j < n; j++) Fm[c][j] = r->F[c][j] * sF[j];
        if (r->dt > 0)
            for (int c = 0; c < 9; c++) {
                if (c % 4 == 0) /* the diagonal: L c * exp(r), then + expm1(r) / dt (-std=c17: never contracted to an fma) */
                    for (int j = 0; j < n; j++) Lm[c][j] = r->grad_v[c][j] * sL[j] + dL[j];
                else
                    for (int j = 0; j < n; j++) Lm[c][j] = r->grad_v[c][j] * sL[j];
            }
        else
            for (int c = 0; c < 9; c++) memcpy(Lm[c], r->grad_v[c], sizeof(double) * (size_t)n);
    }
    hearth_block b = {
        .n = n,
        .dim = r->dim == 2 ? 2 : 3,
        .dt = r->dt,
        .temperature = needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_THERMAL_EXPANSION) ? (r->temperature ? r->temperature : nan_col) : NULL,
        .porosity = needs & HEARTH_NEEDS_POROSITY ? (porous ? P : nan_col) : NULL,
        .saturation = needs & HEARTH_NEEDS_SATURATION ? (r->saturation ? r->saturation : nan_col) : NULL,
        .p = ms->params,
        .p_col = pcolumn,
        .state = state,
        .state_stride = stride,
    };
    for (int c = 0; c < 9; c++) {
        b.grad_v[c] = th ? Lm[c] : r->grad_v[c];
        b.F[c] = th ? Fm[c] : r->F[c];
        memset(tau[c], 0, sizeof(double) * (size_t)n); /* as P2G's tau = {0}: an unwritten entry reads the same both ways */
    }
    plugin_call_enter(m, "stress_block");
    m->stress_block(&b, tau, code);

    /* non-finite entries: x - x is 0 for a finite x and NaN otherwise (material_finite9's test) */
    for (int j = 0; j < n; j++) {
        double z = 0;
        for (int c = 0; c < 9; c++) z += tau[c][j] - tau[c][j];
        if (__builtin_expect(!code[j] && !(z == 0), 0)) code[j] = MATERIAL_NONFINITE;
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
    double numax = 0;
    memcpy(q, ms->params, sizeof(double) * (size_t)np);
    for (int j = 0; j < n; j++) {
        for (int v = 0; v < nv; v++) q[vk[v]] = vcol[v][j];
        hearth_point pt; /* for run_after's callbacks, which read p, state and the fields, never F or grad_v */
        pt.dt = r->dt;
        pt.p = q;
        pt.state = state ? state + (size_t)j * stride : NULL;
        pt.temperature = r->temperature ? r->temperature[j] : NAN;
        pt.porosity = porous ? P[j] : NAN;
        pt.saturation = r->saturation ? r->saturation[j] : NAN;
        pt.dim = b.dim;
        const material_env env = run_env(r, j, th && split[j] ? flags & ~(unsigned)MATERIAL_EXPANSION : flags);
        /* (a bad K's point, split -1, failed above: no pressure in its place) */
        /* the core's terms are isotropic and touch only the diagonal; a crack's cut-off rewrites all nine */
        double tj[9];
        if (flags & MATERIAL_DAMAGE)
            for (int c = 0; c < 9; c++) tj[c] = tau[c][j];
        else
            tj[0] = tau[0][j], tj[4] = tau[4][j], tj[8] = tau[8][j];
        run_after(ms, &pt, &env, tj, &wave[j], &numax);
        if (flags & MATERIAL_DAMAGE)
            for (int c = 0; c < 9; c++) tau[c][j] = tj[c];
        else
            tau[0][j] = tj[0], tau[4][j] = tj[4], tau[8][j] = tj[8];
    }
    plugin_call_leave();
    return numax;
}

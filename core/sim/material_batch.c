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
#include <math.h>
#include <string.h>

#include "material.h"

/* More distinct parameters with curves than this and the run goes point by
 * point (every in-tree use has one or two). */
#define RUN_MAX_VARYING 8

/* What P2G did after the plugin's stress, for one point: the next step's
 * wave speed, the viscosity, and the core's terms (the door's second half). */
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

/* Point by point: P2G's own calls, unchanged. */
static double run_points(const material_table *t, const particles *ps, const material_run *r, unsigned flags,
                         double (*tau)[9], int *code, double *wave) {
    const material_slot *ms = &t->slot[r->mat];
    const double *Cc = r->grad_v, *Fc = r->F;
    double *state = pcold(ps, PC_STATE), pscratch[MATERIAL_MAX_PARAMS], numax = 0;
    const int stride = ps->state_stride;
    for (int j = 0; j < r->n; j++) {
        const int i = r->i0 + j;
        hearth_point pt;
        memcpy(pt.grad_v, Cc + 9 * (size_t)j, sizeof pt.grad_v);
        memcpy(pt.F, Fc + 9 * (size_t)j, sizeof pt.F);
        pt.dt = r->dt;
        pt.p = material_params(t, ps, r->mat, i, pscratch);
        pt.state = state ? state + (size_t)i * stride : NULL;
        const material_env env = run_env(r, j, flags);
        memset(tau[j], 0, sizeof tau[j]);
        code[j] = material_point_stress(ms->m, ms->core, &pt, &env, tau[j]);
        run_after(ms, &pt, &env, tau[j], &wave[j], &numax);
    }
    plugin_call_leave();
    return numax;
}

double material_run_eval(const material_table *t, const particles *ps, const material_run *r, double (*tau)[9], int *code,
                         double *wave) {
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
    const double *Cc = r->grad_v, *Fc = r->F;
    double *state = pcold(ps, PC_STATE);
    if (state) state += (size_t)i0 * stride;
    double L[9][HEARTH_BLOCK_MAX], F[9][HEARTH_BLOCK_MAX], out[9][HEARTH_BLOCK_MAX];
    double T[HEARTH_BLOCK_MAX], P[HEARTH_BLOCK_MAX], S[HEARTH_BLOCK_MAX], vcol[RUN_MAX_VARYING][HEARTH_BLOCK_MAX];
    for (int j = 0; j < n; j++)
        for (int c = 0; c < 9; c++) {
            L[c][j] = Cc[9 * j + c];
            F[c][j] = Fc[9 * j + c];
            out[c][j] = 0; /* as P2G's tau = {0}: an entry a plugin leaves unwritten reads the same both ways */
        }
    /* point j's whole parameter set: the uniform ones once, the curves' patched in per point */
    double q[MATERIAL_MAX_PARAMS], scratch[MATERIAL_MAX_PARAMS];
    const double *pcolumn[MATERIAL_MAX_PARAMS];
    memcpy(q, ms->params, sizeof(double) * (size_t)np);
    for (int k = 0; k < np; k++) pcolumn[k] = NULL;
    for (int v = 0; v < nv; v++) pcolumn[vk[v]] = vcol[v];
    for (int j = 0; j < n; j++) {
        if (nv) {
            const double *pj = material_params_resolve(ms, ps, i0 + j, scratch);
            for (int v = 0; v < nv; v++) q[vk[v]] = vcol[v][j] = pj[vk[v]];
        }
        T[j] = r->temperature ? r->temperature[j] : NAN;
        S[j] = r->saturation ? r->saturation[j] : NAN;
        P[j] = NAN;
        if (flags & MATERIAL_POROSITY_PLASTIC) { /* as material_point_stress: J^P at the start of the step */
            double JP = 1.0;
            if (m->plastic_J) {
                plugin_call_enter(m, "plastic_J");
                JP = m->plastic_J(q, state ? state + (size_t)j * stride : NULL);
            }
            P[j] = gas_porosity(JP, ms->core[CP_POROSITY0]);
        }
    }
    hearth_block b = {
        .n = n,
        .dim = r->dim == 2 ? 2 : 3,
        .dt = r->dt,
        .temperature = m->needs & (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_THERMAL_EXPANSION) ? T : NULL,
        .porosity = m->needs & HEARTH_NEEDS_POROSITY ? P : NULL,
        .saturation = m->needs & HEARTH_NEEDS_SATURATION ? S : NULL,
        .p = ms->params,
        .p_col = pcolumn,
        .state = state,
        .state_stride = stride,
    };
    double *const tcol[9] = {out[0], out[1], out[2], out[3], out[4], out[5], out[6], out[7], out[8]};
    for (int c = 0; c < 9; c++) {
        b.grad_v[c] = L[c];
        b.F[c] = F[c];
    }
    plugin_call_enter(m, "stress_block");
    m->stress_block(&b, tcol, code);

    double numax = 0;
    memcpy(q, ms->params, sizeof(double) * (size_t)np);
    for (int j = 0; j < n; j++) {
        for (int c = 0; c < 9; c++) tau[j][c] = out[c][j];
        if (__builtin_expect(!code[j] && !material_finite9(tau[j]), 0)) code[j] = MATERIAL_NONFINITE;
        if (__builtin_expect(code[j] != 0, 0) && (flags & MATERIAL_ZERO_FAILED)) memset(tau[j], 0, sizeof tau[j]);
        for (int v = 0; v < nv; v++) q[vk[v]] = vcol[v][j];
        hearth_point pt; /* for run_after's callbacks, which read p, state and the fields, never F or grad_v */
        pt.dt = r->dt;
        pt.p = q;
        pt.state = state ? state + (size_t)j * stride : NULL;
        pt.temperature = T[j];
        pt.porosity = P[j];
        pt.saturation = S[j];
        pt.dim = b.dim;
        const material_env env = run_env(r, j, flags);
        run_after(ms, &pt, &env, tau[j], &wave[j], &numax);
    }
    plugin_call_leave();
    return numax;
}

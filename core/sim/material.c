/* material.c: the scene's material slots and the resolution of a particle's
 * parameters (temperature curves, a mixture's blend). The slots used to sit
 * loose in the scene, written by scene.c, bodies.c and mixing.c; now this
 * file is the only writer, and the scene, the fields and the solvers read.
 * The door to a material point (material_point_eval) stays header-only in
 * material.h: it runs per particle per step. */
#include "material.h"

#include <float.h>
#include <math.h>
#include <stdio.h>

#include "alloc.h"
#include "error.h"
#include "tensor.h"

/* A parameter array is never of size 0, so a plugin without parameters still has a pointer. */
static size_t params_bytes(const hearth_material *m) { return sizeof(double) * (size_t)(m->nparams > 0 ? m->nparams : 1); }

/* A mixture's k parameter sets. */
static size_t mixture_bytes(const hearth_material *m, int k) {
    return sizeof(double) * (size_t)k * (size_t)(m->nparams > 0 ? m->nparams : 1);
}

void material_table_init(material_table *t) { *t = (material_table){0}; }

void material_slot_free(material_slot *ms) {
    mem_free(ms->params, params_bytes(ms->m));
    for (int k = 0; k < ms->ncurves; k++) {
        mem_free(ms->curves[k].T, sizeof(double) * (size_t)ms->curves[k].n);
        mem_free(ms->curves[k].v, sizeof(double) * (size_t)ms->curves[k].n);
    }
    mem_free(ms->curves, sizeof(curve) * (size_t)ms->ncurves);
    mem_free(ms->mix_params, mixture_bytes(ms->m, ms->mix_k));
    ms->params = ms->mix_params = NULL;
    ms->curves = NULL;
    ms->ncurves = ms->mix_k = 0;
}

void material_table_free(material_table *t) {
    for (int i = 0; i < t->n; i++) material_slot_free(&t->slot[i]);
    mem_free(t->slot, sizeof(material_slot) * (size_t)t->cap);
    material_table_init(t);
}

hearth_status material_slot_init(material_slot *ms, const hearth_plugin *pl, const char *const *names,
                                 const double *values, int n, hearth_error *err) {
    const hearth_material *m = hearth_plugin_material(pl);
    if (m->nparams > MATERIAL_MAX_PARAMS)
        return err_set(err, HEARTH_ERR_PLUGIN, "material '%s' declares %d parameters; hearth supports at most %d", m->name,
                       m->nparams, MATERIAL_MAX_PARAMS);
    double *p = mem_alloc(params_bytes(m));
    if (!p) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for material '%s'", m->name);
    double core[CP_COUNT];
    hearth_status st = params_resolve(m, names, values, n, p, core, err);
    if (st) {
        mem_free(p, params_bytes(m));
        return st;
    }
    if (core[CP_DRY_CONDUCTIVITY] > core[CP_CONDUCTIVITY]) { /* the step limits use conductivity (material.h) */
        mem_free(p, params_bytes(m));
        return err_set(err, HEARTH_ERR_PARAM,
                       "material '%s': dry_conductivity = %g W/(m K) exceeds its conductivity = %g W/(m K); valid range "
                       "[0, conductivity] (a dried material conducts at most as the wet one; 0 = as wet)",
                       m->name, core[CP_DRY_CONDUCTIVITY], core[CP_CONDUCTIVITY]);
    }
    if (core[CP_DRY_SPECIFIC_HEAT] > core[CP_SPECIFIC_HEAT]) { /* losing water loses heat capacity (material.h) */
        mem_free(p, params_bytes(m));
        return err_set(err, HEARTH_ERR_PARAM,
                       "material '%s': dry_specific_heat = %g J/(kg K) exceeds its specific_heat = %g J/(kg K); valid "
                       "range [0, specific_heat] (the water a material loses takes its heat capacity with it; 0 = as wet)",
                       m->name, core[CP_DRY_SPECIFIC_HEAT], core[CP_SPECIFIC_HEAT]);
    }
    if (core[CP_AMBIENT_PRESSURE] > 0) { /* the pores start with air at p_a - p_v(theta_0) (gas.h, gas_tau_ambient) */
        const double pv0 = vapour_psat(core[CP_REFERENCE_T] + KELVIN);
        if (!(core[CP_AMBIENT_PRESSURE] > pv0)) {
            mem_free(p, params_bytes(m));
            return err_set(err, HEARTH_ERR_PARAM,
                           "material '%s': ambient_pressure = %g Pa is not above water's vapour pressure %.6g Pa at its "
                           "reference_temperature = %g degC; valid range (%.6g, 1e7] Pa (the pores start with air at "
                           "ambient_pressure less the vapour; 0 = eq. 13 as printed), or a lower reference_temperature",
                           m->name, core[CP_AMBIENT_PRESSURE], pv0, core[CP_REFERENCE_T], pv0);
        }
    }
    *ms = (material_slot){.plugin = pl, .m = m, .params = p, .density_index = params_index(m, "density")};
    memcpy(ms->core, core, sizeof core);
    return HEARTH_OK;
}

/* damage(p, NULL): whether a point with parameters p may crack (<hearth/material.h>). */
static int may_crack(const hearth_material *m, const double *p) {
    if (!m->damage) return 0;
    plugin_call_enter(m, "damage");
    const int may = m->damage(p, NULL) != 0;
    plugin_call_leave();
    return may;
}

hearth_status material_table_reserve(material_table *t, hearth_error *err) {
    if (t->n < t->cap) return HEARTH_OK;
    const int cap = t->cap ? t->cap * 2 : 4;
    material_slot *ms = mem_realloc(t->slot, sizeof(material_slot) * (size_t)t->cap, sizeof(material_slot) * (size_t)cap);
    if (!ms) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for materials");
    t->slot = ms;
    t->cap = cap;
    return HEARTH_OK;
}

/* Eq. 10's thermal strain divides by the plugin's bulk_modulus (material.h,
 * material_thermal_scales), asked only when the material expands (c lambda > 0).
 * A K that is NaN, infinite or <= 0 at the material's own parameters would stop
 * the run at its first heated step (the guard, FAIL_BULK); ask once here, with a
 * fresh state from init (poisoned with NaN first, as plugin_check.c does), so
 * the scene line that adds the material is the one that fails. A K that goes bad
 * only later (state, curves) is still the guard's. Returns 0 when K is fine. */
static hearth_status check_bulk_at_params(const material_slot *ms, hearth_error *err) {
    const hearth_material *m = ms->m;
    if (!m->bulk_modulus || !(ms->core[CP_EXPANSION] > 0)) return HEARTH_OK;
    const size_t bytes = sizeof(double) * (size_t)(m->state_size > 0 ? m->state_size : 1);
    double *state = mem_alloc(bytes);
    if (!state) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for material '%s'", m->name);
    for (int i = 0; i < m->state_size; i++) state[i] = NAN;
    if (m->state_size > 0) {
        plugin_call_enter(m, "init");
        m->init(ms->params, state);
        plugin_call_leave();
    }
    plugin_call_enter(m, "bulk_modulus");
    const double K = m->bulk_modulus(ms->params, m->state_size > 0 ? state : NULL);
    plugin_call_leave();
    mem_free(state, bytes);
    if (K > 0 && K < INFINITY) return HEARTH_OK;
    return err_set(err, HEARTH_ERR_PARAM,
                   "material '%s' (%s): bulk_modulus is %g Pa at these parameters (fresh state from init); it must "
                   "be finite and > 0 for eq. 10's thermal expansion (expansion = %g Pa/K; with 0 K is never asked)",
                   m->name, hearth_plugin_file(ms->plugin), K, ms->core[CP_EXPANSION]);
}

int material_table_push(material_table *t, material_slot *ms, hearth_error *err) {
    HEARTH_ASSERT(t->n < t->cap);
    const hearth_material *m = ms->m;
    if (check_bulk_at_params(ms, err)) {
        material_slot_free(ms);
        return -1;
    }
    if (m->state_size == 0) {
        plugin_call_enter(m, "wave_speed");
        ms->wave_speed = m->wave_speed(ms->params, NULL);
        plugin_call_leave();
        /* the loader checked the schema's corners; these values may lie between them */
        if (!(ms->wave_speed > 0 && ms->wave_speed <= DBL_MAX)) {
            err_set(err, HEARTH_ERR_PARAM,
                    "material '%s' (%s): wave_speed is %g m/s at these parameters; it must be finite and > 0 for "
                    "a stable step to exist",
                    m->name, hearth_plugin_file(ms->plugin), ms->wave_speed);
            material_slot_free(ms);
            return -1;
        }
    }
    ms->wave_per_point = m->state_size > 0 || ms->ncurves > 0;
    ms->fracture = may_crack(m, ms->params);
    t->slot[t->n] = *ms;
    return t->n++;
}

/* ---- temperature and moisture curves --------------------------------- */

/* The extremes [lo, hi] of a curve's values. */
static void curve_range(const double *v, int n, double *lo, double *hi) {
    *lo = *hi = v[0];
    for (int i = 1; i < n; i++) {
        if (v[i] < *lo) *lo = v[i];
        if (v[i] > *hi) *hi = v[i];
    }
}

hearth_status material_curve_check(const material_table *t, int mat, const char *param, int of, int n, const double *T,
                                   const double *v, int *kout, hearth_error *err) {
    if (mat < 0 || mat >= t->n) return err_set(err, HEARTH_ERR_PARAM, "curve: material %d does not exist", mat);
    if (of != CURVE_OF_TEMPERATURE && of != CURVE_OF_MOISTURE)
        return err_set(err, HEARTH_ERR_PARAM, "curve for '%s': kind %d; valid: temperature (0) or moisture (1)", param, of);
    const material_slot *ms = &t->slot[mat];
    const int k = params_index(ms->m, param);
    if (k < 0) return err_set(err, HEARTH_ERR_PARAM, "curve: material '%s' has no parameter '%s'", ms->m->name, param);
    const hearth_param *p = &ms->m->params[k];
    if (n < 1 || n > 10000) return err_set(err, HEARTH_ERR_PARAM, "curve for '%s': %d points; valid range [1, 10000]", param, n);
    const int moist = of == CURVE_OF_MOISTURE;
    for (int i = 0; i < n; i++) {
        if (!isfinite(T[i]) || (i > 0 && !(T[i] > T[i - 1])) || (moist && T[i] < 0))
            return err_set(err, HEARTH_ERR_PARAM, "curve for '%s': %s must be finite%s and strictly increasing (point %d: %g)",
                           param, moist ? "moisture ratios X/X0" : "temperatures", moist ? ", >= 0" : "", i + 1, T[i]);
        if (moist ? !(v[i] > 0 && v[i] <= 1e9) : !(v[i] >= p->min && v[i] <= p->max)) {
            if (moist)
                return err_set(err, HEARTH_ERR_PARAM, "curve for '%s': factor %g at moisture ratio %g is outside (0, 1e9]",
                               param, v[i], T[i]);
            return err_set(err, HEARTH_ERR_PARAM, "curve for '%s': value %g at %g degrees C is outside the range [%g, %g] %s",
                           param, v[i], T[i], p->min, p->max, p->unit);
        }
    }
    /* the parameter's values before and the factors after: base, or its temperature curve's extremes */
    double vlo = ms->params[k], vhi = vlo, flo = 1, fhi = 1;
    if (moist) curve_range(v, n, &flo, &fhi);
    else curve_range(v, n, &vlo, &vhi);
    for (int i = 0; i < ms->ncurves; i++) {
        const curve *c = &ms->curves[i];
        if (c->param != k) continue;
        if (c->of == of)
            return err_set(err, HEARTH_ERR_PARAM, "curve for '%s': the parameter already has a %s curve", param,
                           moist ? "moisture" : "temperature");
        if (c->of == CURVE_OF_MOISTURE) curve_range(c->v, c->n, &flo, &fhi);
        else curve_range(c->v, c->n, &vlo, &vhi);
    }
    /* factors > 0: the products' extremes are among the corners */
    const double corner[4] = {vlo * flo, vlo * fhi, vhi * flo, vhi * fhi};
    for (int i = 0; i < 4; i++)
        if (!(corner[i] >= p->min && corner[i] <= p->max))
            return err_set(err, HEARTH_ERR_PARAM,
                           "curve for '%s': values %g..%g times moisture factors %g..%g reach %g, outside the range [%g, %g] %s",
                           param, vlo, vhi, flo, fhi, corner[i], p->min, p->max, p->unit);
    *kout = k;
    return HEARTH_OK;
}

double material_moisture_factor(const material_slot *ms, const curve *c, const particles *ps, int i) {
    double r = material_moisture_ratio(ms, ps, i);
    if (c->irreversible && (ps->enabled & (1u << PC_DRIED))) r = fmin(r, 1.0 - pcold(ps, PC_DRIED)[i]);
    return curve_eval(c, r);
}

const double *material_params_resolve(const material_slot *ms, const particles *ps, int i, double *scratch) {
    if (ms->mix_k) material_blend_at(ms, ps, i, scratch);
    else memcpy(scratch, ms->params, sizeof(double) * (size_t)ms->m->nparams);
    const double *T = pcold(ps, PC_TEMPERATURE), *Tmax = pcold(ps, PC_TEMP_MAX);
    int k = 0;
    for (; k < ms->ncurves && ms->curves[k].of == CURVE_OF_TEMPERATURE; k++) {
        const curve *c = &ms->curves[k];
        scratch[c->param] = curve_eval(c, c->irreversible ? Tmax[i] : T[i]);
    }
    /* the moisture factors, after every temperature curve (material_curve_add orders them) */
    if (k < ms->ncurves) material_moisture_apply(ms, ps, i, k, scratch);
    return scratch;
}

void material_moisture_apply(const material_slot *ms, const particles *ps, int i, int k, double *scratch) {
    for (; k < ms->ncurves; k++) scratch[ms->curves[k].param] *= material_moisture_factor(ms, &ms->curves[k], ps, i);
}

hearth_status material_curve_add(material_table *t, int mat, int k, int of, int n, const double *T, const double *v,
                                 int irreversible, hearth_error *err) {
    material_slot *ms = &t->slot[mat];
    /* fresh arrays first, so a failure leaves the material as it was */
    curve *cs = mem_alloc(sizeof(curve) * (size_t)(ms->ncurves + 1));
    double *tt = mem_alloc(sizeof(double) * (size_t)n), *vv = mem_alloc(sizeof(double) * (size_t)n);
    if (!cs || !tt || !vv) {
        mem_free(cs, sizeof(curve) * (size_t)(ms->ncurves + 1));
        mem_free(tt, sizeof(double) * (size_t)n);
        mem_free(vv, sizeof(double) * (size_t)n);
        return err_set(err, HEARTH_ERR_NOMEM, "curve: out of memory");
    }
    /* temperature curves first: material_params sets a parameter, then multiplies its moisture factor */
    int at = ms->ncurves;
    if (of == CURVE_OF_TEMPERATURE)
        while (at > 0 && ms->curves[at - 1].of == CURVE_OF_MOISTURE) at--;
    if (at) memcpy(cs, ms->curves, sizeof(curve) * (size_t)at);
    if (ms->ncurves > at) memcpy(cs + at + 1, ms->curves + at, sizeof(curve) * (size_t)(ms->ncurves - at));
    mem_free(ms->curves, sizeof(curve) * (size_t)ms->ncurves);
    ms->curves = cs;
    memcpy(tt, T, sizeof(double) * (size_t)n);
    memcpy(vv, v, sizeof(double) * (size_t)n);
    ms->curves[at] = (curve){.param = k, .n = n, .T = tt, .v = vv, .irreversible = irreversible != 0, .of = of};
    ms->ncurves++;
    /* a new identity for the slot's curves: a particle's PC_CURVE_MEMO entry (material_batch.c) written for the
     * old set, whose curve indices this insertion may have shifted, no longer matches */
    ms->curve_stamp = ++t->curve_epoch;
    /* a curve may move the parameters into cracking: asked at each of its values (a moisture curve's as
     * factors on the base), with the other parameters at their base values */
    for (int j = 0; j < n && !ms->fracture && ms->m->damage; j++) {
        double q[MATERIAL_MAX_PARAMS];
        memcpy(q, ms->params, sizeof(double) * (size_t)ms->m->nparams);
        q[k] = of == CURVE_OF_MOISTURE ? q[k] * v[j] : v[j];
        ms->fracture = may_crack(ms->m, q);
    }
    /* the cached wave speed is the base parameters': a stiffer curve point (E x 100 in a dried crust) would
     * outrun the step limit (seen: an elastic block inverted within a second of drying) */
    ms->wave_per_point = 1;
    return HEARTH_OK;
}

/* ---- mixtures -------------------------------------------------------- */

double *material_mixture_params(const material_table *t, int id, int k, const char *const *const *names,
                                const double *const *values, const int *n, hearth_error *err) {
    const material_slot *ms = &t->slot[id];
    const hearth_material *m = ms->m;
    if (!m->blend) {
        err_set(err, HEARTH_ERR_PARAM, "mixture: plugin '%s' has no blend callback; it cannot mix", m->name);
        return NULL;
    }
    const int np = m->nparams;
    double *mp = mem_alloc(mixture_bytes(m, k));
    if (!mp) {
        err_set(err, HEARTH_ERR_NOMEM, "out of memory for a mixture");
        return NULL;
    }
    memcpy(mp, ms->params, sizeof(double) * (size_t)np);
    double core[CP_COUNT]; /* the first constituent's core field properties are the mixture's */
    for (int c = 1; c < k; c++)
        if (params_resolve(m, names[c], values[c], n[c], mp + (size_t)c * np, core, err)) {
            char msg[sizeof err->msg];
            snprintf(msg, sizeof msg, "%s", err->msg);
            err_set(err, HEARTH_ERR_PARAM, "mixture constituent %d: %s", c + 1, msg);
            mem_free(mp, mixture_bytes(m, k));
            return NULL;
        }
    return mp;
}

void material_mixture_params_free(const material_table *t, int id, int k, double *mp) {
    mem_free(mp, mixture_bytes(t->slot[id].m, k));
}

void material_mixture_set(material_table *t, int id, int k, double *mp) {
    material_slot *ms = &t->slot[id];
    const hearth_material *m = ms->m;
    const int np = m->nparams;
    ms->mix_k = k;
    ms->mix_params = mp;
    for (int c = 0; c < k && !ms->fracture; c++) ms->fracture = may_crack(m, mp + (size_t)c * np); /* a constituent may crack */
    if (m->state_size == 0) /* any blend's waves are bounded by the fastest constituent's */
        for (int c = 1; c < k; c++) {
            plugin_call_enter(m, "wave_speed");
            ms->wave_speed = fmax(ms->wave_speed, m->wave_speed(mp + (size_t)c * np, NULL));
            plugin_call_leave();
        }
}

/* The ratios are normalised here; a plugin that refuses the blend gets its dominant constituent. */
void material_blend_at(const material_slot *ms, const particles *ps, int i, double *out) {
    const double *a = pcold(ps, PC_MIXD) + (size_t)MIX_MAX * i;
    const int np = ms->m->nparams, k = ms->mix_k;
    const double *pk[MIX_MAX];
    double alpha[MIX_MAX], sum = 0;
    for (int c = 0; c < k; c++) {
        pk[c] = ms->mix_params + (size_t)c * np;
        alpha[c] = a[c] > 0 ? a[c] : 0;
        sum += alpha[c];
    }
    if (!(sum > 0)) { /* cannot happen for a mixture particle; keep the first constituent */
        memcpy(out, pk[0], sizeof(double) * (size_t)np);
        return;
    }
    for (int c = 0; c < k; c++) alpha[c] /= sum;
    plugin_call_enter(ms->m, "blend");
    const int refused = ms->m->blend(k, alpha, pk, out);
    plugin_call_leave();
    if (refused) { /* a plugin that refuses: the dominant constituent */
        int best = 0;
        for (int c = 1; c < k; c++)
            if (alpha[c] > alpha[best]) best = c;
        memcpy(out, pk[best], sizeof(double) * (size_t)np);
    }
}

/* ---- checking parameters without a scene ----------------------------- */

hearth_status hearth_material_check(const char *plugin, const char *const *names, const double *values, int n,
                                    hearth_error *err) {
    hearth_error local;
    if (!err) err = &local;
    const hearth_plugin *pl = hearth_plugin_load(plugin, err);
    if (!pl) return err->code;
    const hearth_material *m = hearth_plugin_material(pl);
    double tmp[MATERIAL_MAX_PARAMS], core[CP_COUNT];
    if (m->nparams > MATERIAL_MAX_PARAMS)
        return err_set(err, HEARTH_ERR_PLUGIN, "material '%s' declares %d parameters; hearth supports at most %d", m->name,
                       m->nparams, MATERIAL_MAX_PARAMS);
    return params_resolve(m, names, values, n, tmp, core, err);
}

/* Rankine's tension cut-off at zero strength on the symmetric part of tau
 * (an isotropic law's tau is symmetric; the symmetric part guards rounding):
 * the principal values are clipped at 0 in their own frame. Only cracked
 * points come here, so the eigen-decomposition is off the hot path. */
void material_tension_cutoff(double tau[9]) {
    double S[9], l[3], Q[9];
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) S[3 * r + c] = 0.5 * (tau[3 * r + c] + tau[3 * c + r]);
    t3_sym_eigen(S, l, Q);
    if (!(l[0] > 0 || l[1] > 0 || l[2] > 0)) return; /* all compressive (or NaN: the guard reports it) */
    for (int k = 0; k < 3; k++) l[k] = fmin(l[k], 0);
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) {
            double v = 0;
            for (int k = 0; k < 3; k++) v += Q[3 * r + k] * l[k] * Q[3 * c + k];
            tau[3 * r + c] = v;
        }
}

/* thermal_ledger.c: the books of a field step that stood's heat (thermal_finish calls thermal_step_books after its
 * update): the oven's Robin heat for latent_heat's ledger, and what each drawing sheet's contact passed to the food
 * (colliders.h). Apart from thermal.c, which holds the update they read. */
#include "thermal.h"

#include <math.h>

#include "colliders.h"
#include "mpm.h"
#include "scene.h"

/* The heat the oven's Robin boundary put in this step, dt sum_p S_p beta_p
 * (theta_out - theta_p), theta_p the nodes' temperature at the particle that
 * the update used: the step start's (forward Euler) or the solution's
 * (backward). Only for the latent_heat ledger; serial, so deterministic. */
static void oven_ledger(hearth_scene *s, double dt) {
    s->heat.step_oven_heat = 0;
    if (!s->def.latent_heat || isnan(s->def.oven_temperature)) return;
    const int ch = s->def.heat_implicit ? CH_T : CH_T0;
    const double *X = pcold(&s->ps, PC_X), *coef = s->heat.bnd_coef;
    const int *flags = pcoli(&s->ps, PC_FLAGS);
    double q = 0;
    for (int i = 0; i < s->ps.n; i++) {
        if (!(flags[i] & PF_BOUNDARY) || !(coef[i] > 0)) continue; /* a collider's contact alone leaves coef 0 */
        int m;
        q += coef[i] * (s->heat.bnd_temp[i] - thermal_field_at(s, X + 3 * i, ch, &m));
    }
    mpm_ranks_fields_reduce(s, &q, 1, NULL, 0); /* MPI slabs: every rank's particles, in rank order */
    s->heat.step_oven_heat = dt * q;
}

/* The heat each drawing sheet's contact passed to the food this field step (colliders.h: its own balance takes it
 * from the sheet): dt sum over its Robin points of beta S (T_c - theta(x_s)), theta the nodes' field the update used
 * (the step start's for forward Euler, the solution's for backward, as oven_ledger; a dried face's reading where
 * dried_face set one), which is what heat_contact_apply scattered onto the nodes (its weights sum to one). Serial in
 * the points' order; MPI slabs sum each sheet's over the ranks. */
static void sheet_ledger(hearth_scene *s, double dt) {
    int any = 0;
    for (int c = 0; c < s->ncol; c++)
        if (collider_draws(&s->cols[c])) s->cols[c].step_heat = s->cols[c].step_ret = 0, any = 1;
    if (!any) return;
    const int ch = s->def.heat_implicit ? CH_T : CH_T0;
    for (int k = 0; k < s->heat.nct; k++) {
        const double *ct = s->heat.ct + THERMAL_CT * k;
        collider *col = &s->cols[(int)ct[10]];
        if (ct[8] != 0 || !collider_draws(col)) continue;
        int m = 1;
        const double v = isnan(ct[9]) ? thermal_field_at(s, ct, ch, &m) : ct[9];
        if (m == 0) continue; /* no node with heat capacity: heat_contact_apply passed nothing */
        col->step_heat += dt * ct[6] * (ct[7] - v);
    }
    for (int c = 0; c < s->ncol; c++)
        if (collider_draws(&s->cols[c])) mpm_ranks_fields_reduce(s, &s->cols[c].step_heat, 1, NULL, 0);
}

void thermal_step_books(hearth_scene *s, double dt) {
    oven_ledger(s, dt);
    sheet_ledger(s, dt);
}

/* water.c: water moving through the solid (Ding et al. 2019 §3.2, §5.5, §6.2).
 *
 *   q^w = -K theta rho^w grad s,  rho^w = rho_0^w s     (Fick's law, §3.2, eq. 8)
 *   q^w . n = beta^w theta s on the air boundary        (evaporation, §3.2)
 *   sigma^w = -c (s - s_0) I                            (water pressure, eq. 14)
 *
 * The diffusivity is D = K theta s: the equation is nonlinear in s.
 * theta is absolute temperature (degrees C + 273.15), as in the gas law: in
 * degrees C the diffusivity would vanish at the freezing point and change
 * sign below it. Without a temperature field a material's
 * reference_temperature stands in.
 *
 * Particles carry their water mass m_p^w (eq. 15) and the saturation is
 * m_p^w / (rho_0^w J V_0): the water rides with the solid exactly, which is
 * what the divergence term of eq. 25 approximates in the paper's Eulerian
 * form, so that term is not needed here. The saturation is floored at
 * WATER_SATURATION_FLOOR (1e-4, the paper's "never completely dry"). Nodes get water mass and water
 * capacity sum rho_0^w V_p w_ip (eq. 15, 18), hence saturation s_i. The flux
 * is evaluated from the current node saturations (eq. 22) and gives the node
 * mass change (eq. 25):
 *
 *   dm_i = dt sum_p V_p q_p . grad w_ip - dt sum_(p in boundary) beta theta_p s_p S_p w_ip.
 *
 * Since sum_i grad w_ip = 0 the flux term moves water without creating any;
 * each node's change then goes to its particles in proportion to
 * their water capacity (see water_take), which also conserves exactly.
 * Boundary particles and
 * their areas S come from boundary.c (§6.6).
 *
 * Wet colliders hold the saturation of the grid nodes inside them or within
 * dx/2 of their surface (a Dirichlet condition at the collider's surface): a wet cloth, or humid air
 * in equilibrium. Water that flows into those nodes leaves into the collider;
 * holding particles instead leaves a boundary layer that halves the exchange
 * in the Crank sheet test, because eq. 19 hands most of a node's gain back to
 * the free particles that share it.
 *
 * With the scene's water_momentum switch the water's motion relative to the
 * solid carries momentum (eq. 26-27): the grid gets sum_p w_ip V_p dq_p with
 * dq_p = q_p^(n-1) - q_p^n (the relative momentum handed back to the solid;
 * lagged one step, since q^(n+1) is not known before the momentum update),
 * and the convective stress -v^w (x) q^w (eq. 7). The solid's mass stays the
 * material's density: the particle mass is the dough's, water included. */
#include "water.h"

#include <math.h>
#include <string.h>

#include "error.h"
#include "scene.h"
#include "mpm.h"
#include "tensor.h"

#define KELVIN 273.15

void water_init(water_state *w) { *w = (water_state){0}; }

void water_free(water_state *w) { water_init(w); }

void water_step_stands(water_state *w) { w->lost += w->step_removed; }

void water_forget_limits(water_state *w) { w->limits_valid = 0; }

void water_restore_lost(water_state *w, double lost) { w->lost = lost; }

int water_active(const hearth_scene *s) { return (s->ps.enabled & (1u << PC_WATER)) != 0; }

int water_material_wants(const hearth_scene *s, int mat) {
    const material_slot *ms = &s->mats.slot[mat];
    return ms->core[CP_WATER_DIFFUSIVITY] > 0 || ms->core[CP_EVAPORATION] > 0 || ms->core[CP_WATER_STIFFNESS] > 0 ||
           (ms->m->needs & HEARTH_NEEDS_SATURATION);
}

static double capacity(const hearth_scene *s, int i) { /* rho_0^w J V_0: water mass at saturation 1 */
    const particles *ps = &s->ps;
    const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
    return ms->core[CP_WATER_DENSITY] * t3_det(pcold(ps, PC_F) + 9 * i) * pcold(ps, PC_VOL0)[i];
}

double water_saturation(const hearth_scene *s, int i) { return pcold(&s->ps, PC_WATER)[i] / capacity(s, i); }

void water_init_particles(hearth_scene *s, int from, int to, double sat) {
    particles *ps = &s->ps;
    for (int i = from; i < to; i++) {
        const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
        double s0 = isnan(sat) ? ms->core[CP_SATURATION0] : sat;
        if (s0 < WATER_SATURATION_FLOOR) s0 = WATER_SATURATION_FLOOR;
        pcold(ps, PC_SAT0)[i] = s0;
        pcold(ps, PC_WATER)[i] = s0 * capacity(s, i);
        if (ps->enabled & (1u << PC_QW)) memset(pcold(ps, PC_QW) + 3 * i, 0, 3 * sizeof(double));
    }
    s->water.limits_valid = 0;
}

hearth_status water_enable(hearth_scene *s, hearth_error *err) {
    particles *ps = &s->ps;
    if (water_active(s)) return HEARTH_OK;
    hearth_status st = particles_enable(ps, PC_WATER, err);
    if (!st) st = particles_enable(ps, PC_SAT0, err);
    /* the last step's flux q^w: only the momentum coupling (eq. 26-27) reads it back */
    if (!st && s->def.water_momentum) st = particles_enable(ps, PC_QW, err);
    if (!st) st = particles_enable(ps, PC_FLAGS, err); /* boundary particles */
    if (st) return st;
    water_init_particles(s, 0, ps->n, NAN);
    return HEARTH_OK;
}

static double theta_abs(const double *T, int i, const material_slot *ms) {
    return (T ? T[i] : ms->core[CP_REFERENCE_T]) + KELVIN;
}

/* What limits the explicit step at one particle of saturation sat: its
 * diffusivity K theta s and its evaporation rate beta theta / rho_0. */
static void particle_limits(const material_slot *ms, double th, double sat, double *d, double *e) {
    *d = fmax(*d, ms->core[CP_WATER_DIFFUSIVITY] * th * sat);
    *e = fmax(*e, ms->core[CP_EVAPORATION] * th / ms->core[CP_WATER_DENSITY]);
}

/* The largest diffusivity K theta s and evaporation rate beta theta / rho_0 over the particles. */
static void scan_limits(const hearth_scene *s, double *dmax, double *emax) {
    const particles *ps = &s->ps;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    double d = 0, e = 0;
    for (int i = 0; i < ps->n; i++) {
        const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
        particle_limits(ms, theta_abs(T, i, ms), water_saturation(s, i), &d, &e);
    }
    *dmax = d;
    *emax = e;
}

double water_dt_limit(const hearth_scene *s) {
    if (!water_active(s)) return INFINITY;
    double d = s->water.dmax, e = s->water.emax;
    if (!s->water.limits_valid) scan_limits(s, &d, &e);
    const double dx = s->def.dx;
    double dt = INFINITY;
    /* forward Euler on the B-spline Laplacian, as for heat: dx^2 / (2 dim D) */
    if (d > 0) dt = dx * dx / (2.0 * s->def.dim * d);
    /* a boundary cell's water rho_0 s dx^dim against its loss beta theta s dx^(dim-1) */
    if (e > 0) dt = fmin(dt, dx / (2.0 * e));
    return dt;
}

double water_total(const hearth_scene *s) {
    if (!water_active(s)) return 0;
    double m = 0;
    const double *W = pcold(&s->ps, PC_WATER);
    for (int i = 0; i < s->ps.n; i++) m += W[i];
    return m;
}

/* ---- the step ----------------------------------------------------------
 * P2G (mpm.c) scatters water mass and capacity (eq. 15, 18); water_prepare
 * turns them into node saturations; transport.c evaluates the flux and
 * evaporation (eq. 22, 25) into CH_DMW in one pass with heat; G2P hands each
 * particle its share (water_take); water_finish sums the step's losses. */

void water_prepare(hearth_scene *s) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    int wet = 0;
    for (int c = 0; c < s->ncol; c++) wet |= !isnan(s->cols[c].saturation);
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) { /* node saturation s_i = m_i^w / (rho_0^w V_i) */
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        for (int l = 0; l < NPB; l++) {
            const double c = node[CH_SW * NPB + l];
            if (!(c > 0)) {
                node[CH_SW * NPB + l] = 0.0;
                continue;
            }
            node[CH_SW * NPB + l] = node[CH_MW * NPB + l] / c;
            node[CH_MW * NPB + l] = c; /* from here on CH_MW is the capacity, for eq. 19 */
            if (!wet) continue;
            /* a node inside a wet collider holds its saturation; water reaching it goes
             * into the collider (its mass is zeroed so eq. 19 hands none of it back) */
            int gi[3];
            grid_node_index(g, bc, l, gi);
            double xi[3] = {0, 0, 0};
            for (int d = 0; d < g->dim; d++) xi[d] = g->lo[d] + gi[d] * g->dx;
            for (int q = 0; q < s->ncol; q++) {
                const collider *col = &s->cols[q];
                /* nodes inside, and the node layer nearest the surface: the held value sits on the surface to within dx/2 */
                if (isnan(col->saturation) || !collider_near(col, xi) || collider_sdf(col, xi, NULL) >= 0.5 * g->dx) continue;
                node[CH_SW * NPB + l] = col->saturation;
                node[CH_MW * NPB + l] = 0.0; /* no capacity: nothing is handed back */
            }
        }
    }
}

/* Each particle takes its nodes' change of saturation (FLIP, as temperature
 * in eq. 21), dm_p = rho_0 V_p sum_i w_ip ds_i, which hands out exactly each
 * node's dm_i since V_i = sum_p V_p w_ip. Eq. 19 shares dm_i in proportion to
 * the particles' water instead; next to a dry region that multiplies a wet
 * particle's gain by s_p / s_i and pushed saturation past its largest initial
 * value (0.94 from 0.9 in water_conservation). Then the floor applies. */
double water_take(hearth_scene *s, int i, double r, double *dmax, double *emax) {
    particles *ps = &s->ps;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    double *W = pcold(ps, PC_WATER);
    const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
    const double cap = ms->core[CP_WATER_DENSITY] * mpm_state_of(s)->vol[i], before = W[i]; /* capacity(), with P2G's volume */
    double m = before + cap * r;
    if (m < WATER_SATURATION_FLOOR * cap) m = WATER_SATURATION_FLOOR * cap;
    W[i] = m;
    particle_limits(ms, theta_abs(T, i, ms), m / cap, dmax, emax);
    return before - m;
}

void water_finish(hearth_scene *s) {
    /* reduce in block order: the same sums on any thread count */
    double removed = 0, dmax = 0, emax = 0;
    const mpm_state *m = mpm_state_of(s);
    for (int k = 0; k < m->npb; k++) {
        removed += m->partial[k].water_removed;
        dmax = fmax(dmax, m->partial[k].water_dmax);
        emax = fmax(emax, m->partial[k].water_emax);
    }
    s->water.step_removed = removed;
    s->water.dmax = dmax;
    s->water.emax = emax;
    s->water.limits_valid = 1;
}

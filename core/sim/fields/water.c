/* water.c: water moving through the solid (Ding et al. 2019 §3.2, §5.5, §6.2).
 *
 *   q^w = -K theta rho^w grad s,  rho^w = rho_0^w s     (Fick's law, §3.2, eq. 8)
 *   q^w . n = beta^w theta (s - s_amb) on the air boundary   (evaporation, §3.2; s_amb ours)
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
 *   dm_i = dt sum_p V_p q_p . grad w_ip - dt sum_(p in boundary) beta theta_p (s_surface,p - s_amb) S_p w_ip,
 *
 * s_surface,p the surface's saturation behind the grid's sample s_p at the
 * particle, which lies a depth d_p inside (water_surface_excess, water.h).
 *
 * Since sum_i grad w_ip = 0 the flux term moves water without creating any;
 * each node's change then goes to its particles in proportion to
 * their water capacity (see water_take), which also conserves exactly.
 * Boundary particles and
 * their areas S come from boundary.c (§6.6).
 *
 * Wet colliders (our extension, issue #17) either hold a saturation S at
 * their face (a Dirichlet condition: a wet cloth, humid air in equilibrium)
 * or, with beta_water > 0, exchange beta_water (s - S) through it (Robin).
 * A holding collider holds the grid nodes inside it or within dx/2 of its
 * face at the profile continued linearly through S (held_value); water that
 * flows into them leaves into the collider; the free nodes get the face's
 * flux that their B-splines see (water_face_flux), and the particles within
 * dx/2 of the face take the grid's saturation (held_particles). Holding
 * particles instead of nodes left a boundary layer that halved the exchange
 * in the Crank sheet test, because eq. 19 hands most of a node's gain back
 * to the free particles that share it. A Robin collider's exchange goes
 * through water_face_flux too. Crank's sheet (tests/unit_water.c,
 * docs/validation.md) converges at second order through both.
 *
 * The oven's ambient saturation s_amb (oven.saturation) is ours as well:
 * Ding et al. dry toward s = 0; with s_amb > s the body takes water up.
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

#include "physics_constants.h"
#include "alloc.h"
#include "grid.h"
#include "material.h"

void water_init(water_state *w) { *w = (water_state){0}; }

void water_free(water_state *w) {
    mem_free(w->front, sizeof(double) * w->front_cap);
    water_init(w);
}

void water_step_stands(water_state *w) { w->lost += w->step_removed; }

void water_forget_limits(water_state *w) { w->limits_valid = 0; }

void water_restore_lost(water_state *w, double lost) { w->lost = lost; }

void water_restore_limits(water_state *w, double dmax, double emax, double lmax) {
    w->dmax = dmax, w->emax = emax, w->lmax = lmax;
    w->limits_valid = 1;
}

int water_active(const hearth_scene *s) { return (s->ps.enabled & (1u << PC_WATER)) != 0; }

double water_psat_boiling(const hearth_scene *s) {
    return s->def.latent_heat && (s->ps.enabled & (1u << PC_TEMPERATURE)) ? vapour_psat(s->def.boiling_point + KELVIN) : 0.0;
}

int water_material_wants(const hearth_scene *s, int mat) {
    const material_slot *ms = &s->mats.slot[mat];
    return ms->core[CP_WATER_DIFFUSIVITY] > 0 || ms->core[CP_EVAPORATION] > 0 || ms->core[CP_WATER_STIFFNESS] > 0 ||
           (ms->m->needs & HEARTH_NEEDS_SATURATION);
}

/* rho_0^w J V_0: water mass at saturation 1. On SPH J is 1 (sph_water_volume,
 * water.h says why). */
static double capacity(const hearth_scene *s, int i) {
    const particles *ps = &s->ps;
    const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
    const double J = s->def.solver == HEARTH_SOLVER_SPH ? 1.0 : particles_J(ps, i);
    return ms->core[CP_WATER_DENSITY] * J * pcold(ps, PC_VOL0)[i];
}

double water_saturation(const hearth_scene *s, int i) { return pcold(&s->ps, PC_WATER)[i] / capacity(s, i); }

double water_surface_saturation(const hearth_scene *s, int i, double s_d) {
    const particles *ps = &s->ps;
    if (!s->boundary.area || i >= s->boundary.area_cap || !(s->boundary.area[i] > 0)) return s_d;
    const double *c = s->mats.slot[pcoli(ps, PC_MAT)[i]].core;
    const double a = water_surface_layer(c[CP_EVAPORATION], c[CP_WATER_DIFFUSIVITY], c[CP_WATER_DENSITY], s->boundary.depth[i]);
    return a > 0 ? s->def.oven_saturation + water_surface_excess(s_d, s->def.oven_saturation, a) : s_d;
}

int water_sph_gas(const hearth_scene *s, const material_slot *ms) {
    return s->def.solver == HEARTH_SOLVER_SPH && ms->core[CP_BUBBLE] > 0;
}

void water_init_particles(hearth_scene *s, int from, int to, double sat) {
    particles *ps = &s->ps;
    for (int i = from; i < to; i++) {
        const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
        double s0 = isnan(sat) ? ms->core[CP_SATURATION0] : sat;
        if (water_sph_gas(s, ms)) s0 = 0; /* a bubble is gas: it holds no liquid water (bodies.c refuses more) */
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
 * diffusivity K theta s, its evaporation rate beta theta / rho_0 and, with
 * latent_heat, its latent sink's Robin coefficient per unit heat capacity
 * beta (s - s_amb) / (rho c), before L and the vapour's factor's bound
 * (thermal.c's thermal_dt_limit adds them). The sink's temperature slope
 * L beta g (s_surface - s_amb) S acts on the grid's sample at a surface
 * particle, an average of its neighbours' saturations weighted by capacity
 * (rho_0^w V w_ip >= 0), so it lies within them, and the surface layer only
 * lowers the excess (water_surface_excess); every particle's own excess thus
 * bounds it, surface or not (an interior neighbour, wetter in a drying body,
 * enters the sample). Only a positive excess stiffens: below s_amb the sink
 * is a source that grows with theta, which forward Euler does not make
 * oscillate. A material with no heat capacity and evaporation gets an
 * infinite rate, the zero step the per-material bound gave it before. */
typedef struct limit_scan {
    int latent;   /* the scene's latent_heat: the latent rate is scanned */
    double s_amb; /* the oven's ambient saturation */
} limit_scan;

static limit_scan limit_scan_of(const hearth_scene *s) {
    return (limit_scan){.latent = s->def.latent_heat != 0, .s_amb = s->def.oven_saturation};
}

static void particle_limits(const limit_scan *ls, const material_slot *ms, double th, double sat, double *d, double *e,
                            double *l) {
    *d = fmax(*d, ms->core[CP_WATER_DIFFUSIVITY] * th * sat);
    *e = fmax(*e, ms->core[CP_EVAPORATION] * th / ms->core[CP_WATER_DENSITY]);
    const double ex = sat - ls->s_amb, bw = ms->core[CP_EVAPORATION];
    if (ls->latent && ex > 0 && bw > 0) {
        /* the smallest alpha, the dried one (material_specific_heat_min): the node the sink acts on may hold a
         * dried particle's capacity beside a wet neighbour's excess */
        const double rc = ms->params[ms->density_index] * material_specific_heat_min(ms);
        *l = fmax(*l, rc > 0 ? bw * ex / rc : INFINITY);
    }
}

/* The largest diffusivity K theta s, evaporation rate beta theta / rho_0 and latent rate over the particles. */
static void scan_limits(const hearth_scene *s, double *dmax, double *emax, double *lmax) {
    const particles *ps = &s->ps;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    const limit_scan ls = limit_scan_of(s);
    double d = 0, e = 0, l = 0;
    for (int i = 0; i < ps->n; i++) {
        const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
        particle_limits(&ls, ms, theta_abs(T, i, ms), water_saturation(s, i), &d, &e, &l);
    }
    *dmax = d;
    *emax = e;
    *lmax = l;
}

void water_keep_limits(hearth_scene *s) {
    if (!water_active(s) || s->water.limits_valid) return;
    scan_limits(s, &s->water.dmax, &s->water.emax, &s->water.lmax);
    s->water.limits_valid = 1;
}

double water_dt_limit(const hearth_scene *s) {
    if (!water_active(s)) return INFINITY;
    double d = s->water.dmax, e = s->water.emax, l = 0;
    if (!s->water.limits_valid) scan_limits(s, &d, &e, &l);
    const double dx = s->def.dx;
    double dt = INFINITY;
    /* forward Euler on the B-spline Laplacian, as for heat: dx^2 / (2 dim D) */
    if (d > 0) dt = dx * dx / (2.0 * s->def.dim * d);
    /* a Robin wet collider's rate beta_water / rho_0, as evaporation's below */
    for (int c = 0; c < s->ncol; c++)
        if (!isnan(s->cols[c].saturation) && s->cols[c].beta_water > 0)
            for (int m = 0; m < s->mats.n; m++) e = fmax(e, s->cols[c].beta_water / s->mats.slot[m].core[CP_WATER_DENSITY]);
    /* a boundary cell's water rho_0 s dx^dim against its loss beta theta s dx^(dim-1) */
    if (e > 0) dt = fmin(dt, dx / (2.0 * e));
    return dt;
}

/* A holding wet collider sets its nodes to the profile continued through its
 * face (held_value), which may pass every particle's saturation, and a
 * surface particle beside it samples them: there the scan bounds nothing, so
 * such a scene keeps the bound it had, s - s_amb <= 1 (or the collider's
 * saturation, if higher), for every material. */
static double held_latent_rate(const hearth_scene *s) {
    double top = -INFINITY;
    for (int c = 0; c < s->ncol; c++)
        if (!isnan(s->cols[c].saturation) && !(s->cols[c].beta_water > 0)) top = fmax(top, fmax(1.0, s->cols[c].saturation));
    if (!(top > -INFINITY)) return 0.0;
    const limit_scan ls = limit_scan_of(s);
    double d = 0, e = 0, l = 0;
    for (int m = 0; m < s->mats.n; m++) particle_limits(&ls, &s->mats.slot[m], 0.0, top + s->def.oven_saturation, &d, &e, &l);
    return l;
}

double water_latent_rate(const hearth_scene *s) {
    if (!water_active(s) || !s->def.latent_heat) return 0.0;
    double d, e, l = s->water.lmax;
    if (!s->water.limits_valid) scan_limits(s, &d, &e, &l);
    return fmax(l, held_latent_rate(s));
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

/* The holding wet collider (saturation, no beta_water) whose face is nearest
 * x, if x lies within dx/2 outside it or inside it: its signed distance in *phi
 * and its outward normal in n. NULL otherwise. */
static const collider *holder_at(const hearth_scene *s, const double x[3], double reach, double *phi, double n[3]) {
    const collider *best = NULL;
    double bd = reach * s->def.dx;
    for (int q = 0; q < s->ncol; q++) {
        const collider *col = &s->cols[q];
        if (isnan(col->saturation) || col->beta_water > 0 || !collider_near(col, x)) continue;
        double nq[3] = {0, 0, 0};
        const double d = collider_sdf(col, x, nq);
        if (d < bd) {
            bd = d, best = col;
            memcpy(n, nq, sizeof nq);
        }
    }
    *phi = bd;
    return best;
}

/* The held value of a node at signed distance phi from a wet collider's face
 * (normal n, held saturation S): the profile continued linearly through S at
 * the face, S + phi g, with g the normal slope between the face and the grid's
 * saturation at 2 dx inside (a point whose B-spline stencil lies wholly in
 * free nodes for a flat face). Holding S itself on the nodes past the face, as
 * before, flattened the profile there: the B-spline field at the face is then
 * (s_(a-1) + 7 S) / 8, not S, and the outermost particles saw a gradient 3/4
 * of the true one. g = 0 (S) where that stencil reaches a node without water
 * or a held one (a corner of the body, a thin part). */
static double held_value(const hearth_scene *s, const double xi[3], double phi, const double n[3], double S) {
    const grid *g = &s->g;
    const int D = g->dim, NPB = g->nodes_per_block;
    const double dx = g->dx, h = 2.0 * dx;
    double xm[3] = {0, 0, 0};
    for (int d = 0; d < D; d++) xm[d] = xi[d] + (h - phi) * n[d];
    int base[3];
    double w[3][3], dw[3][3];
    grid_point_weights(g, xm, base, w, dw);
    double sm = 0;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                const int gi[3] = {base[0] + a, base[1] + b, D == 3 ? base[2] + c : 0};
                int l;
                const double *node = grid_node_at(g, gi, &l);
                if (!node) return S;
                double xj[3] = {0, 0, 0}, pj, nj[3];
                for (int d = 0; d < D; d++) xj[d] = g->lo[d] + gi[d] * dx;
                /* a held node's value is being written by another thread: ask the geometry first */
                if (holder_at(s, xj, 0.5, &pj, nj) || !(node[CH_MW * NPB + l] > 0)) return S;
                sm += w[0][a] * w[1][b] * w[2][c] * node[CH_SW * NPB + l];
            }
    return S + phi * (sm - S) / h;
}

void water_prepare(hearth_scene *s) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    int wet = 0, exchange = 0; /* colliders that hold their saturation, and Robin ones */
    for (int c = 0; c < s->ncol; c++) {
        wet |= !isnan(s->cols[c].saturation) && !(s->cols[c].beta_water > 0);
        exchange |= !isnan(s->cols[c].saturation) && s->cols[c].beta_water > 0;
    }
    s->water.exchange = exchange;
    s->water.hold = wet;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) { /* node saturation s_i = m_i^w / (rho_0^w V_i) */
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double c = node[CH_SW * NPB + l];
            if (!(c > 0)) {
                node[CH_SW * NPB + l] = 0.0;
                continue;
            }
            node[CH_SW * NPB + l] = node[CH_MW * NPB + l] / c;
            node[CH_MW * NPB + l] = c; /* from here on CH_MW is the capacity, for eq. 19 */
        }
    }
    if (!wet) return;
    /* A node inside a wet collider or within dx/2 of its face is held; water
     * reaching it goes into the collider (its capacity is zeroed so eq. 19
     * hands none of it back). This pass writes only held nodes and reads only
     * free ones (held_value refuses a held neighbour), so blocks run in parallel. */
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        for (int l = 0; l < NPB; l++) {
            if (!(node[CH_MW * NPB + l] > 0)) continue;
            int gi[3];
            grid_node_index(g, bc, l, gi);
            double xi[3] = {0, 0, 0}, phi, n[3] = {0, 0, 0};
            for (int d = 0; d < g->dim; d++) xi[d] = g->lo[d] + gi[d] * g->dx;
            const collider *col = holder_at(s, xi, 0.5, &phi, n);
            if (!col) continue;
            node[CH_SW * NPB + l] = held_value(s, xi, phi, n, col->saturation);
            node[CH_MW * NPB + l] = 0.0; /* no capacity: nothing is handed back */
        }
    }
}

/* The flux through wet colliders' faces into the free nodes, from the
 * particles within dx of a face, each carrying V_p/dx of it (a band of
 * thickness dx sums to the contact area whatever way the face lies; heated
 * colliders do the same, thermal.c). Each hands its flux density to the
 * nodes around its foot on the face, where the weak form's boundary term
 * int_face w_i q.n dS lives:
 *  - a holding face: -rho_0 D n.grad s, at the particle. The held nodes take
 *    what the Galerkin sum hands them, but a free node's B-spline does not
 *    vanish on the face (w = 1/8 there for a face on a node row), so without
 *    this term the free nodes took 0.875 of a linear profile's flux, and
 *    Crank's sheet stayed first order (9.8%, 4.1%, 1.9% low at 10, 20, 40
 *    cells; with it 3.9%, 0.9%, 0.3%).
 *  - a Robin face (beta_water > 0): -beta_water (s_face - S), s_face the
 *    saturation extrapolated from the particle to its foot along the normal
 *    (the particle's own value sits dx/4 to 3dx/4 inside and would move the
 *    exchange's reference by O(dx)). boundary.area is no help here: boundary.c
 *    removes the contact faces from the air surface (contact is not air).
 * Serial: it runs only in scenes with a wet collider. */
void water_face_flux(hearth_scene *s, double dt) {
    if (!s->water.hold && !s->water.exchange) return;
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int D = g->dim, NPB = g->nodes_per_block;
    const double dx = g->dx, *X = pcold(ps, PC_X), *W = pcold(ps, PC_WATER), *vol = mpm_state_of(s)->vol;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    for (int i = 0; i < ps->n; i++) {
        const double *x = X + 3 * i;
        double phi = dx, n[3] = {0, 0, 0};
        const collider *col = NULL;
        for (int q = 0; q < s->ncol; q++) { /* the nearest wet face within dx */
            const collider *cq = &s->cols[q];
            if (isnan(cq->saturation) || !collider_near(cq, x)) continue;
            double nq[3] = {0, 0, 0};
            const double d = collider_sdf(cq, x, nq);
            if (d < phi) col = cq, phi = d, memcpy(n, nq, sizeof nq);
        }
        if (!col) continue;
        /* n . grad s at the particle, from the node saturations (held ones included) */
        int base[3];
        double w[3][3], dw[3][3];
        grid_point_weights(g, x, base, w, dw);
        double gn = 0, si = 0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                    const int gi[3] = {base[0] + a, base[1] + b, D == 3 ? base[2] + c : 0};
                    int l;
                    const double *node = grid_node_at(g, gi, &l);
                    if (!node) continue;
                    const double wz = D == 3 ? w[2][c] : 1.0, sv = node[CH_SW * NPB + l];
                    si += sv * w[0][a] * w[1][b] * wz;
                    gn += sv * (n[0] * dw[0][a] * w[1][b] * wz + n[1] * w[0][a] * dw[1][b] * wz +
                                (D == 3 ? n[2] * w[0][a] * w[1][b] * dw[2][c] : 0.0));
                }
        gn *= g->inv_dx;
        const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
        const double rho0 = ms->core[CP_WATER_DENSITY], sp = W[i] / (rho0 * vol[i]);
        const double diff = ms->core[CP_WATER_DIFFUSIVITY] * theta_abs(T, i, ms) * sp;
        const double h = phi > 0 ? phi : 0.0;
        const double inflow = col->beta_water > 0 ? -col->beta_water * (si - h * gn - col->saturation) : -rho0 * diff * gn;
        const double dm = dt * inflow * vol[i] / dx; /* into the body, kg */
        /* to the nodes around the particle's foot on the face */
        double xf[3] = {x[0], x[1], x[2]};
        for (int d = 0; d < D; d++) xf[d] -= h * n[d];
        grid_point_weights(g, xf, base, w, dw);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                    const int gi[3] = {base[0] + a, base[1] + b, D == 3 ? base[2] + c : 0};
                    int l;
                    double *node = grid_node_at(g, gi, &l);
                    if (node) node[CH_DMW * NPB + l] += dm * w[0][a] * w[1][b] * (D == 3 ? w[2][c] : 1.0);
                }
    }
}


/* Each particle takes its nodes' change of saturation (FLIP, as temperature
 * in eq. 21), dm_p = rho_0 V_p sum_i w_ip ds_i, which hands out exactly each
 * node's dm_i since V_i = sum_p V_p w_ip. Eq. 19 shares dm_i in proportion to
 * the particles' water instead; next to a dry region that multiplies a wet
 * particle's gain by s_p / s_i and pushed saturation past its largest initial
 * value (0.94 from 0.9 in water_conservation). Then the floor applies. */
double water_take(hearth_scene *s, int i, double r, double *dmax, double *emax, double *lmax) {
    particles *ps = &s->ps;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    double *W = pcold(ps, PC_WATER);
    const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
    const double cap = ms->core[CP_WATER_DENSITY] * mpm_state_of(s)->vol[i], before = W[i]; /* capacity(), with P2G's volume */
    double m = before + cap * r;
    if (m < WATER_SATURATION_FLOOR * cap) m = WATER_SATURATION_FLOOR * cap;
    W[i] = m;
    const limit_scan ls = limit_scan_of(s);
    particle_limits(&ls, ms, theta_abs(T, i, ms), m / cap, dmax, emax, lmax);
    return before - m;
}

/* Interior boiling (the scene's latent_heat with its boiling_point T_b; issue
 * #18, beyond Ding et al., whose eq. 9 has no latent term and whose eq. 8
 * evaporates through the surface only). MPM calls it in G2P (SPH in
 * sph_water.c, once its temperatures moved), after the particle took its
 * nodes' temperature change: a particle holding water above the saturation
 * floor whose temperature passed T_b turns the excess sensible heat into
 * vapour, dm = m c (T - T_b) / L, capped by that water, and T falls by
 * L dm / (m c) (to T_b unless the cap bit). m c is mc, the heat capacity the
 * step heated the particle with (P2G's, at the water it held when the step
 * began: material_specific_heat), so the sensible heat it gives up is the one
 * the step's update put in; heat lost = L x water lost to round-off, in both heat
 * schemes: the implicit one solved for T first, and the clamp acts on the
 * solution (operator splitting; the CG never sees the sink).
 * Where the vapour goes: in a real crumb it moves through the pores to the
 * surface and out (and part condenses again further in: evaporation-
 * condensation, which moves heat inward ahead of the front); here it leaves the body
 * at once. That is the simplest closure that conserves energy: it leaves out
 * the heat the vapour carries toward the colder core and the water it
 * deposits there, so the wet core heats by conduction alone (slower than
 * a real crumb).
 * No step limit: it is a projection onto T <= T_b, which never amplifies. A
 * pinned body's held particles (PF_HOLD_T) keep their temperature: mpm.c
 * does not call this for them. Returns the water boiled (kg). */
double water_boil(hearth_scene *s, int i, double *T, double Tb, double vol, double mc) {
    particles *ps = &s->ps;
    double *W = pcold(ps, PC_WATER);
    const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
    const double spare = W[i] - water_floor(ms->core[CP_WATER_DENSITY], vol);
    if (!(spare > 0) || !(mc > 0)) return 0.0;
    double dm = mc * (*T - Tb) / HEARTH_LATENT_HEAT;
    if (dm < spare) {
        *T = Tb;
    } else {
        dm = spare;
        *T -= dm * HEARTH_LATENT_HEAT / mc;
    }
    W[i] -= dm;
    return dm;
}

/* After G2P, the particles within dx/2 of a holding wet collider's face take
 * the grid's new saturation at their place, sum_i w_ip (s_i + ds_i) with the
 * held nodes' values (PIC), instead of the FLIP change G2P gave them: they
 * stand for the layer the held nodes cover, and the held nodes have no change
 * to hand them. With FLIP they kept their starting saturation beside a face
 * held at another (Crank's sheet: 13%, 5.1%, 2.3% low, first order). A pass
 * of its own, so that G2P costs what it did in scenes without such a
 * collider; it sees the positions G2P moved the particles to, which differ
 * from P2G's by v dt, far below dx. Returns the water the particles lost. */
static double held_particles(hearth_scene *s, double *dmax, double *emax, double *lmax) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int D = g->dim, NPB = g->nodes_per_block;
    const double *X = pcold(ps, PC_X), *vol = mpm_state_of(s)->vol;
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    double *W = pcold(ps, PC_WATER), removed = 0;
    const limit_scan ls = limit_scan_of(s);
    for (int i = 0; i < ps->n; i++) {
        double phi, n[3];
        if (!holder_at(s, X + 3 * i, 0.5, &phi, n)) continue;
        int base[3];
        double w[3][3], dw[3][3];
        grid_point_weights(g, X + 3 * i, base, w, dw);
        double sat = 0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                    const int gi[3] = {base[0] + a, base[1] + b, D == 3 ? base[2] + c : 0};
                    int l;
                    const double *node = grid_node_at(g, gi, &l);
                    if (!node) continue;
                    const double cw = node[CH_MW * NPB + l], ds = cw > 0 ? node[CH_DMW * NPB + l] / cw : 0.0;
                    sat += w[0][a] * w[1][b] * w[2][c] * (node[CH_SW * NPB + l] + ds);
                }
        const material_slot *ms = &s->mats.slot[pcoli(ps, PC_MAT)[i]];
        const double cap = ms->core[CP_WATER_DENSITY] * vol[i], before = W[i];
        double m = sat * cap;
        if (m < WATER_SATURATION_FLOOR * cap) m = WATER_SATURATION_FLOOR * cap;
        W[i] = m;
        particle_limits(&ls, ms, theta_abs(T, i, ms), m / cap, dmax, emax, lmax);
        removed += before - m;
    }
    return removed;
}

void water_finish(hearth_scene *s) {
    /* reduce in block order: the same sums on any thread count (a maximum is exact in any order anyway) */
    double removed = 0, dmax = 0, emax = 0, lmax = 0;
    const mpm_state *m = mpm_state_of(s);
    for (int k = 0; k < m->npb; k++) {
        removed += m->partial[k].water_removed;
        dmax = fmax(dmax, m->partial[k].water_dmax);
        emax = fmax(emax, m->partial[k].water_emax);
        lmax = fmax(lmax, m->partial[k].water_lmax);
    }
    if (s->water.hold) removed += held_particles(s, &dmax, &emax, &lmax);
    removed += s->water.front_removed; /* water_boil_front's (0 without latent_heat) */
    s->water.front_removed = 0;
    /* on MPI slabs each rank took its own particles': added and maxed in rank
     * order, so every rank takes the same step next (mpm_stable_dt) */
    double mx[3] = {dmax, emax, lmax};
    mpm_ranks_fields_reduce(s, &removed, 1, mx, 3);
    dmax = mx[0], emax = mx[1], lmax = mx[2];
    s->water.step_removed = removed;
    s->water.dmax = dmax;
    s->water.emax = emax;
    s->water.lmax = lmax;
    s->water.limits_valid = 1;
}

/* The driest state each particle reached, for irreversible moisture curves
 * (material.h): PC_DRIED holds 1 - the lowest X/X_0, so the column's zeros
 * read "never dried" without a pass at seeding. Stepped once a step stands,
 * like browning, so a rolled back step leaves no trace. */
void water_dried_step(hearth_scene *s) {
    const particles *ps = &s->ps;
    const int n = ps->n;
    double *d = pcold(ps, PC_DRIED);
    const int *mat = pcoli(ps, PC_MAT);
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        const double dry = 1.0 - material_moisture_ratio(&s->mats.slot[mat[i]], ps, i);
        if (dry > d[i]) d[i] = dry > 1 ? 1 : dry;
    }
}

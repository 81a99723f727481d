/* thermal.c: heat transport (Ding et al. 2019 eq. 9, §6.3, §6.6).
 *
 *   rho alpha Dtheta/Dt = div(kappa grad theta) - theta c lambda div v
 *
 * Nodes get temperature from the particles weighted by heat capacity
 * m alpha (eq. 17 with alpha folded in, so energy is conserved when alpha
 * varies between materials). The conduction operator is the particle-
 * quadrature Galerkin Laplacian L_ij = sum_p V_p kappa_p grad w_ip . grad w_jp,
 * whose columns sum to zero, so conduction conserves heat exactly in both
 * the forward (gamma = 0) and backward (gamma = 1) Euler updates of §6.3.
 * Particles take the change of their nodes' temperature (FLIP, eq. 21) in G2P.
 * The operator itself is applied by transport.c, in one pass with water's.
 *
 * Boundaries relax toward the outside temperature: the flux into the body is
 * S beta (theta_out - theta) (the printed signs in §4/§6.3 are ambiguous; the
 * analytic slab test decides). Boundary particles and their areas S come from
 * boundary.c (§6.6), with the depth of their temperature sample: the oven's
 * coefficient is beta / (1 + beta d / kappa) (find_boundary).
 * Heated colliders act on particles within dx of them, each carrying V_p/dx
 * of contact area (a band of thickness dx sums to the contact area).
 *
 * The expansion term uses absolute temperature (theta + 273.15): in degrees C
 * it would change sign at the freezing point.
 *
 * FLIP keeps heat exactly but not a maximum principle: where two materials
 * share nodes a particle can overshoot (seen: 110 degC from a 90 degC start in
 * `heat_insulated_conservation_explicit`); the scene's heat_flip < 1 blends
 * toward PIC, which keeps one (`heat_flip_pic_bounds`). */
#include "thermal.h"

#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "scene.h"
#include "mpm.h"
#include "transport.h"

#define KELVIN 273.15

void thermal_init(thermal_state *h) { *h = (thermal_state){0}; }

void thermal_free(thermal_state *h) {
    mem_free(h->bnd_coef, sizeof(double) * (size_t)h->bnd_cap);
    mem_free(h->bnd_temp, sizeof(double) * (size_t)h->bnd_cap);
    mem_free(h->cg_partial, sizeof(double) * (size_t)h->cg_cap);
    thermal_init(h);
}

int thermal_cg_iterations(const hearth_scene *s) { return s->heat.cg_iterations; }

int thermal_active(const hearth_scene *s) { return (s->ps.enabled & (1u << PC_TEMPERATURE)) != 0; }

double thermal_dt_limit(const hearth_scene *s) {
    if (!thermal_active(s) || s->def.heat_implicit) return INFINITY;
    /* the strongest boundary coupling: a node's heat capacity against S beta */
    double beta = isnan(s->def.oven_temperature) ? 0 : s->def.oven_beta;
    for (int c = 0; c < s->ncol; c++)
        if (!isnan(s->cols[c].temperature) && s->cols[c].beta > beta) beta = s->cols[c].beta;
    double dt = INFINITY;
    for (int m = 0; m < s->mats.n; m++) {
        const material_slot *ms = &s->mats.slot[m];
        const double k = ms->core[CP_CONDUCTIVITY], ra = ms->params[ms->density_index] * ms->core[CP_SPECIFIC_HEAT];
        /* forward Euler on the B-spline Laplacian: rho alpha dx^2 / (2 dim kappa) */
        if (k > 0) dt = fmin(dt, ra * s->def.dx * s->def.dx / (2.0 * s->def.dim * k));
        /* and on the Robin term: a boundary cell's rho alpha dx^dim against beta dx^(dim-1) */
        if (beta > 0) dt = fmin(dt, ra * s->def.dx / (2.0 * beta));
    }
    return dt;
}

double thermal_energy(const hearth_scene *s) {
    if (!thermal_active(s)) return 0;
    double e = 0;
    const double *T = pcold(&s->ps, PC_TEMPERATURE), *m = pcold(&s->ps, PC_MASS);
    const int *mat = pcoli(&s->ps, PC_MAT);
    for (int i = 0; i < s->ps.n; i++) e += m[i] * s->mats.slot[mat[i]].core[CP_SPECIFIC_HEAT] * (T[i] + KELVIN);
    return e;
}

/* ---- boundary coefficients ------------------------------------------- */

/* Fills s->heat.bnd_coef (S beta, W/K) and s->heat.bnd_temp (degrees C) for the
 * particles flagged PF_BOUNDARY, from the air boundary (boundary.c) and the
 * heated colliders. Other particles' entries are stale: readers check the
 * flag first, so the interior costs no memory traffic. */
static void find_boundary(hearth_scene *s) {
    const grid *g = &s->g;
    particles *ps = &s->ps;
    const int n = ps->n;
    double *coef = s->heat.bnd_coef, *temp = s->heat.bnd_temp;
    const double *X = pcold(ps, PC_X);
    int *flags = pcoli(ps, PC_FLAGS); /* live with temperature */
    const int oven = !isnan(s->def.oven_temperature) && s->def.oven_beta > 0;
    const int *mat = pcoli(ps, PC_MAT);
    const double beta = s->def.oven_beta, *depth = s->boundary.depth;
    for (int i = 0; i < n; i++)
        if (flags[i] & PF_BOUNDARY) { /* flagged by boundary.c: the air boundary */
            /* The grid samples the particle's temperature at depth d below the
             * surface (boundary.c), colder than the surface by d q / kappa, so the
             * flux q = beta (theta_out - theta_s) is beta / (1 + beta d / kappa) times
             * theta_out - theta_p: the Robin condition moved in by d, exact for a
             * linear profile. Without it the flux was overstated by about 0.6 dx Bi / R
             * (first order). A coefficient, not an extrapolated temperature, so the
             * implicit operator stays symmetric. With no conduction nothing carries heat
             * from the surface to the sample: the flux acts on the particle directly. */
            double b = 0.0;
            if (oven) {
                const double kap = s->mats.slot[mat[i]].core[CP_CONDUCTIVITY];
                b = kap > 0 ? beta / (1.0 + beta * depth[i] / kap) : beta;
            }
            coef[i] = s->boundary.area[i] * b;
            temp[i] = oven ? s->def.oven_temperature : 0.0;
        }
    /* heated colliders: the band within dx of the surface */
    for (int c = 0; c < s->ncol; c++) {
        const collider *col = &s->cols[c];
        if (isnan(col->temperature) || col->beta <= 0) continue;
        for (int i = 0; i < n; i++) {
            const double *x = X + 3 * i;
            if (!collider_near(col, x) || collider_sdf(col, x, NULL) >= g->dx) continue;
            if (!(flags[i] & PF_BOUNDARY)) coef[i] = temp[i] = 0.0;
            const double Vp = mpm_state_of(s)->vol[i]; /* J V_0, from this step's P2G */
            /* a particle touching both air and the pan: the pan's temperature wins the ambient, areas add */
            const double cS = Vp / g->dx * col->beta;
            temp[i] = coef[i] > 0 ? (temp[i] * coef[i] + col->temperature * cS) / (coef[i] + cS) : col->temperature;
            coef[i] += cS;
            flags[i] |= PF_BOUNDARY;
        }
    }
}

/* Deterministic dot product over nodes with heat capacity: per block, then in block order. */
static double dot(hearth_scene *s, int a, int b) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    double *part = s->heat.cg_partial;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        const double *node = grid_block(g, k);
        double acc = 0;
        for (int l = 0; l < NPB; l++)
            if (node[CH_HC * NPB + l] > 0) acc += node[a * NPB + l] * node[b * NPB + l];
        part[k] = acc;
    }
    double sum = 0;
    for (int k = 0; k < g->nactive; k++) sum += part[k];
    return sum;
}

static void clear_channel(hearth_scene *s, int ch) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) memset(grid_block(g, k) + ch * NPB, 0, sizeof(double) * (size_t)NPB);
}

hearth_status thermal_prepare(hearth_scene *s, hearth_error *err) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, n = s->ps.n;
    if (n > s->heat.bnd_cap || g->nactive > s->heat.cg_cap) {
        const int nc = n > s->heat.bnd_cap ? n : s->heat.bnd_cap, gc = g->nactive > s->heat.cg_cap ? g->nactive * 2 : s->heat.cg_cap;
        double *a = mem_alloc(sizeof(double) * (size_t)nc), *b = mem_alloc(sizeof(double) * (size_t)nc);
        double *c = mem_alloc(sizeof(double) * (size_t)gc);
        if (!a || !b || !c) {
            mem_free(a, sizeof(double) * (size_t)nc);
            mem_free(b, sizeof(double) * (size_t)nc);
            mem_free(c, sizeof(double) * (size_t)gc);
            return err_set(err, HEARTH_ERR_NOMEM, "out of memory for heat transport (%d particles)", n);
        }
        mem_free(s->heat.bnd_coef, sizeof(double) * (size_t)s->heat.bnd_cap);
        mem_free(s->heat.bnd_temp, sizeof(double) * (size_t)s->heat.bnd_cap);
        mem_free(s->heat.cg_partial, sizeof(double) * (size_t)s->heat.cg_cap);
        s->heat.bnd_coef = a;
        s->heat.bnd_temp = b;
        s->heat.cg_partial = c;
        s->heat.bnd_cap = nc;
        s->heat.cg_cap = gc;
    }
    /* node temperatures (eq. 17): C theta / C */
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double c = node[CH_HC * NPB + l];
            node[CH_T * NPB + l] = c > 0 ? node[CH_T * NPB + l] / c : 0.0;
            node[CH_T0 * NPB + l] = node[CH_T * NPB + l];
            node[CH_R * NPB + l] = node[CH_B * NPB + l] = 0.0;
        }
    }
    find_boundary(s);
    return HEARTH_OK;
}

/* One heat-only pass of the operator (the CG's products). */
static void apply(hearth_scene *s, int in, int out) {
    const transport_pass tp = {.heat_in = in, .heat_out = out, .heat_src = -1, .water = 0};
    transport_apply(s, &tp);
}

void thermal_finish(hearth_scene *s, double dt) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    if (!s->def.heat_implicit) { /* forward Euler (gamma = 0) */
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                const double c = node[CH_HC * NPB + l];
                if (c > 0) node[CH_T * NPB + l] += dt * (node[CH_B * NPB + l] - node[CH_R * NPB + l]) / c;
            }
        }
        return;
    }
    /* backward Euler (gamma = 1): (C/dt + L) x = C/dt theta^n + b, solved by
     * conjugate gradients from x = theta^n; r = b - L theta^n. Preconditioned by
     * the diagonal C/dt: node heat capacities span orders of magnitude between
     * the interior and the edge of a body, and plain CG needed ~480 iterations
     * at a tiny step where the preconditioned one needs a handful.
     * Channels: CH_T = x, CH_CG_R = r, CH_B = z = M^-1 r, CH_CG_P = p, CH_R = Ap. */
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (int k = 0; k < g->nactive; k++) {
        double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double c = node[CH_HC * NPB + l];
            const double r = c > 0 ? node[CH_B * NPB + l] - node[CH_R * NPB + l] : 0.0;
            node[CH_CG_R * NPB + l] = r;
            node[CH_B * NPB + l] = c > 0 ? r * dt / c : 0.0;
            node[CH_CG_P * NPB + l] = node[CH_B * NPB + l];
        }
    }
    /* Stop when the residual is 1e-12 of C theta / dt (theta in degrees C). The
     * residual's sum is all the energy an inexact solve can create, since the
     * conduction operator's columns sum to zero. */
    double scale = 0;
    for (int k = 0; k < g->nactive; k++) {
        const double *node = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            const double v = node[CH_HC * NPB + l] * (fabs(node[CH_T * NPB + l]) + 1.0) / dt;
            scale += v * v;
        }
    }
    scale = sqrt(scale);
    double rz = dot(s, CH_CG_R, CH_B), rr = dot(s, CH_CG_R, CH_CG_R);
    s->heat.cg_iterations = 0;
    for (int it = 0; it < 2000 && sqrt(rr) > 1e-12 * scale; it++) {
        clear_channel(s, CH_R);
        apply(s, CH_CG_P, CH_R);
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                const double c = node[CH_HC * NPB + l];
                node[CH_R * NPB + l] = c > 0 ? node[CH_R * NPB + l] + c / dt * node[CH_CG_P * NPB + l] : 0.0;
            }
        }
        const double pAp = dot(s, CH_CG_P, CH_R);
        if (!(pAp > 0)) break;
        const double alpha = rz / pAp;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                const double c = node[CH_HC * NPB + l];
                if (!(c > 0)) continue;
                node[CH_T * NPB + l] += alpha * node[CH_CG_P * NPB + l];
                node[CH_CG_R * NPB + l] -= alpha * node[CH_R * NPB + l];
                node[CH_B * NPB + l] = node[CH_CG_R * NPB + l] * dt / c;
            }
        }
        const double rz2 = dot(s, CH_CG_R, CH_B), beta = rz2 / rz;
        rz = rz2;
        rr = dot(s, CH_CG_R, CH_CG_R);
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) node[CH_CG_P * NPB + l] = node[CH_B * NPB + l] + beta * node[CH_CG_P * NPB + l];
        }
        s->heat.cg_iterations = it + 1;
    }
}

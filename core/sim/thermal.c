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
 *
 * Boundaries relax toward the outside temperature: the flux into the body is
 * S beta (theta_out - theta) (the printed signs in §4/§6.3 are ambiguous; the
 * analytic slab test decides). Boundary particles and their areas S come from
 * boundary.c (§6.6).
 * Heated colliders act on particles within dx of them, each carrying V_p/dx
 * of contact area (a band of thickness dx sums to the contact area).
 *
 * The expansion term uses absolute temperature (theta + 273.15): in degrees C
 * it would change sign at the freezing point. */
#include "thermal.h"

#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "scene.h"
#include "tensor.h"

#define KELVIN 273.15

int thermal_active(const hearth_scene *s) { return (s->ps.enabled & (1u << PC_TEMPERATURE)) != 0; }

double thermal_dt_limit(const hearth_scene *s) {
    if (!thermal_active(s) || s->def.heat_implicit) return INFINITY;
    /* the strongest boundary coupling: a node's heat capacity against S beta */
    double beta = isnan(s->def.oven_temperature) ? 0 : s->def.oven_beta;
    for (int c = 0; c < s->ncol; c++)
        if (!isnan(s->cols[c].temperature) && s->cols[c].beta > beta) beta = s->cols[c].beta;
    double dt = INFINITY;
    for (int m = 0; m < s->nmat; m++) {
        const material_slot *ms = &s->mats[m];
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
    for (int i = 0; i < s->ps.n; i++) e += m[i] * s->mats[mat[i]].core[CP_SPECIFIC_HEAT] * (T[i] + KELVIN);
    return e;
}

/* ---- boundary coefficients ------------------------------------------- */

/* Fills s->bnd_coef (S beta, W/K) and s->bnd_temp (degrees C) per particle
 * from the air boundary (boundary.c) and the heated colliders. */
static void find_boundary(hearth_scene *s) {
    const grid *g = &s->g;
    particles *ps = &s->ps;
    const int n = ps->n;
    double *coef = s->bnd_coef, *temp = s->bnd_temp;
    memset(coef, 0, sizeof(double) * (size_t)n);
    memset(temp, 0, sizeof(double) * (size_t)n);
    const double *X = pcold(ps, PC_X), *V0 = pcold(ps, PC_VOL0), *Fc = pcold(ps, PC_F);
    int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    if (!isnan(s->def.oven_temperature) && s->def.oven_beta > 0)
        for (int i = 0; i < n; i++)
            if (s->bnd_area[i] > 0) {
                coef[i] = s->bnd_area[i] * s->def.oven_beta;
                temp[i] = s->def.oven_temperature;
            }
    /* heated colliders: the band within dx of the surface */
    for (int c = 0; c < s->ncol; c++) {
        const collider *col = &s->cols[c];
        if (isnan(col->temperature) || col->beta <= 0) continue;
        for (int i = 0; i < n; i++) {
            const double *x = X + 3 * i;
            if (!collider_near(col, x) || collider_sdf(col, x, NULL) >= g->dx) continue;
            const double Vp = V0[i] * t3_det(Fc + 9 * i);
            /* a particle touching both air and the pan: the pan's temperature wins the ambient, areas add */
            const double cS = Vp / g->dx * col->beta;
            temp[i] = coef[i] > 0 ? (temp[i] * coef[i] + col->temperature * cS) / (coef[i] + cS) : col->temperature;
            coef[i] += cS;
            if (flags) flags[i] |= PF_BOUNDARY;
        }
    }
}

/* ---- the operator ------------------------------------------------------ */

/* Node of a tile: the tile spans GRID_T nodes per axis from the block origin,
 * i.e. the block and its +1 neighbours (as in P2G). */
static double *tile_node(const grid *g, const int bc[3], int a, int b, int c, int *l) {
    const int D = g->dim;
    const int blk = grid_block_id(g, bc[0] + a / GRID_B, bc[1] + b / GRID_B, bc[2] + (D == 3 ? c / GRID_B : 0));
    *l = D == 2 ? (a % GRID_B) * GRID_B + b % GRID_B : ((a % GRID_B) * GRID_B + b % GRID_B) * GRID_B + c % GRID_B;
    return grid_block(g, g->slot[blk]);
}

static void apply_block(hearth_scene *s, int q, int in, int out, int src, double *tin, double *tout, double *tsrc) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int D = g->dim, NPB = g->nodes_per_block, TN = D == 2 ? GRID_T * GRID_T : GRID_T * GRID_T * GRID_T;
    const pblock pb = s->pb[s->colour_pb[q]];
    int bc[3];
    grid_block_coords(g, pb.block, bc);
    for (int a = 0; a < GRID_T; a++) /* gather the input once into a dense tile */
        for (int b = 0; b < GRID_T; b++)
            for (int c = 0; c < (D == 3 ? GRID_T : 1); c++) {
                int l;
                const double *node = tile_node(g, bc, a, b, c, &l);
                tin[D == 2 ? a * GRID_T + b : (a * GRID_T + b) * GRID_T + c] = node[in * NPB + l];
            }
    memset(tout, 0, sizeof(double) * (size_t)TN);
    if (src >= 0) memset(tsrc, 0, sizeof(double) * (size_t)TN);
    const double *X = pcold(ps, PC_X), *V0 = pcold(ps, PC_VOL0), *Fc = pcold(ps, PC_F), *Cc = pcold(ps, PC_C);
    const double *T = pcold(ps, PC_TEMPERATURE);
    const int *mat = pcoli(ps, PC_MAT);
    for (int i = pb.start; i < pb.end; i++) {
        int base[3] = {0, 0, 0};
        double w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3][3] = {{0}};
        for (int d = 0; d < D; d++) {
            const double Xd = (X[3 * i + d] - g->lo[d]) * g->inv_dx;
            const int bb = (int)floor(Xd - 0.5);
            bspline_weights(Xd - bb, w[d], dw[d]);
            for (int k = 0; k < 3; k++) dw[d][k] *= g->inv_dx;
            base[d] = bb - bc[d] * GRID_B;
        }
        const material_slot *ms = &s->mats[mat[i]];
        const double J = t3_det(Fc + 9 * i), Vp = V0[i] * J, kap = ms->core[CP_CONDUCTIVITY];
        double xp = 0, gx[3] = {0, 0, 0};
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                    const double wc = D == 3 ? w[2][c] : 1.0, v = tin[D == 2 ? (base[0] + a) * GRID_T + base[1] + b
                                                                               : ((base[0] + a) * GRID_T + base[1] + b) * GRID_T + base[2] + c];
                    xp += w[0][a] * w[1][b] * wc * v;
                    gx[0] += dw[0][a] * w[1][b] * wc * v;
                    gx[1] += w[0][a] * dw[1][b] * wc * v;
                    if (D == 3) gx[2] += w[0][a] * w[1][b] * dw[2][c] * v;
                }
        const double qk[3] = {Vp * kap * gx[0], Vp * kap * gx[1], Vp * kap * gx[2]};
        const double bcoef = s->bnd_coef[i];
        double source = 0;
        if (src >= 0) {
            source = bcoef * s->bnd_temp[i];
            const double cl = ms->core[CP_EXPANSION];
            if (cl > 0) source -= V0[i] * cl * (T[i] + KELVIN) * (Cc[9 * i] + Cc[9 * i + 4] + Cc[9 * i + 8]);
        }
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                    const double wc = D == 3 ? w[2][c] : 1.0, wt = w[0][a] * w[1][b] * wc;
                    const double g0 = dw[0][a] * w[1][b] * wc, g1 = w[0][a] * dw[1][b] * wc,
                                 g2 = D == 3 ? w[0][a] * w[1][b] * dw[2][c] : 0.0;
                    const int t = D == 2 ? (base[0] + a) * GRID_T + base[1] + b
                                         : ((base[0] + a) * GRID_T + base[1] + b) * GRID_T + base[2] + c;
                    tout[t] += g0 * qk[0] + g1 * qk[1] + g2 * qk[2] + wt * bcoef * xp;
                    if (src >= 0) tsrc[t] += wt * source;
                }
    }
    for (int a = 0; a < GRID_T; a++) /* flush into the block and its +1 neighbours */
        for (int b = 0; b < GRID_T; b++)
            for (int c = 0; c < (D == 3 ? GRID_T : 1); c++) {
                const int t = D == 2 ? a * GRID_T + b : (a * GRID_T + b) * GRID_T + c;
                int l;
                double *node = tile_node(g, bc, a, b, c, &l);
                node[out * NPB + l] += tout[t];
                if (src >= 0) node[src * NPB + l] += tsrc[t];
            }
}

/* One coloured particle pass: out_i += (L x)_i with
 *   (L x)_i = sum_p grad w_ip . (V_p kappa_p grad x_p) + sum_p S_p beta_p w_ip x_p,
 * and, when src >= 0, src_i += sum_p w_ip (S_p beta_p theta_out,p + e_p), the
 * sources: boundary ambient and the expansion term e_p = -V0 c lambda theta_abs div v.
 * Each particle block works in dense tiles, as P2G does; colours keep it
 * deterministic and free of atomics. */
static void apply(hearth_scene *s, int in, int out, int src) {
    for (int col = 0; col < 8; col++) {
#pragma omp parallel if (s->ps.n >= SCENE_PARALLEL_MIN)
        {
            double tin[GRID_T * GRID_T * GRID_T], tout[GRID_T * GRID_T * GRID_T], tsrc[GRID_T * GRID_T * GRID_T];
#pragma omp for schedule(dynamic, 2)
            for (int q = s->colour_start[col]; q < s->colour_start[col + 1]; q++) apply_block(s, q, in, out, src, tin, tout, tsrc);
        }
    }
}

/* Deterministic dot product over nodes with heat capacity: per block, then in block order. */
static double dot(hearth_scene *s, int a, int b) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block;
    double *part = s->cg_partial;
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

hearth_status thermal_grid_update(hearth_scene *s, double dt, hearth_error *err) {
    grid *g = &s->g;
    const int NPB = g->nodes_per_block, n = s->ps.n;
    if (n > s->bnd_cap || g->nactive > s->cg_cap) {
        const int nc = n > s->bnd_cap ? n : s->bnd_cap, gc = g->nactive > s->cg_cap ? g->nactive * 2 : s->cg_cap;
        double *a = mem_alloc(sizeof(double) * (size_t)nc), *b = mem_alloc(sizeof(double) * (size_t)nc);
        double *c = mem_alloc(sizeof(double) * (size_t)gc);
        if (!a || !b || !c) {
            mem_free(a, sizeof(double) * (size_t)nc);
            mem_free(b, sizeof(double) * (size_t)nc);
            mem_free(c, sizeof(double) * (size_t)gc);
            return err_set(err, HEARTH_ERR_NOMEM, "out of memory for heat transport (%d particles)", n);
        }
        mem_free(s->bnd_coef, sizeof(double) * (size_t)s->bnd_cap);
        mem_free(s->bnd_temp, sizeof(double) * (size_t)s->bnd_cap);
        mem_free(s->cg_partial, sizeof(double) * (size_t)s->cg_cap);
        s->bnd_coef = a;
        s->bnd_temp = b;
        s->cg_partial = c;
        s->bnd_cap = nc;
        s->cg_cap = gc;
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
    /* sources into CH_B, L theta^n into CH_R */
    apply(s, CH_T, CH_R, CH_B);
    if (!s->def.heat_implicit) { /* forward Euler (gamma = 0) */
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int k = 0; k < g->nactive; k++) {
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                const double c = node[CH_HC * NPB + l];
                if (c > 0) node[CH_T * NPB + l] += dt * (node[CH_B * NPB + l] - node[CH_R * NPB + l]) / c;
            }
        }
        return HEARTH_OK;
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
    s->cg_iterations = 0;
    for (int it = 0; it < 2000 && sqrt(rr) > 1e-12 * scale; it++) {
        clear_channel(s, CH_R);
        apply(s, CH_CG_P, CH_R, -1);
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
        s->cg_iterations = it + 1;
    }
    return HEARTH_OK;
}

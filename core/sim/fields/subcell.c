/* subcell.c: heat exchanged inside a cell among dried particles (issue #18).
 *
 * Why. FLIP (Ding et al. 2019 eq. 21) hands a particle its nodes' temperature
 * change, never their value, so a difference between particles that share
 * nodes is never damped: the B-spline field averages it away and the
 * particles keep it. Under latent_heat it grows: water_boil holds a wet
 * particle at the boiling point while a dried neighbour on the same nodes
 * keeps its full share of the heat the nodes take. The dried crust's own
 * temperatures (what browning integrates) then scatter about the right field
 * by more as dx falls (docs/validation.md, "Dried particles take the field's
 * temperature" and "Sub-cell exchange among dried particles").
 *
 * What. Real conduction damps a mode of wavelength dx at the rate
 *   r = kappa (2 pi / dx)^2 / (rho alpha) = pi^2 kappa / (rho alpha (dx/2)^2)
 * (the sub-cell mode's decay, taken at the dried material's kappa and alpha,
 * the crust this acts on). Each dried particle p (moisture ratio under 0.01,
 * past water_boil's hold) relaxes, over the fields' time dt, by
 *   dT_p = k_p sum_i w_ip (fit_i(x_p) - T0_p),  k_p = 1 - exp(-r_p dt),
 *   fit_i(x) = Tbar_i + G_i . (x - xbar_i),
 *   Tbar_i = S_i / W_i,  S_i = sum_p w_ip a_p T0_p,  W_i = sum_p w_ip a_p,
 *   xbar_i = x_i + M_i / W_i,  M_i = sum_p w_ip a_p (x_p - x_i),
 *   a_p = k_p C_p,  C_p = m_p alpha_p(w_p)  (material_specific_heat_of),
 * T0 the particles' step-start temperatures (P2G's), nodes with W_i = 0
 * skipped, G_i the dried particles' gradient at node i fitted to its
 * neighbours (node_fit). Summed with weights C_p this is
 *   sum_i [W_i Tbar_i - S_i + G_i . (M_i - W_i (xbar_i - x_i))] = 0
 * for any G_i: exactly conserving, node by node, for any mix of materials
 * (k_p is folded into the weight for that). Wet particles take no part, so
 * no heat is moved into the boiling front and the kink between the dried
 * profile and the wet rows at the boiling point stays: the exchange acts on
 * a particle's difference from the dried particles' own field, not from the
 * B-spline average over wet and dried (helper boilflip's relaxations toward
 * that average moved heat into the front or lost it). The fit's gradient
 * makes it exact on a linear profile everywhere, at the surface and beside
 * the wet rows too: toward Tbar_i alone the one-sided nodes at the dried
 * set's edges pulled the hot top down and pushed heat into the front (the
 * drying slab's 1 mm top 129.9 against 142.7 degC; docs/validation.md).
 * Part-dried particles weighted by their dryness 1 - X/X0 took heat into the
 * boiling zone and cooled the coarse crust: only dried ones take part.
 *
 * Rejected: a relaxation toward CH_T or CH_T0 (the average over every
 * particle; docs/validation.md lists the five that broke the front or the
 * books); a source deposited on the grid for the next solve (a step's lag).
 *
 * Order. Serial over the particles in their sorted order (the same at any
 * thread count); on MPI slabs the node sums go through the halo exchange
 * (mpm_ranks_fields_sum), in the replicated mode every rank holds every
 * particle and computes the same. */
#include "subcell.h"

#include <math.h>
#include <stddef.h>
#include <string.h>

#include "scene.h"
#include "mpm.h"
#include "material.h"
#include "grid.h"
#include "alloc.h"
#include "error.h"
#include "hearth/tensor.h"

#define SUBCELL_PI 3.14159265358979323846

/* A fitted gradient direction needs the neighbours' centroids to spread by
 * at least this (in dx^2; node_fit): measured, not derived (docs/validation.md,
 * "Sub-cell exchange among dried particles": 0.01-0.1 broke the unit test's
 * exactness at a block's corners, none of them ran away in the loaf). */
#define SUBCELL_SPAN 0.005

/* Only dried particles take part, weight 1 (header: part-dried ones weighted
 * by 1 - X/X0 took heat into the boiling zone). */
static double dryness(const material_slot *ms, const particles *ps, int i) {
    return material_moisture_ratio(ms, ps, i) < 0.01 ? 1.0 : 0.0;
}

int subcell_dried(const hearth_scene *s, int i) {
    const particles *ps = &s->ps;
    if (!(s->def.latent_heat && (ps->enabled & (1u << PC_WATER)))) return 0;
    if ((ps->enabled & (1u << PC_FLAGS)) && (pcoli(ps, PC_FLAGS)[i] & PF_HOLD_T)) return 0;
    return dryness(&s->mats.slot[pcoli(ps, PC_MAT)[i]], ps, i) > 0;
}

/* The sub-cell rate of a dried particle of material ms (1/s). */
static double subcell_rate(const material_slot *ms, double dx) {
    const double kd = ms->core[CP_DRY_CONDUCTIVITY] > 0 ? ms->core[CP_DRY_CONDUCTIVITY] : ms->core[CP_CONDUCTIVITY];
    const double rho = ms->params[ms->density_index], ad = material_specific_heat_min(ms), h = 0.5 * dx;
    return rho > 0 && ad > 0 ? SUBCELL_PI * SUBCELL_PI * kd / (rho * ad * h * h) : 0.0;
}

/* The scratch channels, dead after thermal_finish until the next step's P2G
 * (grid.c: written whole before read): W_i, S_i, and the first moments
 * sum_p w_ip a_p (x_p - x_i) along each axis. */
enum { SC_W = CH_R, SC_S = CH_B };
static const int SC_M[3] = {CH_CG_P, CH_CG_R, CH_HC};

/* Node gi's dried mean Tbar, the dried particles' centroid xbar, and the
 * gradient G of the dried particles' field there: the least-squares fit of
 * Tbar_j - Tbar_i = G . (xbar_j - xbar_i) over its neighbours j that hold
 * dried particles (weighted by W_j), exact for a linear profile whatever the
 * particles' places. G = 0 where the neighbours do not span the dimensions.
 * Returns 0 where the node holds no dried particle. */
static int node_fit(const grid *g, const int gi[3], double *Tbar, double xbar[3], double G[3]) {
    const int D = g->dim, NPB = g->nodes_per_block;
    int l;
    const double *node = grid_node_at(g, gi, &l);
    if (!node || !(node[SC_W * NPB + l] > 0)) return 0;
    const double Wi = node[SC_W * NPB + l];
    *Tbar = node[SC_S * NPB + l] / Wi;
    for (int d = 0; d < 3; d++) xbar[d] = d < D ? g->lo[d] + gi[d] * g->dx + node[SC_M[d] * NPB + l] / Wi : 0.0, G[d] = 0;
    double A[3][3] = {{0}}, b[3] = {0}, wsum = 0; /* wsum: the neighbours' weight, for the spread's normalisation */
    for (int a = -1; a <= 1; a++)
        for (int c = -1; c <= 1; c++)
            for (int e = (D == 3 ? -1 : 0); e <= (D == 3 ? 1 : 0); e++) {
                if (!a && !c && !e) continue;
                const int gj[3] = {gi[0] + a, gi[1] + c, gi[2] + e};
                int lj;
                const double *nj = grid_node_at(g, gj, &lj);
                if (!nj || !(nj[SC_W * NPB + lj] > 0)) continue;
                const double Wj = nj[SC_W * NPB + lj], dT = nj[SC_S * NPB + lj] / Wj - *Tbar;
                wsum += Wj;
                double r[3];
                for (int d = 0; d < D; d++) r[d] = g->lo[d] + gj[d] * g->dx + nj[SC_M[d] * NPB + lj] / Wj - xbar[d];
                for (int p = 0; p < D; p++) {
                    b[p] += Wj * r[p] * dT;
                    for (int q = 0; q < D; q++) A[p][q] += Wj * r[p] * r[q];
                }
            }
    /* G = A^+ b over the directions the neighbours span well: the eigenvalues of A / sum W_j are the
     * neighbours' spread squared (3/4 dx^2 along each axis for a full 3^dim neighbourhood); a direction with
     * under SUBCELL_SPAN dx^2 (a single row of dried particles, a corner) is left out, G's component there 0.
     * Without this a row whose centroids lie almost on a line got gradients of 5e6 K/m across it, and the
     * fit's extrapolation ran away (the loaf's base, dx 2.5 mm). */
    const double floor_ = SUBCELL_SPAN * g->dx * g->dx * wsum;
    if (!(wsum > 0)) return 1;
    if (D == 2) { /* the 2x2 in closed form (most scenes; the Jacobi sweeps below cost a drying bake 40%) */
        const double m = 0.5 * (A[0][0] + A[1][1]), h = 0.5 * (A[0][0] - A[1][1]), r = hypot(h, A[0][1]);
        const double l0 = m - r, l1 = m + r;
        if (l0 > floor_) { /* both directions: A^-1 b */
            const double det = A[0][0] * A[1][1] - A[0][1] * A[0][1];
            G[0] = (b[0] * A[1][1] - b[1] * A[0][1]) / det;
            G[1] = (A[0][0] * b[1] - A[0][1] * b[0]) / det;
        } else if (l1 > floor_) { /* the larger one's eigenvector (h + r, A01), or (A01, r - h) when h < 0 */
            double v0 = h >= 0 ? h + r : A[0][1], v1 = h >= 0 ? A[0][1] : r - h;
            const double nv = hypot(v0, v1);
            v0 /= nv, v1 /= nv;
            const double vb = (v0 * b[0] + v1 * b[1]) / l1;
            G[0] = v0 * vb, G[1] = v1 * vb;
        }
        return 1;
    }
    double S[9], lam[3], Q[9];
    for (int p = 0; p < 3; p++)
        for (int q = 0; q < 3; q++) S[3 * p + q] = A[p][q];
    hearth_t3_sym_eigen(S, lam, Q);
    for (int k = 0; k < 3; k++) {
        if (!(lam[k] > floor_)) continue;
        double vb = 0; /* column k of Q is the eigenvector */
        for (int p = 0; p < D; p++) vb += Q[3 * p + k] * b[p];
        for (int p = 0; p < D; p++) G[p] += Q[3 * p + k] * vb / lam[k];
    }
    return 1;
}

/* k = 1 - exp(-r dt) of material m, memoised on the last material asked (the sorted particles come in runs) */
typedef struct k_memo {
    int mat;
    double k;
} k_memo;
static double k_of(const hearth_scene *s, k_memo *km, int m, double fdt) {
    if (m != km->mat) km->mat = m, km->k = -expm1(-subcell_rate(&s->mats.slot[m], s->g.dx) * fdt);
    return km->k;
}

/* Particle i's share of its nodes' fit this step, k phi: 0 for a particle held at its temperature or still wet
 * (both passes below select by it) */
static double relax_share(const hearth_scene *s, k_memo *km, const int *flags, int i, double fdt) {
    if (flags && (flags[i] & PF_HOLD_T)) return 0.0;
    const int m = pcoli(&s->ps, PC_MAT)[i];
    const double phi = dryness(&s->mats.slot[m], &s->ps, i);
    if (!(phi > 0)) return 0.0;
    return k_of(s, km, m, fdt) * phi;
}

hearth_status subcell_exchange(hearth_scene *s, double fdt, hearth_error *err) {
    particles *ps = &s->ps;
    grid *g = &s->g;
    if (!(s->def.latent_heat && (ps->enabled & (1u << PC_WATER)) && (ps->enabled & (1u << PC_TEMPERATURE)))) return HEARTH_OK;
    const int D = g->dim, NPB = g->nodes_per_block, n = ps->n;
    const double *X = pcold(ps, PC_X), *M = pcold(ps, PC_MASS), *Wc = pcold(ps, PC_WATER);
    const int *mat = pcoli(ps, PC_MAT);
    const int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    double *T = pcold(ps, PC_TEMPERATURE);
    int any = 0;
    for (int i = 0; i < n && !any; i++)
        any = !(flags && (flags[i] & PF_HOLD_T)) && dryness(&s->mats.slot[mat[i]], ps, i) > 0;
    /* every rank must take part in the slab exchange below, so only a scene of one rank may stop here */
    if (!any && s->mpm->nranks == 1) return HEARTH_OK;
    k_memo km = {-1, 0.0};
    const int nch = 2 + D, chs[5] = {SC_W, SC_S, SC_M[0], SC_M[1], SC_M[2]};
    for (int k = 0; k < g->nactive; k++) {
        double *d = grid_block(g, k);
        for (int c = 0; c < nch; c++) memset(d + chs[c] * NPB, 0, sizeof(double) * (size_t)NPB);
    }
    /* W_i, S_i and the first moments */
    for (int i = 0; i < n; i++) {
        const double r = relax_share(s, &km, flags, i, fdt);
        if (!(r > 0)) continue;
        const double a = r * M[i] * material_specific_heat_of(&s->mats.slot[mat[i]], ps, i, Wc[i]);
        if (!(a > 0)) continue;
        grid_point_nodes pn;
        grid_point_nodes_of(g, X + 3 * i, &pn);
        for (int j = 0; j < pn.n; j++) {
            double *node = pn.node[j];
            const int l = pn.l[j], *gi = pn.gi[j];
            const double wt = pn.w[j];
            node[SC_W * NPB + l] += wt * a;
            node[SC_S * NPB + l] += wt * a * T[i];
            for (int d = 0; d < D; d++) node[SC_M[d] * NPB + l] += wt * a * (X[3 * i + d] - (g->lo[d] + gi[d] * g->dx));
        }
    }
    hearth_status st = mpm_ranks_fields_sum(s, chs, nch, err);
    if (st) return st;
    /* each node's fit once: fit(x) = f_i + G_i . (x - x_i), f_i = Tbar_i + G_i . (x_i - xbar_i), the value at
     * the node (NaN where it holds no dried particle) */
    const size_t nf = (size_t)(1 + D), need = (size_t)g->nactive * (size_t)NPB * nf;
    if (need > s->heat.sub_cap) {
        double *f = mem_alloc(sizeof(double) * need);
        if (!f) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the dried particles' node fits (%zu nodes)",
                               (size_t)g->nactive * (size_t)NPB);
        mem_free(s->heat.sub_fit, sizeof(double) * s->heat.sub_cap);
        s->heat.sub_fit = f, s->heat.sub_cap = need;
    }
    double *fit = s->heat.sub_fit;
    for (int k = 0; k < g->nactive; k++) {
        int bc[3];
        grid_block_coords(g, g->active[k], bc);
        const double *blk = grid_block(g, k);
        for (int l = 0; l < NPB; l++) {
            int gi[3];
            double *f = fit + ((size_t)k * (size_t)NPB + (size_t)l) * nf, Tb, xb[3], G[3];
            if (!(blk[SC_W * NPB + l] > 0)) { /* most nodes of a bake hold no dried particle */
                f[0] = NAN;
                continue;
            }
            grid_node_index(g, bc, l, gi);
            if (!node_fit(g, gi, &Tb, xb, G)) {
                f[0] = NAN;
                continue;
            }
            f[0] = Tb;
            for (int d = 0; d < D; d++) f[0] += G[d] * (g->lo[d] + gi[d] * g->dx - xb[d]), f[1 + d] = G[d];
        }
    }
    /* each dried particle toward its nodes' fits, from the same step-start values (the sums above read T
     * before any particle changes). Summed with weights C_p the change is sum_i [W_i f_i + G_i . M_i - S_i]
     * = sum_i [W_i Tbar_i - S_i + G_i . (M_i - W_i (xbar_i - x_i))] = 0 for any G_i, M_i the first moments
     * (xbar_i - x_i = M_i / W_i). */
    const size_t stride = (size_t)g->nch * (size_t)NPB;
    for (int i = 0; i < n; i++) {
        const double r = relax_share(s, &km, flags, i, fdt);
        if (!(r > 0)) continue; /* C_p = 0 would add nothing to the books either way */
        grid_point_nodes pn;
        grid_point_nodes_of(g, X + 3 * i, &pn);
        double sum = 0;
        for (int j = 0; j < pn.n; j++) {
            const double *node = pn.node[j];
            const int l = pn.l[j], *gi = pn.gi[j];
            const double wt = pn.w[j];
            const double *f = fit + ((size_t)((node - g->data) / (ptrdiff_t)stride) * (size_t)NPB + (size_t)l) * nf;
            if (isnan(f[0])) continue;
            double v = f[0];
            for (int d = 0; d < D; d++) v += f[1 + d] * (X[3 * i + d] - (g->lo[d] + gi[d] * g->dx));
            sum += wt * (v - T[i]);
        }
        T[i] += r * sum;
    }
    return HEARTH_OK;
}

/* sph_forces.c: the SPH momentum equation's right-hand side and the kick
 * (Rodriguez-Arenas 2011, equation numbers the thesis's): the artificial
 * stress against the tensile instability (Monaghan 2000), then per particle
 * the pair sums of pressure (eq. 3.18), artificial viscosity (eq. 3.41),
 * deviatoric and artificial stress, viscosity (eq. 3.19) with no-slip walls,
 * surface tension (eq. 3.30) and gravity, and the kick into st->vnew.
 * Phases of sph_step (sph.c), moved here to keep sph.c one file's length. */
#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "sph_kernel.h"
#include "sph_state.h"
#include "tensor.h"

/* Artificial stress against the tensile instability (Monaghan 2000,
 * J. Comput. Phys. 159, 290-311; Gray, Monaghan & Swift 2001, Comput.
 * Methods Appl. Mech. Engrg. 190, 6641-6662, for elastic solids). Under
 * tension, SPH particles attract their neighbours more the closer they
 * are, so they clump in pairs and strings and a stretched body breaks
 * (bread of the dead split along its toppings). In the principal frame
 * of sigma = S - p I each tensile component sigma'_k > 0 gets
 * R'_k = -epsilon sigma'_k / rho^2 (compressive ones 0); rotated back,
 * R_a enters the momentum equation as sum_b m_b f_ab^n (R_a + R_b) .
 * grad_a W with f_ab = W(r_ab) / W(dp), dp the rest spacing, n = 4: a
 * short-range repulsion that is strong exactly where particles clump
 * (r < dp) and negligible at the rest spacing's neighbours beyond.
 * Off by default (sph.artificial_stress = 0): the same repulsion resists
 * a cooling bubble's contraction (at 0.3 it loses 31% less volume than
 * its gas, `sph_bubble_cooling_contracts`); bread of the dead sets 0.3. */
void sph_artificial_stress(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const int n = s->ps.n;
    const double eps_as = s->def.sph.artificial_stress;
    if (!(eps_as > 0)) return;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        double sig[9], l[3], Q[9], *Ri = st->R + 9 * i;
        for (int a = 0; a < 9; a++) sig[a] = st->S[9 * i + a] - (a % 4 == 0 ? st->prs[i] : 0.0);
        t3_sym_eigen(sig, l, Q);
        double r[3];
        for (int k = 0; k < 3; k++) r[k] = l[k] > 0 ? -eps_as * l[k] / (st->rho[i] * st->rho[i]) : 0.0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++) { /* R = Q diag(r) Q^T */
                Ri[3 * a + b] = 0;
                for (int k = 0; k < 3; k++) Ri[3 * a + b] += Q[3 * a + k] * r[k] * Q[3 * b + k];
            }
    }
}

/* Particle i's pair sums of sph_forces into a[] and *drag, with dim, wall
 * (i has a wall frame) and as (artificial stress on) constants in each copy.
 * In 2D the z components are left out: every particle's z and the z of every
 * velocity are 0 there, so each z term is a zero added to a sum that started
 * at +0, and a zero changes no such sum (the same bits). Without a wall frame
 * no pair is a wall pair, so drag stays 0. Prr holds P_j / rho_j^2 (the same
 * division as per pair, once per particle). */
static inline __attribute__((always_inline)) void forces_pairs(const struct sph_state *st, const sph_cols *c, int i,
                                                                const int dim, const int wall, const int as,
                                                                double av_beta, double eps_as, const double wn[3],
                                                                double da, double dah, double a[3], double *drag) {
    const int *flags = c->flags;
    const double *x = c->x, *v = c->v, *m = c->m;
    const int *off = st->nl.off, *nb = st->nl.j;
    const double *h = st->h, *rho = st->rho, *Prr = st->perm, *mu = st->mu, *vc = st->vc;
    const double ri = rho[i], Pi = Prr[i], *Si = st->S + 9 * i, hi = h[i], mui = mu[i], vci = vc[i];
    const sph_kc kci = sph_kc_of(dim, hi);
    double dr = 0;
    for (int k = off[i]; k < off[i + 1]; k++) {
        const int j = nb[k];
        double d[3];
        sph_disp_dim(&st->cells, dim, x + 3 * i, x + 3 * j, d);
        const double r2 = dim == 3 ? d[0] * d[0] + d[1] * d[1] + d[2] * d[2] : d[0] * d[0] + d[1] * d[1], r = sqrt(r2);
        if (r <= 0) continue;
        SPH_PAIR_KC(kc, dim, kci, hi, h[j]);
        const double hij = kc->h, rj = rho[j];
        const double g = sph_dw_kc(kc, r) / r; /* grad_i W = g d */
        double vij[3], vd = 0;
        for (int q = 0; q < dim; q++) {
            vij[q] = v[3 * i + q] - v[3 * j + q];
            vd += vij[q] * d[q];
        }
        double Pij = Pi + Prr[j]; /* eq. 3.18 */
        if (av_beta > 0 && vd < 0) { /* eq. 3.41, with mu_ij of eq. 3.37 */
            const double muij = hij * vd / (r2 + 0.01 * hij * hij);
            Pij += av_beta * muij * muij / (0.5 * (ri + rj));
        }
        const double *Sj = st->S + 9 * j, lv = sph_lap_visc_kc(kc, r);
        /* eq. 3.19 over rho_i; its Laplacian renormalised (sph_viscous_factor), the pair's mean factor so
         * the pair's forces stay equal and opposite */
        const double visc = 0.5 * (mui + mu[j]) * m[j] / (rj * ri) * lv * 0.5 * (vci + vc[j]);
        /* a wall particle's velocity for eq. 3.19: Morris et al. 1997 (sph_wall_frame) */
        const int wj = wall && (flags[j] & PF_FIXED);
        const double beta = wj ? sph_wall_beta(d, wn, da, dah) : 1.0;
        double fn = 0; /* f_ab^4 of the artificial stress */
        if (as) {
            const double dp = 0.5 * (st->sp[i] + st->sp[j]);
            const double f = sph_w_kc(kc, r) / sph_w_kc(kc, dp);
            fn = f * f * f * f;
        }
        const double *Ri = st->R + 9 * i, *Rj = st->R + 9 * j;
        for (int q = 0; q < dim; q++) {
            double sd = 0;
            for (int b = 0; b < dim; b++) sd += (Si[3 * q + b] + Sj[3 * q + b]) * d[b]; /* S / rho^2 (above) */
            if (as && fn > 0)
                for (int b = 0; b < dim; b++) sd += fn * (Ri[3 * q + b] + Rj[3 * q + b]) * d[b];
            /* with a wall b: -visc beta (v_a - V_b), V_b the wall's own (prescribed) velocity; the
             * beta v_a part is the implicit drag below */
            a[q] += m[j] * (-Pij * g * d[q] + sd * g) - (wj ? -visc * beta * v[3 * j + q] : visc * vij[q]);
        }
        if (wall) dr += wj ? visc * beta : 0.0;
    }
    *drag = dr;
    (void)eps_as;
}

/* The symmetric path (sph_forces): without wall frames and artificial
 * stress, particle j's pair term from i is particle i's from j with d and
 * v_i - v_j negated and m_i for m_j, so each pair is evaluated once, by
 * its lower index, into both particles' list slots (st->pairc, dim doubles
 * per list entry): i's own at k, j's at the slot of its list that holds i.
 * Each particle then sums its slots in its list order, the order the
 * per-particle loop adds them in, so the sums are the same. The negations
 * are exact and every other factor is a sum or product of the pair's two
 * values (0.5 (mu_i + mu_j), rho_j rho_i, h_ij, ...), which commute, so a
 * slot holds the bits the per-particle loop adds. Returns the pairs it
 * wrote, or -1 when one is not as the path needs (coincident particles, or
 * j's list lacking i): sph_forces then takes the per-particle loop, as it
 * does when the pairs written do not fill every slot. */
static inline __attribute__((always_inline)) int pairs_once(const struct sph_state *st, const sph_cols *c, int i,
                                                             const int dim, const int uni, double av_beta,
                                                             const int *mir, double *pc) {
    const double *x = c->x, *v = c->v, *m = c->m;
    const int *off = st->nl.off, *nb = st->nl.j;
    const double *h = st->h, *rho = st->rho, *Prr = st->perm, *mu = st->mu, *vc = st->vc;
    const double ri = rho[i], Pi = Prr[i], *Si = st->S + 9 * i, hi = h[i], mui = mu[i], vci = vc[i], mi = m[i];
    const sph_kc kci = sph_kc_of(dim, hi);
    int np = 0;
    for (int k = off[i + 1] - 1; k >= off[i] && nb[k] > i; k--, np++) { /* the lists ascend: j > i at the end */
        const int j = nb[k], p = mir[k]; /* i in j's list (pair_mirror) */
        double d[3];
        sph_disp_dim(&st->cells, dim, x + 3 * i, x + 3 * j, d);
        const double r2 = dim == 3 ? d[0] * d[0] + d[1] * d[1] + d[2] * d[2] : d[0] * d[0] + d[1] * d[1], r = sqrt(r2);
        if (!(r > 0)) return -1;
        SPH_PAIR_KC(kcp, dim, kci, hi, uni ? hi : h[j]);
        const sph_kc *kc = uni ? &kci : kcp; /* uni: every h_j is h_i */
        const double hij = kc->h, rj = rho[j];
        const double g = sph_dw_kc(kc, r) / r;
        double vij[3], vd = 0;
        for (int q = 0; q < dim; q++) {
            vij[q] = v[3 * i + q] - v[3 * j + q];
            vd += vij[q] * d[q];
        }
        double Pij = Pi + Prr[j]; /* eq. 3.18 */
        if (av_beta > 0 && vd < 0) { /* eq. 3.41, with mu_ij of eq. 3.37 */
            const double muij = hij * vd / (r2 + 0.01 * hij * hij);
            Pij += av_beta * muij * muij / (0.5 * (ri + rj));
        }
        const double *Sj = st->S + 9 * j, lv = sph_lap_visc_kc(kc, r);
        const double mu2 = 0.5 * (mui + mu[j]), rr = rj * ri, vc2 = 0.5 * (vci + vc[j]);
        const double visc = mu2 * m[j] / rr * lv * vc2, viscj = mu2 * mi / rr * lv * vc2; /* as forces_pairs' */
        for (int q = 0; q < dim; q++) {
            double sd = 0;
            for (int b = 0; b < dim; b++) sd += (Si[3 * q + b] + Sj[3 * q + b]) * d[b];
            const double t = -Pij * g * d[q] + sd * g, nd = -d[q], nsd = -sd, nv = -vij[q];
            pc[(size_t)dim * k + q] = m[j] * t - visc * vij[q];
            pc[(size_t)dim * p + q] = mi * (-Pij * g * nd + nsd * g) - viscj * nv; /* j's, as its own loop has it */
        }
    }
    return np;
}

/* pairs_once in 2D with one h for all (the dam break's case): the same
 * expressions, each x, y pair in one sph_v2 (sph_state.h: the same bits
 * lane for lane), the kernel constants i's (h_ij = h_i). The stress sums
 * sd_q = (S_q0 d_0) + (S_q1 d_1) of both rows are taken from the rows'
 * products transposed, each in the scalar loop's order from +0. */
static inline __attribute__((always_inline)) int pairs_once_2d(const struct sph_state *st, const sph_cols *c, int i,
                                                                double av_beta, const int *mir, double *pc) {
    const double *x = c->x, *v = c->v, *m = c->m;
    const int *off = st->nl.off, *nb = st->nl.j;
    const double *rho = st->rho, *Prr = st->perm, *mu = st->mu, *vc = st->vc;
    const double ri = rho[i], Pi = Prr[i], *Si = st->S + 9 * i, mui = mu[i], vci = vc[i], mi = m[i];
    const sph_kc kci = sph_kc_of(2, st->h[i]);
    const double hij = kci.h;
    const sph_v2 xi = sph_ld2(x + 3 * i), vi = sph_ld2(v + 3 * i), S0i = sph_ld2(Si), S1i = sph_ld2(Si + 3);
    const sph_v2 zero = {0, 0};
    int np = 0;
    for (int k = off[i + 1] - 1; k >= off[i] && nb[k] > i; k--, np++) {
        const int j = nb[k], p = mir[k];
        const sph_v2 d = xi - sph_ld2(x + 3 * j), dd = d * d;
        const double r2 = dd[0] + dd[1], r = sqrt(r2);
        if (!(r > 0)) return -1;
        const double rj = rho[j];
        const double g = sph_dw_kc(&kci, r) / r;
        const sph_v2 vij = vi - sph_ld2(v + 3 * j), vdd = vij * d;
        const double vd = 0 + vdd[0] + vdd[1];
        double Pij = Pi + Prr[j]; /* eq. 3.18 */
        if (av_beta > 0 && vd < 0) { /* eq. 3.41, with mu_ij of eq. 3.37 */
            const double muij = hij * vd / (r2 + 0.01 * hij * hij);
            Pij += av_beta * muij * muij / (0.5 * (ri + rj));
        }
        const double *Sj = st->S + 9 * j, lv = sph_lap_visc_kc(&kci, r);
        const double mu2 = 0.5 * (mui + mu[j]), rr = rj * ri, vc2 = 0.5 * (vci + vc[j]);
        const double visc = mu2 * m[j] / rr * lv * vc2, viscj = mu2 * mi / rr * lv * vc2; /* as forces_pairs' */
        const sph_v2 a0 = (S0i + sph_ld2(Sj)) * d, a1 = (S1i + sph_ld2(Sj + 3)) * d; /* row q's two products */
        const sph_v2 sd = (zero + (sph_v2){a0[0], a1[0]}) + (sph_v2){a0[1], a1[1]};
        const sph_v2 t = -Pij * g * d + sd * g, nd = -d, nsd = -sd, nv = -vij;
        const sph_v2 ti = m[j] * t - visc * vij, tj = mi * (-Pij * g * nd + nsd * g) - viscj * nv;
        memcpy(pc + 2 * (size_t)k, &ti, sizeof ti);
        memcpy(pc + 2 * (size_t)p, &tj, sizeof tj); /* j's, as its own loop has it */
    }
    return np;
}

/* pairs_once in 3D with one h for all: pairs_once_2d's x, y pairs in one
 * sph_v2 with each z beside them as a scalar, every expression pairs_once's
 * in its order (r^2 = (dx^2 + dy^2) + dz^2, v_ij . d from +0 over x, y, z,
 * each row's stress sum from +0 over x, y, z), so a slot holds the same bits
 * (sph_fast_paths_same_bits). Like pairs_once_2d it takes no periodic
 * displacement: the slots exist only without a periodic axis (pair_mirror). */
static inline __attribute__((always_inline)) int pairs_once_3d(const struct sph_state *st, const sph_cols *c, int i,
                                                                double av_beta, const int *mir, double *pc) {
    const double *x = c->x, *v = c->v, *m = c->m;
    const int *off = st->nl.off, *nb = st->nl.j;
    const double *rho = st->rho, *Prr = st->perm, *mu = st->mu, *vc = st->vc;
    const double ri = rho[i], Pi = Prr[i], *Si = st->S + 9 * i, mui = mu[i], vci = vc[i], mi = m[i];
    const sph_kc kci = sph_kc_of(3, st->h[i]);
    const double hij = kci.h;
    const sph_v2 xi = sph_ld2(x + 3 * i), vi = sph_ld2(v + 3 * i);
    const double xiz = x[3 * i + 2], viz = v[3 * i + 2];
    const sph_v2 S0i = sph_ld2(Si), S1i = sph_ld2(Si + 3), S2i = sph_ld2(Si + 6), Szi = {Si[2], Si[5]};
    const sph_v2 zero = {0, 0};
    int np = 0;
    for (int k = off[i + 1] - 1; k >= off[i] && nb[k] > i; k--, np++) {
        const int j = nb[k], p = mir[k];
        const sph_v2 d = xi - sph_ld2(x + 3 * j), dd = d * d;
        const double dz = xiz - x[3 * j + 2];
        const double r2 = dd[0] + dd[1] + dz * dz, r = sqrt(r2);
        if (!(r > 0)) return -1;
        const double rj = rho[j];
        const double g = sph_dw_kc(&kci, r) / r;
        const sph_v2 vij = vi - sph_ld2(v + 3 * j), vdd = vij * d;
        const double vijz = viz - v[3 * j + 2];
        const double vd = 0 + vdd[0] + vdd[1] + vijz * dz;
        double Pij = Pi + Prr[j]; /* eq. 3.18 */
        if (av_beta > 0 && vd < 0) { /* eq. 3.41, with mu_ij of eq. 3.37 */
            const double muij = hij * vd / (r2 + 0.01 * hij * hij);
            Pij += av_beta * muij * muij / (0.5 * (ri + rj));
        }
        const double *Sj = st->S + 9 * j, lv = sph_lap_visc_kc(&kci, r);
        const double mu2 = 0.5 * (mui + mu[j]), rr = rj * ri, vc2 = 0.5 * (vci + vc[j]);
        const double visc = mu2 * m[j] / rr * lv * vc2, viscj = mu2 * mi / rr * lv * vc2; /* as forces_pairs' */
        /* row q's sum (S_q0 d_0 + S_q1 d_1) + S_q2 d_2 from +0: rows x, y transposed into lanes as in
         * pairs_once_2d, their z products as one pair; row z alone */
        const sph_v2 a0 = (S0i + sph_ld2(Sj)) * d, a1 = (S1i + sph_ld2(Sj + 3)) * d, a2 = (S2i + sph_ld2(Sj + 6)) * d;
        const sph_v2 az = (Szi + (sph_v2){Sj[2], Sj[5]}) * dz;
        const sph_v2 sdv = ((zero + (sph_v2){a0[0], a1[0]}) + (sph_v2){a0[1], a1[1]}) + az;
        const double sdz = ((0 + a2[0]) + a2[1]) + (Si[8] + Sj[8]) * dz;
        const sph_v2 t = -Pij * g * d + sdv * g, nd = -d, nsd = -sdv, nv = -vij;
        const sph_v2 ti = m[j] * t - visc * vij, tj = mi * (-Pij * g * nd + nsd * g) - viscj * nv;
        const double tz = -Pij * g * dz + sdz * g, ndz = -dz, nsdz = -sdz, nvz = -vijz;
        memcpy(pc + 3 * (size_t)k, &ti, sizeof ti);
        pc[3 * (size_t)k + 2] = m[j] * tz - visc * vijz;
        memcpy(pc + 3 * (size_t)p, &tj, sizeof tj); /* j's, as its own loop has it */
        pc[3 * (size_t)p + 2] = mi * (-Pij * g * ndz + nsdz * g) - viscj * nvz;
    }
    return np;
}

/* For each list entry k of particle i with j = nb[k] > i, the slot of j's
 * list that holds i, into st->pairm[k]. Without a periodic axis the lists
 * ascend (sph_neighbours.c's stencil: rows of sorted cells in order), so
 * j's lower neighbours are its first entries, in the order this loop over
 * ascending i meets them: a counter per particle (st->key, free after the
 * sort) finds each in a few instructions where a search of j's list cost
 * about 35 a pair. Each slot is checked to hold i; 0 when one does not
 * (the lists are then not as this needs, and each pass takes its
 * per-particle loop). Returns the pairs, each entry j > i one, or -1.
 * Serial: about 9 instructions an entry (179 a particle at 5k). */
static long pair_mirror(struct sph_state *st, int n) {
    const int *off = st->nl.off, *nb = st->nl.j;
    int *cur = st->key, *mir = st->pairm;
    long pairs = 0;
    for (int i = 0; i < n; i++) cur[i] = off[i];
    for (int i = 0; i < n; i++)
        for (int k = off[i + 1] - 1; k >= off[i] && nb[k] > i; k--, pairs++) {
            const int j = nb[k], p = cur[j]++;
            if (p >= off[j + 1] || nb[p] != i) return -1;
            mir[k] = p;
        }
    return pairs;
}

/* The step's pair slots, after the lists: st->pairm by pair_mirror, room in
 * st->pairc for dim + 1 doubles per list entry (the forces' dim terms,
 * which XSPH's weights reuse, and W_ij from sph_kinematics), and
 * st->pair_ok when every slot has its pair. Periodic axes wrap the
 * stencil's rows, so their lists do not ascend: no slots then, and each
 * pass takes its per-particle loop. */
hearth_status sph_pairs_prepare(hearth_scene *s, hearth_error *err) {
    struct sph_state *st = s->sph;
    const int n = s->ps.n;
    st->pair_ok = 0;
    const size_t nent = n > 0 ? (size_t)st->nl.off[n] : 0;
    if (st->cells.anyper || nent == 0) return HEARTH_OK; /* (no pairs: nothing to share) */
    if (nent > st->pairm_cap) {
        mem_free(st->pairm, sizeof(int) * st->pairm_cap);
        st->pairm_cap = nent + nent / 4 + 16;
        st->pairm = mem_alloc(sizeof(int) * st->pairm_cap);
        if (!st->pairm) {
            st->pairm_cap = 0;
            return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for %zu pair slots", nent);
        }
    }
    const size_t need = (size_t)(s->def.dim + 1) * nent; /* the forces' dim terms, then W (sph_kinematics) */
    if (need > st->pairc_cap) {
        mem_free(st->pairc, sizeof(double) * st->pairc_cap);
        st->pairc_cap = need + need / 4 + 16;
        st->pairc = mem_alloc(sizeof(double) * st->pairc_cap);
        if (!st->pairc) {
            st->pairc_cap = 0;
            return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for %zu pair terms", need);
        }
    }
    st->pair_ok = 2 * pair_mirror(st, n) == (long)nent; /* each entry one half of a pair */
    return HEARTH_OK;
}

/* One particle's accelerations and kick (sph_forces), dim a constant in
 * each copy; with pc (the symmetric path) its pair terms are the slots of
 * st->pairc, summed in list order, and it has no wall frame. */
static inline __attribute__((always_inline)) void forces_one(hearth_scene *s, const sph_cols *c, int i, const int dim,
                                                              double dt, const double *pc) {
    struct sph_state *st = s->sph;
    const hearth_sph_def *o = &s->def.sph;
    const int *flags = c->flags;
    const double *x = c->x, *v = c->v;
    const double eps_as = o->artificial_stress, av_beta = o->av_beta;
    const double *gvec = s->def.gravity;
    double a[3] = {gvec[0], gvec[1], dim == 3 ? gvec[2] : 0.0};
    if (s->body_force) {
        double bf[3] = {0, 0, 0};
        s->body_force(s->body_force_ud, s->t, x + 3 * i, bf);
        for (int q = 0; q < dim; q++) a[q] += bf[q];
    }
    const double ri = st->rho[i];
    double wn[3] = {0, 0, 0}, da = 0, drag = 0;
    const int wall = !pc && flags && !(flags[i] & PF_FIXED) && sph_wall_frame(s, i, wn, &da);
    const double dah = fmax(da, 0.5 * st->sp[i]);
    if (pc && dim == 2) { /* the x, y pair of each slot in one sph_v2: the same sums lane for lane */
        sph_v2 av = {a[0], a[1]};
        for (int k = st->nl.off[i]; k < st->nl.off[i + 1]; k++) av += sph_ld2(pc + 2 * (size_t)k);
        a[0] = av[0], a[1] = av[1];
    } else if (pc && sph_fast_paths) { /* in 3D likewise, with z beside */
        sph_v2 av = {a[0], a[1]};
        double az = a[2];
        for (int k = st->nl.off[i]; k < st->nl.off[i + 1]; k++) {
            av += sph_ld2(pc + 3 * (size_t)k);
            az += pc[3 * (size_t)k + 2];
        }
        a[0] = av[0], a[1] = av[1], a[2] = az;
    } else if (pc) {
        for (int k = st->nl.off[i]; k < st->nl.off[i + 1]; k++)
            for (int q = 0; q < dim; q++) a[q] += pc[(size_t)dim * k + q];
    } else if (eps_as > 0) {
        if (wall) forces_pairs(st, c, i, dim, 1, 1, av_beta, eps_as, wn, da, dah, a, &drag);
        else forces_pairs(st, c, i, dim, 0, 1, av_beta, eps_as, wn, da, dah, a, &drag);
    } else {
        if (wall) forces_pairs(st, c, i, dim, 1, 0, av_beta, eps_as, wn, da, dah, a, &drag);
        else forces_pairs(st, c, i, dim, 0, 0, av_beta, eps_as, wn, da, dah, a, &drag);
    }
    if (o->surface_tension > 0 && st->surf[i]) { /* eq. 3.30 */
        const double *Ni = st->N + 3 * i, nn = sqrt(Ni[0] * Ni[0] + Ni[1] * Ni[1] + Ni[2] * Ni[2]);
        if (nn > 0)
            for (int q = 0; q < dim; q++) a[q] -= o->surface_tension / ri * st->lapC[i] * Ni[q] / nn;
    }
    memcpy(st->acc + 3 * i, a, sizeof a);
    /* the kick. The wall drag -drag v is linear in v (the wall velocities
     * above are multiples of v_i), so it is taken implicitly: with beta up
     * to about 5 it would otherwise break the viscous dt limit, which is
     * set for fluid-fluid pairs (a channel at 100 Pa s blew up) */
    const int fixed = flags && (flags[i] & PF_FIXED);
    /* a no-slip collider's wall in eq. 3.19 (sph_collider_drag): -dc (v - Vc), implicit as the walls' */
    double Vc[3] = {0, 0, 0};
    const double dc = fixed || s->ncol == 0 ? 0.0 : sph_collider_drag(s, i, Vc);
    for (int q = 0; q < 3; q++) /* a fixed particle keeps its prescribed velocity (sph_walls_begin) */
        st->vnew[3 * i + q] = fixed     ? v[3 * i + q]
                              : dc > 0 ? (v[3 * i + q] + dt * a[q] + dt * dc * Vc[q]) / (1.0 + dt * (drag + dc))
                                       : (v[3 * i + q] + dt * a[q]) / (1.0 + dt * drag);
}

/* Accelerations, then the kick into st->vnew (sph_step then takes the heat
 * rates, sph_heat.c). Per particle: gravity and the body force; per neighbour the
 * pressure (eq. 3.18) with the artificial viscosity's beta term (eq. 3.41,
 * mu_ij of eq. 3.37), the deviatoric and artificial stresses, the viscosity
 * (eq. 3.19) with no-slip walls (Morris et al. 1997, sph_wall_frame); then
 * surface tension (eq. 3.30). */
void sph_forces(hearth_scene *s, double dt) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim;
    /* the symmetric path needs the pair slots (sph_pairs_prepare), no wall frame (no fixed particle) and no
     * artificial stress */
    int sym = st->pair_ok && !(s->def.sph.artificial_stress > 0);
    for (int i = 0; sym && c.flags && i < n; i++) sym = !(c.flags[i] & PF_FIXED);
    /* S / rho^2, as eq. 3.18's pair sum reads it, once per particle instead of twice per pair (the same
     * division, so the same bits); st->S holds it from here to the step's end */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        for (int k = 0; k < 9; k++) st->S[9 * i + k] = st->S[9 * i + k] / (st->rho[i] * st->rho[i]);
        st->perm[i] = st->prs[i] / (st->rho[i] * st->rho[i]); /* P / rho^2 of eq. 3.18 (perm is free scratch now) */
    }
    if (sym) { /* each pair once, into both particles' slots (pairs_once) */
        const double av_beta = s->def.sph.av_beta;
        double *pc = st->pairc;
        const int *mir = st->pairm;
        long pairs = 0;
        int bad = 0;
        int uni = sph_fast_paths; /* one h for all: pairs_once_2d, pairs_once_3d */
        for (int i = 1; i < n && uni; i++) uni = st->h[i] == st->h[0];
        const int uni2 = uni && dim == 2, uni3 = uni && dim == 3;
#pragma omp parallel for schedule(static) reduction(+ : pairs, bad) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) {
            const int k = uni2 ? pairs_once_2d(st, &c, i, av_beta, mir, pc)
                          : dim == 2 ? pairs_once(st, &c, i, 2, 0, av_beta, mir, pc)
                          : uni3     ? pairs_once_3d(st, &c, i, av_beta, mir, pc)
                                     : pairs_once(st, &c, i, 3, 0, av_beta, mir, pc);
            if (k < 0) bad++;
            else pairs += k;
        }
        sym = !bad && 2 * pairs == (long)st->nl.off[n]; /* every slot written, each once (as pair_mirror checked) */
    }
    const double *pc = sym ? st->pairc : NULL;
    /* one copy of the loop per dimension: the kernels' dim is a constant in each */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN && !s->body_force_serial)
    for (int i = 0; i < n; i++) {
        if (dim == 2) {
            if (pc) forces_one(s, &c, i, 2, dt, pc);
            else forces_one(s, &c, i, 2, dt, NULL);
        } else {
            if (pc) forces_one(s, &c, i, 3, dt, pc);
            else forces_one(s, &c, i, 3, dt, NULL);
        }
    }
}

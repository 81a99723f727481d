/* sph_xsph.c: XSPH, the velocity smoothing of eq. 3.34 (Rodriguez-Arenas
 * 2011) with eq. 4.4's temperature tuner of its epsilon: one phase of the SPH
 * step (sph.c's order), after the kick and the field rates, from the kicked
 * velocities st->vnew into the particles' v. It is applied once a step, as
 * the thesis writes it, so its damping per second grows with the step count
 * (docs/validation.md, "The roll's bounce on its tray"). */
#include <math.h>

#include "sph_kernel.h"
#include "sph_state.h"

/* The epsilon a pair (i, j) shares in eq. 3.34 when eq. 4.4 gives its
 * particles different ones (sph_xsph says why a pair shares one): the
 * mass-weighted mean (m_j eps_i + m_i eps_j) / (m_i + m_j), the same bits
 * from either end. */
static inline double xsph_pair_eps(const double *eps, const double *m, int i, int j) {
    return (m[j] * eps[i] + m[i] * eps[j]) / (m[i] + m[j]);
}

/* XSPH's pair weights once per pair, as pairs_once in sph_forces.c does
 * the forces' terms (its comment says why they are the same bits): i's
 * w_ij = 2 m_j / (rho_i + rho_j) W_ij into its slot k, j's w_ji into the
 * slot of j's list that holds i (st->pairm), for every pair whether or not
 * its particles take XSPH; with varied epsilons each weight carries the
 * pair's epsilon (xsph_pair_eps). W_ij is sph_kinematics', kept per entry (wb):
 * the kernel at the same r and h_ij, so the same bits. The weight and not w (v_j - v_i) is kept: xsph_one
 * then multiplies and adds as before, which a compiler may fuse into one
 * rounding (-march=native), so the sums keep their bits in either build. */
static inline __attribute__((always_inline)) void xsph_pairs_once(const struct sph_state *st, const sph_cols *c, int i,
                                                                   const double *wb, double *pc, const int varied) {
    const double *m = c->m, *rho = st->rho;
    const int *off = st->nl.off, *nb = st->nl.j, *mir = st->pairm;
    const double ri = rho[i], mi = m[i];
    for (int k = off[i + 1] - 1; k >= off[i] && nb[k] > i; k--) {
        const int j = nb[k], p = mir[k];
        const double W = wb[k], rs = ri + rho[j]; /* sph_kinematics kept W_ij */
        pc[k] = 2 * m[j] / rs * W;
        pc[p] = 2 * mi / rs * W; /* j's, as its own loop has it: rho_j + rho_i is rho_i + rho_j */
        if (varied) {
            const double e = xsph_pair_eps(st->xsph, m, i, j);
            pc[k] *= e;
            pc[p] *= e;
        }
    }
}

/* One particle's XSPH velocity (sph_xsph), dim a constant in each copy
 * (2D leaves z out, as forces_pairs in sph_forces.c); with pc its pair
 * weights are the slots xsph_pairs_once wrote. With varied, each pair takes
 * its shared epsilon (in pc's weights already, or xsph_pair_eps here). */
static inline __attribute__((always_inline)) void xsph_one(struct sph_state *st, const sph_cols *c, int i, const int dim,
                                                            const double *pc, const int varied) {
    const double *x = c->x, *m = c->m, *h = st->h, *rho = st->rho, *vnew = st->vnew;
    const int *off = st->nl.off, *nb = st->nl.j;
    double *vi = c->v + 3 * i;
    const double *wi = vnew + 3 * i;
    double corr[3] = {0, 0, 0};
    if ((varied || st->xsph[i] > 0) && pc) {
        for (int k = off[i]; k < off[i + 1]; k++) {
            const int j = nb[k];
            const double w = pc[k];
            for (int q = 0; q < dim; q++) corr[q] += w * (vnew[3 * j + q] - wi[q]);
        }
    } else if (varied || st->xsph[i] > 0) {
        const double hi = h[i], ri = rho[i];
        const sph_kc kci = sph_kc_of(dim, hi);
        for (int k = off[i]; k < off[i + 1]; k++) {
            const int j = nb[k];
            double d[3];
            sph_disp_dim(&st->cells, dim, x + 3 * i, x + 3 * j, d);
            const double r = sqrt(dim == 3 ? d[0] * d[0] + d[1] * d[1] + d[2] * d[2] : d[0] * d[0] + d[1] * d[1]);
            SPH_PAIR_KC(kc, dim, kci, hi, h[j]);
            double w = 2 * m[j] / (ri + rho[j]) * sph_w_kc(kc, r);
            if (varied) w *= xsph_pair_eps(st->xsph, m, i, j);
            for (int q = 0; q < dim; q++) corr[q] += w * (vnew[3 * j + q] - wi[q]);
        }
    }
    if (varied)
        for (int q = 0; q < 3; q++) vi[q] = wi[q] + corr[q];
    else
        for (int q = 0; q < 3; q++) vi[q] = wi[q] + st->xsph[i] * corr[q];
    if (dim == 2) vi[2] = 0;
}

/* XSPH (eq. 3.34, its epsilon the tuner of eq. 4.4) from the kicked
 * velocities into the particles' v; the largest |a| for the force limit.
 * Eq. 3.34 moves no momentum for one epsilon: m_i w_ij = m_j w_ji while
 * v_j - v_i changes sign. Eq. 4.4 gives each particle its own epsilon from
 * its temperature, and taken per particle a pair then moves
 * (eps_i - eps_j) m_i w_ij (v_j - v_i) of momentum wherever a hot and a cool
 * particle differ in velocity: the heated bread roll drifted 2 cm along its
 * slip tray (docs/validation.md "SPH bread roll", `sph_xsph_varied_eps_keeps_momentum`).
 * So when the epsilons differ each pair shares one, eps_ij = (m_j eps_i +
 * m_i eps_j) / (m_i + m_j). That weighting keeps what eq. 4.4 asks of the pair:
 * its relative velocity is damped at the rate eps_i w_ij + eps_j w_ji, the
 * per-particle form's (eps_ij (w_ij + w_ji) is that, since m_i w_ij = m_j
 * w_ji); only the push on the pair's centre of mass is gone. A plain mean
 * does the same for equal masses; the minimum or a harmonic mean would damp
 * a hot-cold pair less than eq. 4.4 does. With one epsilon everywhere the
 * sums are the ones before, to the bit.
 * When sph_forces took the symmetric path and some particle takes XSPH,
 * each pair's weights are made once (xsph_pairs_once) into st->pairc, free
 * again once the forces are summed. */
void sph_xsph(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim, *flags = c.flags;
    int any = 0, varied = 0;
    for (int i = 0; i < n && !varied; i++) {
        any |= st->xsph[i] > 0;
        varied = st->xsph[i] != st->xsph[0];
    }
    double *pc = any && st->pair_ok ? st->pairc : NULL;
    if (pc) {
        const double *wb = st->pairc + (size_t)dim * st->nl.off[n];
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) {
            if (varied) xsph_pairs_once(st, &c, i, wb, pc, 1);
            else xsph_pairs_once(st, &c, i, wb, pc, 0);
        }
    }
    double amax = 0;
#pragma omp parallel for schedule(static) reduction(max : amax) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        if (flags && (flags[i] & PF_FIXED)) continue; /* its prescribed velocity, 0 unless it moves */
        if (dim == 2) {
            if (varied) xsph_one(st, &c, i, 2, pc, 1);
            else if (pc) xsph_one(st, &c, i, 2, pc, 0);
            else xsph_one(st, &c, i, 2, NULL, 0);
        } else {
            if (varied) xsph_one(st, &c, i, 3, pc, 1);
            else if (pc) xsph_one(st, &c, i, 3, pc, 0);
            else xsph_one(st, &c, i, 3, NULL, 0);
        }
        const double an = sqrt(st->acc[3 * i] * st->acc[3 * i] + st->acc[3 * i + 1] * st->acc[3 * i + 1] +
                               st->acc[3 * i + 2] * st->acc[3 * i + 2]);
        if (an > amax) amax = an;
    }
    st->amax = amax;
}

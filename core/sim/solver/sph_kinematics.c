/* sph_kinematics.c: SPH's kinematics phase (Rodriguez-Arenas 2011, equation
 * numbers the thesis's): per particle the velocity gradient (eq. 3.27) into
 * its C, the colour field's gradient (eq. 3.29) and Laplacian (eq. 3.28),
 * the surface flag, and the moments of eq. 3.8's renormalisation
 * (sph_viscosity.c). One general loop and, for one h without a periodic
 * axis, a 2D and a 3D copy that keep x, y in a two-lane vector (sph_v2)
 * with every sum in the general loop's order, so the bits are the same
 * (sph_fast_paths_same_bits compares them). A phase of sph_step (sph.c),
 * moved here when the vector copies took sph.c past a file's length. */
#include <math.h>

#include "sph_kernel.h"
#include "sph_neighbours.h"
#include "sph_state.h"

/* Velocity gradient (eq. 3.27) into the particles' C, the colour field's
 * gradient (eq. 3.29) and Laplacian (eq. 3.28); surface particles where
 * |grad C| h passes sph.surface_threshold; and in the same loop over the
 * neighbours (it needs only the densities too) the moments of eq. 3.8's
 * renormalisation into st->vc (sph_viscous_factor, sph_viscosity.c). */
static inline __attribute__((always_inline)) void kinematics_one(hearth_scene *s, const sph_cols *c, int i,
                                                                  const int dim, double *wb, const int uni,
                                                                  const int lap) {
    struct sph_state *st = s->sph;
    const double *x = c->x, *v = c->v, *m = c->m;
    const int *off = st->nl.off, *nb = st->nl.j;
    /* eq. 3.28 sums over every j including i itself: without the self
     * term the Laplacian is positive everywhere and eq. 3.30 pushes the
     * surface outward (a square drop blew apart) */
    double L[9] = {0}, Ni[3] = {0, 0, 0}, lc = lap ? m[i] / st->rho[i] * sph_lap_w(dim, 0, st->h[i]) : 0;
    double fill = 0, tr = 0, gm[3] = {0, 0, 0};
    /* in 2D the z rows and columns stay +0 (every z is 0; see forces_pairs in sph_forces.c) */
    const double *h = st->h, *V = st->perm, hi = h[i];
    const sph_kc kci = sph_kc_of(dim, hi);
    for (int k = off[i]; k < off[i + 1]; k++) {
        const int j = nb[k];
        double d[3];
        sph_disp_dim(&st->cells, dim, x + 3 * i, x + 3 * j, d);
        const double r2 = dim == 3 ? d[0] * d[0] + d[1] * d[1] + d[2] * d[2] : d[0] * d[0] + d[1] * d[1];
        const double r = sqrt(r2);
        SPH_PAIR_KC(kcp, dim, kci, hi, uni ? hi : h[j]);
        const sph_kc *kc = uni ? &kci : kcp; /* uni: every h_j is h_i */
        if (r <= 0) {
            if (wb) wb[k] = sph_w_kc(kc, r); /* XSPH takes the pair, as the walk does */
            continue;
        }
        double wk, dwk, lapk;
        sph_w_dw_lap_kc(dim, kc, r, &wk, &dwk, lap ? &lapk : NULL);
        if (wb) wb[k] = wk; /* W_ij for xsph_pairs_once: sph_w_kc's bits (sph_kernel_one_pass_same_bits) */
        const double Vj = V[j], g = dwk / r;
        for (int a = 0; a < dim; a++) {
            const double dv = v[3 * j + a] - v[3 * i + a];
            for (int b = 0; b < dim; b++) L[3 * a + b] += Vj * dv * g * d[b];
            Ni[a] += Vj * g * d[a];
        }
        if (lap) lc += Vj * lapk;
        /* eq. 3.8's moments for the viscous renormalisation (sph_viscous_factor) */
        const double lr2 = Vj * sph_lap_visc_kc(kc, r) * r2;
        fill += Vj * wk;
        tr += lr2;
        for (int q = 0; q < dim; q++) gm[q] += lr2 * d[q];
    }
    st->vc[i] = sph_viscous_factor(s, i, fill, tr, gm);
    memcpy(c->C + 9 * i, L, sizeof L);
    memcpy(st->N + 3 * i, Ni, sizeof Ni);
    st->lapC[i] = lc;
    st->surf[i] = sqrt(Ni[0] * Ni[0] + Ni[1] * Ni[1] + Ni[2] * Ni[2]) * st->h[i] > s->def.sph.surface_threshold;
}

/* kinematics_one in 2D when every h is the same and no axis is periodic
 * (the step's usual case): the same sums, term for term, with each x, y pair
 * of d, v_j - v_i and the sums held in one sph_v2 (sph_state.h), so the
 * bits are kinematics_one's; the kernel constants are i's throughout, as
 * SPH_PAIR_KC gives them when h_j = h_i. The colour field's Laplacian
 * (st->lapC) is summed only with `lap`: its one reader is eq. 3.30's
 * surface tension (sph_forces), and without it st->lapC is left 0. */
static inline __attribute__((always_inline)) void kinematics_one_2d(hearth_scene *s, const sph_cols *c, int i,
                                                                     double *wb, const int lap) {
    struct sph_state *st = s->sph;
    const double *x = c->x, *v = c->v, *m = c->m, *V = st->perm;
    const int *off = st->nl.off, *nb = st->nl.j;
    const double hi = st->h[i];
    double lc = lap ? m[i] / st->rho[i] * sph_lap_w(2, 0, hi) : 0, fill = 0, tr = 0;
    sph_v2 L0 = {0, 0}, L1 = {0, 0}, Nv = {0, 0}, gv = {0, 0}; /* L's x and y rows, grad C, the moment's centre */
    const sph_v2 xi = sph_ld2(x + 3 * i), vi = sph_ld2(v + 3 * i);
    const sph_kc kci = sph_kc_of(2, hi);
    for (int k = off[i]; k < off[i + 1]; k++) {
        const int j = nb[k];
        const sph_v2 d = xi - sph_ld2(x + 3 * j), dd = d * d;
        const double r2 = dd[0] + dd[1], r = sqrt(r2);
        if (r <= 0) {
            if (wb) wb[k] = sph_w_kc(&kci, r);
            continue;
        }
        double wk, dwk, lapk;
        sph_w_dw_lap_kc(2, &kci, r, &wk, &dwk, lap ? &lapk : NULL);
        if (wb) wb[k] = wk;
        const double Vj = V[j], g = dwk / r;
        const sph_v2 t = Vj * (sph_ld2(v + 3 * j) - vi) * g; /* Vj dv g per row, then times d[b] */
        L0 += t[0] * d;
        L1 += t[1] * d;
        Nv += Vj * g * d;
        if (lap) lc += Vj * lapk;
        const double lr2 = Vj * sph_lap_visc_kc(&kci, r) * r2;
        fill += Vj * wk;
        tr += lr2;
        gv += lr2 * d;
    }
    const double L[9] = {L0[0], L0[1], 0, L1[0], L1[1], 0, 0, 0, 0}, Ni[3] = {Nv[0], Nv[1], 0},
                 gm[3] = {gv[0], gv[1], 0};
    st->vc[i] = sph_viscous_factor(s, i, fill, tr, gm);
    memcpy(c->C + 9 * i, L, sizeof L);
    memcpy(st->N + 3 * i, Ni, sizeof Ni);
    st->lapC[i] = lc;
    st->surf[i] = sqrt(Ni[0] * Ni[0] + Ni[1] * Ni[1] + Ni[2] * Ni[2]) * hi > s->def.sph.surface_threshold;
}

/* kinematics_one in 3D when every h is the same and no axis is periodic:
 * kinematics_one_2d's x, y pairs in one sph_v2 with each z beside them as a
 * scalar, every sum term for term and in kinematics_one's order (r^2 is
 * (dx^2 + dy^2) + dz^2; each row of L is its x, y lanes and its z), so the
 * bits are kinematics_one's (sph_fast_paths_same_bits). A four-lane vector
 * would read past the last particle's z when loading x_j. */
static inline __attribute__((always_inline)) void kinematics_one_3d(hearth_scene *s, const sph_cols *c, int i,
                                                                     double *wb, const int lap) {
    struct sph_state *st = s->sph;
    const double *x = c->x, *v = c->v, *m = c->m, *V = st->perm;
    const int *off = st->nl.off, *nb = st->nl.j;
    const double hi = st->h[i];
    double lc = lap ? m[i] / st->rho[i] * sph_lap_w(3, 0, hi) : 0, fill = 0, tr = 0;
    /* L's rows a = x, y, z: columns x, y in La, column z in Laz; grad C and the moment's centre likewise */
    sph_v2 L0 = {0, 0}, L1 = {0, 0}, L2 = {0, 0}, Nv = {0, 0}, gv = {0, 0};
    double L0z = 0, L1z = 0, L2z = 0, Nz = 0, gz = 0;
    const sph_v2 xi = sph_ld2(x + 3 * i), vi = sph_ld2(v + 3 * i);
    const double xiz = x[3 * i + 2], viz = v[3 * i + 2];
    const sph_kc kci = sph_kc_of(3, hi);
    for (int k = off[i]; k < off[i + 1]; k++) {
        const int j = nb[k];
        const sph_v2 d = xi - sph_ld2(x + 3 * j), dd = d * d;
        const double dz = xiz - x[3 * j + 2];
        const double r2 = dd[0] + dd[1] + dz * dz, r = sqrt(r2);
        if (r <= 0) {
            if (wb) wb[k] = sph_w_kc(&kci, r);
            continue;
        }
        double wk, dwk, lapk;
        sph_w_dw_lap_kc(3, &kci, r, &wk, &dwk, lap ? &lapk : NULL);
        if (wb) wb[k] = wk;
        const double Vj = V[j], g = dwk / r;
        const sph_v2 t = Vj * (sph_ld2(v + 3 * j) - vi) * g; /* Vj dv g of rows x, y, then times d[b] */
        const double tz = Vj * (v[3 * j + 2] - viz) * g;     /* and of row z */
        L0 += t[0] * d;
        L0z += t[0] * dz;
        L1 += t[1] * d;
        L1z += t[1] * dz;
        L2 += tz * d;
        L2z += tz * dz;
        Nv += Vj * g * d;
        Nz += Vj * g * dz;
        if (lap) lc += Vj * lapk;
        const double lr2 = Vj * sph_lap_visc_kc(&kci, r) * r2;
        fill += Vj * wk;
        tr += lr2;
        gv += lr2 * d;
        gz += lr2 * dz;
    }
    const double L[9] = {L0[0], L0[1], L0z, L1[0], L1[1], L1z, L2[0], L2[1], L2z}, Ni[3] = {Nv[0], Nv[1], Nz},
                 gm[3] = {gv[0], gv[1], gz};
    st->vc[i] = sph_viscous_factor(s, i, fill, tr, gm);
    memcpy(c->C + 9 * i, L, sizeof L);
    memcpy(st->N + 3 * i, Ni, sizeof Ni);
    st->lapC[i] = lc;
    st->surf[i] = sqrt(Ni[0] * Ni[0] + Ni[1] * Ni[1] + Ni[2] * Ni[2]) * hi > s->def.sph.surface_threshold;
}

void sph_kinematics(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim;
    for (int i = 0; i < n; i++) st->sp[i] = dim == 3 ? cbrt(c.V0[i]) : sqrt(c.V0[i]); /* once, not per pair */
    sph_lattice_moment_prepare(s);
    /* V = m / rho once per particle (the same division as per pair); perm is free scratch after the sort */
    for (int i = 0; i < n; i++) st->perm[i] = c.m[i] / st->rho[i];
    /* W of each list entry for XSPH, after the forces' terms in st->pairc (sph_pairs_prepare) */
    double *wb = st->pair_ok ? st->pairc + (size_t)dim * st->nl.off[n] : NULL;
    /* one copy of the loop per dimension: the kernels' dim is a constant in each. One h for all: in 2D
     * without a periodic axis the vector copies (kinematics_one_2d, _3d), else in 3D the kernel constants i's */
    int uni = sph_fast_paths;
    for (int i = 1; i < n && uni; i++) uni = st->h[i] == st->h[0];
    const int fast2 = uni && dim == 2 && !st->cells.anyper, fast3 = uni && dim == 3 && !st->cells.anyper,
              uni3 = uni && dim == 3;
    /* the colour field's Laplacian only for st->lapC's one reader, surface tension (sph_forces); else 0 */
    const int lap = s->def.sph.surface_tension > 0;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        if (fast2 && lap) {
            if (wb) kinematics_one_2d(s, &c, i, wb, 1);
            else kinematics_one_2d(s, &c, i, NULL, 1);
        } else if (fast2) {
            if (wb) kinematics_one_2d(s, &c, i, wb, 0);
            else kinematics_one_2d(s, &c, i, NULL, 0);
        } else if (dim == 2) { /* (the general 2D loop: rare, so one copy, with the Laplacian) */
            if (wb) kinematics_one(s, &c, i, 2, wb, 0, 1);
            else kinematics_one(s, &c, i, 2, NULL, 0, 1);
        } else if (fast3 && lap) {
            if (wb) kinematics_one_3d(s, &c, i, wb, 1);
            else kinematics_one_3d(s, &c, i, NULL, 1);
        } else if (fast3) {
            if (wb) kinematics_one_3d(s, &c, i, wb, 0);
            else kinematics_one_3d(s, &c, i, NULL, 0);
        } else if (uni3 && !lap) { /* (3D with a periodic axis and one h) */
            if (wb) kinematics_one(s, &c, i, 3, wb, 1, 0);
            else kinematics_one(s, &c, i, 3, NULL, 1, 0);
        } else {
            if (wb) kinematics_one(s, &c, i, 3, wb, 0, 1);
            else kinematics_one(s, &c, i, 3, NULL, 0, 1);
        }
    }
}

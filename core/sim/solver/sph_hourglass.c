/* sph_hourglass.c: hourglass control for the SPH solver (sph.hourglass), a
 * damping of the particles' zero-energy modes: the part of a pair's relative
 * motion that the smoothed velocity gradient of eq. 3.27 (Rodriguez-Arenas
 * 2011) does not describe.
 *
 * Why: eq. 3.27's L_i sums over a whole kernel, so two particles can close
 * on each other (or shear past each other in a zigzag) while L, and the F
 * and det F integrated from it (phase_stress), stay as they were: the
 * rank-deficiency of SPH's gradient that Ganzenmueller (2015, "An hourglass
 * control algorithm for Lagrangian Smooth Particle Hydrodynamics", Comput.
 * Methods Appl. Mech. Engrg. 286, 87-106) treats for total-Lagrangian SPH,
 * after the hourglass control of finite elements (Flanagan & Belytschko
 * 1981, Int. J. Numer. Meth. Engng 17, 679-706). Where the dough's squeeze
 * is read from its own det F (sph.own_squeeze, sph_gas.c) nothing else holds
 * such a pair apart: in the bread roll's hot dough particles pair and spring
 * apart at 0.25-0.8 m/s, and the roll, standing on 1-3 particles, hops on
 * its tray (docs/validation.md "The roll's bounce on its tray").
 *
 * What: Ganzenmueller's control compares a pair's separation with the one
 * its particles' F predict from the reference configuration; SPH here is
 * updated-Lagrangian (the lists change every step, there is no reference),
 * so this is its rate form. For each pair (i, j), x_ij = x_i - x_j, r = |x_ij|,
 * u = x_ij / r, the velocity error along the pair
 *   delta_ij = (v_i - v_j - 0.5 (L_i + L_j) x_ij) . u
 * (0 for any motion L describes: translation, rotation, any uniform
 * stretch), damped by the pair force
 *   a_i += -sum_j alpha nu_ij delta_ij u,
 * nu_ij eq. 3.19's pair viscosity as sph_forces has it (0.5 (mu_i + mu_j)
 * m_j / (rho_i rho_j) times the viscosity kernel's Laplacian and the pair's
 * mean renormalisation), alpha = sph.hourglass: the dough's own viscosity,
 * alpha times over, on the motion it has no gradient for. m_i nu_ij is
 * symmetric and delta_ij u antisymmetric, so the pair forces are equal and
 * opposite and central: momentum and angular momentum are kept.
 *
 * Implicit: the viscous step (sph_dt.c) already puts eq. 3.19's dt D at
 * 1.4-1.8 in the roll, under explicit Euler's 2 with little room, and the
 * same damping explicit at alpha 0.5 blew up in the raw dough (11 m/s at
 * 0.18 s; docs/validation.md). So the velocities the pair terms read are
 * the step's new ones, v* solving (I + dt D_i) v*_i = v'_i + dt sum_j
 * alpha nu_ij ((v*_j + Lbar x_ij) . u) u (v' the kick's velocities, D_i =
 * sum_j alpha nu_ij u u^T), by HG_SWEEPS Jacobi sweeps from v'; then the
 * pair forces above, with v* in delta, are added to v' explicitly. A solved
 * v* makes that last pass v* itself; an unfinished one still gives equal and
 * opposite pair forces. (The Jacobi result taken as the new velocity keeps
 * no momentum: the roll slid 5 mm sideways in 2 s solved for v_i alone, 1.6
 * mm after four sweeps.) Fixed particles (walls) take no part: their pairs have
 * Morris et al.'s no-slip velocities (sph_walls.c). Every loop writes only
 * its own particle's entries, so any thread count gives the same bits. */
#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "sph_kernel.h"
#include "sph_state.h"
#include "tensor.h"

/* Jacobi sweeps toward the implicit velocities: the iteration contracts by
 * dt D / (1 + dt D) per sweep, about 0.5 in the roll's hot dough at alpha 1 */
#define HG_SWEEPS 4

/* The doubles per particle sph_hourglass keeps: (I + dt D)^-1 (9), the
 * right-hand side (3), two velocity iterates (3 + 3). */
#define HG_DOUBLES 18

int sph_hourglass_doubles(const hearth_scene *s) { return s->def.sph.hourglass > 0 ? HG_DOUBLES : 0; }

hearth_status sph_hourglass_ensure(hearth_scene *s, int n, hearth_error *err) {
    struct sph_state *st = s->sph;
    if (!(s->def.sph.hourglass > 0) || n <= st->hg_cap) return HEARTH_OK;
    const int cap = n + n / 4 + 16;
    double *a = mem_alloc(sizeof(double) * HG_DOUBLES * (size_t)cap);
    if (!a) return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for the hourglass control of %d particles", n);
    mem_free(st->hg, sizeof(double) * HG_DOUBLES * (size_t)st->hg_cap);
    st->hg = a;
    st->hg_cap = cap;
    return HEARTH_OK;
}

void sph_hourglass_free(struct sph_state *st) {
    mem_free(st->hg, sizeof(double) * HG_DOUBLES * (size_t)st->hg_cap);
    st->hg = NULL;
    st->hg_cap = 0;
}

/* Particle i's pairs: with vk, out += sum_j w ((vk_j . u) u) (the neighbours'
 * part of the implicit sweep); without, out += sum_j w ((Lbar x_ij) . u) u
 * and D += sum_j w u u^T; with vk and self, out += -sum_j w (((vk_i - vk_j)
 * - Lbar x_ij) . u) u, the pair forces. w = alpha nu_ij. */
static void hg_pairs(const struct sph_state *st, const sph_cols *c, int i, double alpha, const double *vk, int self,
                     double out[3], double D[9]) {
    const int dim = c->dim, *off = st->nl.off, *nb = st->nl.j, *flags = c->flags;
    const double *x = c->x, *m = c->m, *L = c->C, hi = st->h[i];
    const sph_kc kci = sph_kc_of(dim, hi);
    for (int k = off[i]; k < off[i + 1]; k++) {
        const int j = nb[k];
        if (flags && (flags[j] & PF_FIXED)) continue;
        double d[3] = {0, 0, 0};
        sph_disp(&st->cells, x + 3 * i, x + 3 * j, d);
        const double r = sqrt(d[0] * d[0] + d[1] * d[1] + (dim == 3 ? d[2] * d[2] : 0));
        if (r <= 0) continue;
        SPH_PAIR_KC(kc, dim, kci, hi, st->h[j]);
        const double w = alpha * 0.5 * (st->mu[i] + st->mu[j]) * m[j] / (st->rho[j] * st->rho[i]) *
                         sph_lap_visc_kc(kc, r) * 0.5 * (st->vc[i] + st->vc[j]);
        const double u[3] = {d[0] / r, d[1] / r, dim == 3 ? d[2] / r : 0};
        double lin = 0, vel = 0; /* (Lbar x_ij) . u and the velocity term */
        for (int q = 0; q < dim; q++) {
            double lq = 0;
            for (int b = 0; b < dim; b++) lq += 0.5 * (L[9 * i + 3 * q + b] + L[9 * j + 3 * q + b]) * d[b];
            lin += lq * u[q];
            if (vk) vel += (self ? vk[3 * i + q] - vk[3 * j + q] : vk[3 * j + q]) * u[q];
        }
        const double f = !vk ? w * lin : self ? -w * (vel - lin) : w * vel;
        for (int q = 0; q < dim; q++) {
            out[q] += f * u[q];
            if (D)
                for (int b = 0; b < dim; b++) D[3 * q + b] += w * u[q] * u[b];
        }
    }
}

/* After sph_forces' kick (st->vnew), before XSPH: the hourglass control
 * (the header says how). Off (bit for bit) when sph.hourglass is 0. */
void sph_hourglass(hearth_scene *s, double dt) {
    const double alpha = s->def.sph.hourglass;
    if (!(alpha > 0)) return;
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim, *flags = c.flags;
    double *Ai = st->hg, *b0 = Ai + 9 * (size_t)n, *va = b0 + 3 * (size_t)n, *vb = va + 3 * (size_t)n;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        double src[3] = {0, 0, 0}, D[9] = {0}, A[9];
        if (!(flags && (flags[i] & PF_FIXED))) hg_pairs(st, &c, i, alpha, NULL, 0, src, D);
        for (int q = 0; q < 9; q++) A[q] = (q % 4 == 0) + dt * D[q];
        if (!t3_inverse(A, Ai + 9 * i)) /* I + dt D is positive definite; a singular one takes no implicit part */
            for (int q = 0; q < 9; q++) Ai[9 * i + q] = q % 4 == 0;
        for (int q = 0; q < 3; q++) {
            b0[3 * i + q] = st->vnew[3 * i + q] + dt * src[q];
            va[3 * i + q] = st->vnew[3 * i + q];
        }
    }
    for (int sweep = 0; sweep < HG_SWEEPS; sweep++) {
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) {
            double nbr[3] = {0, 0, 0}, rhs[3];
            if (!(flags && (flags[i] & PF_FIXED))) hg_pairs(st, &c, i, alpha, va, 0, nbr, NULL);
            for (int q = 0; q < 3; q++) rhs[q] = b0[3 * i + q] + dt * nbr[q];
            const double *M = Ai + 9 * i;
            for (int q = 0; q < 3; q++)
                vb[3 * i + q] = q < dim ? M[3 * q] * rhs[0] + M[3 * q + 1] * rhs[1] + M[3 * q + 2] * rhs[2] : va[3 * i + q];
        }
        double *t = va;
        va = vb;
        vb = t;
    }
    /* the pair forces with the sweeps' velocities, added to the kick's */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        if (flags && (flags[i] & PF_FIXED)) continue;
        double a[3] = {0, 0, 0};
        hg_pairs(st, &c, i, alpha, va, 1, a, NULL);
        for (int q = 0; q < dim; q++) vb[3 * i + q] = st->vnew[3 * i + q] + dt * a[q];
    }
    for (int i = 0; i < n; i++)
        if (!(flags && (flags[i] & PF_FIXED)))
            for (int q = 0; q < dim; q++) st->vnew[3 * i + q] = vb[3 * i + q];
}

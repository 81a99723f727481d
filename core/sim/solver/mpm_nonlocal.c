/* mpm_nonlocal.c: a damage driver averaged over a physical length (scene
 * setting damage_length; <hearth/material.h> rule 11; issue #18).
 *
 * Why: a softening damage that each point drives by its own stretch
 * localises into the narrowest band the discretisation allows, one cell: the
 * crack's width and place then follow dx and nothing converges under
 * refinement (docs/validation.md, "A damage with a length"). The standard cure
 * drives the damage by an average of the driver over a fixed length, so the
 * damaged zone has a width of its own (Pijaudier-Cabot & Bazant 1987, J. Eng.
 * Mech. 113:1512: nonlocal damage with a normalised weight; Bazant & Jirasek
 * 2002, J. Eng. Mech. 128:1119, review its weights).
 *
 * What: at the start of an MPM step (before the sort, whose permutation then
 * carries the result with its particle), each particle of a material with a
 * damage_driver gives its driver d_p (what its last stress stored in its
 * state: a one-step lag, first order in dt as the damage's own explicit sum)
 * and the average
 *
 *   dbar_p = sum_q a(x_p - x_q) V_q d_q / sum_q a(x_p - x_q) V_q,
 *
 * a Gaussian a of standard deviation sigma = damage_length / 2 per axis (its
 * weight e^-2 of the centre's at r = damage_length), is taken on the grid:
 * V d and V (V = J V_0, the current volume) go to the nodes with the quadratic
 * B-spline weights P2G uses, both node fields are smoothed by a separable
 * Gaussian, and both come back to the particle with the same weights before
 * the division. The round trip through the B-splines is itself a smoothing of
 * variance dx^2 / 2 per axis (each quadratic B-spline's is dx^2 / 4), so the
 * nodes' Gaussian takes sigma_n^2 = sigma^2 - dx^2 / 2 (none when that is not
 * positive): the whole is close to one Gaussian of sigma at every dx, which
 * is the point of a physical length. Dividing by the averaged volume
 * normalises the weight where it meets a free surface or the box's walls (the
 * crust is at a free surface: an unnormalised sum would dilute its driver by
 * the air). Particles of materials without the callback, pinned ones, and a
 * driver that is not finite count in neither sum.
 *
 * The passes are serial, in particle order, over dense node arrays of the
 * box: the same bits at any thread count. Not for MPI ranks or periodic axes
 * (scene.c refuses both with damage_length > 0).
 */
#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "material.h"
#include "mpm.h"

/* The most nodes the smoothing's kernel spans each side (3 sigma_n): past it a
 * length is far beyond any the box can show, and the loop's cost is bounded. */
enum { NL_KMAX = 256 };

/* One axis of the separable Gaussian: a[...] smoothed along axis d with the
 * weights gk[0..K] (symmetric), into b. nn: the nodes per axis. */
static void smooth_axis(const double *a, double *b, const int nn[3], int d, const double *gk, int K) {
    const int stride[3] = {nn[1] * nn[2], nn[2], 1};
    const int n = nn[d], st = stride[d];
    const long total = (long)nn[0] * nn[1] * nn[2];
    for (long base = 0; base < total; base++) {
        /* each line along d once: from its node with index 0 along d */
        const int id = (int)(base / st % n);
        if (id != 0) continue;
        for (int i = 0; i < n; i++) {
            double s = gk[0] * a[base + (long)i * st];
            for (int k = 1; k <= K; k++) {
                if (i - k >= 0) s += gk[k] * a[base + (long)(i - k) * st];
                if (i + k < n) s += gk[k] * a[base + (long)(i + k) * st];
            }
            b[base + (long)i * st] = s;
        }
    }
}

hearth_status mpm_nonlocal(hearth_scene *s, hearth_error *err) {
    const double len = s->def.damage_length;
    if (!(len > 0)) return HEARTH_OK;
    particles *ps = &s->ps;
    const grid *g = &s->g;
    mpm_state *m = s->mpm;
    if (!(ps->enabled & (1u << PC_NONLOCAL)) && particles_enable(ps, PC_NONLOCAL, err)) return HEARTH_ERR_NOMEM;
    const int D = g->dim;
    const int nn[3] = {g->nn[0], D > 1 ? g->nn[1] : 1, D > 2 ? g->nn[2] : 1};
    const size_t nodes = (size_t)nn[0] * nn[1] * nn[2];
    if (m->nl_cap < 3 * nodes) {
        double *p = mem_alloc(sizeof(double) * 3 * nodes);
        if (!p) return err_set(err, HEARTH_ERR_NOMEM, "scene: out of memory for damage_length's node fields (%zu nodes)", nodes);
        mem_free(m->nl_node, sizeof(double) * m->nl_cap);
        m->nl_node = p, m->nl_cap = 3 * nodes;
    }
    double *num = m->nl_node, *vol = num + nodes, *tmp = vol + nodes;
    memset(num, 0, sizeof(double) * 2 * nodes);
    const double *X = pcold(ps, PC_X), *V0 = pcold(ps, PC_VOL0), *state = pcold(ps, PC_STATE);
    const int *mat = pcoli(ps, PC_MAT);
    const int *pflags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    double *out = pcold(ps, PC_NONLOCAL);
    const int stride = ps->state_stride;
    /* the drivers to the nodes */
    for (int i = 0; i < ps->n; i++) {
        out[i] = NAN;
        const material_slot *ms = &s->mats.slot[mat[i]];
        if (!ms->m->damage_driver || (pflags && (pflags[i] & PF_FIXED))) continue;
        const double d = ms->m->damage_driver(state + (size_t)i * stride);
        if (!isfinite(d)) continue;
        const double V = particles_J(ps, i) * V0[i];
        int base[3];
        double w[3][3], dw[3][3];
        grid_point_weights(g, X + 3 * (size_t)i, base, w, dw);
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < (D > 1 ? 3 : 1); b++)
                for (int c = 0; c < (D > 2 ? 3 : 1); c++) {
                    const int i0 = base[0] + a, i1 = base[1] + b, i2 = base[2] + c;
                    if (i0 < 0 || i0 >= nn[0] || i1 < 0 || i1 >= nn[1] || i2 < 0 || i2 >= nn[2]) continue;
                    const size_t k = ((size_t)i0 * nn[1] + i1) * nn[2] + i2;
                    const double wv = w[0][a] * w[1][b] * w[2][c] * V;
                    num[k] += wv * d;
                    vol[k] += wv;
                }
    }
    /* the nodes' Gaussian: what the B-splines' round trip leaves of sigma^2 (header) */
    const double sigma = 0.5 * len, s2 = sigma * sigma - 0.5 * g->dx * g->dx;
    if (s2 > 0) {
        const double sn = sqrt(s2);
        int K = (int)ceil(3 * sn / g->dx);
        if (K > NL_KMAX) K = NL_KMAX;
        double gk[NL_KMAX + 1];
        for (int k = 0; k <= K; k++) gk[k] = exp(-0.5 * (k * g->dx / sn) * (k * g->dx / sn));
        for (int f = 0; f < 2; f++) {
            double *a = f ? vol : num;
            for (int d = 0; d < D; d++) {
                smooth_axis(a, tmp, nn, d, gk, K);
                memcpy(a, tmp, sizeof(double) * nodes);
            }
        }
    }
    /* back to the particles, with the same weights, and the division */
    for (int i = 0; i < ps->n; i++) {
        const material_slot *ms = &s->mats.slot[mat[i]];
        if (!ms->m->damage_driver || (pflags && (pflags[i] & PF_FIXED))) continue;
        int base[3];
        double w[3][3], dw[3][3];
        grid_point_weights(g, X + 3 * (size_t)i, base, w, dw);
        double sn = 0, sv = 0;
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < (D > 1 ? 3 : 1); b++)
                for (int c = 0; c < (D > 2 ? 3 : 1); c++) {
                    const int i0 = base[0] + a, i1 = base[1] + b, i2 = base[2] + c;
                    if (i0 < 0 || i0 >= nn[0] || i1 < 0 || i1 >= nn[1] || i2 < 0 || i2 >= nn[2]) continue;
                    const size_t k = ((size_t)i0 * nn[1] + i1) * nn[2] + i2;
                    const double wk = w[0][a] * w[1][b] * w[2][c];
                    sn += wk * num[k];
                    sv += wk * vol[k];
                }
        if (sv > 0) out[i] = sn / sv;
    }
    return HEARTH_OK;
}

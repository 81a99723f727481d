/* mpm_self.c: how much of a uniform stress over a particle's neighbourhood comes back into its own C, for the
 * step's bound on a lone particle or a small cluster (mpm_stable_dt; #18, the newtonian cfl 1 cell).
 *
 * MLS-MPM (Hu et al. 2018) hands a particle's stress to its nodes as f_i = -V_q sigma_q D^-1 (x_i - x_q) w_iq, and
 * APIC (Jiang et al. 2015) reads its new C back as D^-1 sum_i w_ip v_i (x_i - x_p)^T, D = dx^2 / 4 (quadratic
 * B-splines). Under a stress sigma the same over the particles that share p's nodes (a small cluster's in-phase
 * mode), the part of p's new C the stress makes is -dt sigma D^-1 A_p / rho, with
 *     A_p = D^-1 sum_i w_ip (x_i - x_p) g_i^T,   g_i = sum_q m_q w_iq (x_i - x_q) / m_i
 * (g_i: the node's offset from the centre of the mass it carries). A lone particle, or a cluster that shares its
 * nodes with nothing else, has g_i = x_i - x_p and A = I; inside a body g_i ~ 0 (a uniform pressure pushes no
 * interior node). With sigma = K ln J I (p = -K ln J) and ln J advanced by dt tr C, the cluster's volume is an
 * oscillator of omega^2 = 4 dim alpha K / (rho dx^2), alpha = tr A / dim, stepped by symplectic Euler (F from the
 * old C in P2G, C from the new stress in G2P), stable for omega dt < 2: c dt / dx < 1 / sqrt(dim alpha), 0.71 in
 * 2D for alpha = 1, below the wave CFL's 1 (c^2 >= K / rho for the wave speeds the plugins report; the shear modes
 * have 2 mu / rho <= dim c^2). A film's tip that parted from its body at cfl 1 oscillated in J every other step
 * and grew until it was crushed (J 0.05, then flung from the wall's corner at 1.4e4 m/s: the stability matrix's
 * newtonian cfl 1, seed 5), and a cluster of three particles in the corner of wall and floor was crushed to J 0.03
 * and inverted (seed 4); docs/validation.md, "The fluid crushed at the side wall at cfl 1".
 *
 * The step is held to MPM_SELF_MARGIN of that bound, which can bind only at cfl > MPM_SELF_MARGIN / sqrt(dim)
 * (0.64 in 2D, 0.52 in 3D): a scene at the default cfl 0.5 computes nothing here and steps as before. When asked,
 * the step takes the separate passes (mpm.c's `usual` is off: no one-region step) and this pass runs between the grid update and
 * G2P: each particle block's particles add to their stencils' nodes, in 2^dim colours of blocks (as P2G's
 * colour phases), the same sums at any thread count; under MPI slabs the seam's sums go across
 * (mpm_ranks_self_halo), as P2G's do. Across a periodic axis a node misses the particles on the far side. */
#include <string.h>

#include "alloc.h"
#include "mpm.h"

int mpm_self_asked(const hearth_scene *s) { return s->def.cfl * sqrt((double)s->def.dim) > MPM_SELF_MARGIN; }

double mpm_self_dt(const hearth_scene *s) {
    if (!(s->self_max > 0 && s->c_max > 0)) return INFINITY; /* not asked, or nothing measured yet */
    return MPM_SELF_MARGIN * s->def.dx / (s->c_max * sqrt(s->def.dim * s->self_max));
}

void mpm_self_free(mpm_state *m) {
    mem_free(m->self_g, sizeof(double) * m->self_g_cap);
    m->self_g = NULL;
    m->self_g_cap = 0;
}

/* particle block q's particles' sums into the nodes of their stencils (m_i g_i, then m_i: MPM_SELF_NCH a node) */
static void self_scatter(hearth_scene *s, int q) {
    const grid *g = &s->g;
    const mpm_state *m = s->mpm;
    const int D = g->dim, NPB = g->nodes_per_block;
    const double *X = pcold(&s->ps, PC_X), *M = pcold(&s->ps, PC_MASS);
    for (int i = m->pb[q].start; i < m->pb[q].end; i++) {
        const double *x = X + 3 * i;
        int base[3] = {0, 0, 0};
        double w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3];
        for (int a = 0; a < D; a++) {
            const double Xa = (x[a] - g->lo[a]) * g->inv_dx;
            base[a] = base_node(Xa);
            bspline_weights(Xa - base[a], w[a], dw);
        }
        for (int p = 0; p < 3; p++)
            for (int r = 0; r < 3; r++)
                for (int t = 0; t < (D == 3 ? 3 : 1); t++) {
                    const int gi[3] = {base[0] + p, base[1] + r, D == 3 ? base[2] + t : 0};
                    int l;
                    const int slot = grid_tile_slot_at(g, D, (const int[3]){0, 0, 0}, gi[0], gi[1], gi[2], &l);
                    double *o = m->self_g + ((size_t)slot * (size_t)NPB + (size_t)l) * MPM_SELF_NCH;
                    const double mw = M[i] * w[0][p] * w[1][r] * (D == 3 ? w[2][t] : 1.0);
                    for (int a = 0; a < D; a++) o[a] += mw * (g->lo[a] + gi[a] * g->dx - x[a]);
                    o[3] += mw;
                }
    }
}

hearth_status mpm_self_gather(hearth_scene *s, hearth_error *err) {
    mpm_state *m = s->mpm;
    const grid *g = &s->g;
    const size_t need = (size_t)g->nactive * (size_t)g->nodes_per_block * MPM_SELF_NCH;
    if (need > m->self_g_cap) {
        mpm_self_free(m);
        m->self_g = mem_alloc(sizeof(double) * need);
        if (!m->self_g) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the lone-particle bound (%d grid blocks)", g->nactive);
        m->self_g_cap = need;
    }
    if (need) memset(m->self_g, 0, sizeof(double) * need); /* no block: nothing (the seam exchange below still runs) */
    /* in 2^dim colours of particle blocks: a block's stencils reach its grid block and the next along each axis, so
     * two blocks of one colour share no node, and each node takes its particle blocks in colour order, the same sums
     * at any thread count */
    const int D = g->dim;
    for (int c = 0; c < (1 << D); c++) {
#pragma omp parallel for schedule(guided) if (s->ps.n >= SCENE_PARALLEL_MIN)
        for (int q = 0; q < m->npb; q++) {
            int b[3];
            grid_block_coords(g, m->pb[q].block, b);
            if (((b[0] & 1) | (b[1] & 1) << 1 | (D == 3 ? (b[2] & 1) << 2 : 0)) == c) self_scatter(s, q);
        }
    }
    hearth_status st = mpm_ranks_self_halo(s, m->self_g, err); /* a seam's nodes: every rank's particles */
    if (st) return st;
    const size_t nodes = (size_t)g->nactive * (size_t)g->nodes_per_block;
    double *q = m->self_g;
#pragma omp parallel for schedule(static) if (s->ps.n >= SCENE_PARALLEL_MIN)
    for (size_t i = 0; i < nodes; i++) /* g_i = the sums over m_i */
        for (int a = 0; a < 3; a++) q[MPM_SELF_NCH * i + a] = q[MPM_SELF_NCH * i + 3] > 0 ? q[MPM_SELF_NCH * i + a] / q[MPM_SELF_NCH * i + 3] : 0.0;
    return HEARTH_OK;
}

/* mpm_periodic.c: periodic axes of an MPM step (moved out of mpm.c whole).
 *
 * Along a periodic axis of N cells the box [lo, hi) is one period. The grid
 * there starts a node below lo and ends two above hi (scene.c): node j lies
 * at lo + (j - 1) dx, the nodes j = 1..N are the period's own, j = 0 is a
 * ghost of N, and j = N + 1, N + 2 are ghosts of 1 and 2. Particles stay in
 * [lo, hi) (wrapped by the sort and by G2P), so their stencils reach the
 * ghosts and no further. After P2G each ghost's mass and momentum are added
 * to its node (mpm_periodic_fold), the grid update runs as usual (no walls on
 * the axis), and the ghosts take their node's velocity back (the unfold)
 * before G2P. Ghosts are folded axis by axis, so a corner ghost of two
 * periodic axes reaches its node in two hops; unfolding goes in the reverse
 * order so each hop reads a finished node. The sort also activates the
 * blocks that hold a ghost's node (mpm_periodic_mark). Heat and water are not
 * wrapped (their passes have no ghosts): a periodic scene with them stops
 * with an error. Rejected: indexing the grid modulo N inside P2G and G2P,
 * which would put a test in every stencil loop of every scene. */
#include <math.h>

#include "mpm.h"
#include "scene.h"

/* x moved into [lo, hi) by whole periods */
static inline double periodic_wrap(double x, double lo, double hi) {
    const double L = hi - lo;
    if (x >= lo && x < hi) return x;
    if (!isfinite(x)) return lo; /* the guard stops on it; keep the block index defined */
    x -= L * floor((x - lo) / L);
    return x >= lo && x < hi ? x : lo; /* round-off at the top edge */
}

/* Every particle into the period along the periodic axes: a pass of its own
 * (the sort's and G2P's loops stay as they were for other scenes), run by the
 * sort and after G2P, so probes and outputs between steps see wrapped positions. */
void mpm_periodic_wrap_all(hearth_scene *s) {
    const grid *g = &s->g;
    double *X = pcold(&s->ps, PC_X);
    const int n = s->ps.n;
    for (int d = 0; d < g->dim; d++) {
        if (!s->def.periodic[d]) continue;
        const double lo = g->lo[d] + g->dx, hi = g->lo[d] + (g->nn[d] - 2) * g->dx; /* the box's own faces */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) X[3 * i + d] = periodic_wrap(X[3 * i + d], lo, hi);
    }
}

/* The node a ghost stands for along an axis of nn = N + 3 nodes, or -1 for a node of the period. */
static inline int periodic_image(int j, int nn) {
    const int N = nn - 3;
    return j == 0 ? N : j > N ? j - N : -1;
}

/* Mark the blocks holding the nodes that the marked blocks' ghosts stand for. */
void mpm_periodic_mark(const hearth_scene *s, unsigned char *mark) {
    const grid *g = &s->g;
    for (int d = 0; d < g->dim; d++) {
        if (!s->def.periodic[d]) continue;
        const int N = g->nn[d] - 3, top0 = (N + 1) / GRID_B, top1 = (N + 2) / GRID_B;
        for (int pass = 0; pass < 2; pass++) /* a block may be both a target and a source of ghosts */
            for (int b = 0; b < g->nblocks; b++) {
                if (!mark[b]) continue;
                int c[3];
                grid_block_coords(g, b, c);
                const int cd = c[d];
                if (cd == 0) {
                    c[d] = N / GRID_B;
                    mark[grid_block_id(g, c[0], c[1], c[2])] = 1;
                    c[d] = cd;
                }
                if (cd == top0 || cd == top1) {
                    c[d] = 0;
                    mark[grid_block_id(g, c[0], c[1], c[2])] = 1;
                }
            }
    }
}

/* unfold = 0: add every ghost's mass and momentum to its node; 1: give every
 * ghost its node's mass and velocity. Serial and in block order: deterministic. */
void mpm_periodic_fold(hearth_scene *s, int unfold) {
    grid *g = &s->g;
    const int D = g->dim, NPB = g->nodes_per_block, fc = s->mpm->flip_ch;
    for (int q = 0; q < D; q++) {
        const int d = unfold ? D - 1 - q : q;
        if (!s->def.periodic[d]) continue;
        for (int k = 0; k < g->nactive; k++) {
            int bc[3];
            grid_block_coords(g, g->active[k], bc);
            if (bc[d] != 0 && (bc[d] + 1) * GRID_B <= g->nn[d] - 2) continue; /* no ghost along d */
            double *node = grid_block(g, k);
            for (int l = 0; l < NPB; l++) {
                int idx[3];
                grid_node_index(g, bc, l, idx);
                int inside = 1;
                for (int e = 0; e < D; e++) inside = inside && idx[e] < g->nn[e];
                const int img = inside ? periodic_image(idx[d], g->nn[d]) : -1;
                if (img < 0) continue;
                idx[d] = img;
                const int slot = g->slot[grid_block_id(g, idx[0] / GRID_B, idx[1] / GRID_B, D == 3 ? idx[2] / GRID_B : 0)];
                if (slot < 0) continue; /* only for a ghost no particle reaches (periodic_mark) */
                const int lt = D == 2 ? (idx[0] % GRID_B) * GRID_B + idx[1] % GRID_B
                                      : ((idx[0] % GRID_B) * GRID_B + idx[1] % GRID_B) * GRID_B + idx[2] % GRID_B;
                double *tn = grid_block(g, slot);
                for (int ch = 0; ch < GRID_NCH_MOMENTUM; ch++) {
                    if (unfold) node[ch * NPB + l] = tn[ch * NPB + lt];
                    else tn[ch * NPB + lt] += node[ch * NPB + l];
                }
                for (int ch = fc; ch < (fc ? fc + D : 0); ch++) { /* transfer = "flip": the momentum before the update */
                    if (unfold) node[ch * NPB + l] = tn[ch * NPB + lt];
                    else tn[ch * NPB + lt] += node[ch * NPB + l];
                }
            }
        }
    }
}

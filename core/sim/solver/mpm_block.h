/* mpm_block.h: what the MPM step's block kernels share across mpm.c (P2G,
 * the grid update, the step's regions) and mpm_g2p.c (G2P): the block
 * function type and its instantiation macro, the fields' clock as a step
 * sees it, the finite check and the failure record. Private to solver/. */
#ifndef HEARTH_MPM_BLOCK_H
#define HEARTH_MPM_BLOCK_H

#include "mpm.h"
#include "thermal.h"
#include "water.h"

#define FORCE_INLINE static inline __attribute__((always_inline))

/* The colliders near grid block bc (colliders.h's collider_list_near_box) into near: the box of the block's
 * nodes grown by `cells` on each side (into lo, hi). Returns -1, "walk them all", without colliders or when more
 * than COLLIDER_NEAR_CAP are near. The grid update asks for its nodes (0 cells), G2P two cells past them (its
 * particles start inside, and move). */
static inline int mpm_block_colliders(const hearth_scene *s, const int bc[3], int cells, double lo[3], double hi[3],
                                      int *near) {
    const grid *g = &s->g;
    for (int d = 0; d < 3; d++) lo[d] = hi[d] = 0;
    if (s->ncol <= 0) return -1;
    for (int d = 0; d < g->dim; d++) {
        lo[d] = g->lo[d] + (bc[d] * GRID_B - cells) * g->dx;
        hi[d] = g->lo[d] + (bc[d] * GRID_B + GRID_B - 1 + cells) * g->dx;
    }
    return collider_list_near_box(s->cols, s->ncol, lo, hi, near);
}

/* Whether this step updates heat and water on the grid, and over what time:
 * the fields' clock (fields/field_clock.c) skips them on most steps of a
 * multirate cycle; the particles' temperature, water and CO2 still ride along. */
static inline int heat_now(const hearth_scene *s) { return thermal_active(s) && !s->field_skip; }
static inline int water_now(const hearth_scene *s) { return water_active(s) && !s->field_skip; }
static inline double field_dt(const hearth_scene *s, double dt) { return s->field_dt > 0 ? s->field_dt : dt; }

/* two doubles, one SSE2 register: 3D P2G's scatter and G2P's sums run in pairs of lanes */
typedef double v2d __attribute__((vector_size(16)));

typedef void (*block_fn)(hearth_scene *, int, double, double *);
/* the instantiations, indexed [dim == 3][heat][water] */
#define BLOCK_FN(kind, D, H, W) \
    static void kind##_##D##H##W(hearth_scene *s, int k, double dt, double *tile) { kind##_block(s, D, H, W, 0, k, dt, tile); }

static inline void record_fail(pb_partial *pp, int i, fail_kind kind, int code) {
    if (pp->fail_i < 0) {
        pp->fail_i = i;
        pp->fail_kind = kind;
        pp->fail_code = code;
    }
}

/* A particle's stencil in its block's tile (org: the block's first node): per
 * axis the tile index of the stencil's first node, the particle's offset from
 * it in cells, and its quadratic B-spline weights; a 2D particle's third axis
 * is one node of weight 1. P2G and G2P both read it. */
FORCE_INLINE void tile_stencil(const grid *g, const int D, const double *x, const int org[3], const double inv_dx, int base[3],
                               double fx[3], double w[3][3]) {
    double dw[3];
    base[2] = 0, fx[2] = 0, w[2][0] = 1, w[2][1] = 0, w[2][2] = 0;
    for (int d = 0; d < D; d++) {
        const double Xd = (x[d] - g->lo[d]) * inv_dx;
        const int b = base_node(Xd);
        fx[d] = Xd - b;
        base[d] = b - org[d];
        bspline_weights(fx[d], w[d], dw);
    }
}

/* Whether every a[k] is finite, with one test instead of one per value: x - x
 * is +0 for a finite x and NaN for an infinite or NaN one, so the sum is 0
 * exactly when all are (the compiler may not fold x - x to 0 without
 * -ffinite-math-only). 5 instructions a particle-step fewer in 2D (callgrind). */
FORCE_INLINE int all_finite(const double *a, const int n) {
    double z = 0.0;
    for (int k = 0; k < n; k++) z += a[k] - a[k];
    return z == 0.0;
}

/* Each phase's range of blocks [lo, hi) in one word, handed out one block at
 * a time, even threads taking from the front and odd ones from the back: at
 * two threads, thread 0 works the low-x end of every phase (the particle
 * blocks, each colour's list and the active grid blocks are all in block
 * order, x slowest) and thread 1 the high-x end, and they meet wherever the
 * work splits, a block apart at most. So each grid node is written (P2G's
 * eight colours, the grid update) and read (G2P) by the same core through
 * the step, but at the seam between the two ends, where `dynamic` and
 * `guided` handed blocks to either thread at random and about half of each
 * node's cache lines went from core to core at each of its nine writes; the
 * 32-cell bench's grid (about 0.7 MB) fits a core's L2, where one thread
 * keeps it (issue 20, docs/performance.md "3D at 32 cells"). Which thread
 * steps a block moves no bits. On the stack of the region's caller (its own
 * cache lines: every claim writes one). */
typedef struct mpm_claims {
    unsigned long long colour[8], grid, g2p;
} __attribute__((aligned(64))) mpm_claims;

/* mpm_share.c: the claims (3D, more than one thread) */
int claim_take(unsigned long long *c, int back);
int claim_end(void);
mpm_claims *claims_begin(hearth_scene *s, mpm_claims *cl);
void claims_end(mpm_state *m);
void p2g_wait_lower(const hearth_scene *s, const int bc[3]);

/* In the one-region step (step_team_sorted) a chunk's particle blocks and its
 * grid blocks go, in P2G, the grid update and G2P alike, first to the thread
 * that owns the chunk (the sort's static split: the chunk it counts and lists
 * first), which takes them from the front of the chunk's span; a thread done
 * with its own chunks takes from the back of the others'. So a particle's
 * columns are read and written by one core from phase to phase and step to
 * step, save where a late thread's share is taken from its tail. Before, P2G
 * went by chunk too but G2P and the grid update by `schedule(guided)`, whose
 * first half went to whichever thread came first: about every other step,
 * G2P ran each particle block on the other core from its P2G, and the x, v,
 * C, F and key lines (about 150 bytes a particle, 3.7 MB at 2D 128 cells,
 * each core's half near its 2 MiB L2) crossed between the cores twice a
 * step. Which thread takes a block moves no bits: each block's work is its
 * own (the same instructions, callgrind). */
typedef struct span_walk {
    int me, P, c0, c1, T, j; /* this thread of P; its own chunks [c0, c1) of T; the chunk being taken from */
    long back;               /* the blocks it took from other threads' chunks */
} span_walk;

/* mpm_share.c: the one-region step's spans (2D, more than one thread) */
span_walk span_walk_start(int T);
int span_next(mpm_span *sp, span_walk *w, const int *ready, int *lo, int *hi);
void span_count(mpm_state *m, int phase, const span_walk *w);

/* mpm_g2p.c */
block_fn g2p_fn(const hearth_scene *s);
void g2p_team(hearth_scene *s, block_fn fn, double dt);
void g2p_reduce(hearth_scene *s, step_report *rep);
void g2p_chunks(hearth_scene *s, mpm_sort_team *t, block_fn fn, double dt);

#endif

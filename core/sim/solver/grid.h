/* grid.h: the block-sparse background grid and the quadratic B-spline weights.
 *
 * Nodes sit at lo + i*dx. They are grouped in blocks of GRID_B^dim nodes; only
 * blocks near particles hold storage, so memory follows the material, not the
 * box. A dense table of block slots (4 bytes per block of the whole box) maps a
 * block to its storage. Each node carries g->nch channels (see CH_*). */
#ifndef HEARTH_GRID_H
#define HEARTH_GRID_H
#include <math.h>
#include "hearth/hearth.h"

#define GRID_B 4     /* nodes per block side */
#define GRID_T 6     /* tile side: a block's particles touch nodes 0..5 from the block origin */
/* Node channels. Momentum runs always use the first four; a scene with heat
 * or water transport uses all of them (grid_set_channels), so it alone pays
 * for them. */
enum {
    CH_M = 0, CH_PX, CH_PY, CH_PZ, /* mass, momentum (velocity after the grid update) */
    CH_HC,                          /* heat capacity sum m alpha w (J/K) */
    CH_T,                           /* sum m alpha theta w, then temperature theta_i */
    CH_T0,                          /* temperature before the heat update (FLIP, eq. 21) */
    CH_R,                           /* heat flux accumulated into the node (W) / CG Ap */
    CH_CG_R, CH_CG_P,               /* conjugate-gradient residual and direction */
    CH_B,                           /* heat sources (W); in the implicit solve, then the preconditioned residual */
    CH_MW,                          /* water mass m_i^w (eq. 15) */
    CH_SW,                          /* water capacity sum rho0^w V_p w (eq. 18), then saturation s_i */
    CH_DMW,                         /* water mass change over the step (eq. 25) */
    GRID_NCH_MAX
};
/* After thermal_finish, fields/subcell.c (latent_heat) takes CH_R, CH_B, CH_CG_P, CH_CG_R and CH_HC as its
 * scratch: nothing reads them again before the next step's P2G or thermal_prepare writes them. */
#define GRID_NCH_MOMENTUM 4
/* A two_field scene's channels (mpm_two_field.c), after all the others so no
 * other scene pays for them: the second field's mass and momentum (velocity
 * after the grid update), in CH_M..CH_PZ's order so the grid update runs on
 * either; the node's reference damage gradient (1/m; zero where the node is
 * not split; at a node two bodies touch, the contact normal instead); the
 * node's reference body's tag (0 where no two bodies touch it; right after the
 * gradient, so P2G and G2P load the three together); the nodal damage (the
 * mass-weighted mean; at a node two bodies touch, after the prepare pass, the
 * gap between their surfaces along the normal); CH_TF_S, the second body's
 * surface while the prepare pass finds that gap. */
enum { CH_TF_M = GRID_NCH_MAX, CH_TF_PX, CH_TF_PY, CH_TF_PZ, CH_TF_GX, CH_TF_GY, CH_TF_GB, CH_TF_D, CH_TF_S, GRID_NCH_TWO };

typedef struct grid {
    int dim;
    double dx, inv_dx, lo[3];
    int nn[3];          /* nodes per axis (1 in z for 2D) */
    int nb[3];          /* blocks per axis */
    int nblocks;        /* nb[0]*nb[1]*nb[2] */
    int nodes_per_block;/* GRID_B^dim */
    int *slot;          /* per block of the box: storage slot or -1 */
    int nactive, cap, acap; /* active blocks; capacity of data and of active */
    int nch;                /* channels per node in use (GRID_NCH_MOMENTUM or GRID_NCH_MAX) */
    int *active;        /* block ids with storage, ascending */
    double *data;       /* cap * nch * nodes_per_block, channel-major within a block */
} grid;

/// Most cells along one axis of the box, and most blocks in the slot table.
#define GRID_CELLS_MAX (1 << 22)
#define GRID_BLOCKS_MAX (1L << 28)
/// Bytes per block of the tables kept for the whole box (slot table, the
/// sort's counts, the activity marks, MPM's particle block of each block);
/// the node data is only for active blocks.
#define GRID_TABLE_BYTES_PER_BLOCK (3 * sizeof(int) + 1)
/// Node and block counts of the grid over lo..hi, checked (every count within
/// its limit before it becomes an int) without allocating. dim, dx, lo and hi
/// must be finite with hi > lo (check_def in scene.c).
hearth_status grid_plan(int dim, double dx, const double lo[3], const double hi[3], int nn[3], int nb[3], long *nblocks,
                        hearth_error *err);
hearth_status grid_init(grid *g, int dim, double dx, const double lo[3], const double hi[3], hearth_error *err);
/// The grid's geometry only (dim, dx, lo, node and block counts), with no
/// tables: for a solver that places particles on the grid's lattice but never
/// transfers to it (solver.uses_grid = 0). grid_free accepts it.
hearth_status grid_init_geometry(grid *g, int dim, double dx, const double lo[3], const double hi[3], hearth_error *err);
void grid_free(grid *g);
/// Use nch channels per node from the next activation on (storage is rebuilt every step).
hearth_status grid_set_channels(grid *g, int nch, hearth_error *err);
/// Give storage (zeroed) to exactly the blocks flagged in mark (nblocks bytes). Keeps capacity.
hearth_status grid_activate(grid *g, const unsigned char *mark, hearth_error *err);
/// grid_activate in parts, for a caller that runs them in its own parallel region:
/// room for n active blocks (on growth, the old blocks lose their slots first), then
/// each chunk [lo, hi) of the block table: its marked blocks get slots k, k + 1, ...
/// (k: the marks before lo) and zeroed storage, the others slot -1; the caller sets nactive.
/// Tables of at least GRID_ACTIVATE_PARALLEL_MIN blocks are worth a parallel activation.
#define GRID_ACTIVATE_PARALLEL_MIN 16384
hearth_status grid_activate_reserve(grid *g, int n, hearth_error *err);
void grid_activate_chunk(grid *g, const unsigned char *mark, int lo, int hi, int k);
static inline double *grid_block(const grid *g, int slot) {
    return g->data + (size_t)slot * (size_t)g->nch * (size_t)g->nodes_per_block;
}
static inline int grid_block_id(const grid *g, int bx, int by, int bz) { return (bx * g->nb[1] + by) * g->nb[2] + bz; }
static inline void grid_block_coords(const grid *g, int id, int b[3]) {
    b[2] = id % g->nb[2];
    b[1] = (id / g->nb[2]) % g->nb[1];
    b[0] = id / (g->nb[2] * g->nb[1]);
}

/// Grid coordinates gi of node l (local index) of the block at block coordinates bc, in dimension D
/// (a constant where the caller's D is one: the division by B folds).
static inline void grid_node_index_d(const int D, const int bc[3], int l, int gi[3]) {
    const int B = GRID_B;
    if (D == 2) {
        gi[0] = bc[0] * B + l / B;
        gi[1] = bc[1] * B + l % B;
        gi[2] = 0;
    } else {
        gi[0] = bc[0] * B + l / (B * B);
        gi[1] = bc[1] * B + (l / B) % B;
        gi[2] = bc[2] * B + l % B;
    }
}

/// Grid coordinates gi of node l (local index) of the block at block coordinates bc.
static inline void grid_node_index(const grid *g, const int bc[3], int l, int gi[3]) { grid_node_index_d(g->dim, bc, l, gi); }

/// Node gi (global grid coordinates): its block's storage and, in *l, its local
/// index; NULL past the grid or in a block without storage (empty air).
static inline double *grid_node_at(const grid *g, const int gi[3], int *l) {
    for (int d = 0; d < g->dim; d++)
        if (gi[d] < 0 || gi[d] > g->nn[d] - 1) return NULL;
    const int slot = g->slot[grid_block_id(g, gi[0] / GRID_B, gi[1] / GRID_B, gi[2] / GRID_B)];
    if (slot < 0) return NULL;
    *l = g->dim == 2 ? (gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B
                     : ((gi[0] % GRID_B) * GRID_B + gi[1] % GRID_B) * GRID_B + gi[2] % GRID_B;
    return grid_block(g, slot);
}

/* A particle block's tile: the block and its +1 neighbours, GRID_T nodes per
 * axis from the block's origin node (as P2G gathers and scatters). */
/// Nodes in a tile (GRID_T^dim).
static inline int grid_tile_count(const grid *g) { return g->dim == 2 ? GRID_T * GRID_T : GRID_T * GRID_T * GRID_T; }
/// Storage slot of tile node t of the block at bc, and its local index in *l.
int grid_tile_slot(const grid *g, const int bc[3], int t, int *l);
/// Node (a, b, c) of the tile of the block at bc (c = 0 in 2D): the storage
/// slot of its block, and its local index in *l. D is the dimension; the
/// particle passes give it as a compile-time constant, so this inlines to a
/// few adds.
static inline __attribute__((always_inline)) int grid_tile_slot_at(const grid *g, const int D, const int bc[3], int a,
                                                                   int b, int c, int *l) {
    *l = D == 2 ? (a % GRID_B) * GRID_B + b % GRID_B : ((a % GRID_B) * GRID_B + b % GRID_B) * GRID_B + c % GRID_B;
    return g->slot[grid_block_id(g, bc[0] + a / GRID_B, bc[1] + b / GRID_B, bc[2] + (D == 3 ? c / GRID_B : 0))];
}
/// The same node's block storage.
static inline __attribute__((always_inline)) double *grid_tile_node(const grid *g, const int D, const int bc[3], int a,
                                                                    int b, int c, int *l) {
    return grid_block(g, grid_tile_slot_at(g, D, bc, a, b, c, l));
}

/// A particle's B-spline stencil in its block's tile: tile index, weight and
/// weight gradient (1/m) of each of its 3^dim nodes.
typedef struct grid_stencil {
    int t[27];
    double w[27], gw[27][3];
    int n;
} grid_stencil;
void grid_tile_stencil(const grid *g, const int bc[3], const double *x, grid_stencil *st);

/// Quadratic B-spline weights and their derivatives (in grid units) for a
/// coordinate X in grid units: base = floor(X - 0.5), fx = X - base in [0.5, 1.5).
static inline void bspline_weights(double fx, double w[3], double dw[3]) {
    w[0] = 0.5 * (1.5 - fx) * (1.5 - fx);
    w[1] = 0.75 - (fx - 1.0) * (fx - 1.0);
    w[2] = 0.5 * (fx - 0.5) * (fx - 0.5);
    dw[0] = fx - 1.5;
    dw[1] = -2.0 * (fx - 1.0);
    dw[2] = fx - 0.5;
}

/// A point's quadratic B-spline stencil: the lowest node base[d] of its 3 nodes
/// per axis, their weights w[d][k] and weight derivatives dw[d][k] (per unit of
/// dx, not per metre). Axes past dim get base 0 and weights {1, 0, 0}.
static inline void grid_point_weights(const grid *g, const double x[3], int base[3], double w[3][3], double dw[3][3]) {
    for (int d = 0; d < 3; d++) {
        base[d] = 0;
        w[d][0] = 1, w[d][1] = w[d][2] = 0;
        dw[d][0] = dw[d][1] = dw[d][2] = 0;
    }
    for (int d = 0; d < g->dim; d++) {
        const double Xd = (x[d] - g->lo[d]) * g->inv_dx;
        base[d] = (int)floor(Xd - 0.5);
        bspline_weights(Xd - base[d], w[d], dw[d]);
    }
}
/// The nodes of a point's stencil that hold storage and weight, in
/// grid_point_weights' order (axis 0 outermost): each one's storage, local
/// index, weight and grid coordinates. For the passes outside P2G and G2P
/// that walk a particle's nodes one by one (fields/water.c's boiling front,
/// fields/subcell.c).
typedef struct grid_point_nodes {
    double *node[27];
    int slot[27], l[27], gi[27][3]; /* slot: node's block storage slot (node = grid_block(g, slot)) */
    double w[27];
    int n;
} grid_point_nodes;
static inline void grid_point_nodes_of(const grid *g, const double x[3], grid_point_nodes *pn) {
    int base[3];
    double w[3][3], dw[3][3];
    grid_point_weights(g, x, base, w, dw);
    pn->n = 0;
    /* grid_node_at's arithmetic per axis once (the block coordinate, the local index, whether it is on the
     * grid), not per node: the same nodes, local indices and weights */
    const int D = g->dim, nc = D == 3 ? 3 : 1;
    int gq[3][3], bq[3][3], lq[3][3], on[3][3];
    for (int d = 0; d < 3; d++)
        for (int a = 0; a < 3; a++) {
            const int gi = d < D ? base[d] + a : 0;
            on[d][a] = d >= D || (gi >= 0 && gi <= g->nn[d] - 1);
            gq[d][a] = gi, bq[d][a] = on[d][a] ? gi / GRID_B : 0, lq[d][a] = on[d][a] ? gi % GRID_B : 0;
        }
    for (int a = 0; a < 3; a++) {
        if (!on[0][a]) continue;
        for (int b = 0; b < 3; b++) {
            if (!on[1][b]) continue;
            for (int c = 0; c < nc; c++) {
                if (!on[2][c]) continue;
                const double wt = w[0][a] * w[1][b] * w[2][c];
                const int slot = g->slot[grid_block_id(g, bq[0][a], bq[1][b], bq[2][c])];
                if (slot < 0 || !(wt > 0)) continue;
                const int k = pn->n++;
                pn->node[k] = grid_block(g, slot), pn->slot[k] = slot;
                pn->l[k] = D == 2 ? lq[0][a] * GRID_B + lq[1][b] : (lq[0][a] * GRID_B + lq[1][b]) * GRID_B + lq[2][c];
                pn->w[k] = wt;
                pn->gi[k][0] = gq[0][a], pn->gi[k][1] = gq[1][b], pn->gi[k][2] = gq[2][c];
            }
        }
    }
}
#endif

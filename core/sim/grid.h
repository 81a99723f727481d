/* grid.h: the block-sparse background grid and the quadratic B-spline weights.
 *
 * Nodes sit at lo + i*dx. They are grouped in blocks of GRID_B^dim nodes; only
 * blocks near particles hold storage, so memory follows the material, not the
 * box. A dense table of block slots (4 bytes per block of the whole box) maps a
 * block to its storage. Each node carries GRID_NCH channels: mass and momentum
 * (velocity after the grid update). */
#ifndef HEARTH_GRID_H
#define HEARTH_GRID_H
#include "hearth/hearth.h"

#define GRID_B 4     /* nodes per block side */
#define GRID_T 6     /* tile side: a block's particles touch nodes 0..5 from the block origin */
#define GRID_NCH 4   /* mass, momentum x, y, z */

typedef struct grid {
    int dim;
    double dx, inv_dx, lo[3];
    int nn[3];          /* nodes per axis (1 in z for 2D) */
    int nb[3];          /* blocks per axis */
    int nblocks;        /* nb[0]*nb[1]*nb[2] */
    int nodes_per_block;/* GRID_B^dim */
    int *slot;          /* per block of the box: storage slot or -1 */
    int nactive, cap, acap; /* active blocks; capacity of data and of active */
    int *active;        /* block ids with storage, ascending */
    double *data;       /* cap * GRID_NCH * nodes_per_block */
} grid;

hearth_status grid_init(grid *g, int dim, double dx, const double lo[3], const double hi[3], hearth_error *err);
void grid_free(grid *g);
/// Give storage (zeroed) to exactly the blocks flagged in mark (nblocks bytes). Keeps capacity.
hearth_status grid_activate(grid *g, const unsigned char *mark, hearth_error *err);
static inline double *grid_block(const grid *g, int slot) {
    return g->data + (size_t)slot * GRID_NCH * (size_t)g->nodes_per_block;
}
static inline int grid_block_id(const grid *g, int bx, int by, int bz) { return (bx * g->nb[1] + by) * g->nb[2] + bz; }
static inline void grid_block_coords(const grid *g, int id, int b[3]) {
    b[2] = id % g->nb[2];
    b[1] = (id / g->nb[2]) % g->nb[1];
    b[0] = id / (g->nb[2] * g->nb[1]);
}

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
#endif

/* sph_neighbours.h: neighbour search for SPH.
 *
 * A uniform cell list (cell size >= the largest support radius) over
 * particles sorted by cell, and the neighbour lists it produces in CSR form.
 * A kd-tree (the thesis's choice, §3.1.2) builds the same lists; it is kept
 * for the comparison the tests print, the solver uses the cell list, which
 * is faster: measured with `SPH_BENCH_N=50000 unit_sph sph_neighbours_agree`
 * (3D, 50k random particles, ~42 neighbours each, wall time on a shared
 * 2-core machine at load 11), the cell list (key, counting sort, gather,
 * one walk per particle filling the lists) took 0.23 s on one thread (0.17 s
 * on two) against 0.73 s for a balanced kd-tree (build + radius queries,
 * serial), both giving the same
 * 2,108,904 pairs. Periodic axes wrap: displacements are minimum
 * images. Lists are in a fixed order (cells in z, y, x order, particles in
 * sorted order), so sums over them do not depend on the thread count. */
#ifndef HEARTH_SPH_NEIGHBOURS_H
#define HEARTH_SPH_NEIGHBOURS_H
#include <stddef.h>

#include "hearth/hearth.h"

typedef struct sph_cells {
    int dim;
    double lo[3], len[3]; /* box origin and size */
    double cell;          /* cell edge (m) */
    int nc[3];            /* cells per axis (1 along z in 2D) */
    int periodic[3];
    int anyper;           /* any periodic axis (the list's walk skips sph_disp without) */
    int ncell;
    int *start;           /* ncell + 1: particles of cell c are [start[c], start[c+1]) after sorting */
    int cap;
} sph_cells;

/* One thread's share of a build (sph_nlist_build): its buffer (chunk 0
 * writes into the list itself), entries used, the next particle to walk. */
typedef struct sph_nlist_chunk {
    int *j;
    size_t cap, used, want;
    int next;
} sph_nlist_chunk;

typedef struct sph_nlist {
    int n;
    int *off;   /* n + 1 */
    int *j;     /* off[n] neighbour indices (self excluded) */
    size_t ncap;
    int offcap;
    sph_nlist_chunk *chunk; /* per thread; with T threads the other T - 1 hold (T - 1) / T of the lists again */
    int nchunk;
} sph_nlist;

/// 1 (the default): the loops written for one h (the neighbour walk here;
/// sph_kinematics (sph_kinematics.c) and the pair terms in sph_forces.c, as
/// two-lane vectors, in 3D with z beside them) take those copies when every
/// h is the same; 0 sends
/// every step through the general loops. The copies give the same bits;
/// `sph_fast_paths_same_bits` switches them off to check it.
extern int sph_fast_paths;

/// Set up the cell table for box [lo, hi] and cell edge `cell`. Periodic axes
/// need at least 3 cells. Reuses storage.
hearth_status sph_cells_setup(sph_cells *c, int dim, const double lo[3], const double hi[3], double cell,
                              const int periodic[3], hearth_error *err);
void sph_cells_free(sph_cells *c);
/// Cell index of a point (clamped into the box; periodic axes wrapped).
int sph_cell_of(const sph_cells *c, const double x[3]);
/// Counting sort: key[i] = cell of particle i; order gets the stable order
/// (new i = old order[i]); fills c->start.
void sph_cells_sort(sph_cells *c, const int *key, int n, int *order);
/// Displacement x_i - x_j, minimum image on periodic axes.
static inline void sph_disp(const sph_cells *c, const double *xi, const double *xj, double d[3]) {
    for (int a = 0; a < 3; a++) {
        double v = xi[a] - xj[a];
        if (c->periodic[a]) {
            const double L = c->len[a];
            if (v > 0.5 * L) v -= L;
            else if (v < -0.5 * L) v += L;
        }
        d[a] = v;
    }
}

/// The same displacement with dim a constant: without periodic axes the plain
/// difference (what sph_disp gives then), and in 2D a z of 0 (every 2D
/// particle's z is 0, so sph_disp's z is +0 too).
static inline __attribute__((always_inline)) void sph_disp_dim(const sph_cells *c, const int dim, const double *xi,
                                                               const double *xj, double d[3]) {
    if (c->anyper) sph_disp(c, xi, xj, d);
    else d[0] = xi[0] - xj[0], d[1] = xi[1] - xj[1], d[2] = xi[2] - xj[2];
    if (dim == 2) d[2] = 0;
}

/// Neighbour lists of sorted particles: j is a neighbour of i (j != i) when
/// |x_i - x_j| < (h_i + h_j) / 2 (symmetric h_ij, eq. 3.56). h may be NULL
/// for the constant h0. The cell edge must be >= max h. One walk per
/// particle. With rho (and masses m, and h), also each particle's density by
/// summation (eq. 3.13, h_ij of eq. 3.56) over its list, in list order.
hearth_status sph_nlist_build(sph_nlist *nl, const sph_cells *c, const double *x, int n, const double *h, double h0,
                              const double *m, double *rho, hearth_error *err);
/// The same lists from a kd-tree over unsorted particles (for the comparison).
hearth_status sph_nlist_kdtree(sph_nlist *nl, const sph_cells *c, const double *x, int n, double h0,
                               hearth_error *err);
void sph_nlist_free(sph_nlist *nl);
#endif

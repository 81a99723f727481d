/* grid.c: block-sparse storage for grid nodes. */
#include "grid.h"

#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"

#ifdef _OPENMP
#include <omp.h>
#endif

hearth_status grid_plan(int dim, double dx, const double lo[3], const double hi[3], int nn[3], int nb[3], long *nblocks,
                        hearth_error *err) {
    /* counts are worked out in double and range-checked before any becomes an
     * int: a box edge at 1e300 used to give a negative block count */
    double total = 1;
    for (int d = 0; d < 3; d++) {
        if (d >= dim) {
            nn[d] = nb[d] = 1;
            continue;
        }
        const double cells = (hi[d] - lo[d]) / dx;
        if (!(cells >= 1 && cells <= GRID_CELLS_MAX))
            return err_set(err, HEARTH_ERR_PARAM,
                           "scene: box axis %c spans %g m = %g cells of dx = %g m; valid range [1, %d] cells per axis "
                           "(use a larger dx or a smaller box)",
                           "xyz"[d], hi[d] - lo[d], cells, dx, GRID_CELLS_MAX);
        nn[d] = (int)ceil(cells - 1e-9) + 1;
        nb[d] = (nn[d] + GRID_B - 1) / GRID_B + 1; /* +1: tiles reach one block past the last */
        total *= nb[d];
    }
    if (total > (double)GRID_BLOCKS_MAX)
        return err_set(err, HEARTH_ERR_PARAM,
                       "scene: dx = %g m gives %.4g grid blocks over the box; the limit is %ld (use a larger dx or a "
                       "smaller box)",
                       dx, total, GRID_BLOCKS_MAX);
    *nblocks = (long)total;
    return HEARTH_OK;
}

hearth_status grid_init_geometry(grid *g, int dim, double dx, const double lo[3], const double hi[3], hearth_error *err) {
    memset(g, 0, sizeof *g);
    long nb = 1;
    hearth_status st = grid_plan(dim, dx, lo, hi, g->nn, g->nb, &nb, err);
    if (st) return st;
    g->dim = dim;
    g->dx = dx;
    g->inv_dx = 1.0 / dx;
    for (int d = 0; d < 3; d++) g->lo[d] = d < dim ? lo[d] : 0.0;
    g->nblocks = (int)nb;
    g->nodes_per_block = dim == 2 ? GRID_B * GRID_B : GRID_B * GRID_B * GRID_B;
    g->nch = g->zero_from = GRID_NCH_MOMENTUM;
    return HEARTH_OK;
}

hearth_status grid_init(grid *g, int dim, double dx, const double lo[3], const double hi[3], hearth_error *err) {
    hearth_status st = grid_init_geometry(g, dim, dx, lo, hi, err);
    if (st) return st;
    const long nb = g->nblocks;
    g->slot = mem_alloc(sizeof(int) * (size_t)nb);
    if (!g->slot) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the grid block table (%ld blocks)", nb);
    for (long i = 0; i < nb; i++) g->slot[i] = -1;
    return HEARTH_OK;
}

void grid_free(grid *g) {
    mem_free(g->slot, sizeof(int) * (size_t)g->nblocks);
    mem_free(g->active, sizeof(int) * (size_t)g->acap);
    mem_free(g->data, sizeof(double) * (size_t)g->nch * (size_t)g->nodes_per_block * (size_t)g->cap);
    memset(g, 0, sizeof *g);
}

hearth_status grid_set_channels(grid *g, int nch, int extra, hearth_error *err) {
    g->zero_from = extra > 0 ? nch - extra : nch;
    if (nch == g->nch) return HEARTH_OK;
    /* keep the byte capacity honest: convert it to blocks of the new width */
    const size_t bytes = sizeof(double) * (size_t)g->nch * (size_t)g->nodes_per_block * (size_t)g->cap;
    mem_free(g->data, bytes);
    g->data = NULL;
    g->cap = 0;
    g->nch = nch;
    (void)err;
    return HEARTH_OK;
}

/* grid_activate's chunks: one per thread over a big table, else one */
#define ACTIVATE_CHUNKS_MAX 64
static int activate_chunks(int nblocks) {
#ifdef _OPENMP
    if (nblocks < GRID_ACTIVATE_PARALLEL_MIN) return 1; /* a few microseconds of work: not worth a parallel region */
    const int t = omp_get_max_threads();
    return t < 1 ? 1 : t > ACTIVATE_CHUNKS_MAX ? ACTIVATE_CHUNKS_MAX : t;
#else
    (void)nblocks;
    return 1;
#endif
}

hearth_status grid_activate_reserve(grid *g, int n, hearth_error *err) {
    if (n <= g->acap && n <= g->cap) return HEARTH_OK;
    /* the old blocks lose their slots first, so a failure below leaves no slot pointing into freed storage */
    for (int i = 0; i < g->nactive; i++) g->slot[g->active[i]] = -1;
    g->nactive = 0;
    /* 1.5x: the node data is the largest table; doubling left up to half of it spare */
    if (n > g->acap) {
        const int ncap = g->acap + g->acap / 2 > n ? g->acap + g->acap / 2 : n;
        int *a = mem_realloc(g->active, sizeof(int) * (size_t)g->acap, sizeof(int) * (size_t)ncap);
        if (!a) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for %d grid blocks", n);
        g->active = a;
        g->acap = ncap;
    }
    if (n > g->cap) {
        const int ncap = g->cap + g->cap / 2 > n ? g->cap + g->cap / 2 : n;
        const size_t per = sizeof(double) * (size_t)g->nch * (size_t)g->nodes_per_block;
        /* the contents are zeroed on activation, so nothing is copied: free, then allocate (no old and new both held) */
        mem_free(g->data, per * (size_t)g->cap);
        g->data = NULL;
        g->cap = 0;
        double *d = mem_alloc(per * (size_t)ncap);
        if (!d) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for %d grid blocks", n);
        g->data = d;
        g->cap = ncap;
    }
    return HEARTH_OK;
}

void grid_activate_chunk(grid *g, const unsigned char *mark, int lo, int hi, int k) {
    /* The channels the passes accumulate into start at zero, CH_CG_R among them
     * (P2G sums the volume there for boundary.c). CH_T0, CH_R, CH_CG_P and CH_B
     * are written whole before they are read (thermal.c, boundary.c), so they
     * are left as they are: a field scene zeroes 10 of its 14 channels. */
    const size_t NPB = (size_t)g->nodes_per_block, z = (size_t)(g->nch < CH_T0 ? g->nch : CH_T0);
    for (int b = lo; b < hi; b++) {
        if (!mark[b]) {
            g->slot[b] = -1;
            continue;
        }
        g->slot[b] = k;
        g->active[k] = b;
        double *d = g->data + (size_t)k * (size_t)g->nch * NPB;
        memset(d, 0, sizeof(double) * z * NPB);
        if (g->nch > CH_CG_R) memset(d + CH_CG_R * NPB, 0, sizeof(double) * NPB);
        if (g->nch > CH_MW) memset(d + CH_MW * NPB, 0, sizeof(double) * (size_t)(g->nch - CH_MW) * NPB);
        else if (g->zero_from < g->nch) /* a solver's own channels past the momentum's (grid_set_channels' extra) */
            memset(d + (size_t)g->zero_from * NPB, 0, sizeof(double) * (size_t)(g->nch - g->zero_from) * NPB);
        k++;
    }
}

/* Blocks get slots in ascending order whatever the chunking: chunk c of the
 * table counts its marks, and its blocks' slots start after the marks of
 * chunks before it, so the slots are the same for any thread count. (The
 * MPM sort does the same inside its own parallel region when it can:
 * mpm_sort.c's sort_team.) */
hearth_status grid_activate(grid *g, const unsigned char *mark, hearth_error *err) {
    const int T = activate_chunks(g->nblocks), NB = g->nblocks;
    int part[ACTIVATE_CHUNKS_MAX + 1] = {0};
#pragma omp parallel for schedule(static) num_threads(T) if (T > 1)
    for (int c = 0; c < T; c++) {
        const int lo = (int)((long)NB * c / T), hi = (int)((long)NB * (c + 1) / T);
        int k = 0;
        for (int b = lo; b < hi; b++) k += mark[b] != 0;
        part[c + 1] = k;
    }
    for (int c = 0; c < T; c++) part[c + 1] += part[c];
    const int n = part[T];
    hearth_status st = grid_activate_reserve(g, n, err);
    if (st) return st;
    g->nactive = n;
#pragma omp parallel for schedule(static) num_threads(T) if (T > 1)
    for (int c = 0; c < T; c++)
        grid_activate_chunk(g, mark, (int)((long)NB * c / T), (int)((long)NB * (c + 1) / T), part[c]);
    return HEARTH_OK;
}

int grid_tile_slot(const grid *g, const int bc[3], int t, int *l) {
    const int D = g->dim;
    int a, b, c = 0;
    if (D == 2) {
        a = t / GRID_T;
        b = t % GRID_T;
    } else {
        a = t / (GRID_T * GRID_T);
        b = (t / GRID_T) % GRID_T;
        c = t % GRID_T;
    }
    return grid_tile_slot_at(g, D, bc, a, b, c, l);
}

void grid_tile_stencil(const grid *g, const int bc[3], const double *x, grid_stencil *st) {
    const int D = g->dim;
    int base[3] = {0, 0, 0};
    double w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3][3] = {{0}};
    for (int d = 0; d < D; d++) {
        const double X = (x[d] - g->lo[d]) * g->inv_dx;
        const int b = (int)floor(X - 0.5);
        bspline_weights(X - b, w[d], dw[d]);
        base[d] = b - bc[d] * GRID_B;
    }
    st->n = 0;
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++)
            for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                const int k = st->n++;
                const double wc = D == 3 ? w[2][c] : 1.0;
                st->t[k] = D == 2 ? (base[0] + a) * GRID_T + base[1] + b
                                  : ((base[0] + a) * GRID_T + base[1] + b) * GRID_T + base[2] + c;
                st->w[k] = w[0][a] * w[1][b] * wc;
                st->gw[k][0] = dw[0][a] * w[1][b] * wc * g->inv_dx;
                st->gw[k][1] = w[0][a] * dw[1][b] * wc * g->inv_dx;
                st->gw[k][2] = D == 3 ? w[0][a] * w[1][b] * dw[2][c] * g->inv_dx : 0.0;
            }
}

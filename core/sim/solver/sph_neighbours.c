/* sph_neighbours.c: uniform cell list and kd-tree neighbour search (see sph_neighbours.h). */
#include "sph_neighbours.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "error.h"

hearth_status sph_cells_setup(sph_cells *c, int dim, const double lo[3], const double hi[3], double cell,
                              const int periodic[3], hearth_error *err) {
    if (!(cell > 0) || !isfinite(cell)) return err_set(err, HEARTH_ERR_PARAM, "sph: cell size must be > 0 m, got %g", cell);
    c->dim = dim;
    c->cell = cell;
    long total = 1;
    for (int a = 0; a < 3; a++) {
        c->lo[a] = lo[a];
        c->len[a] = hi[a] - lo[a];
        c->periodic[a] = a < dim && periodic && periodic[a];
        if (a >= dim) {
            c->nc[a] = 1;
            continue;
        }
        /* periodic axes: cells tile the period exactly (edge >= cell) */
        int k = c->periodic[a] ? (int)floor(c->len[a] / cell) : (int)ceil(c->len[a] / cell);
        if (k < 1) k = 1;
        if (c->periodic[a] && k < 3)
            return err_set(err, HEARTH_ERR_PARAM,
                           "sph: periodic axis %d is %g m long, less than 3 smoothing lengths (%g m); enlarge the box "
                           "or lower h_factor",
                           a, c->len[a], cell);
        c->nc[a] = k;
        total *= k;
    }
    if (total > 100000000L)
        return err_set(err, HEARTH_ERR_PARAM, "sph: %ld cells of %g m in the box; the box is too large for h", total,
                       cell);
    if ((int)total + 1 > c->cap) {
        mem_free(c->start, sizeof(int) * (size_t)c->cap);
        c->start = mem_alloc(sizeof(int) * ((size_t)total + 1));
        if (!c->start) {
            c->cap = 0;
            return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for %ld cells", total);
        }
        c->cap = (int)total + 1;
    }
    c->ncell = (int)total;
    return HEARTH_OK;
}

void sph_cells_free(sph_cells *c) {
    mem_free(c->start, sizeof(int) * (size_t)c->cap);
    memset(c, 0, sizeof *c);
}

static int axis_cell(const sph_cells *c, int a, double x) {
    const double e = c->periodic[a] ? c->len[a] / c->nc[a] : c->cell;
    int k = (int)floor((x - c->lo[a]) / e);
    if (c->periodic[a]) {
        k %= c->nc[a];
        if (k < 0) k += c->nc[a];
    } else if (k < 0) k = 0;
    else if (k >= c->nc[a]) k = c->nc[a] - 1;
    return k;
}

int sph_cell_of(const sph_cells *c, const double x[3]) {
    int k[3] = {0, 0, 0};
    for (int a = 0; a < c->dim; a++) k[a] = axis_cell(c, a, x[a]);
    return (k[2] * c->nc[1] + k[1]) * c->nc[0] + k[0];
}

void sph_cells_sort(sph_cells *c, const int *key, int n, int *order) {
    memset(c->start, 0, sizeof(int) * ((size_t)c->ncell + 1));
    for (int i = 0; i < n; i++) c->start[key[i] + 1]++;
    for (int k = 0; k < c->ncell; k++) c->start[k + 1] += c->start[k];
    /* stable placement; start[] is shifted back afterwards */
    for (int i = 0; i < n; i++) order[c->start[key[i]]++] = i;
    for (int k = c->ncell; k > 0; k--) c->start[k] = c->start[k - 1];
    c->start[0] = 0;
}

/* Visit the neighbours of particle i: fn-like macro body over cells. */
static int walk(const sph_cells *c, const double *x, int i, const double *h, double h0, int *out) {
    int ki[3] = {0, 0, 0};
    for (int a = 0; a < c->dim; a++) ki[a] = axis_cell(c, a, x[3 * i + a]);
    const double hi = h ? h[i] : h0;
    int cnt = 0;
    const int r2 = c->dim == 3 ? 1 : 0;
    for (int dz = -r2; dz <= r2; dz++)
        for (int dy = -1; dy <= 1; dy++)
            for (int dxc = -1; dxc <= 1; dxc++) {
                int k[3] = {ki[0] + dxc, ki[1] + dy, ki[2] + dz}, ok = 1;
                for (int a = 0; a < 3; a++) {
                    if (k[a] >= 0 && k[a] < c->nc[a]) continue;
                    if (c->periodic[a]) k[a] = (k[a] + c->nc[a]) % c->nc[a];
                    else ok = 0;
                }
                if (!ok) continue;
                const int cell = (k[2] * c->nc[1] + k[1]) * c->nc[0] + k[0];
                for (int j = c->start[cell]; j < c->start[cell + 1]; j++) {
                    if (j == i) continue;
                    double d[3];
                    sph_disp(c, x + 3 * i, x + 3 * j, d);
                    const double r2d = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                    const double hij = h ? 0.5 * (hi + h[j]) : h0;
                    if (r2d < hij * hij) {
                        if (out) out[cnt] = j;
                        cnt++;
                    }
                }
            }
    return cnt;
}

static hearth_status nlist_reserve(sph_nlist *nl, int n, size_t total, hearth_error *err) {
    if (n + 1 > nl->offcap) {
        mem_free(nl->off, sizeof(int) * (size_t)nl->offcap);
        nl->off = mem_alloc(sizeof(int) * ((size_t)n + 1));
        nl->offcap = nl->off ? n + 1 : 0;
        if (!nl->off) return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for neighbour lists");
    }
    if (total > nl->ncap) {
        mem_free(nl->j, sizeof(int) * nl->ncap);
        size_t cap = total + total / 4 + 16;
        nl->j = mem_alloc(sizeof(int) * cap);
        nl->ncap = nl->j ? cap : 0;
        if (!nl->j) return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for %zu neighbour entries", total);
    }
    return HEARTH_OK;
}

hearth_status sph_nlist_build(sph_nlist *nl, const sph_cells *c, const double *x, int n, const double *h, double h0,
                              hearth_error *err) {
    hearth_status st = nlist_reserve(nl, n, 0, err);
    if (st) return st;
    nl->n = n;
#pragma omp parallel for schedule(static) if (n >= 2048)
    for (int i = 0; i < n; i++) nl->off[i + 1] = walk(c, x, i, h, h0, NULL);
    nl->off[0] = 0;
    for (int i = 0; i < n; i++) nl->off[i + 1] += nl->off[i];
    if ((st = nlist_reserve(nl, n, (size_t)nl->off[n], err))) return st;
#pragma omp parallel for schedule(static) if (n >= 2048)
    for (int i = 0; i < n; i++) walk(c, x, i, h, h0, nl->j + nl->off[i]);
    return HEARTH_OK;
}

void sph_nlist_free(sph_nlist *nl) {
    mem_free(nl->off, sizeof(int) * (size_t)nl->offcap);
    mem_free(nl->j, sizeof(int) * nl->ncap);
    memset(nl, 0, sizeof *nl);
}

/* ---- kd-tree (the thesis's structure, §3.1.2), for the comparison ---------- */

typedef struct kd {
    const double *x;
    int *idx;
    int dim;
} kd;

static const double *g_kx; /* qsort has no context argument in C17 */
static int g_kaxis;
static int kd_cmp(const void *a, const void *b) {
    double u = g_kx[3 * *(const int *)a + g_kaxis], v = g_kx[3 * *(const int *)b + g_kaxis];
    return u < v ? -1 : u > v ? 1 : (*(const int *)a - *(const int *)b);
}

/* Balanced tree in place: idx[lo..hi) sorted by the median along depth % dim. */
static void kd_build(kd *t, int lo, int hi, int depth) {
    if (hi - lo <= 1) return;
    g_kx = t->x;
    g_kaxis = depth % t->dim;
    qsort(t->idx + lo, (size_t)(hi - lo), sizeof(int), kd_cmp);
    int mid = (lo + hi) / 2;
    kd_build(t, lo, mid, depth + 1);
    kd_build(t, mid + 1, hi, depth + 1);
}

static int kd_query(const kd *t, int lo, int hi, int depth, const double *q, double r, int self, int *out, int cnt) {
    if (hi <= lo) return cnt;
    int mid = (lo + hi) / 2, p = t->idx[mid], a = depth % t->dim;
    const double *xp = t->x + 3 * p;
    double d2 = 0;
    for (int k = 0; k < 3; k++) d2 += (q[k] - xp[k]) * (q[k] - xp[k]);
    if (p != self && d2 < r * r) {
        if (out) out[cnt] = p;
        cnt++;
    }
    double diff = q[a] - xp[a];
    if (diff - r < 0) cnt = kd_query(t, lo, mid, depth + 1, q, r, self, out, cnt);
    if (diff + r >= 0) cnt = kd_query(t, mid + 1, hi, depth + 1, q, r, self, out, cnt);
    return cnt;
}

hearth_status sph_nlist_kdtree(sph_nlist *nl, const sph_cells *c, const double *x, int n, double h0,
                               hearth_error *err) {
    (void)c; /* no periodic wrap: the comparison uses a closed box */
    kd t = {x, mem_alloc(sizeof(int) * (size_t)(n > 0 ? n : 1)), c->dim};
    if (!t.idx) return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for the kd-tree");
    for (int i = 0; i < n; i++) t.idx[i] = i;
    kd_build(&t, 0, n, 0);
    hearth_status st = nlist_reserve(nl, n, 0, err);
    if (!st) {
        nl->n = n;
        nl->off[0] = 0;
        for (int i = 0; i < n; i++) nl->off[i + 1] = nl->off[i] + kd_query(&t, 0, n, 0, x + 3 * i, h0, i, NULL, 0);
        st = nlist_reserve(nl, n, (size_t)nl->off[n], err);
    }
    if (!st)
        for (int i = 0; i < n; i++) kd_query(&t, 0, n, 0, x + 3 * i, h0, i, nl->j + nl->off[i], 0);
    mem_free(t.idx, sizeof(int) * (size_t)(n > 0 ? n : 1));
    return st;
}

/* sph_neighbours.c: uniform cell list and kd-tree neighbour search (see sph_neighbours.h). */
#include "sph_neighbours.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "sph_kernel.h"

#ifdef _OPENMP
#include <omp.h>
#endif

int sph_fast_paths = 1;

hearth_status sph_cells_setup(sph_cells *c, int dim, const double lo[3], const double hi[3], double cell,
                              const int periodic[3], hearth_error *err) {
    if (!(cell > 0) || !isfinite(cell)) return err_set(err, HEARTH_ERR_PARAM, "sph: cell size must be > 0 m, got %g", cell);
    c->dim = dim;
    c->cell = cell;
    c->anyper = 0;
    long total = 1;
    for (int a = 0; a < 3; a++) {
        c->lo[a] = lo[a];
        c->len[a] = hi[a] - lo[a];
        c->periodic[a] = a < dim && periodic && periodic[a];
        c->anyper |= c->periodic[a];
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

/* The stencil of particle i: the 3 x 3 (x 3 in 3D) cells around its own,
 * in z, y, x order, as ranges of sorted particles. Along a non-periodic x
 * axis the cells of one row are adjacent in the sorted order, so a row is
 * one range; a periodic x wraps, so its rows are three. Returns the number
 * of ranges; *cand their total length (a bound on the neighbours). */
static int stencil(const sph_cells *c, const double *xi, int lo[27], int hi[27], int *cand) {
    int ki[3] = {0, 0, 0};
    for (int a = 0; a < c->dim; a++) ki[a] = axis_cell(c, a, xi[a]);
    const int rz = c->dim == 3 ? 1 : 0;
    int nr = 0, tot = 0;
    for (int dz = -rz; dz <= rz; dz++)
        for (int dy = -1; dy <= 1; dy++) {
            int ky = ki[1] + dy, kz = ki[2] + dz;
            if (ky < 0 || ky >= c->nc[1]) {
                if (!c->periodic[1]) continue;
                ky = (ky + c->nc[1]) % c->nc[1];
            }
            if (kz < 0 || kz >= c->nc[2]) {
                if (!c->periodic[2]) continue;
                kz = (kz + c->nc[2]) % c->nc[2];
            }
            const int row = (kz * c->nc[1] + ky) * c->nc[0];
            if (!c->periodic[0]) {
                const int k0 = ki[0] > 0 ? ki[0] - 1 : 0, k1 = ki[0] + 1 < c->nc[0] ? ki[0] + 1 : c->nc[0] - 1;
                lo[nr] = c->start[row + k0], hi[nr] = c->start[row + k1 + 1];
                tot += hi[nr] - lo[nr];
                nr++;
                continue;
            }
            for (int dx = -1; dx <= 1; dx++) {
                const int kx = (ki[0] + dx + c->nc[0]) % c->nc[0];
                lo[nr] = c->start[row + kx], hi[nr] = c->start[row + kx + 1];
                tot += hi[nr] - lo[nr];
                nr++;
            }
        }
    *cand = tot;
    return nr;
}

/* One candidate j of particle i (walk_dim): into out and, with rho, into
 * the density sum r when within h_ij. */
static inline __attribute__((always_inline)) void candidate(const sph_cells *c, const int dim, const int withh,
                                                             const int withrho, const int anyper, const int uni,
                                                             const double *x, const double *xi, int j,
                                                             const double *h, double h0, double hi_, double hi2,
                                                             const sph_kc *kci, const double *m, double *r, int *out,
                                                             int *cnt) {
    double d[3];
    if (anyper) sph_disp(c, xi, x + 3 * j, d);
    else d[0] = xi[0] - x[3 * j], d[1] = xi[1] - x[3 * j + 1], d[2] = dim == 3 ? xi[2] - x[3 * j + 2] : 0;
    const double r2d = dim == 3 ? d[0] * d[0] + d[1] * d[1] + d[2] * d[2] : d[0] * d[0] + d[1] * d[1];
    /* uni: every h is h_i, so h_ij = (h_i + h_j) / 2 is h_i exactly and its square is hi2 */
    const double hj = uni ? hi_ : withh ? h[j] : h0;
    const double hij = uni ? hi_ : withh ? 0.5 * (hi_ + hj) : h0;
    if (r2d < (uni ? hi2 : hij * hij)) {
        out[(*cnt)++] = j;
        if (withrho) {
            if (uni) *r += m[j] * sph_w_kc(kci, sqrt(r2d));
            else {
                SPH_PAIR_KC(kc, dim, *kci, hi_, hj);
                *r += m[j] * sph_w_kc(kc, sqrt(r2d));
            }
        }
    }
}

/* Particle i's neighbours into out (room for the stencil's candidates), in
 * stencil order; with rho, its density by summation (eq. 3.13) over them in
 * that order. Returns their count. dim is a constant in each copy (walk);
 * in 2D z is left out of r^2 (every z is 0, and + 0 changes no sum of
 * squares), and pairs with h_j = h_i take i's kernel constants (the same
 * bits: sph_kernel.h). `fast`, a constant too: no periodic axis, and h, m
 * and rho given (the step's case); the rest is read as the arguments say.
 * `uni` (with fast): every particle has the same h, so no h_j is read. The
 * range holding i itself is walked in two parts around it, which skips
 * the self test per candidate and keeps the order. */
static inline __attribute__((always_inline)) int walk_dim(const sph_cells *c, const int dim, const int fast,
                                                          const int uni, const double *x, int i, const double *h,
                                                          double h0, const double *m, double *rho, const int *lo,
                                                          const int *hi, int nr, int *out) {
    const double *xi = x + 3 * i;
    const int withh = fast || h, withrho = fast || rho, anyper = !fast && c->anyper;
    const double hi_ = withh ? h[i] : h0, hi2 = hi_ * hi_;
    const sph_kc kci = sph_kc_of(dim, hi_);
    double r = withrho ? m[i] * sph_w_kc(&kci, 0) : 0;
    int cnt = 0;
    for (int q = 0; q < nr; q++) {
        const int e = hi[q], self = i >= lo[q] && i < e ? i : e;
        for (int j = lo[q]; j < self; j++)
            candidate(c, dim, withh, withrho, anyper, uni, x, xi, j, h, h0, hi_, hi2, &kci, m, &r, out, &cnt);
        for (int j = self + 1; j < e; j++)
            candidate(c, dim, withh, withrho, anyper, uni, x, xi, j, h, h0, hi_, hi2, &kci, m, &r, out, &cnt);
    }
    if (withrho) rho[i] = r;
    return cnt;
}

static int walk(const sph_cells *c, const double *x, int i, const double *h, double h0, const double *m, double *rho,
                const int uni, const int *lo, const int *hi, int nr, int *out) {
    if (!c->anyper && h && m && rho) {
        if (uni)
            return c->dim == 2 ? walk_dim(c, 2, 1, 1, x, i, h, h0, m, rho, lo, hi, nr, out)
                               : walk_dim(c, 3, 1, 1, x, i, h, h0, m, rho, lo, hi, nr, out);
        return c->dim == 2 ? walk_dim(c, 2, 1, 0, x, i, h, h0, m, rho, lo, hi, nr, out)
                           : walk_dim(c, 3, 1, 0, x, i, h, h0, m, rho, lo, hi, nr, out);
    }
    return c->dim == 2 ? walk_dim(c, 2, 0, 0, x, i, h, h0, m, rho, lo, hi, nr, out)
                       : walk_dim(c, 3, 0, 0, x, i, h, h0, m, rho, lo, hi, nr, out);
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

/* Grow chunk t's buffer (chunk 0's is nl->j itself) to hold `need` entries,
 * keeping the first `keep`. */
static hearth_status chunk_grow(sph_nlist *nl, int t, size_t keep, size_t need, hearth_error *err) {
    int **buf = t ? &nl->chunk[t].j : &nl->j;
    size_t *cap = t ? &nl->chunk[t].cap : &nl->ncap;
    if (need <= *cap) return HEARTH_OK;
    const size_t nc = need + need / 4 + 16;
    int *b = mem_alloc(sizeof(int) * nc);
    if (!b) return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for %zu neighbour entries", need);
    if (keep) memcpy(b, *buf, sizeof(int) * keep);
    mem_free(*buf, sizeof(int) * *cap);
    *buf = b;
    *cap = nc;
    return HEARTH_OK;
}

/* One pass over the particles (the lists used to be walked twice, to count
 * and then to fill). The particles are split into one contiguous chunk per
 * thread; chunk 0 writes into nl->j, the others into their own buffers,
 * copied after it once the counts are known. A chunk whose buffer cannot
 * take the next particle's candidates stops there; its buffer grows (here,
 * between parallel regions, so allocation failures stay deterministic) and
 * it resumes. The lists do not depend on the chunks, so neither do they on
 * the thread count. */
hearth_status sph_nlist_build(sph_nlist *nl, const sph_cells *c, const double *x, int n, const double *h, double h0,
                              const double *m, double *rho, hearth_error *err) {
    hearth_status st = nlist_reserve(nl, n, 0, err);
    if (st) return st;
    nl->n = n;
    int T = 1;
#ifdef _OPENMP
    if (n >= 2048) T = omp_get_max_threads();
#endif
    if (T > n) T = n > 0 ? n : 1;
    if (T > nl->nchunk) {
        sph_nlist_chunk *ch = mem_calloc(sizeof *ch * (size_t)T);
        if (!ch) return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for neighbour lists");
        if (nl->nchunk) memcpy(ch, nl->chunk, sizeof *ch * (size_t)nl->nchunk);
        mem_free(nl->chunk, sizeof *ch * (size_t)nl->nchunk);
        nl->chunk = ch;
        nl->nchunk = T;
    }
    /* one h for all (the step's usual case): the walk reads no h_j */
    int uni = h != NULL && sph_fast_paths;
    for (int i = 1; i < n && uni; i++) uni = h[i] == h[0];
    for (int t = 0; t < T; t++) {
        nl->chunk[t].next = (int)((long)n * t / T);
        nl->chunk[t].used = 0;
    }
    for (;;) {
        int stuck = 0;
#pragma omp parallel for schedule(static, 1) num_threads(T) reduction(+ : stuck) if (T > 1)
        for (int t = 0; t < T; t++) {
            sph_nlist_chunk *ch = &nl->chunk[t];
            int *buf = t ? ch->j : nl->j;
            const size_t cap = t ? ch->cap : nl->ncap;
            const int end = (int)((long)n * (t + 1) / T);
            int lo[27], hi[27], cand;
            for (; ch->next < end; ch->next++) {
                const int i = ch->next, nr = stencil(c, x + 3 * i, lo, hi, &cand);
                if (ch->used + (size_t)cand > cap) {
                    ch->want = ch->used + (size_t)cand;
                    stuck++;
                    break;
                }
                const int k = walk(c, x, i, h, h0, m, rho, uni, lo, hi, nr, buf + ch->used);
                nl->off[i + 1] = k;
                ch->used += (size_t)k;
            }
        }
        if (!stuck) break;
        for (int t = 0; t < T; t++) {
            sph_nlist_chunk *ch = &nl->chunk[t];
            const int b = (int)((long)n * t / T), end = (int)((long)n * (t + 1) / T);
            if (ch->next >= end) continue;
            /* room for the rest of the chunk at the mean so far, and the stuck particle's candidates */
            const int done = ch->next - b;
            const size_t guess = done > 0 ? ch->used / (size_t)done * (size_t)(end - ch->next) : 0;
            if ((st = chunk_grow(nl, t, ch->used, ch->want > guess + ch->used ? ch->want : guess + ch->used, err)))
                return st;
        }
    }
    size_t total = 0;
    for (int t = 0; t < T; t++) total += nl->chunk[t].used;
    if ((st = chunk_grow(nl, 0, nl->chunk[0].used, total, err))) return st;
    size_t at = nl->chunk[0].used;
    for (int t = 1; t < T; t++) {
        if (nl->chunk[t].used) memcpy(nl->j + at, nl->chunk[t].j, sizeof(int) * nl->chunk[t].used);
        at += nl->chunk[t].used;
    }
    nl->off[0] = 0;
    for (int i = 0; i < n; i++) nl->off[i + 1] += nl->off[i];
    return HEARTH_OK;
}

void sph_nlist_free(sph_nlist *nl) {
    for (int t = 1; t < nl->nchunk; t++) mem_free(nl->chunk[t].j, sizeof(int) * nl->chunk[t].cap);
    mem_free(nl->chunk, sizeof(sph_nlist_chunk) * (size_t)nl->nchunk);
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

/* particles.c: SoA columns, their growth, permutation and copies. */
#include "particles.h"

#include <limits.h>
#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "team_wait.h"

#ifdef _OPENMP
#include <omp.h>
#endif

static const struct {
    const char *name;
    int ncomp; /* 0: state stride */
    int is_int;
} col_info[PC_COUNT] = {
    [PC_X] = {"x", 3, 0},           [PC_V] = {"v", 3, 0},
    [PC_C] = {"C", 9, 0},           [PC_F] = {"F", 9, 0},
    [PC_MASS] = {"mass", 1, 0},     [PC_VOL0] = {"vol0", 1, 0},
    [PC_MAT] = {"material", 1, 1},  [PC_ID] = {"id", 1, 1},
    [PC_STATE] = {"state", 0, 0},   [PC_TEMPERATURE] = {"temperature", 1, 0},
    [PC_TEMP_MAX] = {"temperature_max", 1, 0},
    [PC_BODY] = {"body", 1, 1},
    [PC_FLAGS] = {"flags", 1, 1},
    [PC_GAS] = {"gas", 1, 0},
    [PC_WATER] = {"water", 1, 0},
    [PC_SAT0] = {"saturation0", 1, 0},
    [PC_QW] = {"water_flux", 3, 0},
    [PC_MIX] = {"mix_ratios", 8, 0},
    [PC_MIXD] = {"mix_ratios_dynamic", 8, 0},
    [PC_BROWNING] = {"browning", 1, 0},
    [PC_DRIED] = {"dried", 1, 0},
    [PC_THERMAL] = {"thermal_strain", 1, 0},
    [PC_VENT] = {"vent_rate", 1, 0},
    [PC_SURFACE] = {"browning_surface", 2, 0},
    [PC_GLUE] = {"glue", 1, 1},
    [PC_GAS_MADE] = {"gas_made", 2, 0},
    [PC_THERMAL_MEMO] = {"thermal_memo", 2, 0},
    [PC_GAS_MEMO] = {"gas_memo", 2, 0},
    [PC_CURVE_MEMO] = {"curve_memo", CURVE_MEMO_WIDTH, 0},
    [PC_PLUGIN_MEMO] = {"plugin_memo", 0, 0}, /* memo_stride doubles */
};

const char *particles_col_name(int c) { return col_info[c].name; }

const char *particles_col_label(const particles *ps, int c) {
    if (ps->t2 && c == PC_C) return "C_xy";
    if (ps->t2 && c == PC_F) return "F_xy";
    return col_info[c].name;
}
int particles_col_is_int(int c) { return col_info[c].is_int; }

int particles_col_ncomp(const particles *ps, int c) {
    if (ps->t2 && (c == PC_C || c == PC_F)) return 4; /* the in-plane block (tensor2.h) */
    return col_info[c].ncomp ? col_info[c].ncomp : c == PC_PLUGIN_MEMO ? ps->memo_stride : ps->state_stride;
}

size_t particles_col_bytes(const particles *ps, int c) {
    return (size_t)particles_col_ncomp(ps, c) * (col_info[c].is_int ? sizeof(int) : sizeof(double));
}

void particles_init(particles *ps) {
    memset(ps, 0, sizeof *ps);
    for (int c = 0; c < PC_NCORE; c++) ps->enabled |= 1u << c;
}

void particles_free(particles *ps) {
    for (int c = 0; c < PC_COUNT; c++)
        if (ps->col[c]) mem_free(ps->col[c], particles_col_bytes(ps, c) * (size_t)ps->ccap[c]);
    uint32_t en = ps->enabled;
    const int t2 = ps->t2;
    memset(ps, 0, sizeof *ps);
    ps->enabled = en;
    ps->t2 = t2;
}

/* Columns grow one at a time with a realloc, so while they grow the store
 * holds its old columns plus one column's growth (not old and new copies of
 * every column at once: 1.5x the steady size for 2x growth, and more while
 * both lived). A failure part way leaves the grown columns grown (ccap
 * records their true room) and the store's cap and contents as they were. */
static hearth_status reserve_to(particles *ps, int ncap, hearth_error *err) {
    for (int c = 0; c < PC_COUNT; c++) {
        const size_t b = particles_col_bytes(ps, c);
        if (!(ps->enabled & (1u << c)) || b == 0 || ps->ccap[c] >= ncap) continue;
        void *p = mem_realloc(ps->col[c], b * (size_t)ps->ccap[c], b * (size_t)ncap);
        if (!p)
            return err_set(err, HEARTH_ERR_NOMEM, "out of memory growing particle column '%s' to %d particles",
                           col_info[c].name, ncap);
        /* the room past n is zeroed, as callers and particles_enable expect */
        memset((char *)p + b * (size_t)ps->n, 0, b * (size_t)(ncap - ps->n));
        ps->col[c] = p;
        ps->ccap[c] = ncap;
    }
    ps->cap = ncap;
    return HEARTH_OK;
}

hearth_status particles_reserve(particles *ps, int cap, hearth_error *err) {
    if (cap <= ps->cap) return HEARTH_OK;
    /* 1.5x: a growing store carries at most half its size spare (2x carried up to all of it) */
    const long grown = (long)ps->cap + ps->cap / 2;
    return reserve_to(ps, grown > cap && grown <= INT_MAX / 2 ? (int)grown : cap, err);
}

hearth_status particles_reserve_exact(particles *ps, int cap, hearth_error *err) {
    return cap <= ps->cap ? HEARTH_OK : reserve_to(ps, cap, err);
}

hearth_status particles_enable(particles *ps, int c, hearth_error *err) {
    if (ps->enabled & (1u << c)) return HEARTH_OK;
    size_t b = particles_col_bytes(ps, c) * (size_t)(ps->cap ? ps->cap : 0);
    if (b) {
        ps->col[c] = mem_calloc(b);
        if (!ps->col[c]) return err_set(err, HEARTH_ERR_NOMEM, "out of memory enabling field '%s'", col_info[c].name);
        ps->ccap[c] = ps->cap;
    }
    ps->enabled |= 1u << c;
    return HEARTH_OK;
}

hearth_status particles_set_state_stride(particles *ps, int stride, hearth_error *err) {
    if (stride <= ps->state_stride) return HEARTH_OK;
    int old = ps->state_stride;
    double *nu = NULL;
    if (ps->cap) {
        nu = mem_calloc(sizeof(double) * (size_t)stride * (size_t)ps->cap);
        if (!nu) return err_set(err, HEARTH_ERR_NOMEM, "out of memory growing plugin state to %d doubles", stride);
        const double *od = ps->col[PC_STATE];
        for (int i = 0; i < ps->n && old > 0; i++) memcpy(nu + (size_t)i * stride, od + (size_t)i * old, sizeof(double) * old);
        mem_free(ps->col[PC_STATE], sizeof(double) * (size_t)old * (size_t)ps->ccap[PC_STATE]);
    }
    ps->col[PC_STATE] = nu;
    ps->ccap[PC_STATE] = ps->cap;
    ps->state_stride = stride;
    return HEARTH_OK;
}

hearth_status particles_set_memo_stride(particles *ps, int stride, hearth_error *err) {
    const uint32_t bit = 1u << PC_PLUGIN_MEMO;
    if ((ps->enabled & bit) && stride <= ps->memo_stride) return HEARTH_OK;
    /* a cache (<hearth/material.h> rule 10): a wider column starts from zeros, which miss, rather than copy */
    if (ps->col[PC_PLUGIN_MEMO])
        mem_free(ps->col[PC_PLUGIN_MEMO], particles_col_bytes(ps, PC_PLUGIN_MEMO) * (size_t)ps->ccap[PC_PLUGIN_MEMO]);
    ps->col[PC_PLUGIN_MEMO] = NULL;
    ps->ccap[PC_PLUGIN_MEMO] = 0;
    ps->enabled &= ~bit;
    if (stride > ps->memo_stride) ps->memo_stride = stride;
    return particles_enable(ps, PC_PLUGIN_MEMO, err);
}

/* Gathers and copies run in parallel: each output element is written by one
 * thread from inputs nobody writes in the same loop, so the result is the
 * same bits for any thread count. Below this many particles a parallel
 * region costs more than it saves (scene.h's SCENE_PARALLEL_MIN). */
#define PERMUTE_PARALLEL_MIN 2048

/* One column in place through a ring of R records, when no particle moves
 * more than W places (R > W): place j is gathered into the ring, and place
 * j - W written back from it, once every place that could read the old
 * record there (within W of it) has been gathered. Records move whole and in
 * order: for C and F one pass of 72-byte records instead of nine strided
 * passes (the sort of a flowing 2D scene: 406 instructions per particle-step
 * for the component form, callgrind). B is the record's bytes, a
 * compile-time constant in the common widths so the copies inline. */
static inline __attribute__((always_inline)) void permute_window(char *col, const int *order, int n, int W, char *ring,
                                                                   int R, const size_t B) {
    int slot = 0, back = 0; /* ring slots of place j and of place j - W */
    for (int j = 0; j < n; j++) {
        memcpy(ring + (size_t)slot * B, col + (size_t)order[j] * B, B);
        if (++slot == R) slot = 0;
        if (j >= W) {
            memcpy(col + (size_t)(j - W) * B, ring + (size_t)back * B, B);
            if (++back == R) back = 0;
        }
    }
    for (int t = n - W > 0 ? n - W : 0; t < n; t++) {
        memcpy(col + (size_t)t * B, ring + (size_t)back * B, B);
        if (++back == R) back = 0;
    }
}

/* Places in [lo, hi) whose record moves (order[j] != j), in a loop the compiler vectorises. */
static int moved_places(const int *order, const int lo, const int hi) {
    int k = 0;
    for (int j = lo; j < hi; j++) k += order[j] != j;
    return k;
}

/* A team's range of places that moves under a quarter of them goes by
 * permute_sparse (particles_permute_team_range): after a step of the 2D
 * 128-cell bench 1-3% of the places move when any do, and the window copied
 * every record of every column twice, a memory-bound pass that two threads
 * did no faster than one (about 590 us a step at 1 thread and at 2;
 * docs/performance.md "Two threads, phase by phase"). A flowing scene moves
 * most places, where permute_sparse's branch per copy lost to the window's
 * plain copies (flow_step.lua, 2D, one thread: the permutation 1.55 -> 2.28 ms
 * a step, as the sole path).
 * One thread keeps the window: there permute_sparse showed no gain (the
 * permuting steps 4442 -> 4734 us, the P2G after it slower, within the
 * run-to-run spread this shared machine gave the same code: 3857 and 4266). */
static int permute_is_sparse(const int *order, const int lo, const int hi) { return 4 * moved_places(order, lo, hi) < hi - lo; }

/* Whether places [j, j + 8) all keep their records, vectorised. */
static inline int kept8(const int *order, const int j) {
    int d = 0;
    for (int k = 0; k < 8; k++) d |= order[j + k] ^ (j + k);
    return d == 0;
}

/* a ring slot moved on by k places */
static inline int slot_add(int slot, const int k, const int R) {
    slot += k;
    if (slot >= R) slot -= R;
    return slot < R ? slot : slot % R;
}

/* permute_range for a permutation that keeps most places: a place that keeps its record
 * (order[j] == j) is neither gathered nor written back, since no other place
 * reads it (order is a permutation) and so it holds its value throughout;
 * eight such places on both sides of the window are passed at once. A
 * place's ring slot is its distance from lo, mod R. */
static inline __attribute__((always_inline)) void permute_sparse(char *col, const int *order, int lo, int hi, int W, int R,
                                                                   int zl, const char *zlo, const char *zhi, char *ring,
                                                                   const size_t B) {
    int gs = 0, ws = 0; /* the ring slots of place j and of place j - W */
    for (int j0 = lo; j0 < hi; j0 += 8) {
        const int m = hi - j0 < 8 ? hi - j0 : 8;
        /* eight kept places, with none to write back (all before lo) or eight kept ones there too */
        if (m == 8 && kept8(order, j0) && (j0 + 8 - lo <= W || (j0 - W >= lo && kept8(order, j0 - W)))) {
            gs = slot_add(gs, 8, R);
            if (j0 - W >= lo) ws = slot_add(ws, 8, R);
            continue;
        }
        for (int j = j0; j < j0 + m; j++) {
            const int src = order[j];
            if (src != j) {
                const char *from = src < lo ? zlo + (size_t)(src - zl) * B : src >= hi ? zhi + (size_t)(src - hi) * B : col + (size_t)src * B;
                memcpy(ring + (size_t)gs * B, from, B);
            }
            if (++gs == R) gs = 0;
            const int p = j - W;
            if (p >= lo) {
                if (order[p] != p) memcpy(col + (size_t)p * B, ring + (size_t)ws * B, B);
                if (++ws == R) ws = 0;
            }
        }
    }
    for (int p = hi - W > lo ? hi - W : lo; p < hi; p++) {
        if (order[p] != p) memcpy(col + (size_t)p * B, ring + (size_t)ws * B, B);
        if (++ws == R) ws = 0;
    }
}

/* One column in place by following the permutation's cycles, for a
 * permutation that moves particles too far for the window's ring: place j
 * takes the record at order[j], then order[j] takes the one at its order,
 * until the cycle comes back to its first place, whose record waited in tmp.
 * done (n bits) marks the places written, so each cycle is followed once.
 * Each record is read once and whole, where a pass per component read each
 * record's cache lines once per component and needed n doubles of scratch;
 * this needs n bits (3D flow_step.lua, 32 cells, whose particles move up to
 * n / 3.3 places: 402 -> 247 instructions per particle-step, callgrind). Records wider than the stack's tmp (a plugin's large
 * state) go in slices of CYCLE_TMP bytes, a pass each. */
enum { CYCLE_TMP = 256 };
static inline __attribute__((always_inline)) void permute_cycles(char *col, const int *order, int n, uint64_t *done,
                                                                   const size_t B) {
    char tmp[CYCLE_TMP];
    for (size_t off = 0; off < B; off += CYCLE_TMP) {
        const size_t w = B - off < CYCLE_TMP ? B - off : CYCLE_TMP;
        char *base = col + off;
        memset(done, 0, sizeof(uint64_t) * (((size_t)n + 63) / 64));
        for (int i = 0; i < n; i++) {
            if (order[i] == i || (done[i >> 6] >> (i & 63) & 1)) continue;
            memcpy(tmp, base + (size_t)i * B, w);
            int j = i;
            for (int k = order[j]; k != i; j = k, k = order[j]) {
                memcpy(base + (size_t)j * B, base + (size_t)k * B, w);
                done[j >> 6] |= 1ull << (j & 63);
            }
            memcpy(base + (size_t)j * B, tmp, w);
            done[j >> 6] |= 1ull << (j & 63);
        }
    }
}

/* Column c through room bytes of scratch: the window's ring when it holds
 * more than W records, else the cycles (done in the scratch's first n bits). */
static void permute_column(particles *ps, int c, const int *order, int W, char *scratch, size_t room) {
    const size_t B = particles_col_bytes(ps, c);
    char *col = ps->col[c];
    const int n = ps->n;
    const int R = room / B > (size_t)n ? n + 1 : (int)(room / B);
    if (W < R) {
        switch (B) { /* the common widths as constants, so each copy is a few moves */
        case 4: permute_window(col, order, n, W, scratch, R, 4); break;
        case 8: permute_window(col, order, n, W, scratch, R, 8); break;
        case 24: permute_window(col, order, n, W, scratch, R, 24); break;
        case 32: permute_window(col, order, n, W, scratch, R, 32); break; /* a 2x2 store's C and F */
        case 64: permute_window(col, order, n, W, scratch, R, 64); break;
        case 72: permute_window(col, order, n, W, scratch, R, 72); break;
        default: permute_window(col, order, n, W, scratch, R, B); break;
        }
        return;
    }
    uint64_t *done = (uint64_t *)(void *)scratch;
    switch (B) {
    case 4: permute_cycles(col, order, n, done, 4); break;
    case 8: permute_cycles(col, order, n, done, 8); break;
    case 24: permute_cycles(col, order, n, done, 24); break;
    case 32: permute_cycles(col, order, n, done, 32); break;
    case 64: permute_cycles(col, order, n, done, 64); break;
    case 72: permute_cycles(col, order, n, done, 72); break;
    default: permute_cycles(col, order, n, done, B); break;
    }
}

void particles_permute(particles *ps, const int *order, void *scratch, size_t room) {
    const int n = ps->n;
    /* the farthest any particle moves: a sort of particles that moved a
     * little moves each by about the particles of the blocks it passed */
    int W = 0;
#pragma omp parallel for schedule(static) reduction(max : W) if (n >= PERMUTE_PARALLEL_MIN)
    for (int j = 0; j < n; j++) {
        const int d = order[j] > j ? order[j] - j : j - order[j];
        if (d > W) W = d;
    }
    particles_permute_within(ps, order, W, scratch, room);
}

/* The columns to move, widest first (the longest copies start first). */
static int permute_columns(const particles *ps, int par[PC_COUNT]) {
    int npar = 0;
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(ps->enabled & (1u << c)) || !ps->col[c] || particles_col_bytes(ps, c) == 0) continue;
        const size_t B = particles_col_bytes(ps, c);
        int q = npar++; /* insertion by width, widest first */
        while (q > 0 && particles_col_bytes(ps, par[q - 1]) < B) par[q] = par[q - 1], q--;
        par[q] = c;
    }
    return npar;
}

void particles_permute_within(particles *ps, const int *order, int W, void *scratch, size_t room) {
    const int n = ps->n;
    ps->edits++;
    if (W == 0) return; /* nothing moves */
    /* Columns are independent: with T threads each takes whole columns
     * (largest first) through its own 1/T of the scratch, 8-byte aligned,
     * which must hold the cycles' n bits (T is at most room / (n / 8): 32
     * threads for the 4 n bytes of MPM's keys). */
    const size_t bits = sizeof(uint64_t) * (((size_t)n + 63) / 64);
    int T = 1;
#ifdef _OPENMP
    if (n >= PERMUTE_PARALLEL_MIN) T = omp_get_max_threads();
    if (T < 1) T = 1;
#endif
    while (T > 1 && (room / (size_t)T & ~(size_t)7) < bits) T--;
    const size_t share = room / (size_t)T & ~(size_t)7;
    HEARTH_ASSERT(share >= bits);
    int par[PC_COUNT];
    const int npar = permute_columns(ps, par);
#pragma omp parallel num_threads(T) if (T > 1)
    {
        int me = 0;
#ifdef _OPENMP
        me = omp_get_thread_num();
#endif
        char *mine = (char *)scratch + share * (size_t)me;
#pragma omp for schedule(dynamic, 1)
        for (int q = 0; q < npar; q++) permute_column(ps, par[q], order, W, mine, share);
    }
}

void particles_permute_team(particles *ps, const int *order, int W, void *scratch, size_t room, team_wait *tw) {
    int T = 1, me = 0;
#ifdef _OPENMP
    T = omp_get_num_threads();
    me = omp_get_thread_num();
#endif
    const size_t bits = sizeof(uint64_t) * (((size_t)ps->n + 63) / 64), share = room / (size_t)T & ~(size_t)7;
    team_wait_barrier(tw);
    /* every thread is past its reads of edits and order's filling; one of them counts the edit */
#pragma omp single nowait
    ps->edits++;
    if (W == 0) return; /* nothing moves (every thread sees the same W) */
    int par[PC_COUNT];
    const int npar = permute_columns(ps, par);
    if (share < bits) { /* more threads than the scratch has shares for: one thread, all of it */
#pragma omp single
        for (int q = 0; q < npar; q++) permute_column(ps, par[q], order, W, scratch, room);
        return;
    }
#pragma omp for schedule(dynamic, 1) nowait
    for (int q = 0; q < npar; q++) permute_column(ps, par[q], order, W, (char *)scratch + share * (size_t)me, share);
    team_wait_barrier(tw);
}

/* One column's places [lo, hi) in place through a ring of W + 1 records, as
 * permute_window does the whole column; a source outside [lo, hi) (within W
 * of it) comes from the records saved before the team's barrier: zlo holds
 * the old places [zl, lo), zhi [hi, hi + W), since the threads that own them
 * may have moved them by now. */
static inline __attribute__((always_inline)) void permute_range(char *col, const int *order, int lo, int hi, int W,
                                                                  int zl, const char *zlo, const char *zhi, char *ring,
                                                                  const size_t B) {
    const int R = W + 1;
    int slot = 0, back = 0;
    for (int j = lo; j < hi; j++) {
        const int src = order[j];
        const char *from = src < lo ? zlo + (size_t)(src - zl) * B : src >= hi ? zhi + (size_t)(src - hi) * B : col + (size_t)src * B;
        memcpy(ring + (size_t)slot * B, from, B);
        if (++slot == R) slot = 0;
        if (j - lo >= W) {
            memcpy(col + (size_t)(j - W) * B, ring + (size_t)back * B, B);
            if (++back == R) back = 0;
        }
    }
    for (int t = hi - W > lo ? hi - W : lo; t < hi; t++) {
        memcpy(col + (size_t)t * B, ring + (size_t)back * B, B);
        if (++back == R) back = 0;
    }
}

int particles_permute_team_range(particles *ps, const int *order, int W, void *scratch, size_t room, int lo, int hi,
                                 team_wait *tw) {
    int T = 1, me = 0;
#ifdef _OPENMP
    T = omp_get_num_threads();
    me = omp_get_thread_num();
#endif
    int par[PC_COUNT];
    const int npar = permute_columns(ps, par), n = ps->n;
    size_t sum = 0, wide = 0;
    for (int q = 0; q < npar; q++) {
        const size_t B = particles_col_bytes(ps, par[q]);
        sum += B, wide = B > wide ? B : wide;
    }
    /* every thread decides alike (the same W, team, room and columns) */
    const size_t share = room / (size_t)T & ~(size_t)7, need = (2 * sum + wide) * (size_t)W + wide;
    if (W <= 0 || need > share) {
        particles_permute_team(ps, order, W, scratch, room, tw);
        return 0;
    }
    /* the old records within W outside this thread's places, every column's, before anyone moves any */
    char *mine = (char *)scratch + share * (size_t)me, *ring = mine + 2 * sum * (size_t)W;
    const int zl = lo - W > 0 ? lo - W : 0, zh = hi + W < n ? hi + W : n;
    size_t off = 0;
    for (int q = 0; q < npar; q++) {
        const size_t B = particles_col_bytes(ps, par[q]);
        const char *col = ps->col[par[q]];
        memcpy(mine + off, col + (size_t)zl * B, (size_t)(lo - zl) * B);
        memcpy(mine + off + (size_t)W * B, col + (size_t)hi * B, (size_t)(zh - hi) * B);
        off += 2 * (size_t)W * B;
    }
    team_wait_barrier(tw);
    /* every thread is past its reads of edits and order's filling, and every zone is saved */
#pragma omp single nowait
    ps->edits++;
    off = 0;
    /* this thread's places keep most records (permute_is_sparse), or the window's every copy */
    const int sparse = permute_is_sparse(order, lo, hi);
#define PERMUTE_AS(width)                                                                                    \
    (sparse ? permute_sparse(col, order, lo, hi, W, W + 1, zl, zlo, zhi, ring, width)                        \
            : permute_range(col, order, lo, hi, W, zl, zlo, zhi, ring, width))
    for (int q = 0; q < npar; q++) {
        const size_t B = particles_col_bytes(ps, par[q]);
        char *col = ps->col[par[q]];
        const char *zlo = mine + off, *zhi = mine + off + (size_t)W * B;
        switch (B) { /* the common widths as constants, so each copy is a few moves */
        case 4: PERMUTE_AS(4); break;
        case 8: PERMUTE_AS(8); break;
        case 24: PERMUTE_AS(24); break;
        case 32: PERMUTE_AS(32); break;
        case 72: PERMUTE_AS(72); break;
        default: PERMUTE_AS(B); break;
        }
        off += 2 * (size_t)W * B;
    }
#undef PERMUTE_AS
    team_wait_barrier(tw);
    return 1;
}

hearth_status particles_copy(particles *dst, const particles *src, hearth_error *err) {
    const unsigned long edits = dst->edits + 1;
    if (dst->state_stride != src->state_stride || dst->memo_stride != src->memo_stride || dst->enabled != src->enabled ||
        dst->t2 != src->t2 || dst->cap < src->n) {
        particles_free(dst);
        particles_init(dst);
        dst->enabled = src->enabled;
        dst->t2 = src->t2;
        dst->state_stride = src->state_stride;
        dst->memo_stride = src->memo_stride;
        hearth_status st = particles_reserve_exact(dst, src->n > 0 ? src->n : 1, err);
        if (st) return st;
    }
    for (int c = 0; c < PC_COUNT; c++)
        if ((src->enabled & (1u << c)) && src->col[c] && src->n)
            memcpy(dst->col[c], src->col[c], particles_col_bytes(src, c) * (size_t)src->n);
    dst->n = src->n;
    dst->edits = edits;
    return HEARTH_OK;
}

int particles_compact(particles *ps, const unsigned char *remove) {
    int w = 0;
    for (int i = 0; i < ps->n; i++) {
        if (remove[i]) continue;
        if (w != i)
            for (int c = 0; c < PC_COUNT; c++) {
                if (!(ps->enabled & (1u << c)) || !ps->col[c]) continue;
                size_t b = particles_col_bytes(ps, c);
                memcpy((char *)ps->col[c] + b * (size_t)w, (char *)ps->col[c] + b * (size_t)i, b);
            }
        w++;
    }
    int removed = ps->n - w;
    ps->n = w;
    ps->edits++;
    return removed;
}

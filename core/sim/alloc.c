/* alloc.c: counted allocation through the user's hook. */
#include "alloc.h"

#include <stdatomic.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hearth/hearth.h"

static void *default_alloc(void *ud, void *ptr, size_t osize, size_t nsize) {
    (void)ud;
    (void)osize;
    if (nsize == 0) {
        free(ptr);
        return NULL;
    }
    return realloc(ptr, nsize);
}

static hearth_alloc_fn g_fn = default_alloc;
static void *g_ud;
static atomic_size_t g_bytes, g_peak; /* held now, and the most held at once */
static atomic_long g_fail_after = -1;
/* hearth_set_memory_limit: the most the library may hold at once (SIZE_MAX:
 * no ceiling of its own), and whether an allocation was refused for it */
static atomic_size_t g_limit = SIZE_MAX;
static atomic_int g_limit_refused;

void hearth_set_allocator(hearth_alloc_fn fn, void *ud) {
    g_fn = fn ? fn : default_alloc;
    g_ud = fn ? ud : NULL;
}

size_t hearth_bytes_allocated(void) { return atomic_load(&g_bytes); }

size_t hearth_bytes_peak(void) { return atomic_load(&g_peak); }

void mem_fail_after(long n) { atomic_store(&g_fail_after, n); }

size_t hearth_machine_memory(void) {
    const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
    if (pages <= 0 || page <= 0) return SIZE_MAX; /* unknown */
    const double b = (double)pages * (double)page;
    return b >= (double)SIZE_MAX ? SIZE_MAX : (size_t)b;
}

void hearth_set_memory_limit(size_t bytes) {
    atomic_store(&g_limit, bytes ? bytes : SIZE_MAX);
    atomic_store(&g_limit_refused, 0);
}

size_t hearth_memory_limit(void) {
    const size_t set = atomic_load(&g_limit), machine = hearth_machine_memory();
    return set < machine ? set : machine;
}

int hearth_memory_limit_refused(void) { return atomic_load(&g_limit_refused); }

void mem_size_words(char *buf, size_t n, double bytes) {
    snprintf(buf, n, "%.3g %s", bytes / (bytes < 1e9 ? 1e6 : 1e9), bytes < 1e9 ? "MB" : "GB");
}

void mem_limit_words(char *buf, size_t n) {
    const size_t limit = hearth_memory_limit();
    /* --memory counts K, M, G in powers of 1024 (64M is 64 MiB, 67.1 MB): the ceiling as the user gave it, then in
     * the decimal MB or GB of the sizes beside it, so "--memory 64M" does not come back as an unexplained 67.1 MB */
    char given[40] = "";
    if (limit % ((size_t)1 << 30) == 0) snprintf(given, sizeof given, "%zu GiB = ", limit >> 30);
    else if (limit % ((size_t)1 << 20) == 0) snprintf(given, sizeof given, "%zu MiB = ", limit >> 20);
    char size[32];
    mem_size_words(size, sizeof size, (double)limit);
    snprintf(buf, n, "%s%s", given, size);
}

/* A growth past the ceiling fails as an out-of-memory would, so every caller's
 * existing NULL path reports it; the flag lets the program name the ceiling.
 * Two threads growing at once may both pass by a block: a ceiling, not an audit. */
static int over_limit(size_t osize, size_t nsize) {
    const size_t limit = atomic_load(&g_limit);
    if (limit == SIZE_MAX || nsize <= osize) return 0;
    const size_t held = atomic_load(&g_bytes) - osize;
    if (nsize <= limit && held <= limit - nsize) return 0;
    atomic_store(&g_limit_refused, 1);
    return 1;
}

static int should_fail(void) {
    long n = atomic_load(&g_fail_after);
    if (n < 0) return 0;
    if (n == 0) return 1;
    atomic_fetch_sub(&g_fail_after, 1);
    return 0;
}

/* A zero-byte block: not NULL, so that NULL from these calls always means
 * out of memory. A count that is legitimately 0 (a rank whose slab holds no
 * particle sizes its per-particle scratch by 0) was reported as "out of
 * memory for 0 particle volumes" and failed that rank's step alone (#21).
 * It is never passed to the hook, counts no bytes, and reading or writing
 * it is as wrong as past any block's end. */
static max_align_t g_empty;
#define EMPTY ((void *)&g_empty)

void *mem_realloc(void *p, size_t osize, size_t nsize) {
    if (p == EMPTY) p = NULL, osize = 0;
    if (nsize == 0) {
        mem_free(p, osize);
        return EMPTY;
    }
    if (should_fail() || over_limit(p ? osize : 0, nsize)) return NULL;
    void *q = g_fn(g_ud, p, p ? osize : 0, nsize);
    if (!q) return NULL;
    if (p) atomic_fetch_sub(&g_bytes, osize);
    const size_t held = atomic_fetch_add(&g_bytes, nsize) + nsize;
    size_t peak = atomic_load(&g_peak);
    while (held > peak && !atomic_compare_exchange_weak(&g_peak, &peak, held)) {
    }
    return q;
}

void *mem_alloc(size_t n) { return n ? mem_realloc(NULL, 0, n) : EMPTY; }

void *mem_calloc(size_t n) {
    void *p = mem_alloc(n);
    if (p) memset(p, 0, n);
    return p;
}

void mem_free(void *p, size_t n) {
    if (!p || p == EMPTY) return;
    g_fn(g_ud, p, n, 0);
    atomic_fetch_sub(&g_bytes, n);
}

char *mem_strdup(const char *s) {
    size_t n = strlen(s) + 1;
    char *d = mem_alloc(n);
    if (d) memcpy(d, s, n);
    return d;
}

void mem_strfree(char *s) {
    if (s) mem_free(s, strlen(s) + 1);
}

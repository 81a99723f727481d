/* ranks_serial.c: one rank, for a build without MPI (ranks.h). Every exchange
 * has nothing to exchange. */
#include <string.h>

#include "ranks.h"

int hearth_ranks_init(int *argc, char ***argv) {
    (void)argc, (void)argv;
    return 1;
}
int hearth_ranks_rank(void) { return 0; }
int hearth_ranks_size(void) { return 1; }
int hearth_ranks_built(void) { return 0; }
void hearth_ranks_finalize(void) {}
void hearth_ranks_traffic(double *bytes, double *seconds) { *bytes = *seconds = 0; }
double hearth_ranks_max(double v) { return v; }

int ranks_size(void) { return 1; }
int ranks_rank(void) { return 0; }
void ranks_allgather(void *base, size_t elem, const int *first) { (void)base, (void)elem, (void)first; }
hearth_status ranks_sum_grid(grid *g, int slot_lo, int slot_hi, hearth_error *err) {
    (void)g, (void)slot_lo, (void)slot_hi, (void)err;
    return HEARTH_OK;
}
void ranks_allgather_fixed(const void *mine, void *all, size_t bytes) {
    if (all != mine) memcpy(all, mine, bytes);
}
void ranks_count_step(int what) { (void)what; }
void ranks_count_held(int n) { (void)n; }
void hearth_ranks_held(int *least, int *most) { *least = *most = 0; }
void hearth_ranks_steps(long *slabs, long *replicated, long *passes) { *slabs = *replicated = *passes = 0; }
double hearth_ranks_gathered(void) { return 0; }
void ranks_max_bytes(unsigned char *buf, size_t n) { (void)buf, (void)n; }
void ranks_combine(void *mine, size_t bytes, void (*fn)(void *acc, const void *next, void *ctx), void *ctx) {
    (void)mine, (void)bytes, (void)fn, (void)ctx;
}
hearth_status ranks_neighbours(const void *down, size_t ndown, const void *up, size_t nup, const void **from_lo, size_t *nlo,
                               const void **from_hi, size_t *nhi, hearth_error *err) {
    (void)down, (void)ndown, (void)up, (void)nup, (void)err;
    *from_lo = *from_hi = NULL;
    *nlo = *nhi = 0;
    return HEARTH_OK;
}

/* ranks_serial.c: one rank, for a build without MPI (ranks.h). Every exchange
 * has nothing to exchange. */
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

int ranks_size(void) { return 1; }
int ranks_rank(void) { return 0; }
void ranks_allgather(void *base, size_t elem, const int *first) { (void)base, (void)elem, (void)first; }
hearth_status ranks_sum_grid(grid *g, int slot_lo, int slot_hi, hearth_error *err) {
    (void)g, (void)slot_lo, (void)slot_hi, (void)err;
    return HEARTH_OK;
}

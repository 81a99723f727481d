/* ranks.h: what the core asks of MPI, in a few calls. ranks_mpi.c does them
 * with MPI (built when meson finds it, -Dmpi); ranks_serial.c is the one-rank
 * stub, so the core builds and runs the same without MPI. Nothing else in the
 * core includes <mpi.h>.
 *
 * Every call is collective: every rank calls it, in the same order, with the
 * same shapes. Every result is the same on every rank and does not depend on
 * how MPI schedules its messages (no MPI_Allreduce of doubles: its order of
 * summation is the library's choice), so a run is deterministic for a given
 * rank count. */
#ifndef HEARTH_RANKS_H
#define HEARTH_RANKS_H
#include <stddef.h>

#include "grid.h"

int ranks_size(void);
int ranks_rank(void);
/// Rank r holds elements [first[r], first[r + 1]) of base (elem bytes each);
/// afterwards every rank holds all of them. first has ranks_size() + 1 entries.
void ranks_allgather(void *base, size_t elem, const int *first);
/// Sum the node data of g over the ranks: rank r's P2G wrote only storage
/// slots [slot_lo, slot_hi) of its copy (every rank has the same active
/// blocks). Afterwards every rank holds, at every node, 0 + c_0 + c_1 + ... in
/// rank order. NOMEM names the bytes it needed.
hearth_status ranks_sum_grid(grid *g, int slot_lo, int slot_hi, hearth_error *err);
#endif

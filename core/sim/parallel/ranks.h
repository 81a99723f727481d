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
/// One MPM step over the ranks, in the slab mode (what = 1) or the replicated
/// one (0); or (2) one more migration pass than the first (hearth_ranks_steps).
void ranks_count_step(int what);
/// The particles this rank holds after a slab-mode step (hearth_ranks_held).
void ranks_count_held(int n);
/// Every rank's `bytes` bytes at mine into all (ranks_size() x bytes), in rank order.
void ranks_allgather_fixed(const void *mine, void *all, size_t bytes);
/// Every rank's `bytes` bytes at mine (at most RANKS_COMBINE_MAX) combined in
/// rank order, the result in mine on every rank: fn(acc, next, ctx) puts
/// acc then next into acc, and must be associative up to rounding. The
/// grouping is a fixed binary tree (ranks 0-1, 2-3, then 0-3, ...), the
/// same for a given rank count; a rank receives at most ceil(log2 N) partial
/// results, rank 0's combination is then broadcast. Rejected: MPI_Reduce with
/// a user op (MPI may apply it in any grouping, even commuted for a
/// non-commutative op), and an allgather (every rank receives N of them).
enum { RANKS_COMBINE_MAX = 512 };
void ranks_combine(void *mine, size_t bytes, void (*fn)(void *acc, const void *next, void *ctx), void *ctx);
/// The bytewise maximum over the ranks of buf (n bytes), in place (integers:
/// the result does not depend on the order MPI combines them).
void ranks_max_bytes(unsigned char *buf, size_t n);
/// Slabs (mpm_ranks.c): send down[0..ndown) bytes to rank - 1 and up[0..nup)
/// to rank + 1 (none past the ends); receive what rank - 1 sent up into
/// *from_lo (*nlo bytes) and what rank + 1 sent down into *from_hi (*nhi).
/// The receive buffers are this module's, valid until the next call. NOMEM
/// names the bytes; it is then this rank's alone (the caller must not go on).
hearth_status ranks_neighbours(const void *down, size_t ndown, const void *up, size_t nup, const void **from_lo, size_t *nlo,
                               const void **from_hi, size_t *nhi, hearth_error *err);
#endif

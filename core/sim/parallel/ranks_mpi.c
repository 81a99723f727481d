/* ranks_mpi.c: ranks.h over MPI (MPI_COMM_WORLD), built when meson finds MPI.
 *
 * MPI starts only when mpirun started the process (its environment names a
 * world size): a plain `hearth run` of an MPI build stays one process and
 * never touches MPI, so it neither waits for a launcher nor prints MPI's
 * warnings. Threads: MPI_THREAD_FUNNELED, every call from the main thread
 * outside OpenMP's parallel regions.
 *
 * Determinism: the grid is summed by hand, not by MPI_Allreduce, whose order
 * of addition is the library's choice (tree or ring by message size): every
 * rank gathers each rank's written slots (MPI_Allgatherv moves bytes, adds
 * nothing) and adds them in rank order. The cost is that every rank receives
 * every rank's written slots (docs/scaling.md models it). */
#include <mpi.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "ranks.h"

static int started, rank_id, nranks = 1;
static int *counts, *displs, *spans; /* nranks, nranks, 2 nranks */
static double *sumbuf;
static unsigned char *nbuf[2]; /* what the lower and the upper neighbour sent (ranks_neighbours) */
static size_t nbcap[2];
static size_t sumcap; /* doubles in sumbuf */
static long steps_slabs, steps_replicated, extra_passes; /* MPM steps in each mode; migration passes past the first */
static double traffic_bytes, traffic_seconds;
static double gathered_bytes; /* of traffic_bytes: whole particle columns (ranks_allgather) */ /* received by this rank, and the time inside the exchanges */

static int launched_by_mpirun(void) {
    /* a hearth that an MPI job's rank starts as a child process (hearth trade
     * running its ladder over ranks) inherits the rank's environment: it must
     * not join that job */
    const char *no = getenv("HEARTH_NO_RANKS");
    if (no && no[0] == '1') return 0;
    static const char *const vars[] = {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "PMIX_RANK", "MPI_LOCALNRANKS", NULL};
    for (int k = 0; vars[k]; k++)
        if (getenv(vars[k])) return 1;
    return 0;
}

int hearth_ranks_init(int *argc, char ***argv) {
    if (started || !launched_by_mpirun()) return nranks;
    int provided = 0, already = 0;
    MPI_Initialized(&already);
    if (!already) MPI_Init_thread(argc, argv, MPI_THREAD_FUNNELED, &provided);
    MPI_Comm_rank(MPI_COMM_WORLD, &rank_id);
    MPI_Comm_size(MPI_COMM_WORLD, &nranks);
    counts = calloc((size_t)nranks, sizeof(int));
    displs = calloc((size_t)nranks, sizeof(int));
    spans = calloc(2 * (size_t)nranks, sizeof(int));
    if (!counts || !displs || !spans) MPI_Abort(MPI_COMM_WORLD, 1); /* a few ints per rank at start-up */
    started = 1;
    return nranks;
}

int hearth_ranks_rank(void) { return rank_id; }
int hearth_ranks_size(void) { return nranks; }
int hearth_ranks_built(void) { return 1; }

void hearth_ranks_finalize(void) {
    if (!started) return;
    mem_free(sumbuf, sumcap * sizeof(double));
    sumbuf = NULL, sumcap = 0;
    for (int k = 0; k < 2; k++) mem_free(nbuf[k], nbcap[k]), nbuf[k] = NULL, nbcap[k] = 0;
    free(counts), free(displs), free(spans);
    counts = displs = spans = NULL;
    int done = 0;
    MPI_Finalized(&done);
    if (!done) MPI_Finalize();
    started = 0;
}

void hearth_ranks_traffic(double *bytes, double *seconds) {
    *bytes = traffic_bytes;
    *seconds = traffic_seconds;
}

void ranks_count_step(int what) {
    if (what == 2) extra_passes++;
    else if (what) steps_slabs++;
    else steps_replicated++;
}

double hearth_ranks_gathered(void) { return gathered_bytes; }

static int held_least = -1, held_most; /* particles held after a slab-mode step; -1: none yet */

void ranks_count_held(int n) {
    if (held_least < 0 || n < held_least) held_least = n;
    if (n > held_most) held_most = n;
}

void hearth_ranks_held(int *least, int *most) {
    *least = held_least < 0 ? 0 : held_least;
    *most = held_most;
}

void hearth_ranks_steps(long *slabs, long *replicated, long *passes) {
    *slabs = steps_slabs;
    *replicated = steps_replicated;
    *passes = extra_passes;
}

int ranks_size(void) { return nranks; }
int ranks_rank(void) { return rank_id; }

void ranks_allgather(void *base, size_t elem, const int *first) {
    if (nranks == 1 || elem == 0) return;
    const double t0 = MPI_Wtime();
    MPI_Datatype t;
    MPI_Type_contiguous((int)elem, MPI_BYTE, &t);
    MPI_Type_commit(&t);
    for (int r = 0; r < nranks; r++) {
        counts[r] = first[r + 1] - first[r];
        displs[r] = first[r];
    }
    MPI_Allgatherv(MPI_IN_PLACE, 0, MPI_DATATYPE_NULL, base, counts, displs, t, MPI_COMM_WORLD);
    MPI_Type_free(&t);
    traffic_bytes += (double)elem * (double)(first[nranks] - first[0] - counts[rank_id]);
    gathered_bytes += (double)elem * (double)(first[nranks] - first[0] - counts[rank_id]);
    traffic_seconds += MPI_Wtime() - t0;
}

hearth_status ranks_sum_grid(grid *g, int slot_lo, int slot_hi, hearth_error *err) {
    if (nranks == 1) return HEARTH_OK;
    if (slot_hi < slot_lo) slot_hi = slot_lo; /* a rank with no particle blocks writes nothing */
    const double t0 = MPI_Wtime();
    const int span[2] = {slot_lo, slot_hi};
    MPI_Allgather(span, 2, MPI_INT, spans, 2, MPI_INT, MPI_COMM_WORLD);
    const size_t sd = (size_t)g->nch * (size_t)g->nodes_per_block; /* doubles per storage slot */
    size_t total = 0;
    for (int r = 0; r < nranks; r++) {
        counts[r] = spans[2 * r + 1] - spans[2 * r];
        displs[r] = (int)total;
        total += (size_t)counts[r];
    }
    /* every rank sees the same total, so all fail here together or none does */
    if (total * sd > sumcap) {
        size_t cap = total * sd + total * sd / 4;
        double *b = mem_alloc(cap * sizeof(double));
        if (!b) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the ranks' grid sum (%zu bytes)", cap * sizeof(double));
        mem_free(sumbuf, sumcap * sizeof(double));
        sumbuf = b, sumcap = cap;
    }
    MPI_Datatype t;
    MPI_Type_contiguous((int)sd, MPI_DOUBLE, &t);
    MPI_Type_commit(&t);
    MPI_Allgatherv(g->data + (size_t)slot_lo * sd, slot_hi - slot_lo, t, sumbuf, counts, displs, t, MPI_COMM_WORLD);
    MPI_Type_free(&t);
    traffic_bytes += (double)(total - (size_t)counts[rank_id]) * (double)sd * sizeof(double) + 2.0 * sizeof(int) * (nranks - 1);
    traffic_seconds += MPI_Wtime() - t0; /* the sum below is this rank's own work, not traffic */
    memset(g->data, 0, (size_t)g->nactive * sd * sizeof(double));
    for (int r = 0; r < nranks; r++) {
        double *dst = g->data + (size_t)spans[2 * r] * sd;
        const double *src = sumbuf + (size_t)displs[r] * sd;
        const size_t n = (size_t)counts[r] * sd;
#pragma omp parallel for schedule(static) if (n >= 65536)
        for (size_t j = 0; j < n; j++) dst[j] += src[j];
    }
    return HEARTH_OK;
}

void ranks_allgather_fixed(const void *mine, void *all, size_t bytes) {
    if (nranks == 1) {
        if (all != mine) memcpy(all, mine, bytes);
        return;
    }
    const double t0 = MPI_Wtime();
    MPI_Allgather(mine, (int)bytes, MPI_BYTE, all, (int)bytes, MPI_BYTE, MPI_COMM_WORLD);
    traffic_bytes += (double)bytes * (nranks - 1);
    traffic_seconds += MPI_Wtime() - t0;
}

void ranks_combine(void *mine, size_t bytes, void (*fn)(void *acc, const void *next, void *ctx), void *ctx) {
    if (nranks == 1 || bytes == 0) return;
    HEARTH_ASSERT(bytes <= RANKS_COMBINE_MAX);
    const double t0 = MPI_Wtime();
    unsigned char next[RANKS_COMBINE_MAX];
    double got = 0;
    /* at level `step`, a rank that is a multiple of 2 step holds ranks
     * [me, me + step) combined and adds [me + step, me + 2 step) from its
     * partner; a rank that is step past one sends its part up and is done */
    for (int step = 1; step < nranks; step *= 2) {
        if (rank_id % (2 * step) == 0) {
            if (rank_id + step < nranks) {
                MPI_Recv(next, (int)bytes, MPI_BYTE, rank_id + step, 73, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
                fn(mine, next, ctx);
                got += (double)bytes;
            }
        } else {
            MPI_Send(mine, (int)bytes, MPI_BYTE, rank_id - step, 73, MPI_COMM_WORLD);
            break;
        }
    }
    MPI_Bcast(mine, (int)bytes, MPI_BYTE, 0, MPI_COMM_WORLD);
    if (rank_id > 0) got += (double)bytes;
    traffic_bytes += got;
    traffic_seconds += MPI_Wtime() - t0;
}

double hearth_ranks_max(double v) {
    if (nranks == 1) return v;
    double m = v; /* a maximum is exact in any grouping */
    MPI_Allreduce(&v, &m, 1, MPI_DOUBLE, MPI_MAX, MPI_COMM_WORLD);
    return m;
}

void ranks_max_bytes(unsigned char *buf, size_t n) {
    if (nranks == 1 || n == 0) return;
    const double t0 = MPI_Wtime();
    MPI_Allreduce(MPI_IN_PLACE, buf, (int)n, MPI_UNSIGNED_CHAR, MPI_MAX, MPI_COMM_WORLD);
    traffic_bytes += (double)n; /* a reduction receives about one buffer, whatever its tree */
    traffic_seconds += MPI_Wtime() - t0;
}

/* Two phases: the byte counts (so the receiver can size its buffer), then the
 * bytes. Each phase is a send down and a send up, posted non-blocking so no
 * rank waits for a neighbour to post its receive first. */
hearth_status ranks_neighbours(const void *down, size_t ndown, const void *up, size_t nup, const void **from_lo, size_t *nlo,
                               const void **from_hi, size_t *nhi, hearth_error *err) {
    *from_lo = *from_hi = NULL;
    *nlo = *nhi = 0;
    if (nranks == 1) return HEARTH_OK;
    const double t0 = MPI_Wtime();
    const int lo = rank_id > 0 ? rank_id - 1 : MPI_PROC_NULL, hi = rank_id + 1 < nranks ? rank_id + 1 : MPI_PROC_NULL;
    unsigned long long sent[2] = {ndown, nup}, got[2] = {0, 0};
    MPI_Request rq[4];
    MPI_Irecv(&got[0], 1, MPI_UNSIGNED_LONG_LONG, lo, 71, MPI_COMM_WORLD, &rq[0]);
    MPI_Irecv(&got[1], 1, MPI_UNSIGNED_LONG_LONG, hi, 71, MPI_COMM_WORLD, &rq[1]);
    MPI_Isend(&sent[0], 1, MPI_UNSIGNED_LONG_LONG, lo, 71, MPI_COMM_WORLD, &rq[2]);
    MPI_Isend(&sent[1], 1, MPI_UNSIGNED_LONG_LONG, hi, 71, MPI_COMM_WORLD, &rq[3]);
    MPI_Waitall(4, rq, MPI_STATUSES_IGNORE);
    int fail = 0;
    for (int k = 0; k < 2; k++)
        if (got[k] > nbcap[k]) {
            unsigned char *b = mem_alloc(got[k] + got[k] / 4);
            if (!b) fail = 1;
            else {
                mem_free(nbuf[k], nbcap[k]);
                nbuf[k] = b, nbcap[k] = got[k] + got[k] / 4;
            }
        }
    if (fail) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the particles that cross into this rank (%llu bytes)", got[0] + got[1]);
    /* messages over 2 GB would need a derived type; a slab's crossings are far below */
    MPI_Irecv(nbuf[0], (int)got[0], MPI_BYTE, lo, 72, MPI_COMM_WORLD, &rq[0]);
    MPI_Irecv(nbuf[1], (int)got[1], MPI_BYTE, hi, 72, MPI_COMM_WORLD, &rq[1]);
    MPI_Isend(down, (int)ndown, MPI_BYTE, lo, 72, MPI_COMM_WORLD, &rq[2]);
    MPI_Isend(up, (int)nup, MPI_BYTE, hi, 72, MPI_COMM_WORLD, &rq[3]);
    MPI_Waitall(4, rq, MPI_STATUSES_IGNORE);
    *from_lo = nbuf[0], *nlo = got[0];
    *from_hi = nbuf[1], *nhi = got[1];
    traffic_bytes += (double)(got[0] + got[1]) + 2.0 * sizeof(unsigned long long) * ((lo != MPI_PROC_NULL) + (hi != MPI_PROC_NULL));
    traffic_seconds += MPI_Wtime() - t0;
    return HEARTH_OK;
}

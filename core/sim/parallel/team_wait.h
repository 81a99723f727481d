/* team_wait.h: waits for the threads of an OpenMP team that spin for a
 * while before they sleep. libgomp under OMP_WAIT_POLICY=passive (what
 * `hearth` sets, app/main.c) puts a waiting thread to sleep on a futex at
 * once, and waking it costs tens of microseconds: a 2D 128-cell step is
 * about 1.2 ms a thread, so its few barriers cost most of what two threads
 * lose against one (docs/performance.md, "A barrier that spins"). These
 * spin for an adaptive time first (long enough to catch the usual wait on
 * a quiet machine, short again once waits turn long, as when the partner
 * thread was descheduled on a loaded one), then sleep on a futex.
 *
 * HEARTH_TEAM_SPIN (microseconds, read by team_wait_init): unset, the
 * default cap TEAM_SPIN_DEFAULT_US; 0, every wait is the plain OpenMP
 * barrier (the old behaviour, and an escape hatch); 1..100000, the cap.
 *
 * A team_wait belongs to one team at a time (the MPM step keeps one in its
 * state); every thread of the enclosing region must call each wait, as for
 * `#pragma omp barrier`. Outside a region (one thread) they return at once. */
#ifndef HEARTH_SIM_TEAM_WAIT_H
#define HEARTH_SIM_TEAM_WAIT_H
#include "error.h"

#define TEAM_SPIN_DEFAULT_US 200
#define TEAM_SPIN_MAX_US 100000

/* Padded rather than _Alignas(64): the states that hold these come from
 * mem_calloc, whose alignment is malloc's, and an over-aligned member would
 * let the compiler assume more. The pads keep the words the waiters spin
 * on off the lines of their neighbours, which the step writes. */
typedef struct team_wait {
    char pad0_[64];
    /* the barrier: arrivals this round, and the round (the futex word); the
     * last thread to arrive resets count and bumps gen (release) */
    unsigned gen;
    unsigned count;
    int sleepers;          /* threads in (or about to enter) a futex wait on gen */
    char pad1_[64];
    int spin_ns;           /* the adaptive spin, shared by the team's threads (relaxed) */
    int max_ns;            /* its cap; 0: sleep at once; -1: the OpenMP barrier */
    long waits, sleeps;    /* waits that found the partner late, and those of them that slept (relaxed; tests, benches) */
} team_wait;

/* A count of finished work items that threads wait on instead of on each
 * other (team_count_wait): work handed out by claims can all be done while a
 * thread is still on its way, and then the others need not wait for it.
 * Reset it to 0 where no thread can be using it (before the region). */
typedef struct team_count {
    char pad0_[64];
    unsigned done; /* the futex word */
    int sleepers;
    char pad1_[64];
} team_count;

/// The spin cap from HEARTH_TEAM_SPIN (see above), or an error naming the
/// variable and its valid range for a value that is not a whole number of
/// microseconds in 0..TEAM_SPIN_MAX_US.
hearth_status team_wait_init(team_wait *tw, hearth_error *err);
/// As team_wait_init with the cap given (microseconds; -1 for the OpenMP barrier), for tests.
void team_wait_init_spin(team_wait *tw, int max_us);
/// Whether waits use the OpenMP barrier (HEARTH_TEAM_SPIN=0).
static inline int team_wait_is_omp(const team_wait *tw) { return tw->max_ns < 0; }

/// A barrier over the enclosing team: no thread returns before every thread
/// has called it, and every write before it is visible after it. tw NULL:
/// the OpenMP barrier (for callers outside the MPM step, and tests).
void team_wait_barrier(team_wait *tw);

/// Adds k finished items to c (release: the work's writes go with them).
void team_count_add(team_count *c, unsigned k);
/// Returns once c has reached target (acquire), spinning and sleeping as
/// team_wait_barrier does. With the OpenMP barrier chosen it is one instead,
/// so every thread of the team must call it.
void team_count_wait(team_wait *tw, team_count *c, unsigned target);

#endif

/* phase_clock.h: a measuring build's per-thread clocks at the MPM step's
 * phase boundaries (issue 20: why 2 threads are not twice 1 in 2D). Off,
 * which is every ordinary build, the marks are empty macros and
 * phase_clock.c compiles to nothing: no cost, no code. On
 * (`-Dc_args=-DHEARTH_PHASE_CLOCK`, scripts/bench/phase_clock.sh), each
 * mark reads the thread's wall clock (CLOCK_MONOTONIC) and CPU clock
 * (CLOCK_THREAD_CPUTIME_ID) and files the time since the thread's last
 * mark under the mark's phase, step by step; team_wait.c's waits add their
 * own wall and CPU time to a per-thread sum, so each phase's time splits
 * into work and waiting. A worker's first mark in a region counts from the
 * master's fork mark (the fork's latency). At exit the medians and means
 * per step go to the file named by HEARTH_PHASE_CLOCK_OUT (JSON), or
 * nowhere. */
#ifndef HEARTH_SIM_PHASE_CLOCK_H
#define HEARTH_SIM_PHASE_CLOCK_H

enum {
    PH_OUTSIDE,  /* from the last step's end to this step's start: the scene's own per-step work */
    PH_SORT_PRE, /* the sort's serial part before any region (keys, tables) */
    PH_FORK,     /* from the master's fork mark to this thread's first mark in the region */
    PH_COUNT,    /* the sort's count (2 threads: per chunk, with its wait) */
    PH_LISTS,    /* the block lists, marks and grid activation (3D: with the colour lists after the sort's region) */
    PH_ORDER,    /* keys out of order: the places and the order (2 threads; 1 thread's are in PH_COUNT) */
    PH_PERMUTE,  /* the particles' permutation (keys out of order) */
    PH_P2G,      /* P2G (2 threads: the tile store, with its wait) */
    PH_GRID,     /* the grid update (2 threads: with the gather, and its wait) */
    PH_G2P,      /* G2P */
    PH_JOIN,     /* the master: from its last mark in a region to after the region (the join; 3D: the sort's and the step's) */
    PH_REDUCE,   /* the master: the step report's reduction and the rest of mpm_step */
    PH_N
};

#ifdef HEARTH_PHASE_CLOCK
void phase_clock_mark(int phase);
void phase_clock_fork(void);             /* the master, just before a region it times */
void phase_clock_step(void);             /* the master, at mpm_step's start: a new step, PH_OUTSIDE */
void phase_clock_wait(long wall, long cpu); /* team_wait.c: a wait's wall and CPU nanoseconds */
long phase_clock_cpu_ns(void);
long phase_clock_wall_ns(void);
#define PHASE_MARK(p) phase_clock_mark(p)
#define PHASE_FORK() phase_clock_fork()
#define PHASE_STEP() phase_clock_step()
#define PHASE_WAIT_BEGIN() const long ph_w0_ = phase_clock_wall_ns(), ph_c0_ = phase_clock_cpu_ns()
#define PHASE_WAIT_END() phase_clock_wait(phase_clock_wall_ns() - ph_w0_, phase_clock_cpu_ns() - ph_c0_)
#else
#define PHASE_MARK(p) ((void)0)
#define PHASE_FORK() ((void)0)
#define PHASE_STEP() ((void)0)
#define PHASE_WAIT_BEGIN() ((void)0)
#define PHASE_WAIT_END() ((void)0)
#endif

#endif

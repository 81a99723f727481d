/* phase_clock.c: the measuring build's per-thread phase clocks
 * (phase_clock.h says what and why). Compiled to nothing unless
 * HEARTH_PHASE_CLOCK is defined. Each step's times are kept raw, per step,
 * thread and phase, and written out at exit, so the script takes medians
 * (a loaded machine's preemptions land in a few steps' wall times). */
#include "phase_clock.h"

#ifdef HEARTH_PHASE_CLOCK
#include <stdio.h>
#include <stdlib.h>
#include <time.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#define PH_THREADS 4
#define PH_STEPS 20000

enum { PH_WALL, PH_CPU, PH_WAIT_WALL, PH_WAIT_CPU, PH_KINDS };

typedef struct ph_thread {
    long last_wall, last_cpu, wait_wall, wait_cpu, mark_wait_wall, mark_wait_cpu;
    unsigned fork_seen;
    char pad_[64];
} ph_thread;

static ph_thread ph_t[PH_THREADS];
static int ph_data[PH_STEPS][PH_THREADS][PH_N][PH_KINDS]; /* nanoseconds */
static int ph_step_now = -1, ph_nthreads = 1;
static unsigned ph_fork_gen;
static long ph_fork_wall;

long phase_clock_wall_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long)ts.tv_sec * 1000000000L + ts.tv_nsec;
}

long phase_clock_cpu_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
    return (long)ts.tv_sec * 1000000000L + ts.tv_nsec;
}

static int me(void) {
#ifdef _OPENMP
    const int t = omp_get_thread_num();
    return t < PH_THREADS ? t : -1;
#else
    return 0;
#endif
}

static const char *const ph_names[PH_N] = {"outside", "sort_pre", "fork", "count", "lists", "order", "permute",
                                           "p2g", "grid", "g2p", "join", "reduce"};

static void ph_write(void) {
    const char *path = getenv("HEARTH_PHASE_CLOCK_OUT");
    if (!path || !*path || ph_step_now < 0) return;
    FILE *f = fopen(path, "w");
    if (!f) return;
    const int steps = ph_step_now + 1 < PH_STEPS ? ph_step_now + 1 : PH_STEPS;
    fprintf(f, "{\"threads\": %d, \"phases\": [", ph_nthreads);
    for (int p = 0; p < PH_N; p++) fprintf(f, "%s\"%s\"", p ? ", " : "", ph_names[p]);
    fprintf(f, "], \"kinds\": [\"wall\", \"cpu\", \"wait_wall\", \"wait_cpu\"], \"steps\": [\n");
    for (int s = 0; s < steps; s++) {
        fprintf(f, "%s[", s ? ",\n" : "");
        for (int t = 0; t < ph_nthreads; t++) {
            fprintf(f, "%s[", t ? ", " : "");
            for (int p = 0; p < PH_N; p++)
                fprintf(f, "%s[%d, %d, %d, %d]", p ? ", " : "", ph_data[s][t][p][0], ph_data[s][t][p][1], ph_data[s][t][p][2],
                        ph_data[s][t][p][3]);
            fprintf(f, "]");
        }
        fprintf(f, "]");
    }
    fprintf(f, "\n]}\n");
    fclose(f);
}

void phase_clock_mark(int phase) {
    const int t = me();
    if (t < 0 || ph_step_now < 0) return;
    ph_thread *th = &ph_t[t];
    const long w = phase_clock_wall_ns(), c = phase_clock_cpu_ns();
    const unsigned gen = __atomic_load_n(&ph_fork_gen, __ATOMIC_ACQUIRE);
    if (th->fork_seen != gen) { /* the first mark in a new region: from the fork, as PH_FORK */
        th->fork_seen = gen;
        if (t > 0) {
            if (t + 1 > ph_nthreads) ph_nthreads = t + 1; /* only thread 1 writes it at 2 threads */
            if (ph_step_now < PH_STEPS) {
                int *d = ph_data[ph_step_now][t][PH_FORK];
                d[PH_WALL] += (int)(w - ph_fork_wall);
                d[PH_CPU] += (int)(th->last_cpu ? c - th->last_cpu : 0);
            }
            th->last_wall = w, th->last_cpu = c;
            th->mark_wait_wall = th->wait_wall, th->mark_wait_cpu = th->wait_cpu;
            return;
        }
    }
    if (ph_step_now < PH_STEPS) {
        int *d = ph_data[ph_step_now][t][phase];
        d[PH_WALL] += (int)(w - th->last_wall);
        d[PH_CPU] += (int)(c - th->last_cpu);
        d[PH_WAIT_WALL] += (int)(th->wait_wall - th->mark_wait_wall);
        d[PH_WAIT_CPU] += (int)(th->wait_cpu - th->mark_wait_cpu);
    }
    th->last_wall = w, th->last_cpu = c;
    th->mark_wait_wall = th->wait_wall, th->mark_wait_cpu = th->wait_cpu;
}

void phase_clock_fork(void) {
    ph_thread *th = &ph_t[0];
    ph_fork_wall = phase_clock_wall_ns();
    th->last_wall = ph_fork_wall, th->last_cpu = phase_clock_cpu_ns();
    __atomic_add_fetch(&ph_fork_gen, 1, __ATOMIC_RELEASE);
}

void phase_clock_step(void) {
    if (ph_step_now < 0) {
        atexit(ph_write);
        ph_t[0].last_wall = phase_clock_wall_ns(), ph_t[0].last_cpu = phase_clock_cpu_ns();
    }
    phase_clock_mark(PH_OUTSIDE); /* into the last step's row: the time between the steps */
    ph_step_now++;
}

void phase_clock_wait(long wall, long cpu) {
    const int t = me();
    if (t < 0) return;
    ph_t[t].wait_wall += wall, ph_t[t].wait_cpu += cpu;
}
#else
typedef int phase_clock_off_; /* ISO C wants a declaration in every file */
#endif

/* team_wait.c: spin-then-sleep waits for an OpenMP team (team_wait.h says
 * why). The barrier is a counting barrier with a round number (a sense
 * reversal that never needs its sense reset: the round only grows); a
 * waiter spins on the round with a pause instruction for the team's
 * adaptive time, then sleeps on it with FUTEX_WAIT, and the last arrival
 * wakes the sleepers with FUTEX_WAKE only when there are some (a quiet
 * step makes no system call). Elsewhere than Linux the sleep is a yield
 * loop. */
#ifdef __linux__
#define _DEFAULT_SOURCE /* syscall(), which the build's _POSIX_C_SOURCE leaves out */
#endif
#include "team_wait.h"
#include "phase_clock.h"

#include <errno.h>
#include <limits.h>
#include <sched.h>
#include <stdlib.h>
#include <time.h>

#ifdef __linux__
#include <linux/futex.h>
#include <sys/syscall.h>
#include <unistd.h>
#endif

#ifdef _OPENMP
#include <omp.h>
#endif

/* The spin never falls below this: a wait shorter than a microsecond or so
 * costs nothing to catch, and the budget has to be able to grow back. */
#define TEAM_SPIN_MIN_NS 1000
/* Waits on a quiet machine are mostly under 16 us (2D 128 cells, 2 threads: 97% of those the spin caught) */
#define TEAM_YIELD_AFTER_NS 16000

hearth_status team_wait_init(team_wait *tw, hearth_error *err) {
    const char *v = getenv("HEARTH_TEAM_SPIN");
    long us = TEAM_SPIN_DEFAULT_US;
    if (v && *v) {
        char *end;
        errno = 0;
        us = strtol(v, &end, 10);
        if (errno || *end || us < 0 || us > TEAM_SPIN_MAX_US)
            return err_set(err, HEARTH_ERR_PARAM,
                           "environment: HEARTH_TEAM_SPIN=\"%s\" is not a whole number of microseconds in 0..%d "
                           "(0: the plain OpenMP barrier; unset: %d)",
                           v, TEAM_SPIN_MAX_US, TEAM_SPIN_DEFAULT_US);
    }
    team_wait_init_spin(tw, us == 0 ? -1 : (int)us);
    return HEARTH_OK;
}

void team_wait_init_spin(team_wait *tw, int max_us) {
    *tw = (team_wait){0};
    tw->max_ns = max_us < 0 ? -1 : max_us * 1000;
    tw->spin_ns = tw->max_ns > 0 ? tw->max_ns : 0; /* start generous: the first waits teach it */
}

static long now_ns(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (long)ts.tv_sec * 1000000000L + ts.tv_nsec;
}

static inline void cpu_pause(void) {
#if defined(__x86_64__) || defined(__i386__)
    __builtin_ia32_pause();
#elif defined(__aarch64__)
    __asm__ __volatile__("yield");
#endif
}

static void futex_sleep(unsigned *word, unsigned seen) {
#ifdef __linux__
    syscall(SYS_futex, word, FUTEX_WAIT_PRIVATE, seen, NULL, NULL, 0);
#else
    (void)word, (void)seen;
    sched_yield();
#endif
}

static void futex_wake_all(unsigned *word) {
#ifdef __linux__
    syscall(SYS_futex, word, FUTEX_WAKE_PRIVATE, INT_MAX, NULL, NULL, 0);
#else
    (void)word;
#endif
}

/* The budget after a wait of d ns: a wait the spin caught, or one slept
 * through that a spin within the cap would have caught, sets the spin to
 * twice it (waits vary; a short spin that just misses costs a whole
 * wake-up); a wait past the cap halves it, since spinning then only takes
 * the core from whoever the late thread is waiting behind. Racy updates
 * between the team's threads only blur the estimate. */
static void spin_learn(team_wait *tw, long d) {
    const int cur = __atomic_load_n(&tw->spin_ns, __ATOMIC_RELAXED);
    int next;
    if (d <= tw->max_ns) {
        const long want = 2 * d;
        next = want > tw->max_ns ? tw->max_ns : want > cur ? (int)want : cur;
    } else {
        next = cur / 2 > TEAM_SPIN_MIN_NS ? cur / 2 : TEAM_SPIN_MIN_NS;
    }
    if (next != cur) __atomic_store_n(&tw->spin_ns, next, __ATOMIC_RELAXED);
}

/* Until *word differs from seen (acquire): spin, then sleep. sleepers
 * counts this thread before it reads the word for the last time, and the
 * writer reads sleepers after it writes the word (both sequentially
 * consistent), so either the writer sees a sleeper and wakes it or the
 * sleeper sees the new word; FUTEX_WAIT itself returns at once when the
 * word has moved on. */
static void wait_change(team_wait *tw, unsigned *word, int *sleepers, unsigned seen) {
    if (__atomic_load_n(word, __ATOMIC_ACQUIRE) != seen) return;
    __atomic_fetch_add(&tw->waits, 1, __ATOMIC_RELAXED);
    const long t0 = now_ns(), budget = __atomic_load_n(&tw->spin_ns, __ATOMIC_RELAXED);
    if (budget > 0)
        for (unsigned k = 1;; k++) {
            cpu_pause();
            if (__atomic_load_n(word, __ATOMIC_ACQUIRE) != seen) {
                spin_learn(tw, now_ns() - t0);
                return;
            }
            if ((k & 63) == 0) {
                const long d = now_ns() - t0;
                if (d > budget) break;
                /* Past the usual wait on a quiet machine, give the core away now and then: on a loaded one the
                 * thread waited for may be queued behind this one (yield returns at once on an idle core). */
                if (d > TEAM_YIELD_AFTER_NS) sched_yield();
            }
        }
    __atomic_fetch_add(&tw->sleeps, 1, __ATOMIC_RELAXED);
    __atomic_fetch_add(sleepers, 1, __ATOMIC_SEQ_CST);
    while (__atomic_load_n(word, __ATOMIC_SEQ_CST) == seen) futex_sleep(word, seen);
    __atomic_fetch_sub(sleepers, 1, __ATOMIC_RELAXED);
    if (tw->max_ns > 0) spin_learn(tw, now_ns() - t0);
}

static void publish(unsigned *word, int *sleepers, unsigned v) {
    __atomic_store_n(word, v, __ATOMIC_SEQ_CST);
    if (__atomic_load_n(sleepers, __ATOMIC_SEQ_CST)) futex_wake_all(word);
}

static int team_size(void) {
#ifdef _OPENMP
    return omp_get_num_threads();
#else
    return 1;
#endif
}

void team_wait_barrier(team_wait *tw) {
    const int T = team_size();
    if (T <= 1) return;
    PHASE_WAIT_BEGIN();
    if (!tw || team_wait_is_omp(tw)) {
#pragma omp barrier
        PHASE_WAIT_END();
        return;
    }
    /* the round cannot move before this thread arrives, and this thread saw the last round's end */
    const unsigned g = __atomic_load_n(&tw->gen, __ATOMIC_RELAXED);
    if (__atomic_add_fetch(&tw->count, 1, __ATOMIC_ACQ_REL) == (unsigned)T) {
        __atomic_store_n(&tw->count, 0, __ATOMIC_RELAXED); /* ordered before the new round by publish */
        publish(&tw->gen, &tw->sleepers, g + 1);
        PHASE_WAIT_END();
        return;
    }
    wait_change(tw, &tw->gen, &tw->sleepers, g);
    PHASE_WAIT_END();
}

void team_count_add(team_count *c, unsigned k) {
    if (!k) return;
    __atomic_add_fetch(&c->done, k, __ATOMIC_SEQ_CST); /* before the read of sleepers (wait_change) */
    /* any waiter's target may be this value or an earlier one: wake them to look */
    if (__atomic_load_n(&c->sleepers, __ATOMIC_SEQ_CST)) futex_wake_all(&c->done);
}

void team_count_wait(team_wait *tw, team_count *c, unsigned target) {
    PHASE_WAIT_BEGIN();
    if (team_wait_is_omp(tw)) {
        if (team_size() > 1) {
#pragma omp barrier
        }
        PHASE_WAIT_END();
        return;
    }
    for (;;) {
        const unsigned v = __atomic_load_n(&c->done, __ATOMIC_ACQUIRE);
        if (v >= target) break;
        wait_change(tw, &c->done, &c->sleepers, v);
    }
    PHASE_WAIT_END();
}

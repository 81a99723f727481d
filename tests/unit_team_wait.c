/* unit_team_wait.c: the spin-then-sleep waits of the MPM step's teams
 * (core/sim/parallel/team_wait.c): a barrier no thread passes early, sleepers
 * woken, a count of work waited for, and the environment variable checked. */
#include <omp.h>
#include <stdlib.h>
#include <time.h>

#include "team_wait.h"
#include "test.h"

static void sleep_us(long us) {
    struct timespec ts = {us / 1000000, (us % 1000000) * 1000};
    nanosleep(&ts, NULL);
}

/* Rounds of a barrier with every thread adding 1 to a shared counter before
 * it: after round r's barrier each thread must see every thread's r + 1
 * additions (none passed early) and at most one more from each (none got a
 * round ahead). At 2 and 3 threads (3 on 2 cores: the partner is often
 * descheduled, so waits sleep), with the default spin, a 1 us cap (mostly
 * sleeps) and 0 (always sleeps). */
TEST(team_wait_rounds_whole) {
    const int caps[3] = {TEAM_SPIN_DEFAULT_US, 1, 0};
    for (int T = 2; T <= 3; T++)
        for (int ci = 0; ci < 3; ci++) {
            team_wait tw;
            team_wait_init_spin(&tw, caps[ci]);
            const long rounds = caps[ci] == 0 ? 1000 : 4000;
            long counter = 0, bad = 0, ran = 0;
#pragma omp parallel num_threads(T) reduction(+ : bad)
            {
#pragma omp single
                ran = omp_get_num_threads();
                for (long r = 0; r < rounds; r++) {
                    __atomic_fetch_add(&counter, 1, __ATOMIC_RELAXED);
                    team_wait_barrier(&tw);
                    const long c = __atomic_load_n(&counter, __ATOMIC_RELAXED);
                    bad += c < T * (r + 1) || c > T * (r + 2);
                    if ((r & 255) == 0 && omp_get_thread_num() == 1) sleep_us(50); /* a late thread now and then */
                }
            }
            CHECK(ran == T);
            CHECK(bad == 0);
            CHECK(counter == T * rounds);
            if (bad) fprintf(stderr, "T %d cap %d us: %ld rounds seen out of step\n", T, caps[ci], bad);
        }
}

/* A thread that went to sleep on the futex is woken when the last one
 * arrives: with the spin at 0 every early arrival sleeps; thread 1 comes 20
 * ms late, so thread 0 is asleep by then (counted), and its write before the
 * barrier is seen after it. A lost wake-up hangs here (meson's timeout). */
TEST(team_wait_sleepers_woken) {
    team_wait tw;
    team_wait_init_spin(&tw, 0);
    int payload[8] = {0}, seen[8] = {0};
#pragma omp parallel num_threads(2)
    for (int r = 0; r < 8; r++) {
        if (omp_get_thread_num() == 1) {
            sleep_us(20000);
            payload[r] = r + 1;
        }
        team_wait_barrier(&tw);
        if (omp_get_thread_num() == 0) seen[r] = payload[r];
    }
    for (int r = 0; r < 8; r++) CHECK(seen[r] == r + 1);
    CHECK(tw.sleeps >= 8); /* thread 0 slept every round */
    CHECK(tw.waits >= tw.sleeps);
}

/* team_count_wait returns once the count of finished items reaches its
 * target and not before: thread 1 does 64 items slowly (each writes its
 * slot, then counts it), thread 0 does none and waits for all 64, then
 * reads every slot; with the spin at 0 (sleeps) and at the default (spins).
 * With the OpenMP barrier chosen it is a barrier, so the same holds. */
TEST(team_count_waits_for_work) {
    const int caps[3] = {0, TEAM_SPIN_DEFAULT_US, -1};
    for (int ci = 0; ci < 3; ci++) {
        team_wait tw;
        team_wait_init_spin(&tw, caps[ci]);
        team_count c = {.done = 0};
        int slot[64] = {0}, missing = 0;
        unsigned done_at_return = 0;
#pragma omp parallel num_threads(2)
        {
            if (omp_get_thread_num() == 1)
                for (int k = 0; k < 64; k++) {
                    if (k % 8 == 0) sleep_us(2000);
                    slot[k] = k + 1;
                    team_count_add(&c, 1);
                }
            team_count_wait(&tw, &c, 64);
            if (omp_get_thread_num() == 0) {
                done_at_return = __atomic_load_n(&c.done, __ATOMIC_RELAXED);
                for (int k = 0; k < 64; k++) missing += slot[k] != k + 1;
            }
        }
        CHECK(done_at_return == 64);
        CHECK(missing == 0);
        if (caps[ci] == 0) CHECK(tw.sleeps >= 1); /* thread 0 slept at least once, and was woken */
    }
}

/* HEARTH_TEAM_SPIN: unset the default cap, 0 the OpenMP barrier, a number of
 * microseconds the cap; anything else an error naming the variable and its
 * valid range. */
TEST(team_wait_env_checked) {
    team_wait tw;
    hearth_error err = {0};
    unsetenv("HEARTH_TEAM_SPIN");
    CHECK(team_wait_init(&tw, &err) == HEARTH_OK);
    CHECK(tw.max_ns == TEAM_SPIN_DEFAULT_US * 1000 && !team_wait_is_omp(&tw));
    setenv("HEARTH_TEAM_SPIN", "0", 1);
    CHECK(team_wait_init(&tw, &err) == HEARTH_OK);
    CHECK(team_wait_is_omp(&tw));
    setenv("HEARTH_TEAM_SPIN", "50", 1);
    CHECK(team_wait_init(&tw, &err) == HEARTH_OK);
    CHECK(tw.max_ns == 50000);
    const char *bad[] = {"abc", "-3", "100001", "20us", "1e3"};
    for (int k = 0; k < 5; k++) {
        setenv("HEARTH_TEAM_SPIN", bad[k], 1);
        CHECK(team_wait_init(&tw, &err) == HEARTH_ERR_PARAM);
        CHECK_STR_CONTAINS(err.msg, "HEARTH_TEAM_SPIN");
        CHECK_STR_CONTAINS(err.msg, bad[k]);
        CHECK_STR_CONTAINS(err.msg, "0..100000");
    }
    unsetenv("HEARTH_TEAM_SPIN");
}

TEST_MAIN(T(team_wait_rounds_whole), T(team_wait_sleepers_woken), T(team_count_waits_for_work), T(team_wait_env_checked))

/* progress.c: the progress bar. */
#include "progress.h"

#include <stdio.h>
#include <time.h>
#include <unistd.h>

double progress_wall(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return ts.tv_sec + 1e-9 * ts.tv_nsec;
}

void progress_start(progress *p, double t_end, int quiet) {
    p->t0_wall = p->last_print = progress_wall();
    p->t_end = t_end;
    p->run_wall0 = p->t0_wall, p->run_t0 = 0;
    p->steps0 = 0;
    p->shown_t = -1, p->shown_steps = -1;
    p->tty = isatty(2);
    p->quiet = quiet;
}

void progress_run_start(progress *p, double t, double t_end, long steps) {
    p->run_wall0 = progress_wall();
    p->run_t0 = t, p->t_end = t_end, p->steps0 = steps;
    p->shown_t = -1, p->shown_steps = -1; /* a new run's last line is its own, whatever it reads */
}

/* The fraction, rate and ETA are the current run's (since progress_run_start), elapsed the process's. */
static void draw(progress *p, double t, long steps, int final) {
    const double now = progress_wall(), el = now - p->t0_wall, run_el = now - p->run_wall0;
    const double span = p->t_end - p->run_t0;
    const double frac = span > 0 ? (t - p->run_t0) / span : 1.0;
    const double sps = run_el > 0 ? (steps - p->steps0) / run_el : 0.0;
    const double eta = frac > 1e-9 && frac < 1 ? run_el * (1 - frac) / frac : 0.0;
    if (p->tty) {
        char bar[31];
        int k = (int)(frac * 30 + 0.5);
        for (int i = 0; i < 30; i++) bar[i] = i < k ? '#' : '.';
        bar[30] = '\0';
        fprintf(stderr, "\r[%s] %3.0f%%  t = %.4g / %.4g s  %.0f steps/s  ETA %.0f s   %s", bar, 100 * frac, t, p->t_end, sps,
                eta, final ? "\n" : "");
    } else {
        /* a run's last line once: its last batch of steps may just have printed the same t and steps (a 3D bread
         * at dx 3 mm, whose batches take seconds, had printed its 100% line twice) */
        if (final && t == p->shown_t && steps == p->shown_steps) return;
        fprintf(stderr, "progress: t = %.4g / %.4g s (%.0f%%), %ld steps, %.0f steps/s, elapsed %.1f s\n", t, p->t_end,
                100 * frac, steps, sps, el);
        p->shown_t = t, p->shown_steps = steps;
    }
    fflush(stderr);
}

void progress_update(progress *p, double t, long steps) {
    if (p->quiet) return;
    const double now = progress_wall();
    if (now - p->last_print < (p->tty ? 0.1 : 5.0)) return;
    p->last_print = now;
    draw(p, t, steps, 0);
}

void progress_finish(progress *p, double t, long steps) {
    if (p->quiet) return;
    draw(p, t, steps, 1);
}

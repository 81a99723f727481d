/* progress.h: progress on stderr for long runs. A live bar when stderr is a
 * terminal, otherwise one plain line every few seconds (for logs and CI). */
#ifndef HEARTH_APP_PROGRESS_H
#define HEARTH_APP_PROGRESS_H

typedef struct progress {
    double t0_wall, last_print, t_end;
    double run_wall0, run_t0; /* the current run's start: its wall time and sim time */
    long steps0;              /* the step count at the current run's start */
    double shown_t;           /* the sim time and steps of the last plain line printed (not on a terminal) */
    long shown_steps;
    int tty, quiet;
} progress;

void progress_start(progress *p, double t_end, int quiet);
/// A new run (s:run) starts at sim time t after `steps` steps, to end at t_end: the rate and the ETA are its own
/// (a scene that runs one scene after another, cookies.lua's ovens, had shown its later runs' steps over the whole
/// process's time); elapsed stays the process's.
void progress_run_start(progress *p, double t, double t_end, long steps);
/// Report sim time t after `steps` steps in total.
void progress_update(progress *p, double t, long steps);
void progress_finish(progress *p, double t, long steps);
double progress_wall(void);
#endif

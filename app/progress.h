/* progress.h: progress on stderr for long runs. A live bar when stderr is a
 * terminal, otherwise one plain line every few seconds (for logs and CI). */
#ifndef HEARTH_APP_PROGRESS_H
#define HEARTH_APP_PROGRESS_H

typedef struct progress {
    double t0_wall, last_print, t_end;
    long steps0;
    int tty, quiet;
} progress;

void progress_start(progress *p, double t_end, int quiet);
/// Report sim time t after `steps` steps in total.
void progress_update(progress *p, double t, long steps);
void progress_finish(progress *p, double t, long steps);
double progress_wall(void);
#endif

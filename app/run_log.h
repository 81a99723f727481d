/* run_log.h: the record of a `hearth run` (<out>/run.log and run.json). */
#ifndef HEARTH_APP_RUN_LOG_H
#define HEARTH_APP_RUN_LOG_H
#include <lua.h>
#include <time.h>

#include "commands.h"

typedef struct run_log {
    const run_args *a;
    time_t start;
    double t0; /* monotonic seconds at the start */
    int have_scene;
    long steps, particles;
    double sim_t;
    char message[1024]; /* why the run stopped, when it failed */
} run_log;

/// Note the start and write the record with status "running".
void run_log_start(run_log *r, const run_args *a);
/// Take steps, sim time and particles from the scene the file built (if any).
void run_log_scene(run_log *r, lua_State *L);
/// The error message of a failed run.
void run_log_message(run_log *r, const char *msg);
/// (Re)write both files; status -1 while running, else the exit status.
/// Failures to write are silent: the record must never change a run's outcome.
void run_log_write(const run_log *r, int status);
#endif

/* run_log.h: the record of a `hearth run`, `demo` or `trade` (<out>/run.log and run.json). */
#ifndef HEARTH_APP_RUN_LOG_H
#define HEARTH_APP_RUN_LOG_H
#include <lua.h>
#include <time.h>

#include "hearth/hearth.h"

typedef struct run_log {
    const char *cmd;          /* "run", "demo", "trade" */
    int argc;                 /* the command line; argv[0] is the subcommand */
    char **argv;
    const char *scene;        /* the scene file, or NULL (the built-in demo) */
    const char *out;          /* the output folder the record goes in */
    const char *const *sets;  /* --set name=value */
    int nsets;
    time_t start;
    struct timespec start_fs; /* the start on the clock file times come from */
    double t0;                /* monotonic seconds at the start */
    int have_scene;
    long steps, particles;
    double sim_t;
    int rollbacks;
    char guard[32];           /* "ok", "rolled_back", "stopped" or a trade's count */
    char diagnosis[1024];     /* what the guard said, when it acted */
    int runs, jobs;           /* hearth trade: runs in the ladder, at a time (0: not a trade) */
    int threads;              /* threads per run when not this process's (hearth trade) */
    int nplugins;             /* plugins the runs loaded, when not this process's (hearth trade) */
    struct { char name[64], file[1024]; int abi; } plugins[16];
    const char *status_1;     /* what exit status 1 means for this command (NULL: "scene error") */
    char message[1024];       /* why the run stopped, when it failed */
} run_log;

/// Note the start and write the record with status "running".
void run_log_start(run_log *r, const char *cmd, int argc, char **argv, const char *scene, const char *out,
                   const char *const *sets, int nsets);
/// Take steps, sim time, particles and the guard's state from the scene the file built (if any).
void run_log_scene(run_log *r, lua_State *L);
/// The same from a scene's statistics (hearth demo).
void run_log_stats(run_log *r, const hearth_stats *st);
/// Take the plugins from a run record's run.log (the runs of hearth trade load them, not trade).
void run_log_plugins_from(run_log *r, const char *run_log_path);
/// The error message of a failed run.
void run_log_message(run_log *r, const char *msg);
/// (Re)write both files; status -1 while running, else the exit status. The
/// final record lists the files written under the output folder since the start.
/// Failures to write are silent: the record must never change a run's outcome.
void run_log_write(const run_log *r, int status);
/// The git revision hearth was built from ("unknown" outside a git checkout).
const char *run_log_revision(void);
#endif

/* commands.h: the subcommands of the hearth executable. Each returns the
 * process exit status: 0 ok, 1 a scene or run error, 2 bad usage, 3 guard stop. */
#ifndef HEARTH_APP_COMMANDS_H
#define HEARTH_APP_COMMANDS_H
#include "hearth/hearth.h"

int cmd_demo(int argc, char **argv);
int cmd_plugins(int argc, char **argv);
int cmd_plugin_check(int argc, char **argv);
int cmd_bench(int argc, char **argv);
int cmd_run(int argc, char **argv);
int cmd_repl(int argc, char **argv);
int cmd_rheometer(int argc, char **argv);
int cmd_fit(int argc, char **argv);
int cmd_trade(int argc, char **argv);
/// hearth scenes: the shipped scenes, each one's path and header's first sentence (cmd_scenes.c)
int cmd_scenes(int argc, char **argv);
/// hearth help scene; hearth doc man|lua (cmd_settings.c)
int cmd_help(int argc, char **argv);
int cmd_doc(int argc, char **argv);

int cmd_dashboard(int argc, char **argv);

/// The options of hearth run / hearth repl / the dashboard (cmd_run.c).
typedef struct run_args {
    const char *scene;
    const char *out;
    double until;
    long frames;
    int quiet, trust;
    int list_params; /* --params: list the scene's parameters (h.params) and stop, nothing simulated or written */
    size_t lua_memory; /* --lua-memory SIZE in bytes; 0 = the default ceiling */
    size_t memory;     /* --memory SIZE in bytes: the library's ceiling (hearth_set_memory_limit); 0 = half the machine's */
    const char *metric, *metric_out; /* --metric NAME [--metric-out FILE] (used by hearth trade) */
    const char *vtu;                 /* --vtu DIR: VTU frames and a .pvd from every s:run, under the output folder */
    const char *movie;               /* --movie FILE: every s:run's PNG frames also become this movie (ffmpeg) */
    int argc;                        /* the command line, for the run record (run_log.c) */
    char **argv;
    const char *sets[65];
    int nsets;
    char out_buf[4096], dir_buf[4096];
    const char *out_shared; /* under mpirun, ranks > 0: rank 0's output folder, read from, never written (cmd_run_ranks.c) */
} run_args;
/// Parse them; prints usage errors. Returns 0 ok, 1 when --help was printed, 2 bad usage.
/// The scene file is required for cmd "run"; the output folder defaults to hearth-out/<scene name>.
int app_run_parse(run_args *a, int argc, char **argv, const char *cmd);
/// Under mpirun, a rank other than 0 writes into a private scratch folder (put
/// in scratch, n bytes) and prints nothing (cmd_run_ranks.c); 1 when it cannot.
int app_ranks_follow(run_args *a, char *scratch, size_t n);
/// Remove that scratch folder (nothing for rank 0).
void app_ranks_cleanup(const char *scratch);
/// Rank 0 of several, unless --quiet: the ranks' exchange traffic and its share of the run, on stderr;
/// a quiet rank > 0 whose run failed (status, message) other than by the guard: that failure, on its own stderr.
void app_ranks_report(const run_args *a, int status, const char *message);
/// The built-in demo scene (cmd_run_demo.c): a jelly disc and syrup falling into a cup.
hearth_scene *app_demo_scene(hearth_error *err);

/* shared by the rheometer and fit commands (cmd_rheometer.c) */
int app_flow_plot(const char *path, const char *title, const double *x, const double *y, int n, const char *data_label,
                  const double *cx, const double *cy, int cn, const char *curve_label, hearth_error *err);
const char *app_sauce_library_path(const char *override);
/// The assets folder: $HEARTH_ASSETS_DIR, else the source tree's assets/ (cmd_rheometer.c).
const char *app_assets_dir(void);

/// Parse a whole positive integer option value; prints a usage error and returns -1 when bad.
long app_parse_int(const char *cmd, const char *flag, const char *text, long min, long max);
/// The name in the NULL-terminated list nearest to word (edit distance at most
/// a third of its length, at least 1), for "did you mean"; NULL when none is near (main.c).
const char *app_did_you_mean(const char *word, const char *const *names);
#endif

/* trade.h: what the parts of `hearth trade` share: the ladder, its runs, and
 * the launchers. cmd_trade.c parses options, builds the ladder, runs it on the
 * local cores and analyses it; trade_report.c writes the CSV, plot and table;
 * trade_launch.c runs the ladder through Slurm or mpirun, and gathers each
 * run's record (runs/NNN/run.txt) back into a ladder (--collect). */
#ifndef HEARTH_APP_TRADE_H
#define HEARTH_APP_TRADE_H
#include <sys/resource.h>
#include <sys/types.h>

#define MAX_KNOBS 12
#define MAX_VALUES 32
#define MAX_RUNS 4096
#define MAX_SETS 32
#define MAX_LAUNCHER_ARGS 32

typedef struct knob {
    char name[64];
    int n;
    char *v[MAX_VALUES];
    char buf[2048];
} knob;

typedef enum run_state { RS_WAIT, RS_RUNNING, RS_OK, RS_GUARD, RS_ERROR, RS_CRASH } run_state;
extern const char *const trade_state_name[]; /* indexed by run_state */

typedef struct trade_run {
    int vi[MAX_KNOBS]; /* value index per knob */
    run_state st;
    pid_t pid;
    double t0, wall, metric, ref, err, rel, order, h, peak_mb;
    long steps;
    int series, pareto, is_ref;
    int mine; /* run by this process (a worker runs only its share) */
    char msg[512];
} trade_run;

typedef enum trade_launcher { TL_LOCAL, TL_SLURM, TL_MPI } trade_launcher;

typedef struct trade {
    const char *scene, *metric, *reference, *until;
    char out[4096];
    knob k[MAX_KNOBS];
    int nk;
    const char *sets[MAX_SETS];
    int nsets, jobs, threads, quiet, trust;
    trade_launcher launcher;
    const char *launcher_args[MAX_LAUNCHER_ARGS]; /* --launcher-arg: passed to sbatch or mpirun */
    int nlauncher_args, no_wait;
    int scene_arg;      /* argv index of the scene, to store it as an absolute path */
    trade_run *r;
    int nr;
    int refine; /* knob index of the refinement knob, or -1 */
    char analytic[1024];
} trade;

/* cmd_trade.c */
/// Print "hearth trade: <fmt with a> (see --help)" on stderr; returns 2.
int trade_bad_usage(const char *fmt, const char *a);
/// Parse hearth trade's options (argv[0] is "trade"). 0 ok, 1 --help printed, 2 bad usage (printed).
int trade_parse(trade *T, int argc, char **argv);
/// Parse and build the ladder (T->r is the caller's to free, also on failure). As trade_parse.
int trade_setup(trade *T, int argc, char **argv);
/// Build the runs from the knobs. 0 ok, 1 out of memory, 2 too many runs or bad values (printed).
int trade_build_ladder(trade *T);
/// Run the runs marked `mine`, T->jobs at a time, each a `hearth run` child; records each.
int trade_run_all(trade *T);
/// "dx=0.01 heat=implicit" (all knobs, or all but the refinement knob).
void trade_run_label(const trade *T, const trade_run *r, int skip_refine, char *buf, size_t n);
/// DIR/runs/NNN for run i.
void trade_run_dir(const trade *T, int i, char *buf, size_t n);
/// Analyse, write trade.csv and trade.png, print the table. The exit status (0, 1, or 2).
int trade_finish(trade *T, int rc);

/* trade_report.c */
int trade_write_csv(const trade *T, const char *path);
int trade_write_plot(const trade *T, const char *path);
void trade_print_table(const trade *T);

/* trade_launch.c */
/// Write run i's record runs/NNN/run.txt (status, wall, steps, peak memory, metric, note).
int trade_record_write(const trade *T, int i);
/// Read run i's record; 0 when there was one. Without one, the run keeps its state.
int trade_record_read(trade *T, int i);
/// Store the ladder's arguments as DIR/trade.args (absolute scene and out), for workers and --collect.
int trade_args_write(const trade *T, int argc, char **argv);
/// Run the ladder through Slurm (one job array) or mpirun, then gather. The exit status.
int trade_launch(trade *T);
/// hearth trade --collect DIR: gather the records in DIR into the table, CSV and plot.
int trade_collect(const char *dir, int quiet);
/// hearth trade --worker slurm|mpi DIR: this task's or rank's share of the ladder in DIR.
int trade_worker(int argc, char **argv);
#endif

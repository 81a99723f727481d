/* cmd_run_ranks.c: `mpirun -n N hearth run`: what the ranks other than 0 do
 * with their outputs. Every reader sees the whole scene on every rank
 * (core/sim/solver/mpm_ranks.c), so rank 0 alone writes the outputs (PNG,
 * CSV, probes, s:vtu, the run record) and prints; the others run the same
 * scene file into a private scratch folder, removed at the end, and print
 * nothing (set HEARTH_RANKS_VERBOSE=1 to keep their messages) but a
 * failure that may be theirs alone (app_ranks_report). The one
 * exception, s:run's VTU frames, are a piece per rank that every rank
 * writes into rank 0's folder (out_shared, lua_output.c's l_vtu_frame). Rejected: a write switch
 * in the core, which every writer (atomic files, PNG, Lua's io.open) would
 * have to consult. */
/* nftw and mkdtemp: the build defines _XOPEN_SOURCE */
#include <ftw.h>
#include <stdio.h>
#include <stdlib.h>
#include <unistd.h>

#include "commands.h"
#include "hearth/hearth.h"

static int quiet_stderr = -1; /* a quiet rank's own stderr, kept for a failure of its own */

int app_ranks_follow(run_args *a, char *scratch, size_t n) {
    scratch[0] = '\0';
    if (hearth_ranks_rank() == 0) return 0;
    const char *tmp = getenv("TMPDIR") && getenv("TMPDIR")[0] ? getenv("TMPDIR") : "/tmp";
    snprintf(scratch, n, "%s/hearth-rank%d-XXXXXX", tmp, hearth_ranks_rank());
    if (!mkdtemp(scratch)) {
        fprintf(stderr, "hearth run (rank %d): cannot make a scratch folder under %s\n", hearth_ranks_rank(), tmp);
        scratch[0] = '\0';
        return 1;
    }
    a->out_shared = a->out; /* a checkpoint an earlier run left there is still read from it */
    a->out = scratch;
    a->quiet = 1;
    a->metric_out = NULL;
    a->movie = NULL;
    const char *v = getenv("HEARTH_RANKS_VERBOSE");
    if (!(v && v[0] == '1')) {
        quiet_stderr = dup(STDERR_FILENO);
        if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr)) return 1;
    }
    return 0;
}

static int remove_entry(const char *path, const struct stat *sb, int flag, struct FTW *ftw) {
    (void)sb, (void)flag, (void)ftw;
    remove(path);
    return 0;
}

void app_ranks_cleanup(const char *scratch) {
    if (scratch && scratch[0]) nftw(scratch, remove_entry, 16, FTW_DEPTH | FTW_PHYS);
}

/* Rank 0's line; with HEARTH_RANKS_VERBOSE=1 too, every rank's (the others' stderr is kept then).
 * A quiet rank whose run failed says why (status, message): the failure may
 * be its alone (an allocation on an empty slab, a Lua error only it raised),
 * and without it the user would see only mpirun's notice that a rank exited
 * non-zero. A failure every rank meets alike then prints once per rank, each
 * line naming its rank; the guard's stop, which reaches every rank at the
 * same step, stays rank 0's alone to print. */
void app_ranks_report(const run_args *a, int status, const char *message) {
    const char *verbose = getenv("HEARTH_RANKS_VERBOSE");
    if (quiet_stderr >= 0) {
        if (status && status != 3) dprintf(quiet_stderr, "hearth run (MPI rank %d): %s\n", hearth_ranks_rank(), message);
        close(quiet_stderr);
        quiet_stderr = -1;
    }
    if (hearth_ranks_size() == 1 || (hearth_ranks_rank() > 0 && !(verbose && verbose[0] == '1'))) return;
    double bytes, seconds;
    hearth_ranks_traffic(&bytes, &seconds);
    const char *v = getenv("HEARTH_RANKS_REPORT");
    if (a->quiet && !(v && v[0] == '1')) return;
    long slabs, replicated, passes;
    hearth_ranks_steps(&slabs, &replicated, &passes);
    const long steps = slabs + replicated;
    const double gathered = hearth_ranks_gathered();
    int least, most;
    hearth_ranks_held(&least, &most);
    fprintf(stderr,
            "hearth run: %d MPI ranks, %ld steps in slabs and %ld replicated, %ld extra migration passes; rank %d received %.3g MB in the exchanges "
            "(%.4g kB a step), %.3g s inside them; whole-set gathers %.3g MB, the rest %.4g kB a step; it held %d to %d particles after a slab step\n",
            hearth_ranks_size(), slabs, replicated, passes, hearth_ranks_rank(), bytes / 1e6, steps ? bytes / 1e3 / (double)steps : 0.0,
            seconds, gathered / 1e6, steps ? (bytes - gathered) / 1e3 / (double)steps : 0.0, least, most);
}

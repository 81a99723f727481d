/* cmd_trade.c: `hearth trade SCENE.lua --metric NAME --knob k=v1,v2...`: the
 * speed/accuracy trade of a scene. Every combination of knob values is one
 * `hearth run` in its own process (so peak memory and wall time are the run's
 * own), up to --jobs at a time with the cores shared out as OpenMP threads.
 * Each run reports a metric; against a reference (the finest run or an
 * analytic value) that gives an error, and along a refinement knob (dx, dt_max,
 * cfl or ppc) the observed order of convergence. Results go to a CSV, a
 * log-log PNG of error against wall time with the Pareto front, and a table.
 *
 * A run is `hearth run SCENE --metric NAME --metric-out FILE --set k=v...`
 * (wall time and peak memory from wait4), --jobs at a time with
 * cores / jobs OpenMP threads each. Knobs are plain --sets: init.lua applies
 * a name the scene declares in h.params to the parameter, and otherwise to
 * the scene setting of that name (the settings settings.c marks as knobs,
 * listed by `hearth help scene` and `hearth trade --help`; ppc in every
 * s:add; blend in h.mix). Metrics are h.metric(name, fn) or built in
 * (h.builtin_metrics: height, spread, centre_temperature, front, volume,
 * water_lost), evaluated by `hearth run --metric` after the scene ran. The
 * refinement knob (the first of dx, dt_max, cfl, ppc with several values)
 * gives the series and observed orders; the plot is a <hearth/plot.h> plot
 * like the rheometer's: a series per refinement ladder (coarse to fine,
 * joined), the Pareto front as rings behind. scripts/trade/ holds the
 * default ladders, docs/trade/ their results.
 *
 * --launcher slurm|mpi hands the same runs to a Slurm job array or to mpirun
 * ranks (trade_launch.c); every run, wherever it ran, leaves runs/NNN/run.txt,
 * and the ladder's arguments are stored as trade.args, so --collect DIR and
 * the launchers gather into exactly the table a local ladder gives. */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE /* wait4 and struct rusage's ru_maxrss */
#endif
#include <errno.h>
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <fcntl.h>
#include <time.h>
#include <unistd.h>

#include "commands.h"
#include "hearth/hearth.h"
#include "hearth/plot.h"
#include "progress.h"
#include "run_log.h"
#include "trade.h"

const char *const trade_state_name[] = {"waiting", "running", "ok", "guard", "error", "crash"};

static void usage(FILE *f) {
    fprintf(f,
            "usage: hearth trade SCENE.lua --metric NAME [--knob name=v1,v2,...]... [--reference finest|analytic:EXPR]\n"
            "                    [--out DIR] [--jobs N] [--threads N] [--until T] [--set k=v]... [--quiet] [--trust]\n"
            "                    [--launcher local|slurm|mpi] [--launcher-arg ARG]... [--no-wait]\n"
            "       hearth trade --collect DIR [--quiet]\n"
            "Runs the scene once for every combination of knob values, each run a separate\n"
            "`hearth run` process, and measures what each setting costs and buys.\n"
            "  --metric NAME   what to measure at the end of a run: a metric the scene declares with\n"
            "                  h.metric(NAME, function(s) ... end), or a built-in: height, spread,\n"
            "                  centre_temperature, front, volume, water_lost\n"
            "  --knob k=a,b,c  values to try: a parameter the scene declares with h.params{...}, ppc (every\n"
            "                  s:add), or a scene setting (hearth help scene):");
    /* the settings a knob may change: the schema's, so this list cannot drift from h.scene's */
    int n = 0, col = 66;
    const hearth_setting *set = hearth_scene_settings(&n);
    for (int k = 0; k < n; k++) {
        if (!set[k].knob) continue;
        char item[128];
        int len = snprintf(item, sizeof item, " %s", set[k].name);
        for (int w = 0; set[k].words && set[k].words[w] && len < (int)sizeof item; w++)
            len += snprintf(item + len, sizeof item - (size_t)len, "%s%s", w ? "|" : " (", set[k].words[w]);
        if (set[k].words && len < (int)sizeof item) len += snprintf(item + len, sizeof item - (size_t)len, ")");
        if (col + len > 100) fprintf(f, "\n                 "), col = 17;
        fputs(item, f);
        col += len;
    }
    fprintf(f,
            "\n"
            "  --reference R   finest (default): each series' run with the smallest refinement knob (dx, else\n"
            "                  dt_max, cfl, ppc; among equals the one with most steps), or\n"
            "                  analytic:EXPR, a Lua expression with math.* and the run's knobs as variables\n"
            "  --out DIR       results folder (default ./hearth-out/trade-<scene>): trade.csv, trade.png,\n"
            "                  and runs/NNN/ with each run's log and outputs\n"
            "  --jobs N        runs at a time (default: the number of cores); each run gets\n"
            "                  cores/N OpenMP threads so the machine is not oversubscribed\n"
            "  --threads N     OpenMP threads per run (default: OMP_NUM_THREADS when set, else cores/jobs;\n"
            "                  1 with --launcher slurm)\n"
            "  --until T, --set k=v, --trust   passed to every run\n"
            "  --launcher L    where the runs run: local (default: child processes on this machine),\n"
            "                  slurm (one Slurm job array, `sbatch --array`, a task per run, each\n"
            "                  --cpus-per-task=THREADS; --jobs N caps the tasks running at once), or\n"
            "                  mpi (`mpirun -n JOBS`: each rank takes runs until none is left; no MPI\n"
            "                  library is linked). The out DIR must be on a filesystem every node sees.\n"
            "  --launcher-arg A   one more argument for sbatch or mpirun, e.g. --launcher-arg\n"
            "                  --partition=short --launcher-arg --time=2:00:00, or --oversubscribe\n"
            "  --no-wait       slurm: submit the job array and return; gather later with --collect\n"
            "  --collect DIR   gather the runs' records in DIR (runs/NNN/run.txt) into the table,\n"
            "                  trade.csv and trade.png, e.g. after a Slurm job array finished\n"
            "Per run: wall time, steps, peak memory (the run's own), the metric, its error against\n"
            "the reference, and the observed order p = log(e1/e2) / log(h1/h2) between successive\n"
            "refinements of runs that differ only in the refinement knob.\n"
            "Exit status: 0 when every run finished, 1 when some did not, 2 bad usage.\n");
}

int trade_bad_usage(const char *fmt, const char *a) {
    fprintf(stderr, "hearth trade: ");
    fprintf(stderr, fmt, a);
    fprintf(stderr, " (see --help)\n");
    return 2;
}

static int parse_knob(trade *T, const char *text) {
    if (T->nk == MAX_KNOBS) return trade_bad_usage("at most %s --knob options", "12");
    const char *eq = strchr(text, '=');
    if (!eq || eq == text || !eq[1]) return trade_bad_usage("--knob needs name=v1,v2,..., got '%s'", text);
    knob *k = &T->k[T->nk];
    memset(k, 0, sizeof *k);
    snprintf(k->name, sizeof k->name, "%.*s", (int)(eq - text), text);
    for (int j = 0; j < T->nk; j++)
        if (!strcmp(T->k[j].name, k->name)) return trade_bad_usage("--knob %s given twice; list all its values in one option", k->name);
    snprintf(k->buf, sizeof k->buf, "%s", eq + 1);
    for (char *p = k->buf; p;) {
        char *c = strchr(p, ',');
        if (c) *c = '\0';
        if (!*p) return trade_bad_usage("--knob has an empty value in '%s'", text);
        if (k->n == MAX_VALUES) return trade_bad_usage("--knob: at most 32 values in '%s'", text);
        k->v[k->n++] = p;
        p = c ? c + 1 : NULL;
    }
    T->nk++;
    return 0;
}

int trade_parse(trade *T, int argc, char **argv) {
    memset(T, 0, sizeof *T);
    T->reference = "finest";
    T->jobs = -1;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
            usage(stdout);
            return 1;
        }
        if (!strcmp(s, "--quiet")) { T->quiet = 1; continue; }
        if (!strcmp(s, "--trust")) { T->trust = 1; continue; }
        if (!strcmp(s, "--no-wait")) { T->no_wait = 1; continue; }
        if (!strcmp(s, "--collect") || !strcmp(s, "--worker"))
            return trade_bad_usage("%s is a command of its own: hearth trade --collect DIR", s);
        if (s[0] == '-' && s[1] == '-') {
            static const char *const valued[] = {"--metric", "--knob", "--reference", "--out", "--jobs", "--until", "--set",
                                                 "--threads", "--launcher", "--launcher-arg", NULL};
            int known = 0;
            for (int k = 0; valued[k]; k++) known |= !strcmp(s, valued[k]);
            if (!known) return trade_bad_usage("unknown option '%s'", s);
            if (i + 1 >= argc) return trade_bad_usage("%s needs a value", s);
            const char *v = argv[++i];
            if (!strcmp(s, "--metric")) T->metric = v;
            else if (!strcmp(s, "--knob")) {
                if (parse_knob(T, v)) return 2;
            } else if (!strcmp(s, "--reference")) T->reference = v;
            else if (!strcmp(s, "--out")) snprintf(T->out, sizeof T->out, "%s", v);
            else if (!strcmp(s, "--jobs")) {
                if ((T->jobs = (int)app_parse_int("trade", "--jobs", v, 1, 256)) < 0) return 2;
            } else if (!strcmp(s, "--threads")) {
                if ((T->threads = (int)app_parse_int("trade", "--threads", v, 1, 1024)) < 0) return 2;
            } else if (!strcmp(s, "--launcher")) {
                if (!strcmp(v, "local")) T->launcher = TL_LOCAL;
                else if (!strcmp(v, "slurm")) T->launcher = TL_SLURM;
                else if (!strcmp(v, "mpi")) T->launcher = TL_MPI;
                else return trade_bad_usage("--launcher must be local, slurm or mpi, got '%s'", v);
            } else if (!strcmp(s, "--launcher-arg")) {
                if (T->nlauncher_args == MAX_LAUNCHER_ARGS) return trade_bad_usage("at most %s --launcher-arg options", "32");
                T->launcher_args[T->nlauncher_args++] = v;
            } else if (!strcmp(s, "--until")) {
                char *end;
                double u = strtod(v, &end);
                if (*end || !(u > 0)) return trade_bad_usage("--until needs a time > 0 in seconds, got '%s'", v);
                T->until = v;
            } else { /* --set */
                if (!strchr(v, '=') || v[0] == '=') return trade_bad_usage("--set needs name=value, got '%s'", v);
                if (T->nsets == MAX_SETS) return trade_bad_usage("at most %s --set options", "32");
                T->sets[T->nsets++] = v;
            }
            continue;
        }
        if (T->scene) return trade_bad_usage("one scene file at a time (got a second: '%s')", s);
        T->scene = s;
        T->scene_arg = i;
    }
    if (!T->scene) return trade_bad_usage("which scene? %s", "usage: hearth trade SCENE.lua --metric NAME");
    if (T->no_wait && T->launcher != TL_SLURM) return trade_bad_usage("--no-wait is for --launcher slurm%s", "");
    if (T->nlauncher_args && T->launcher == TL_LOCAL)
        return trade_bad_usage("--launcher-arg is for --launcher slurm or mpi (got '%s')", T->launcher_args[0]);
    if (!T->metric) return trade_bad_usage("--metric NAME is required (e.g. %s)", "--metric height");
    if (strcmp(T->reference, "finest") && strncmp(T->reference, "analytic:", 9))
        return trade_bad_usage("--reference must be 'finest' or 'analytic:<lua expression>', got '%s'", T->reference);
    for (int j = 0; j < T->nk; j++)
        for (int s = 0; s < T->nsets; s++)
            if (!strncmp(T->sets[s], T->k[j].name, strlen(T->k[j].name)) && T->sets[s][strlen(T->k[j].name)] == '=')
                return trade_bad_usage("'%s' is both a --knob and a --set", T->k[j].name);
    if (!T->out[0]) {
        const char *base = strrchr(T->scene, '/');
        base = base ? base + 1 : T->scene;
        size_t n = strlen(base);
        if (n > 4 && !strcmp(base + n - 4, ".lua")) n -= 4;
        snprintf(T->out, sizeof T->out, "hearth-out/trade-%.*s", (int)n, base);
    }
    return 0;
}

/* ---- the ladder ------------------------------------------------------------ */

static int is_number(const char *s, double *v) {
    char *end;
    errno = 0;
    *v = strtod(s, &end);
    return end != s && !*end && !errno && isfinite(*v);
}

/* Refinement measure h of a knob value: smaller is finer. ppc refines like
 * 1/sqrt(ppc) (particle spacing in 2D). */
static double refine_h(const trade *T, const trade_run *r) {
    if (T->refine < 0) return NAN;
    const knob *k = &T->k[T->refine];
    double v;
    if (!is_number(k->v[r->vi[T->refine]], &v) || !(v > 0)) return NAN;
    return strcmp(k->name, "ppc") ? v : 1.0 / sqrt(v);
}

int trade_build_ladder(trade *T) {
    long n = 1;
    for (int j = 0; j < T->nk; j++) n *= T->k[j].n;
    if (n > MAX_RUNS) {
        fprintf(stderr, "hearth trade: %ld runs is more than the %d allowed; use fewer knob values\n", n, MAX_RUNS);
        return 2;
    }
    T->nr = (int)n;
    T->r = calloc((size_t)n, sizeof *T->r);
    if (!T->r) return 1;
    /* the refinement knob: the first of these that has more than one value */
    static const char *const pref[] = {"dx", "dt_max", "cfl", "ppc"};
    T->refine = -1;
    for (int p = 0; p < 4 && T->refine < 0; p++)
        for (int j = 0; j < T->nk; j++) {
            double v;
            if (strcmp(T->k[j].name, pref[p]) || T->k[j].n < 2) continue;
            int numeric = 1;
            for (int i = 0; i < T->k[j].n; i++) numeric &= is_number(T->k[j].v[i], &v) && v > 0;
            if (!numeric) {
                fprintf(stderr, "hearth trade: --knob %s needs numbers > 0\n", T->k[j].name);
                return 2;
            }
            T->refine = j;
            break;
        }
    for (int i = 0; i < T->nr; i++) { /* the last knob varies fastest */
        long rem = i;
        for (int j = T->nk - 1; j >= 0; j--) {
            T->r[i].vi[j] = (int)(rem % T->k[j].n);
            rem /= T->k[j].n;
        }
        T->r[i].metric = T->r[i].ref = T->r[i].err = T->r[i].rel = T->r[i].order = NAN;
        T->r[i].steps = -1;
        T->r[i].h = refine_h(T, &T->r[i]);
        T->r[i].mine = 1;
    }
    /* series: runs equal in every knob but the refinement knob */
    int ns = 0;
    for (int i = 0; i < T->nr; i++) {
        T->r[i].series = -1;
        for (int j = 0; j < i && T->r[i].series < 0; j++) {
            int same = 1;
            for (int k = 0; k < T->nk; k++) same &= k == T->refine || T->r[i].vi[k] == T->r[j].vi[k];
            if (same) T->r[i].series = T->r[j].series;
        }
        if (T->r[i].series < 0) T->r[i].series = ns++;
    }
    return 0;
}

/* "dx=0.01 heat=implicit" (all knobs, or all but the refinement knob) */
void trade_run_label(const trade *T, const trade_run *r, int skip_refine, char *buf, size_t n) {
    size_t l = 0;
    buf[0] = '\0';
    for (int j = 0; j < T->nk && l < n; j++) {
        if (skip_refine && j == T->refine) continue;
        l += (size_t)snprintf(buf + l, n - l, "%s%s=%s", l ? " " : "", T->k[j].name, T->k[j].v[r->vi[j]]);
    }
    if (!buf[0]) snprintf(buf, n, "%s", skip_refine ? "all runs" : "(defaults)");
}

/* ---- running ------------------------------------------------------------- */

void trade_run_dir(const trade *T, int i, char *buf, size_t n) { snprintf(buf, n, "%s/runs/%03d", T->out, i); }

static int start_run(trade *T, int i) {
    trade_run *r = &T->r[i];
    char dir[4200], res[4300], log[4300], thr[16];
    trade_run_dir(T, i, dir, sizeof dir);
    hearth_error err;
    if (hearth_mkdir_p(dir, &err)) {
        fprintf(stderr, "hearth trade: %s\n", err.msg);
        return -1;
    }
    snprintf(res, sizeof res, "%s/result.txt", dir);
    snprintf(log, sizeof log, "%s/log.txt", dir);
    unlink(res);
    snprintf(thr, sizeof thr, "%d", T->threads);
    char setbuf[MAX_KNOBS][600];
    const char *av[32 + 2 * (MAX_KNOBS + MAX_SETS)];
    int a = 0;
    av[a++] = "hearth";
    av[a++] = "run";
    av[a++] = T->scene;
    av[a++] = "--quiet";
    av[a++] = "--out";
    av[a++] = dir;
    av[a++] = "--metric";
    av[a++] = T->metric;
    av[a++] = "--metric-out";
    av[a++] = res;
    av[a++] = "--threads";
    av[a++] = thr;
    if (T->until) av[a++] = "--until", av[a++] = T->until;
    if (T->trust) av[a++] = "--trust";
    for (int s = 0; s < T->nsets; s++) av[a++] = "--set", av[a++] = T->sets[s];
    for (int j = 0; j < T->nk; j++) {
        snprintf(setbuf[j], sizeof setbuf[j], "%s=%s", T->k[j].name, T->k[j].v[r->vi[j]]);
        av[a++] = "--set", av[a++] = setbuf[j];
    }
    av[a] = NULL;
    fflush(NULL);
    r->t0 = progress_wall();
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "hearth trade: cannot start a run: %s\n", strerror(errno));
        return -1;
    }
    if (pid == 0) {
        int fd = open(log, O_WRONLY | O_CREAT | O_TRUNC, 0644);
        if (fd >= 0) {
            dup2(fd, 1);
            dup2(fd, 2);
            close(fd);
        }
        setenv("OMP_NUM_THREADS", thr, 1);
        setenv("OMP_WAIT_POLICY", "passive", 1);
        /* a run is one process: under --launcher mpi this child inherits its rank's
         * environment, and must not join that job as a rank of one scene (docs/scaling.md) */
        setenv("HEARTH_NO_RANKS", "1", 1);
        execv("/proc/self/exe", (char *const *)av);
        fprintf(stderr, "hearth trade: cannot run /proc/self/exe: %s\n", strerror(errno));
        _exit(127);
    }
    r->pid = pid;
    r->st = RS_RUNNING;
    return 0;
}

/* The reason a run did not finish, from its log: the guard's diagnosis or the error line. */
static void read_failure(const char *log, char *msg, size_t n) {
    FILE *f = fopen(log, "r");
    snprintf(msg, n, "(no log)");
    if (!f) return;
    char line[2048];
    int next_is_diag = 0;
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        if (next_is_diag) {
            const char *p = line;
            while (*p == ' ') p++;
            snprintf(msg, n, "%.*s", (int)n - 1, p);
            break;
        }
        if (strstr(line, "stability guard stopped the run")) next_is_diag = 1;
        else if (!strncmp(line, "hearth run: ", 12)) {
            snprintf(msg, n, "%.*s", (int)n - 1, line + 12);
            break;
        }
    }
    fclose(f);
}

static volatile sig_atomic_t interrupted;
static void on_signal(int sig) {
    (void)sig;
    interrupted = 1;
}

static void finish_run(trade *T, int i, int wstatus, const struct rusage *ru) {
    trade_run *r = &T->r[i];
    r->wall = progress_wall() - r->t0;
    r->peak_mb = ru->ru_maxrss / 1024.0; /* Linux: kilobytes */
    char dir[4200], path[4300];
    trade_run_dir(T, i, dir, sizeof dir);
    snprintf(path, sizeof path, "%s/result.txt", dir);
    FILE *f = fopen(path, "r");
    if (f) {
        char key[32];
        double v;
        while (fscanf(f, "%31s %lf%*[^\n]", key, &v) == 2) {
            if (!strcmp(key, "metric")) r->metric = v;
            else if (!strcmp(key, "steps")) r->steps = (long)v;
        }
        fclose(f);
    }
    snprintf(path, sizeof path, "%s/log.txt", dir);
    /* a run stops itself on our SIGTERM with 128 + the signal (hearth run's interrupt) */
    const int stopped = WIFSIGNALED(wstatus) || (WIFEXITED(wstatus) && WEXITSTATUS(wstatus) > 128);
    if (stopped && interrupted) {
        r->st = RS_ERROR;
        snprintf(r->msg, sizeof r->msg, "stopped: hearth trade was interrupted");
    } else if (WIFSIGNALED(wstatus)) {
        r->st = RS_CRASH;
        snprintf(r->msg, sizeof r->msg, "killed by signal %d (%s); see %.150s", WTERMSIG(wstatus), strsignal(WTERMSIG(wstatus)), path);
    } else if (WEXITSTATUS(wstatus) == 0 && isfinite(r->metric)) r->st = RS_OK;
    else {
        r->st = WEXITSTATUS(wstatus) == 3 ? RS_GUARD : RS_ERROR;
        read_failure(path, r->msg, sizeof r->msg);
        if (WEXITSTATUS(wstatus) == 0) snprintf(r->msg, sizeof r->msg, "the metric is not a finite number");
    }
    trade_record_write(T, i); /* for --collect, and how a worker reports */
}


int trade_run_all(trade *T) {
    int next = 0, running = 0, done = 0, killed = 0, nmine = 0;
    for (int i = 0; i < T->nr; i++) nmine += T->r[i].mine;
    const double t0 = progress_wall();
    double last_beat = t0;
    struct sigaction sa, old_int, old_term;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    while (done < nmine) {
        while (!interrupted && running < T->jobs && next < T->nr) {
            if (!T->r[next].mine) {
                next++;
                continue;
            }
            if (start_run(T, next)) {
                T->r[next].st = RS_ERROR;
                snprintf(T->r[next].msg, sizeof T->r[next].msg, "could not start");
                trade_record_write(T, next);
                done++;
            } else running++;
            next++;
        }
        if (!running) break;
        int ws;
        struct rusage ru;
        pid_t pid = wait4(-1, &ws, WNOHANG, &ru);
        if (pid < 0 && errno != EINTR) break;
        if (pid <= 0) { /* nothing ended yet: poll, and say what is running now and then */
            if (interrupted && !killed) {
                for (int i = 0; i < T->nr; i++)
                    if (T->r[i].st == RS_RUNNING) kill(T->r[i].pid, SIGTERM);
                killed = 1;
            }
            const struct timespec nap = {0, 100000000};
            nanosleep(&nap, NULL);
            const double now = progress_wall();
            if (!T->quiet && now - last_beat >= 15) {
                last_beat = now;
                fprintf(stderr, "trade: %d/%d done, running:", done, nmine);
                for (int i = 0; i < T->nr; i++)
                    if (T->r[i].st == RS_RUNNING) {
                        char lab[512];
                        trade_run_label(T, &T->r[i], 0, lab, sizeof lab);
                        fprintf(stderr, " [%s for %.0f s]", lab, now - T->r[i].t0);
                    }
                fprintf(stderr, "  (elapsed %.0f s)\n", now - t0);
            }
            continue;
        }
        last_beat = progress_wall();
        for (int i = 0; i < T->nr; i++) {
            if (T->r[i].st != RS_RUNNING || T->r[i].pid != pid) continue;
            finish_run(T, i, ws, &ru);
            running--;
            done++;
            if (!T->quiet) {
                char lab[512];
                trade_run_label(T, &T->r[i], 0, lab, sizeof lab);
                const double el = progress_wall() - t0;
                fprintf(stderr, "trade: [%d/%d] %s: %s, %.2f s", done, nmine, lab, trade_state_name[T->r[i].st], T->r[i].wall);
                if (T->r[i].st == RS_OK) fprintf(stderr, ", %s = %.6g", T->metric, T->r[i].metric);
                else fprintf(stderr, ": %s", T->r[i].msg);
                fprintf(stderr, "  (elapsed %.0f s, ETA %.0f s)\n", el, done ? el * (nmine - done) / done : 0.0);
            }
        }
    }
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    if (interrupted) {
        fprintf(stderr, "hearth trade: interrupted; %d of %d runs done\n", done, nmine);
        return 1;
    }
    return 0;
}

/* ---- analysis ------------------------------------------------------------ */

/* The analytic reference for one run: EXPR with math.* and the run's knobs as globals. */
static int analytic_value(const trade *T, const trade_run *r, double *out, char *msg, size_t n) {
    lua_State *L = luaL_newstate();
    if (!L) return snprintf(msg, n, "out of memory"), -1;
    luaL_requiref(L, LUA_GNAME, luaopen_base, 1);
    luaL_requiref(L, LUA_MATHLIBNAME, luaopen_math, 1);
    lua_pop(L, 2);
    for (int j = 0; j < T->nk; j++) {
        double v;
        const char *s = T->k[j].v[r->vi[j]];
        if (is_number(s, &v)) lua_pushnumber(L, v);
        else lua_pushstring(L, s);
        lua_setglobal(L, T->k[j].name);
    }
    char code[1200];
    snprintf(code, sizeof code, "return (%s)", T->analytic);
    int rc = -1;
    if (luaL_loadbufferx(L, code, strlen(code), "=--reference", "t") != LUA_OK || lua_pcall(L, 0, 1, 0) != LUA_OK)
        snprintf(msg, n, "--reference analytic:%s: %s", T->analytic, lua_tostring(L, -1));
    else if (lua_type(L, -1) != LUA_TNUMBER || !isfinite(lua_tonumber(L, -1)))
        snprintf(msg, n, "--reference analytic:%s: gives %s, not a finite number", T->analytic, luaL_tolstring(L, -1, NULL));
    else *out = lua_tonumber(L, -1), rc = 0;
    lua_close(L);
    return rc;
}

static int analyse(trade *T) {
    int ref_run = -1;
    if (T->analytic[0]) {
        for (int i = 0; i < T->nr; i++) {
            char msg[1400];
            if (analytic_value(T, &T->r[i], &T->r[i].ref, msg, sizeof msg)) {
                fprintf(stderr, "hearth trade: %s\n", msg);
                return 2;
            }
        }
    } else {
        /* each series against its own finest run: a linear blend and the model, or
         * MPM and SPH, converge (or not) to different answers, and one shared
         * reference would call their difference an error */
        int any = 0;
        for (int sr = 0; sr < T->nr; sr++) {
            ref_run = -1;
            for (int i = 0; i < T->nr; i++) {
                const trade_run *r = &T->r[i], *b = ref_run >= 0 ? &T->r[ref_run] : NULL;
                if (r->st != RS_OK || r->series != sr) continue;
                const double hr = isfinite(r->h) ? r->h : INFINITY, hb = b && isfinite(b->h) ? b->h : INFINITY;
                if (!b || hr < hb || (hr == hb && r->steps >= b->steps)) ref_run = i;
            }
            if (ref_run < 0) continue;
            any = 1;
            T->r[ref_run].is_ref = 1;
            for (int i = 0; i < T->nr; i++)
                if (T->r[i].series == sr) T->r[i].ref = T->r[ref_run].metric;
        }
        if (!any) return 0;
    }
    for (int i = 0; i < T->nr; i++) {
        trade_run *r = &T->r[i];
        if (r->st != RS_OK) continue;
        r->err = fabs(r->metric - r->ref);
        r->rel = r->ref != 0 ? r->err / fabs(r->ref) : r->err;
    }
    /* observed order between successive refinements within a series */
    if (T->refine >= 0)
        for (int i = 0; i < T->nr; i++) {
            trade_run *r = &T->r[i];
            int prev = -1; /* the next coarser run of the same series */
            for (int j = 0; j < T->nr; j++) {
                const trade_run *q = &T->r[j];
                if (j == i || q->series != r->series || !(q->h > r->h)) continue;
                if (prev < 0 || q->h < T->r[prev].h) prev = j;
            }
            if (prev < 0 || r->st != RS_OK || T->r[prev].st != RS_OK) continue;
            if (r->err > 0 && T->r[prev].err > 0 && !r->is_ref)
                r->order = log(T->r[prev].err / r->err) / log(T->r[prev].h / r->h);
        }
    /* Pareto front over (wall time, error): no other run is both as fast and as accurate */
    for (int i = 0; i < T->nr; i++) {
        trade_run *r = &T->r[i];
        if (r->st != RS_OK || !(r->rel > 0)) continue;
        r->pareto = 1;
        for (int j = 0; j < T->nr && r->pareto; j++) {
            const trade_run *q = &T->r[j];
            if (j == i || q->st != RS_OK || !(q->rel > 0)) continue;
            if (q->wall <= r->wall && q->rel <= r->rel && (q->wall < r->wall || q->rel < r->rel)) r->pareto = 0;
        }
    }
    return 0;
}

int trade_finish(trade *T, int rc) {
    int arc = analyse(T);
    if (arc) return arc;
    char csv[4200], png[4200];
    snprintf(csv, sizeof csv, "%s/trade.csv", T->out);
    snprintf(png, sizeof png, "%s/trade.png", T->out);
    if (trade_write_csv(T, csv) || trade_write_plot(T, png)) rc = 1;
    trade_print_table(T);
    int failed = 0;
    for (int i = 0; i < T->nr; i++) failed += T->r[i].st != RS_OK;
    printf("\nwrote %s and %s\n", csv, png);
    if (failed) printf("%d of %d runs did not finish (see the status column and runs/NNN/log.txt)\n", failed, T->nr);
    return rc || failed ? 1 : 0;
}

int trade_setup(trade *T, int argc, char **argv) {
    int rc = trade_parse(T, argc, argv);
    if (rc) return rc;
    if (!strncmp(T->reference, "analytic:", 9)) snprintf(T->analytic, sizeof T->analytic, "%s", T->reference + 9);
    if ((rc = trade_build_ladder(T))) return rc;
    if (T->analytic[0]) { /* a bad expression is a usage error, found before any run */
        char msg[1400];
        double v;
        if (analytic_value(T, &T->r[0], &v, msg, sizeof msg)) {
            fprintf(stderr, "hearth trade: %s\n", msg);
            return 2;
        }
    }
    return 0;
}

/* The trade's run record (run_log.c): the steps of all its runs, and how many
 * runs the guard stopped or failed otherwise. */
static void trade_record(const trade *T, run_log *rec, int status) {
    int guard = 0, other = 0;
    rec->have_scene = 1;
    for (int i = 0; i < T->nr; i++) {
        if (T->r[i].steps > 0) rec->steps += T->r[i].steps;
        guard += T->r[i].st == RS_GUARD;
        other += T->r[i].st != RS_OK && T->r[i].st != RS_GUARD;
    }
    snprintf(rec->guard, sizeof rec->guard, guard ? "stopped %d of %d runs" : "ok", guard, T->nr);
    for (int i = 0; i < T->nr && !rec->nplugins; i++) { /* the plugins the runs loaded, from a run's own record */
        char dir[4200], path[4300];
        trade_run_dir(T, i, dir, sizeof dir);
        snprintf(path, sizeof path, "%s/run.log", dir);
        run_log_plugins_from(rec, path);
    }
    if (other) snprintf(rec->message, sizeof rec->message, "%d of %d runs failed otherwise (see trade.csv)", other, T->nr);
    run_log_write(rec, status);
}

/* The user's OMP_NUM_THREADS, a whole number in [1, 1024], is each run's thread count when --threads is not given:
 * every run's environment had it overwritten by cores / jobs ("OMP_NUM_THREADS=1 hearth trade" ran 2 threads a run;
 * #18, helpers userview4, userfix8). Another value (an OpenMP list, a typo) is said and left to cores / jobs. */
static int env_threads(int quiet) {
    const char *v = getenv("OMP_NUM_THREADS");
    if (!v || !*v) return 0;
    char *end;
    errno = 0;
    long n = strtol(v, &end, 10);
    if (*end || errno || n < 1 || n > 1024) {
        if (!quiet)
            fprintf(stderr, "trade: OMP_NUM_THREADS=%.40s is not a whole number in [1, 1024]; each run gets cores / jobs "
                            "threads (--threads N sets them)\n", v);
        return 0;
    }
    return (int)n;
}

int cmd_trade(int argc, char **argv) {
    if (argc >= 2 && !strcmp(argv[1], "--collect")) {
        if (argc < 3 || argv[2][0] == '-') return trade_bad_usage("--collect needs the results folder: hearth trade --collect DIR%s", "");
        int quiet = 0;
        for (int i = 3; i < argc; i++) {
            if (strcmp(argv[i], "--quiet")) return trade_bad_usage("--collect DIR takes only --quiet, got '%s'", argv[i]);
            quiet = 1;
        }
        return trade_collect(argv[2], quiet);
    }
    if (argc >= 2 && !strcmp(argv[1], "--worker")) return trade_worker(argc, argv);
    trade T;
    int rc = trade_setup(&T, argc, argv);
    if (!rc && access(T.scene, R_OK) != 0) { /* here, not in trade_setup: --collect needs no scene */
        fprintf(stderr, "hearth trade: cannot read scene '%s': %s\n", T.scene, strerror(errno));
        rc = 2;
    }
    if (rc) {
        free(T.r);
        return rc == 1 ? 0 : rc;
    }
    long cores = sysconf(_SC_NPROCESSORS_ONLN);
    if (cores < 1) cores = 1;
    if (!T.threads && T.launcher != TL_SLURM) T.threads = env_threads(T.quiet);
    const int jobs_given = T.jobs > 0;
    if (T.jobs < 0) T.jobs = (int)cores;
    if (T.jobs > T.nr) T.jobs = T.nr;
    if (!T.threads) T.threads = T.launcher == TL_SLURM ? 1 : (int)(cores / T.jobs) > 0 ? (int)(cores / T.jobs) : 1;
    if (T.launcher == TL_SLURM && !jobs_given) T.jobs = 0; /* no cap on the array's running tasks */
    hearth_error err;
    if (hearth_mkdir_p(T.out, &err)) {
        fprintf(stderr, "hearth trade: %s\n", err.msg);
        free(T.r);
        return 1;
    }
    if (trade_args_write(&T, argc, argv)) {
        free(T.r);
        return 1;
    }
    run_log rec;
    run_log_start(&rec, "trade", argc, argv, T.scene, T.out, T.sets, T.nsets);
    rec.runs = T.nr, rec.jobs = T.jobs, rec.threads = T.threads;
    rec.status_1 = "a run did not finish, or the results could not be written";
    if (T.launcher != TL_LOCAL) {
        rc = trade_launch(&T);
    } else {
        if (!T.quiet)
            fprintf(stderr, "trade: %s, %d runs, %d at a time with %d thread%s each; metric %s, reference %s\n", T.scene, T.nr,
                    T.jobs, T.threads, T.threads > 1 ? "s" : "", T.metric, T.reference);
        rc = trade_run_all(&T);
        rc = trade_finish(&T, rc);
    }
    trade_record(&T, &rec, rc);
    free(T.r);
    return rc;
}

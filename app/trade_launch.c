/* trade_launch.c: `hearth trade --launcher slurm|mpi`, the workers they start,
 * and `hearth trade --collect DIR`. Every run leaves a record,
 * runs/NNN/run.txt (status, wall time, steps, peak memory, metric, note),
 * written by the process that waited for the run, whichever launcher started
 * it; the ladder itself is stored once as DIR/trade.args (the command line
 * with absolute paths). Gathering is therefore the same for all launchers:
 * rebuild the ladder from trade.args, read the records, analyse. That is why
 * the table, CSV and plot of a Slurm or mpirun ladder equal the local one.
 *
 * Slurm: one job array (`sbatch --array=0-(N-1)`), a small generated batch
 * script DIR/slurm-array.sh whose task I runs `hearth trade --worker slurm DIR`,
 * and the worker runs rung $SLURM_ARRAY_TASK_ID. We wait by polling squeue
 * (sbatch --wait polls every ~10 s; we poll fast at first, then back off) and
 * by watching the records appear; accounting (sacct) is not needed, so a
 * cluster without slurmdbd works too. A task that left no record is named
 * with its output file DIR/slurm-JOB_TASK.out.
 *
 * mpirun: `mpirun -n JOBS hearth trade --worker mpi DIR`, no MPI library
 * linked: a rank only needs to know it is a rank (OMPI_COMM_WORLD_RANK,
 * PMI_RANK or PMIX_RANK) and the shared out folder. The ranks share the runs
 * out by claiming them (O_CREAT|O_EXCL on runs/NNN/claim), each starting at
 * its own rank, so a rank that drew a fine (slow) run does not hold up runs a
 * fixed rank-to-run split would have queued behind it. The rejected
 * alternative, rung = rank + k * size, needs the world size and balances
 * badly: ladders refine geometrically, so run costs differ by 8x per step. */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE
#endif
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "commands.h"
#include "hearth/hearth.h"
#include "progress.h"
#include "trade.h"

/* ---- run records ----------------------------------------------------------- */

int trade_record_write(const trade *T, int i) {
    const trade_run *r = &T->r[i];
    char dir[4200], path[4300];
    trade_run_dir(T, i, dir, sizeof dir);
    snprintf(path, sizeof path, "%s/run.txt", dir);
    hearth_error err;
    hearth_atomic_file *af = hearth_atomic_file_open(path, &err);
    if (!af) {
        fprintf(stderr, "hearth trade: %s\n", err.msg);
        return -1;
    }
    /* %.17g: the metric reads back to the same double, so gathered tables equal local ones */
    hearth_atomic_file_printf(af, "status %s\nwall %.17g\nsteps %ld\npeak_mb %.17g\nmetric %.17g\nnote %s\n",
                              trade_state_name[r->st], r->wall, r->steps, r->peak_mb, r->metric, r->msg);
    if (hearth_atomic_file_commit(af, &err)) {
        fprintf(stderr, "hearth trade: %s\n", err.msg);
        return -1;
    }
    return 0;
}

int trade_record_read(trade *T, int i) {
    trade_run *r = &T->r[i];
    char dir[4200], path[4300], line[1024];
    trade_run_dir(T, i, dir, sizeof dir);
    snprintf(path, sizeof path, "%s/run.txt", dir);
    FILE *f = fopen(path, "r");
    if (!f) return -1;
    int have_status = 0;
    const char *bad = NULL; /* a record comes from a folder someone else may have made: each number in its range */
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        char *v = strchr(line, ' '), *end;
        if (!v) continue;
        *v++ = '\0';
        if (!strcmp(line, "status")) {
            for (int s = RS_WAIT; s <= RS_CRASH; s++)
                if (!strcmp(v, trade_state_name[s])) r->st = (run_state)s, have_status = 1;
        } else if (!strcmp(line, "wall")) {
            r->wall = strtod(v, &end);
            if (end == v || !(r->wall >= 0 && r->wall < 1e9)) bad = "wall (0 to 1e9 s)";
        } else if (!strcmp(line, "steps")) {
            r->steps = strtol(v, &end, 10);
            if (end == v || r->steps < -1) bad = "steps (-1 for none, or 0 and up)";
        } else if (!strcmp(line, "peak_mb")) {
            r->peak_mb = strtod(v, &end);
            if (end == v || !(r->peak_mb >= 0 && r->peak_mb < 1e9)) bad = "peak_mb (0 to 1e9 MB)";
        } else if (!strcmp(line, "metric")) {
            r->metric = strtod(v, &end);
            if (end == v || isinf(r->metric)) bad = "metric (a finite number, or nan for none)";
        } else if (!strcmp(line, "note")) snprintf(r->msg, sizeof r->msg, "%s", v);
    }
    fclose(f);
    if (!have_status || bad) {
        r->st = RS_ERROR;
        r->wall = 0, r->steps = -1, r->peak_mb = 0, r->metric = NAN;
        snprintf(r->msg, sizeof r->msg, "unreadable record %.200s%s%s", path, bad ? ": bad " : "", bad ? bad : "");
    }
    return 0;
}

/* ---- the stored ladder (DIR/trade.args) -------------------------------------- */

static const char args_header[] = "# hearth trade ladder: its arguments, each ended by a NUL byte\n";

int trade_args_write(const trade *T, int argc, char **argv) {
    char scene[PATH_MAX], out[PATH_MAX], threads[16], path[4200];
    hearth_error err;
    if (!realpath(T->scene, scene) || !realpath(T->out, out)) {
        fprintf(stderr, "hearth trade: cannot resolve the path of '%s': %s\n", realpath(T->scene, scene) ? T->out : T->scene,
                strerror(errno));
        return -1;
    }
    snprintf(path, sizeof path, "%s/trade.args", out);
    hearth_atomic_file *af = hearth_atomic_file_open(path, &err);
    if (!af) {
        fprintf(stderr, "hearth trade: %s\n", err.msg);
        return -1;
    }
    hearth_atomic_file_write(af, args_header, sizeof args_header - 1);
    snprintf(threads, sizeof threads, "%d", T->threads);
    /* as given, but for the scene's and --out's absolute paths, the resolved --threads,
     * and none of --jobs or --no-wait (they are the submitter's business) */
    static const char *const valued[] = {"--metric", "--knob", "--reference", "--until", "--set", "--launcher", "--launcher-arg", NULL};
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        int pair = 0;
        for (int k = 0; valued[k]; k++) pair |= !strcmp(a, valued[k]);
        if (!strcmp(a, "--out") || !strcmp(a, "--threads") || !strcmp(a, "--jobs")) {
            i++;
            continue;
        }
        if (!strcmp(a, "--no-wait")) continue;
        if (i == T->scene_arg) a = scene;
        hearth_atomic_file_write(af, a, strlen(a) + 1);
        if (pair && i + 1 < argc) i++, hearth_atomic_file_write(af, argv[i], strlen(argv[i]) + 1);
    }
    const char *tail[] = {"--out", out, "--threads", threads};
    for (int k = 0; k < 4; k++) hearth_atomic_file_write(af, tail[k], strlen(tail[k]) + 1);
    if (hearth_atomic_file_commit(af, &err)) {
        fprintf(stderr, "hearth trade: %s\n", err.msg);
        return -1;
    }
    return 0;
}

/* The ladder stored in DIR: T's strings point into *store (free it after T). */
static int args_load(const char *dir, const char *who, trade *T, char **store, char ***argvp) {
    char path[4200];
    snprintf(path, sizeof path, "%s/trade.args", dir);
    *store = NULL, *argvp = NULL;
    memset(T, 0, sizeof *T);
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "hearth trade %s: cannot read %s: %s (is %s the --out folder of a hearth trade?)\n", who, path,
                strerror(errno), dir);
        return 2;
    }
    size_t cap = 4096, n = 0;
    char *buf = malloc(cap);
    for (size_t got; buf && (got = fread(buf + n, 1, cap - n, f)) > 0;) {
        n += got;
        if (n == cap) {
            char *b = realloc(buf, cap *= 2);
            if (!b) free(buf);
            buf = b;
        }
    }
    fclose(f);
    if (!buf) return 1;
    const size_t h = sizeof args_header - 1;
    if (n < h || memcmp(buf, args_header, h) || buf[n - 1] != '\0') {
        fprintf(stderr, "hearth trade %s: %s is not a ladder written by hearth trade\n", who, path);
        free(buf);
        return 2;
    }
    int argc = 1;
    for (size_t k = h; k < n; k++) argc += buf[k] == '\0';
    char **argv = calloc((size_t)argc + 1, sizeof *argv);
    if (!argv) {
        free(buf);
        return 1;
    }
    argv[0] = "trade";
    for (size_t k = h, a = 1; k < n; k += strlen(buf + k) + 1) argv[a++] = buf + k;
    *store = buf, *argvp = argv;
    int rc = trade_setup(T, argc, argv);
    if (rc == 1) rc = 2; /* --help cannot be stored */
    /* the folder where it is now: results copied off the cluster gather too */
    if (!rc) snprintf(T->out, sizeof T->out, "%s", dir);
    return rc;
}

/* ---- gathering ------------------------------------------------------------------ */

/* The Slurm job of DIR (DIR/slurm-job.txt), or 0. */
static long slurm_job_of(const char *dir) {
    char path[4200];
    long job = 0;
    snprintf(path, sizeof path, "%s/slurm-job.txt", dir);
    FILE *f = fopen(path, "r");
    if (f) {
        if (fscanf(f, "%ld", &job) != 1) job = 0;
        fclose(f);
    }
    return job;
}

/* Runs without a record: say what is known. For Slurm tasks, the task's output file and its last line. */
static void explain_missing(trade *T, int i, long job, const char *slurm_state) {
    trade_run *r = &T->r[i];
    r->st = RS_ERROR;
    if (!job) {
        snprintf(r->msg, sizeof r->msg, "no record (runs/%03d/run.txt): the run did not finish", i);
        return;
    }
    char path[4300], line[512], last[512] = "";
    snprintf(path, sizeof path, "%s/slurm-%ld_%d.out", T->out, job, i);
    FILE *f = fopen(path, "r");
    if (f) {
        while (fgets(line, sizeof line, f)) {
            line[strcspn(line, "\n")] = '\0';
            if (line[0]) snprintf(last, sizeof last, "%s", line);
        }
        fclose(f);
    }
    snprintf(r->msg, sizeof r->msg, "Slurm task %d of job %ld left no record%s%s%s%s%.200s; see %.200s", i, job,
             slurm_state ? " (state " : "", slurm_state ? slurm_state : "", slurm_state ? ")" : "", last[0] ? ": " : "", last, path);
}

static int gather(trade *T, long job, char (*states)[16]) {
    for (int i = 0; i < T->nr; i++)
        if (trade_record_read(T, i)) explain_missing(T, i, job, states && states[i][0] ? states[i] : NULL);
    return trade_finish(T, 0);
}

int trade_collect(const char *dir, int quiet) {
    trade T;
    char *store, **argv;
    int rc = args_load(dir, "--collect", &T, &store, &argv);
    if (!rc) {
        T.quiet = quiet;
        rc = gather(&T, slurm_job_of(T.out), NULL);
    }
    free(T.r);
    free(argv);
    free(store);
    return rc;
}

/* ---- workers ---------------------------------------------------------------------- */

static const char *env_rank(const char **name) {
    static const char *const vars[] = {"OMPI_COMM_WORLD_RANK", "PMI_RANK", "PMIX_RANK", NULL};
    for (int k = 0; vars[k]; k++) {
        const char *v = getenv(vars[k]);
        if (v && *v) return *name = vars[k], v;
    }
    return NULL;
}

static int worker_run_one(trade *T, int i, const char *who) {
    for (int j = 0; j < T->nr; j++) T->r[j].mine = j == i;
    trade_run_all(T);
    const trade_run *r = &T->r[i];
    char lab[512];
    trade_run_label(T, r, 0, lab, sizeof lab);
    fprintf(stderr, "trade %s: run %03d %s: %s, %.2f s", who, i, lab, trade_state_name[r->st], r->wall);
    if (r->st == RS_OK) fprintf(stderr, ", %s = %.6g\n", T->metric, r->metric);
    else fprintf(stderr, ": %s\n", r->msg);
    return r->st == RS_OK ? 0 : 1;
}

int trade_worker(int argc, char **argv) {
    if (argc != 4 || (strcmp(argv[2], "slurm") && strcmp(argv[2], "mpi")))
        return trade_bad_usage("--worker slurm|mpi DIR is how hearth trade --launcher starts its tasks%s", "");
    trade T;
    char *store, **targv;
    int rc = args_load(argv[3], "--worker", &T, &store, &targv);
    if (rc) goto done;
    T.jobs = 1, T.quiet = 1;
    char who[64];
    if (!strcmp(argv[2], "slurm")) {
        const char *id = getenv("SLURM_ARRAY_TASK_ID");
        char *end;
        long task = id ? strtol(id, &end, 10) : -1;
        if (!id || *end || task < 0 || task >= T.nr) {
            fprintf(stderr, "hearth trade --worker slurm: SLURM_ARRAY_TASK_ID is %s%s%s; the ladder in %s has runs 0..%d\n",
                    id ? "'" : "not set", id ? id : "", id ? "'" : "", argv[3], T.nr - 1);
            rc = 2;
            goto done;
        }
        snprintf(who, sizeof who, "slurm task %ld", task);
        rc = worker_run_one(&T, (int)task, who);
    } else {
        const char *var = NULL, *id = env_rank(&var);
        char *end;
        long rank = id ? strtol(id, &end, 10) : -1;
        if (!id || *end || rank < 0) {
            fprintf(stderr, "hearth trade --worker mpi: no MPI rank in the environment (OMPI_COMM_WORLD_RANK, PMI_RANK or "
                            "PMIX_RANK); hearth trade --launcher mpi starts the workers with mpirun\n");
            rc = 2;
            goto done;
        }
        snprintf(who, sizeof who, "rank %ld", rank);
        /* claim runs, starting at our own rank; a failed run is in its record, not our exit status
         * (mpirun would stop the other ranks at a non-zero exit) */
        for (int k = 0; k < T.nr; k++) {
            const int i = (int)((rank + k) % T.nr);
            char dir[4200], claim[4300];
            trade_run_dir(&T, i, dir, sizeof dir);
            snprintf(claim, sizeof claim, "%s/claim", dir);
            int fd = open(claim, O_WRONLY | O_CREAT | O_EXCL, 0644);
            if (fd < 0) {
                if (errno == EEXIST) continue;
                fprintf(stderr, "hearth trade %s: cannot claim run %d (%s): %s\n", who, i, claim, strerror(errno));
                rc = 1;
                break;
            }
            dprintf(fd, "%ld\n", rank);
            close(fd);
            worker_run_one(&T, i, who);
        }
    }
done:
    free(T.r);
    free(targv);
    free(store);
    return rc;
}

/* ---- launching ---------------------------------------------------------------------- */

/* The full path of a program on PATH, or NULL. */
static const char *find_program(const char *name, char *buf, size_t n) {
    const char *path = getenv("PATH");
    if (!path || !*path) path = "/usr/bin:/bin";
    for (const char *p = path; *p;) {
        const char *c = strchr(p, ':');
        size_t len = c ? (size_t)(c - p) : strlen(p);
        snprintf(buf, n, "%.*s/%s", (int)len, len ? p : ".", name);
        if (access(buf, X_OK) == 0) return buf;
        if (!c) break;
        p = c + 1;
    }
    return NULL;
}

/* Fresh run folders: no record, claim or result left from an earlier ladder in DIR. */
static int clear_runs(const trade *T) {
    static const char *const stale[] = {"run.txt", "claim", "result.txt"};
    for (int i = 0; i < T->nr; i++) {
        char dir[4200], path[4300];
        hearth_error err;
        trade_run_dir(T, i, dir, sizeof dir);
        if (hearth_mkdir_p(dir, &err)) {
            fprintf(stderr, "hearth trade: %s\n", err.msg);
            return -1;
        }
        for (int k = 0; k < 3; k++) {
            snprintf(path, sizeof path, "%s/%s", dir, stale[k]);
            unlink(path);
        }
    }
    return 0;
}

/* 'text' for sh, inner quotes as '\'' */
static void sh_quote(FILE *f, const char *s) {
    fputc('\'', f);
    for (; *s; s++)
        if (*s == '\'') fputs("'\\''", f);
        else fputc(*s, f);
    fputc('\'', f);
}

static volatile sig_atomic_t stop_waiting;
static void on_interrupt(int sig) {
    (void)sig;
    stop_waiting = 1;
}

/* squeue's view of the array: per task its state letters (PD, R, CD, F, ...);
 * returns the number of tasks still active, or -1 when squeue failed. */
static int slurm_active(long job, int nr, char (*states)[16]) {
    char cmd[160], line[256];
    snprintf(cmd, sizeof cmd, "squeue -h -t all -j %ld -o '%%K %%t' 2>&1", job);
    FILE *p = popen(cmd, "r");
    if (!p) return -1;
    int active = 0, lines = 0, invalid = 0;
    while (fgets(line, sizeof line, p)) {
        char task[128], st[16];
        if (strstr(line, "Invalid job id")) invalid = 1; /* purged after MinJobAge: long finished */
        if (sscanf(line, "%127s %15s", task, st) != 2) continue;
        lines++;
        const int done = !strcmp(st, "CD") || !strcmp(st, "F") || !strcmp(st, "CA") || !strcmp(st, "TO") ||
                         !strcmp(st, "NF") || !strcmp(st, "OOM") || !strcmp(st, "BF") || !strcmp(st, "DL") ||
                         !strcmp(st, "PR") || !strcmp(st, "RV");
        char *end;
        long t = strtol(task, &end, 10);
        if (!*end && t >= 0 && t < nr) snprintf(states[t], sizeof states[t], "%s", st);
        if (!done) active++; /* pending tasks show as one line "[2-3]" */
    }
    int status = pclose(p);
    if (invalid) return 0;
    if (status != 0 && !lines) return -1;
    return active;
}

static int launch_slurm(trade *T, const char *exe) {
    char sbatch[4200], script[4300], out_pat[4300], array[64], cpus[32], name[160];
    if (!find_program("sbatch", sbatch, sizeof sbatch)) {
        fprintf(stderr, "hearth trade: --launcher slurm needs Slurm's sbatch, and it is not on PATH; run hearth trade on a "
                        "machine that can submit jobs (a login node), or use --launcher local\n");
        return 2;
    }
    snprintf(script, sizeof script, "%s/slurm-array.sh", T->out);
    FILE *f = fopen(script, "w");
    if (!f) {
        fprintf(stderr, "hearth trade: cannot write %s: %s\n", script, strerror(errno));
        return 1;
    }
    fprintf(f, "#!/bin/sh\n# Written by hearth trade: task I of this job array runs run I of the ladder in\n"
               "# trade.args (runs/NNN/). Gather the results with: hearth trade --collect ");
    sh_quote(f, T->out);
    fputs("\nexec ", f);
    sh_quote(f, exe);
    fputs(" trade --worker slurm ", f);
    sh_quote(f, T->out);
    fputc('\n', f);
    if (fclose(f)) {
        fprintf(stderr, "hearth trade: cannot write %s: %s\n", script, strerror(errno));
        return 1;
    }
    const char *base = strrchr(T->scene, '/');
    snprintf(name, sizeof name, "--job-name=trade-%.100s", base ? base + 1 : T->scene);
    if (T->jobs > 0) snprintf(array, sizeof array, "--array=0-%d%%%d", T->nr - 1, T->jobs);
    else snprintf(array, sizeof array, "--array=0-%d", T->nr - 1);
    snprintf(cpus, sizeof cpus, "--cpus-per-task=%d", T->threads);
    snprintf(out_pat, sizeof out_pat, "--output=%s/slurm-%%A_%%a.out", T->out);
    const char *av[16 + MAX_LAUNCHER_ARGS];
    int a = 0;
    av[a++] = "sbatch", av[a++] = "--parsable", av[a++] = name, av[a++] = array, av[a++] = cpus, av[a++] = out_pat;
    for (int k = 0; k < T->nlauncher_args; k++) av[a++] = T->launcher_args[k];
    av[a++] = script, av[a] = NULL;
    int fds[2];
    if (pipe(fds)) return 1;
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        dup2(fds[1], 1);
        close(fds[0]), close(fds[1]);
        execv(sbatch, (char *const *)av);
        _exit(127);
    }
    close(fds[1]);
    char reply[256] = "";
    size_t n = 0;
    for (ssize_t got; pid > 0 && n < sizeof reply - 1 && (got = read(fds[0], reply + n, sizeof reply - 1 - n)) > 0;) n += (size_t)got;
    reply[n] = '\0';
    close(fds[0]);
    int ws = 0;
    if (pid < 0 || waitpid(pid, &ws, 0) < 0 || !WIFEXITED(ws) || WEXITSTATUS(ws)) {
        fprintf(stderr, "hearth trade: sbatch did not take the job array (exit status %d; its message is above); script %s\n",
                WIFEXITED(ws) ? WEXITSTATUS(ws) : -1, script);
        return 1;
    }
    long job = strtol(reply, NULL, 10); /* --parsable: "JOBID" or "JOBID;CLUSTER" */
    if (job <= 0) {
        fprintf(stderr, "hearth trade: sbatch answered '%s', not a job id\n", reply);
        return 1;
    }
    char path[4300];
    snprintf(path, sizeof path, "%s/slurm-job.txt", T->out);
    hearth_error err;
    hearth_atomic_file *af = hearth_atomic_file_open(path, &err);
    if (af) hearth_atomic_file_printf(af, "%ld\n", job);
    if (!af || hearth_atomic_file_commit(af, &err)) fprintf(stderr, "hearth trade: %s\n", err.msg);
    fprintf(stderr, "trade: %s, %d runs as Slurm job array %ld (%d thread%s per task); metric %s\n", T->scene, T->nr, job,
            T->threads, T->threads > 1 ? "s" : "", T->metric);
    if (T->no_wait) {
        printf("submitted Slurm job %ld, %d tasks; when they are done: hearth trade --collect %s\n", job, T->nr, T->out);
        return 0;
    }
    /* wait: squeue, fast at first and then gently; the records tell which runs are done */
    char(*states)[16] = calloc((size_t)T->nr, sizeof *states);
    char *seen = calloc((size_t)T->nr, 1);
    if (!states || !seen) {
        free(states), free(seen);
        return 1;
    }
    struct sigaction sa, old_int, old_term;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_interrupt;
    sigaction(SIGINT, &sa, &old_int);
    sigaction(SIGTERM, &sa, &old_term);
    const double t0 = progress_wall();
    int nseen = 0, failures = 0, rc = 0;
    for (;;) {
        for (int i = 0; i < T->nr; i++) {
            if (seen[i] || trade_record_read(T, i)) continue;
            seen[i] = 1, nseen++;
            if (!T->quiet) {
                char lab[512];
                trade_run_label(T, &T->r[i], 0, lab, sizeof lab);
                fprintf(stderr, "trade: [%d/%d] %s: %s, %.2f s", nseen, T->nr, lab, trade_state_name[T->r[i].st], T->r[i].wall);
                if (T->r[i].st == RS_OK) fprintf(stderr, ", %s = %.6g", T->metric, T->r[i].metric);
                else fprintf(stderr, ": %s", T->r[i].msg);
                fprintf(stderr, "  (elapsed %.0f s)\n", progress_wall() - t0);
            }
        }
        if (nseen == T->nr) break;
        const int active = slurm_active(job, T->nr, states);
        if (active == 0) {
            /* the records are written before a task ends: read once more, then name the missing */
            for (int i = 0; i < T->nr; i++)
                if (!seen[i] && !trade_record_read(T, i)) seen[i] = 1;
            break;
        }
        failures = active < 0 ? failures + 1 : 0;
        if (failures == 10 || stop_waiting) {
            fprintf(stderr, "hearth trade: %s; Slurm job %ld keeps running (scancel %ld stops it). Gather its results "
                            "later with: hearth trade --collect %s\n",
                    stop_waiting ? "stopped waiting" : "squeue failed 10 times in a row", job, job, T->out);
            rc = 1;
            break;
        }
        const double el = progress_wall() - t0;
        const long ms = el < 20 ? 250 : el < 300 ? 2000 : 10000;
        const struct timespec nap = {ms / 1000, (ms % 1000) * 1000000L};
        nanosleep(&nap, NULL);
    }
    sigaction(SIGINT, &old_int, NULL);
    sigaction(SIGTERM, &old_term, NULL);
    if (!rc) rc = gather(T, job, states);
    free(states), free(seen);
    return rc;
}

static int launch_mpi(trade *T, const char *exe) {
    char mpirun[4200], ranks[16];
    if (!find_program("mpirun", mpirun, sizeof mpirun)) {
        fprintf(stderr, "hearth trade: --launcher mpi needs mpirun (Debian: openmpi-bin, or MPICH's), and it is not on "
                        "PATH; or use --launcher local\n");
        return 2;
    }
    snprintf(ranks, sizeof ranks, "%d", T->jobs);
    const char *av[16 + MAX_LAUNCHER_ARGS];
    int a = 0;
    av[a++] = "mpirun", av[a++] = "-n", av[a++] = ranks;
    for (int k = 0; k < T->nlauncher_args; k++) av[a++] = T->launcher_args[k];
    av[a++] = exe, av[a++] = "trade", av[a++] = "--worker", av[a++] = "mpi", av[a++] = T->out, av[a] = NULL;
    if (!T->quiet)
        fprintf(stderr, "trade: %s, %d runs over mpirun -n %d, %d thread%s per run; metric %s\n", T->scene, T->nr, T->jobs,
                T->threads, T->threads > 1 ? "s" : "", T->metric);
    fflush(NULL);
    pid_t pid = fork();
    if (pid == 0) {
        /* Open MPI binds each rank to a core by default, which would put a run's
         * OpenMP threads on one core; MPICH ignores this variable */
        setenv("OMPI_MCA_hwloc_base_binding_policy", "none", 0);
        execv(mpirun, (char *const *)av);
        fprintf(stderr, "hearth trade: cannot run %s: %s\n", mpirun, strerror(errno));
        _exit(127);
    }
    int ws = 0;
    if (pid < 0 || waitpid(pid, &ws, 0) < 0) {
        fprintf(stderr, "hearth trade: cannot start mpirun: %s\n", strerror(errno));
        return 1;
    }
    if (!WIFEXITED(ws) || WEXITSTATUS(ws))
        fprintf(stderr, "hearth trade: mpirun ended with %s %d (its message is above); gathering the runs that finished\n",
                WIFEXITED(ws) ? "exit status" : "signal", WIFEXITED(ws) ? WEXITSTATUS(ws) : WTERMSIG(ws));
    return gather(T, 0, NULL);
}

int trade_launch(trade *T) {
    char exe[PATH_MAX];
    ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
    if (n <= 0) {
        fprintf(stderr, "hearth trade: cannot find the hearth executable (/proc/self/exe): %s\n", strerror(errno));
        return 1;
    }
    exe[n] = '\0';
    char out[PATH_MAX]; /* the tasks may start in another folder */
    if (!realpath(T->out, out)) {
        fprintf(stderr, "hearth trade: cannot resolve the path of '%s': %s\n", T->out, strerror(errno));
        return 1;
    }
    snprintf(T->out, sizeof T->out, "%s", out);
    if (clear_runs(T)) return 1;
    return T->launcher == TL_SLURM ? launch_slurm(T, exe) : launch_mpi(T, exe);
}

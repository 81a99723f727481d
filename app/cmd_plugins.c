/* cmd_plugins.c: `hearth plugins` (list with parameter tables) and
 * `hearth plugin check FILE.so` (the conformance battery, isolated in a child). */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700 /* kill, clock_gettime */
#endif
#include <errno.h>
#include <poll.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include "commands.h"
#include "crash.h"
#include "hearth/hearth.h"

/* One plugin's entry; 0 listed, 1 refused (said why). Runs in a child (print_plugin). */
static int print_one(const char *name, const char *path) {
    hearth_error err;
    const hearth_plugin *pl = hearth_plugin_load(path, &err);
    if (!pl) {
        printf("%s  (%s)\n  cannot load: %s\n\n", name, path, err.msg);
        return 1;
    }
    const hearth_material *m = hearth_plugin_material(pl);
    printf("%s  (%s)\n  %s\n", m->name, path, m->summary ? m->summary : "");
    if (m->state_size) printf("  state: %d doubles per particle\n", m->state_size);
    printf("  %-14s %-10s %12s %12s %12s  %s\n", "parameter", "unit", "default", "min", "max", "meaning");
    for (int i = 0; i < m->nparams; i++) {
        const hearth_param *p = &m->params[i];
        printf("  %-14s %-10s %12g %12g %12g  %s\n", p->name, p->unit, p->def, p->min, p->max, p->help);
    }
    printf("\n");
    return 0;
}

/* Loading runs plugin code (constructors, init and wave_speed at the schema's corners), so each plugin is loaded
 * in a child: one that crashes there (named on stderr by crash.c, as in a run) is listed as not loadable and the
 * listing goes on, where it ended at that plugin with exit 4 and listed none after it (#18, helper userview5). */
static void print_plugin(void *ud, const char *name, const char *path) {
    int *count = ud;
    fflush(stdout); /* the child inherits no unwritten output */
    pid_t pid = fork();
    if (pid == 0) {
        int rc = print_one(name, path);
        fflush(stdout);
        _exit(rc);
    }
    int st = 0;
    if (pid < 0) { /* no child: load it here, as before */
        if (print_one(name, path) == 0) (*count)++;
        return;
    }
    while (waitpid(pid, &st, 0) < 0 && errno == EINTR) {}
    if (WIFEXITED(st) && WEXITSTATUS(st) == 0) (*count)++;
    else if (!(WIFEXITED(st) && WEXITSTATUS(st) == 1))
        printf("%s  (%s)\n  cannot load: it crashed or exited while loading (%s %d; above on stderr); "
               "hearth plugin check %s says more\n\n",
               name, path, WIFSIGNALED(st) ? "signal" : "exit status",
               WIFSIGNALED(st) ? WTERMSIG(st) : WEXITSTATUS(st), path);
}

int cmd_plugins(int argc, char **argv) {
    if (argc > 1) {
        if (!strcmp(argv[1], "--help")) {
            printf("usage: hearth plugins\nLists every material plugin on the search path with its parameter table.\n");
            return 0;
        }
        fprintf(stderr, "hearth plugins: takes no arguments (see --help)\n");
        return 2;
    }
    int count = 0;
    hearth_plugin_each(print_plugin, &count);
    if (count == 0) {
        fprintf(stderr, "hearth plugins: no plugins found; set HEARTH_PLUGIN_PATH to a folder holding hearth_<name>.so files\n");
        return 1;
    }
    return 0;
}

/* ---- plugin check: the battery in a child process -------------------------
 *
 * A plugin under test may crash, abort, hang or call exit(); none of that may
 * take the command down unexplained or make it report success. The child
 * loads the plugin and runs the battery, sending one line per event over a
 * pipe (R: a check's result, L: the plugin did not load, D: done); its crash
 * handlers (crash.c) add a C, X or H record naming the callback in flight.
 * The parent prints the results as they come and judges how the child ended. */

#define CHECK_DEFAULT_TIMEOUT 20.0

static void put_all(int fd, const char *s, size_t n) {
    while (n > 0) {
        ssize_t w = write(fd, s, n);
        if (w < 0 && errno == EINTR) continue;
        if (w <= 0) return;
        s += w;
        n -= (size_t)w;
    }
}

/* One line per record: fields may not hold tabs or newlines. */
static void child_send(int fd, char kind, const char *a, const char *b, const char *c) {
    char line[2048];
    int n = snprintf(line, sizeof line, "%c\t%s\t%s\t%s", kind, a ? a : "", b ? b : "", c ? c : "");
    if (n < 0) return;
    size_t len = (size_t)n < sizeof line - 1 ? (size_t)n : sizeof line - 2;
    for (size_t i = 0; i < len; i++) /* the callers strip tabs; a newline would split the record */
        if (line[i] == '\n') line[i] = ' ';
    line[len] = '\n';
    put_all(fd, line, len + 1);
}

static void child_result(void *ud, const char *check, int passed, const char *detail) {
    char d[1800];
    snprintf(d, sizeof d, "%s", detail ? detail : "");
    for (char *q = d; *q; q++)
        if (*q == '\t' || *q == '\n') *q = ' ';
    child_send(*(int *)ud, 'R', check, passed == 2 ? "2" : passed ? "1" : "0", d);
}

static void check_child(int fd, const char *path) {
    crash_install(fd);
    hearth_error err;
    int failed = hearth_plugin_check(path, child_result, &fd, &err);
    if (failed < 0) {
        for (char *q = err.msg; *q; q++)
            if (*q == '\t' || *q == '\n') *q = ' ';
        child_send(fd, 'L', err.msg, "", "");
    } else {
        char n[32];
        snprintf(n, sizeof n, "%d", failed);
        child_send(fd, 'D', n, "", "");
    }
    _exit(0);
}

typedef struct check_parent {
    const char *shown;
    int done, failed, loaded_err;
    char rec_kind;            /* 'C', 'X' or 'H' from the child's handlers, 0 if none */
    char rec[5][512];         /* signal, material, file, callback, context */
} check_parent;

/* Split a record line at tabs into at most n fields (in place). */
static int split_tabs(char *line, char **f, int n) {
    int k = 0;
    f[k++] = line;
    for (char *q = line; *q && k < n; q++)
        if (*q == '\t') {
            *q = '\0';
            f[k++] = q + 1;
        }
    return k;
}

static void parent_line(check_parent *cp, char *line) {
    char *f[6] = {0};
    int n = split_tabs(line, f, 6);
    if (n < 1 || strlen(f[0]) != 1) return;
    switch (f[0][0]) {
    case 'R':
        if (n >= 4)
            printf("%-20s %s  %s\n", f[1], strcmp(f[2], "1") == 0 ? "PASS" : strcmp(f[2], "2") == 0 ? "WARN" : "FAIL", f[3]);
        fflush(stdout);
        break;
    case 'D':
        cp->done = 1;
        cp->failed = n >= 2 ? atoi(f[1]) : 1;
        break;
    case 'L':
        cp->loaded_err = 1;
        fprintf(stderr, "hearth plugin check: %s\n", n >= 2 ? f[1] : "the plugin did not load");
        break;
    case 'C': case 'X': case 'H':
        cp->rec_kind = f[0][0];
        for (int i = 0; i < 5; i++) snprintf(cp->rec[i], sizeof cp->rec[i], "%s", i + 1 < n ? f[i + 1] : "");
        break;
    default: break;
    }
}

/* who: "plugin 'x' (/p/hearth_x.so)"; where: "in its stress callback during check 'rest'"
 * or "outside any plugin callback (...)" when no callback was in flight. */
static void who_where(const check_parent *cp, char *who, size_t wcap, char *where, size_t cap) {
    if (cp->rec_kind && cp->rec[3][0]) {
        snprintf(who, wcap, "plugin '%s' (%s)", cp->rec[1], cp->rec[2][0] ? cp->rec[2] : cp->shown);
        snprintf(where, cap, "in its %s callback%s%s", cp->rec[3], cp->rec[4][0] ? " during " : "", cp->rec[4]);
    } else if (cp->rec_kind == 'H') { /* the child answered the timeout probe between callbacks */
        snprintf(who, wcap, "plugin %s", cp->shown);
        snprintf(where, cap, "while the battery ran between callbacks (no plugin code was running)");
    } else {
        snprintf(who, wcap, "plugin %s", cp->shown);
        snprintf(where, cap, "outside any plugin callback (while loading: dlopen, a constructor or the entry function)");
    }
}

static double now_s(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int run_isolated(const char *path, const char *shown, double timeout) {
    int fds[2];
    if (pipe(fds) != 0) {
        fprintf(stderr, "hearth plugin check: cannot create a pipe: %s\n", strerror(errno));
        return 1;
    }
    fflush(stdout);
    fflush(stderr);
    pid_t pid = fork();
    if (pid < 0) {
        fprintf(stderr, "hearth plugin check: cannot start the check process: %s\n", strerror(errno));
        close(fds[0]);
        close(fds[1]);
        return 1;
    }
    if (pid == 0) {
        close(fds[0]);
        check_child(fds[1], path);
    }
    close(fds[1]);
    check_parent cp = {.shown = shown};
    char buf[8192];
    size_t used = 0;
    const double t0 = now_s();
    int probed = 0, killed = 0, eof = 0;
    double probe_t = 0;
    while (!eof) {
        double left = probed ? probe_t + 2.0 - now_s() : t0 + timeout - now_s();
        if (left <= 0) {
            if (!probed) { /* ask the child which callback it is stuck in, then give it 2 s */
                kill(pid, SIGUSR1);
                probed = 1;
                probe_t = now_s();
                continue;
            }
            kill(pid, SIGKILL);
            killed = 1;
            break;
        }
        struct pollfd pf = {.fd = fds[0], .events = POLLIN};
        int pr = poll(&pf, 1, (int)(left * 1000) + 1);
        if (pr < 0 && errno == EINTR) continue;
        if (pr <= 0) continue;
        ssize_t r = read(fds[0], buf + used, sizeof buf - 1 - used);
        if (r < 0 && errno == EINTR) continue;
        if (r <= 0) {
            eof = 1;
            r = 0;
        }
        used += (size_t)r;
        buf[used] = '\0';
        char *start = buf, *nl;
        while ((nl = strchr(start, '\n'))) {
            *nl = '\0';
            parent_line(&cp, start);
            start = nl + 1;
        }
        used = strlen(start);
        memmove(buf, start, used + 1);
        if (used == sizeof buf - 1) used = 0; /* a line longer than the buffer: drop it */
    }
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
    if (cp.loaded_err) return 1;
    char who[1200], where[1200], msg[3000];
    who_where(&cp, who, sizeof who, where, sizeof where);
    const char *label = NULL;
    if (probed) {
        label = "timeout";
        snprintf(msg, sizeof msg, "%s did not finish within %g s %s%s", who, timeout, where,
                 killed ? " (and did not answer; killed)" : "; stopped");
    } else if (cp.rec_kind == 'C' || (WIFSIGNALED(status) && !cp.done)) {
        label = "crash";
        snprintf(msg, sizeof msg, "%s crashed with %s %s", who,
                 cp.rec_kind == 'C' ? cp.rec[0] : crash_signal_name(WTERMSIG(status)), where);
    } else if (cp.rec_kind == 'X') {
        label = "exit";
        snprintf(msg, sizeof msg, "%s called exit() %s, before the battery finished", who, where);
    } else if (!cp.done) {
        label = "exit";
        snprintf(msg, sizeof msg, "%s ended the check process (exit status %d) %s, before the battery finished", who,
                 WIFEXITED(status) ? WEXITSTATUS(status) : -1, where);
    }
    if (label) {
        printf("%-20s FAIL  %s\n", label, msg);
        printf("%s: FAILED\n", shown);
        return 1;
    }
    printf("%s: %s\n", shown, cp.failed ? "FAILED" : "all checks passed");
    return cp.failed ? 1 : 0;
}

int cmd_plugin_check(int argc, char **argv) {
    double timeout = CHECK_DEFAULT_TIMEOUT;
    const char *file = NULL;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help")) {
            printf("usage: hearth plugin check [--timeout S] FILE.so\n"
                   "Loads one plugin by path and runs the conformance battery: zero stress at rest,\n"
                   "symmetric stress, frame indifference, finite output at parameter extremes, and a\n"
                   "wave speed consistent with the small-strain stiffness. The battery runs in a child\n"
                   "process: a crash, abort, exit() or a hang longer than S seconds (default %g) is a\n"
                   "failure naming the callback. Exits 0 when all pass.\n",
                   CHECK_DEFAULT_TIMEOUT);
            return 0;
        }
        if (!strcmp(argv[i], "--timeout")) {
            char *end = NULL;
            const char *t = i + 1 < argc ? argv[++i] : "";
            timeout = strtod(t, &end);
            if (end == t || *end || !(timeout > 0 && timeout <= 86400)) {
                fprintf(stderr, "hearth plugin check: --timeout needs seconds in (0, 86400], got '%s'\n", t);
                return 2;
            }
        } else if (!file) {
            file = argv[i];
        } else {
            fprintf(stderr, "hearth plugin check: one plugin file at a time; extra argument '%s' (see --help)\n", argv[i]);
            return 2;
        }
    }
    if (!file) {
        fprintf(stderr, "usage: hearth plugin check [--timeout S] FILE.so\n");
        return 2;
    }
    const char *path = file;
    char buf[4200];
    if (!strchr(path, '/')) { /* a bare file name means this folder, not the search path */
        snprintf(buf, sizeof buf, "./%s", path);
        path = buf;
    }
    return run_isolated(path, file, timeout);
}

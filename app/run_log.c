/* run_log.c: the record of a `hearth run`, `hearth demo` or `hearth trade`,
 * beside its outputs: <out>/run.log (lines to read) and <out>/run.json (the
 * same, for scripts), like LAMMPS's log.lammps. It holds the command line,
 * --set values, version and git revision, plugins, threads, timings, steps,
 * peak memory (getrusage), the guard's verdict and the files the run wrote:
 * every regular file under the output folder modified since the start (so
 * frames, dumps, CSV, movies and checkpoints written by any route are listed,
 * and a frame left from an earlier run into the same folder is not). Both are written when the run starts (status
 * "running": a run killed by SIGKILL or a power cut still leaves one that
 * says so) and rewritten when it ends; each write is atomic, so a reader never
 * sees a torn record. A later run into the same folder replaces them, as it
 * replaces the frames. The JSON is written by hand: a dozen keys do not need
 * a library. */
#ifndef _DEFAULT_SOURCE
#define _DEFAULT_SOURCE /* clock_gettime, gmtime_r, CLOCK_REALTIME_COARSE, struct stat's st_mtim */
#endif
#include "run_log.h"

#include <dirent.h>
#include <lauxlib.h>
#include <lua.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <time.h>

#include "hearth/hearth.h"
#include "hearth/material.h"
#include "hearth_lua.h"
#include "hearth_revision.h"

const char *run_log_revision(void) { return HEARTH_REVISION[0] ? HEARTH_REVISION : "unknown"; }

static double now_s(void) {
    struct timespec ts;
    clock_gettime(CLOCK_MONOTONIC, &ts);
    return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void iso_utc(time_t t, char *out, size_t n) {
    struct tm tm;
    gmtime_r(&t, &tm);
    strftime(out, n, "%Y-%m-%dT%H:%M:%SZ", &tm);
}

void run_log_start(run_log *r, const char *cmd, int argc, char **argv, const char *scene, const char *out,
                   const char *const *sets, int nsets) {
    memset(r, 0, sizeof *r);
    r->cmd = cmd, r->argc = argc, r->argv = argv, r->scene = scene, r->out = out, r->sets = sets, r->nsets = nsets;
    r->start = time(NULL);
    /* file times come from the kernel's coarse clock, which lags the fine one
     * by up to a tick: a file written just after the start must not look older */
#ifdef CLOCK_REALTIME_COARSE
    clock_gettime(CLOCK_REALTIME_COARSE, &r->start_fs);
#else
    r->start_fs.tv_sec = r->start - 1;
#endif
    r->t0 = now_s();
    snprintf(r->guard, sizeof r->guard, "ok");
    run_log_write(r, -1);
}

void run_log_stats(run_log *r, const hearth_stats *st) {
    static const char *gs[] = {"ok", "rolled_back", "stopped"};
    r->have_scene = 1;
    r->steps = st->step, r->sim_t = st->t, r->particles = st->particles, r->rollbacks = st->rollbacks;
    snprintf(r->guard, sizeof r->guard, "%s", gs[st->guard]);
    snprintf(r->diagnosis, sizeof r->diagnosis, "%s", st->diagnosis);
}

/* The scene's counters after the run, from h._last_scene:stats(). */
void run_log_scene(run_log *r, lua_State *L) {
    int top = lua_gettop(L);
    lua_getglobal(L, "require");
    lua_pushliteral(L, "hearth");
    if (hl_pcall(L, 1, 1) == LUA_OK && lua_istable(L, -1)) {
        lua_getfield(L, -1, "_last_scene");
        if (!lua_isnil(L, -1) && lua_getfield(L, -1, "stats") == LUA_TFUNCTION) {
            lua_pushvalue(L, -2);
            if (hl_pcall(L, 1, 1) == LUA_OK && lua_istable(L, -1)) {
                r->have_scene = 1;
                lua_getfield(L, -1, "step"), r->steps = (long)lua_tointeger(L, -1), lua_pop(L, 1);
                lua_getfield(L, -1, "t"), r->sim_t = lua_tonumber(L, -1), lua_pop(L, 1);
                lua_getfield(L, -1, "particles"), r->particles = (long)lua_tointeger(L, -1), lua_pop(L, 1);
                lua_getfield(L, -1, "rollbacks"), r->rollbacks = (int)lua_tointeger(L, -1), lua_pop(L, 1);
                lua_getfield(L, -1, "guard");
                if (lua_isstring(L, -1)) snprintf(r->guard, sizeof r->guard, "%s", lua_tostring(L, -1));
                lua_pop(L, 1);
                lua_getfield(L, -1, "diagnosis");
                if (lua_isstring(L, -1)) snprintf(r->diagnosis, sizeof r->diagnosis, "%s", lua_tostring(L, -1));
                lua_pop(L, 1);
            }
        }
    }
    lua_settop(L, top);
}

void run_log_plugins_from(run_log *r, const char *path) {
    FILE *f = fopen(path, "r");
    if (!f) return;
    char line[1400];
    while (r->nplugins < 16 && fgets(line, sizeof line, f)) {
        int k = r->nplugins;
        if (sscanf(line, "plugin: %63s abi %d %1023[^\n]", r->plugins[k].name, &r->plugins[k].abi, r->plugins[k].file) == 3)
            r->nplugins++;
    }
    fclose(f);
}

/* the plugins: this process's, or those a trade's run recorded */
static int plugin_count(const run_log *r) { return r->nplugins ? r->nplugins : hearth_plugin_loaded_count(); }
static void plugin_at(const run_log *r, int i, const char **name, int *abi, const char **file) {
    if (r->nplugins) {
        *name = r->plugins[i].name, *abi = r->plugins[i].abi, *file = r->plugins[i].file;
        return;
    }
    const hearth_plugin *pl = hearth_plugin_loaded(i);
    const hearth_material *m = hearth_plugin_material(pl);
    *name = m->name, *abi = m->abi_version, *file = hearth_plugin_file(pl);
}
static int threads_of(const run_log *r) { return r->threads ? r->threads : hearth_get_threads(); }

void run_log_message(run_log *r, const char *msg) { snprintf(r->message, sizeof r->message, "%s", msg ? msg : ""); }

static const char *status_word(const run_log *r, int status) {
    switch (status) {
    case -1: return "running";
    case 0: return "done";
    case 1: return r->status_1 ? r->status_1 : "scene error";
    case 2: return "usage or bad --set value";
    case 3: return "the stability guard stopped the run";
    case 4: return "a plugin crashed or called exit()";
    case 130: return "interrupted (SIGINT)";
    case 143: return "terminated (SIGTERM)";
    default: return "stopped";
    }
}

static void json_str(hearth_atomic_file *f, const char *s) {
    hearth_atomic_file_write(f, "\"", 1);
    for (; s && *s; s++) {
        unsigned char c = (unsigned char)*s;
        if (c == '"' || c == '\\') hearth_atomic_file_printf(f, "\\%c", c);
        else if (c < 0x20) hearth_atomic_file_printf(f, "\\u%04x", c);
        else hearth_atomic_file_write(f, s, 1);
    }
    hearth_atomic_file_write(f, "\"", 1);
}

/* The command line as a shell would take it back: words with anything but
 * [A-Za-z0-9_./=:,+-] single-quoted. */
static void shell_word(hearth_atomic_file *f, const char *w) {
    if (*w && strspn(w, "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_./=:,+-%") == strlen(w)) {
        hearth_atomic_file_printf(f, "%s", w);
        return;
    }
    hearth_atomic_file_write(f, "'", 1);
    for (; *w; w++) {
        if (*w == '\'') hearth_atomic_file_printf(f, "'\\''");
        else hearth_atomic_file_write(f, w, 1);
    }
    hearth_atomic_file_write(f, "'", 1);
}

/* ---- the files a run wrote ---------------------------------------------- */

typedef struct out_file {
    char *path; /* relative to the output folder */
    long long bytes;
} out_file;

typedef struct file_list {
    out_file *v;
    int n, cap;
} file_list;

static int newer(const struct stat *st, const struct timespec *t) {
    return st->st_mtim.tv_sec > t->tv_sec || (st->st_mtim.tv_sec == t->tv_sec && st->st_mtim.tv_nsec >= t->tv_nsec);
}

/* Regular files under root/rel modified since t, depth first; the record's own
 * files and atomic writes' temporaries (".tmp.") are left out. */
static void walk(const char *root, const char *rel, const struct timespec *t, file_list *L, int depth) {
    char dir[4400];
    snprintf(dir, sizeof dir, "%s%s%s", root, rel[0] ? "/" : "", rel);
    DIR *d = opendir(dir);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d)) && L->n < 1000000) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        char sub[4400], full[8800];
        snprintf(sub, sizeof sub, "%s%s%s", rel, rel[0] ? "/" : "", e->d_name);
        snprintf(full, sizeof full, "%s/%s", root, sub);
        struct stat st;
        if (lstat(full, &st)) continue;
        if (S_ISDIR(st.st_mode)) {
            if (depth < 16) walk(root, sub, t, L, depth + 1);
            continue;
        }
        if (!S_ISREG(st.st_mode) || !newer(&st, t) || strstr(e->d_name, ".tmp.")) continue;
        if (!rel[0] && (!strcmp(e->d_name, "run.json") || !strcmp(e->d_name, "run.log"))) continue;
        if (L->n == L->cap) {
            int cap = L->cap ? 2 * L->cap : 64;
            out_file *v = realloc(L->v, sizeof *v * (size_t)cap);
            if (!v) break;
            L->v = v, L->cap = cap;
        }
        char *copy = strdup(sub);
        if (!copy) break;
        L->v[L->n++] = (out_file){copy, (long long)st.st_size};
    }
    closedir(d);
}

static int by_path(const void *a, const void *b) { return strcmp(((const out_file *)a)->path, ((const out_file *)b)->path); }

static void list_free(file_list *L) {
    for (int i = 0; i < L->n; i++) free(L->v[i].path);
    free(L->v);
}

/* peak resident memory in MB: of this process, or the largest of its waited-for children */
static double peak_mb(int who) {
    struct rusage ru;
    if (getrusage(who, &ru)) return 0;
    return (double)ru.ru_maxrss / 1024.0; /* Linux: kilobytes */
}

static void write_text(const run_log *r, int status, const char *path, double wall, const char *start, const char *end,
                       const file_list *files) {
    hearth_error err;
    hearth_atomic_file *f = hearth_atomic_file_open(path, &err);
    if (!f) return;
    hearth_atomic_file_printf(f, "hearth %s (revision %s) %s record\ncommand: hearth", HEARTH_VERSION, run_log_revision(),
                              r->cmd); /* argv[0] is the subcommand */
    for (int i = 0; i < r->argc; i++) hearth_atomic_file_write(f, " ", 1), shell_word(f, r->argv[i]);
    hearth_atomic_file_printf(f, "\nscene: %s\noutputs: %s\n", r->scene ? r->scene : "(built in)", r->out);
    for (int i = 0; i < r->nsets; i++) hearth_atomic_file_printf(f, "set: %s\n", r->sets[i]);
    hearth_atomic_file_printf(f, "threads: %d%s\n", threads_of(r), r->runs ? " per run" : "");
    if (r->runs) hearth_atomic_file_printf(f, "runs: %d, %d at a time\n", r->runs, r->jobs);
    if (hearth_ranks_size() > 1) {
        long slabs, replicated, passes;
        hearth_ranks_steps(&slabs, &replicated, &passes);
        (void)passes;
        hearth_atomic_file_printf(f, "MPI ranks: %d; %ld steps with each rank holding its slab, %ld replicated%s\n",
                                  hearth_ranks_size(), slabs, replicated,
                                  replicated ? " (every rank holds the whole scene: heat, water, mixing, CO2, periodic axes or "
                                               "the rollback guard; docs/scaling.md)"
                                             : "");
    }
    for (int i = 0; i < plugin_count(r); i++) {
        const char *name, *file;
        int abi;
        plugin_at(r, i, &name, &abi, &file);
        hearth_atomic_file_printf(f, "plugin: %s abi %d %s\n", name, abi, file);
    }
    hearth_atomic_file_printf(f, "start: %s\n", start);
    if (status >= 0) {
        hearth_atomic_file_printf(f, "end: %s\nwall: %.3f s\n", end, wall);
        if (r->runs) hearth_atomic_file_printf(f, "steps: %ld (all runs)\n", r->steps);
        else if (r->have_scene)
            hearth_atomic_file_printf(f, "steps: %ld (%.1f steps/s)\nsim time: %.9g s\nparticles: %ld\n", r->steps,
                                      wall > 0 ? (double)r->steps / wall : 0.0, r->sim_t, r->particles);
        hearth_atomic_file_printf(f, "peak memory: %.1f MB", peak_mb(RUSAGE_SELF));
        if (r->runs) hearth_atomic_file_printf(f, " (the largest run: %.1f MB)", peak_mb(RUSAGE_CHILDREN));
        hearth_atomic_file_printf(f, "\nguard: %s", r->guard);
        if (!r->runs) hearth_atomic_file_printf(f, ", %d rollback%s", r->rollbacks, r->rollbacks == 1 ? "" : "s");
        if (r->diagnosis[0]) hearth_atomic_file_printf(f, ": %s", r->diagnosis);
        hearth_atomic_file_write(f, "\n", 1);
    }
    hearth_atomic_file_printf(f, "status: %d (%s)\n", status < 0 ? 0 : status, status_word(r, status));
    if (r->message[0]) { /* a traceback's lines indented under it */
        hearth_atomic_file_printf(f, "message: ");
        for (const char *m = r->message; *m; m++) {
            hearth_atomic_file_write(f, m, 1);
            if (*m == '\n') hearth_atomic_file_write(f, "  ", 2);
        }
        hearth_atomic_file_write(f, "\n", 1);
    }
    if (files) {
        hearth_atomic_file_printf(f, "files written: %d\n", files->n);
        for (int i = 0; i < files->n; i++) hearth_atomic_file_printf(f, "  %s (%lld bytes)\n", files->v[i].path, files->v[i].bytes);
    }
    hearth_atomic_file_commit(f, &err);
}

static void write_json(const run_log *r, int status, const char *path, double wall, const char *start, const char *end,
                       const file_list *files) {
    hearth_error err;
    hearth_atomic_file *f = hearth_atomic_file_open(path, &err);
    if (!f) return;
    hearth_atomic_file_printf(f, "{\n  \"command\": ");
    json_str(f, r->cmd);
    hearth_atomic_file_printf(f, ",\n  \"hearth_version\": \"%s\",\n  \"git_revision\": ", HEARTH_VERSION);
    json_str(f, run_log_revision());
    hearth_atomic_file_printf(f, ",\n  \"argv\": [\"hearth\"");
    for (int i = 0; i < r->argc; i++) {
        hearth_atomic_file_write(f, ", ", 2);
        json_str(f, r->argv[i]);
    }
    hearth_atomic_file_printf(f, "],\n  \"scene\": ");
    if (r->scene) json_str(f, r->scene);
    else hearth_atomic_file_printf(f, "null");
    hearth_atomic_file_printf(f, ",\n  \"outputs\": ");
    json_str(f, r->out);
    hearth_atomic_file_printf(f, ",\n  \"sets\": {");
    for (int i = 0; i < r->nsets; i++) {
        const char *eq = strchr(r->sets[i], '=');
        char key[256];
        snprintf(key, sizeof key, "%.*s", eq ? (int)(eq - r->sets[i]) : 0, r->sets[i]);
        hearth_atomic_file_printf(f, "%s", i ? ", " : "");
        json_str(f, key);
        hearth_atomic_file_write(f, ": ", 2);
        json_str(f, eq ? eq + 1 : "");
    }
    hearth_atomic_file_printf(f, "},\n  \"threads\": %d,\n", threads_of(r));
    if (r->runs) hearth_atomic_file_printf(f, "  \"runs\": %d,\n  \"jobs\": %d,\n", r->runs, r->jobs);
    hearth_atomic_file_printf(f, "  \"plugins\": [");
    for (int i = 0; i < plugin_count(r); i++) {
        const char *name, *file;
        int abi;
        plugin_at(r, i, &name, &abi, &file);
        hearth_atomic_file_printf(f, "%s{\"name\": ", i ? ", " : "");
        json_str(f, name);
        hearth_atomic_file_printf(f, ", \"abi\": %d, \"path\": ", abi);
        json_str(f, file);
        hearth_atomic_file_write(f, "}", 1);
    }
    hearth_atomic_file_printf(f, "],\n  \"start\": \"%s\",\n", start);
    if (status >= 0) {
        hearth_atomic_file_printf(f, "  \"end\": \"%s\",\n  \"wall_s\": %.6f,\n", end, wall);
        if (r->runs) hearth_atomic_file_printf(f, "  \"steps\": %ld,\n", r->steps); /* of all runs */
        else if (r->have_scene)
            hearth_atomic_file_printf(f, "  \"steps\": %ld,\n  \"steps_per_s\": %.6g,\n  \"sim_time_s\": %.17g,\n  \"particles\": %ld,\n",
                                      r->steps, wall > 0 ? (double)r->steps / wall : 0.0, r->sim_t, r->particles);
        hearth_atomic_file_printf(f, "  \"peak_memory_mb\": %.3f,\n", peak_mb(RUSAGE_SELF));
        if (r->runs) hearth_atomic_file_printf(f, "  \"peak_memory_largest_run_mb\": %.3f,\n", peak_mb(RUSAGE_CHILDREN));
        hearth_atomic_file_printf(f, "  \"guard\": {\"verdict\": ");
        json_str(f, r->guard);
        if (!r->runs) hearth_atomic_file_printf(f, ", \"rollbacks\": %d", r->rollbacks);
        hearth_atomic_file_printf(f, ", \"diagnosis\": ");
        json_str(f, r->diagnosis);
        hearth_atomic_file_printf(f, "},\n");
    }
    if (status < 0) hearth_atomic_file_printf(f, "  \"status\": null,\n  \"status_text\": ");
    else hearth_atomic_file_printf(f, "  \"status\": %d,\n  \"status_text\": ", status);
    json_str(f, status_word(r, status));
    hearth_atomic_file_printf(f, ",\n  \"message\": ");
    json_str(f, r->message);
    hearth_atomic_file_printf(f, ",\n  \"files\": [");
    for (int i = 0; files && i < files->n; i++) {
        hearth_atomic_file_printf(f, "%s\n    {\"path\": ", i ? "," : "");
        json_str(f, files->v[i].path);
        hearth_atomic_file_printf(f, ", \"bytes\": %lld}", files->v[i].bytes);
    }
    hearth_atomic_file_printf(f, "%s]\n}\n", files && files->n ? "\n  " : "");
    hearth_atomic_file_commit(f, &err);
}

void run_log_write(const run_log *r, int status) {
    char start[32], end[32], path[4200];
    iso_utc(r->start, start, sizeof start);
    iso_utc(time(NULL), end, sizeof end);
    const double wall = now_s() - r->t0;
    file_list files = {0};
    if (status >= 0) { /* the list once the run is over */
        walk(r->out, "", &r->start_fs, &files, 0);
        if (files.n > 1) qsort(files.v, (size_t)files.n, sizeof *files.v, by_path);
    }
    snprintf(path, sizeof path, "%s/run.log", r->out);
    write_text(r, status, path, wall, start, end, status >= 0 ? &files : NULL);
    snprintf(path, sizeof path, "%s/run.json", r->out);
    write_json(r, status, path, wall, start, end, status >= 0 ? &files : NULL);
    list_free(&files);
}

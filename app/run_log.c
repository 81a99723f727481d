/* run_log.c: the record of a `hearth run`, beside its outputs:
 * <out>/run.log (lines to read) and <out>/run.json (the same, for scripts),
 * like LAMMPS's log.lammps. Both are written when the run starts (status
 * "running": a run killed by SIGKILL or a power cut still leaves one that
 * says so) and rewritten when it ends; each write is atomic, so a reader never
 * sees a torn record. A later run into the same folder replaces them, as it
 * replaces the frames. The JSON is written by hand: a dozen keys do not need
 * a library. */
#define _POSIX_C_SOURCE 200809L /* clock_gettime, gmtime_r */
#include "run_log.h"

#include <lauxlib.h>
#include <lua.h>
#include <stdio.h>
#include <string.h>
#include <time.h>

#include "hearth/hearth.h"
#include "hearth/material.h"
#include "hearth_lua.h"

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

void run_log_start(run_log *r, const run_args *a) {
    memset(r, 0, sizeof *r);
    r->a = a;
    r->start = time(NULL);
    r->t0 = now_s();
    run_log_write(r, -1);
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
            }
        }
    }
    lua_settop(L, top);
}

void run_log_message(run_log *r, const char *msg) { snprintf(r->message, sizeof r->message, "%s", msg ? msg : ""); }

static const char *status_word(int status) {
    switch (status) {
    case -1: return "running";
    case 0: return "done";
    case 1: return "scene error";
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

static void write_text(const run_log *r, int status, const char *path, double wall, const char *start, const char *end) {
    hearth_error err;
    hearth_atomic_file *f = hearth_atomic_file_open(path, &err);
    if (!f) return;
    const run_args *a = r->a;
    hearth_atomic_file_printf(f, "hearth %s run record\ncommand: hearth", HEARTH_VERSION); /* argv[0] is the subcommand */
    for (int i = 0; i < a->argc; i++) hearth_atomic_file_write(f, " ", 1), shell_word(f, a->argv[i]);
    hearth_atomic_file_printf(f, "\nscene: %s\noutputs: %s\n", a->scene ? a->scene : "", a->out);
    for (int i = 0; i < a->nsets; i++) hearth_atomic_file_printf(f, "set: %s\n", a->sets[i]);
    hearth_atomic_file_printf(f, "threads: %d\n", hearth_get_threads());
    for (int i = 0; i < hearth_plugin_loaded_count(); i++) {
        const hearth_plugin *pl = hearth_plugin_loaded(i);
        const hearth_material *m = hearth_plugin_material(pl);
        hearth_atomic_file_printf(f, "plugin: %s abi %d %s\n", m->name, m->abi_version, hearth_plugin_file(pl));
    }
    hearth_atomic_file_printf(f, "start: %s\n", start);
    if (status >= 0) {
        hearth_atomic_file_printf(f, "end: %s\nwall: %.3f s\n", end, wall);
        if (r->have_scene)
            hearth_atomic_file_printf(f, "steps: %ld (%.1f steps/s)\nsim time: %.9g s\nparticles: %ld\n", r->steps,
                                      wall > 0 ? (double)r->steps / wall : 0.0, r->sim_t, r->particles);
    }
    hearth_atomic_file_printf(f, "status: %d (%s)\n", status < 0 ? 0 : status, status_word(status));
    if (r->message[0]) { /* a traceback's lines indented under it */
        hearth_atomic_file_printf(f, "message: ");
        for (const char *m = r->message; *m; m++) {
            hearth_atomic_file_write(f, m, 1);
            if (*m == '\n') hearth_atomic_file_write(f, "  ", 2);
        }
        hearth_atomic_file_write(f, "\n", 1);
    }
    hearth_atomic_file_commit(f, &err);
}

static void write_json(const run_log *r, int status, const char *path, double wall, const char *start, const char *end) {
    hearth_error err;
    hearth_atomic_file *f = hearth_atomic_file_open(path, &err);
    if (!f) return;
    const run_args *a = r->a;
    hearth_atomic_file_printf(f, "{\n  \"hearth_version\": \"%s\",\n  \"argv\": [\"hearth\"", HEARTH_VERSION);
    for (int i = 0; i < a->argc; i++) {
        hearth_atomic_file_write(f, ", ", 2);
        json_str(f, a->argv[i]);
    }
    hearth_atomic_file_printf(f, "],\n  \"scene\": ");
    json_str(f, a->scene);
    hearth_atomic_file_printf(f, ",\n  \"outputs\": ");
    json_str(f, a->out);
    hearth_atomic_file_printf(f, ",\n  \"sets\": {");
    for (int i = 0; i < a->nsets; i++) {
        const char *eq = strchr(a->sets[i], '=');
        char key[256];
        snprintf(key, sizeof key, "%.*s", eq ? (int)(eq - a->sets[i]) : 0, a->sets[i]);
        hearth_atomic_file_printf(f, "%s", i ? ", " : "");
        json_str(f, key);
        hearth_atomic_file_write(f, ": ", 2);
        json_str(f, eq ? eq + 1 : "");
    }
    hearth_atomic_file_printf(f, "},\n  \"threads\": %d,\n  \"plugins\": [", hearth_get_threads());
    for (int i = 0; i < hearth_plugin_loaded_count(); i++) {
        const hearth_plugin *pl = hearth_plugin_loaded(i);
        const hearth_material *m = hearth_plugin_material(pl);
        hearth_atomic_file_printf(f, "%s{\"name\": ", i ? ", " : "");
        json_str(f, m->name);
        hearth_atomic_file_printf(f, ", \"abi\": %d, \"path\": ", m->abi_version);
        json_str(f, hearth_plugin_file(pl));
        hearth_atomic_file_write(f, "}", 1);
    }
    hearth_atomic_file_printf(f, "],\n  \"start\": \"%s\",\n", start);
    if (status >= 0) {
        hearth_atomic_file_printf(f, "  \"end\": \"%s\",\n  \"wall_s\": %.6f,\n", end, wall);
        if (r->have_scene)
            hearth_atomic_file_printf(f, "  \"steps\": %ld,\n  \"steps_per_s\": %.6g,\n  \"sim_time_s\": %.17g,\n  \"particles\": %ld,\n",
                                      r->steps, wall > 0 ? (double)r->steps / wall : 0.0, r->sim_t, r->particles);
    }
    if (status < 0) hearth_atomic_file_printf(f, "  \"status\": null,\n  \"status_text\": ");
    else hearth_atomic_file_printf(f, "  \"status\": %d,\n  \"status_text\": ", status);
    json_str(f, status_word(status));
    hearth_atomic_file_printf(f, ",\n  \"message\": ");
    json_str(f, r->message);
    hearth_atomic_file_printf(f, "\n}\n");
    hearth_atomic_file_commit(f, &err);
}

void run_log_write(const run_log *r, int status) {
    char start[32], end[32], path[4200];
    iso_utc(r->start, start, sizeof start);
    iso_utc(time(NULL), end, sizeof end);
    const double wall = now_s() - r->t0;
    snprintf(path, sizeof path, "%s/run.log", r->a->out);
    write_text(r, status, path, wall, start, end);
    snprintf(path, sizeof path, "%s/run.json", r->a->out);
    write_json(r, status, path, wall, start, end);
}

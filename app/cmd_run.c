/* cmd_run.c: `hearth run SCENE.lua` (headless, progress bar, outputs) and
 * `hearth repl [SCENE.lua]` (a plain Lua prompt; lines from a pipe run too). */
#include <errno.h>
#include <math.h>
#include <signal.h>
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "commands.h"
#include "hearth/hearth.h"
#include "hearth_lua.h"
#include "progress.h"
#include "run_log.h"


static void run_usage(FILE *f, const char *cmd) {
    if (!strcmp(cmd, "repl"))
        fprintf(f, "usage: hearth repl [SCENE.lua] [--out DIR] [--set k=v]... [--threads N] [--lua-memory SIZE] [--memory SIZE]\n"
                   "                  [--trust]\n"
                   "A plain Lua prompt (no curses) with the scene loaded; its variables are globals.\n"
                   "Lines read from a pipe run too:  echo 'print(s:stats().t)' | hearth repl scene.lua\n");
    else
        fprintf(f, "usage: hearth run SCENE.lua [--until T] [--frames N] [--vtu DIR] [--movie FILE] [--out DIR] [--set k=v]... [--threads N] [--quiet]\n"
                   "                 [--lua-memory SIZE] [--memory SIZE] [--trust] [--params]\n"
                   "Runs a Lua scene headless. Outputs go to DIR (default ./hearth-out/<scene name>/).\n"
                   "  --until T    stop every s:run at sim time T (s), with a frame of the state there\n"
                   "  --frames N   N frames per run (every = span / N)\n"
                   "  --vtu DIR    every s:run also writes VTU frames and DIR/frame.pvd (DIR under the outputs)\n"
                   "  --movie FILE every s:run's PNG frames also become the movie FILE (.mp4; 10 fps) through the\n"
                   "               ffmpeg program; without ffmpeg a notice says so and the frames stay\n"
                   "  --set k=v    override a parameter the scene declares with h.params{...}\n"
                   "  --params     list the scene's parameters, their defaults, the words each word\n"
                   "               parameter takes (h.choice), each number's range (h.number) and what each\n"
                   "               switch does (h.flag), then stop: nothing is simulated or written\n"
                   "  --threads N  OpenMP threads (results do not depend on it)\n"
                   "  --quiet      no progress output\n"
                   "  --metric M   at the end print metric M (h.metric or built-in: height, spread,\n"
                   "               centre_temperature, front, volume, water_lost)\n"
                   "  --metric-out FILE  also write it with steps and wall time to FILE (for hearth trade)\n"
                   "  --lua-memory SIZE  ceiling of the scene's Lua memory: bytes, or with K, M, G (default 512M)\n"
                   "  --memory SIZE      ceiling of the simulation's memory (particles, grid, scratch): bytes,\n"
                   "               or with K, M, G (default half the machine's memory)\n"
                   "  --trust      lift the sandbox (os.execute, io.popen, writes outside DIR, C modules,\n"
                   "               plugins by path or from the scene's folder)\n"
                   "Exit status: 0 done, 1 scene error, 2 bad usage or --set value, 3 the stability guard stopped\n"
                   "the run, 4 a plugin crashed or called exit() (it is named), 130 SIGINT (Ctrl-C), 143 SIGTERM.\n");
}

/* "300M", "2G", "1.5G", "65536": bytes, K/M/G binary multiples, an optional
 * trailing B or iB. Returns 0 and the size, or -1. */
static int parse_size(const char *v, size_t *out) {
    char *end;
    errno = 0;
    double x = strtod(v, &end);
    if (end == v || errno || !(x > 0)) return -1;
    double mul = 1;
    if (*end == 'K' || *end == 'k') mul = 1024.0, end++;
    else if (*end == 'M' || *end == 'm') mul = 1024.0 * 1024, end++;
    else if (*end == 'G' || *end == 'g') mul = 1024.0 * 1024 * 1024, end++;
    else if (*end == 'T' || *end == 't') mul = 1024.0 * 1024 * 1024 * 1024, end++;
    if (mul > 1 && *end == 'i') end++;
    if (*end == 'B' || *end == 'b') end++;
    if (*end) return -1;
    x *= mul;
    if (!(x < 9.0e15)) return -1;
    *out = (size_t)x;
    return 0;
}

int app_run_parse(run_args *a, int argc, char **argv, const char *cmd) {
    memset(a, 0, sizeof *a);
    a->argc = argc;
    a->argv = argv;
    for (int i = 1; i < argc; i++) {
        const char *s = argv[i];
        if (!strcmp(s, "--help") || !strcmp(s, "-h")) {
            run_usage(stdout, cmd);
            return 1;
        }
        if (!strcmp(s, "--quiet")) { a->quiet = 1; continue; }
        if (!strcmp(s, "--trust")) { a->trust = 1; continue; }
        if (!strcmp(s, "--params") && !strcmp(cmd, "run")) { a->list_params = 1; continue; }
        if (s[0] == '-' && s[1] == '-') {
            static const char *const valued[] = {"--out", "--until", "--frames", "--threads", "--set", "--metric", "--metric-out", "--lua-memory", "--memory", "--vtu", "--movie", NULL};
            int known = 0;
            for (int k = 0; valued[k]; k++) known |= !strcmp(s, valued[k]);
            if (!known) {
                static const char *const all[] = {"--out", "--until", "--frames", "--threads", "--set", "--metric", "--metric-out",
                                                  "--lua-memory", "--memory", "--vtu", "--movie", "--quiet", "--trust", "--params", "--help", NULL};
                const char *near = app_did_you_mean(s, all);
                if (near) fprintf(stderr, "hearth %s: unknown option '%s'; did you mean '%s'? (see --help)\n", cmd, s, near);
                else fprintf(stderr, "hearth %s: unknown option '%s' (see --help)\n", cmd, s);
                return 2;
            }
            if (i + 1 >= argc) {
                fprintf(stderr, "hearth %s: %s needs a value (see --help)\n", cmd, s);
                return 2;
            }
            const char *v = argv[++i];
            if (!strcmp(s, "--out")) a->out = v;
            else if (!strcmp(s, "--vtu")) a->vtu = v;
            else if (!strcmp(s, "--movie")) a->movie = v;
            else if (!strcmp(s, "--metric")) a->metric = v;
            else if (!strcmp(s, "--metric-out")) a->metric_out = v;
            else if (!strcmp(s, "--lua-memory")) {
                /* below 16M the module itself does not fit; the top is only a sanity bound */
                if (parse_size(v, &a->lua_memory) || a->lua_memory < ((size_t)16 << 20) || a->lua_memory > ((size_t)1 << 40)) {
                    fprintf(stderr, "hearth %s: --lua-memory needs a size from 16M to 1T (bytes, or with K, M, G: "
                                    "300M, 2G), got '%s'\n", cmd, v);
                    return 2;
                }
            }
            else if (!strcmp(s, "--memory")) {
                /* below 64M not even a small scene fits; the top is only a sanity bound */
                if (parse_size(v, &a->memory) || a->memory < ((size_t)64 << 20) || a->memory > ((size_t)1 << 50)) {
                    fprintf(stderr, "hearth %s: --memory needs a size from 64M to 1024T (bytes, or with K, M, G, T: "
                                    "8G, 500M), got '%s'\n", cmd, v);
                    return 2;
                }
            }
            else if (!strcmp(s, "--until")) {
                char *end;
                a->until = strtod(v, &end);
                if (*end || !(a->until > 0)) {
                    fprintf(stderr, "hearth %s: --until needs a time > 0 in seconds, got '%s'\n", cmd, v);
                    return 2;
                }
            } else if (!strcmp(s, "--frames")) {
                if ((a->frames = app_parse_int(cmd, "--frames", v, 1, 1000000)) < 0) return 2;
            } else if (!strcmp(s, "--threads")) {
                long t = app_parse_int(cmd, "--threads", v, 1, 1024);
                if (t < 0) return 2;
                hearth_set_threads((int)t);
            } else if (!strcmp(s, "--set")) {
                if (!strchr(v, '=') || v[0] == '=') {
                    fprintf(stderr, "hearth %s: --set needs name=value, got '%s'\n", cmd, v);
                    return 2;
                }
                if (a->nsets == 64) {
                    fprintf(stderr, "hearth %s: at most 64 --set options\n", cmd);
                    return 2;
                }
                a->sets[a->nsets++] = v;
            } else {
                fprintf(stderr, "hearth %s: unknown option '%s' (see --help)\n", cmd, s);
                return 2;
            }
            continue;
        }
        if (a->scene) {
            fprintf(stderr, "hearth %s: one scene file at a time ('%s' and '%s')\n", cmd, a->scene, s);
            return 2;
        }
        a->scene = s;
    }
    /* a scene from someone else may not take the whole machine: half of it
     * unless the user says otherwise (the library alone has no ceiling but the machine's) */
    const size_t machine = hearth_machine_memory();
    hearth_set_memory_limit(a->memory ? a->memory : machine == SIZE_MAX ? 0 : machine / 2);
    if (!a->scene && !strcmp(cmd, "run")) {
        fprintf(stderr, "hearth run: which scene? usage: hearth run SCENE.lua (see --help)\n");
        return 2;
    }
    if (a->scene && access(a->scene, R_OK) != 0) {
        fprintf(stderr, "hearth %s: cannot read scene '%s': %s\n", cmd, a->scene, strerror(errno));
        return 2;
    }
    /* scene folder (plugins and assets next to a scene are found) and default output folder */
    snprintf(a->dir_buf, sizeof a->dir_buf, "%s", a->scene ? a->scene : ".");
    char *slash = strrchr(a->dir_buf, '/');
    if (!a->scene) snprintf(a->dir_buf, sizeof a->dir_buf, ".");
    else if (slash) *slash = '\0';
    else snprintf(a->dir_buf, sizeof a->dir_buf, ".");
    if (!a->out) {
        const char *base = a->scene ? strrchr(a->scene, '/') : NULL;
        base = base ? base + 1 : (a->scene ? a->scene : "repl");
        size_t n = strlen(base);
        if (n > 4 && !strcmp(base + n - 4, ".lua")) n -= 4;
        snprintf(a->out_buf, sizeof a->out_buf, "hearth-out/%.*s", (int)n, base);
        a->out = a->out_buf;
    }
    return 0;
}

static void on_progress(void *ud, double t, double t_end, long steps, int final) {
    progress *p = ud;
    p->t_end = t_end;
    if (final == HL_PROGRESS_START) progress_run_start(p, t, t_end, steps);
    else if (final) progress_finish(p, t, steps);
    else progress_update(p, t, steps);
}

/* The last failure's message, for the run record. */
static char g_last_error[1024];

/* Report a failed protected call; returns the exit status: 3 for a guard
 * stop, 2 for a bad --set value, 128 + the signal for an interrupt, else 1. */
static int report(lua_State *L, const char *cmd, const char *out) {
    int st;
    int kind = hl_error_message(L, -1);
    snprintf(g_last_error, sizeof g_last_error, "%s", lua_tostring(L, -1) ? lua_tostring(L, -1) : "");
    switch (kind) {
    case HL_ERR_GUARD:
        fprintf(stderr, "hearth %s: the stability guard stopped the run:\n  %s\n", cmd, lua_tostring(L, -1));
        st = 3;
        break;
    case HL_ERR_USAGE:
        fprintf(stderr, "hearth %s: %s\n", cmd, lua_tostring(L, -1));
        st = 2;
        break;
    case HL_ERR_LISTED: /* --params: the listing is on stdout, and that is the whole run */
        st = 0;
        break;
    case HL_ERR_INTERRUPT:
        fprintf(stderr, "hearth %s: %s; the outputs written before it are whole, in %s/\n", cmd, lua_tostring(L, -1), out);
        st = 128 + hl_interrupted();
        break;
    default:
        fprintf(stderr, "hearth %s: %s\n", cmd, lua_tostring(L, -1));
        st = 1;
    }
    lua_pop(L, 2);
    return st;
}

static lua_State *start(run_args *a, progress *pr, const char *cmd) {
    hearth_error err;
    if (!a->list_params && hearth_mkdir_p(a->out, &err)) { /* a listing writes nothing */
        fprintf(stderr, "hearth %s: %s\n", cmd, err.msg);
        return NULL;
    }
    int stale = a->list_params ? 0 : hearth_clean_stale_temps(a->out);
    if (stale > 0)
        fprintf(stderr, "hearth %s: removed %d stale temporary file%s of killed runs from %s/\n", cmd, stale,
                stale == 1 ? "" : "s", a->out);
    /* the scene's folder may hold plugins only a trusted scene may load:
     * an untrusted one could have put them there */
    if (a->trust) hearth_plugin_path_add(a->dir_buf);
    hl_interrupt_install();
    progress_start(pr, a->until, a->quiet);
    hl_options o = {.out_dir = a->out, .scene_dir = a->dir_buf, .until_override = a->until,
                    .frames_override = (int)a->frames, .quiet = a->quiet, .trusted = a->trust,
                    .sets = a->sets, .progress = on_progress, .progress_ud = pr,
                    .assets_dir = app_assets_dir(), .lua_memory = a->lua_memory, .vtu_dir = a->vtu,
                    .movie = a->movie, .in_dir = a->out_shared, .list_params = a->list_params};
    lua_State *L = hl_new_state(&o, &err);
    if (!L) fprintf(stderr, "hearth %s: %s\n", cmd, err.msg);
    return L;
}

/* Evaluate --metric on the scene the file built and print it; with
 * --metric-out also write "key value" lines (status, metric, steps, t,
 * particles, rollbacks, message) for hearth trade. status is the run's
 * status so far; returns the final one. */
static int metric_report(lua_State *L, const run_args *a, int status) {
    double value = NAN, t = NAN;
    long steps = -1, rollbacks = 0, particles = 0;
    char msg[1200] = "";
    if (status == 0) {
        lua_getglobal(L, "require");
        lua_pushliteral(L, "hearth");
        if (hl_pcall(L, 1, 1) == LUA_OK) {
            lua_getfield(L, -1, "_metric");
            lua_pushstring(L, a->metric);
            if (hl_pcall(L, 1, 2) != LUA_OK) {
                hl_error_message(L, -1);
                snprintf(msg, sizeof msg, "%s", lua_tostring(L, -1));
                lua_pop(L, 2);
                fprintf(stderr, "hearth run: %s\n", msg);
                status = 1;
            } else {
                value = lua_tonumber(L, -2);
                lua_getfield(L, -1, "step"), steps = (long)lua_tointeger(L, -1), lua_pop(L, 1);
                lua_getfield(L, -1, "t"), t = lua_tonumber(L, -1), lua_pop(L, 1);
                lua_getfield(L, -1, "rollbacks"), rollbacks = (long)lua_tointeger(L, -1), lua_pop(L, 1);
                lua_getfield(L, -1, "particles"), particles = (long)lua_tointeger(L, -1), lua_pop(L, 1);
                lua_pop(L, 2);
                printf("metric %s = %.10g\n", a->metric, value);
            }
            lua_pop(L, 1);
        }
    }
    if (!a->metric_out) return status;
    char tmp[4200];
    snprintf(tmp, sizeof tmp, "%s.tmp", a->metric_out);
    FILE *f = fopen(tmp, "w");
    if (!f) {
        fprintf(stderr, "hearth run: cannot write %s: %s\n", tmp, strerror(errno));
        return status ? status : 1;
    }
    fprintf(f, "status %d\nmetric %.17g\nsteps %ld\nt %.17g\nparticles %ld\nrollbacks %ld\n", status, value, steps, t,
            particles, rollbacks);
    if (msg[0]) fprintf(f, "message %s\n", msg);
    if (fclose(f) || rename(tmp, a->metric_out)) {
        fprintf(stderr, "hearth run: cannot write %s: %s\n", a->metric_out, strerror(errno));
        return status ? status : 1;
    }
    return status;
}

int cmd_run(int argc, char **argv) {
    run_args a;
    int rc = app_run_parse(&a, argc, argv, "run");
    if (rc) return rc == 1 ? 0 : rc;
    char scratch[4096];
    if (app_ranks_follow(&a, scratch, sizeof scratch)) return 1; /* mpirun: ranks > 0 write nothing of their own */
    progress pr;
    lua_State *L = start(&a, &pr, "run");
    if (!L) {
        app_ranks_cleanup(scratch);
        return 1;
    }
    run_log rec;
    run_log_start(&rec, "run", a.argc, a.argv, a.scene, a.out, a.sets, a.nsets);
    int status = 0;
    if (luaL_loadfilex(L, a.scene, "t") != LUA_OK) status = report(L, "run", a.out);
    else if (hl_pcall(L, 0, 0) != LUA_OK) status = report(L, "run", a.out);
    else { /* h._finish(): --set checks, and run a scene the file built but did not run */
        lua_getglobal(L, "require");
        lua_pushliteral(L, "hearth");
        if (hl_pcall(L, 1, 1) != LUA_OK) status = report(L, "run", a.out);
        else {
            lua_getfield(L, -1, "_finish");
            if (hl_pcall(L, 0, 0) != LUA_OK) status = report(L, "run", a.out);
            lua_pop(L, 1);
        }
    }
    if (a.metric && status < 128 && !a.list_params) status = metric_report(L, &a, status);
    /* Under several ranks stats() is collective while slabs are kept: a rank
     * whose run failed on its own (a Lua error only it raised, between two
     * step calls) would wait in it for ranks waiting in their next step. A
     * guard stop reaches every rank at the same step, so it keeps its
     * counters; after any other failure the record goes without them, and
     * main's _exit lets mpirun end the others (#21). */
    if (!(status && status != 3 && hearth_ranks_size() > 1)) run_log_scene(&rec, L);
    if (status) run_log_message(&rec, g_last_error);
    if (!a.list_params) run_log_write(&rec, status); /* a listing writes nothing */
    if (status == 0 && !a.quiet && !a.list_params) fprintf(stderr, "hearth run: done; outputs in %s/\n", a.out);
    hl_close_state(L);
    app_ranks_cleanup(scratch);
    app_ranks_report(&a, status, g_last_error);
    return status;
}

/* ---- repl ------------------------------------------------------------- */

static int incomplete(lua_State *L, int status) {
    if (status != LUA_ERRSYNTAX) return 0;
    size_t n;
    const char *msg = lua_tolstring(L, -1, &n);
    return n >= 5 && !strcmp(msg + n - 5, "<eof>");
}

int cmd_repl(int argc, char **argv) {
    run_args a;
    int rc = app_run_parse(&a, argc, argv, "repl");
    if (rc) return rc == 1 ? 0 : rc;
    a.quiet = 1;
    progress pr;
    lua_State *L = start(&a, &pr, "repl");
    if (!L) return 1;
    const int tty = isatty(0);
    if (a.scene) {
        if (luaL_loadfilex(L, a.scene, "t") != LUA_OK || hl_pcall(L, 0, 0) != LUA_OK) {
            int st = report(L, "repl", a.out);
            hl_close_state(L);
            return st;
        }
    }
    /* `h` is always at hand; `s` is the scene the file built */
    lua_getglobal(L, "require");
    lua_pushliteral(L, "hearth");
    if (hl_pcall(L, 1, 1) == LUA_OK) {
        lua_getfield(L, -1, "_last_scene");
        if (!lua_isnil(L, -1)) {
            lua_getglobal(L, "s");
            if (lua_isnil(L, -1)) lua_pushvalue(L, -2), lua_setglobal(L, "s");
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
        lua_setglobal(L, "h");
    } else lua_pop(L, 1);
    if (tty) printf("hearth %s repl: Lua 5.4 with the scene loaded (h = require \"hearth\"); Ctrl-D quits\n", HEARTH_VERSION);
    char line[8192];
    char *buf = NULL;
    size_t blen = 0;
    int errors = 0;
    for (;;) {
        if (tty) {
            fputs(blen ? ">> " : "> ", stdout);
            fflush(stdout);
        }
        if (hl_interrupted() || !fgets(line, sizeof line, stdin)) break;
        size_t ln = strlen(line);
        char *nb = realloc(buf, blen + ln + 1);
        if (!nb) break;
        buf = nb;
        memcpy(buf + blen, line, ln + 1);
        blen += ln;
        /* an expression prints its value; otherwise a statement */
        lua_pushfstring(L, "return %s", buf);
        int st = luaL_loadbufferx(L, lua_tostring(L, -1), strlen(lua_tostring(L, -1)), "=stdin", "t");
        lua_remove(L, -2);
        if (st != LUA_OK) {
            lua_pop(L, 1);
            st = luaL_loadbufferx(L, buf, blen, "=stdin", "t");
        }
        if (incomplete(L, st)) { /* multi-line input: keep reading */
            lua_pop(L, 1);
            continue;
        }
        blen = 0;
        if (st != LUA_OK) {
            fprintf(stderr, "%s\n", lua_tostring(L, -1));
            lua_pop(L, 1);
            errors++;
            continue;
        }
        int top = lua_gettop(L) - 1;
        if (hl_pcall(L, 0, LUA_MULTRET) != LUA_OK) {
            if (report(L, "repl", a.out) >= 128) break; /* Ctrl-C stops the repl as it stops a run */
            errors++;
            continue;
        }
        int nres = lua_gettop(L) - top;
        for (int i = 1; i <= nres; i++) {
            printf("%s%s", luaL_tolstring(L, top + i, NULL), i < nres ? "\t" : "\n");
            lua_pop(L, 1);
        }
        lua_settop(L, top);
        fflush(stdout);
    }
    free(buf);
    if (tty) printf("\n");
    hl_close_state(L);
    if (hl_interrupted()) return 128 + hl_interrupted();
    return errors && !tty ? 1 : 0;
}

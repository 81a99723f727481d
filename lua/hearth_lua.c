/* hearth_lua.c: the Lua state scenes run in, and the `hearth` module in it.
 *
 * hl_new_state is the one constructor: a counting allocator with a ceiling,
 * an interrupt hook, the standard library (sandboxed unless trusted) and the
 * module. `require "hearth"` runs the embedded lua/hearth/init.lua with the C
 * core table (hearth.core) as its argument. The options (output folder, --set
 * values, overrides) are kept in the registry for the module's functions. */
#define _POSIX_C_SOURCE 200809L /* sigaction */
#include <signal.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <lualib.h>

#include "hearth_lua.h"

typedef struct {
    const char *name;
    const char *src;
    size_t len;
} hl_embedded;
extern const hl_embedded hl_embedded_sources[];

static const char OPTS_KEY = 'o';

const hl_options *hl_opts(lua_State *L) {
    lua_rawgetp(L, LUA_REGISTRYINDEX, &OPTS_KEY);
    const hl_options *o = lua_touserdata(L, -1);
    lua_pop(L, 1);
    return o;
}

#define HL_ERROR "hearth.error" /* metatable of the module's marked errors (guard stops, usage, --params listed) */

/* Is the value at idx one of the module's marked errors? Compares the real
 * metatable (lua_getmetatable ignores __metatable), which scenes cannot reach. */
static int marked_error(lua_State *L, int idx) {
    if (lua_type(L, idx) != LUA_TTABLE || !lua_getmetatable(L, idx)) return 0;
    luaL_getmetatable(L, HL_ERROR);
    int ours = lua_rawequal(L, -1, -2);
    lua_pop(L, 2);
    return ours;
}

int hl_raise_kind(lua_State *L, const char *kind, const char *msg) {
    lua_createtable(L, 0, 3);
    lua_pushstring(L, kind);
    lua_setfield(L, -2, "kind");
    lua_pushboolean(L, !strcmp(kind, "guard")); /* scenes test e.guard to tell a guard stop from an error */
    lua_setfield(L, -2, "guard");
    lua_pushstring(L, msg);
    lua_setfield(L, -2, "message");
    luaL_setmetatable(L, HL_ERROR);
    return lua_error(L);
}

static int l_error_tostring(lua_State *L) {
    lua_getfield(L, 1, "message");
    return 1;
}

/* core.usage_error(msg [, level]): a bad --set value, exit 2 in hearth run;
 * level as error()'s, for the scene line that declared the parameter */
static int l_usage_error(lua_State *L) {
    const char *msg = luaL_checkstring(L, 1);
    int level = (int)luaL_optinteger(L, 2, 0);
    if (level > 0) luaL_where(L, level);
    else lua_pushliteral(L, "");
    lua_pushstring(L, msg);
    lua_concat(L, 2);
    return hl_raise_kind(L, "usage", lua_tostring(L, -1));
}

/* core.listed(): hearth run --params has printed the scene's parameters (lua/hearth/params.lua); the
 * run ends here, successfully, before the scene makes anything. A marked error, so only the module raises it. */
static int l_listed(lua_State *L) {
    return hl_raise_kind(L, "listed", "the scene's parameters are listed (hearth run --params)");
}

static int traceback(lua_State *L) {
    if (marked_error(L, 1)) return 1; /* a guard stop or usage error: its message says it all, no traceback */
    const char *msg = lua_type(L, 1) == LUA_TSTRING || lua_type(L, 1) == LUA_TNUMBER ? lua_tostring(L, 1) : NULL;
    if (!msg)
        msg = lua_pushfstring(L, "the scene raised an error that is a %s, not a message (error(\"text\") gives one)",
                              luaL_typename(L, 1));
    /* An error raised in the scene's main chunk itself (its own check of a --set value, or a slip on a top-level
     * line) already names the file and line, and a traceback would repeat that line under "stack traceback:";
     * userview saw users read it as a crash. So does a refusal hearth's own modules raise at the caller's line
     * (h.material's range check, error(msg, level)): the frames above the chunk are then hearth's, and the message
     * begins with the chunk's own file:line. Keep the traceback where it says more: a scene function between the
     * error and the chunk (a helper, an on_frame callback), or an error inside hearth's modules (a message that
     * names a line of theirs). */
    int scene_frames = 0, main_level = 0;
    lua_Debug ar;
    /* stop at the second scene frame, or 64 levels: a stack overflow holds ~1e5 frames, and lua_getstack walks
     * to its level */
    for (int level = 1; scene_frames < 2 && level <= 64 && lua_getstack(L, level, &ar); level++) {
        if (!lua_getinfo(L, "S", &ar) || ar.what[0] == 'C' || !strncmp(ar.source, "=[hearth]/", 10)) continue;
        scene_frames++;
        if (!strcmp(ar.what, "main")) main_level = level;
    }
    if (scene_frames == 1 && main_level && lua_getstack(L, main_level, &ar) && lua_getinfo(L, "Sl", &ar)) {
        char where[LUA_IDSIZE + 32];
        snprintf(where, sizeof where, "%s:%d:", ar.short_src, ar.currentline);
        if (!strncmp(msg, where, strlen(where))) {
            lua_pushstring(L, msg);
            return 1;
        }
    }
    luaL_traceback(L, L, msg, 1);
    return 1;
}

int hl_errorf(lua_State *L, const char *fmt, ...) {
    char buf[512];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    return luaL_error(L, "%s", buf);
}

int hl_pcall(lua_State *L, int nargs, int nres) {
    int base = lua_gettop(L) - nargs;
    lua_pushcfunction(L, traceback);
    lua_insert(L, base);
    int st = lua_pcall(L, nargs, nres, base);
    lua_remove(L, base);
    return st;
}

static int l_options(lua_State *L) {
    const hl_options *o = hl_opts(L);
    lua_createtable(L, 0, 8);
    if (o->out_dir) lua_pushstring(L, o->out_dir), lua_setfield(L, -2, "out_dir");
    if (o->scene_dir) lua_pushstring(L, o->scene_dir), lua_setfield(L, -2, "scene_dir");
    if (o->assets_dir) lua_pushstring(L, o->assets_dir), lua_setfield(L, -2, "assets_dir");
    if (o->until_override > 0) lua_pushnumber(L, o->until_override), lua_setfield(L, -2, "until_t");
    if (o->frames_override > 0) lua_pushinteger(L, o->frames_override), lua_setfield(L, -2, "frames");
    if (o->vtu_dir) lua_pushstring(L, o->vtu_dir), lua_setfield(L, -2, "vtu_dir");
    if (o->movie) lua_pushstring(L, o->movie), lua_setfield(L, -2, "movie");
    lua_pushboolean(L, o->quiet), lua_setfield(L, -2, "quiet");
    lua_pushboolean(L, o->yield_steps), lua_setfield(L, -2, "yield");
    lua_pushboolean(L, o->list_params), lua_setfield(L, -2, "list_params");
    lua_newtable(L);
    for (int i = 0; o->sets && o->sets[i]; i++) {
        const char *eq = strchr(o->sets[i], '=');
        if (!eq) continue;
        lua_pushlstring(L, o->sets[i], (size_t)(eq - o->sets[i]));
        lua_pushstring(L, eq + 1);
        lua_settable(L, -3);
    }
    lua_setfield(L, -2, "sets");
    return 1;
}

static int l_progress(lua_State *L) {
    const hl_options *o = hl_opts(L);
    /* the 4th argument: true at a run's end, "start" at its start (run.lua), else nothing */
    const int phase = lua_type(L, 4) == LUA_TSTRING && !strcmp(lua_tostring(L, 4), "start") ? HL_PROGRESS_START
                                                                                             : lua_toboolean(L, 4);
    if (o->progress && !o->quiet)
        o->progress(o->progress_ud, luaL_checknumber(L, 1), luaL_checknumber(L, 2), (long)luaL_checkinteger(L, 3), phase);
    return 0;
}

static int l_field_unit(lua_State *L) {
    const char *u = hearth_field_unit(luaL_checkstring(L, 1));
    if (u) lua_pushstring(L, u);
    else lua_pushnil(L);
    return 1;
}

static int open_core(lua_State *L) {
    lua_newtable(L);
    hl_open_shapes(L);
    hl_open_scene(L);
    hl_open_output(L);
    hl_open_material(L);
    luaL_getmetatable(L, HL_SCENE); /* init.lua adds its Lua methods to the same table */
    lua_getfield(L, -1, "__index");
    lua_setfield(L, -3, "scene_methods");
    lua_pop(L, 1);
    lua_pushcfunction(L, l_options);
    lua_setfield(L, -2, "options");
    lua_pushcfunction(L, l_progress);
    lua_setfield(L, -2, "progress");
    lua_pushcfunction(L, l_field_unit);
    lua_setfield(L, -2, "field_unit");
    lua_pushcfunction(L, l_usage_error);
    lua_setfield(L, -2, "usage_error");
    lua_pushcfunction(L, l_listed);
    lua_setfield(L, -2, "listed");
    lua_pushstring(L, HEARTH_VERSION);
    lua_setfield(L, -2, "version");
    return 1;
}

/* package.preload entries: hearth (init.lua) and hearth.* helpers, all embedded. */
static int load_embedded(lua_State *L) {
    const char *name = lua_tostring(L, 1);
    for (const hl_embedded *e = hl_embedded_sources; e->name; e++) {
        if (strcmp(e->name, name) != 0) continue;
        char chunk[128];
        snprintf(chunk, sizeof chunk, "=[hearth]/%s.lua", e->name);
        if (luaL_loadbufferx(L, e->src, e->len, chunk, "t") != LUA_OK) return lua_error(L);
        luaL_requiref(L, "hearth.core", open_core, 0);
        lua_call(L, 1, 1);
        return 1;
    }
    return luaL_error(L, "no embedded module '%s'", name);
}

void hl_open(lua_State *L, const hl_options *opt) {
    hl_options *o = lua_newuserdatauv(L, sizeof *o, 0);
    *o = *opt;
    lua_rawsetp(L, LUA_REGISTRYINDEX, &OPTS_KEY);
    lua_getglobal(L, "package");
    lua_getfield(L, -1, "preload");
    for (const hl_embedded *e = hl_embedded_sources; e->name; e++) {
        lua_pushcfunction(L, load_embedded);
        lua_setfield(L, -2, e->name);
    }
    lua_pop(L, 2);
    if (luaL_newmetatable(L, HL_ERROR)) {
        lua_pushcfunction(L, l_error_tostring);
        lua_setfield(L, -2, "__tostring");
        lua_pushliteral(L, HL_ERROR); /* getmetatable(e) gives this string: a scene cannot forge a guard stop */
        lua_setfield(L, -2, "__metatable");
    }
    lua_pop(L, 1);
}

/* ---- the state: memory ceiling, interrupts ---------------------------- */

typedef struct hl_mem {
    size_t used, limit;
    int hit; /* an allocation was refused for the ceiling */
} hl_mem;

/* Lua's allocator with a ceiling: growing past limit fails like malloc, so
 * Lua raises its memory error, which hl_error_message names. Shrinking and
 * freeing always succeed. */
static void *counting_alloc(void *ud, void *ptr, size_t osize, size_t nsize) {
    hl_mem *m = ud;
    const size_t old = ptr ? osize : 0; /* without ptr, osize is a type tag */
    if (nsize == 0) {
        free(ptr);
        m->used -= old;
        return NULL;
    }
    if (nsize > old && nsize - old > m->limit - m->used) {
        m->hit = 1;
        return NULL;
    }
    void *p = realloc(ptr, nsize);
    if (!p) return NULL;
    m->used = m->used - old + nsize;
    return p;
}

static int on_panic(lua_State *L) {
    const char *msg = lua_tostring(L, -1);
    fprintf(stderr, "hearth: Lua panic (an error outside any protected call): %s\n", msg ? msg : "?");
    return 0; /* Lua aborts */
}

static volatile sig_atomic_t g_signal;
static int (*g_host_interrupted)(void);
static lua_State *volatile g_main; /* the state of hl_new_state, for the signal handler */
static void interrupt_hook(lua_State *L, lua_Debug *ar);

/* The scene stops at its next Lua instruction, but not inside a call into the
 * core: one step of a big scene (a few thousand colliders against a million
 * particles) can take minutes, and a user who sent SIGTERM saw nothing happen.
 * If the process is still here STOP_NOTICE_S seconds after the first signal,
 * say why and how to quit at once (write and alarm are async-signal-safe). */
enum { STOP_NOTICE_S = 2 };
static void on_stop_notice(int sig) {
    (void)sig;
    static const char msg_int[] = "hearth: stopping after SIGINT once the core returns from the call it is in "
                                  "(a long step); SIGINT again quits at once\n";
    static const char msg_term[] = "hearth: stopping after SIGTERM once the core returns from the call it is in "
                                   "(a long step); SIGTERM again quits at once\n";
    if (g_signal == SIGTERM) (void)!write(STDERR_FILENO, msg_term, sizeof msg_term - 1);
    else (void)!write(STDERR_FILENO, msg_int, sizeof msg_int - 1);
    /* A plugin callback that never returns looks like a long step: when the thread the alarm lands on is inside
     * one (the main thread, which also steps), name it, as a crash in one is named (#18, helper userview5). Reads
     * only, and strlen and write are async-signal-safe. */
    hearth_plugin_call_info c;
    if (hearth_plugin_call_current(&c)) {
        const char *part[] = {"hearth: the call is inside plugin '", c.material, "' (", c.file, "), callback ",
                              c.callback, "; a callback that never returns keeps it there\n"};
        for (size_t i = 0; i < sizeof part / sizeof *part; i++)
            (void)!write(STDERR_FILENO, part[i], strlen(part[i]));
    }
}

static void on_signal(int sig) {
    if (g_signal) _exit(128 + sig); /* the second Ctrl-C: the user means it */
    g_signal = sig;
    /* lua_sethook is safe in a signal handler (the manual says so): the main
     * thread now stops at its next instruction, not its next count */
    if (g_main) lua_sethook(g_main, interrupt_hook, LUA_MASKCALL | LUA_MASKRET | LUA_MASKCOUNT, 1);
    alarm(STOP_NOTICE_S);
}

void hl_interrupt_install(void) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sa.sa_handler = on_stop_notice;
    sa.sa_flags = SA_RESTART; /* the notice must not fail a write the stop is finishing (EINTR) */
    sigaction(SIGALRM, &sa, NULL);
}

int hl_interrupted(void) {
    if (g_signal) return (int)g_signal;
    return g_host_interrupted ? g_host_interrupted() : 0;
}

/* Every HOOK_COUNT instructions in every coroutine (a new thread inherits its
 * creator's hook). Once a signal stands the hook fires at every instruction,
 * call and return of the thread it caught, and raises each time: a pcall in
 * the scene catches the error only to meet it again at its next instruction,
 * so the scene unwinds to the host. */
#define HOOK_COUNT 1000
static void interrupt_hook(lua_State *L, lua_Debug *ar) {
    (void)ar;
    int sig = hl_interrupted();
    if (!sig) return;
    lua_sethook(L, interrupt_hook, LUA_MASKCALL | LUA_MASKRET | LUA_MASKCOUNT, 1);
    lua_pushstring(L, sig == SIGTERM ? "interrupted by SIGTERM" : sig == SIGINT ? "interrupted by SIGINT" : "interrupted by a signal");
    lua_error(L);
}

static int open_state(lua_State *L) {
    const hl_options *opt = lua_touserdata(L, 1);
    if (opt->trusted) luaL_openlibs(L);
    else hl_open_sandboxed_libs(L);
    hl_open(L, opt);
    return 0;
}

lua_State *hl_new_state(const hl_options *opt, hearth_error *err) {
    hl_mem *m = calloc(1, sizeof *m);
    if (!m) {
        err->code = HEARTH_ERR_NOMEM;
        snprintf(err->msg, sizeof err->msg, "out of memory starting Lua");
        return NULL;
    }
    m->limit = opt->lua_memory ? opt->lua_memory : HL_LUA_MEMORY_DEFAULT;
    lua_State *L = lua_newstate(counting_alloc, m);
    if (!L) {
        free(m);
        err->code = HEARTH_ERR_NOMEM;
        snprintf(err->msg, sizeof err->msg, "out of memory starting Lua");
        return NULL;
    }
    lua_atpanic(L, on_panic);
    lua_setwarnf(L, NULL, NULL);
    g_host_interrupted = opt->interrupted;
    hearth_set_interrupt_check(hl_interrupted); /* a batch of steps (s:run's 64) ends at the next step's start */
    lua_sethook(L, interrupt_hook, LUA_MASKCOUNT, HOOK_COUNT);
    g_main = L;
    /* before any scene code: native code only by name from folders the scene cannot write */
    if (!opt->trusted) hearth_plugin_restrict(opt->out_dir);
    lua_pushcfunction(L, open_state);
    lua_pushlightuserdata(L, (void *)opt);
    if (lua_pcall(L, 1, 0, 0) != LUA_OK) {
        err->code = HEARTH_ERR_NOMEM;
        snprintf(err->msg, sizeof err->msg, "cannot start Lua: %s (the Lua memory ceiling is %zu bytes; see --lua-memory)",
                 lua_tostring(L, -1) ? lua_tostring(L, -1) : "?", m->limit);
        hl_close_state(L);
        return NULL;
    }
    return L;
}

void hl_close_state(lua_State *L) {
    if (!L) return;
    if (g_main == L) g_main = NULL;
    lua_sethook(L, NULL, 0, 0); /* the scene's finalizers (freeing scenes) run even after an interrupt */
    void *ud = NULL;
    const lua_Alloc f = lua_getallocf(L, &ud);
    lua_close(L);
    if (f == counting_alloc) free(ud);
}

/* "512 MiB", "1.5 GiB", "300000 bytes" */
static void format_size(char *buf, size_t n, size_t bytes) {
    if (bytes >= ((size_t)1 << 30) && bytes % ((size_t)1 << 30) == 0) snprintf(buf, n, "%zu GiB", bytes >> 30);
    else if (bytes >= ((size_t)1 << 20) && bytes % ((size_t)1 << 20) == 0) snprintf(buf, n, "%zu MiB", bytes >> 20);
    else snprintf(buf, n, "%zu bytes", bytes);
}

hl_error_kind hl_error_message(lua_State *L, int idx) {
    idx = lua_absindex(L, idx);
    int sig = hl_interrupted();
    if (sig) {
        lua_pushstring(L, sig == SIGTERM ? "interrupted by SIGTERM" : sig == SIGINT ? "interrupted by SIGINT" : "interrupted by a signal");
        return HL_ERR_INTERRUPT;
    }
    if (marked_error(L, idx)) {
        lua_getfield(L, idx, "kind");
        const int guard = lua_tostring(L, -1) && !strcmp(lua_tostring(L, -1), "guard");
        const int listed = lua_tostring(L, -1) && !strcmp(lua_tostring(L, -1), "listed");
        lua_pop(L, 1);
        lua_getfield(L, idx, "message");
        if (!lua_isstring(L, -1)) {
            lua_pop(L, 1);
            lua_pushliteral(L, "(no message)");
        }
        return guard ? HL_ERR_GUARD : listed ? HL_ERR_LISTED : HL_ERR_USAGE;
    }
    const int t = lua_type(L, idx);
    if (t != LUA_TSTRING && t != LUA_TNUMBER) {
        lua_pushfstring(L, "the scene raised an error that is a %s, not a message (error(\"text\") gives one)",
                        luaL_typename(L, idx));
        return HL_ERR_SCRIPT;
    }
    const char *msg = lua_tostring(L, idx);
    void *ud = NULL;
    const hl_mem *m = lua_getallocf(L, &ud) == counting_alloc ? ud : NULL;
    if (m && m->hit && !strncmp(msg, "not enough memory", 17)) {
        char size[64];
        format_size(size, sizeof size, m->limit);
        lua_pushfstring(L, "not enough memory: the scene's Lua memory reached its ceiling of %s; "
                           "raise it with --lua-memory SIZE (e.g. --lua-memory 2G)", size);
        return HL_ERR_MEMORY;
    }
    lua_pushstring(L, msg);
    return HL_ERR_SCRIPT;
}

/* the module table, from package.loaded (loading it if need be); raises on failure */
static void push_module(lua_State *L) {
    lua_getglobal(L, "require");
    lua_pushliteral(L, "hearth");
    lua_call(L, 1, 1);
}

void hl_push_scene(lua_State *L, hearth_scene *s) {
    if (!s) luaL_error(L, "hl_push_scene: no scene");
    push_module(L);
    hl_scene *u = lua_newuserdatauv(L, sizeof *u, 1);
    u->s = s;
    luaL_setmetatable(L, HL_SCENE);
    lua_newtable(L);
    lua_setiuservalue(L, -2, 1);
    lua_getfield(L, -2, "_adopt");
    lua_pushvalue(L, -2);
    lua_call(L, 1, 0);
    lua_remove(L, -2);
}

int hl_scene_clock(lua_State *L, double *time_scale) {
    *time_scale = 1;
    int animation = 0;
    const int top = lua_gettop(L);
    lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    lua_getfield(L, -1, "hearth");
    if (lua_istable(L, -1)) {
        lua_pushliteral(L, "_last_scene");
        lua_rawget(L, -2);
        if (luaL_testudata(L, -1, HL_SCENE) && lua_getiuservalue(L, -1, 1) == LUA_TTABLE) {
            lua_pushliteral(L, "time_scale");
            if (lua_rawget(L, -2) == LUA_TNUMBER && lua_tonumber(L, -1) > 0) *time_scale = lua_tonumber(L, -1);
            lua_pop(L, 1);
            lua_pushliteral(L, "time_units");
            animation = lua_rawget(L, -2) == LUA_TSTRING && !strcmp(lua_tostring(L, -1), "animation");
        }
    }
    lua_settop(L, top);
    return animation;
}

hearth_scene *hl_current_scene(lua_State *L) {
    lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    lua_getfield(L, -1, "hearth");
    hearth_scene *s = NULL;
    if (lua_istable(L, -1)) {
        lua_getfield(L, -1, "_last_scene");
        hl_scene *u = luaL_testudata(L, -1, HL_SCENE);
        s = u ? u->s : NULL;
        lua_pop(L, 1);
    }
    lua_pop(L, 2);
    return s;
}

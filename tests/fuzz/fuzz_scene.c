/* fuzz_scene.c: the scene loader, a Lua chunk run in the sandbox.
 *
 * Each input is a scene's text, run as `hearth run` runs an untrusted scene:
 * the standard libraries, then hl_open with trusted = 0 (which installs the
 * sandbox), the output folder a fresh temporary one, text chunks only. Three
 * limits keep one input cheap and let the fuzzer explore instead of waiting:
 * a Lua memory ceiling (the allocator refuses past LUA_MEM_CAP, and Lua
 * raises "not enough memory"), an instruction and time budget (a count hook
 * raises after ~1e6 VM instructions or 1 s) and the --until / --frames
 * overrides, so any s:run stops early. Time spent inside one C call (a long
 * s:step) is not bounded here; libFuzzer's -timeout catches that. A scene error is the normal outcome; a crash, a leak
 * or a file written beside the output folder (a sandbox escape through
 * "..") is a finding.
 *
 * TODO(issue 15, coordinator): another helper adds hl_new_state(opts, err),
 * the one place a host makes a scene's state (allow-list environment, memory
 * ceiling, interrupt hook). After merging, build with -DFUZZ_HL_NEW_STATE
 * (the line is in tests/fuzz/meson.build, commented out) so the fuzzer runs
 * exactly what `hearth run` runs; the budget hook below still applies. If the
 * signature differs, only new_state() below changes. */
#include <dirent.h>
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>

#include "fuzz_util.h"
#include "hearth_lua.h"

#define LUA_MEM_CAP ((size_t)64 << 20)
#define INSTR_BUDGET 1000000L
#define HOOK_EVERY 1000

typedef struct lua_budget {
    size_t used;
} lua_budget;

/* The hook's counter is not in the allocator's user data, so it works the
 * same whoever made the state. */
static long g_instructions;

static void *capped_alloc(void *ud, void *ptr, size_t osize, size_t nsize) {
    lua_budget *b = ud;
    size_t old = ptr ? osize : 0;
    if (nsize == 0) {
        free(ptr);
        b->used -= old;
        return NULL;
    }
    if (nsize > old && b->used - old + nsize > LUA_MEM_CAP) return NULL;
    void *p = realloc(ptr, nsize);
    if (p) b->used = b->used - old + nsize;
    return p;
}

/* Instructions alone do not bound time: `s = s .. s` on megabyte strings
 * costs a copy per instruction. So the hook also checks the clock. */
#define WALL_BUDGET_S 1.0
static struct timespec g_start;

static double seconds_since_start(void) {
    struct timespec now;
    clock_gettime(CLOCK_MONOTONIC, &now);
    return (double)(now.tv_sec - g_start.tv_sec) + 1e-9 * (double)(now.tv_nsec - g_start.tv_nsec);
}

static void budget_hook(lua_State *L, lua_Debug *ar) {
    (void)ar;
    g_instructions += HOOK_EVERY;
    if (seconds_since_start() > WALL_BUDGET_S) luaL_error(L, "fuzz: time budget of %d s spent", (int)WALL_BUDGET_S);
    if (g_instructions > INSTR_BUDGET) luaL_error(L, "fuzz: instruction budget of %d spent", (int)INSTR_BUDGET);
}

static lua_State *new_state(lua_budget *b, const hl_options *o) {
#ifdef FUZZ_HL_NEW_STATE
    /* hl_new_state's own ceiling and allocator apply; b stays unused. */
    (void)b;
    hearth_error err;
    return hl_new_state(o, &err);
#else
    lua_State *L = lua_newstate(capped_alloc, b);
    if (!L) return NULL;
    luaL_openlibs(L);
    hl_open(L, o);
    return L;
#endif
}

/* Anything beside out/ in the per-process folder came from a scene writing
 * through "..": the sandbox let it out. */
static void check_no_escape(const char *root) {
    DIR *d = opendir(root);
    if (!d) return;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..") || !strcmp(e->d_name, "out")) continue;
        fprintf(stderr, "fuzz_scene: the scene wrote '%s/%s', outside its output folder\n", root, e->d_name);
        FUZZ_CHECK(!"a scene wrote outside its output folder");
    }
    closedir(d);
}

/* Under libFuzzer only (driver.c does not call it): a scene's io.read must
 * not wait on the terminal, and its prints would bury libFuzzer's log. */
int LLVMFuzzerInitialize(int *argc, char ***argv);
int LLVMFuzzerInitialize(int *argc, char ***argv) {
    (void)argc;
    (void)argv;
    if (!freopen("/dev/null", "r", stdin) || !freopen("/dev/null", "w", stdout))
        fprintf(stderr, "fuzz_scene: cannot point stdin and stdout at /dev/null\n");
    return 0;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    hearth_set_threads(1);
    const char *root = fuzz_temp_dir();
    if (!root) return 0;
    char out[600];
    snprintf(out, sizeof out, "%s/out", root);
    fuzz_remove_tree(root, 0); /* the last input's outputs */
    if (mkdir(out, 0700) != 0) return 0;

    lua_budget b = {0};
    g_instructions = 0;
    clock_gettime(CLOCK_MONOTONIC, &g_start);
    hl_options o = {.out_dir = out, .scene_dir = out, .until_override = 0.005, .frames_override = 1,
                    .quiet = 1, .trusted = 0};
    lua_State *L = new_state(&b, &o);
    if (!L) return 0;
    lua_sethook(L, budget_hook, LUA_MASKCOUNT, HOOK_EVERY);
    int st = luaL_loadbufferx(L, (const char *)data, size, "=fuzz.lua", "t");
    if (st == LUA_OK) st = hl_pcall(L, 0, 0);
    if (st != LUA_OK) {
        /* Any value may be an error object (error({}), error(nil)); it must not crash reporting. */
        const char *msg = lua_tostring(L, -1);
        if (fuzz_verbose()) fprintf(stderr, "fuzz_scene: %s\n", msg ? msg : "(not a string)");
        lua_pop(L, 1);
    }
    lua_close(L);
#ifndef FUZZ_HL_NEW_STATE
    FUZZ_CHECK(b.used == 0); /* every Lua block returned */
#endif
    check_no_escape(root);
    return 0;
}

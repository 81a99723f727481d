/* fuzz_scene.c: the scene loader, a Lua chunk run in the sandbox.
 *
 * Each input is a scene's text, run as `hearth run` runs an untrusted scene:
 * a state from hl_new_state with trusted = 0 (the allow-list sandbox, the
 * write gate, plugins by name), the output folder a fresh temporary one,
 * text chunks only. Three limits keep one input cheap and let the fuzzer
 * explore instead of waiting: hl_new_state's Lua memory ceiling at
 * LUA_MEM_CAP, an instruction and time budget (a count hook
 * raises after ~1e6 VM instructions or 1 s) and the --until / --frames
 * overrides, so any s:run stops early. Time spent inside one C call (a long
 * s:step) is not bounded here; libFuzzer's -timeout catches that. A scene error is the normal outcome; a crash, a leak
 * or a file written beside the output folder (a sandbox escape through
 * "..") is a finding.
 */
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

/* The hook's counter is global: the hook has no user data. */
static long g_instructions;

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

    g_instructions = 0;
    clock_gettime(CLOCK_MONOTONIC, &g_start);
    hl_options o = {.out_dir = out, .scene_dir = out, .until_override = 0.005, .frames_override = 1,
                    .quiet = 1, .trusted = 0, .lua_memory = LUA_MEM_CAP};
    hearth_error err;
    lua_State *L = hl_new_state(&o, &err);
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
    hl_close_state(L);
    check_no_escape(root);
    return 0;
}

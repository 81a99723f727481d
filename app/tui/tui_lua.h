/* tui_lua.h: the dashboard's Lua session. The scene file and every prompt
 * command run as coroutines ("jobs"): s:run and s:step yield after each step
 * (hl_options.yield_steps), so the dashboard steps a job a little per redraw
 * and a long s:run{...} never freezes the screen. print goes to the log. */
#ifndef HEARTH_TUI_LUA_H
#define HEARTH_TUI_LUA_H
#include <lua.h>

#include "hearth/hearth.h"
#include "hearth_lua.h"
#include "tui_log.h"

#define TUI_MAX_JOBS 8

typedef struct tui_lua {
    lua_State *L;
    int job_ref[TUI_MAX_JOBS]; ///< registry refs of suspended coroutines; job 0 runs first
    char job_name[TUI_MAX_JOBS][64];
    int njobs;
    tui_log *log;
    char pending[8192]; ///< an unfinished statement gathered over several lines
    size_t plen;
} tui_lua;

/// What a Lua action came to.
typedef enum tui_lua_result {
    TUI_LUA_DONE,    ///< finished
    TUI_LUA_MORE,    ///< the statement is unfinished: give it another line
    TUI_LUA_ERROR,   ///< an error, logged with its line
    TUI_LUA_GUARD,   ///< the stability guard stopped a run; diagnosis in the log
    TUI_LUA_WAITING, ///< a job yielded (it stepped) and will go on
    TUI_LUA_IDLE     ///< no job to resume
} tui_lua_result;

/// Open a Lua state with the hearth module (options as for hearth run, plus
/// yield_steps) and print redirected to the log. Returns 0, or -1 (logged).
int tui_lua_open(tui_lua *t, const hl_options *o, tui_log *log);
void tui_lua_close(tui_lua *t);
/// Queue a scene file as job 0 (it runs on the first resume). -1 when it does not load (logged).
int tui_lua_start_file(tui_lua *t, const char *path);
/// Make a scene built in C the current scene, as `s` (and h is `h`). Takes ownership.
int tui_lua_adopt(tui_lua *t, hearth_scene *s);
/// Set the globals `h` (the module) and `s` (the current scene) unless the scene set them.
void tui_lua_globals(tui_lua *t);
/// Run one line from the prompt (an expression prints its value). An
/// unfinished statement returns TUI_LUA_MORE and keeps the text.
tui_lua_result tui_lua_eval(tui_lua *t, const char *line);
/// Drop an unfinished statement.
void tui_lua_discard(tui_lua *t);
/// Resume the first job for one step.
tui_lua_result tui_lua_resume(tui_lua *t);
/// The scene the session works on (the last h.scene / h.load), or NULL.
hearth_scene *tui_lua_scene(tui_lua *t);
/// The current scene's clock (hl_scene_clock): *time_scale real seconds a simulated second; 1 = animation units.
int tui_lua_clock(tui_lua *t, double *time_scale);
/// Completions of word (a name, "tbl.na" or "obj:me") from the globals, the
/// hearth module and scene methods: up to max candidates written as full
/// words, sorted, into out (each up to 64 bytes). Returns the count.
int tui_lua_complete(tui_lua *t, const char *word, char out[][64], int max);
#endif

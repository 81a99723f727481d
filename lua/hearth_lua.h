/* hearth_lua.h: the `hearth` Lua module (C side), shared by its files.
 *
 * The binding is thin: one Lua function per core operation, with argument
 * checking and error messages that name the field and its valid range.
 * Sugar (h.params, h.curve tables, presets) lives in lua/hearth/init.lua,
 * embedded in the binary so a scene needs no installed files. */
#ifndef HEARTH_LUA_H
#define HEARTH_LUA_H
#include <lauxlib.h>
#include <lua.h>

#include "hearth/hearth.h"

#define HL_SCENE "hearth.scene"
#define HL_SHAPE "hearth.shape"

/// Options a host (the command line) gives the module before scenes run.
typedef struct hl_options {
    const char *out_dir;    ///< output folder; relative paths in scenes resolve here
    const char *scene_dir;  ///< folder of the scene file (plugins and assets are searched there)
    double until_override;  ///< > 0: s:run stops here whatever the script asks (hearth run --until)
    int frames_override;    ///< > 0: s:run writes this many frames (hearth run --frames)
    int quiet;              ///< no progress bar
    int trusted;            ///< --trust: no sandbox
    const char *const *sets;///< --set k=v strings (NULL-terminated), read by h.params
    const char *assets_dir; ///< where the material tables live (sauces.csv), for h.library
    /// Progress of s:run (sim time t of t_end after `steps` steps; final = last call). May be NULL.
    void (*progress)(void *ud, double t, double t_end, long steps, int final);
    void *progress_ud;
    int yield_steps;        ///< s:run and s:step yield (coroutine.yield) between steps, so a host
                            ///< running them in a coroutine can draw and take input (the dashboard)
} hl_options;

/// Open the module into L: registers package.preload.hearth and sets the options.
void hl_open(lua_State *L, const hl_options *opt);
/// Run a chunk under a traceback handler; on error leaves "file:line: msg\ntraceback" on the stack top.
int hl_pcall(lua_State *L, int nargs, int nres);
/// Push a Lua scene object that owns s (freed by the garbage collector) and
/// make it the module's current scene (h._last_scene), as h.load does.
/// Raises on a NULL scene or when the module cannot load; call it protected.
void hl_push_scene(lua_State *L, hearth_scene *s);
/// The C scene of the module's current scene (the last h.scene / h.load), or NULL.
hearth_scene *hl_current_scene(lua_State *L);
/// Set up the restricted environment for untrusted scenes (see lua_sandbox.c).
void hl_sandbox(lua_State *L, const char *out_dir);

/* internal, between the binding's files */
typedef struct hl_scene {
    hearth_scene *s;
} hl_scene;
hearth_shape *hl_checkshape(lua_State *L, int idx);
hl_scene *hl_checkscene(lua_State *L, int idx);
void hl_pushshape(lua_State *L, hearth_shape *sh); /* takes ownership; raises on NULL */
const hl_options *hl_opts(lua_State *L);
/* a vector of 2 or 3 numbers at idx (z = 0 when absent) */
void hl_checkvec(lua_State *L, int idx, const char *what, double v[3]);
/* resolve a scene path against the output folder (absolute paths stay) into buf */
const char *hl_out_path(lua_State *L, const char *path, char *buf, size_t n);
int hl_raise(lua_State *L, const hearth_error *err);
/* luaL_error with C printf formats (%g and friends, which lua_pushfstring lacks). */
int hl_errorf(lua_State *L, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void hl_open_shapes(lua_State *L);   /* adds shape constructors to the table on top */
void hl_open_scene(lua_State *L);    /* adds h.scene and h.load to the table on top */
void hl_open_output(lua_State *L);   /* scene methods for files, registered into the scene metatable */
void hl_open_material(lua_State *L); /* core.blend */
#endif

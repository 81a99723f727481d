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

/// The Lua memory ceiling when the host gives none (--lua-memory): room for
/// any scene we ship many times over, far below what takes a machine down.
#define HL_LUA_MEMORY_DEFAULT ((size_t)512 << 20)

/// hl_options.progress's `final` at a run's start (s:run's first call, before its steps)
enum { HL_PROGRESS_START = 2 };

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
    /// Progress of s:run (sim time t of t_end after `steps` steps; final: 0 on the way, 1 the run's last call,
    /// HL_PROGRESS_START its first, before any step: a new run, whose rate is its own). May be NULL.
    void (*progress)(void *ud, double t, double t_end, long steps, int final);
    void *progress_ud;
    int yield_steps;        ///< s:run and s:step yield (coroutine.yield) between steps, so a host
                            ///< running them in a coroutine can draw and take input (the dashboard)
    size_t lua_memory;      ///< ceiling of the Lua state's memory in bytes (0 = HL_LUA_MEMORY_DEFAULT)
    /// A host's own stop flag (the dashboard's signal handler), polled with the
    /// module's own by the interrupt hook; NULL for none. Returns a signal number or 0.
    int (*interrupted)(void);
    const char *vtu_dir;    ///< every s:run without its own vtu = {...} writes VTU frames and a .pvd here (hearth run --vtu)
    const char *movie;      ///< every s:run without its own movie = ... encodes its PNG frames into this file (hearth run --movie)
    const char *in_dir;     ///< or NULL: a file to read that is not in out_dir is looked for here (mpirun ranks > 0: rank 0's output folder)
    int list_params;        ///< hearth run --params: h.params prints the scene's parameters and their words, then
                            ///< core.listed() ends the run (HL_ERR_LISTED, exit 0) before anything is simulated
} hl_options;

/// The one constructor of a Lua state that runs scenes (hearth run, repl, the
/// dashboard, the scene fuzz target). It has a counting allocator that refuses
/// past opt->lua_memory, an interrupt hook (see hl_interrupt_install), the
/// standard library (all of it with opt->trusted; without, the allow-list
/// sandbox of lua_sandbox.c, and plugins restricted to names on the search
/// path outside the output folder: hearth_plugin_restrict), and the hearth
/// module (hl_open). Returns NULL with err set when Lua cannot start.
lua_State *hl_new_state(const hl_options *opt, hearth_error *err);
/// Close a state made by hl_new_state and free its allocator record.
void hl_close_state(lua_State *L);

/// SIGINT and SIGTERM stop the running scene: the handler only sets a flag,
/// and the interrupt hook (every few hundred Lua instructions, in every
/// coroutine) raises "interrupted by SIGINT" until the scene has unwound, so a
/// pcall in the scene cannot swallow it. A second signal exits at once with
/// 128 + its number. Work in C (a simulation step, a file write) finishes
/// first, so completed outputs are whole.
void hl_interrupt_install(void);
/// The signal that stopped the scene (SIGINT, SIGTERM), or 0.
int hl_interrupted(void);

/// What an error value left by hl_pcall (or a failed resume) is.
typedef enum hl_error_kind {
    HL_ERR_SCRIPT,    ///< an error in the scene (or a bad call): exit 1
    HL_ERR_GUARD,     ///< the stability guard stopped a run: exit 3
    HL_ERR_USAGE,     ///< a bad --set value (core.usage_error): exit 2
    HL_ERR_MEMORY,    ///< the Lua memory ceiling was reached: exit 1
    HL_ERR_INTERRUPT, ///< SIGINT / SIGTERM (hl_interrupted says which): exit 128 + signal
    HL_ERR_LISTED,    ///< hearth run --params printed the scene's parameters and stopped it (core.listed): exit 0
} hl_error_kind;
/// Classify the error value at idx and push its message (a string, always).
/// Only errors made by the module are guard or usage errors: their marker
/// metatable is hidden from scenes, so error({}) is a script error.
hl_error_kind hl_error_message(lua_State *L, int idx);

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
/// The current scene's clock as its h.scene declared it (time_scale, time_units; run.lua's S:_clock): *time_scale the
/// real seconds one simulated second stands for (1 when it declared none, or for a scene made outside h.scene).
/// Returns 1 when its seconds are Ding et al.'s Table 2 animation units, else 0. Reads raw fields; never raises.
int hl_scene_clock(lua_State *L, double *time_scale);
/// Open the standard library as the allow-list sandbox for untrusted scenes (see lua_sandbox.c).
void hl_open_sandboxed_libs(lua_State *L);

/* internal, between the binding's files */
typedef struct hl_scene {
    hearth_scene *s;
} hl_scene;
hearth_shape *hl_checkshape(lua_State *L, int idx);
hl_scene *hl_checkscene(lua_State *L, int idx);
/* the scene as the steps left it (over MPI ranks, each rank's slab): for stats and the time */
hl_scene *hl_checkscene_slabs(lua_State *L, int idx);
/* the scene's read-only methods (lua_scene_read.c) */
extern const luaL_Reg hl_scene_readers[];
void hl_pushshape(lua_State *L, hearth_shape *sh); /* takes ownership; raises on NULL */
const hl_options *hl_opts(lua_State *L);
/* a vector of 2 or 3 numbers at idx (z = 0 when absent) */
void hl_checkvec(lua_State *L, int idx, const char *what, double v[3]);
/* The one gate for every file a scene writes (frames, VTU, PLY, CSV,
 * checkpoints, h.write, io.open for writing, os.remove / os.rename): joins a
 * relative path to the output folder, resolves the real location of its
 * deepest existing part (symlinks and ..), and without --trust raises an
 * error naming `call`, the path, the output folder and --trust when it lies
 * outside the output folder. flags: HL_PATH_MKDIRS creates the file's missing
 * folders; HL_PATH_AS_IS leaves a relative path relative to the working
 * folder, as Lua's own io and os functions take it. The result is in buf. */
enum { HL_PATH_MKDIRS = 1, HL_PATH_AS_IS = 2 };
const char *hl_out_path(lua_State *L, const char *call, const char *path, int flags, char *buf, size_t n);
/* A path as an error message quotes it: whole up to HL_QUOTE_MAX bytes, else
 * its head and tail around "...", with its length. Pushed on L's stack (it
 * stays until the caller pops it or raises). Every path refusal goes through
 * it: a 100 kB path once came back whole in the message. */
enum { HL_QUOTE_MAX = 160 };
const char *hl_quote_path(lua_State *L, const char *path);
/* a path a scene reads: relative paths resolve under the output folder (absolute ones stay) */
const char *hl_in_path(lua_State *L, const char *path, char *buf, size_t n);
/* Encode PNG frames (in: a printf pattern, frames first .. first+count-1) into
 * the movie out with the ffmpeg program (found on PATH). shown names the movie in messages.
 * 0 written, 1 no ffmpeg (msg: a notice, the frames stay), -1 failed (msg). */
int hl_movie_encode(const char *in, long first, long count, const char *out, double fps, const char *shown, char *msg,
                    size_t n);
/* a marked error object (kind "guard" or "usage") with message msg; see hl_error_message */
int hl_raise_kind(lua_State *L, const char *kind, const char *msg);
int hl_raise(lua_State *L, const hearth_error *err);
/* luaL_error with C printf formats (%g and friends, which lua_pushfstring lacks). */
int hl_errorf(lua_State *L, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
void hl_open_shapes(lua_State *L);   /* adds shape constructors to the table on top */
void hl_open_scene(lua_State *L);    /* adds h.scene and h.load to the table on top */
void hl_open_output(lua_State *L);   /* scene methods for files, registered into the scene metatable */
void hl_open_material(lua_State *L); /* core.blend */
#endif

/* hearth_lua.c: opening the `hearth` module in a Lua state.
 *
 * `require "hearth"` runs the embedded lua/hearth/init.lua with the C core
 * table (hearth.core) as its argument. The options (output folder, --set
 * values, overrides) are kept in the registry for the module's functions. */
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

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

static int traceback(lua_State *L) {
    if (lua_istable(L, 1)) return 1; /* a guard stop: its message is the diagnosis, no traceback */
    const char *msg = lua_tostring(L, 1);
    if (!msg) msg = lua_pushfstring(L, "(error object is a %s value)", luaL_typename(L, 1));
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
    lua_pushboolean(L, o->quiet), lua_setfield(L, -2, "quiet");
    lua_pushboolean(L, o->yield_steps), lua_setfield(L, -2, "yield");
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
    if (o->progress && !o->quiet)
        o->progress(o->progress_ud, luaL_checknumber(L, 1), luaL_checknumber(L, 2), (long)luaL_checkinteger(L, 3),
                    lua_toboolean(L, 4));
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
    if (!opt->trusted) hl_sandbox(L, opt->out_dir);
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

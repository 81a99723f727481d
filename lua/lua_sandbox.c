/* lua_sandbox.c: the restricted environment scenes run in by default.
 *
 * Scenes are shared between people, so a scene from elsewhere must not run
 * programs, load native code or write outside the output folder. Each refused
 * call says which call it was and how to allow it (--trust). Reading files is
 * allowed: scenes load masks and tables. Binary chunks are refused because
 * crafted bytecode can break the VM. */
#define _XOPEN_SOURCE 700 /* realpath */
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hearth_lua.h"

static int refuse(lua_State *L) {
    return luaL_error(L, "%s is not allowed in a scene (run with --trust to allow it)", lua_tostring(L, lua_upvalueindex(1)));
}

static void block(lua_State *L, const char *lib, const char *name) {
    lua_getglobal(L, lib);
    if (!lua_istable(L, -1)) {
        lua_pop(L, 1);
        return;
    }
    lua_pushfstring(L, "%s.%s", lib, name);
    lua_pushcclosure(L, refuse, 1);
    lua_setfield(L, -2, name);
    lua_pop(L, 1);
}

/* Is path inside the output folder? Resolve the parent folder (the file may not exist yet). */
static int under_out(lua_State *L, const char *path) {
    const char *out = lua_tostring(L, lua_upvalueindex(1));
    char want[PATH_MAX], parent[PATH_MAX], real[PATH_MAX];
    if (!out || !realpath(out, want)) return 0;
    snprintf(parent, sizeof parent, "%s", path);
    char *slash = strrchr(parent, '/');
    if (!slash) snprintf(parent, sizeof parent, ".");
    else if (slash == parent) parent[1] = '\0';
    else *slash = '\0';
    if (!realpath(parent, real)) return 0;
    size_t n = strlen(want);
    return strncmp(real, want, n) == 0 && (real[n] == '/' || real[n] == '\0');
}

static int guarded_open(lua_State *L) {
    const char *path = luaL_checkstring(L, 1);
    const char *mode = luaL_optstring(L, 2, "r");
    if (strpbrk(mode, "wa+") && !under_out(L, path))
        return luaL_error(L, "io.open('%s', '%s'): a scene may write only under its output folder %s (run with --trust to allow it)",
                          path, mode, lua_tostring(L, lua_upvalueindex(1)));
    lua_pushvalue(L, lua_upvalueindex(2));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
    return lua_gettop(L);
}

static int guarded_path_op(lua_State *L) { /* os.remove / os.rename: every path argument under the output folder */
    for (int i = 1; i <= lua_gettop(L); i++)
        if (!under_out(L, luaL_checkstring(L, i)))
            return luaL_error(L, "%s('%s'): a scene may change files only under its output folder (run with --trust to allow it)",
                              lua_tostring(L, lua_upvalueindex(3)), lua_tostring(L, i));
    lua_pushvalue(L, lua_upvalueindex(2));
    lua_insert(L, 1);
    lua_call(L, lua_gettop(L) - 1, LUA_MULTRET);
    return lua_gettop(L);
}

static int text_only_load(lua_State *L) { /* load(chunk, name, mode, env) with mode forced to "t" */
    lua_settop(L, 4);
    lua_pushliteral(L, "t");
    lua_replace(L, 3);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, 4, LUA_MULTRET);
    return lua_gettop(L);
}

/* loadfile(name, mode, env) with mode forced to "t" */
static int text_only_loadfile(lua_State *L) {
    lua_settop(L, 3);
    const char *name = luaL_optstring(L, 1, NULL);
    int envi = !lua_isnone(L, 3) && !lua_isnil(L, 3);
    if (luaL_loadfilex(L, name, "t") != LUA_OK) {
        lua_pushnil(L);
        lua_insert(L, -2);
        return 2;
    }
    if (envi) {
        lua_pushvalue(L, 3);
        if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
    }
    return 1;
}

static int text_only_dofile(lua_State *L) {
    const char *name = luaL_optstring(L, 1, NULL);
    lua_settop(L, 1);
    if (luaL_loadfilex(L, name, "t") != LUA_OK) return lua_error(L);
    lua_call(L, 0, LUA_MULTRET);
    return lua_gettop(L) - 1;
}

/* package.searchers[2] for scenes: Lua files on package.path, text only */
static int lua_file_searcher(lua_State *L) {
    const char *name = luaL_checkstring(L, 1);
    lua_getglobal(L, "package");
    lua_getfield(L, -1, "path");
    const char *path = lua_tostring(L, -1);
    const char *file = path ? luaL_gsub(L, name, ".", "/") : NULL;
    if (!file) return 0;
    /* try each template */
    const char *p = path;
    while (*p) {
        const char *e = strchr(p, ';');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        lua_pushlstring(L, p, len);
        const char *cand = luaL_gsub(L, lua_tostring(L, -1), "?", file);
        FILE *f = fopen(cand, "r");
        if (f) {
            fclose(f);
            if (luaL_loadfilex(L, cand, "t") != LUA_OK) return lua_error(L);
            lua_pushstring(L, cand);
            return 2;
        }
        lua_pop(L, 2);
        p += len + (e != NULL);
    }
    lua_pushfstring(L, "no Lua file for '%s' on package.path", name);
    return 1;
}

static int no_c_modules(lua_State *L) {
    lua_pushfstring(L, "C modules are not allowed in a scene: require '%s' cannot load native code (run with --trust to allow it)",
                    luaL_checkstring(L, 1));
    return 1;
}

static void wrap(lua_State *L, const char *lib, const char *name, lua_CFunction fn, const char *out) {
    lua_getglobal(L, lib);
    lua_pushstring(L, out);
    lua_getfield(L, -2, name);
    lua_pushfstring(L, "%s.%s", lib, name);
    lua_pushcclosure(L, fn, 3);
    lua_setfield(L, -2, name);
    lua_pop(L, 1);
}

void hl_sandbox(lua_State *L, const char *out_dir) {
    block(L, "os", "execute");
    block(L, "os", "exit");
    block(L, "os", "tmpname");
    block(L, "io", "popen");
    block(L, "io", "output"); /* would redirect writes to any file */
    block(L, "package", "loadlib");
    wrap(L, "io", "open", guarded_open, out_dir);
    wrap(L, "os", "remove", guarded_path_op, out_dir);
    wrap(L, "os", "rename", guarded_path_op, out_dir);
    /* require: Lua modules only (no C searchers) */
    lua_getglobal(L, "package");
    lua_pushliteral(L, "");
    lua_setfield(L, -2, "cpath");
    lua_getfield(L, -1, "searchers");
    lua_pushnil(L);
    lua_seti(L, -2, 4);
    lua_pushcfunction(L, no_c_modules);
    lua_seti(L, -2, 3);
    lua_pushcfunction(L, lua_file_searcher);
    lua_seti(L, -2, 2);
    lua_pop(L, 2);
    lua_getglobal(L, "load");
    lua_pushcclosure(L, text_only_load, 1);
    lua_setglobal(L, "load");
    lua_pushcfunction(L, text_only_loadfile);
    lua_setglobal(L, "loadfile");
    lua_pushcfunction(L, text_only_dofile);
    lua_setglobal(L, "dofile");
    lua_pushnil(L); /* debug can reach into anything (registry, metatables of userdata) */
    lua_setglobal(L, "debug");
}

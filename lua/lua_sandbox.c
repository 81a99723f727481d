/* lua_sandbox.c: the environment scenes run in without --trust.
 *
 * Scenes are shared between people, so a scene from elsewhere must not run
 * programs, load native code or write outside its output folder. The
 * environment is built from an allow-list, not by deleting dangerous entries
 * from the full library: a deny-list misses what it did not think of (the
 * debug library left in package.loaded, string.dump through the string
 * metatable). So the untrusted state never opens debug; the io and os a scene
 * sees (as globals and in package.loaded) are fresh tables holding only
 * functions vetted here; load, loadfile, dofile and require take text chunks
 * only, since crafted bytecode can break the VM; string.dump is gone.
 *
 * Every write goes through hl_out_path (lua_output.c), the one gate. Reading
 * stays allowed anywhere: scenes load masks, tables and checkpoints. Each
 * refused call names itself and --trust. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <lualib.h>

#include "hearth_lua.h"

/* a refusing stand-in for a function the sandbox leaves out, so a scene
 * calling it learns why instead of "attempt to call a nil value" */
static int refuse(lua_State *L) {
    return luaL_error(L, "%s is not allowed in a scene (run with --trust to allow it)", lua_tostring(L, lua_upvalueindex(1)));
}

static void set_refusal(lua_State *L, int t, const char *lib, const char *name) {
    t = lua_absindex(L, t);
    lua_pushfstring(L, "%s.%s", lib, name);
    lua_pushcclosure(L, refuse, 1);
    lua_setfield(L, t, name);
}

/* copy field name from table `from` to table `to` (both absolute indices) */
static void copy_field(lua_State *L, int from, int to, const char *name) {
    lua_getfield(L, from, name);
    lua_setfield(L, to, name);
}

/* io.open(path, mode): reading anywhere; any writing mode through the gate */
static int safe_open(lua_State *L) {
    const char *path = luaL_checkstring(L, 1);
    const char *mode = luaL_optstring(L, 2, "r");
    const int base = lua_gettop(L);
    char buf[4096];
    if (strpbrk(mode, "wa+")) {
        const char *qp = hl_quote_path(L, path), *qm = hl_quote_path(L, mode);
        lua_pushfstring(L, "io.open('%s', '%s')", qp, qm); /* the call as messages name it */
        lua_replace(L, -3);
        lua_pop(L, 1);
        path = hl_out_path(L, lua_tostring(L, -1), path, HL_PATH_AS_IS, buf, sizeof buf);
        lua_pop(L, 1);
    }
    lua_pushvalue(L, lua_upvalueindex(1)); /* the real io.open, reachable only from here */
    lua_pushstring(L, path);
    lua_pushstring(L, mode);
    lua_call(L, 2, LUA_MULTRET);
    return lua_gettop(L) - base;
}

/* io.lines(path, ...): reading only; with no path it reads standard input */
static int safe_lines(lua_State *L) {
    int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
}

/* os.remove / os.rename: every path through the gate (no folders made) */
static int safe_path_op(lua_State *L) {
    const char *call = lua_tostring(L, lua_upvalueindex(2));
    int n = lua_gettop(L);
    for (int i = 1; i <= n; i++) {
        char buf[4096];
        const char *path = luaL_checkstring(L, i);
        lua_pushfstring(L, "%s('%s')", call, hl_quote_path(L, path));
        lua_remove(L, -2);
        lua_pushstring(L, hl_out_path(L, lua_tostring(L, -1), path, HL_PATH_AS_IS, buf, sizeof buf));
        lua_replace(L, i);
        lua_pop(L, 1);
    }
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
}

/* load(chunk, name, mode, env) with mode forced to "t" */
static int text_only_load(lua_State *L) {
    const int has_env = !lua_isnone(L, 4); /* an absent env (not nil) keeps the globals */
    lua_settop(L, has_env ? 4 : 3);
    lua_pushliteral(L, "t");
    lua_replace(L, 3);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, has_env ? 4 : 3, LUA_MULTRET);
    return lua_gettop(L);
}

/* loadfile(name, mode, env) with mode forced to "t" */
static int text_only_loadfile(lua_State *L) {
    const char *name = luaL_optstring(L, 1, NULL);
    int has_env = !lua_isnone(L, 3);
    if (luaL_loadfilex(L, name, "t") != LUA_OK) {
        luaL_pushfail(L);
        lua_insert(L, -2);
        return 2;
    }
    if (has_env) {
        lua_pushvalue(L, 3);
        if (!lua_setupvalue(L, -2, 1)) lua_pop(L, 1);
    }
    return 1;
}

static int dofile_cont(lua_State *L, int status, lua_KContext k) {
    (void)status, (void)k;
    return lua_gettop(L) - 1;
}

static int text_only_dofile(lua_State *L) {
    const char *name = luaL_optstring(L, 1, NULL);
    lua_settop(L, 1);
    if (luaL_loadfilex(L, name, "t") != LUA_OK) {
        /* A relative path is the current folder's, not the scene's: say which folder was searched, so a script
         * that runs a shipped scene by its path from the source root (scripts/validation/loaf_whatif.lua) says why
         * it fails elsewhere (#18, helper userview4: "cannot open scripts/scenes/...: No such file" alone) */
        char cwd[4096];
        if (name && name[0] != '/' && access(name, F_OK) != 0 && getcwd(cwd, sizeof cwd))
            lua_pushfstring(L, "%s (a relative path is read from the folder hearth runs in, %s: run from the "
                               "folder it is relative to, or give its path)", lua_tostring(L, -1), cwd),
                lua_error(L);
        return lua_error(L);
    }
    lua_callk(L, 0, LUA_MULTRET, 0, dofile_cont);
    return dofile_cont(L, 0, 0);
}

/* package.searchers[2] for scenes: Lua files on package.path, text only */
static int lua_file_searcher(lua_State *L) {
    const char *name = luaL_checkstring(L, 1);
    lua_getfield(L, lua_upvalueindex(1), "path");
    const char *path = lua_tostring(L, -1);
    if (!path) return 0;
    const char *file = luaL_gsub(L, name, ".", "/");
    for (const char *p = path; *p;) {
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
        if (!e) break;
        p = e + 1;
    }
    lua_pushfstring(L, "no Lua file for '%s' on package.path", name);
    return 1;
}

static int no_c_modules(lua_State *L) {
    lua_pushfstring(L, "C modules are not allowed in a scene: require '%s' cannot load native code (run with --trust to allow it)",
                    luaL_checkstring(L, 1));
    return 1;
}

/* collectgarbage: the queries and a full or partial collection; a scene may
 * not stop the collector or retune it (it could only make the ceiling come sooner) */
static int safe_collectgarbage(lua_State *L) {
    static const char *const ok[] = {"collect", "count", "step", "isrunning", NULL};
    luaL_checkoption(L, 1, "collect", ok);
    int n = lua_gettop(L);
    lua_pushvalue(L, lua_upvalueindex(1));
    lua_insert(L, 1);
    lua_call(L, n, LUA_MULTRET);
    return lua_gettop(L);
}

/* replace global `name` with a C closure over its current value */
static void wrap_global(lua_State *L, const char *name, lua_CFunction fn) {
    lua_getglobal(L, name);
    lua_pushcclosure(L, fn, 1);
    lua_setglobal(L, name);
}

void hl_open_sandboxed_libs(lua_State *L) {
    /* the libraries that reach nothing outside the state */
    static const luaL_Reg safe[] = {{LUA_GNAME, luaopen_base},          {LUA_LOADLIBNAME, luaopen_package},
                                    {LUA_COLIBNAME, luaopen_coroutine}, {LUA_TABLIBNAME, luaopen_table},
                                    {LUA_STRLIBNAME, luaopen_string},   {LUA_MATHLIBNAME, luaopen_math},
                                    {LUA_UTF8LIBNAME, luaopen_utf8},    {NULL, NULL}};
    for (const luaL_Reg *l = safe; l->name; l++) {
        luaL_requiref(L, l->name, l->func, 1);
        lua_pop(L, 1);
    }
    lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    const int loaded = lua_gettop(L);

    /* io: a fresh table of vetted functions; the real table is dropped */
    luaL_requiref(L, LUA_IOLIBNAME, luaopen_io, 0);
    const int rio = lua_gettop(L);
    lua_createtable(L, 0, 12);
    const int io = lua_gettop(L);
    lua_getfield(L, rio, "open");
    lua_pushcclosure(L, safe_open, 1);
    lua_setfield(L, io, "open");
    lua_getfield(L, rio, "lines");
    lua_pushcclosure(L, safe_lines, 1);
    lua_setfield(L, io, "lines");
    for (const char *const *f = (const char *const[]){"read", "write", "type", "stdout", "stderr", "stdin", NULL}; *f; f++)
        copy_field(L, rio, io, *f);
    for (const char *const *f = (const char *const[]){"popen", "output", "input", "close", "tmpfile", NULL}; *f; f++)
        set_refusal(L, io, "io", *f);
    lua_pushvalue(L, io);
    lua_setfield(L, loaded, LUA_IOLIBNAME);
    lua_setglobal(L, LUA_IOLIBNAME);
    lua_pop(L, 1);

    /* os: time and environment queries; files only through the gate */
    luaL_requiref(L, LUA_OSLIBNAME, luaopen_os, 0);
    const int ros = lua_gettop(L);
    lua_createtable(L, 0, 12);
    const int os = lua_gettop(L);
    for (const char *const *f = (const char *const[]){"clock", "date", "time", "difftime", "getenv", NULL}; *f; f++)
        copy_field(L, ros, os, *f);
    for (const char *const *f = (const char *const[]){"remove", "rename", NULL}; *f; f++) {
        lua_getfield(L, ros, *f);
        lua_pushfstring(L, "os.%s", *f);
        lua_pushcclosure(L, safe_path_op, 2);
        lua_setfield(L, os, *f);
    }
    for (const char *const *f = (const char *const[]){"execute", "exit", "tmpname", "setlocale", NULL}; *f; f++)
        set_refusal(L, os, "os", *f);
    lua_pushvalue(L, os);
    lua_setfield(L, loaded, LUA_OSLIBNAME);
    lua_setglobal(L, LUA_OSLIBNAME);
    lua_pop(L, 1);

    /* string.dump would hand out bytecode; the string metatable's __index is this same table */
    lua_getglobal(L, LUA_STRLIBNAME);
    set_refusal(L, -1, "string", "dump");
    lua_pop(L, 1);

    /* package: Lua files only, text only; no native code */
    lua_getglobal(L, LUA_LOADLIBNAME);
    const int pkg = lua_gettop(L);
    set_refusal(L, pkg, "package", "loadlib");
    lua_pushliteral(L, "");
    lua_setfield(L, pkg, "cpath");
    lua_getfield(L, pkg, "searchers");
    lua_createtable(L, 3, 0);
    lua_geti(L, -2, 1); /* the preload searcher: the embedded hearth modules */
    lua_seti(L, -2, 1);
    lua_pushvalue(L, pkg);
    lua_pushcclosure(L, lua_file_searcher, 1);
    lua_seti(L, -2, 2);
    lua_pushcfunction(L, no_c_modules);
    lua_seti(L, -2, 3);
    lua_setfield(L, pkg, "searchers");
    lua_pop(L, 2);

    wrap_global(L, "load", text_only_load);
    lua_pushcfunction(L, text_only_loadfile);
    lua_setglobal(L, "loadfile");
    lua_pushcfunction(L, text_only_dofile);
    lua_setglobal(L, "dofile");
    wrap_global(L, "collectgarbage", safe_collectgarbage);
    lua_pop(L, 1); /* package.loaded */
}

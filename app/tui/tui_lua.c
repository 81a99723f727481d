/* tui_lua.c: the dashboard's Lua session: jobs as coroutines, prompt lines,
 * print to the log, completion. */
#include "tui_lua.h"

#include <lauxlib.h>
#include <lualib.h>
#include <stdio.h>
#include <string.h>

#include "tui_screen.h"

static const char LOG_KEY = 'l';

/* print(...) -> the log panel, tab separated as the standard print */
static int l_print(lua_State *L) {
    lua_rawgetp(L, LUA_REGISTRYINDEX, &LOG_KEY);
    tui_log *log = lua_touserdata(L, -1);
    lua_pop(L, 1);
    int n = lua_gettop(L); /* before luaL_buffinit, which may push a placeholder */
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    for (int i = 1; i <= n; i++) {
        luaL_tolstring(L, i, NULL);
        luaL_addvalue(&b);
        if (i < n) luaL_addchar(&b, '\t');
    }
    luaL_pushresult(&b);
    if (log) tui_log_add(log, "%s", lua_tostring(L, -1));
    return 0;
}

int tui_lua_open(tui_lua *t, const hl_options *o, tui_log *log) {
    memset(t, 0, sizeof *t);
    t->log = log;
    hl_options lo = *o;
    /* Ctrl-C is the dashboard's signal; the hook also stops a runaway prompt command with it */
    if (!lo.interrupted) lo.interrupted = tui_screen_interrupted;
    hearth_error err;
    t->L = hl_new_state(&lo, &err);
    if (!t->L) {
        tui_log_add(log, "%s", err.msg);
        return -1;
    }
    lua_pushlightuserdata(t->L, log);
    lua_rawsetp(t->L, LUA_REGISTRYINDEX, &LOG_KEY);
    lua_pushcfunction(t->L, l_print);
    lua_setglobal(t->L, "print");
    return 0;
}

void tui_lua_close(tui_lua *t) {
    if (t->L) hl_close_state(t->L);
    t->L = NULL;
}

/* log an error value left on top of L (a message or a guard table) and pop it */
static tui_lua_result log_error(tui_lua *t, lua_State *L) {
    if (hl_error_message(L, -1) == HL_ERR_GUARD) {
        tui_log_add(t->log, "the stability guard stopped the run (paused):\n  %s", lua_tostring(L, -1));
        lua_pop(L, 2);
        return TUI_LUA_GUARD;
    }
    tui_log_add(t->log, "error: %s", lua_tostring(L, -1));
    lua_pop(L, 2);
    return TUI_LUA_ERROR;
}

/* the function on top of t->L becomes a job at the end of the queue */
static int add_job(tui_lua *t, const char *name) {
    lua_State *L = t->L;
    if (t->njobs == TUI_MAX_JOBS) {
        lua_pop(L, 1);
        tui_log_add(t->log, "error: %d runs are already waiting; let them finish first", TUI_MAX_JOBS);
        return -1;
    }
    lua_State *co = lua_newthread(L);
    lua_pushvalue(L, -2);
    lua_xmove(L, co, 1);
    t->job_ref[t->njobs] = luaL_ref(L, LUA_REGISTRYINDEX);
    snprintf(t->job_name[t->njobs], sizeof t->job_name[0], "%s", name);
    t->njobs++;
    lua_pop(L, 1);
    return t->njobs - 1;
}

static void drop_job(tui_lua *t, int k) {
    luaL_unref(t->L, LUA_REGISTRYINDEX, t->job_ref[k]);
    memmove(t->job_ref + k, t->job_ref + k + 1, sizeof t->job_ref[0] * (size_t)(t->njobs - k - 1));
    memmove(t->job_name + k, t->job_name + k + 1, sizeof t->job_name[0] * (size_t)(t->njobs - k - 1));
    t->njobs--;
}

/* resume job k once; prints a prompt command's results when it finishes */
static tui_lua_result resume_job(tui_lua *t, int k, int print_results) {
    lua_State *L = t->L;
    lua_rawgeti(L, LUA_REGISTRYINDEX, t->job_ref[k]);
    lua_State *co = lua_tothread(L, -1);
    lua_pop(L, 1);
    int nres = 0;
    int st = lua_resume(co, L, 0, &nres);
    if (st == LUA_YIELD) {
        lua_pop(co, nres);
        return TUI_LUA_WAITING;
    }
    tui_lua_result r = TUI_LUA_DONE;
    if (st == LUA_OK) {
        if (print_results && nres > 0) {
            luaL_Buffer b;
            luaL_buffinit(L, &b);
            for (int i = 1; i <= nres; i++) {
                luaL_tolstring(co, i, NULL);
                lua_xmove(co, L, 1);
                luaL_addvalue(&b);
                if (i < nres) luaL_addchar(&b, '\t');
            }
            luaL_pushresult(&b);
            tui_log_add(t->log, "%s", lua_tostring(L, -1));
            lua_pop(L, 1);
        }
        lua_settop(co, 0);
    } else {
        lua_xmove(co, L, 1);
        r = log_error(t, L);
    }
    drop_job(t, k);
    return r;
}

int tui_lua_start_file(tui_lua *t, const char *path) {
    if (luaL_loadfilex(t->L, path, "t") != LUA_OK) {
        log_error(t, t->L);
        return -1;
    }
    const char *base = strrchr(path, '/');
    return add_job(t, base ? base + 1 : path) < 0 ? -1 : 0;
}

static int adopt(lua_State *L) {
    hl_push_scene(L, lua_touserdata(L, 1));
    return 1;
}

int tui_lua_adopt(tui_lua *t, hearth_scene *s) {
    lua_pushcfunction(t->L, adopt);
    lua_pushlightuserdata(t->L, s);
    if (lua_pcall(t->L, 1, 1, 0) != LUA_OK) {
        /* not destroyed here: once its Lua object exists the collector owns the scene */
        log_error(t, t->L);
        return -1;
    }
    lua_setglobal(t->L, "s");
    tui_lua_globals(t);
    return 0;
}

void tui_lua_globals(tui_lua *t) {
    lua_State *L = t->L;
    lua_getfield(L, LUA_REGISTRYINDEX, LUA_LOADED_TABLE);
    lua_getfield(L, -1, "hearth");
    if (!lua_istable(L, -1)) { /* the scene never required it: load it now */
        lua_pop(L, 1);
        lua_getglobal(L, "require");
        lua_pushliteral(L, "hearth");
        if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
            log_error(t, L);
            lua_pop(L, 1);
            return;
        }
    }
    if (lua_getglobal(L, "h") == LUA_TNIL) lua_pushvalue(L, -2), lua_setglobal(L, "h");
    lua_pop(L, 1);
    lua_getfield(L, -1, "_last_scene");
    if (!lua_isnil(L, -1) && lua_getglobal(L, "s") == LUA_TNIL) lua_pushvalue(L, -2), lua_setglobal(L, "s");
    lua_settop(L, 0);
}

static int incomplete(lua_State *L, int status) {
    if (status != LUA_ERRSYNTAX) return 0;
    size_t n;
    const char *msg = lua_tolstring(L, -1, &n);
    return n >= 5 && !strcmp(msg + n - 5, "<eof>");
}

void tui_lua_discard(tui_lua *t) { t->plen = 0; }

tui_lua_result tui_lua_eval(tui_lua *t, const char *line) {
    lua_State *L = t->L;
    size_t n = strlen(line);
    if (t->plen + n + 2 > sizeof t->pending) {
        t->plen = 0;
        tui_log_add(t->log, "error: the statement is longer than %zu bytes; dropped", sizeof t->pending);
        return TUI_LUA_ERROR;
    }
    if (t->plen) t->pending[t->plen++] = '\n';
    memcpy(t->pending + t->plen, line, n + 1);
    t->plen += n;
    /* an expression prints its value; otherwise a statement (as the Lua REPL) */
    lua_pushfstring(L, "return %s", t->pending);
    int st = luaL_loadbufferx(L, lua_tostring(L, -1), lua_rawlen(L, -1), "=prompt", "t");
    lua_remove(L, -2);
    if (st != LUA_OK) {
        lua_pop(L, 1);
        st = luaL_loadbufferx(L, t->pending, t->plen, "=prompt", "t");
    }
    if (incomplete(L, st)) {
        lua_pop(L, 1);
        return TUI_LUA_MORE;
    }
    t->plen = 0;
    if (st != LUA_OK) return log_error(t, L);
    /* run it now: it either finishes or, having started a run, waits as a job */
    int k = add_job(t, "prompt");
    if (k < 0) return TUI_LUA_ERROR;
    if (k > 0) { /* another run is going: a command that does not step still runs at once */
        tui_lua_result r = resume_job(t, k, 1);
        if (r == TUI_LUA_WAITING)
            tui_log_add(t->log, "(this run waits for the one in progress: %s)", t->job_name[0]);
        return r;
    }
    return resume_job(t, k, 1);
}

tui_lua_result tui_lua_resume(tui_lua *t) {
    if (t->njobs == 0) return TUI_LUA_IDLE;
    return resume_job(t, 0, 1);
}

hearth_scene *tui_lua_scene(tui_lua *t) { return hl_current_scene(t->L); }
int tui_lua_clock(tui_lua *t, double *time_scale) {
    if (!t->L) return *time_scale = 1, 0;
    return hl_scene_clock(t->L, time_scale);
}

/* Completion in Lua: the candidates for a word, sorted. */
static const char complete_src[] =
    "local word = ...\n"
    "local base, sep, part = word:match('^(.-)([.:])([%w_]*)$')\n"
    "local t = _G\n"
    "if base then\n"
    "  for name in base:gmatch('[^.:]+') do\n"
    "    if type(t) ~= 'table' then return {} end\n"
    "    t = rawget(t, name) or t[name]\n"
    "  end\n"
    "  if type(t) ~= 'table' or sep == ':' then\n"
    "    local mt = getmetatable(t)\n"
    "    t = type(mt) == 'table' and mt.__index or nil\n"
    "    if type(t) ~= 'table' then return {} end\n"
    "  end\n"
    "else part, base, sep = word, '', '' end\n"
    "local out, seen = {}, {}\n"
    "local function scan(tbl)\n"
    "  for k, v in pairs(tbl) do\n"
    "    if type(k) == 'string' and k:sub(1, #part) == part and k:match('^[%a_][%w_]*$') and not seen[k]\n"
    "       and (k:sub(1, 1) ~= '_' or part:sub(1, 1) == '_') and (sep ~= ':' or type(v) == 'function') then\n"
    "      seen[k] = true; out[#out + 1] = base .. sep .. k\n"
    "    end\n"
    "  end\n"
    "end\n"
    "scan(t)\n"
    "if base == '' then\n"
    "  local h = package.loaded.hearth\n"
    "  for _, kw in ipairs { 'and', 'break', 'do', 'else', 'elseif', 'end', 'false', 'for', 'function', 'if', 'in',\n"
    "      'local', 'nil', 'not', 'or', 'repeat', 'return', 'then', 'true', 'until', 'while' } do\n"
    "    if kw:sub(1, #part) == part and not seen[kw] then seen[kw] = true; out[#out + 1] = kw end\n"
    "  end\n"
    "end\n"
    "table.sort(out)\n"
    "return out\n";

int tui_lua_complete(tui_lua *t, const char *word, char out[][64], int max) {
    lua_State *L = t->L;
    int top = lua_gettop(L);
    if (luaL_loadbufferx(L, complete_src, sizeof complete_src - 1, "=complete", "t") != LUA_OK) {
        lua_settop(L, top);
        return 0;
    }
    lua_pushstring(L, word);
    int n = 0;
    if (lua_pcall(L, 1, 1, 0) == LUA_OK && lua_istable(L, -1)) {
        lua_Integer len = luaL_len(L, -1);
        for (lua_Integer i = 1; i <= len && n < max; i++) {
            lua_geti(L, -1, i);
            snprintf(out[n++], 64, "%s", lua_tostring(L, -1));
            lua_pop(L, 1);
        }
    }
    lua_settop(L, top);
    return n;
}

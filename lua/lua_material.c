/* lua_material.c: material operations that need a plugin but no scene:
 * blending parameter sets through the plugin's own blend callback. */
#include <math.h>
#include <string.h>

#include "hearth_lua.h"

/* core.blend(plugin, {params1, params2, ...}, {w1, w2, ...} [, mode]) -> params table.
 * Each params table maps names to numbers; missing names take the defaults.
 * mode "nonlinear" (the default) is the plugin's own blend callback (for
 * sauces Nagasawa et al. eq. 28-31); "linear" is the weighted arithmetic mean
 * of every parameter, the naive blend the paper compares against (Fig. 1b).
 * A mean of values inside a range stays inside it. */
static int l_blend(lua_State *L) {
    const char *plugin = luaL_checkstring(L, 1);
    luaL_checktype(L, 2, LUA_TTABLE);
    luaL_checktype(L, 3, LUA_TTABLE);
    hearth_error err;
    const hearth_plugin *pl = hearth_plugin_load(plugin, &err);
    if (!pl) return hl_raise(L, &err);
    const hearth_material *m = hearth_plugin_material(pl);
    static const char *const modes[] = {"nonlinear", "linear", NULL};
    const int linear = luaL_checkoption(L, 4, "nonlinear", modes) == 1;
    if (!linear && !m->blend) return luaL_error(L, "h.mix: plugin '%s' has no blend callback; it cannot mix", plugin);
    const int k = (int)luaL_len(L, 2), np = m->nparams;
    if (k < 1 || k > 8 || luaL_len(L, 3) != k) return luaL_error(L, "h.mix: 1 to 8 constituents with one weight each");
    if (np > 256) return luaL_error(L, "h.mix: plugin '%s' has too many parameters", plugin);
    double *buf = lua_newuserdatauv(L, sizeof(double) * (size_t)np * (size_t)(k + 1), 0); /* freed by the GC */
    const double *pk[8];
    double alpha[8], sum = 0;
    for (int c = 0; c < k; c++) {
        double *p = buf + (size_t)c * np;
        for (int i = 0; i < np; i++) p[i] = m->params[i].def;
        lua_geti(L, 2, c + 1);
        for (int i = 0; i < np; i++) {
            if (lua_getfield(L, -1, m->params[i].name) == LUA_TNUMBER) p[i] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
        pk[c] = p;
        lua_geti(L, 3, c + 1);
        alpha[c] = lua_tonumber(L, -1);
        lua_pop(L, 1);
        if (!(alpha[c] >= 0)) return hl_errorf(L, "h.mix: weight %d = %g; weights must be >= 0", c + 1, alpha[c]);
        sum += alpha[c];
    }
    if (!(sum > 0)) return luaL_error(L, "h.mix: the weights sum to zero");
    for (int c = 0; c < k; c++) alpha[c] /= sum; /* ratios need not be given normalised */
    double *out = buf + (size_t)k * np;
    int code = 0;
    if (linear)
        for (int i = 0; i < np; i++) {
            out[i] = 0;
            for (int c = 0; c < k; c++) out[i] += alpha[c] * pk[c][i];
            out[i] = fmin(fmax(out[i], m->params[i].min), m->params[i].max); /* rounding only */
        }
    else {
        hearth_plugin_call_enter(m, "blend"); /* a crash in it names the plugin (app/crash.c) */
        code = m->blend(k, alpha, pk, out);
        hearth_plugin_call_leave();
    }
    if (code) return luaL_error(L, "h.mix: plugin '%s' could not blend: %s", plugin, m->describe_error(code));
    lua_createtable(L, 0, np);
    for (int i = 0; i < np; i++) {
        lua_pushnumber(L, out[i]);
        lua_setfield(L, -2, m->params[i].name);
    }
    return 1;
}

void hl_open_material(lua_State *L) {
    lua_pushcfunction(L, l_blend);
    lua_setfield(L, -2, "blend");
}

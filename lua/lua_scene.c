/* lua_scene.c: the scene userdata: creating, building, stepping and editing
 * it. Each method is one core operation; the Lua side (lua/hearth/init.lua)
 * validates tables and adds events, runs and frames on top. The methods that
 * only read the scene (probes, stats, particles) are in lua_scene_read.c. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hearth_lua.h"

/* the scene as the steps left it: over MPI ranks, each rank's slab only */
hl_scene *hl_checkscene_slabs(lua_State *L, int idx) {
    hl_scene *u = luaL_checkudata(L, idx, HL_SCENE);
    if (!u->s) luaL_argerror(L, idx, "scene was released");
    return u;
}

/* every particle: a method that reads or edits them needs the whole scene */
hl_scene *hl_checkscene(lua_State *L, int idx) {
    hl_scene *u = hl_checkscene_slabs(L, idx);
    hearth_error err;
    if (hearth_scene_whole(u->s, &err)) hl_raise(L, &err);
    return u;
}

int hl_raise(lua_State *L, const hearth_error *err) {
    /* a marked object, so `hearth run` can tell a guard stop (exit 3) from a script error */
    if (err->code == HEARTH_ERR_GUARD) return hl_raise_kind(L, "guard", err->msg);
    /* luaL_error's position is the caller's line: the scene's when scene code
     * calls the core directly, but a line of hearth's own Lua modules when a
     * wrapper does, and the wrapper re-raises at the scene's line anyway
     * (error(msg, 2)); so an internal position is left out */
    luaL_where(L, 1);
    const char *where = lua_tostring(L, -1);
    if (!strncmp(where, "[hearth]/", 9)) lua_pushstring(L, err->msg);
    else lua_pushfstring(L, "%s%s", where, err->msg);
    return lua_error(L);
}

/* core.scene_settings() -> the schema (hearth_scene_settings) as a list of
 * {name, kind, unit, help, default, min, max, min_open, nan_ok, words, vec_default,
 * lua_only, knob}: init.lua's h.scene checks, defaults and suggestions, and --set's
 * knobs, read it here rather than keep a copy. */
static int l_scene_settings(lua_State *L) {
    static const char *const kinds[] = {"real", "int", "seed", "flag", "choice", "vector", "box", "text"};
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    lua_createtable(L, n, 0);
    for (int k = 0; k < n; k++) {
        const hearth_setting *e = &set[k];
        lua_createtable(L, 0, 13);
        lua_pushstring(L, e->name), lua_setfield(L, -2, "name");
        lua_pushstring(L, kinds[e->kind]), lua_setfield(L, -2, "kind");
        lua_pushstring(L, e->unit), lua_setfield(L, -2, "unit");
        lua_pushstring(L, e->help), lua_setfield(L, -2, "help");
        if (!isnan(e->def)) {
            if (e->kind == HEARTH_SETTING_FLAG) lua_pushboolean(L, e->def != 0);
            else if (e->kind == HEARTH_SETTING_CHOICE) lua_pushstring(L, e->words[(int)e->def]);
            else if (e->kind == HEARTH_SETTING_REAL) lua_pushnumber(L, e->def);
            else lua_pushinteger(L, (lua_Integer)e->def);
            lua_setfield(L, -2, "default");
        }
        lua_pushnumber(L, e->min), lua_setfield(L, -2, "min");
        lua_pushnumber(L, e->max), lua_setfield(L, -2, "max");
        lua_pushboolean(L, e->min_open), lua_setfield(L, -2, "min_open");
        lua_pushboolean(L, e->nan_ok), lua_setfield(L, -2, "nan_ok");
        lua_pushboolean(L, e->offset < 0), lua_setfield(L, -2, "lua_only");
        lua_pushboolean(L, e->knob), lua_setfield(L, -2, "knob");
        if (e->words) {
            lua_newtable(L);
            for (int w = 0; e->words[w]; w++) lua_pushstring(L, e->words[w]), lua_seti(L, -2, w + 1);
            lua_setfield(L, -2, "words");
        }
        if (e->vec_def) {
            const int nv = e->kind == HEARTH_SETTING_BOX ? 2 : 1;
            lua_createtable(L, nv, 0);
            for (int v = 0; v < nv; v++) {
                lua_createtable(L, 3, 0);
                for (int c = 0; c < 3; c++) lua_pushnumber(L, e->vec_def[3 * v + c]), lua_seti(L, -2, c + 1);
                lua_seti(L, -2, v + 1);
            }
            if (nv == 1) lua_geti(L, -1, 1), lua_remove(L, -2); /* a vector is {x, y, z}, a box {{lo}, {hi}} */
            lua_setfield(L, -2, "vec_default");
        }
        lua_seti(L, -2, k + 1);
    }
    return 1;
}

static void field_vec(lua_State *L, int t, const char *k, double v[3]) {
    lua_getfield(L, t, k);
    hl_checkvec(L, lua_gettop(L), k, v);
    lua_pop(L, 1);
}

/* core.scene_new{[name] = value, ...}: keys are hearth_scene_settings() names
 * ("dx", "oven.beta", "sph.h_factor"), already checked by init.lua's h.scene;
 * a word is given as its index, a flag as a boolean, the box as {lo, hi}.
 * Missing keys keep the schema's defaults; the core checks every range again. */
static int l_scene_new(lua_State *L) {
    luaL_checktype(L, 1, LUA_TTABLE);
    hearth_scene_def d = hearth_default_scene_def();
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    for (int k = 0; k < n; k++) {
        const hearth_setting *e = &set[k];
        if (e->offset < 0) continue;
        char *f = (char *)&d + e->offset;
        const int ty = lua_getfield(L, 1, e->name), top = lua_gettop(L);
        if (ty != LUA_TNIL) switch (e->kind) {
            case HEARTH_SETTING_REAL: *(double *)f = luaL_checknumber(L, top); break;
            case HEARTH_SETTING_INT:
            case HEARTH_SETTING_CHOICE: *(int *)f = (int)luaL_checknumber(L, top); break;
            case HEARTH_SETTING_SEED: *(uint64_t *)f = (uint64_t)luaL_checknumber(L, top); break;
            case HEARTH_SETTING_FLAG: *(int *)f = lua_toboolean(L, top); break;
            case HEARTH_SETTING_VECTOR: hl_checkvec(L, top, e->name, (double *)f); break;
            case HEARTH_SETTING_BOX:
                field_vec(L, top, "lo", (double *)f);
                field_vec(L, top, "hi", (double *)((char *)&d + e->offset2));
                break;
            case HEARTH_SETTING_TEXT: break;
            }
        lua_pop(L, 1);
    }
    hl_scene *u = lua_newuserdatauv(L, sizeof *u, 1);
    u->s = NULL;
    luaL_setmetatable(L, HL_SCENE);
    lua_newtable(L); /* per-scene Lua state: materials, colliders' motion, events */
    lua_setiuservalue(L, -2, 1);
    hearth_error err;
    u->s = hearth_scene_create(&d, &err);
    if (u->s) hearth_scene_keep_slabs(u->s, 1); /* every scene method but the stepping ones calls hearth_scene_whole (hl_checkscene) */
    if (!u->s) return hl_raise(L, &err);
    return 1;
}

static int l_gc(lua_State *L) {
    hl_scene *u = luaL_checkudata(L, 1, HL_SCENE);
    hearth_scene_destroy(u->s);
    u->s = NULL;
    return 0;
}

/* s:_state() -> the per-scene Lua table */
static int l_state(lua_State *L) {
    hl_checkscene_slabs(L, 1);
    lua_getiuservalue(L, 1, 1);
    return 1;
}

/* s:_material(plugin, {name = number, ...}) -> id */
static int l_material(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const char *plugin = luaL_checkstring(L, 2);
    luaL_checktype(L, 3, LUA_TTABLE);
    const char *names[256];
    double vals[256];
    int n = 0;
    lua_pushnil(L);
    while (lua_next(L, 3) && n < 256) {
        names[n] = lua_tostring(L, -2);
        vals[n++] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
    hearth_error err;
    int id = hearth_scene_add_material(u->s, plugin, names, vals, n, &err);
    if (id < 0) return hl_raise(L, &err);
    lua_pushinteger(L, id);
    return 1;
}

/* core.material_check(plugin, {name = number}) -> true or raises */
static int l_material_check(lua_State *L) {
    const char *plugin = luaL_checkstring(L, 1);
    luaL_checktype(L, 2, LUA_TTABLE);
    const char *names[256];
    double vals[256];
    int n = 0;
    lua_pushnil(L);
    while (lua_next(L, 2) && n < 256) {
        names[n] = lua_tostring(L, -2);
        vals[n++] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
    hearth_error err;
    if (hearth_material_check(plugin, names, vals, n, &err)) return hl_raise(L, &err);
    lua_pushboolean(L, 1);
    return 1;
}

/* s:_curve(mat, param, {x...}, {v...}, irreversible, moisture): x in degrees C, or moisture ratios (then v are factors) */
static int l_curve(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    int mat = (int)luaL_checkinteger(L, 2);
    const char *param = luaL_checkstring(L, 3);
    int n = (int)luaL_len(L, 4);
    if (n < 1 || n > 10000 || luaL_len(L, 5) != n) luaL_error(L, "curve for '%s': need 1..10000 points", param);
    double *T = lua_newuserdatauv(L, sizeof(double) * 2 * (size_t)n, 0), *v = T + n; /* freed by the GC */
    for (int i = 0; i < n; i++) {
        lua_geti(L, 4, i + 1);
        T[i] = lua_tonumber(L, -1);
        lua_geti(L, 5, i + 1);
        v[i] = lua_tonumber(L, -1);
        lua_pop(L, 2);
    }
    hearth_error err;
    const hearth_curve_of of = lua_toboolean(L, 7) ? HEARTH_CURVE_MOISTURE : HEARTH_CURVE_TEMPERATURE;
    if (hearth_scene_material_curve_of(u->s, mat, param, of, n, T, v, lua_toboolean(L, 6), &err)) return hl_raise(L, &err);
    return 0;
}

/* s:mixing_ratios() -> flat array of the dynamic mixture's particles' ratios, k per particle */
static int l_mixing_ratios(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const int n = hearth_scene_particle_count(u->s);
    int k = 0;
    const double *r = hearth_scene_mixing_ratios(u->s, &k);
    lua_newtable(L);
    int j = 0;
    for (int i = 0; r && i < n; i++) {
        double sum = 0;
        for (int c = 0; c < k; c++) sum += r[8 * i + c];
        if (!(sum > 0)) continue; /* not a particle of the mixture */
        for (int c = 0; c < k; c++) {
            lua_pushnumber(L, r[8 * i + c]);
            lua_seti(L, -2, ++j);
        }
    }
    return 1;
}

/* s:_mixture(plugin, {params1, params2, ...}) -> material id of a dynamic mixture */
static int l_mixture(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const char *plugin = luaL_checkstring(L, 2);
    luaL_checktype(L, 3, LUA_TTABLE);
    const int k = (int)luaL_len(L, 3);
    if (k < 2 || k > 8) return luaL_error(L, "mixture: 2 to 8 constituents (got %d)", k);
    const char *names[8][256];
    double values[8][256];
    int n[8] = {0};
    const char *const *np[8];
    const double *vp[8];
    for (int c = 0; c < k; c++) {
        lua_geti(L, 3, c + 1);
        luaL_checktype(L, -1, LUA_TTABLE);
        lua_pushnil(L);
        while (lua_next(L, -2)) { /* the keys stay alive in the table while this function runs */
            if (lua_type(L, -2) == LUA_TSTRING && lua_isnumber(L, -1) && n[c] < 256) {
                names[c][n[c]] = lua_tostring(L, -2);
                values[c][n[c]++] = lua_tonumber(L, -1);
            }
            lua_pop(L, 1);
        }
        np[c] = names[c];
        vp[c] = values[c];
        lua_pop(L, 1);
    }
    hearth_error err;
    const int id = hearth_scene_add_mixture(u->s, plugin, k, np, vp, n, &err);
    if (id < 0) return hl_raise(L, &err);
    lua_pushinteger(L, id);
    return 1;
}

/* s:_add(shape, mat, ppc, jitter, velocity, temperature|nil, fixed, saturation|nil, ratios|nil, fixed_temperature,
 *        smooth_surface) -> body id */
static int l_add(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    hearth_body_def b = hearth_default_body_def();
    b.shape = hl_checkshape(L, 2);
    b.material = (int)luaL_checkinteger(L, 3);
    b.ppc = (int)luaL_checkinteger(L, 4);
    b.jitter = luaL_checknumber(L, 5);
    hl_checkvec(L, 6, "velocity", b.velocity);
    b.temperature = lua_isnoneornil(L, 7) ? NAN : luaL_checknumber(L, 7);
    b.fixed = lua_toboolean(L, 8);
    b.saturation = lua_isnoneornil(L, 9) ? NAN : luaL_checknumber(L, 9);
    b.fixed_temperature = lua_toboolean(L, 11);
    b.smooth_surface = lua_toboolean(L, 12);
    if (lua_istable(L, 10)) { /* a dynamic mixture's initial ratios */
        const int k = (int)luaL_len(L, 10);
        for (int c = 0; c < k && c < 8; c++) {
            lua_geti(L, 10, c + 1);
            b.ratios[c] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
    }
    hearth_error err;
    int id = hearth_scene_add_body(u->s, &b, &err);
    if (id < 0) return hl_raise(L, &err);
    lua_pushinteger(L, id);
    return 1;
}

/* s:_labels(body, {material ids}, {ratios}, seed) -> {count per material} */
static int l_labels(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const int body = (int)luaL_checkinteger(L, 2);
    luaL_checktype(L, 3, LUA_TTABLE);
    luaL_checktype(L, 4, LUA_TTABLE);
    const double seed = luaL_checknumber(L, 5);
    const int k = (int)luaL_len(L, 3);
    if (k < 1 || k > 8 || luaL_len(L, 4) != k) return luaL_error(L, "labels: 1 to 8 materials with one ratio each");
    int mats[8], counts[8];
    double ratio[8];
    for (int i = 0; i < k; i++) {
        lua_geti(L, 3, i + 1);
        mats[i] = (int)lua_tointeger(L, -1);
        lua_geti(L, 4, i + 1);
        ratio[i] = lua_tonumber(L, -1);
        lua_pop(L, 2);
    }
    hearth_error err;
    if (hearth_scene_body_labels(u->s, body, k, mats, ratio, (uint64_t)seed, counts, &err)) return hl_raise(L, &err);
    lua_createtable(L, k, 0);
    for (int i = 0; i < k; i++) {
        lua_pushinteger(L, counts[i]);
        lua_seti(L, -2, i + 1);
    }
    return 1;
}

/* Collider motion from Lua functions. The record lives in the scene's state
 * table so the GC keeps it while the scene lives. A Lua error inside the
 * step cannot unwind through the C library: it is caught, the collider
 * stops for that step, and the error is raised when the step returns. */
typedef struct hl_motion {
    lua_State *L;
    int vref, oref;   /* registry refs of velocity(t) and omega(t), or LUA_NOREF */
    int failed;
    const char *what; /* whose motion, for messages: "collider" (NULL) or "body" */
    char msg[512];
} hl_motion;

static void call_vec(hl_motion *m, int ref, double t, double out[3], int scalar_is_z) {
    lua_State *L = m->L;
    out[0] = out[1] = out[2] = 0;
    if (ref == LUA_NOREF || m->failed) return;
    lua_rawgeti(L, LUA_REGISTRYINDEX, ref);
    lua_pushnumber(L, t);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
        m->failed = 1;
        snprintf(m->msg, sizeof m->msg, "%s motion function: %s", m->what ? m->what : "collider", lua_tostring(L, -1));
    } else if (lua_isnumber(L, -1) && scalar_is_z) {
        out[2] = lua_tonumber(L, -1); /* a 2D spin: omega about z */
    } else if (lua_istable(L, -1)) {
        for (int k = 0; k < 3; k++) {
            lua_geti(L, -1, k + 1);
            out[k] = lua_isnumber(L, -1) ? lua_tonumber(L, -1) : 0;
            lua_pop(L, 1);
        }
    } else {
        m->failed = 1;
        snprintf(m->msg, sizeof m->msg, "%s motion function at t = %g returned %s; expected a vector%s",
                 m->what ? m->what : "collider", t, luaL_typename(L, -1), scalar_is_z ? " or a number" : "");
    }
    lua_pop(L, 1);
}

static void motion_cb(void *ud, double t, double v[3], double omega[3]) {
    hl_motion *m = ud;
    call_vec(m, m->vref, t, v, 0);
    call_vec(m, m->oref, t, omega, 1);
}

static int motion_check(lua_State *L) {
    lua_getiuservalue(L, 1, 1);
    if (lua_getfield(L, -1, "motions") == LUA_TTABLE) {
        lua_Integer n = luaL_len(L, -1);
        for (lua_Integer i = 1; i <= n; i++) {
            lua_geti(L, -1, i);
            hl_motion *m = lua_touserdata(L, -1);
            if (m && m->failed) {
                m->failed = 0;
                return luaL_error(L, "%s", m->msg);
            }
            lua_pop(L, 1);
        }
    }
    lua_pop(L, 2);
    return 0;
}

static int l_motion_gc(lua_State *L) {
    hl_motion *m = lua_touserdata(L, 1);
    luaL_unref(L, LUA_REGISTRYINDEX, m->vref);
    luaL_unref(L, LUA_REGISTRYINDEX, m->oref);
    m->vref = m->oref = LUA_NOREF;
    return 0;
}

/* Append the value on top of the stack (a motion userdata, left there) to the
 * scene's (argument 1) motions list: alive while the scene is, and checked
 * after each step. */
static void keep_motion(lua_State *L) {
    lua_getiuservalue(L, 1, 1);
    if (lua_getfield(L, -1, "motions") != LUA_TTABLE) {
        lua_pop(L, 1);
        lua_newtable(L);
        lua_pushvalue(L, -1);
        lua_setfield(L, -3, "motions");
    }
    lua_pushvalue(L, -3);
    lua_seti(L, -2, luaL_len(L, -2) + 1);
    lua_pop(L, 2);
}

/* A motion record for the functions at stack indices vidx (velocity) and
 * oidx (omega), 0 for none, kept by the scene; left on the stack. what names
 * its owner in messages (NULL: "collider"). */
static hl_motion *new_motion(lua_State *L, int vidx, int oidx, const char *what) {
    hl_motion *m = lua_newuserdatauv(L, sizeof *m, 0);
    memset(m, 0, sizeof *m);
    m->L = L;
    m->what = what;
    m->vref = m->oref = LUA_NOREF;
    if (luaL_newmetatable(L, "hearth.motion")) {
        lua_pushcfunction(L, l_motion_gc);
        lua_setfield(L, -2, "__gc");
    }
    lua_setmetatable(L, -2);
    if (vidx) {
        lua_pushvalue(L, vidx);
        m->vref = luaL_ref(L, LUA_REGISTRYINDEX);
    }
    if (oidx) {
        lua_pushvalue(L, oidx);
        m->oref = luaL_ref(L, LUA_REGISTRYINDEX);
    }
    keep_motion(L);
    return m;
}

/* s:_collider(shape, mode, friction, velocity (vec|fn), omega (num|vec|fn), pivot, ...) -> id */

/* s:collider's optional number at idx, named by its key (unit: what the message adds after "a number"): 1 and *out set
 * when given, 0 when nil (*out keeps its default); any other type is an error naming the key. */
static int collider_number(lua_State *L, int idx, const char *key, const char *unit, double *out) {
    if (lua_isnoneornil(L, idx)) return 0;
    if (lua_type(L, idx) != LUA_TNUMBER)
        return luaL_error(L, "s:collider: %s is a %s; valid: a number%s", key, luaL_typename(L, idx), unit);
    *out = lua_tonumber(L, idx);
    return 1;
}

static int l_collider(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    hearth_collider_def cd = hearth_default_collider_def();
    cd.shape = hl_checkshape(L, 2);
    cd.mode = (hearth_contact)luaL_checkinteger(L, 3);
    cd.friction = luaL_checknumber(L, 4);
    int vfn = lua_isfunction(L, 5), ofn = lua_isfunction(L, 6);
    if (!vfn && !lua_isnil(L, 5)) hl_checkvec(L, 5, "collider velocity", cd.velocity);
    if (!ofn && lua_isnumber(L, 6)) cd.omega[2] = lua_tonumber(L, 6);
    else if (!ofn && !lua_isnil(L, 6)) hl_checkvec(L, 6, "collider omega", cd.omega);
    if (!lua_isnil(L, 7)) hl_checkvec(L, 7, "collider pivot", cd.pivot);
    if (!lua_isnoneornil(L, 8)) cd.temperature = luaL_checknumber(L, 8);
    cd.beta = luaL_optnumber(L, 9, 0);
    if (!lua_isnoneornil(L, 10)) cd.saturation = luaL_checknumber(L, 10);
    cd.beta_water = luaL_optnumber(L, 11, 0);
    /* the warming and drawing sheet's numbers (their ranges: collider_init); a wrong type named here by its key, not
     * as argument #12 */
    collider_number(L, 12, "start_temperature", ", degrees C", &cd.start_temperature);
    cd.warm_time = luaL_optnumber(L, 13, 0);
    /* a sheet the food draws from: heat_capacity and area, and face_beta, warm_time's other name (warm_time =
     * heat_capacity / face_beta) */
    collider_number(L, 14, "heat_capacity", "", &cd.heat_capacity);
    collider_number(L, 15, "area", "", &cd.area);
    double fb = NAN;
    if (collider_number(L, 16, "face_beta", "", &fb)) {
        if (!(fb > 0 && fb <= 1e9))
            return luaL_error(L, "s:collider: face_beta = %f W/(m^2 K); valid range (0, 1e9] (the oven's coefficient on "
                                 "the sheet's faces)", fb);
        if (!(cd.heat_capacity > 0) || cd.warm_time != 0)
            return luaL_error(L, "s:collider: face_beta (the oven's coefficient on the sheet's faces) goes with "
                                 "heat_capacity, in place of warm_time (warm_time = heat_capacity / face_beta): give "
                                 "one of the two");
        cd.warm_time = cd.heat_capacity / fb;
    }
    if (vfn || ofn) {
        cd.motion = motion_cb;
        cd.motion_ud = new_motion(L, vfn ? 5 : 0, ofn ? 6 : 0, NULL);
    }
    hearth_error err;
    int id = hearth_scene_add_collider(u->s, &cd, &err);
    if (id < 0) return hl_raise(L, &err);
    motion_check(L);
    lua_pushinteger(L, id);
    return 1;
}

/* s:_body_motion(body, velocity (vec|fn|nil), omega (num|vec|fn|nil), pivot|nil): a fixed body's
 * prescribed motion (SPH walls and lids), spelt as a collider's; functions go through the same
 * motion record, kept and checked the same way. */
static int l_body_motion(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const int body = (int)luaL_checkinteger(L, 2);
    double v[3] = {0, 0, 0}, w[3] = {0, 0, 0}, p[3] = {0, 0, 0};
    const int vfn = lua_isfunction(L, 3), ofn = lua_isfunction(L, 4);
    if (!vfn && !lua_isnoneornil(L, 3)) hl_checkvec(L, 3, "body velocity", v);
    if (!ofn && lua_isnumber(L, 4)) w[2] = lua_tonumber(L, 4);
    else if (!ofn && !lua_isnoneornil(L, 4)) hl_checkvec(L, 4, "body omega", w);
    if (!lua_isnoneornil(L, 5)) hl_checkvec(L, 5, "body pivot", p);
    hearth_motion_fn fn = NULL;
    hl_motion *m = NULL;
    if (vfn || ofn) {
        m = new_motion(L, vfn ? 3 : 0, ofn ? 4 : 0, "body");
        fn = motion_cb;
    }
    hearth_error err;
    if (hearth_scene_body_motion(u->s, body, v, w, p, fn, m, &err)) return hl_raise(L, &err);
    motion_check(L);
    return 0;
}

/* Gravity from a Lua function of time, called by the core once a step (outside
 * parallel loops). As with collider motion, a Lua error or a bad value is
 * kept and raised when the step returns; the step keeps the previous gravity. */
static void gravity_cb(void *ud, double t, double g[3]) {
    hl_motion *m = ud;
    lua_State *L = m->L;
    if (m->failed) return;
    lua_rawgeti(L, LUA_REGISTRYINDEX, m->vref);
    lua_pushnumber(L, t);
    if (lua_pcall(L, 1, 1, 0) != LUA_OK) {
        m->failed = 1;
        snprintf(m->msg, sizeof m->msg, "s:gravity function: %s", lua_tostring(L, -1));
    } else if (lua_istable(L, -1)) {
        double v[3] = {0, 0, 0};
        int ok = 1;
        for (int k = 0; k < 3; k++) {
            const int ty = lua_geti(L, -1, k + 1);
            if (ty == LUA_TNUMBER) v[k] = lua_tonumber(L, -1);
            else if (!(k == 2 && ty == LUA_TNIL)) ok = 0;
            lua_pop(L, 1);
        }
        if (ok && isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])) memcpy(g, v, sizeof v);
        else {
            m->failed = 1;
            snprintf(m->msg, sizeof m->msg, "s:gravity function at t = %g returned a table that is not {gx, gy[, gz]} of "
                     "finite numbers (m/s^2)", t);
        }
    } else {
        m->failed = 1;
        snprintf(m->msg, sizeof m->msg, "s:gravity function at t = %g returned %s; expected {gx, gy[, gz]} (m/s^2)", t,
                 luaL_typename(L, -1));
    }
    lua_pop(L, 1);
}

/* s:_gravity(vec | function(t) -> vec): set gravity now, or from a function of time every step */
static int l_gravity(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    if (!lua_isfunction(L, 2)) {
        double g[3];
        hl_checkvec(L, 2, "gravity", g);
        hearth_error err;
        hearth_scene_set_gravity_fn(u->s, NULL, NULL);
        if (hearth_scene_set_gravity(u->s, g, &err)) return hl_raise(L, &err);
        return 0;
    }
    /* kept in the scene's motions list: alive while the scene is, and checked after each step */
    hl_motion *m = new_motion(L, 2, 0, NULL);
    hearth_scene_set_gravity_fn(u->s, gravity_cb, m);
    return 0;
}

/* A body force from a Lua function f(x, y, z, t) -> fx, fy[, fz] (m/s^2),
 * called by the MPM grid update at every node with mass, each step (by SPH
 * at every particle), on one thread (hearth_scene_set_body_force_serial).
 * Several numbers rather than a table: no garbage per node. As with
 * gravity, the first error or bad value is kept and raised when the step
 * returns; the nodes after it get no extra force. */
static void body_force_cb(void *ud, double t, const double x[3], double acc[3]) {
    hl_motion *m = ud;
    lua_State *L = m->L;
    if (m->failed) return;
    lua_rawgeti(L, LUA_REGISTRYINDEX, m->vref);
    for (int k = 0; k < 3; k++) lua_pushnumber(L, x[k]);
    lua_pushnumber(L, t);
    if (lua_pcall(L, 4, 3, 0) != LUA_OK) {
        m->failed = 1;
        snprintf(m->msg, sizeof m->msg, "s:body_force function: %s", lua_tostring(L, -1));
        lua_pop(L, 1);
        return;
    }
    double f[3] = {0, 0, 0};
    int ok = 1;
    for (int k = 0; k < 3; k++) {
        const int idx = -3 + k;
        if (lua_type(L, idx) == LUA_TNUMBER) f[k] = lua_tonumber(L, idx);
        else if (!(k == 2 && lua_isnil(L, idx))) ok = 0;
    }
    if (ok && isfinite(f[0]) && isfinite(f[1]) && isfinite(f[2])) {
        for (int k = 0; k < 3; k++) acc[k] += f[k];
    } else {
        m->failed = 1;
        snprintf(m->msg, sizeof m->msg, "s:body_force function at (%g, %g, %g), t = %g returned %s, %s, %s; expected "
                 "fx, fy[, fz]: finite numbers (m/s^2)", x[0], x[1], x[2], t, luaL_typename(L, -3), luaL_typename(L, -2),
                 luaL_typename(L, -1));
    }
    lua_pop(L, 3);
}

/* s:_body_force(function(x, y, z, t) -> fx, fy[, fz] | nil): an acceleration field added to gravity */
static int l_body_force(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    if (lua_isnoneornil(L, 2)) {
        hearth_scene_set_body_force(u->s, NULL, NULL);
        return 0;
    }
    luaL_checktype(L, 2, LUA_TFUNCTION);
    hl_motion *m = new_motion(L, 2, 0, NULL); /* alive while the scene is, and checked after each step */
    hearth_scene_set_body_force_serial(u->s, body_force_cb, m);
    return 0;
}

/* s:_advance(t_end) / s:_step(n): one core call each; raises on guard stops */
static int l_advance(lua_State *L) {
    hl_scene *u = hl_checkscene_slabs(L, 1);
    hearth_error err;
    hearth_status st = hearth_scene_advance_steps(u->s, luaL_checknumber(L, 2), (long)luaL_optinteger(L, 3, -1), &err);
    motion_check(L);
    if (st) return hl_raise(L, &err);
    return 0;
}

static int l_step_raw(lua_State *L) {
    hl_scene *u = hl_checkscene_slabs(L, 1);
    hearth_error err;
    hearth_status st = hearth_scene_step(u->s, (int)luaL_optinteger(L, 2, 1), &err);
    motion_check(L);
    if (st) return hl_raise(L, &err);
    return 0;
}

static int l_push(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    double v[3];
    hl_checkvec(L, 3, "push velocity", v);
    hearth_error err;
    if (hearth_scene_body_set_velocity(u->s, (int)luaL_checkinteger(L, 2), v, &err)) return hl_raise(L, &err);
    return 0;
}

static int l_cut(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    hearth_error err;
    int n = hearth_scene_remove_inside(u->s, hl_checkshape(L, 2), &err);
    if (n < 0) return hl_raise(L, &err);
    lua_pushinteger(L, n);
    return 1;
}

static int l_move(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    double d[3];
    hl_checkvec(L, 3, "move by", d);
    hearth_error err;
    if (hearth_scene_collider_translate(u->s, (int)luaL_checkinteger(L, 2), d, &err)) return hl_raise(L, &err);
    return 0;
}

static int l_collider_velocity(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    double v[3] = {0, 0, 0}, w[3] = {0, 0, 0};
    hl_checkvec(L, 3, "collider velocity", v);
    if (lua_isnumber(L, 4)) w[2] = lua_tonumber(L, 4);
    else if (!lua_isnoneornil(L, 4)) hl_checkvec(L, 4, "collider omega", w);
    hearth_error err;
    if (hearth_scene_collider_set_velocity(u->s, (int)luaL_checkinteger(L, 2), v, w, &err)) return hl_raise(L, &err);
    return 0;
}

static int l_set_dt(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const hearth_scene_def *d = hearth_scene_get_def(u->s);
    hearth_error err;
    if (hearth_scene_set_dt_limits(u->s, luaL_optnumber(L, 2, d->cfl), luaL_optnumber(L, 3, d->dt_max), &err))
        return hl_raise(L, &err);
    return 0;
}

/* s:oven(temperature [, beta]) -> the oven now; s:oven(nil) removes it; s:oven() reads it */
static int l_oven(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const hearth_scene_def *d = hearth_scene_get_def(u->s);
    if (lua_gettop(L) >= 2) {
        double T = lua_isnil(L, 2) ? NAN : luaL_checknumber(L, 2);
        /* the core reads a NaN temperature as "no oven": only nil may say that, or a 0/0 would put the oven out */
        if (!lua_isnil(L, 2) && isnan(T)) {
            const hearth_setting *e = hearth_scene_setting("oven.temperature");
            return hl_errorf(L, "s:oven: temperature = nan; valid range [%g, %g] %s, or nil for no oven", e->min, e->max,
                             e->unit);
        }
        /* beta: the scene's own when it has one, else the schema's default (10) */
        double beta = luaL_optnumber(L, 3, d->oven_beta > 0 ? d->oven_beta : hearth_scene_setting("oven.beta")->def);
        hearth_error err;
        if (hearth_scene_set_oven(u->s, T, beta, &err)) return hl_raise(L, &err);
    }
    if (isnan(d->oven_temperature)) return lua_pushnil(L), 1;
    lua_pushnumber(L, d->oven_temperature);
    lua_pushnumber(L, d->oven_beta);
    return 2;
}

static void push_vec3(lua_State *L, const double v[3]) {
    lua_createtable(L, 3, 0);
    for (int c = 0; c < 3; c++) lua_pushnumber(L, v[c]), lua_seti(L, -2, c + 1);
}

/* s:settings() -> the scene's settings now, keyed as h.scene spells them
 * ("dx", "oven.beta", "sph.h_factor"): words as words, flags as booleans, no
 * oven as a missing oven.temperature. Read from the core's definition through
 * the schema, so a test can hold h.scene's defaults against the C ones. */
static int l_settings(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const char *d = (const char *)hearth_scene_get_def(u->s);
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    lua_newtable(L);
    for (int k = 0; k < n; k++) {
        const hearth_setting *e = &set[k];
        if (e->offset < 0) continue;
        const char *f = d + e->offset;
        switch (e->kind) {
        case HEARTH_SETTING_REAL:
            if (isnan(*(const double *)f)) continue;
            lua_pushnumber(L, *(const double *)f);
            break;
        case HEARTH_SETTING_INT: lua_pushinteger(L, *(const int *)f); break;
        case HEARTH_SETTING_SEED: lua_pushinteger(L, (lua_Integer) * (const uint64_t *)f); break;
        case HEARTH_SETTING_FLAG: lua_pushboolean(L, *(const int *)f); break;
        case HEARTH_SETTING_CHOICE: lua_pushstring(L, e->words[*(const int *)f]); break;
        case HEARTH_SETTING_VECTOR: push_vec3(L, (const double *)f); break;
        case HEARTH_SETTING_BOX:
            lua_createtable(L, 2, 0);
            push_vec3(L, (const double *)f), lua_seti(L, -2, 1);
            push_vec3(L, (const double *)(d + e->offset2)), lua_seti(L, -2, 2);
            break;
        case HEARTH_SETTING_TEXT: continue;
        }
        lua_setfield(L, -2, e->name);
    }
    return 1;
}

static int l_load(lua_State *L) {
    char buf[4096];
    const char *given = luaL_checkstring(L, 1);
    const char *path = hl_in_path(L, given, buf, sizeof buf);
    hearth_error err;
    hearth_scene *s = hearth_scene_load(path, &err);
    if (!s && given[0] != '/' && hl_opts(L)->out_dir && access(path, F_OK) != 0) {
        /* dofile reads a relative path from the current folder, h.load from the output folder (where s:save
         * wrote it): a missing one says which, as a user restarting another run's checkpoint meets it (#18,
         * helper userview5) */
        size_t used = strlen(err.msg);
        snprintf(err.msg + used, sizeof err.msg - used,
                 " (h.load reads a relative path from the output folder, %s, where s:save writes; give the path "
                 "from there, or an absolute one)",
                 hl_opts(L)->out_dir);
    }
    if (!s) return hl_raise(L, &err);
    hearth_scene_keep_slabs(s, 1); /* as for h.scene */
    hl_scene *u = lua_newuserdatauv(L, sizeof *u, 1);
    u->s = s;
    luaL_setmetatable(L, HL_SCENE);
    lua_newtable(L);
    lua_pushboolean(L, 1); /* s:run continues the series the saved run left: VTU, PNG, PLY, CSV (run.lua) */
    lua_setfield(L, -2, "restored");
    lua_setiuservalue(L, -2, 1);
    return 1;
}

void hl_open_scene(lua_State *L) {
    static const luaL_Reg methods[] = {
        {"_state", l_state},     {"_material", l_material}, {"_curve", l_curve},       {"_add", l_add}, {"_mixture", l_mixture}, {"mixing_ratios", l_mixing_ratios},       {"_labels", l_labels},
        {"_collider", l_collider}, {"_advance", l_advance}, {"_step", l_step_raw},     {"push", l_push},
        {"cut", l_cut},          {"move", l_move},         {"collider_velocity", l_collider_velocity},
        {"set_dt", l_set_dt}, {"settings", l_settings},    {"oven", l_oven},    {"_body_motion", l_body_motion},
        {"_gravity", l_gravity}, {"_body_force", l_body_force}, {NULL, NULL}};
    luaL_newmetatable(L, HL_SCENE);
    lua_pushcfunction(L, l_gc);
    lua_setfield(L, -2, "__gc");
    luaL_newlib(L, methods);
    luaL_setfuncs(L, hl_scene_readers, 0); /* the methods that read the scene: lua_scene_read.c */
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);
    static const luaL_Reg fns[] = {{"scene_new", l_scene_new}, {"scene_settings", l_scene_settings}, {"load", l_load}, {"material_check", l_material_check},
                                   {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
}

/* lua_scene_read.c: the scene userdata's methods that read it and change
 * nothing: probes at a point, along a line and over a slice, stats(), the
 * particles' fields and positions, a material's parameters, the volume, the
 * time and the hash. Over MPI ranks each gathers the whole scene first
 * (hl_checkscene), except stats() and the time, which every rank already
 * agrees on. lua_scene.c registers them with the other methods. */
#include <stdio.h>
#include <string.h>

#include "hearth_lua.h"

static void push_values(lua_State *L, const double *v, int n) {
    if (n == 1) {
        lua_pushnumber(L, v[0]);
        return;
    }
    lua_createtable(L, n, 0);
    for (int k = 0; k < n; k++) {
        lua_pushnumber(L, v[k]);
        lua_seti(L, -2, k + 1);
    }
}

static int l_probe(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const char *f = luaL_checkstring(L, 2);
    double x[3], out[9]; /* the widest field is the stress tensor */
    hl_checkvec(L, 3, "probe point", x);
    hearth_error err;
    if (hearth_probe_point(u->s, f, x, out, &err)) return hl_raise(L, &err);
    push_values(L, out, hearth_field_components(f));
    return 1;
}

static int l_line(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const char *f = luaL_checkstring(L, 2);
    double a[3], b[3];
    hl_checkvec(L, 3, "line start", a);
    hl_checkvec(L, 4, "line end", b);
    int n = (int)luaL_checkinteger(L, 5), nc = hearth_field_components(f);
    if (n < 2 || n > 1000000) luaL_error(L, "line: n = %d samples; valid range [2, 1000000]", n);
    double *out = lua_newuserdatauv(L, sizeof(double) * (size_t)n * (size_t)(nc > 0 ? nc : 1), 0);
    hearth_error err;
    if (hearth_probe_line(u->s, f, a, b, n, out, &err)) return hl_raise(L, &err);
    lua_createtable(L, n, 0);
    for (int i = 0; i < n; i++) {
        push_values(L, out + (size_t)i * nc, nc);
        lua_seti(L, -2, i + 1);
    }
    return 1;
}

/* s:_slice(field, axis, at, w, h) -> rows (h tables of w numbers, row 1 at the low end) */
static int l_slice(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const char *f = luaL_checkstring(L, 2);
    int axis = (int)luaL_checkinteger(L, 3), w = (int)luaL_checkinteger(L, 5), h = (int)luaL_checkinteger(L, 6);
    if (w < 1 || h < 1 || (long)w * h > 16L * 1024 * 1024) luaL_error(L, "slice: res %d x %d; each side >= 1, total <= 16M", w, h);
    double *out = lua_newuserdatauv(L, sizeof(double) * (size_t)w * (size_t)h, 0);
    hearth_error err;
    if (hearth_probe_slice(u->s, f, axis, luaL_checknumber(L, 4), w, h, out, &err)) return hl_raise(L, &err);
    lua_createtable(L, h, 0);
    for (int r = 0; r < h; r++) {
        lua_createtable(L, w, 0);
        for (int c = 0; c < w; c++) {
            lua_pushnumber(L, out[(size_t)r * w + c]);
            lua_seti(L, -2, c + 1);
        }
        lua_seti(L, -2, r + 1);
    }
    return 1;
}

static int l_stats(lua_State *L) {
    hl_scene *u = hl_checkscene_slabs(L, 1);
    hearth_stats st;
    hearth_scene_stats(u->s, &st);
    lua_createtable(L, 0, 14);
    lua_pushnumber(L, st.t); lua_setfield(L, -2, "t");
    lua_pushinteger(L, st.step); lua_setfield(L, -2, "step");
    lua_pushnumber(L, st.dt); lua_setfield(L, -2, "dt");
    lua_pushinteger(L, st.particles); lua_setfield(L, -2, "particles");
    lua_pushnumber(L, st.kinetic); lua_setfield(L, -2, "kinetic");
    lua_pushnumber(L, st.max_speed); lua_setfield(L, -2, "max_speed");
    lua_pushnumber(L, st.cfl); lua_setfield(L, -2, "cfl");
    lua_pushnumber(L, st.wave_speed); lua_setfield(L, -2, "wave_speed");
    lua_pushinteger(L, st.out_of_domain); lua_setfield(L, -2, "out_of_domain");
    lua_pushinteger(L, st.rollbacks); lua_setfield(L, -2, "rollbacks");
    static const char *gs[] = {"ok", "rolled_back", "stopped"};
    lua_pushstring(L, gs[st.guard]); lua_setfield(L, -2, "guard");
    lua_pushstring(L, st.diagnosis); lua_setfield(L, -2, "diagnosis");
    lua_pushinteger(L, hearth_scene_body_count(u->s)); lua_setfield(L, -2, "bodies");
    lua_pushnumber(L, st.heat_energy); lua_setfield(L, -2, "heat_energy");
    lua_pushinteger(L, st.cg_iterations); lua_setfield(L, -2, "cg_iterations");
    lua_pushnumber(L, st.gas_moles); lua_setfield(L, -2, "gas");
    lua_pushnumber(L, st.water_mass); lua_setfield(L, -2, "water_mass");
    lua_pushnumber(L, st.water_lost); lua_setfield(L, -2, "water_lost");
    lua_pushnumber(L, st.oven_heat_in); lua_setfield(L, -2, "oven_heat_in");
    lua_pushnumber(L, st.field_limit); lua_setfield(L, -2, "field_limit");
    lua_pushnumber(L, st.field_dt); lua_setfield(L, -2, "field_dt");
    lua_pushinteger(L, st.field_cycle); lua_setfield(L, -2, "field_cycle");
    /* the live fields as a list */
    lua_newtable(L);
    const char *f = hearth_scene_fields(u->s);
    int k = 0;
    while (*f) {
        const char *e = strchr(f, ' ');
        size_t len = e ? (size_t)(e - f) : strlen(f);
        lua_pushlstring(L, f, len);
        lua_seti(L, -2, ++k);
        f += len + (e != NULL);
    }
    lua_setfield(L, -2, "fields");
    return 1;
}

static int l_body_particles(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    lua_pushinteger(L, hearth_scene_body_particles(u->s, (int)luaL_checkinteger(L, 2)));
    return 1;
}

/* s:positions() -> flat array {x1, y1, z1, x2, ...} (for metrics and scripts) */
static int l_positions(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const int n = hearth_scene_particle_count(u->s);
    const double *x = hearth_scene_positions(u->s);
    lua_createtable(L, 3 * n, 0);
    for (int i = 0; i < 3 * n; i++) {
        lua_pushnumber(L, x[i]);
        lua_seti(L, -2, i + 1);
    }
    return 1;
}

/* s:_particle_field(name) -> flat array of n * components numbers in particle
 * order; "id" gives the particle ids. init.lua's s:particles checks the names
 * first (for its did-you-mean) and gathers several fields. */
static int l_particle_field(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const char *f = luaL_checkstring(L, 2);
    const int n = hearth_scene_particle_count(u->s);
    if (strcmp(f, "id") == 0) {
        const int *id = hearth_scene_particle_ids(u->s);
        lua_createtable(L, n, 0);
        for (int i = 0; i < n; i++) {
            lua_pushinteger(L, id[i]);
            lua_seti(L, -2, i + 1);
        }
        return 1;
    }
    const int nc = hearth_field_components(f);
    const size_t len = (size_t)(n > 0 ? n : 1) * (size_t)(nc > 0 ? nc : 1);
    double *out = lua_newuserdatauv(L, sizeof(double) * len, 0); /* freed by Lua's GC, even on an error */
    hearth_error err;
    if (hearth_scene_particle_field(u->s, f, out, &err)) return hl_raise(L, &err);
    const lua_Integer total = (lua_Integer)n * nc;
    lua_createtable(L, (int)total, 0);
    for (lua_Integer i = 0; i < total; i++) {
        lua_pushnumber(L, out[i]);
        lua_seti(L, -2, i + 1);
    }
    return 1;
}

/* s:material_params(id) -> {name = value, ...}: what the scene simulates with
 * (after blending), so a scene can print or check it. */
static int l_material_params(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const int id = (int)luaL_checkinteger(L, 2);
    const hearth_material *m = hearth_scene_material_info(u->s, id);
    if (!m) return luaL_error(L, "material_params: material %d does not exist (the scene has %d)", id,
                              hearth_scene_material_count(u->s));
    const double *p = hearth_scene_material_params(u->s, id);
    lua_createtable(L, 0, m->nparams);
    for (int i = 0; i < m->nparams; i++) {
        lua_pushnumber(L, p[i]);
        lua_setfield(L, -2, m->params[i].name);
    }
    return 1;
}

static int l_volume(lua_State *L) {
    lua_pushnumber(L, hearth_scene_volume(hl_checkscene(L, 1)->s));
    return 1;
}

static int l_time(lua_State *L) {
    lua_pushnumber(L, hearth_scene_time(hl_checkscene_slabs(L, 1)->s));
    return 1;
}

static int l_hash(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    char buf[32];
    snprintf(buf, sizeof buf, "%016llx", (unsigned long long)hearth_scene_hash(u->s));
    lua_pushstring(L, buf);
    return 1;
}

/* s:collider_heat(id) -> {temperature = degC, drawn = J, oven_in = J} (hearth_scene_collider_heat) */
static int l_collider_heat(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    const lua_Integer id = luaL_checkinteger(L, 2);
    double out[3];
    hearth_error err;
    if (id < 0 || id > INT32_MAX || hearth_scene_collider_heat(u->s, (int)id, out, &err))
        return luaL_error(L, "s:collider_heat: collider %I does not exist (the scene has %d; ids from s:collider)", id,
                          hearth_scene_collider_count(u->s));
    lua_createtable(L, 0, 3);
    lua_pushnumber(L, out[0]);
    lua_setfield(L, -2, "temperature");
    lua_pushnumber(L, out[1]);
    lua_setfield(L, -2, "drawn");
    lua_pushnumber(L, out[2]);
    lua_setfield(L, -2, "oven_in");
    return 1;
}

/* the read-only methods, added to the scene's method table by hl_open_scene */
const luaL_Reg hl_scene_readers[] = {
    {"probe", l_probe},
    {"line", l_line},
    {"_slice", l_slice},
    {"stats", l_stats},
    {"_time", l_time},
    {"body_particles", l_body_particles},
    {"hash", l_hash},
    {"positions", l_positions},
    {"_particle_field", l_particle_field},
    {"volume", l_volume},
    {"material_params", l_material_params},
    {"collider_heat", l_collider_heat},
    {NULL, NULL}};

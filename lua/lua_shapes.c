/* lua_shapes.c: shape constructors and boolean operators for scenes.
 *   h.box(lo, hi)  h.sphere(c, r)  h.disc(c, r)  h.cylinder(c, axis, r, half_height)
 *   h.capsule(a, b, r)  h.plane(point, normal)  h.container(base, axis, r_in, height, wall, floor)
 *   h.mask(png, lo, hi)  h.extrude(shape, z0, z1)
 *   a + b (union), a * b (intersection), a - b (difference) */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "hearth_lua.h"

typedef struct hl_shape {
    hearth_shape *sh;
} hl_shape;

hearth_shape *hl_checkshape(lua_State *L, int idx) {
    hl_shape *u = luaL_checkudata(L, idx, HL_SHAPE);
    if (!u->sh) luaL_argerror(L, idx, "shape was released");
    return u->sh;
}

void hl_pushshape(lua_State *L, hearth_shape *sh) {
    if (!sh) { /* the constructor says which argument (a NaN centre is not "out of memory") */
        const char *why = hearth_shape_error();
        luaL_error(L, "could not make the shape: %s", why ? why : "out of memory");
    }
    hl_shape *u = lua_newuserdatauv(L, sizeof *u, 0);
    u->sh = sh;
    luaL_setmetatable(L, HL_SHAPE);
}

void hl_checkvec(lua_State *L, int idx, const char *what, double v[3]) {
    v[0] = v[1] = v[2] = 0;
    if (!lua_istable(L, idx)) luaL_error(L, "%s: expected a vector like {x, y} or {x, y, z}, got %s", what, luaL_typename(L, idx));
    lua_Integer n = luaL_len(L, idx);
    if (n < 2 || n > 3) luaL_error(L, "%s: expected 2 or 3 numbers, got %d", what, (int)n);
    for (int k = 0; k < n; k++) {
        lua_geti(L, idx, k + 1);
        if (!lua_isnumber(L, -1)) luaL_error(L, "%s[%d]: expected a number, got %s", what, k + 1, luaL_typename(L, -1));
        v[k] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
}

static double posnum(lua_State *L, int idx, const char *what, const char *unit) {
    double x = luaL_checknumber(L, idx);
    if (isnan(x)) hl_errorf(L, "%s = nan %s; it must be > 0", what, unit); /* %g writes 0/0 as "-nan" */
    if (!(x > 0) || !isfinite(x)) hl_errorf(L, "%s = %g %s; it must be > 0", what, x, unit);
    return x;
}

static int l_box(lua_State *L) {
    double lo[3], hi[3], c[3], h[3];
    hl_checkvec(L, 1, "box lo", lo);
    hl_checkvec(L, 2, "box hi", hi);
    int n2 = (int)luaL_len(L, 1);
    for (int d = 0; d < 3; d++) {
        if (d < n2 && !(hi[d] > lo[d])) hl_errorf(L, "box: hi[%d] = %g must exceed lo[%d] = %g", d + 1, hi[d], d + 1, lo[d]);
        c[d] = 0.5 * (lo[d] + hi[d]);
        h[d] = 0.5 * (hi[d] - lo[d]);
    }
    if (n2 == 2) h[2] = 0; /* a 2D box: unbounded in z (the shape module's convention) */
    hl_pushshape(L, hearth_shape_box(c, h));
    return 1;
}

static int l_sphere(lua_State *L) {
    double c[3];
    hl_checkvec(L, 1, "sphere centre", c);
    hl_pushshape(L, hearth_shape_sphere(c, posnum(L, 2, "sphere radius", "m")));
    return 1;
}

static int l_cylinder(lua_State *L) {
    double c[3], a[3];
    hl_checkvec(L, 1, "cylinder centre", c);
    hl_checkvec(L, 2, "cylinder axis", a);
    double r = posnum(L, 3, "cylinder radius", "m"), hh = posnum(L, 4, "cylinder half height", "m");
    hl_pushshape(L, hearth_shape_cylinder(c, a, r, hh));
    return 1;
}

static int l_capsule(lua_State *L) {
    double a[3], b[3];
    hl_checkvec(L, 1, "capsule end a", a);
    hl_checkvec(L, 2, "capsule end b", b);
    hl_pushshape(L, hearth_shape_capsule(a, b, posnum(L, 3, "capsule radius", "m")));
    return 1;
}

static int l_plane(lua_State *L) {
    double p[3], n[3];
    hl_checkvec(L, 1, "plane point", p);
    hl_checkvec(L, 2, "plane normal", n);
    if (n[0] == 0 && n[1] == 0 && n[2] == 0) luaL_error(L, "plane normal must not be zero");
    hl_pushshape(L, hearth_shape_plane(p, n));
    return 1;
}

static int l_container(lua_State *L) {
    double b[3], a[3];
    hl_checkvec(L, 1, "container base", b);
    hl_checkvec(L, 2, "container axis", a);
    double r = posnum(L, 3, "container inner radius", "m"), h = posnum(L, 4, "container height", "m");
    double w = posnum(L, 5, "container wall", "m"), f = posnum(L, 6, "container floor", "m");
    hl_pushshape(L, hearth_shape_container(b, a, r, h, w, f));
    return 1;
}

static int l_mask(lua_State *L) {
    const char *path = luaL_checkstring(L, 1);
    double lo[3], hi[3];
    hl_checkvec(L, 2, "mask lo", lo);
    hl_checkvec(L, 3, "mask hi", hi);
    char buf[4096];
    const hl_options *o = hl_opts(L);
    if (path[0] != '/' && o->scene_dir) { /* masks are assets next to the scene */
        snprintf(buf, sizeof buf, "%s/%s", o->scene_dir, path);
        FILE *f = fopen(buf, "rb");
        if (f) {
            fclose(f);
            path = buf;
        }
    }
    hearth_error err;
    hearth_shape *sh = hearth_shape_mask(path, lo, hi, &err);
    if (!sh) return hl_raise(L, &err);
    hl_pushshape(L, sh);
    return 1;
}

static int l_extrude(lua_State *L) {
    hearth_shape *a = hl_checkshape(L, 1);
    double z0 = luaL_checknumber(L, 2), z1 = luaL_checknumber(L, 3);
    if (!(z1 > z0)) hl_errorf(L, "extrude: z1 = %g must exceed z0 = %g", z1, z0);
    hl_pushshape(L, hearth_shape_extrude(a, z0, z1));
    return 1;
}

/* h.union(a, b, c, ...) folds left to right: ((a op b) op c) ...; every
 * argument counts (a third shape used to be dropped without a word). */
static int combine(lua_State *L, hearth_shape_op op) {
    const int n = lua_gettop(L);
    hearth_shape *a = hl_checkshape(L, 1), *b = hl_checkshape(L, 2);
    for (int k = 3; k <= n; k++) hl_checkshape(L, k);
    hl_pushshape(L, hearth_shape_combine(op, a, b));
    for (int k = 3; k <= n; k++) {
        hearth_shape *acc = hl_checkshape(L, -1);
        hl_pushshape(L, hearth_shape_combine(op, acc, hl_checkshape(L, k)));
        /* drop the last partial result: one slot in use however many shapes
         * (pushing all n - 2 overran Lua's stack at ~40 shapes and freed a bad
         * pointer at the next collection: h.union of a roll's 150 bubbles) */
        lua_remove(L, -2);
    }
    return 1;
}
static int l_union(lua_State *L) { return combine(L, HEARTH_UNION); }
static int l_intersect(lua_State *L) { return combine(L, HEARTH_INTERSECT); }
static int l_subtract(lua_State *L) { return combine(L, HEARTH_SUBTRACT); }

static int l_sdf(lua_State *L) {
    hearth_shape *a = hl_checkshape(L, 1);
    double x[3];
    hl_checkvec(L, 2, "point", x);
    lua_pushnumber(L, hearth_shape_sdf(a, x, NULL));
    return 1;
}

static int l_gc(lua_State *L) {
    hl_shape *u = luaL_checkudata(L, 1, HL_SHAPE);
    hearth_shape_free(u->sh);
    u->sh = NULL;
    return 0;
}

static int l_tostring(lua_State *L) {
    double lo[3], hi[3];
    hearth_shape_bounds(hl_checkshape(L, 1), lo, hi);
    lua_pushfstring(L, "hearth.shape (bounds %f %f .. %f %f)", lo[0], lo[1], hi[0], hi[1]);
    return 1;
}

void hl_open_shapes(lua_State *L) {
    static const luaL_Reg meta[] = {{"__add", l_union}, {"__mul", l_intersect}, {"__sub", l_subtract},
                                    {"__gc", l_gc},     {"__tostring", l_tostring}, {NULL, NULL}};
    static const luaL_Reg methods[] = {{"sdf", l_sdf}, {NULL, NULL}};
    luaL_newmetatable(L, HL_SHAPE);
    luaL_setfuncs(L, meta, 0);
    luaL_newlib(L, methods);
    lua_setfield(L, -2, "__index");
    lua_pop(L, 1);
    static const luaL_Reg fns[] = {{"box", l_box},           {"sphere", l_sphere},       {"disc", l_sphere},
                                   {"cylinder", l_cylinder}, {"capsule", l_capsule},     {"plane", l_plane},
                                   {"container", l_container}, {"cup", l_container},     {"mask", l_mask},
                                   {"extrude", l_extrude},   {"union", l_union},         {"intersection", l_intersect},
                                   {"difference", l_subtract}, {NULL, NULL}};
    luaL_setfuncs(L, fns, 0);
}

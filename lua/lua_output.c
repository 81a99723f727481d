/* lua_output.c: files a scene writes: pictures, particle dumps, checkpoints,
 * and the atomic text writer the Lua side uses for CSV series. Relative paths
 * resolve under the output folder, which is created when missing. Every one
 * of them, and every write the sandbox allows (io.open, os.remove,
 * os.rename), passes hl_out_path: the one place that decides what a scene
 * may write. It lives here at the bottom, in C, because a scene can reach
 * hearth.core's raw functions around any check made in Lua. */
#define _XOPEN_SOURCE 700 /* realpath, lstat */
#include <errno.h>
#include <limits.h>
#include <spawn.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include "hearth_lua.h"

extern char **environ;

/* Does the path (a "/"-separated tail of folders not yet made) hold a ".."
 * component? Such a tail cannot be resolved before the folders exist. */
static int has_dotdot(const char *tail) {
    for (const char *p = tail; *p;) {
        const char *e = strchr(p, '/');
        size_t len = e ? (size_t)(e - p) : strlen(p);
        if (len == 2 && p[0] == '.' && p[1] == '.') return 1;
        if (!e) break;
        p = e + 1;
    }
    return 0;
}

/* The real location of path, which need not exist yet: realpath of its
 * deepest existing ancestor with the missing rest appended. Returns NULL on
 * success, or why it cannot say where the path leads. */
static const char *resolve_target(const char *path, char *out, size_t n) {
    char head[PATH_MAX], tail[PATH_MAX] = "", real[PATH_MAX];
    if (snprintf(head, sizeof head, "%s", path) >= (int)sizeof head) return "the path is too long";
    for (;;) {
        size_t hl = strlen(head);
        while (hl > 1 && head[hl - 1] == '/') head[--hl] = '\0'; /* "a/b/" is "a/b" */
        if (realpath(hl ? head : ".", real)) break;
        struct stat st;
        if (hl && lstat(head, &st) == 0) /* it exists, yet does not resolve: a dangling or looping link */
            return "it passes through a symbolic link that does not resolve";
        if (!hl || !strcmp(head, "/") || !strcmp(head, ".")) return "no part of it exists";
        char *slash = strrchr(head, '/');
        const char *comp = slash ? slash + 1 : head;
        char t[PATH_MAX];
        if (snprintf(t, sizeof t, "%s%s%s", comp, tail[0] ? "/" : "", tail) >= (int)sizeof t) return "the path is too long";
        memcpy(tail, t, sizeof tail);
        if (!slash) head[0] = '\0';
        else if (slash == head) head[1] = '\0';
        else *slash = '\0';
    }
    if (has_dotdot(tail)) return "'..' follows a folder that does not exist";
    size_t rl = strlen(real);
    if (snprintf(out, n, "%s%s%s", real, tail[0] && real[rl - 1] != '/' ? "/" : "", tail) >= (int)n) return "the path is too long";
    return NULL;
}

const char *hl_quote_path(lua_State *L, const char *path) {
    const size_t len = strlen(path), head = HL_QUOTE_MAX - 60, tail = 40;
    if (len <= HL_QUOTE_MAX) return lua_pushstring(L, path);
    /* Lua's format has no precision: the pieces go in as strings */
    lua_pushlstring(L, path, head);
    lua_pushstring(L, path + len - tail);
    const char *q = lua_pushfstring(L, "%s...%s (%I bytes)", lua_tostring(L, -2), lua_tostring(L, -1), (lua_Integer)len);
    lua_replace(L, -3);
    lua_pop(L, 1);
    return q;
}

/* path resolved in the folder out_dir (the output folder, or under mpirun
 * rank 0's output folder for a rank > 0: io_pvtu's pieces), checked as
 * hl_out_path says */
static const char *out_path_in(lua_State *L, const char *out_dir, const char *call, const char *path, int flags,
                               char *buf, size_t n) {
    const hl_options *o = hl_opts(L);
    int w;
    if (path[0] == '/' || !out_dir || (flags & HL_PATH_AS_IS)) w = snprintf(buf, n, "%s", path);
    else w = snprintf(buf, n, "%s/%s", out_dir, path);
    if (w < 0 || (size_t)w >= n) /* a cut path would name another file than the one checked and asked for */
        return luaL_error(L, "%s: the path '%s' is longer than %d bytes", call, hl_quote_path(L, path), (int)(n - 1)),
               (const char *)NULL;
    if (!o->trusted) {
        char out_real[PATH_MAX], target[PATH_MAX];
        hearth_error err;
        if (!out_dir || hearth_mkdir_p(out_dir, &err) || !realpath(out_dir, out_real))
            return luaL_error(L, "%s: '%s': the output folder '%s' cannot be resolved, so a scene without --trust cannot "
                                 "write (run with --trust to allow it)", call, hl_quote_path(L, path),
                              hl_quote_path(L, out_dir ? out_dir : "(none)")),
                   (const char *)NULL;
        const char *why = resolve_target(buf, target, sizeof target);
        if (why)
            return luaL_error(L, "%s: '%s' is refused: %s, so it may lead outside the output folder '%s'; a scene "
                                 "without --trust writes only inside its output folder (run with --trust to allow it)",
                              call, hl_quote_path(L, path), why, hl_quote_path(L, out_dir)),
                   (const char *)NULL;
        size_t ol = strlen(out_real);
        int inside = !strcmp(out_real, "/") || (!strncmp(target, out_real, ol) && (target[ol] == '/' || target[ol] == '\0'));
        if (!inside)
            return luaL_error(L, "%s: '%s' is outside the output folder '%s' (it resolves to '%s'); a scene without "
                                 "--trust writes only inside its output folder (run with --trust to allow it)",
                              call, hl_quote_path(L, path), hl_quote_path(L, out_dir), hl_quote_path(L, target)),
                   (const char *)NULL;
    }
    if (flags & HL_PATH_MKDIRS) { /* make the file's folder, so "frames/t0001.png" just works */
        char dir[4096];
        snprintf(dir, sizeof dir, "%s", buf);
        char *slash = strrchr(dir, '/');
        if (slash && slash != dir) {
            *slash = '\0';
            hearth_error err;
            if (hearth_mkdir_p(dir, &err)) hl_raise(L, &err);
        }
    }
    return buf;
}

const char *hl_out_path(lua_State *L, const char *call, const char *path, int flags, char *buf, size_t n) {
    return out_path_in(L, hl_opts(L)->out_dir, call, path, flags, buf, n);
}

const char *hl_in_path(lua_State *L, const char *path, char *buf, size_t n) {
    const hl_options *o = hl_opts(L);
    if (path[0] == '/' || !o->out_dir) snprintf(buf, n, "%s", path);
    else snprintf(buf, n, "%s/%s", o->out_dir, path);
    /* under mpirun a rank > 0 writes into its own scratch folder, but reads
     * what an earlier run left in the shared output folder (a checkpoint) */
    if (o->in_dir && path[0] != '/' && access(buf, F_OK) != 0) snprintf(buf, n, "%s/%s", o->in_dir, path);
    return buf;
}

/* Two numbers {lo, hi} at index idx into r, or a message naming the option. */
static void range_pair(lua_State *L, int idx, const char *opt, double r[2]) {
    if (!lua_istable(L, idx) || lua_rawlen(L, idx) != 2)
        luaL_error(L, "png: %s = {lo, hi}, two numbers in the field's unit", opt);
    for (int k = 0; k < 2; k++) {
        lua_rawgeti(L, idx, k + 1);
        if (!lua_isnumber(L, -1)) luaL_error(L, "png: %s = {lo, hi}, two numbers in the field's unit", opt);
        r[k] = lua_tonumber(L, -1);
        lua_pop(L, 1);
    }
    if (!(r[0] < r[1])) luaL_error(L, "png: %s = {%f, %f}; the first must be smaller", opt, r[0], r[1]);
}

/* region = {{u lo, v lo}, {u hi, v hi}} (m): the picture's close-up (hearth_picture_def.region; hearth_render
 * checks it against the domain) */
static void region_pair(lua_State *L, int idx, double r[4]) {
    const char *want = "png: region = {{lo, lo}, {hi, hi}}, the corners of the part shown (m), the picture's "
                       "horizontal axis first";
    if (!lua_istable(L, idx) || lua_rawlen(L, idx) != 2) luaL_error(L, "%s", want);
    for (int c = 0; c < 2; c++) {
        lua_rawgeti(L, idx, c + 1);
        if (!lua_istable(L, -1) || lua_rawlen(L, -1) != 2) luaL_error(L, "%s", want);
        for (int k = 0; k < 2; k++) {
            lua_rawgeti(L, -1, k + 1);
            if (!lua_isnumber(L, -1)) luaL_error(L, "%s", want);
            r[2 * c + k] = lua_tonumber(L, -1);
            lua_pop(L, 1);
        }
        lua_pop(L, 1);
    }
}

/* t[name] = {v[1], ..., v[n]} on the table at the top of the stack */
static void set_numbers(lua_State *L, const char *name, const double *v, int n) {
    lua_createtable(L, n, 0);
    for (int k = 0; k < n; k++) lua_pushnumber(L, v[k]), lua_rawseti(L, -2, k + 1);
    lua_setfield(L, -2, name);
}

/* s:png(field, path, {kind = "slice"|"particles", width, height, axis, at,
 * range = {lo, hi} | "frame", colormap, grow = {lo, hi}, time_scale, label, region, depth}) -> path, info
 * (info: range, data, ticks, colormap, unit, width, height, title: what it drew with; area = {left, top, width,
 * height} px and view_lo, view_hi (m): where its plot lies and what it shows) */
static int l_png(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    hearth_picture_def d = hearth_default_picture_def();
    d.field = luaL_checkstring(L, 2);
    char buf[4096];
    const char *path = hl_out_path(L, "s:png", luaL_checkstring(L, 3), HL_PATH_MKDIRS, buf, sizeof buf);
    const char *kind = NULL; /* not given: by the field (below) */
    int depth_given = 0;
    if (lua_istable(L, 4)) {
        static const char *const keys[] = {"kind",     "width",      "height", "axis",   "at",    "range", "colormap",
                                           "grow",     "time_scale", "label",  "region", "depth", NULL};
        lua_pushnil(L);
        while (lua_next(L, 4)) { /* a misspelt option must not be silently ignored */
            int ok = 0;
            for (int k = 0; keys[k]; k++) ok |= lua_type(L, -2) == LUA_TSTRING && !strcmp(lua_tostring(L, -2), keys[k]);
            if (!ok)
                return luaL_error(L, "png: unknown option '%s' (valid: kind, width, height, axis, at, range, colormap, "
                                     "grow, time_scale, label, region, depth)",
                                  luaL_tolstring(L, -2, NULL));
            lua_pop(L, 1);
        }
        if (lua_getfield(L, 4, "kind") == LUA_TSTRING) kind = lua_tostring(L, -1);
        if (lua_getfield(L, 4, "width") == LUA_TNUMBER) d.width = (int)lua_tointeger(L, -1);
        if (lua_getfield(L, 4, "height") == LUA_TNUMBER) d.height = (int)lua_tointeger(L, -1);
        if (lua_getfield(L, 4, "axis") == LUA_TSTRING) {
            const char *a = lua_tostring(L, -1);
            d.axis = a[0] == 'x' ? 0 : a[0] == 'y' ? 1 : 2;
        }
        if (lua_getfield(L, 4, "at") == LUA_TNUMBER) d.at = lua_tonumber(L, -1);
        lua_pop(L, 5);
        int ts = lua_getfield(L, 4, "time_scale");
        if (ts == LUA_TNUMBER) d.time_scale = lua_tonumber(L, -1); /* hearth_render checks its range */
        else if (ts != LUA_TNIL)
            return luaL_error(L, "png: time_scale = the real seconds one simulated second stands for (a number), got %s",
                              luaL_typename(L, -1));
        lua_pop(L, 1);
        int t = lua_getfield(L, 4, "range");
        if (t == LUA_TSTRING && !strcmp(lua_tostring(L, -1), "frame")) d.range_mode = HEARTH_RANGE_FRAME;
        else if (t == LUA_TTABLE) range_pair(L, -1, "range", d.range), d.range_mode = HEARTH_RANGE_FIXED;
        else if (t != LUA_TNIL)
            return luaL_error(L, "png: range = {lo, hi} (the field's unit) or \"frame\" (each frame its own), got %s",
                              luaL_typename(L, -1));
        lua_pop(L, 1);
        if (lua_getfield(L, 4, "region") != LUA_TNIL) region_pair(L, -1, d.region);
        lua_pop(L, 1);
        t = lua_getfield(L, 4, "depth"); /* hearth_render checks its range and where it applies */
        if (t == LUA_TNUMBER) d.depth = lua_tonumber(L, -1), depth_given = 1;
        else if (t != LUA_TNIL)
            return luaL_error(L, "png: depth = a 3D particle picture's slab thickness (m), or math.huge for every "
                                 "particle, got %s", luaL_typename(L, -1));
        lua_pop(L, 1);
        if (lua_getfield(L, 4, "grow") == LUA_TTABLE && d.range_mode == HEARTH_RANGE_DEFAULT)
            range_pair(L, -1, "grow", d.range), d.range_mode = HEARTH_RANGE_GROW;
        lua_pop(L, 1);
        t = lua_getfield(L, 4, "colormap");
        if (t == LUA_TSTRING) d.colormap = lua_tostring(L, -1); /* stays on the stack while the picture is drawn */
        else if (t != LUA_TNIL) return luaL_error(L, "png: colormap = a name (%s), got %s", hearth_colormap_names(), luaL_typename(L, -1));
        t = lua_getfield(L, 4, "label"); /* stays on the stack while the picture is drawn; hearth_render checks it */
        if (t == LUA_TSTRING) d.label = lua_tostring(L, -1);
        else if (t != LUA_TNIL)
            return luaL_error(L, "png: label = a short text before the time in the title (a string), got %s", luaL_typename(L, -1));
    }
    /* A crust's colour is one particle deep: browning (and the surface's temperature and water it browned at) is
     * carried by the outermost particles alone. A slice samples the probe's kernel average, 1.5 dx wide, so it mixed
     * that particle with the crumb under it and drew the crust pale (#18, helper userfix9; userview4's item 6: the
     * physical pancake's browning.png drew its top pale while its line gave 0.247). Those fields default to the
     * particles, each in its own colour; every other field to the slice, as before. */
    if (!kind) kind = !strncmp(d.field, "browning", 8) ? "particles" : "slice";
    if (!strcmp(kind, "particles")) d.kind = HEARTH_PICTURE_PARTICLES;
    else if (strcmp(kind, "slice") != 0) return luaL_error(L, "png: kind = '%s'; valid: 'slice', 'particles'", kind);
    /* In 3D a particle picture is a projection along -z, the nearest particle on top: a browning picture showed the
     * front face's crust, brown all over, and not the ring a cut through the middle shows (Ding Fig. 18's halves;
     * #18, helper userfix11; userfix9's Left). Those fields draw a slab 2 dx thick about the middle plane (or
     * `at`) unless a depth is given: four particle layers at 8 a cell, so the cut shows no holes between discs (a
     * slab of one dx, two layers, showed white gaps in muffins.lua --set dim=3's risen batter), and thin beside a
     * muffin or a loaf (a 25 mm cup's wall lies 0.7 mm off the middle plane's at the slab's faces). Rejected: a
     * slice (it blurs the one-particle crust, above). Other fields keep the projection. */
    const hearth_scene_def *sd = hearth_scene_get_def(u->s);
    if (!depth_given && sd->dim == 3 && d.kind == HEARTH_PICTURE_PARTICLES && !strncmp(d.field, "browning", 8))
        d.depth = 2 * sd->dx;
    if (d.width < 64 || d.width > 8192) return luaL_error(L, "png: width = %d px; valid range [64, 8192]", d.width);
    if (d.height != 0 && (d.height < 64 || d.height > 8192))
        return luaL_error(L, "png: height = %d px; valid range [64, 8192]", d.height);
    hearth_error err;
    hearth_picture_info info;
    if (hearth_render(u->s, &d, path, &info, &err)) return hl_raise(L, &err);
    lua_pushstring(L, path);
    lua_createtable(L, 0, 11);
    set_numbers(L, "range", info.range, 2);
    set_numbers(L, "data", info.data, 2);
    set_numbers(L, "ticks", info.ticks, info.nticks);
    lua_pushstring(L, info.colormap);
    lua_setfield(L, -2, "colormap");
    lua_pushstring(L, info.unit);
    lua_setfield(L, -2, "unit");
    lua_pushinteger(L, info.width);
    lua_setfield(L, -2, "width");
    lua_pushinteger(L, info.height);
    lua_setfield(L, -2, "height");
    lua_pushstring(L, info.title);
    lua_setfield(L, -2, "title");
    /* where the plot lies in the picture and what it shows: a test or a caller finds a point's pixel */
    set_numbers(L, "area", info.area, 4);
    set_numbers(L, "view_lo", info.view_lo, 2);
    set_numbers(L, "view_hi", info.view_hi, 2);
    return 2;
}

/* core.colormap(name, t) -> r, g, b (0..255): a colour map's colour at t in
 * [0, 1]; an unknown name is an error naming the valid ones */
static int l_colormap(lua_State *L) {
    const char *name = luaL_checkstring(L, 1);
    unsigned char rgb[3];
    if (hearth_colormap_rgb(name, luaL_checknumber(L, 2), rgb))
        return luaL_error(L, "colormap '%s' is unknown; valid: %s", name, hearth_colormap_names());
    for (int k = 0; k < 3; k++) lua_pushinteger(L, rgb[k]);
    return 3;
}

static int dump(lua_State *L, const char *call, hearth_status (*fn)(const hearth_scene *, const char *, hearth_error *)) {
    hl_scene *u = hl_checkscene(L, 1);
    char buf[4096];
    const char *path = hl_out_path(L, call, luaL_checkstring(L, 2), HL_PATH_MKDIRS, buf, sizeof buf);
    hearth_error err;
    if (fn(u->s, path, &err)) return hl_raise(L, &err);
    lua_pushstring(L, path);
    return 1;
}
static int l_vtu(lua_State *L) { return dump(L, "s:vtu", hearth_write_vtu); }

/* s:_vtu_frame(path) -> the file the .pvd lists: s:run's VTU frame. On one
 * process path itself (s:vtu). Under mpirun every rank writes its particles
 * as a piece beside PATH.pvtu (path's .vtu replaced) and rank 0 the index,
 * without gathering the slabs (io_pvtu.c). A rank > 0 writes into its
 * scratch folder otherwise, so its piece goes to rank 0's output folder
 * (in_dir), checked there as rank 0 checks it. */
static int l_vtu_frame(lua_State *L) {
    if (hearth_ranks_size() == 1) return dump(L, "s:vtu", hearth_write_vtu);
    hl_scene *u = hl_checkscene_slabs(L, 1);
    size_t len;
    const char *given = luaL_checklstring(L, 2, &len);
    lua_pushlstring(L, given, len >= 4 && !strcmp(given + len - 4, ".vtu") ? len - 4 : len);
    lua_pushliteral(L, ".pvtu");
    lua_concat(L, 2);
    const char *index = lua_tostring(L, -1);
    const hl_options *o = hl_opts(L);
    char buf[4096];
    const char *path = out_path_in(L, o->in_dir ? o->in_dir : o->out_dir, "s:run{vtu = ...}", index, HL_PATH_MKDIRS, buf, sizeof buf);
    hearth_error err;
    if (hearth_write_vtu_pieces(u->s, path, &err)) return hl_raise(L, &err);
    lua_pushstring(L, path);
    return 1;
}

/* s:ply(path [, {color = "temperature" | false, range = {lo, hi}, colormap = "viridis"}]) */
static int l_ply(lua_State *L) {
    hl_scene *u = hl_checkscene(L, 1);
    char buf[4096];
    const char *path = hl_out_path(L, "s:ply", luaL_checkstring(L, 2), HL_PATH_MKDIRS, buf, sizeof buf);
    hearth_ply_def def = hearth_default_ply_def();
    if (lua_istable(L, 3)) {
        static const char *const keys[] = {"color", "range", "colormap", NULL};
        lua_pushnil(L);
        while (lua_next(L, 3)) { /* a misspelt option must not be silently ignored */
            int ok = 0;
            for (int k = 0; keys[k]; k++) ok |= lua_type(L, -2) == LUA_TSTRING && !strcmp(lua_tostring(L, -2), keys[k]);
            if (!ok) return luaL_error(L, "s:ply: unknown option '%s' (valid: color, range, colormap)", luaL_tolstring(L, -2, NULL));
            lua_pop(L, 1);
        }
        int t = lua_getfield(L, 3, "color");
        if (t == LUA_TBOOLEAN) def.color = lua_toboolean(L, -1);
        else if (t == LUA_TSTRING) def.color_field = lua_tostring(L, -1);
        else if (t != LUA_TNIL) return luaL_error(L, "s:ply: color = \"field name\" or false, got %s", luaL_typename(L, -1));
        t = lua_getfield(L, 3, "range");
        if (t == LUA_TTABLE) {
            lua_geti(L, -1, 1);
            lua_geti(L, -2, 2);
            if (!lua_isnumber(L, -2) || !lua_isnumber(L, -1) || !(lua_tonumber(L, -2) < lua_tonumber(L, -1)))
                return luaL_error(L, "s:ply: range = {lo, hi} with lo < hi (in the field's unit)");
            def.range[0] = lua_tonumber(L, -2);
            def.range[1] = lua_tonumber(L, -1);
            lua_pop(L, 2);
        } else if (t != LUA_TNIL) return luaL_error(L, "s:ply: range = {lo, hi}, got %s", luaL_typename(L, -1));
        t = lua_getfield(L, 3, "colormap");
        if (t == LUA_TSTRING) def.colormap = lua_tostring(L, -1);
        else if (t != LUA_TNIL) return luaL_error(L, "s:ply: colormap = \"viridis\", got %s", luaL_typename(L, -1));
        /* the strings stay on the stack (anchored by the table) until the write is done */
    }
    hearth_error err;
    if (hearth_write_ply_with(u->s, path, &def, &err)) return hl_raise(L, &err);
    lua_pushstring(L, path);
    return 1;
}
static int l_save(lua_State *L) { return dump(L, "s:save", hearth_scene_save); }

/* core.write_atomic(path, text [, call]): for CSV series and anything else a
 * scene writes; call names the Lua function in messages (default h.write) */
static int l_write_atomic(lua_State *L) {
    size_t len;
    char buf[4096];
    const char *call = luaL_optstring(L, 3, "h.write");
    const char *path = hl_out_path(L, call, luaL_checkstring(L, 1), HL_PATH_MKDIRS, buf, sizeof buf);
    const char *text = luaL_checklstring(L, 2, &len);
    hearth_error err;
    hearth_atomic_file *af = hearth_atomic_file_open(path, &err);
    if (!af) return hl_raise(L, &err);
    hearth_atomic_file_write(af, text, len); /* a failed write is reported by the commit, with its cause */
    if (hearth_atomic_file_commit(af, &err)) return hl_raise(L, &err);
    lua_pushstring(L, path);
    return 1;
}

/* core.read_text(path [, head]) -> the text of a file an earlier run left in the output folder (read as h.load
 * reads: a relative path from the output folder, under mpirun rank 0's), or nil when there is none or it is over
 * 64 MB; with head, its first head bytes at most (a PNG's title, a PLY's header). s:run reads a restored scene's
 * .pvd, CSV, PNG and PLY frames with it, to continue their series (run.lua). */
static int l_read_text(lua_State *L) {
    char buf[4096];
    const char *path = hl_in_path(L, luaL_checkstring(L, 1), buf, sizeof buf);
    lua_Integer head = luaL_optinteger(L, 2, 0);
    FILE *f = fopen(path, "rb");
    if (!f) return 0;
    luaL_Buffer b;
    luaL_buffinit(L, &b);
    size_t n, total = 0, cap = (size_t)64 << 20, want = head > 0 && (size_t)head < cap ? (size_t)head : 0;
    char chunk[8192];
    while ((n = fread(chunk, 1, want && want - total < sizeof chunk ? want - total : sizeof chunk, f)) > 0 &&
           (total += n) <= cap) {
        luaL_addlstring(&b, chunk, n);
        if (want && total >= want) break;
    }
    int bad = ferror(f) || total > cap;
    fclose(f);
    luaL_pushresult(&b);
    if (bad) lua_pushnil(L);
    return 1;
}

/* Encode the PNG frames in_pattern % first .. first+count-1 (a printf pattern
 * with one %d or %0Nd) into the movie out_path with the ffmpeg program.
 * ffmpeg runs from an argv, never through a shell, since both paths are the
 * user's. It writes a temp file beside the movie (same extension, so ffmpeg
 * picks the same container), renamed over the movie when it is whole.
 * shown is the movie's name in messages (as the user wrote it). Returns 0
 * written, 1 ffmpeg is not installed (msg says so and where the frames are:
 * a missing encoder is not a failed run), -1 a failed encode (msg). */
int hl_movie_encode(const char *in, long first, long count, const char *out, double fps, const char *shown, char *msg,
                    size_t n) {
    char tmp[4200], in_arg[4200], out_arg[4300], first_s[32], count_s[32], fps_s[32];
    const char *slash = strrchr(out, '/'), *base = slash ? slash + 1 : out;
    const char *ext = strrchr(base, '.');
    snprintf(tmp, sizeof tmp, "%.*s.%s.tmp%ld%s", (int)(base - out), out, base, (long)getpid(), ext ? ext : "");
    /* a leading "./" keeps a relative path that starts with '-' from reading as an option */
    snprintf(in_arg, sizeof in_arg, "%s%s", in[0] == '/' ? "" : "./", in);
    snprintf(out_arg, sizeof out_arg, "file:%s", tmp); /* file: keeps "x:y.mp4" from naming a protocol */
    snprintf(first_s, sizeof first_s, "%ld", first);
    snprintf(count_s, sizeof count_s, "%ld", count);
    snprintf(fps_s, sizeof fps_s, "%.9g", fps);
    char *argv[] = {"ffmpeg", "-nostdin", "-hide_banner", "-loglevel", "error", "-y", "-framerate", fps_s,
                    "-f", "image2", "-pattern_type", "sequence", /* never a glob: '*' in a folder name stays literal */
                    "-start_number", first_s, "-i", in_arg, "-frames:v", count_s,
                    /* libx264 with yuv420p needs even sizes: pad one pixel where odd */
                    "-vf", "pad=ceil(iw/2)*2:ceil(ih/2)*2", "-c:v", "libx264", "-pix_fmt", "yuv420p", out_arg, NULL};
    pid_t pid;
    int rc = posix_spawnp(&pid, "ffmpeg", NULL, NULL, argv, environ);
    if (rc == ENOENT || rc == EACCES) {
        char dir[4096];
        snprintf(dir, sizeof dir, "%s", in);
        char *ds = strrchr(dir, '/');
        if (ds) *ds = '\0';
        else snprintf(dir, sizeof dir, ".");
        snprintf(msg, n, "movie %s not written: the ffmpeg program is not installed (Debian package ffmpeg); the frames are in %s",
                 shown, dir);
        return 1;
    }
    if (rc) return snprintf(msg, n, "movie %s: cannot start ffmpeg: %s", shown, strerror(rc)), -1;
    int status;
    while (waitpid(pid, &status, 0) < 0)
        if (errno != EINTR) return snprintf(msg, n, "movie %s: waiting for ffmpeg: %s", shown, strerror(errno)), -1;
    if (!WIFEXITED(status) || WEXITSTATUS(status)) {
        remove(tmp);
        if (WIFSIGNALED(status))
            return snprintf(msg, n, "movie %s not written: ffmpeg was killed by signal %d", shown, WTERMSIG(status)), -1;
        snprintf(msg, n, "movie %s not written: ffmpeg exited with status %d (its message is above); the frames are "
                         "%s from number %ld", shown, WEXITSTATUS(status), in, first);
        return -1;
    }
    if (rename(tmp, out)) {
        int e = errno;
        remove(tmp);
        return snprintf(msg, n, "movie %s: cannot rename the finished file into place: %s", shown, strerror(e)), -1;
    }
    return 0;
}

/* core.movie(pattern, first, count, path, fps): hl_movie_encode of the
 * frames (pattern relative to the output folder) into the movie path (through
 * hl_out_path). Returns true, or false and a message when ffmpeg is not
 * installed (the frames stay). A failed encode raises. */
static int l_movie(lua_State *L) {
    const char *pattern = luaL_checkstring(L, 1);
    lua_Integer first = luaL_checkinteger(L, 2), count = luaL_checkinteger(L, 3);
    const char *path = luaL_checkstring(L, 4);
    double fps = luaL_checknumber(L, 5);
    char in[4096], out[4096], msg[9000];
    hl_in_path(L, pattern, in, sizeof in);
    if (!hl_out_path(L, "movie", path, HL_PATH_MKDIRS, out, sizeof out)) return 0;
    int rc = hl_movie_encode(in, (long)first, (long)count, out, fps, path, msg, sizeof msg);
    if (rc < 0) return luaL_error(L, "%s", msg);
    if (rc == 1) {
        fprintf(stderr, "hearth: %s\n", msg); /* a notice, not an error: the run goes on */
        lua_pushboolean(L, 0);
        lua_pushstring(L, msg);
        return 2;
    }
    lua_pushboolean(L, 1);
    return 1;
}

void hl_open_output(lua_State *L) {
    luaL_getmetatable(L, HL_SCENE);
    lua_getfield(L, -1, "__index");
    static const luaL_Reg methods[] = {{"png", l_png}, {"vtu", l_vtu}, {"_vtu_frame", l_vtu_frame}, {"ply", l_ply}, {"save", l_save}, {NULL, NULL}};
    luaL_setfuncs(L, methods, 0);
    lua_pop(L, 2);
    lua_pushcfunction(L, l_write_atomic);
    lua_setfield(L, -2, "write_atomic");
    lua_pushcfunction(L, l_read_text);
    lua_setfield(L, -2, "read_text");
    lua_pushcfunction(L, l_colormap);
    lua_setfield(L, -2, "colormap");
    lua_pushcfunction(L, l_movie);
    lua_setfield(L, -2, "movie");
}

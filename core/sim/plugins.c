/* plugins.c: find, dlopen, validate and cache material plugins.
 *
 * A plugin is trusted only after every field of its descriptor has been
 * checked (Redis-modules style: one entry symbol, RTLD_NOW|RTLD_LOCAL,
 * dlclose and a specific reason on any failure). Loaded plugins stay loaded
 * until exit: the core keeps pointers to their callbacks and static strings,
 * so unloading would be a use-after-free waiting to happen.
 *
 * Not thread-safe: plugins are loaded while a scene is being built, from one
 * thread; the step loop only calls into already-loaded descriptors. */
#ifndef _XOPEN_SOURCE
#define _XOPEN_SOURCE 700 /* realpath, PATH_MAX, dirent */
#endif
#include "plugins.h"

#include <dirent.h>
#include <dlfcn.h>
#include <elf.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "alloc.h"
#include "error.h"

/* Empty means "no such folder": a build without a plugin folder (or an
 * uninstalled library) simply skips that entry of the path. */
#ifndef HEARTH_BUILD_PLUGIN_DIR
#define HEARTH_BUILD_PLUGIN_DIR ""
#endif
#ifndef HEARTH_INSTALL_PLUGIN_DIR
#define HEARTH_INSTALL_PLUGIN_DIR ""
#endif

struct hearth_plugin {
    char *path;  /* resolved (realpath), the cache key */
    void *handle;
    plugin_desc desc;
};

/* Each plugin is its own block, so the pointers handed out stay valid when
 * the registry array grows. */
static hearth_plugin **g_loaded;
static int g_nloaded, g_caploaded;
static char **g_added; /* folders from hearth_plugin_path_add, in call order */
static int g_nadded, g_capadded;
/* hearth_plugin_restrict: an untrusted scene is running. Plugins load only by
 * name, and not from the folder it can write (its realpath, or "" for none). */
static int g_restricted;
static char g_writable[PATH_MAX];

_Thread_local plugin_call plugin_current_call __attribute__((tls_model("initial-exec")));

int hearth_plugin_loaded_count(void) { return g_nloaded; }
const hearth_plugin *hearth_plugin_loaded(int i) { return i >= 0 && i < g_nloaded ? g_loaded[i] : NULL; }

void hearth_plugin_call_enter(const hearth_material *m, const char *callback) { plugin_call_enter(m, callback); }
void hearth_plugin_call_leave(void) { plugin_call_leave(); }

/* Called from signal handlers: no locks, no allocation, only reads. The
 * registry is written only while scenes are built (one thread), never while
 * a callback runs. */
int hearth_plugin_call_current(hearth_plugin_call_info *out) {
    const plugin_call c = plugin_current_call;
    if (!c.callback) return 0;
    const char *file = c.file;
    for (int i = 0; !file && c.m && i < g_nloaded; i++)
        if (&g_loaded[i]->desc.mat == c.m) file = g_loaded[i]->path;
    *out = (hearth_plugin_call_info){
        .material = c.m && c.m->name ? c.m->name : "(unknown)",
        .file = file ? file : "",
        .callback = c.callback,
        .context = c.context ? c.context : "",
    };
    return 1;
}

/* ---- growable arrays of pointers ------------------------------------ */

/* arrp points to an array of pointers (char **, hearth_plugin **, ...). The
 * pointer is moved with memcpy rather than a (void ***) cast, which would
 * break strict aliasing. */
static int plugin_grow(void *arrp, int *cap, int need) {
    if (need <= *cap) return 0;
    int ncap = *cap ? *cap * 2 : 8;
    while (ncap < need) ncap *= 2;
    void *old;
    memcpy(&old, arrp, sizeof old);
    void *n = mem_realloc(old, (size_t)*cap * sizeof(void *), (size_t)ncap * sizeof(void *));
    if (!n) return -1;
    memcpy(arrp, &n, sizeof n);
    *cap = ncap;
    return 0;
}

/* ---- the search path ------------------------------------------------- */

typedef struct plugin_dirs {
    char **dir;
    int n, cap;
} plugin_dirs;

static void plugin_dirs_free(plugin_dirs *d) {
    for (int i = 0; i < d->n; i++) mem_strfree(d->dir[i]);
    mem_free(d->dir, (size_t)d->cap * sizeof *d->dir);
    *d = (plugin_dirs){0};
}

/* Empty entries (as in "a::b") and repeats are dropped: a repeat can never
 * win and would only lengthen the "not found" message. */
static int plugin_dirs_push(plugin_dirs *d, const char *s, size_t len) {
    if (len == 0) return 0;
    for (int i = 0; i < d->n; i++)
        if (strlen(d->dir[i]) == len && memcmp(d->dir[i], s, len) == 0) return 0;
    if (plugin_grow(&d->dir, &d->cap, d->n + 1)) return -1;
    char *c = mem_alloc(len + 1);
    if (!c) return -1;
    memcpy(c, s, len);
    c[len] = '\0';
    d->dir[d->n++] = c;
    return 0;
}

/* Order: build folder, install folder, $HEARTH_PLUGIN_PATH, added folders.
 * The build folder comes first so a developer running from the tree gets the
 * plugins they just compiled, not stale installed ones. */
static int plugin_dirs_build(plugin_dirs *d) {
    *d = (plugin_dirs){0};
    const char *fixed[2] = {HEARTH_BUILD_PLUGIN_DIR, HEARTH_INSTALL_PLUGIN_DIR};
    for (int i = 0; i < 2; i++)
        if (plugin_dirs_push(d, fixed[i], strlen(fixed[i]))) goto nomem;
    const char *env = getenv("HEARTH_PLUGIN_PATH");
    while (env && *env) {
        const char *colon = strchr(env, ':');
        size_t len = colon ? (size_t)(colon - env) : strlen(env);
        if (plugin_dirs_push(d, env, len)) goto nomem;
        env = colon ? colon + 1 : NULL;
    }
    for (int i = 0; i < g_nadded; i++)
        if (plugin_dirs_push(d, g_added[i], strlen(g_added[i]))) goto nomem;
    return 0;
nomem:
    plugin_dirs_free(d);
    return -1;
}

void hearth_plugin_path_add(const char *dir) {
    if (!dir || !*dir) return;
    for (int i = 0; i < g_nadded; i++)
        if (strcmp(g_added[i], dir) == 0) return;
    /* The API returns nothing, so out of memory just leaves the path as it
     * was; a later load then reports the folders it did search. */
    if (plugin_grow(&g_added, &g_capadded, g_nadded + 1)) return;
    char *c = mem_strdup(dir);
    if (c) g_added[g_nadded++] = c;
}

/* dir + "/" + file into out; 0 when it fits. */
static int plugin_join(char *out, size_t cap, const char *dir, const char *file) {
    size_t n = strlen(dir);
    const char *sep = (n > 0 && dir[n - 1] == '/') ? "" : "/";
    int w = snprintf(out, cap, "%s%s%s", dir, sep, file);
    return (w < 0 || (size_t)w >= cap) ? -1 : 0;
}

static int plugin_is_file(const char *path) {
    struct stat st;
    return stat(path, &st) == 0 && S_ISREG(st.st_mode);
}

/* Resolve a bare name to the first hearth_<name>.so on the path. */
static hearth_status plugin_find(const char *name, char *out, size_t cap, hearth_error *err) {
    char file[256]; /* NAME_MAX on every system we target */
    int w = snprintf(file, sizeof file, "hearth_%s.so", name);
    if (w < 0 || (size_t)w >= sizeof file)
        return err_set(err, HEARTH_ERR_PLUGIN, "%s: plugin name is too long for a file name", name);
    plugin_dirs d;
    if (plugin_dirs_build(&d))
        return err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory building the plugin search path", name);
    for (int i = 0; i < d.n; i++) {
        if (plugin_join(out, cap, d.dir[i], file) == 0 && plugin_is_file(out)) {
            plugin_dirs_free(&d);
            return HEARTH_OK;
        }
    }
    char list[768] = "";
    size_t used = 0;
    for (int i = 0; i < d.n && used < sizeof list; i++) {
        int k = snprintf(list + used, sizeof list - used, "%s%s", i ? ", " : "", d.dir[i]);
        if (k < 0) break;
        used += (size_t)k;
    }
    /* A user who typed "foo.so" meant a file; say how to give one. */
    size_t nl = strlen(name);
    int looks_like_file = nl > 3 && strcmp(name + nl - 3, ".so") == 0;
    err_set(err, HEARTH_ERR_PLUGIN,
            "%s: plugin not found: no %s in %s%s; %s HEARTH_PLUGIN_PATH (colon separated), or %s%s%s%s",
            name, file, d.n ? "the search path: " : "any folder (the search path is empty)", list,
            d.n ? "put the file in one of these folders, add its folder to" : "add the plugin's folder to",
            g_restricted ? "run with --trust to load a file by its path" : "give a path containing '/'",
            looks_like_file && !g_restricted ? " (for this file: ./" : "", looks_like_file && !g_restricted ? name : "",
            looks_like_file && !g_restricted ? ")" : "");
    plugin_dirs_free(&d);
    return HEARTH_ERR_PLUGIN;
}

/* ---- descriptor validation ------------------------------------------ */

int plugin_param_index(const hearth_material *m, const char *name) {
    for (int i = 0; i < m->nparams; i++)
        if (m->params[i].name && strcmp(m->params[i].name, name) == 0) return i;
    return -1;
}

/* Material names are [a-z0-9_]+ (material.h). Parameter names become Lua
 * table keys ({E = 2e4}), so they follow Lua's identifier rule. */
static int plugin_ident_ok(const char *s, int lua_ident) {
    if (!s || !*s) return 0;
    for (const char *c = s; *c; c++) {
        int lower = (*c >= 'a' && *c <= 'z') || *c == '_';
        int digit = *c >= '0' && *c <= '9';
        int upper = *c >= 'A' && *c <= 'Z';
        int ok = lua_ident ? (lower || upper || (digit && c != s)) : (lower || digit);
        if (!ok) return 0;
    }
    return 1;
}

void plugin_desc_free(plugin_desc *d) {
    if (!d) return;
    mem_free(d->params, (size_t)d->mat.nparams * sizeof *d->params);
    *d = (plugin_desc){0};
}

/* The bytes of a v1 descriptor up to and including describe_error: every
 * required field. plastic_J (appended later) is optional. */
#define PLUGIN_V1_MIN_SIZE (offsetof(hearth_material, describe_error) + sizeof(((hearth_material *)0)->describe_error))
/* Bounds a descriptor must respect before the loader allocates for it: the
 * core's per-particle parameter buffer (scene.h SCENE_MAX_PARAMS) and a
 * state far beyond any law's (cam_clay_dough keeps 7 doubles). */
#define PLUGIN_MAX_PARAMS 256
#define PLUGIN_MAX_STATE 4096
#define PLUGIN_KNOWN_NEEDS                                                                         \
    (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_POROSITY | HEARTH_NEEDS_SATURATION |                  \
     HEARTH_NEEDS_THERMAL_EXPANSION | HEARTH_NEEDS_DIM | HEARTH_NEEDS_MEMO)

static hearth_status plugin_check_params(const char *shown, const hearth_material *m, hearth_error *err) {
    const hearth_param *ps = m->params;
    for (int i = 0; i < m->nparams; i++) {
        const hearth_param *q = &ps[i];
        if (!plugin_ident_ok(q->name, 1))
            return err_set(err, HEARTH_ERR_PLUGIN,
                           "%s: parameter %d has %s name \"%s\"; names are identifiers [A-Za-z_][A-Za-z0-9_]* "
                           "used from Lua",
                           shown, i, q->name ? "an invalid" : "a NULL", q->name ? q->name : "");
        if (!q->unit)
            return err_set(err, HEARTH_ERR_PLUGIN,
                           "%s: parameter '%s' has a NULL unit; give its SI unit (\"1\" if dimensionless)",
                           shown, q->name);
        if (!isfinite(q->min) || !isfinite(q->max))
            return err_set(err, HEARTH_ERR_PLUGIN,
                           "%s: parameter '%s' has non-finite bounds [%g, %g] %s; give finite min and max",
                           shown, q->name, q->min, q->max, q->unit);
        if (q->min > q->max)
            return err_set(err, HEARTH_ERR_PLUGIN,
                           "%s: parameter '%s' has min %g > max %g (%s); swap or fix the bounds", shown,
                           q->name, q->min, q->max, q->unit);
        if (!(q->def >= q->min && q->def <= q->max))
            return err_set(err, HEARTH_ERR_PLUGIN,
                           "%s: parameter '%s' default %g %s is outside its own range [%g, %g] %s", shown,
                           q->name, q->def, q->unit, q->min, q->max, q->unit);
        for (int j = 0; j < i; j++)
            if (strcmp(ps[j].name, q->name) == 0)
                return err_set(err, HEARTH_ERR_PLUGIN,
                               "%s: duplicate parameter name '%s' (entries %d and %d); names must be unique",
                               shown, q->name, j, i);
        /* A scene names core and plugin parameters in one table ({density = 500,
         * porosity = 0.3}); params_resolve looks in the plugin's schema first, so
         * a plugin entry with a core name would silently hide the core's. */
        int ncore = 0;
        const hearth_param *core = hearth_core_params(&ncore);
        for (int c = 0; c < ncore; c++)
            if (strcmp(core[c].name, q->name) == 0) {
                char list[512] = "";
                for (int k = 0; k < ncore; k++) {
                    if (k) strncat(list, ", ", sizeof list - strlen(list) - 1);
                    strncat(list, core[k].name, sizeof list - strlen(list) - 1);
                }
                return err_set(err, HEARTH_ERR_PLUGIN,
                               "%s: parameter '%s' clashes with the core parameter '%s' (%s, %s) that every "
                               "material accepts; rename the plugin's parameter (reserved names: %s)",
                               shown, q->name, core[c].name, core[c].unit, core[c].help, list);
            }
    }
    int d = plugin_param_index(m, "density");
    if (d < 0)
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: material '%s' has no parameter named \"density\" (unit kg/m^3); the core needs "
                       "it to give particles mass",
                       shown, m->name);
    if (strcmp(ps[d].unit, "kg/m^3") != 0)
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: parameter 'density' has unit \"%s\"; it must be \"kg/m^3\" (the core computes "
                       "particle mass from it)",
                       shown, ps[d].unit);
    if (!(ps[d].min > 0))
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: parameter 'density' has min %g kg/m^3; it must be > 0 so every particle has mass",
                       shown, ps[d].min);
    return HEARTH_OK;
}

/* "E = 0.01 Pa, nu = 0 1, density = 1 kg/m^3" into buf (cut with "..." when long). */
static void plugin_format_params(const hearth_material *c, const double *p, char *buf, size_t cap) {
    size_t used = 0;
    buf[0] = '\0';
    for (int i = 0; i < c->nparams; i++) {
        int k = snprintf(buf + used, cap - used, "%s%s = %g %s", i ? ", " : "", c->params[i].name, p[i],
                         c->params[i].unit);
        if (k < 0 || (size_t)k >= cap - used) {
            if (cap > 4) memcpy(buf + cap - 4, "...", 4);
            return;
        }
        used += (size_t)k;
    }
}

/* The step size is cfl dx / (speed + wave speed): a wave speed that is NaN,
 * infinite, zero or negative anywhere in the schema's range gives a step of
 * 0 or NaN, or no CFL limit at all. Evaluate init and wave_speed at the
 * defaults, at each parameter's min and max (the rest at defaults), and with
 * every parameter at its min and at its max, before the plugin is trusted.
 * The rest of the range is the run-time guard's (mpm.c P2G). */
static hearth_status plugin_check_wave_corners(const char *shown, const hearth_material *raw, const hearth_material *c,
                                               hearth_error *err) {
    const int np = c->nparams, ns = c->state_size;
    double *p = mem_alloc(sizeof(double) * (size_t)(np > 0 ? np : 1));
    double *state = mem_alloc(sizeof(double) * (size_t)(ns > 0 ? ns : 1));
    if (!p || !state) {
        mem_free(p, sizeof(double) * (size_t)(np > 0 ? np : 1));
        mem_free(state, sizeof(double) * (size_t)(ns > 0 ? ns : 1));
        return err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory checking the wave speed", shown);
    }
    hearth_status st = HEARTH_OK;
    plugin_call_set_context(shown, "the loader's wave-speed check at the schema's corners");
    /* corner k: 0 defaults; 1..2np one parameter at min (odd) or max (even); then all-min, all-max */
    for (int k = 0; k < 2 * np + 3 && st == HEARTH_OK; k++) {
        const char *which = "at the defaults";
        char label[160];
        for (int i = 0; i < np; i++) p[i] = c->params[i].def;
        if (k >= 1 && k <= 2 * np) {
            const int i = (k - 1) / 2, hi = (k - 1) % 2;
            p[i] = hi ? c->params[i].max : c->params[i].min;
            snprintf(label, sizeof label, "with %s at its %s (the rest at defaults)", c->params[i].name, hi ? "max" : "min");
            which = label;
        } else if (k > 2 * np) {
            const int hi = k == 2 * np + 2;
            for (int i = 0; i < np; i++) p[i] = hi ? c->params[i].max : c->params[i].min;
            which = hi ? "with every parameter at its max" : "with every parameter at its min";
        }
        for (int i = 0; i < ns; i++) state[i] = 0;
        plugin_call_enter(raw, "init");
        c->init(p, state); /* a buffer even when state_size is 0: the core never passes NULL to init */
        plugin_call_enter(raw, "wave_speed");
        const double w = c->wave_speed(p, ns > 0 ? state : NULL);
        plugin_call_leave();
        if (!(isfinite(w) && w > 0)) {
            char vals[600];
            plugin_format_params(c, p, vals, sizeof vals);
            st = err_set(err, HEARTH_ERR_PLUGIN,
                         "%s: material '%s': wave_speed is %g m/s %s (%s); it must be finite and > 0 over the "
                         "whole parameter range, or no stable step exists (fix wave_speed or narrow the range)",
                         shown, c->name, w, which, vals);
        }
    }
    plugin_call_set_context(NULL, NULL);
    mem_free(p, sizeof(double) * (size_t)(np > 0 ? np : 1));
    mem_free(state, sizeof(double) * (size_t)(ns > 0 ? ns : 1));
    return st;
}

hearth_status plugin_describe(const char *shown, const hearth_material *m, plugin_desc *out, hearth_error *err) {
    *out = (plugin_desc){0};
    if (!m)
        return err_set(err, HEARTH_ERR_PLUGIN, "%s: %s() returned NULL; it must return a static descriptor",
                       shown, HEARTH_MATERIAL_ENTRY_NAME);
    /* abi_version, struct_size and real_size lead every version of the
     * struct, so they are safe to read before anything else. */
    if (m->abi_version != HEARTH_MATERIAL_ABI)
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: built for material ABI %d, this hearth expects %d; rebuild against this hearth's "
                       "<hearth/material.h>",
                       shown, m->abi_version, HEARTH_MATERIAL_ABI);
    if (m->struct_size < 0 || (size_t)m->struct_size < PLUGIN_V1_MIN_SIZE)
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: descriptor struct_size is %d bytes, smaller than the %zu bytes of a material ABI "
                       "%d descriptor through describe_error; set struct_size = sizeof(hearth_material) and "
                       "rebuild against this hearth's <hearth/material.h>",
                       shown, m->struct_size, (size_t)PLUGIN_V1_MIN_SIZE, HEARTH_MATERIAL_ABI);
    if (m->real_size != (int)sizeof(double))
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: built with %d-byte reals, this hearth uses %zu-byte double; set real_size = "
                       "sizeof(double) and rebuild with double precision",
                       shown, m->real_size, sizeof(double));

    /* Copy only what the plugin declared: fields appended after its build
     * stay zero (NULL optional callbacks), and a newer plugin's extra fields
     * are ignored rather than read past our struct. */
    hearth_material c;
    memset(&c, 0, sizeof c);
    size_t n = (size_t)m->struct_size < sizeof c ? (size_t)m->struct_size : sizeof c;
    memcpy(&c, m, n);

    if (!c.name)
        return err_set(err, HEARTH_ERR_PLUGIN, "%s: descriptor name is NULL; give a short identifier [a-z0-9_]+",
                       shown);
    if (!plugin_ident_ok(c.name, 0))
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: material name \"%s\" is not an identifier [a-z0-9_]+ (it is used from Lua)", shown,
                       c.name);
    if (c.nparams < 0)
        return err_set(err, HEARTH_ERR_PLUGIN, "%s: material '%s' has negative nparams (%d)", shown, c.name,
                       c.nparams);
    if (c.nparams > 0 && !c.params)
        return err_set(err, HEARTH_ERR_PLUGIN, "%s: material '%s' has nparams = %d but params is NULL", shown,
                       c.name, c.nparams);
    if (c.state_size < 0)
        return err_set(err, HEARTH_ERR_PLUGIN, "%s: material '%s' has negative state_size (%d)", shown, c.name,
                       c.state_size);
    if (c.needs & ~(unsigned)PLUGIN_KNOWN_NEEDS)
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: material '%s' needs fields 0x%x unknown to this hearth (known bits 0x%x); rebuild "
                       "against this hearth's <hearth/material.h>",
                       shown, c.name, c.needs & ~(unsigned)PLUGIN_KNOWN_NEEDS, (unsigned)PLUGIN_KNOWN_NEEDS);
    const char *missing = !c.init         ? "init"
                          : !c.stress     ? "stress"
                          : !c.wave_speed ? "wave_speed"
                          : !c.describe_error ? "describe_error"
                                              : NULL;
    if (missing)
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: material '%s' has required callback '%s' set to NULL; every plugin must provide "
                       "init, stress, wave_speed and describe_error",
                       shown, c.name, missing);
    if (c.state_size > PLUGIN_MAX_STATE)
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: material '%s' has state_size %d doubles per point; at most %d are allowed", shown,
                       c.name, c.state_size, PLUGIN_MAX_STATE);
    if (c.nparams > PLUGIN_MAX_PARAMS)
        return err_set(err, HEARTH_ERR_PLUGIN, "%s: material '%s' has %d parameters; at most %d are allowed",
                       shown, c.name, c.nparams, PLUGIN_MAX_PARAMS);
    /* rule 10: the memo comes with stress_block and its needs bit, each with the other */
    if (c.memo_size < 0 || c.memo_size > HEARTH_MEMO_MAX)
        return err_set(err, HEARTH_ERR_PLUGIN, "%s: material '%s' has memo_size %d doubles per point; valid range 0..%d",
                       shown, c.name, c.memo_size, HEARTH_MEMO_MAX);
    if (c.memo_size > 0 && (!c.stress_block || !(c.needs & HEARTH_NEEDS_MEMO)))
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: material '%s' has memo_size %d but %s; the memo is stress_block's and read under "
                       "HEARTH_NEEDS_MEMO (<hearth/material.h> rule 10)",
                       shown, c.name, c.memo_size, !c.stress_block ? "no stress_block" : "not HEARTH_NEEDS_MEMO");
    if (c.memo_size == 0 && (c.needs & HEARTH_NEEDS_MEMO))
        return err_set(err, HEARTH_ERR_PLUGIN,
                       "%s: material '%s' sets HEARTH_NEEDS_MEMO with memo_size 0; give memo_size 1..%d or drop the bit",
                       shown, c.name, HEARTH_MEMO_MAX);
    hearth_status st = plugin_check_params(shown, &c, err);
    if (st != HEARTH_OK) return st;
    if ((st = plugin_check_wave_corners(shown, m, &c, err)) != HEARTH_OK) return st;

    /* Own a copy of the schema so the core never meets a NULL help or summary. */
    if (c.nparams > 0) {
        out->params = mem_alloc((size_t)c.nparams * sizeof *out->params);
        if (!out->params)
            return err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory copying the parameter schema", shown);
        memcpy(out->params, c.params, (size_t)c.nparams * sizeof *out->params);
        for (int i = 0; i < c.nparams; i++)
            if (!out->params[i].help) out->params[i].help = "";
    }
    if (!c.summary) c.summary = "";
    /* <hearth/material.h> rule 7: HEARTH_PLUGIN_NO_BATCH=1 runs a scene on the one-point stress alone,
     * to compare the two paths' outputs byte for byte */
    const char *nb = getenv("HEARTH_PLUGIN_NO_BATCH");
    if (nb && *nb && strcmp(nb, "0") != 0) c.stress_block = NULL, c.scalars_block = NULL, c.memo_size = 0; /* rules 9, 10: with stress_block only */
    c.params = out->params;
    out->mat = c;
    out->density = plugin_param_index(&c, "density");
    return HEARTH_OK;
}

/* ---- loading ---------------------------------------------------------- */

static hearth_plugin *plugin_cached(const char *real) {
    for (int i = 0; i < g_nloaded; i++)
        if (strcmp(g_loaded[i]->path, real) == 0) return g_loaded[i];
    return NULL;
}

/* dlopen maps a file's segments as the headers describe them; a file cut
 * short (an interrupted copy) then faults with SIGBUS when the loader touches
 * a page past its end. Check that the headers and every loaded segment lie
 * inside the file first, so a truncated plugin is a message, not a crash. */
static hearth_status plugin_elf_check(const char *shown, const char *real, hearth_error *err) {
    FILE *f = fopen(real, "rb");
    if (!f) return err_set(err, HEARTH_ERR_PLUGIN, "%s: cannot open the plugin file (%s)", shown, strerror(errno));
    Elf64_Ehdr eh;
    struct stat st;
    hearth_status rc = HEARTH_OK;
    const char *why = NULL;
    char detail[160] = "";
    if (fstat(fileno(f), &st) != 0 || fread(&eh, sizeof eh, 1, f) != 1) {
        why = "too short for an ELF header";
    } else if (memcmp(eh.e_ident, ELFMAG, SELFMAG) != 0) {
        why = "not an ELF file";
    } else if (eh.e_ident[EI_CLASS] != ELFCLASS64 || sizeof(void *) != 8) {
        why = "not a 64-bit ELF object (this hearth is 64-bit)";
    } else if (eh.e_type != ET_DYN) {
        why = "not a shared object (ELF type is not ET_DYN)";
    } else if (eh.e_phentsize != sizeof(Elf64_Phdr) || eh.e_phnum == 0 || eh.e_phnum > 4096) {
        why = "its program header table is malformed";
    } else {
        const unsigned long long size = (unsigned long long)st.st_size;
        const unsigned long long ph_end = (unsigned long long)eh.e_phoff + (unsigned long long)eh.e_phnum * sizeof(Elf64_Phdr);
        const unsigned long long sh_end = (unsigned long long)eh.e_shoff + (unsigned long long)eh.e_shnum * eh.e_shentsize;
        if (ph_end > size || eh.e_phoff > size) {
            why = "truncated";
            snprintf(detail, sizeof detail, " (its program headers end at byte %llu, the file has %llu)", ph_end, size);
        } else if (eh.e_shoff > 0 && (sh_end > size || eh.e_shoff > size)) {
            why = "truncated";
            snprintf(detail, sizeof detail, " (its section headers end at byte %llu, the file has %llu)", sh_end, size);
        } else if (fseek(f, (long)eh.e_phoff, SEEK_SET) != 0) {
            why = "unreadable";
        } else {
            for (int i = 0; i < eh.e_phnum && !why; i++) {
                Elf64_Phdr ph;
                if (fread(&ph, sizeof ph, 1, f) != 1) {
                    why = "unreadable";
                } else if (ph.p_type == PT_LOAD && (ph.p_offset > size || ph.p_filesz > size - ph.p_offset)) {
                    why = "truncated";
                    snprintf(detail, sizeof detail, " (segment %d needs bytes up to %llu, the file has %llu)", i,
                             (unsigned long long)ph.p_offset + (unsigned long long)ph.p_filesz, size);
                }
            }
        }
    }
    fclose(f);
    if (why)
        rc = err_set(err, HEARTH_ERR_PLUGIN,
                     "%s: not loadable as a shared object: %s%s; rebuild or copy the plugin again (cc -shared -fPIC)",
                     shown, why, detail);
    return rc;
}

/* "hearth_foo.so" -> length of "foo", or 0 when the file is not a plugin name. */
static size_t plugin_stem(const char *f) {
    size_t n = strlen(f);
    if (n <= 10 || strncmp(f, "hearth_", 7) != 0 || strcmp(f + n - 3, ".so") != 0) return 0;
    return n - 10;
}

/* material.h rule 2: a file named hearth_<name>.so holds the material <name>. Scenes load it by the file's
 * name and checkpoints name it by the descriptor's, so a copy renamed (hearth_b.so holding 'a') would run and
 * then leave checkpoints no search finds (#18, helper userview5). A file not named hearth_*.so (a path given
 * to `hearth plugin check` or, with --trust, to h.material) is not held to it. */
static hearth_status plugin_name_matches(const char *shown, const char *name, hearth_error *err) {
    const char *base = strrchr(shown, '/');
    base = base ? base + 1 : shown;
    size_t len = plugin_stem(base);
    if (!len || (strlen(name) == len && strncmp(base + 7, name, len) == 0)) return HEARTH_OK;
    return err_set(err, HEARTH_ERR_PLUGIN,
                   "%s: the file is named for material '%.*s' but holds material '%s'; a plugin file is "
                   "hearth_<name>.so with the descriptor's name (rename the file hearth_%s.so, or build the plugin "
                   "with name \"%.*s\")",
                   shown, (int)len, base + 7, name, name, (int)len, base + 7);
}

/* dlopen the file at real (shown in messages as `shown`), validate, cache. */
static const hearth_plugin *plugin_open(const char *shown, const char *real, hearth_error *err) {
    if (plugin_elf_check(shown, real, err) != HEARTH_OK) return NULL;
    dlerror(); /* clear a stale message so the one we report is ours */
    /* dlopen runs the plugin's constructors: plugin code, so a crash names the file */
    plugin_call_set_context(shown, "loading");
    plugin_call_enter(NULL, "dlopen (the plugin's constructors)");
    void *h = dlopen(real, RTLD_NOW | RTLD_LOCAL);
    plugin_call_leave();
    plugin_call_set_context(NULL, NULL);
    if (!h) {
        const char *why = dlerror();
        err_set(err, HEARTH_ERR_PLUGIN,
                "%s: not loadable as a shared object: %s; build a plugin with cc -shared -fPIC and link any "
                "library it uses",
                shown, why ? why : "unknown dlopen error");
        return NULL;
    }
    void *sym = dlsym(h, HEARTH_MATERIAL_ENTRY_NAME);
    if (!sym) {
        dlclose(h);
        err_set(err, HEARTH_ERR_PLUGIN,
                "%s: not a hearth plugin: it exports no symbol '%s'; define HEARTH_PLUGIN_EXPORT const "
                "hearth_material *%s(void) from <hearth/material.h>",
                shown, HEARTH_MATERIAL_ENTRY_NAME, HEARTH_MATERIAL_ENTRY_NAME);
        return NULL;
    }
    /* ISO C has no object-to-function pointer cast; POSIX guarantees the
     * representations match, so copy the bits. */
    hearth_material_entry_fn entry;
    memcpy(&entry, &sym, sizeof entry);

    hearth_plugin *pl = mem_calloc(sizeof *pl);
    if (!pl || plugin_grow(&g_loaded, &g_caploaded, g_nloaded + 1) ||
        !(pl->path = mem_strdup(real))) {
        if (pl) mem_free(pl, sizeof *pl);
        dlclose(h);
        err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory registering the plugin", shown);
        return NULL;
    }
    /* The entry function is plugin code too: a crash in it names the file. */
    plugin_call_set_context(shown, "loading");
    plugin_call_enter(NULL, HEARTH_MATERIAL_ENTRY_NAME);
    const hearth_material *desc = entry();
    plugin_call_leave();
    plugin_call_set_context(NULL, NULL);
    if (plugin_describe(shown, desc, &pl->desc, err) != HEARTH_OK ||
        plugin_name_matches(shown, pl->desc.mat.name, err) != HEARTH_OK) {
        plugin_desc_free(&pl->desc); /* empty when plugin_describe refused */
        mem_strfree(pl->path);
        mem_free(pl, sizeof *pl);
        dlclose(h);
        return NULL;
    }
    pl->handle = h;
    g_loaded[g_nloaded++] = pl;
    return pl;
}

void hearth_plugin_restrict(const char *writable_dir) {
    g_restricted = 1;
    g_writable[0] = '\0';
    if (writable_dir && !realpath(writable_dir, g_writable)) snprintf(g_writable, sizeof g_writable, "%s", writable_dir);
}

static int plugin_plain_name(const char *s) {
    for (const char *p = s; *p; p++)
        if (!((*p >= 'a' && *p <= 'z') || (*p >= '0' && *p <= '9') || *p == '_')) return 0;
    return 1;
}

const hearth_plugin *hearth_plugin_load(const char *name_or_path, hearth_error *err) {
    if (!name_or_path || !*name_or_path) {
        err_set(err, HEARTH_ERR_PLUGIN, "(empty): plugin name is empty; give a name such as \"elastic\" or a path");
        return NULL;
    }
    if (g_restricted && !plugin_plain_name(name_or_path)) {
        err_set(err, HEARTH_ERR_PLUGIN,
                "%.300s: a scene without --trust loads plugins by name (a-z, 0-9 and _, such as \"elastic\") from the "
                "plugin search path; run with --trust to load a file",
                name_or_path);
        return NULL;
    }
    char file[PATH_MAX];
    if (strchr(name_or_path, '/')) {
        if (strlen(name_or_path) >= sizeof file) {
            err_set(err, HEARTH_ERR_PLUGIN, "%.200s...: plugin path is longer than PATH_MAX", name_or_path);
            return NULL;
        }
        strcpy(file, name_or_path);
        struct stat st;
        if (stat(file, &st) != 0) {
            int e = errno;
            err_set(err, HEARTH_ERR_PLUGIN, "%s: %s (%s); check the path", file,
                    e == ENOENT || e == ENOTDIR ? "plugin file not found" : "cannot access the plugin file",
                    strerror(e));
            return NULL;
        }
        if (!S_ISREG(st.st_mode)) {
            err_set(err, HEARTH_ERR_PLUGIN, "%s: not a regular file; give the path of a hearth_<name>.so", file);
            return NULL;
        }
    } else if (plugin_find(name_or_path, file, sizeof file, err) != HEARTH_OK) {
        return NULL;
    }
    char real[PATH_MAX];
    if (!realpath(file, real)) {
        err_set(err, HEARTH_ERR_PLUGIN, "%s: cannot resolve the path (%s)", file, strerror(errno));
        return NULL;
    }
    size_t wl = strlen(g_writable);
    if (g_restricted && wl && !strncmp(real, g_writable, wl) && (real[wl] == '/' || !strcmp(g_writable, "/"))) {
        err_set(err, HEARTH_ERR_PLUGIN,
                "%s: the plugin file %s is in the output folder %s, which the scene can write; a scene without "
                "--trust loads plugins only from folders it cannot write (run with --trust to allow it)",
                name_or_path, real, g_writable);
        return NULL;
    }
    const hearth_plugin *pl = plugin_cached(real);
    return pl ? pl : plugin_open(file, real, err);
}

const hearth_material *hearth_plugin_material(const hearth_plugin *pl) { return pl ? &pl->desc.mat : NULL; }

const char *hearth_plugin_file(const hearth_plugin *pl) { return pl ? pl->path : NULL; }

int plugin_density_index(const hearth_plugin *pl) { return pl->desc.density; }

/* ---- listing ------------------------------------------------------------ */

static int plugin_cmp(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

int hearth_plugin_each(void (*fn)(void *ud, const char *name, const char *path), void *ud) {
    plugin_dirs d;
    if (plugin_dirs_build(&d)) return 0;
    plugin_dirs seen = {0}; /* names already reported: first folder wins */
    int visited = 0;
    for (int i = 0; i < d.n; i++) {
        DIR *dir = opendir(d.dir[i]);
        if (!dir) continue; /* a missing folder on the path is normal */
        /* Sort each folder so the listing does not depend on readdir order. */
        plugin_dirs files = {0};
        for (struct dirent *e; (e = readdir(dir));)
            if (plugin_stem(e->d_name)) plugin_dirs_push(&files, e->d_name, strlen(e->d_name));
        closedir(dir);
        if (files.n) qsort(files.dir, (size_t)files.n, sizeof *files.dir, plugin_cmp);
        for (int k = 0; k < files.n; k++) {
            char path[PATH_MAX];
            const char *f = files.dir[k];
            size_t len = plugin_stem(f);
            if (plugin_join(path, sizeof path, d.dir[i], f) || !plugin_is_file(path)) continue;
            int before = seen.n;
            if (plugin_dirs_push(&seen, f + 7, len) || seen.n == before) continue;
            if (fn) fn(ud, seen.dir[seen.n - 1], path);
            visited++;
        }
        plugin_dirs_free(&files);
    }
    plugin_dirs_free(&seen);
    plugin_dirs_free(&d);
    return visited;
}

/* plugins.h: private side of the plugin loader (plugins.c) and the
 * conformance battery (plugin_check.c).
 *
 * The public functions live in <hearth/hearth.h>. What is here lets the rest
 * of the core (and the unit tests) reach the validated descriptor without
 * going through a shared object. */
#ifndef HEARTH_SIM_PLUGINS_H
#define HEARTH_SIM_PLUGINS_H
#include "hearth/hearth.h"

/// A descriptor after validation: a normalised copy the core can trust.
/// Optional callbacks the plugin's struct_size does not cover are NULL,
/// NULL summary/help strings are "", and `density` indexes the density
/// parameter. params is owned (free with plugin_desc_free); mat.params points to it.
typedef struct plugin_desc {
    hearth_material mat;
    hearth_param *params;
    int density;
} plugin_desc;

/// Validate the descriptor m as returned by a plugin whose file is `shown`
/// (used to start every message). On success fills out and returns HEARTH_OK;
/// otherwise returns HEARTH_ERR_PLUGIN (or HEARTH_ERR_NOMEM) with err filled
/// and out left empty. m is read only as far as m->struct_size allows.
hearth_status plugin_describe(const char *shown, const hearth_material *m, plugin_desc *out, hearth_error *err);
/// Release what plugin_describe allocated (safe on an empty or zeroed desc).
void plugin_desc_free(plugin_desc *d);

/// Index of the parameter called name in m's schema, or -1.
int plugin_param_index(const hearth_material *m, const char *name);
/// Index of the "density" parameter of a loaded plugin (always present: the loader refuses schemas without it).
int plugin_density_index(const hearth_plugin *pl);

/// The plugin callback a thread is in (plugin_call_enter / plugin_call_leave
/// around every call into plugin code). A fatal-signal handler or an atexit
/// hook reads it through hearth_plugin_call_current to name the plugin.
/// The hot path pays two stores before a call and one after; `file` and
/// `context` are set only by the loader and the conformance battery, which
/// clear them again (plugin_call_set_context).
typedef struct plugin_call {
    const hearth_material *m; /* NULL before the descriptor is known */
    const char *callback;     /* NULL: no callback running */
    const char *file;         /* set by the loader before the plugin is registered */
    const char *context;
} plugin_call;
/* initial-exec: the record sits in the static TLS block, so reading it from a
 * signal handler never allocates (a lazily allocated dynamic TLS block would). */
extern _Thread_local plugin_call plugin_current_call __attribute__((tls_model("initial-exec")));

static inline void plugin_call_enter(const hearth_material *m, const char *callback) {
    plugin_current_call.m = m;
    plugin_current_call.callback = callback;
}
static inline void plugin_call_leave(void) { plugin_current_call.callback = NULL; }
/// Set (or clear, with NULLs) the file and context the next calls report.
static inline void plugin_call_set_context(const char *file, const char *context) {
    plugin_current_call.file = file;
    plugin_current_call.context = context;
}
#endif

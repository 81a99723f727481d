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
#endif

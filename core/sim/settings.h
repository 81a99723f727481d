/* settings.h: the scene's settings schema (hearth_scene_settings) applied to a
 * hearth_scene_def: its defaults and its range checks. */
#ifndef HEARTH_SIM_SETTINGS_H
#define HEARTH_SIM_SETTINGS_H
#include "hearth/hearth.h"

/// Write every setting's default into d (those with an offset).
void settings_defaults(hearth_scene_def *d);
/// Check every setting whose name starts with prefix ("" for all, "sph." for
/// the SPH solver's) and, with skip_prefix non-NULL, does not start with
/// skip_prefix. The first bad one fills err with the setting's name, value,
/// valid range or words, unit and help.
hearth_status settings_check(const hearth_scene_def *d, const char *prefix, const char *skip_prefix,
                             hearth_error *err);
#endif

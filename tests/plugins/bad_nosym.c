/* bad_nosym.c: test fixture. A valid shared object that exports a
 * misspelt entry point instead of hearth_material_v1; the loader must say
 * it is not a hearth plugin (and dlclose it). */
#include <hearth/material.h>

HEARTH_PLUGIN_EXPORT int hearth_materal_v1(void); /* note the typo */
HEARTH_PLUGIN_EXPORT int hearth_materal_v1(void) { return 42; }

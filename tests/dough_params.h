/* dough_params.h: cam_clay_dough's parameters in its schema's order and its
 * state's length, for the tests that call the plugin through its ABI
 * (unit_dough.c, unit_dough_fracture.c, unit_dough_dt.c). The plugin's
 * params[] (plugins/cam_clay_dough.c) is the truth; dough_plugin_check
 * checks the count. */
#ifndef HEARTH_TEST_DOUGH_PARAMS_H
#define HEARTH_TEST_DOUGH_PARAMS_H

enum { P_E, P_NU, P_TAU_Y, P_ETA, P_COMPACTION, P_DENSITY, P_MAX_POROSITY, P_FRACTURE_STRAIN, P_FRACTURE_STRETCH,
       P_FRACTURE_STRAIN_SET, P_CRACK_OPENING, P_CRACK_BAND, P_FRACTURE_UNSET, NP };
enum { NSTATE = 8 };

#endif

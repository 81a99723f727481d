/* sauce_library.h: the sauce library (assets/sauces.csv): Table 1 of
 * Nagasawa et al. 2019 as Herschel-Bulkley parameter sets, and their mapping
 * onto a plugin's parameter array (by parameter name: h, eta, sigma_y). */
#ifndef HEARTH_SIM_SAUCE_LIBRARY_H
#define HEARTH_SIM_SAUCE_LIBRARY_H
#include "hearth/hearth.h"

#define SAUCE_NAME_MAX 48
#define SAUCE_LABEL_MAX 96

/// One row of the library.
typedef struct sauce {
    char name[SAUCE_NAME_MAX];   ///< [a-z0-9_]+, e.g. "mayo_b"
    char label[SAUCE_LABEL_MAX]; ///< brand-free label, e.g. "Mayonnaise (My^b)"
    char geometry[16];           ///< "cone" or "parallel"
    double temperature_C;        ///< measurement temperature (degrees C)
    double h;                    ///< flow index (1)
    double eta;                  ///< consistency (Pa s^h)
    double sigma_y;              ///< yield stress (Pa)
} sauce;

typedef struct sauce_library {
    int n;
    sauce *items; ///< n rows in file order; owned
} sauce_library;

/// Load a library CSV: a header row naming the columns name, label,
/// temperature_C, h, eta, sigma_y and geometry (any order; extra columns are
/// ignored), then one sauce per row. Blank lines and lines starting with '#'
/// are skipped. Errors (HEARTH_ERR_IO, HEARTH_ERR_FORMAT, HEARTH_ERR_NOMEM)
/// name the file and line. Names must be unique and [a-z0-9_]+; h > 0,
/// eta > 0, sigma_y >= 0, all finite.
hearth_status sauce_library_load(const char *path, sauce_library *lib, hearth_error *err);
void sauce_library_free(sauce_library *lib);

/// The sauce called name ("mayo" or "sauce.mayo"), or NULL.
const sauce *sauce_find(const sauce_library *lib, const char *name);
/// Like sauce_find, but fills err (HEARTH_ERR_PARAM) for an unknown name with
/// the nearest library name as a suggestion.
const sauce *sauce_lookup(const sauce_library *lib, const char *name, hearth_error *err);

/// Fill p (m->nparams values) with m's defaults, then set the parameters
/// named h, eta and sigma_y from s. HEARTH_ERR_PARAM when m lacks one of them
/// or a value lies outside its schema range (the message gives the range).
hearth_status sauce_params(const hearth_material *m, const sauce *s, double *p, hearth_error *err);
#endif

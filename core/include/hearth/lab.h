/* hearth/lab.h: the lab bench of libhearth: a virtual rheometer for material
 * plugins, flow-curve files, the Herschel-Bulkley fit and the sauce library.
 *
 * Used by `hearth rheometer` and `hearth fit`, and by anyone who wants to
 * measure a material without writing a scene. Like the rest of the library,
 * nothing here prints or exits: every failure returns a status and fills a
 * hearth_error that names the file, line, rate or parameter.
 *
 * The homogeneous driver calls a plugin directly, with no scene: one material
 * point in simple shear, grad_v = [[0, rate, 0], [0, 0, 0], [0, 0, 0]], its F
 * advanced as F <- (I + dt grad_v) F every step, the plugin's state carried
 * from step to step. The measured quantity is the Cauchy shear stress
 * sigma_xy = tau_xy / det F (det F = 1 in simple shear).
 *
 * The fit is the paper's (Nagasawa et al. 2019, eq. 2): Herschel-Bulkley
 * sigma = sigma_Y + eta rate^h with the sum of squared RELATIVE residuals
 * minimised. */
#ifndef HEARTH_LAB_H
#define HEARTH_LAB_H

#include "hearth.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- the homogeneous rheometer ------------------------------------------ */

/// Options of hearth_rheometer_steady. Start from hearth_rheometer_default_opts().
typedef struct hearth_rheometer_opts {
    /// Fixed step (s); 0 = adaptive from the material: each step shears by 1% of
    /// the elastic strain |sigma_xy| / G, with G the shear modulus the first
    /// steps from rest measure (before that, rho c^2 from the plugin's
    /// wave_speed, an upper bound), so every relaxation is resolved whatever the
    /// material's stiffness and viscosity.
    double dt;
    /// Steady when, over a window of `window` steps, |change of sigma_xy| <=
    /// rel_tol |sigma_xy| and the geometric extrapolation of the remaining drift
    /// is as small (so a slow creep is not mistaken for a plateau). Default 1e-6.
    double rel_tol;
    int window;        ///< steps per window (default 64)
    double max_strain; ///< give up after this total shear strain (default 1e7)
    long max_steps;    ///< give up after this many steps (default 4e6)
} hearth_rheometer_opts;

hearth_rheometer_opts hearth_rheometer_default_opts(void);

/// What hearth_rheometer_steady measured.
typedef struct hearth_rheometer_result {
    double stress; ///< sigma_xy at the end (Pa): the steady stress when steady
    double strain; ///< total shear strain applied
    double time;   ///< total time (s)
    long steps;
    int steady;    ///< 1 when the criterion was met
} hearth_rheometer_result;

/// Drive material m with parameters p (m->nparams values, schema order) in
/// simple shear at `rate` (1/s, > 0) from rest until sigma_xy is steady.
/// HEARTH_ERR_PARAM for a bad rate or options, HEARTH_ERR_PLUGIN when the
/// plugin returns an error code or a non-finite stress (the message has its
/// describe_error text, the step and the strain), HEARTH_ERR_STATE when no
/// steady stress was reached within the caps (r still holds the last values),
/// HEARTH_ERR_NOMEM.
hearth_status hearth_rheometer_steady(const hearth_material *m, const double *p, double rate,
                                      const hearth_rheometer_opts *o, hearth_rheometer_result *r, hearth_error *err);

/// Start-up curve: from rest, n steps of size dt at `rate`; sigma[i] gets
/// sigma_xy after step i + 1, i.e. at time (i + 1) dt. Errors as hearth_rheometer_steady.
hearth_status hearth_rheometer_startup(const hearth_material *m, const double *p, double rate, double dt, int n,
                                       double *sigma, hearth_error *err);

/// A flow curve: hearth_rheometer_steady at every rate. stress[i] for rates[i].
/// Stops at the first failure (err names the rate).
hearth_status hearth_rheometer_flow_curve(const hearth_material *m, const double *p, const double *rates, int n,
                                          const hearth_rheometer_opts *o, double *stress, hearth_error *err);

/// n values spaced evenly in log between lo and hi inclusive (n >= 2; n == 1
/// gives lo): the rates of a flow curve, or the samples of a curve to plot.
void hearth_log_spaced(double lo, double hi, int n, double *out);

/// Herschel-Bulkley stress sigma_Y + eta rate^h (Nagasawa et al. 2019, eq. 1), in Pa.
double hearth_hb_stress(double sigma_y, double eta, double h, double rate);

/* ---- the MPM shear cell ------------------------------------------------- */

/// Options of hearth_rheometer_mpm_steady. Start from hearth_rheometer_mpm_default_opts().
typedef struct hearth_rheometer_mpm_opts {
    double gap;      ///< plate separation H (m), default 0.01
    int cells;       ///< grid cells across the gap, default 16
    double length;   ///< cell length in gaps (the layer is length x H), default 4
    int ppc;         ///< particles per cell (a k x k lattice), default 4
    double rel_tol;  ///< steady when the windowed mean stress changes less than this (relative), default 2e-4
    double max_time; ///< give up after this sim time (s), default 1
} hearth_rheometer_mpm_opts;

hearth_rheometer_mpm_opts hearth_rheometer_mpm_default_opts(void);

/// What hearth_rheometer_mpm_steady measured.
typedef struct hearth_rheometer_mpm_result {
    double stress;      ///< mean Cauchy sigma_xy of the particles in the middle half of the layer (Pa)
    double rate;        ///< shear rate measured there: slope of v_x against y over the inner 80% of the gap (1/s)
    double plate_speed; ///< each plate's speed (m/s), +V on top and -V below
    double time;        ///< sim time to steady (s)
    long steps;
    int particles;
    int steady;
} hearth_rheometer_mpm_result;

/// The full MPM solver as a rheometer: a 2D (plane strain) layer of material
/// between two sticky plates (colliders) moving at +-V = +-rate H / 2, no
/// gravity, slip walls at the ends. The layer starts with the linear velocity
/// profile of simple shear (so only the stress has to build up, not the flow)
/// and runs until the mean shear stress in its middle half is steady. The
/// plates' no-slip surfaces are the layer's faces, so the nominal rate is
/// 2V/H; the measured rate is reported too. o may be NULL (the defaults).
/// Errors as hearth_rheometer_steady, plus the scene's own (a guard stop is
/// HEARTH_ERR_GUARD).
hearth_status hearth_rheometer_mpm_steady(const char *plugin, const double *p, double rate,
                                          const hearth_rheometer_mpm_opts *o, hearth_rheometer_mpm_result *r,
                                          hearth_error *err);

/* ---- flow-curve files ----------------------------------------------------- */

/// A flow curve read from CSV: n points, rate (1/s) and stress (Pa). Owned
/// arrays; release with hearth_flow_curve_free.
typedef struct hearth_flow_curve {
    int n;
    double *rate, *stress;
} hearth_flow_curve;

/// Read a CSV with a header row naming the columns `shear_rate_1_per_s` (1/s)
/// and `stress_Pa` (Pa), as `hearth rheometer` writes them, or the bare
/// `shear_rate` and `stress` (any order, other columns ignored; blank lines and lines starting with '#'
/// skipped). Every data row needs both cells as finite numbers, shear_rate > 0
/// and stress > 0 (the fit's residuals are relative and the plot is log-log);
/// at least 3 rows, at most 1,000,000; lines of at most 4095 characters and
/// no NUL bytes (a UTF-16 file is refused as such). Errors (HEARTH_ERR_IO,
/// HEARTH_ERR_FORMAT) name the file, the line and the data row.
hearth_status hearth_flow_curve_read(const char *path, hearth_flow_curve *c, hearth_error *err);
/// Release the arrays and zero *c (a zeroed curve is fine).
void hearth_flow_curve_free(hearth_flow_curve *c);

/* ---- the Herschel-Bulkley fit --------------------------------------------- */

typedef struct hearth_hb_fit_result {
    double sigma_y, eta, h; ///< Pa, Pa s^h, 1
    double rel_error;       ///< RMS relative residual sqrt(sum r_i^2 / n), r_i = (model_i - data_i) / data_i
    double objective;       ///< eq. 2: sum r_i^2
} hearth_hb_fit_result;

/// Fit sigma = sigma_Y + eta rate^h to n >= 3 points (rates > 0, stresses > 0)
/// by eq. 2. For a fixed h the relative residuals are linear in (sigma_Y, eta),
/// so the best pair is a weighted linear least squares with sigma_Y >= 0 and
/// eta >= 0 enforced; h is then found by a log-spaced scan over [0.02, 3] and a
/// golden-section refinement of the best bracket (variable projection).
hearth_status hearth_hb_fit(const double *rate, const double *stress, int n, hearth_hb_fit_result *out,
                            hearth_error *err);

/* ---- the sauce library (assets/sauces.csv) -------------------------------- */

#define HEARTH_SAUCE_NAME_MAX 48
#define HEARTH_SAUCE_LABEL_MAX 96

/// One row of the library: Table 1 of Nagasawa et al. 2019 as a
/// Herschel-Bulkley parameter set.
typedef struct hearth_sauce {
    char name[HEARTH_SAUCE_NAME_MAX];   ///< [a-z0-9_]+, e.g. "mayo_b"
    char label[HEARTH_SAUCE_LABEL_MAX]; ///< brand-free label, e.g. "Mayonnaise (My^b)"
    char geometry[16];                  ///< "cone" or "parallel"
    double temperature_C;               ///< measurement temperature (degrees C)
    double h;                           ///< flow index (1)
    double eta;                         ///< consistency (Pa s^h)
    double sigma_y;                     ///< yield stress (Pa)
} hearth_sauce;

typedef struct hearth_sauce_library {
    int n;
    hearth_sauce *items; ///< n rows in file order; owned, released by hearth_sauce_library_free
} hearth_sauce_library;

/// Load a library CSV: a header row naming the columns name, label,
/// temperature_C, h, eta, sigma_y and geometry (any order; extra columns are
/// ignored), then one sauce per row. Blank lines and lines starting with '#'
/// are skipped. Errors (HEARTH_ERR_IO, HEARTH_ERR_FORMAT, HEARTH_ERR_NOMEM)
/// name the file and line. Names must be unique and [a-z0-9_]+; h > 0,
/// eta > 0, sigma_y >= 0, all finite.
hearth_status hearth_sauce_library_load(const char *path, hearth_sauce_library *lib, hearth_error *err);
/// Release the rows and zero *lib (a zeroed library is fine).
void hearth_sauce_library_free(hearth_sauce_library *lib);

/// The sauce called name ("mayo" or "sauce.mayo"), or NULL. Points into lib.
const hearth_sauce *hearth_sauce_find(const hearth_sauce_library *lib, const char *name);
/// Like hearth_sauce_find, but fills err (HEARTH_ERR_PARAM) for an unknown name
/// with the nearest library name as a suggestion.
const hearth_sauce *hearth_sauce_lookup(const hearth_sauce_library *lib, const char *name, hearth_error *err);

/// Fill p (m->nparams values) with m's defaults, then set the parameters
/// named h, eta and sigma_y from s. HEARTH_ERR_PARAM when m lacks one of them
/// or a value lies outside its schema range (the message gives the range).
hearth_status hearth_sauce_params(const hearth_material *m, const hearth_sauce *s, double *p, hearth_error *err);

#ifdef __cplusplus
}
#endif
#endif

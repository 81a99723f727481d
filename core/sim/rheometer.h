/* rheometer.h: a virtual rheometer for material plugins, and flow-curve fitting.
 *
 * The homogeneous driver calls a plugin directly, with no scene: one material
 * point in simple shear, grad_v = [[0, rate, 0], [0, 0, 0], [0, 0, 0]], its F
 * advanced as F <- (I + dt grad_v) F every step, the plugin's state carried
 * from step to step. The measured quantity is the Cauchy shear stress
 * sigma_xy = tau_xy / det F (det F = 1 in simple shear).
 *
 * The fit is the paper's (Nagasawa et al. 2019, eq. 2): Herschel-Bulkley
 * sigma = sigma_Y + eta rate^h with the sum of squared RELATIVE residuals
 * minimised.
 *
 * Uses only <hearth/material.h>, <hearth/hearth.h> and the alloc/error helpers. */
#ifndef HEARTH_SIM_RHEOMETER_H
#define HEARTH_SIM_RHEOMETER_H
#include "hearth/hearth.h"

/// Options of rheo_steady. Start from rheo_default_opts().
typedef struct rheo_opts {
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
} rheo_opts;

rheo_opts rheo_default_opts(void);

/// What rheo_steady measured.
typedef struct rheo_result {
    double stress; ///< sigma_xy at the end (Pa): the steady stress when steady
    double strain; ///< total shear strain applied
    double time;   ///< total time (s)
    long steps;
    int steady;    ///< 1 when the criterion was met
} rheo_result;

/// Drive material m with parameters p (m->nparams values, schema order) in
/// simple shear at `rate` (1/s, > 0) from rest until sigma_xy is steady.
/// HEARTH_ERR_PARAM for a bad rate or options, HEARTH_ERR_PLUGIN when the
/// plugin returns an error code or a non-finite stress (the message has its
/// describe_error text, the step and the strain), HEARTH_ERR_STATE when no
/// steady stress was reached within the caps (r still holds the last values),
/// HEARTH_ERR_NOMEM.
hearth_status rheo_steady(const hearth_material *m, const double *p, double rate, const rheo_opts *o, rheo_result *r,
                          hearth_error *err);

/// Start-up curve: from rest, n steps of size dt at `rate`; sigma[i] gets
/// sigma_xy after step i + 1, i.e. at time (i + 1) dt. Errors as rheo_steady.
hearth_status rheo_startup(const hearth_material *m, const double *p, double rate, double dt, int n, double *sigma,
                           hearth_error *err);

/// A flow curve: rheo_steady at every rate. stress[i] for rates[i]. Stops at
/// the first failure (err names the rate).
hearth_status rheo_flow_curve(const hearth_material *m, const double *p, const double *rates, int n,
                              const rheo_opts *o, double *stress, hearth_error *err);

/// n rates spaced evenly in log between lo and hi inclusive (n >= 2; n == 1 gives lo).
void rheo_log_rates(double lo, double hi, int n, double *rates);

/// Herschel-Bulkley stress sigma_Y + eta rate^h (eq. 1).
double rheo_hb(double sigma_y, double eta, double h, double rate);

/* ---- the MPM shear cell (rheometer_mpm.c) --------------------------------- */

/// Options of rheo_mpm_steady. Start from rheo_mpm_default_opts().
typedef struct rheo_mpm_opts {
    double gap;      ///< plate separation H (m), default 0.01
    int cells;       ///< grid cells across the gap, default 16
    double length;   ///< cell length in gaps (the layer is length x H), default 4
    int ppc;         ///< particles per cell (a k x k lattice), default 4
    double rel_tol;  ///< steady when the windowed mean stress changes less than this (relative), default 2e-4
    double max_time; ///< give up after this sim time (s), default 1
} rheo_mpm_opts;

rheo_mpm_opts rheo_mpm_default_opts(void);

/// What rheo_mpm_steady measured.
typedef struct rheo_mpm_result {
    double stress;      ///< mean Cauchy sigma_xy of the particles in the middle half of the layer (Pa)
    double rate;        ///< shear rate measured there: slope of v_x against y over the inner 80% of the gap (1/s)
    double plate_speed; ///< each plate's speed (m/s), +V on top and -V below
    double time;        ///< sim time to steady (s)
    long steps;
    int particles;
    int steady;
} rheo_mpm_result;

/// The full MPM solver as a rheometer: a 2D (plane strain) layer of material
/// between two sticky plates (colliders) moving at +-V = +-rate H / 2, no
/// gravity, slip walls at the ends. The layer starts with the linear velocity
/// profile of simple shear (so only the stress has to build up, not the flow)
/// and runs until the mean shear stress in its middle half is steady. The
/// plates' no-slip surfaces are the layer's faces, so the nominal rate is
/// 2V/H; the measured rate is reported too. Errors as rheo_steady, plus the
/// scene's own (a guard stop is HEARTH_ERR_GUARD).
hearth_status rheo_mpm_steady(const char *plugin, const double *p, double rate, const rheo_mpm_opts *o,
                              rheo_mpm_result *r, hearth_error *err);

/* ---- flow-curve files ---------------------------------------------------- */

/// A flow curve read from CSV: n points, rate (1/s) and stress (Pa).
typedef struct rheo_curve {
    int n;
    double *rate, *stress;
} rheo_curve;

/// Read a CSV with a header row naming the columns `shear_rate` and `stress`
/// (any order, other columns ignored; blank lines and lines starting with '#'
/// skipped). Every data row needs both cells as finite numbers, shear_rate > 0
/// and stress > 0 (the fit's residuals are relative and the plot is log-log);
/// at least 3 rows, at most 1,000,000; lines of at most 4095 characters and
/// no NUL bytes (a UTF-16 file is refused as such). Errors (HEARTH_ERR_IO,
/// HEARTH_ERR_FORMAT) name the file, the line and the data row.
hearth_status rheo_curve_read(const char *path, rheo_curve *c, hearth_error *err);
void rheo_curve_free(rheo_curve *c);

/* ---- fitting --------------------------------------------------------------- */

typedef struct rheo_fit_result {
    double sigma_y, eta, h; ///< Pa, Pa s^h, 1
    double rel_error;       ///< RMS relative residual sqrt(sum r_i^2 / n), r_i = (model_i - data_i) / data_i
    double objective;       ///< eq. 2: sum r_i^2
} rheo_fit_result;

/// Fit sigma = sigma_Y + eta rate^h to n >= 3 points (rates > 0, stresses > 0)
/// by eq. 2. For a fixed h the relative residuals are linear in (sigma_Y, eta),
/// so the best pair is a weighted linear least squares with sigma_Y >= 0 and
/// eta >= 0 enforced; h is then found by a log-spaced scan over [0.02, 3] and a
/// golden-section refinement of the best bracket (variable projection).
hearth_status rheo_fit_hb(const double *rate, const double *stress, int n, rheo_fit_result *out, hearth_error *err);
#endif

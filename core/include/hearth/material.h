/* hearth/material.h: the material plugin ABI. The only header a plugin needs.
 *
 * A plugin is a shared object that exports one symbol, HEARTH_MATERIAL_ENTRY
 * ("hearth_material_v1"), returning a pointer to a static descriptor. The
 * loader checks abi_version, struct_size and real_size before reading any
 * other field, then checks every required callback and the parameter schema.
 *
 * Rules that keep old plugins working:
 *   - fields of hearth_material and hearth_point are only ever appended;
 *   - a new optional callback is read only when struct_size says it exists;
 *   - a change that breaks layout bumps HEARTH_MATERIAL_ABI.
 *
 * All tensors are 3x3, row-major (a[3*row+col]), in SI units. 2D scenes are
 * plane strain: the solver passes tensors whose z row and column describe no
 * deformation, and ignores the zz stress for motion (it still counts for
 * pressure and yield).
 */
#ifndef HEARTH_MATERIAL_H
#define HEARTH_MATERIAL_H

#ifdef __cplusplus
extern "C" {
#endif

/// Major version of this ABI. The loader refuses any other value.
#define HEARTH_MATERIAL_ABI 1
/// Name of the one exported entry symbol.
#define HEARTH_MATERIAL_ENTRY hearth_material_v1
#define HEARTH_MATERIAL_ENTRY_NAME "hearth_material_v1"

/// Bits of hearth_material.needs: fields the core must keep live for this material.
enum {
    HEARTH_NEEDS_TEMPERATURE = 1u << 0, ///< hearth_point.temperature is filled (degrees C)
    HEARTH_NEEDS_POROSITY = 1u << 1,    ///< hearth_point.porosity is filled (0..1)
    HEARTH_NEEDS_SATURATION = 1u << 2,  ///< hearth_point.saturation is filled (0..1)
    /// The law is written to be completed by the core's thermal expansion term -c*lambda*J^E*(T-Tref) I
    /// (Ding et al. eq. 10). The core adds that term to any material whose core parameter `expansion`
    /// (c*lambda) is > 0, flagged or not; the flag states the intent, and `hearth plugin check` and the
    /// rheometer fill the temperature for it.
    HEARTH_NEEDS_THERMAL_EXPANSION = 1u << 3
};

/// One entry of a parameter schema. def must lie in [min, max].
typedef struct hearth_param {
    const char *name; ///< identifier used in Lua and on the command line
    const char *unit; ///< SI unit, e.g. "Pa", "Pa s", "kg/m^3", "1" for dimensionless
    const char *help; ///< one line for `hearth plugins`
    double def, min, max;
} hearth_param;

/// One material point, solver-agnostic (MPM and SPH fill it the same way).
/// Valid only for the duration of one callback.
typedef struct hearth_point {
    double grad_v[9]; ///< velocity gradient dv/dx over the step (1/s)
    double F[9];      ///< total deformation gradient at the END of the step (already updated by the solver)
    double dt;        ///< step (s); 0 means "evaluate only": do not advance time-dependent state
    double temperature, porosity, saturation; ///< NaN when the field is off
    const double *p;  ///< resolved parameters in schema order (curves already evaluated)
    double *state;    ///< plugin-owned per-point state, state_size doubles
} hearth_point;

/// The descriptor a plugin returns. Static storage, never freed by the core.
typedef struct hearth_material {
    int abi_version; ///< must be HEARTH_MATERIAL_ABI
    int struct_size; ///< sizeof(hearth_material) as the plugin was compiled
    int real_size;   ///< sizeof(double) as the plugin was compiled
    const char *name;    ///< short identifier, [a-z0-9_]+
    const char *summary; ///< one line
    const hearth_param *params;
    int nparams;
    int state_size;  ///< doubles of per-point state (0 allowed)
    unsigned needs;  ///< HEARTH_NEEDS_* bits

    /// Required. Set the initial state of a point at rest (F = I).
    void (*init)(const double *p, double *state);
    /// Required. Advance state over pt->dt and write the Kirchhoff stress tau = J sigma.
    /// Returns 0 on success, or a plugin-specific positive code explained by describe_error.
    int (*stress)(hearth_point *pt, double tau[9]);
    /// Required. An upper bound of the speed of elastic/pressure waves (m/s) for the CFL limit.
    double (*wave_speed)(const double *p, const double *state);
    /// Optional (may be NULL). Blend k parameter sets with weights alpha (summing to 1) into out.
    int (*blend)(int k, const double *alpha, const double *const *pk, double *out);
    /// Required. Text for a code returned by stress. Static storage.
    const char *(*describe_error)(int code);
    /// Optional (may be NULL, meaning 1). Plastic volume ratio J^P from the state, for porosity (Ding et al. §5.4).
    double (*plastic_J)(const double *p, const double *state);
    /// Optional (may be NULL; read only when struct_size covers it). The dynamic viscosity (Pa s)
    /// the stress applies explicitly from the velocity gradient, for the step limit
    /// dt <= rho dx^2 / (2 dim eta). Leave NULL when viscous flow is integrated implicitly.
    double (*viscosity)(const double *p, const double *state);
} hearth_material;

/// The entry point a plugin defines.
typedef const hearth_material *(*hearth_material_entry_fn)(void);

#if defined(_WIN32)
#define HEARTH_PLUGIN_EXPORT __declspec(dllexport)
#else
#define HEARTH_PLUGIN_EXPORT __attribute__((visibility("default")))
#endif

#ifdef __cplusplus
}
#endif
#endif

/* material.h: the scene's materials and the one door to a material point.
 *
 * The slots (material.c). A scene holds its materials in a material_table:
 * one slot per material id (the PC_MAT column), with the plugin, its resolved
 * parameters, the core's field properties (params.h CP_*), the parameters
 * that follow temperature (curves.h) and, for a mixture, its constituents'
 * parameter sets. material_params() is the one place a particle's parameters
 * are resolved: temperature curves evaluated, a mixture blended at the
 * particle's ratios. Only material.c writes a slot; everyone else reads.
 *
 * The door. Every caller that asks a
 * plugin for a stress (MPM's P2G, SPH's stress phase, the probes, the guard's
 * cause attribution, `hearth plugin check` and the rheometer) goes through
 * material_point_eval() or its two halves (P2G through material_run_eval(),
 * which calls them, or the plugin's stress_block, for a run of particles), so the fields the point carries, the recording of the plugin call (plugins.h) and
 * the core's coupling stresses are written once.
 *
 * The caller fills the point's kinematics and parameters (grad_v, F, dt, p,
 * state) and says in a material_env what its solver supplies: the
 * temperature, saturation and porosity to pass, and which of the core's
 * coupling terms to add. Where the callers disagree on a field (the plugin
 * check passes porosity 0.1 and saturation 0.5, the rheometer 0 and 0; MPM
 * derives the porosity from J^P when the material needs it or the scene has
 * gas, SPH when the material needs it, the probes always; the guard passes
 * the J^P-derived value it also uses for its own terms), each passes its own
 * value explicitly, so the disagreement is visible at the call rather than
 * hidden in a copy. Only MPM asks for the coupling terms; the door is checked
 * against each in-tree plugin called directly in tests/unit_material.c.
 *
 * The door is header-only and always inlined: MPM's P2G instantiates it per dimension and
 * field set, and a call there would cost instructions on the hot path. */
#ifndef HEARTH_SIM_MATERIAL_H
#define HEARTH_SIM_MATERIAL_H
#include <math.h>
#include <string.h>

#include "curves.h"
#include "gas.h"
#include "hearth/material.h"
#include "params.h"
#include "particles.h"
#include "plugins.h"
#include "water.h"

/* Plugins may declare at most this many parameters (per-particle resolution
 * uses a stack buffer of this size). */
#define MATERIAL_MAX_PARAMS 256
/* Constituents of a mixture, and the width of the particles' ratio columns (PC_MIX, PC_MIXD). */
#define MIX_MAX 8

typedef struct material_slot {
    const hearth_plugin *plugin;
    const hearth_material *m;
    double *params;     /* resolved, schema order */
    int density_index;  /* schema index of "density" */
    int wave_per_point; /* ask the plugin per particle: it has state, or curves change its parameters (material.c);
                         * here, in density_index's padding, the slot keeps its size and layout (P2G indexes it) */
    double wave_speed;  /* cached when the plugin is stateless (state_size 0) and no curve moves its parameters */
    curve *curves;      /* parameters that follow temperature */
    int ncurves;
    int fracture;       /* the plugin reports damage and these parameters may crack (material.c); in ncurves' padding */
    double core[CP_COUNT]; /* field properties (params.h CP_*) */
    int mix_k;             /* a mixture (mixing.c): number of constituents, 0 for a plain material */
    int curve_stamp;       /* its curves' identity in the table (> 0 once it has one; each curve added gives a new
                            * one): the key of PC_CURVE_MEMO's entries, so no entry outlives the curves it holds */
    double *mix_params;    /* mix_k parameter sets, schema order */
} material_slot;

/* The scene's materials, indexed by material id. Held by value in the scene. */
typedef struct material_table {
    material_slot *slot;
    int n, cap;
    int curve_epoch; /* the last curve stamp handed out (material_curve_add) */
} material_table;

/// An empty table (allocates nothing).
void material_table_init(material_table *t);
/// Free every slot and the table; t is empty afterwards (material_table_init's state).
void material_table_free(material_table *t);
/// Resolve plugin pl's parameters (names/values, n pairs) into a slot that no
/// table holds yet: checks the parameter count against MATERIAL_MAX_PARAMS and
/// every value against the schema. On failure nothing stays allocated.
hearth_status material_slot_init(material_slot *ms, const hearth_plugin *pl, const char *const *names,
                                 const double *values, int n, hearth_error *err);
/// Free what a slot owns (parameters, curves, constituents).
void material_slot_free(material_slot *ms);
/// Room for one more slot.
hearth_status material_table_reserve(material_table *t, hearth_error *err);
/// Append ms (reserved room) after caching a stateless plugin's wave speed,
/// which must be finite and > 0 at these parameters. Returns the new id, or
/// -1 with err set and ms freed.
int material_table_push(material_table *t, material_slot *ms, hearth_error *err);

/// Check a curve of kind `of` (CURVE_OF_*) for parameter `param` of material
/// mat (n points, abscissae strictly increasing, no curve of that kind yet).
/// A temperature curve's values lie in the parameter's range; a moisture
/// curve's abscissae are >= 0 and its factors > 0; with both kinds on one
/// parameter every product of their extremes (or of the parameter's value
/// and the factors) lies in the range. *k gets the parameter's schema index.
hearth_status material_curve_check(const material_table *t, int mat, const char *param, int of, int n, const double *T,
                                   const double *v, int *k, hearth_error *err);
/// Add the checked curve (copies T and v), temperature curves ahead of
/// moisture ones (material_params multiplies after it sets); a failure leaves
/// the slot as it was.
hearth_status material_curve_add(material_table *t, int mat, int k, int of, int n, const double *T, const double *v,
                                 int irreversible, hearth_error *err);

/// The k parameter sets of a mixture whose first constituent is material id
/// (its parameters are set 0); sets 1..k-1 resolved from names[c]/values[c].
/// Returns an array for material_mixture_set, or NULL with err set (the
/// plugin has no blend callback, a constituent is refused, no memory).
double *material_mixture_params(const material_table *t, int id, int k, const char *const *const *names,
                                const double *const *values, const int *n, hearth_error *err);
/// Free an array from material_mixture_params that was not handed over.
void material_mixture_params_free(const material_table *t, int id, int k, double *mp);
/// Make material id a mixture of k constituents, taking mp; a stateless
/// plugin's cached wave speed becomes the fastest constituent's.
void material_mixture_set(material_table *t, int id, int k, double *mp);

/// A mixture's blend of its constituents at particle i's dynamic ratios (PC_MIXD), into out (material.c).
void material_blend_at(const material_slot *ms, const particles *ps, int i, double *out);
/// Particle i's moisture ratio X/X_0 = m^w / (s_0 rho_0^w V_0), its water w = m^w over
/// the water it was given (curves.h): 1 when the scene has no water or the
/// body was given none (water.c's floor), so a moisture curve then leaves
/// the parameter as the raw dough's.
static inline double material_moisture_ratio_of(const material_slot *ms, const particles *ps, int i, double w) {
    if (!(ps->enabled & (1u << PC_WATER))) return 1.0;
    const double s0 = pcold(ps, PC_SAT0)[i];
    if (!(s0 > 2 * WATER_SATURATION_FLOOR)) return 1.0;
    return w / (s0 * ms->core[CP_WATER_DENSITY] * pcold(ps, PC_VOL0)[i]);
}
/// The same with the water it holds now (PC_WATER).
static inline double material_moisture_ratio(const material_slot *ms, const particles *ps, int i) {
    return material_moisture_ratio_of(ms, ps, i, ps->enabled & (1u << PC_WATER) ? pcold(ps, PC_WATER)[i] : 0.0);
}

/* Particle i's heat conductivity kappa (W/(m K)). A dried crust is a porous
 * solid with air where the water was, and conducts less than the wet crumb it
 * was (issue #18), so with dry_conductivity > 0 kappa goes linearly in the
 * moisture ratio X/X_0 (material_moisture_ratio, above; clamped to [0, 1]) from
 * dry_conductivity when dry to conductivity with all its water: the form a
 * bread model's effective conductivity takes (techMathGroup/breadBakingFoam,
 * compEffProps.H, interpolates between 0.18 W/(m K) dry and 0.37 W/(m K) wet
 * by the moisture ratio; docs/validation.md "A dried crust conducts less").
 * The ratio, not the saturation, so a crumb that swells (J > 1) keeps its
 * conductivity; a body given no water reads 1, as its moisture curves do.
 * dry_conductivity <= conductivity (material_slot_init), so the explicit step
 * limit on conductivity stays safe. dry_conductivity 0 returns conductivity
 * itself without reading the particle: a scene without it computes the bits
 * it did before. */
static inline double material_conductivity(const material_slot *ms, const particles *ps, int i) {
    const double k = ms->core[CP_CONDUCTIVITY], kd = ms->core[CP_DRY_CONDUCTIVITY];
    if (!(kd > 0)) return k;
    double r = material_moisture_ratio(ms, ps, i);
    r = r > 0 ? (r < 1 ? r : 1) : 0;
    return kd + (k - kd) * r;
}

/* Particle i's specific heat alpha (J/(kg K)) when it holds water w (kg),
 * per kg of its mass m, which stays the wet dough's (PC_MASS; water.c: the
 * particle mass is the dough's, water included). The water a dried crust lost took its heat capacity with
 * it (issue #18). The mixture rule for a particle of solids m_s and water w,
 *   m alpha = m_s c_s + w c_w,
 * is linear in the water it holds; at w = w0 (PC_SAT0 rho_0^w V_0, what it was
 * made with) it is the dough's specific_heat, at w = 0 it is m_s c_s / m =
 * dry_specific_heat, so
 *   alpha = dry_specific_heat + (specific_heat - dry_specific_heat) w / w0,
 * w / w0 the moisture ratio (material_moisture_ratio, above), and the slope
 * (specific_heat - dry_specific_heat) m / w0 is the water's c_w. Not clamped
 * at 1: a particle wetter than it was made holds that water's heat capacity
 * too (the rule holds for any w); floored at 0. dry_specific_heat
 * <= specific_heat (material_slot_init), so alpha is smallest dry, where the
 * step limits take it (material_heat_stiffest, below). The temperature
 * equation with it, alpha(w) m dtheta/dt = heat in - L x water evaporated, is
 * the enthalpy balance d(m alpha theta)/dt = heat in - (L + c_w theta) x water
 * evaporated: water leaves at the particle's temperature and carries its own
 * sensible heat, so a particle's temperature does not jump as it dries. The
 * term the rule adds to conduction when water moves inside the body,
 * -c_w q^w . grad theta, is left out, as it was with a constant alpha
 * (docs/validation.md, "A dried crust holds less heat"). dry_specific_heat 0
 * returns specific_heat itself without reading the particle: a scene without
 * it computes the bits it did before. */
static inline double material_specific_heat_of(const material_slot *ms, const particles *ps, int i, double w) {
    const double c = ms->core[CP_SPECIFIC_HEAT], cd = ms->core[CP_DRY_SPECIFIC_HEAT];
    if (!(cd > 0)) return c;
    const double r = material_moisture_ratio_of(ms, ps, i, w);
    return cd + (c - cd) * (r > 0 ? r : 0.0);
}
/* The same at the water it holds now (PC_WATER). */
static inline double material_specific_heat(const material_slot *ms, const particles *ps, int i) {
    return material_specific_heat_of(ms, ps, i, ps->enabled & (1u << PC_WATER) ? pcold(ps, PC_WATER)[i] : 0.0);
}

/* The smallest specific heat a particle of ms can have: the dried one
 * (dry_specific_heat when set, else specific_heat). The Robin and latent step
 * limits act on a node's heat capacity, which the driest particle on it may
 * hold alone. */
static inline double material_specific_heat_min(const material_slot *ms) {
    const double cd = ms->core[CP_DRY_SPECIFIC_HEAT];
    return cd > 0 ? cd : ms->core[CP_SPECIFIC_HEAT];
}

/* The (alpha, kappa) end of ms, dried or with all its water, whose
 * alpha / kappa is the smaller: conduction's explicit step limit
 * rho alpha dx^2 / (2 dim kappa) is shortest there. Both are linear in the
 * moisture ratio r (kappa clamped to [0, 1], alpha floored at 0), so their
 * ratio is a quotient of linear functions of r with a positive denominator,
 * monotone on [0, 1] and at least as large past 1 (kappa stops, alpha grows):
 * its smallest value is at r = 0 or r = 1. The wet pair when neither dry
 * parameter is set, or when only dry_conductivity is (a dried particle that
 * conducts less has the longer step): the expressions and bits as before. */
static inline void material_heat_stiffest(const material_slot *ms, double *alpha, double *kappa) {
    const double cw = ms->core[CP_SPECIFIC_HEAT], kw = ms->core[CP_CONDUCTIVITY];
    const double cd = material_specific_heat_min(ms), kd = ms->core[CP_DRY_CONDUCTIVITY] > 0 ? ms->core[CP_DRY_CONDUCTIVITY] : kw;
    *alpha = cw, *kappa = kw;
    if (cd * kw < cw * kd) *alpha = cd, *kappa = kd; /* cd / kd < cw / kw, without dividing by a kappa that may be 0 */
}

/// A moisture curve's factor at particle i; an irreversible one at the lowest
/// ratio the particle has reached (PC_DRIED holds 1 - that ratio, 0 when it
/// never dried), so a crust stays crisp when water diffuses back into it.
/// Out of line (material.c): inlined, its body grew P2G's particle loop by 1 %
/// of instructions in `hearth bench --dim 3` for scenes that have no moisture curve.
double material_moisture_factor(const material_slot *ms, const curve *c, const particles *ps, int i);
/// Multiply scratch by the factors of ms's curves from index k on (all moisture curves).
void material_moisture_apply(const material_slot *ms, const particles *ps, int i, int k, double *scratch);

/// The out-of-line half of material_params: a mixture's blend and the curves, into scratch.
const double *material_params_resolve(const material_slot *ms, const particles *ps, int i, double *scratch);

/// Particle i's parameters (schema order): the slot's own when it has no
/// curve and is no mixture, otherwise a mixture's blend at the particle's
/// dynamic ratios (PC_MIXD) and the curves at its temperature (PC_TEMPERATURE,
/// or PC_TEMP_MAX for an irreversible curve), then times the moisture curves'
/// factors at its moisture ratio, written into scratch
/// (MATERIAL_MAX_PARAMS doubles). Calls no plugin but blend. Inline: P2G
/// resolves every particle's parameters every step, and a call there cost
/// instructions (the blend, rare and long, stays out of line).
static inline const double *material_params(const material_table *t, const particles *ps, int mat, int i,
                                            double *scratch) {
    const material_slot *ms = &t->slot[mat];
    if (__builtin_expect(!ms->mix_k && ms->ncurves == 0, 1)) return ms->params;
    return material_params_resolve(ms, ps, i, scratch);
}

/// A run's parameters resolved once per run (material_batch.c): the same
/// values and bits as material_params_resolve at every point of a material
/// that is no mixture and has curves, with the uniform parameters copied once
/// and the moisture factors evaluated again only when a point's moisture
/// ratios differ from the last point's (never, without a water field).
typedef struct material_run_params {
    double q[MATERIAL_MAX_PARAMS];
    int nt;                                    /* ms->curves[0, nt) are temperature curves, the rest moisture curves */
    double r, rd;                              /* the last point's moisture ratio, and its driest for irreversible curves */
    double f[2 * MATERIAL_MAX_PARAMS];         /* moisture curve nt + k: its factor at r or rd */
    unsigned char mp[2 * MATERIAL_MAX_PARAMS]; /* moisture curve nt + k: its parameter has a temperature curve */
    const double *T, *Tmax, *dried;
} material_run_params;
/// Set rp up for a run of ms's particles (ms: curves, no mixture).
void material_run_params_init(material_run_params *rp, const material_slot *ms, const particles *ps);
/// Particle i's parameters (rp->q, rewritten by the next call).
const double *material_run_params_at(material_run_params *rp, const material_slot *ms, const particles *ps, int i);

#define MATERIAL_INLINE static inline __attribute__((always_inline))

/* Bits of material_env.flags. */
enum {
    /* A failed point (a plugin code or a non-finite tau) contributes no plugin stress: tau is zeroed
     * before the core's terms are added (MPM). Without the bit tau is left as the plugin wrote it, for
     * callers that report what the plugin returned (the plugin check, the probes). */
    MATERIAL_ZERO_FAILED = 1u << 0,
    /* n^p = 1 - (1 - n^p_0) / J^P (Ding et al. §5.4's gas volume fraction; gas.h) from the plugin's plastic_J at
     * the start of the step; without the bit the point gets env->porosity as given. */
    MATERIAL_POROSITY_PLASTIC = 1u << 1,
    /* The core's thermal expansion, eq. 10 as a thermal strain: taken out of F and grad_v before the stress for a
     * plugin with bulk_modulus (material_thermal_split, by the caller), else tau -= c lambda (theta - theta_ref) I
     * after it, when c lambda > 0.
     * The gas (eq. 13) and water (eq. 14) pressures are added when env->gas and env->saturation0 are
     * non-NULL: a bit and two pointers that MPM's instantiations know at compile time or once per block. */
    MATERIAL_EXPANSION = 1u << 2,
    /* The material may crack (material_slot.fracture): the plugin's damage is asked per point, and a cracked
     * point is cut off in tension (material_point_couple). Without the bit no damage call is made. */
    MATERIAL_DAMAGE = 1u << 3
};

/* The door's results beyond the plugin's own positive codes: tau came back NaN or infinite; the
 * plugin's bulk_modulus was not finite and > 0 where eq. 10's thermal strain needed it (the point
 * fails: no pressure is put in its place, material_thermal_scales). */
#define MATERIAL_NONFINITE (-1)
#define MATERIAL_BAD_BULK (-2)

/* What the solver supplies at this point. */
typedef struct material_env {
    unsigned flags;     /* MATERIAL_* */
    double J;           /* det F at the end of the step; read by the coupling terms */
    double temperature; /* degrees C, NaN when the scene has no temperature */
    double saturation;  /* (0..1), NaN when the scene has no water */
    double porosity;    /* passed as is without MATERIAL_POROSITY_PLASTIC (NaN: not supplied) */
    /* Per-particle columns read at [index] only by the term that needs them, so a solver hands
     * over its columns without loading a value it may not use. NULL: the scene has no such field. */
    const double *gas;         /* n^g (mol/m^3): gas pressure, eq. 13: tau_g = -n^g R theta / n^p I */
    const double *saturation0; /* s_0: water pressure, eq. 14: tau_w = -J c (s - s_0) I, when water_stiffness c > 0 */
    int index;
    /* The point's hearth_point.dim (<hearth/material.h> rule 8): the scene's (MPM, SPH, the probes, the
     * guard); 0 (a caller without a scene: the check, the rheometer) passes 3. */
    int dim;
} material_env;

/* x - x is 0 for a finite x and NaN otherwise: one test instead of nine
 * (the per-point door ran nine, 38 instructions of a dough point's ~3300). */
MATERIAL_INLINE int material_finite9(const double *a) {
    double z = 0;
    for (int k = 0; k < 9; k++) z += a[k] - a[k];
    return z == 0;
}

/* The first half of the door: fill pt's temperature, porosity and saturation
 * from env and call the plugin's stress (recorded, so a crash names the plugin
 * and the callback). core is the material's core parameters (params.h CP_*);
 * it may be NULL when env asks for neither the plastic porosity nor a coupling
 * term. Returns 0, the plugin's code, or MATERIAL_NONFINITE. The caller leaves
 * the plugin-call record afterwards (plugin_call_leave), so it can make
 * further calls under the same record. */
MATERIAL_INLINE int material_point_stress(const hearth_material *m, const double *core, hearth_point *pt,
                                          const material_env *env, double tau[9]) {
    const unsigned fl = env->flags;
    pt->temperature = env->temperature;
    pt->saturation = env->saturation;
    pt->dim = env->dim == 2 ? 2 : 3;
    if (fl & MATERIAL_POROSITY_PLASTIC) {
        double JP = 1.0;
        if (m->plastic_J) {
            plugin_call_enter(m, "plastic_J");
            JP = m->plastic_J(pt->p, pt->state);
        }
        pt->porosity = gas_porosity(JP, core[CP_POROSITY0]);
    } else {
        pt->porosity = env->porosity;
    }
    plugin_call_enter(m, "stress");
    int code = m->stress(pt, tau);
    if (__builtin_expect(!code && !material_finite9(tau), 0)) code = MATERIAL_NONFINITE;
    if (__builtin_expect(code != 0, 0) && (fl & MATERIAL_ZERO_FAILED)) memset(tau, 0, 9 * sizeof(double));
    return code;
}

/* material_thermal_split's scalars (below), for the caller that applies them itself
 * (material_batch.c's thermal_scales_block gives a block's points these values, bit for bit, on
 * columns: a change here is a change there): s[0] = exp(-e / 3) scales F,
 * s[1] = exp(r) scales L and s[2] = expm1(r) / dt goes on L's diagonal; with
 * dt = 0 or when the strain cannot be taken out (returns 0) they are 1, 1 and
 * -0.0, which leave every F and L entry's bits as they were (x * 1 and
 * x + -0.0 are x, signed zeros and NaNs included). Returns 1 when the strain
 * is taken out, 0 without a temperature, and -1 when K is NaN, infinite or
 * <= 0: a plugin from elsewhere may return anything, and the caller fails the
 * point with MATERIAL_BAD_BULK (the guard stops the run naming the plugin and
 * the value) rather than fall back to the pressure, which swells a yielding
 * law without end (the reason for the split) and would do so silently. The
 * caller has entered "bulk_modulus" (plugin_call_enter). */
MATERIAL_INLINE int material_thermal_scales(const hearth_material *m, const double *core, const double *p,
                                            const double *state, double T, double *e_store, double dt, double s[3]) {
    s[0] = 1, s[1] = 1, s[2] = -0.0;
    const double K = m->bulk_modulus(p, state);
    if (!(T == T)) return 0;
    if (!(K > 0 && K < INFINITY)) return -1; /* MATERIAL_BAD_BULK: F and L as they were */
    const double e0 = *e_store, e = dt > 0 ? core[CP_EXPANSION] * (T - core[CP_REFERENCE_T]) / K : e0;
    s[0] = exp(-e / 3);
    if (dt > 0) {
        const double r = (e0 - e) / 3;
        s[1] = exp(r), s[2] = expm1(r) / dt;
        *e_store = e;
    }
    return 1;
}

/* Eq. 10 as a thermal strain, for a plugin that gives its bulk modulus K
 * (<hearth/material.h>, bulk_modulus): the split F = F_M F_th with
 * F_th = exp(e / 3) I and e = ln J_th = c lambda (theta - theta_ref) / K.
 * The plugin gets the mechanical part: F_M = F exp(-e / 3), and over the step
 * f_M = exp((e_n - e) / 3) (I + dt L), i.e. L_M = exp(r) L + expm1(r) / dt I
 * with r = (e_n - e) / 3, e_n the strain taken out at the last step (the
 * particle's PC_THERMAL, written here when dt > 0). So the law's own elastic
 * strain and its return map see the thermal strain, and its stress vanishes
 * once the volume has grown by J_th: a free body, molten or not, ends at
 * J = J_th (a lone molten marshmallow particle at 2 Pa/K swelled without end
 * when the pressure -c lambda dT I was added after the law's yield; issue
 * #18, `lone_molten_particle_thermal_strain`). For a Hencky law that holds
 * (no yield) this is the additive pressure to rounding: K ln(J^E / J_th) =
 * K ln J^E - c lambda dT, and K from the point's own parameters keeps that
 * so when a curve moves E (the increments telescope). c lambda / K is
 * 3 alpha, the volumetric thermal expansion coefficient of linear
 * thermoelasticity (tau = C:(eps - alpha dT I) gives -3 K alpha dT I;
 * Gonzalez & Stuart 2008, the derivation Ding et al. cite for eq. 10).
 * dt = 0 (evaluate only) takes out the stored strain and writes nothing.
 * Returns 1 when the strain was taken out (the caller then adds no thermal
 * pressure), 0 when there is no temperature, -1 when K is not finite and > 0
 * (material_thermal_scales: the caller fails the point, MATERIAL_BAD_BULK). */
MATERIAL_INLINE int material_thermal_split(const hearth_material *m, const double *core, const double *p,
                                           const double *state, double T, double *e_store, double dt, double F[9],
                                           double L[9]) {
    plugin_call_enter(m, "bulk_modulus");
    double s[3];
    const int split = material_thermal_scales(m, core, p, state, T, e_store, dt, s);
    if (split <= 0) return split;
    for (int k = 0; k < 9; k++) F[k] *= s[0];
    if (dt > 0) {
        for (int k = 0; k < 9; k++) L[k] *= s[1];
        L[0] += s[2];
        L[4] += s[2];
        L[8] += s[2];
    }
    return 1;
}

/* The core's coupling terms, after the plugin's stress (material_point_couple
 * below adds a cracked point's cut-off). MPM calls the door's halves apart so
 * it can read the step limits (wave_speed, viscosity) between them while the
 * state is in cache. *gas_stiff (when not NULL) gets the pores' gas stiffness
 * for the step's wave speed (gas_tau_ambient; 0 without ambient_pressure). */
MATERIAL_INLINE void material_point_couple_terms(const hearth_material *m, const double *core, hearth_point *pt,
                                                 const material_env *env, double tau[9], double *gas_stiff) {
    const unsigned fl = env->flags;
    const double *gas = env->gas, *s0 = env->saturation0;
    if (!gas && !s0 && !(fl & MATERIAL_EXPANSION)) return;

    /* J^P after this step's plastic flow, for the gas term */
    const double cl = core[CP_EXPANSION];
    const int expand = (fl & MATERIAL_EXPANSION) && cl > 0;
    double JP1 = 1.0;
    if (m->plastic_J && gas) {
        plugin_call_enter(m, "plastic_J");
        JP1 = m->plastic_J(pt->p, pt->state);
    }
    const double J = env->J;
    if (s0 && core[CP_WATER_STIFFNESS] > 0) { /* water pressure (eq. 14) */
        const double tw = -J * core[CP_WATER_STIFFNESS] * (pt->saturation - s0[env->index]);
        tau[0] += tw;
        tau[4] += tw;
        tau[8] += tw;
    }
    if (gas) { /* gas pressure (eq. 13): tau_g = J sigma_g = -n^g R theta / n^p I */
        /* porosity after this step's plastic flow */
        const double np = m->plastic_J ? gas_porosity(JP1, core[CP_POROSITY0]) : pt->porosity;
        double stiff = 0;
        const double tg = core[CP_AMBIENT_PRESSURE] > 0
                              ? gas_tau_ambient(gas[env->index], env->temperature, J, pt->saturation > 0,
                                                core[CP_AMBIENT_PRESSURE], core[CP_POROSITY0], core[CP_REFERENCE_T],
                                                core[CP_OPEN_TEMPERATURE], &stiff)
                              : gas_tau(gas[env->index], env->temperature, np);
        if (gas_stiff) *gas_stiff = stiff;
        tau[0] += tg;
        tau[4] += tg;
        tau[8] += tg;
    }
    /* thermal expansion (Ding et al. eq. 10) for a plugin without bulk_modulus (one with it had the
     * strain taken out of F and grad_v instead, material_thermal_split, and comes here without
     * MATERIAL_EXPANSION), as the Kirchhoff stress of a thermal strain:
     * tau_th = -c lambda (theta - theta_ref) I, the same at every J^E. With a Hencky (or any
     * log-volumetric) skeleton, K ln J^E, a free body then swells to J^E = exp(c lambda dT / K):
     * a linear expansion alpha dT with alpha = c lambda / (3K), bounded. This is the stress whose
     * power tau : d per reference volume is the heat equation's coupling term, V0 c lambda theta
     * tr(grad v) (transport.c, eq. 9), so the pair conserves energy.
     * Eq. 10 as printed, sigma = -c lambda J theta, i.e. tau = -c lambda J^2 theta, has no free
     * equilibrium once c lambda dT > K / (2e) (K ln J = A J^2 has no root; ln J / J^2 peaks at
     * 1 / (2e)): a crumb no longer held by its crust, or a layer past the pore cap, inflated
     * without bound (crust_cracks.lua: A = 1000 Pa against K / (2e) = 766 Pa; the guard stopped
     * the unconfined slab at 0.51 s and the cracked one at 0.57 s). Session 27, issue #18.
     * Rejected before that: the total J in place of J^E (the batter of the pancake and the
     * lava cake swelled x4: a Cam-clay skeleton that yields in tension grew J^P, which raised
     * the pressure, which grew J^P further). Left as it is: added after the law's yield, this
     * pressure is never relaxed by plastic flow, so a skeleton whose yield stress is below it
     * (a molten marshmallow at 2 Pa/K) swells without end; hence the split for plugins that
     * give K (session 30). */
    if (expand) {
        const double th = cl * (env->temperature - core[CP_REFERENCE_T]);
        tau[0] -= th;
        tau[4] -= th;
        tau[8] -= th;
    }
}

/* The wave speed c of a point whose pores' gas has the stiffness `stiff` (Pa; gas.h, gas_tau_ambient) beside its
 * skeleton: sqrt(c^2 + stiff / rho) at the current density rho0 / J, so the step's CFL limit (mpm_stable_dt)
 * sees the gas (a p_a of 1e5 Pa against a step chosen from the dough's E stopped the guard at 0.56 s; #18). */
MATERIAL_INLINE double material_gas_wave(double c, double stiff, double J, double rho0) {
    return stiff > 0 ? sqrt(c * c + stiff * J / rho0) : c;
}

/* Particle i's gas term tau_g (Kirchhoff, the coefficient on I) as P2G adds it, for the readers outside the step
 * (the guard's cause, the probes): eq. 13 (gas_tau), or over the atmosphere with ambient_pressure (gas_tau_ambient;
 * the particle holds water when its PC_WATER is > 0, as P2G's saturation). */
static inline double material_gas_tau(const material_slot *ms, const particles *ps, int i, double ng, double T, double np,
                                      double J) {
    const double *core = ms->core;
    if (!(core[CP_AMBIENT_PRESSURE] > 0)) return gas_tau(ng, T, np);
    const int wet = (ps->enabled & (1u << PC_WATER)) && pcold(ps, PC_WATER)[i] > 0;
    double stiff;
    return gas_tau_ambient(ng, T, J, wet, core[CP_AMBIENT_PRESSURE], core[CP_POROSITY0], core[CP_REFERENCE_T],
                           core[CP_OPEN_TEMPERATURE], &stiff);
}

/* A cracked point (the plugin's damage callback at 1): each tensile
 * principal value of its tau set to 0 (material.c). */
void material_tension_cutoff(double tau[9]);

/* The second half of material_point_eval: the core's coupling terms or, for
 * a point its plugin reports cracked (damage 1, <hearth/material.h>), the
 * tension cut-off of the plugin's stress and no pressure terms. The crack
 * opens the point's pores to the oven, so its gas vents, and its faces are
 * free, so it holds no thermal stress. Rejected: the cut-off on the total
 * stress with the terms kept, when eq. 10's pressure was c lambda J^E^2
 * (theta - theta_ref) and grew as a point swelled: with no tension held
 * against it, cracked points of a bread's crust inflated until the guard
 * stopped the run (J^E ~ 400 at 2 s). Eq. 10 is now a thermal strain (above),
 * bounded; a cracked point still drops its terms (its faces are free). */
MATERIAL_INLINE void material_point_couple(const hearth_material *m, const double *core, hearth_point *pt,
                                           const material_env *env, double tau[9], double *gas_stiff) {
    if (gas_stiff) *gas_stiff = 0; /* a cracked point holds no gas pressure, so its gas no stiffness */
    if ((env->flags & MATERIAL_DAMAGE) && m->damage) {
        plugin_call_enter(m, "damage");
        if (m->damage(pt->p, pt->state) >= 1) {
            material_tension_cutoff(tau);
            return;
        }
    }
    material_point_couple_terms(m, core, pt, env, tau, gas_stiff);
}

/* The door: material_point_stress, then material_point_couple. Returns 0, the
 * plugin's code, or MATERIAL_NONFINITE. */
MATERIAL_INLINE int material_point_eval(const hearth_material *m, const double *core, hearth_point *pt,
                                        const material_env *env, double tau[9]) {
    const int code = material_point_stress(m, core, pt, env, tau);
    material_point_couple(m, core, pt, env, tau, NULL);
    return code;
}

/* ---- the batched door (material_batch.c) -----------------------------------
 * MPM's P2G hands over a run of consecutive particles of one material whose F
 * it has just advanced; the door gives each its stress, its wave speed and
 * the core's terms, as material_point_stress and material_point_couple would,
 * point by point. A plugin with stress_block (<hearth/material.h> rule 7) gets
 * the run as one hearth_block; its parameters are resolved once when uniform
 * and only the curves' parameters go in columns. A mixture's run, and any run
 * of a plugin without stress_block, goes point by point through the same code. */

/* The run: particles i0 .. i0 + n - 1 (n <= HEARTH_BLOCK_MAX), all of material mat, none pinned,
 * each with a finite F and det F > 0. */
typedef struct material_run {
    int mat, i0, n;
    int dim;
    double dt;
    unsigned flags;              /* MATERIAL_* for every point; the door adds the material's own */
    /* The points' 3x3 F (at the end of the step) and velocity gradient as columns, as a hearth_block
     * holds them: entry c (row-major) of point j is F[c][j]. The solver's scratch (P2G writes them as it
     * advances F; a 2D store of 2x2 tensors writes plane-strain 3x3s, <hearth/material.h> rule 8). */
    const double *F[9], *grad_v[9];
    /* 1: the plane strain embedding of a 2D store (tensor2.h, t2_embed): entries 2, 5, 6 and 7 of F and
     * grad_v, and 8 of grad_v, are +0.0 at every point (the door then passes them through unscaled), and F's
     * entry 8 is 1.0 (its thermal split is the scale itself) */
    int plane;
    const double *J;             /* det F of each point (n) */
    const double *temperature;   /* each point's (n), or NULL: NaN */
    const double *saturation;    /* each point's (n), or NULL: NaN */
    const double *gas, *saturation0; /* particle columns, as in material_env */
} material_run;

/* What the door gives back for each point j < n: its stress in columns, tau[c][j], with the core's terms
 * added (zero for a point whose stress failed, MATERIAL_ZERO_FAILED being set), code[j] (0, the plugin's
 * code, MATERIAL_NONFINITE or MATERIAL_BAD_BULK) and wave[j], the wave speed that limits the next step (unchecked). Returns
 * the largest kinematic viscosity (m^2/s) a point's plugin applies, 0 when none. */
double material_run_eval(const material_table *t, const particles *ps, const material_run *r, double *const tau[9],
                         int *code, double *wave);
#endif

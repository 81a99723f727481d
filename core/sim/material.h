/* material.h: the one door to a material point. Every caller that asks a
 * plugin for a stress (MPM's P2G, SPH's stress phase, the probes, the guard's
 * cause attribution, `hearth plugin check` and the rheometer) goes through
 * material_point_eval() or its two halves, so the fields the point carries, the recording of the plugin call (plugins.h) and
 * the core's coupling stresses are written once.
 *
 * The caller fills the point's kinematics and parameters (grad_v, F, dt, p,
 * state) and says in a material_env what its solver supplies: the
 * temperature, saturation and porosity to pass, and which of the core's
 * coupling terms to add. Where the callers disagree on a field (the plugin
 * check passes porosity 0.1, the rheometer 0, MPM, SPH and the probes
 * derive it from J^P), each passes its own value explicitly, so the
 * disagreement is visible at the call rather than hidden in a copy.
 *
 * Header-only and always inlined: MPM's P2G instantiates it per dimension and
 * field set, and a call there would cost instructions on the hot path. */
#ifndef HEARTH_SIM_MATERIAL_H
#define HEARTH_SIM_MATERIAL_H
#include <math.h>
#include <string.h>

#include "gas.h"
#include "hearth/material.h"
#include "params.h"
#include "plugins.h"

#define MATERIAL_INLINE static inline __attribute__((always_inline))

/* Bits of material_env.flags. */
enum {
    /* A failed point (a plugin code or a non-finite tau) contributes no plugin stress: tau is zeroed
     * before the core's terms are added (MPM). Without the bit tau is left as the plugin wrote it, for
     * callers that report what the plugin returned (the plugin check, the probes). */
    MATERIAL_ZERO_FAILED = 1u << 0,
    /* n^p = J^P - 1 + n^p_0 (Ding et al. §5.4) from the plugin's plastic_J at the start of the step;
     * without the bit the point gets env->porosity as given. */
    MATERIAL_POROSITY_PLASTIC = 1u << 1,
    /* The core's thermal expansion, eq. 10: tau -= c lambda J^E^2 (theta - theta_ref) I, when c lambda > 0.
     * The gas (eq. 13) and water (eq. 14) pressures are added when env->gas and env->saturation0 are
     * non-NULL: a bit and two pointers that MPM's instantiations know at compile time or once per block. */
    MATERIAL_EXPANSION = 1u << 2
};

/* The door's result beyond the plugin's own positive codes: tau came back NaN or infinite. */
#define MATERIAL_NONFINITE (-1)

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
} material_env;

MATERIAL_INLINE int material_finite9(const double *a) {
    for (int k = 0; k < 9; k++)
        if (!isfinite(a[k])) return 0;
    return 1;
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

/* The second half of material_point_eval: the core's coupling terms, after the
 * plugin's stress. MPM calls the halves apart so it can read the step limits
 * (wave_speed, viscosity) between them while the state is in cache. */
MATERIAL_INLINE void material_point_couple(const hearth_material *m, const double *core, hearth_point *pt,
                                           const material_env *env, double tau[9]) {
    const unsigned fl = env->flags;
    const double *gas = env->gas, *s0 = env->saturation0;
    if (!gas && !s0 && !(fl & MATERIAL_EXPANSION)) return;

    /* J^P after this step's plastic flow, for the gas and expansion terms */
    const double cl = core[CP_EXPANSION];
    const int expand = (fl & MATERIAL_EXPANSION) && cl > 0;
    double JP1 = 1.0;
    if (m->plastic_J && (gas || expand)) {
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
        const double tg = gas_tau(gas[env->index], env->temperature, np);
        tau[0] += tg;
        tau[4] += tg;
        tau[8] += tg;
    }
    /* thermal expansion (Ding et al. eq. 10): sigma += -c lambda J (theta - theta_ref) I, so tau = J sigma.
     * J is the elastic J^E = J / J^P of a plastic material: the potential
     * penalises F^{s,E} only (§5.2). With the total J, a skeleton that
     * yields in tension (Cam-clay, eq. 12, M > 0) grows J^P, which raised
     * the expansion pressure as J^2, which grew J^P further: the batter
     * of the pancake and the lava cake swelled x4 and blew up. */
    if (expand) {
        const double JE = J / JP1;
        const double th = cl * JE * JE * (env->temperature - core[CP_REFERENCE_T]);
        tau[0] -= th;
        tau[4] -= th;
        tau[8] -= th;
    }
}

/* The door: material_point_stress, then material_point_couple. Returns 0, the
 * plugin's code, or MATERIAL_NONFINITE. */
MATERIAL_INLINE int material_point_eval(const hearth_material *m, const double *core, hearth_point *pt,
                                        const material_env *env, double tau[9]) {
    const int code = material_point_stress(m, core, pt, env, tau);
    material_point_couple(m, core, pt, env, tau);
    return code;
}
#endif

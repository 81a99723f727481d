/* gas.c: CO2 production and pressure (Ding et al. 2019 §5.4).
 *
 *   dn^g/dt = alpha^g R0 exp(-((theta - theta_r)/dtheta)^2)
 *   n^p = J^{s,P} - 1 + n^p_0
 *   sigma^g = -n^g R theta / (J n^p) I            (eq. 13)
 *
 * The rate is integrated over each step as if the temperature moved linearly
 * from its value before the step's heat update to its value after, which the
 * erf form does exactly; at constant temperature it reduces to rate * dt.
 * The gas law takes absolute temperature: the user works in degrees C.
 *
 * Venting (scene settings gas_vent and vent_porosity; beyond Ding et al.,
 * who keep every mole where it was made). A dough's gas cells are closed
 * while their walls are whole, but at the surface a cell whose walls have
 * thinned out opens to the air and its gas leaves: the crumb turns from a
 * foam of separate cells into a sponge of communicating pores (McGee 2004,
 * On Food and Cooking, "From foam to sponge"), and bread-baking models
 * switch their pores open and let CO2 and vapour flow out through them
 * (Zhang, Datta & Mukherjee 2005, AIChE J. 51:2569; pore opening at
 * 71-81 degC measured by Zhang et al. 2025, Foods 14:1649). Here the opening is by
 * porosity, not temperature: a foam's cells press into one another past the
 * packing fraction of spheres (0.64 random, 0.74 ordered), so a surface
 * particle whose gas porosity has reached vent_porosity (default 0.7) is
 * open, and its CO2 leaves through its share S_p of the air surface
 * (boundary.c, the one heat and evaporation use) as a first-order loss,
 *   dn^g/dt = -h S_p / V_p n^g,   V_p = J V_p^0,
 * h = gas_vent (m/s) a mass-transfer velocity (an open pore's CO2 diffusing
 * into the air, D / delta ~ 1.6e-5 m^2/s / 1 mm ~ 0.02 m/s in real time).
 * Integrated exactly over the step (the factor exp(-h S_p dt / V_p)), so any
 * h is stable; a closed particle, or one inside, keeps its gas. Why: the
 * leavened cookie's top and rim swelled past the crumb (issue #18,
 * docs/validation.md "The cookie's skin"); an open skin vents instead, so
 * its pores stop at J^P ~ (1 - n^p_0) / (1 - vent_porosity).
 * `gas_vent_decays_at_closed_form` checks it against the exponential.
 *
 * Toward the atmosphere, not to nothing (issue #18, helper cookiecool; docs/validation.md "The physical cookie in
 * the cooler ovens"). With the gas law over the atmosphere (ambient_pressure p_a > 0, gas.h's gas_tau_ambient) an
 * open pore is the air's: its gas exchanges with the oven until it stands at p_a, so the loss is first order in
 * the CO2 over what that takes, dn^g/dt = -h S_p / V_p (n^g - n*), n* the CO2 at which the pores' air, vapour and
 * CO2 make p_a (at least 0), integrated exactly as n* + (n^g - n*) e^{-h S_p dt / V_p} with n* held over the step.
 * That is the Robin condition multiphase bread models put on the gas pressure at an open surface (the gas
 * pressure relaxes to the oven's through a mass-transfer coefficient: Zhang, Datta & Mukherjee 2005's model as
 * the breadBakingFoam solver sets it up, its breadPGMixed condition). Vented to n^g = 0 as before, a swollen
 * pore's air and vapour alone stood tens of kPa under p_a (J 2.5, 75 degC: -52 kPa), which crushed the soft
 * skin (yield ~0.1-7 kPa) of the physical cookie at 70-78 degC in the 150 degC oven; the crumb it squeezed rose
 * to +69 kPa and burst, and the cookie shed 6-7% of its particles. Without an atmosphere (ambient_pressure 0,
 * eq. 13 as printed, every paper preset) n* = 0: the law and its bits are as before. n* takes the particle's
 * temperature, J and water as the step leaves them (G2P) or as it holds them (gas_between).
 *
 * On the fields' own clock (field_clock.c) the grid carries heat and the
 * boundary only every k-th step, but the CO2 is the particles' own and moves
 * every step, as at single rate: a step without a field update makes each
 * particle's gas at the temperature it holds since the last field step and
 * vents it through the surface it held then (gas_between, PC_VENT), so the
 * pressure the material sees grows smoothly. Made in lumps of a cycle, a
 * lone pore's gas overshot its quasi-static closed form 15-fold
 * (`lone_gassy_pore_gas_volume_fraction`, |J/J* - 1| 2.9e-2 against 2e-3) and
 * a vented particle's n^g stood still between updates
 * (`gas_vent_decays_at_closed_form` read NaN rates). The field step then adds
 * the linear-temperature law over the whole cycle less what its earlier steps
 * made (gas_moles_field_step): a cycle makes the single-rate total for the
 * temperature's linear path, and a temperature that holds makes a t exactly.
 *
 * A second share (core parameters gas_rate_2, reaction_temperature_2, reaction_width_2; beyond Ding et al., whose
 * eq. 14 has one bell per material): a chemical leavener can be two reactions at two temperatures, the sugar-snap
 * cookie's NH4Cl share (dissolved ammonium bicarbonate, under way by ~60 degC) and its leftover soda (~100 degC)
 * (issue #18, docs/validation.md "The physical cookie's two shares"). Its moles are a second bell added after the
 * first's, n += a1 b1 + a2 b2 in that order, by the same linear-path integral, so with gas_rate_2 = 0 nothing is
 * added and every bit is the one-bell code's; a scene pays the second exp only when it has a second share. Its
 * exp takes no memo (PC_GAS_MEMO holds the first bell's; a second column for a rarely used share was not worth
 * its place in the sort): exp is what exp_memo returns, so the bits are the same. It needs gas_rate > 0 (scene.c
 * refuses it alone), so everything that turns the gas on still reads gas_rate. `gas_two_shares_on_a_ramp` checks
 * the two bells' sum along a linear ramp against the two Gaussian integrals' closed form.
 *
 * Each share's amount (core parameters gas_amount, gas_amount_2, mol/kg; beyond Ding et al., whose eq. 14 never
 * runs out): a leavener is a finite amount, so with an amount set each particle counts what each share has made
 * (PC_GAS_MADE, enabled only then) and the share's step is capped at what is left, in G2P and here through one
 * helper, gas.h's gas_share_capped (why capped within the step: there). Without amounts the helper returns its
 * argument and nothing is counted: eq. 14's bits. `gas_amount_caps_share_at_held_temperature` checks both call
 * sites against the closed form, the bell's integral capped at the amount. */
#include "gas.h"

#include <math.h>

#include "exp_memo.h"
#include "material.h"
#include "mpm.h"
#include "physics_constants.h"
#include "plugins.h"
#include "scene.h"
#define SQRT_PI 1.7724538509055160273

double gas_moles_step(double T0, double T1, double dt, double alpha_g, double R0, double Tr, double dT) {
    if (!(alpha_g > 0) || !(dt > 0)) return 0;
    const double a = (T0 - Tr) / dT, b = (T1 - Tr) / dT;
    const double k = alpha_g * R0 * dt;
    if (fabs(b - a) < 1e-6) { /* nearly constant: midpoint of the Gaussian, error O((b-a)^2) ~ 1e-12 */
        const double m = 0.5 * (a + b);
        return k * exp(-m * m) * (1 + (b - a) * (b - a) * (2 * m * m - 1) / 12);
    }
    /* dt * mean of exp(-u^2) over u in [a, b] */
    return k * 0.5 * SQRT_PI * (erf(b) - erf(a)) / (b - a);
}

double gas_moles_field_step(double T0, double T1, double fdt, double acc, double alpha_g, double R0, double Tr, double dT) {
    const double n = gas_moles_step(T0, T1, fdt, alpha_g, R0, Tr, dT);
    return acc > 0 ? n - gas_moles_step(T0, T0, acc, alpha_g, R0, Tr, dT) : n;
}

/* h S_p where particle i's pores are open and it holds air surface this step, else 0 */
static double vent_coefficient(const hearth_scene *s, int i) {
    const double h = s->def.gas_vent;
    const particles *ps = &s->ps;
    if (!(h > 0) || !s->boundary.area || i >= s->boundary.area_cap) return 0.0;
    const double S = s->boundary.area[i];
    if (!(S > 0)) return 0.0;
    const int m = pcoli(ps, PC_MAT)[i];
    const material_slot *ms = &s->mats.slot[m];
    double JP = 1.0;
    if (ms->m->plastic_J) { /* the porosity as the door gives it (material.h, MATERIAL_POROSITY_PLASTIC) */
        double pscratch[SCENE_MAX_PARAMS];
        const double *st = ps->state_stride ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL;
        plugin_call_enter(ms->m, "plastic_J");
        JP = ms->m->plastic_J(material_params(&s->mats, ps, m, i, pscratch), st);
        plugin_call_leave();
    }
    if (!(gas_porosity(JP, ms->core[CP_POROSITY0]) >= s->def.vent_porosity)) return 0.0; /* closed */
    return h * S;
}

/* exp(-c dt / V_p), V_p = J V_p^0: (-h S) dt / V is (-h) S dt / V to the bit */
static inline double vent_decay(const particles *ps, int i, double c, double dt) {
    if (!(c > 0)) return 1.0;
    const double V = pcold(ps, PC_VOL0)[i] * particles_J(ps, i);
    return V > 0 ? exp(-c * dt / V) : 1.0;
}

/* The CO2 n* (moles per reference volume) at which particle i's open pores stand at the atmosphere (the vent's
 * target, above): 0 for eq. 13 as printed (ambient_pressure 0, no atmosphere in the gas law), else gas.h's
 * gas_tau_ambient solved for p = p_a, n* = (p_a - p_v(theta)) J n^p / (R theta) - n_air, at least 0 (a pore whose
 * air and vapour alone stand over p_a keeps its CO2 at 0: the air's own loss is not modelled). */
static double vent_target(const hearth_scene *s, int i) {
    const particles *ps = &s->ps;
    const double *core = s->mats.slot[pcoli(ps, PC_MAT)[i]].core;
    const double pa = core[CP_AMBIENT_PRESSURE];
    if (!(pa > 0) || !(ps->enabled & (1u << PC_TEMPERATURE))) return 0.0;
    const double n0 = core[CP_POROSITY0], T = pcold(ps, PC_TEMPERATURE)[i];
    const int wet = (ps->enabled & (1u << PC_WATER)) && pcold(ps, PC_WATER)[i] > 0;
    const double th = T + KELVIN, pv = wet ? vapour_psat(th) : 0;
    const double nair = gas_air_moles(pa, n0, core[CP_REFERENCE_T], wet), J = particles_J(ps, i);
    const double n = (pa - pv) * J * gas_porosity(J, n0) / (R_GAS * th) - nair;
    return n > 0 ? n : 0.0;
}

/* n <- n* + (n - n*) e, e the step's decay; n* = 0 (no atmosphere) is n e, the same bits as the law before */
static inline double vent_relax(const hearth_scene *s, int i, double n, double e) {
    if (e == 1.0) return n;
    const double t = vent_target(s, i);
    return t > 0 ? t + (n - t) * e : n * e;
}

double gas_vent(const hearth_scene *s, int i, double n, double dt) {
    const double c = vent_coefficient(s, i);
    if (s->ps.enabled & (1u << PC_VENT)) pcold(&s->ps, PC_VENT)[i] = c; /* for the steps until the next field step */
    return vent_relax(s, i, n, vent_decay(&s->ps, i, c, dt));
}

/* gas_between for a scene of one gassy material with the memo (the dough bench's): per chunk of particles, the
 * memo's hits read in a loop of selects that vectorises (exp_memo's test: m[0] == x and m[1] != 0), exp_memo
 * only where one missed (none between the fields' updates), then G += k e and the vent's decay: each particle's
 * operations and values as the loop of gas_between, so the same bits; the chunks share nothing, so any thread
 * count gives them. Per particle the loop of exp_memo calls cost 25 instructions a step in the 2D bench. */
enum { GAS_CHUNK = 256 };
static void gas_between_one(const hearth_scene *s, double *restrict G, const double *restrict T, double *restrict memo,
                            const double *restrict vent, const particles *ps, int n, double rate, double Tr, double width,
                            double dt) {
    const int nchunks = (n + GAS_CHUNK - 1) / GAS_CHUNK;
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int c = 0; c < nchunks; c++) {
        const int i0 = c * GAS_CHUNK, m = n - i0 < GAS_CHUNK ? n - i0 : GAS_CHUNK;
        const double *t = T + i0;
        double *g = G + i0, *mm = memo + 2 * (size_t)i0;
        double X[GAS_CHUNK], E[GAS_CHUNK], miss = 0;
        for (int j = 0; j < m; j++) {
            const double u = (t[j] - Tr) / width, x = -u * u, k = mm[2 * j], v = mm[2 * j + 1];
            const double hit = k == x && v != 0 ? 1.0 : 0.0;
            X[j] = x;
            E[j] = hit == 1.0 ? v : 0.0;
            miss = hit == 1.0 ? miss : 1.0; /* a flag picked, not summed (a sum of doubles stays in order) */
        }
        for (int j = 0; j < m && miss > 0; j++)
            if (!(mm[2 * j] == X[j] && mm[2 * j + 1] != 0)) E[j] = exp_memo(mm + 2 * j, X[j]);
        for (int j = 0; j < m; j++) g[j] += rate * E[j];
        if (vent)
            for (int j = 0; j < m; j++)
                if (vent[i0 + j] > 0) g[j] = vent_relax(s, i0 + j, g[j], vent_decay(ps, i0 + j, vent[i0 + j], dt));
    }
}

void gas_between(hearth_scene *s, double dt) {
    particles *ps = &s->ps;
    if (!(ps->enabled & (1u << PC_GAS)) || !(ps->enabled & (1u << PC_TEMPERATURE)) || !(dt > 0)) return;
    double *G = pcold(ps, PC_GAS);
    const double *T = pcold(ps, PC_TEMPERATURE);
    const double *vent = s->def.gas_vent > 0 && (ps->enabled & (1u << PC_VENT)) ? pcold(ps, PC_VENT) : NULL;
    const int *mat = pcoli(ps, PC_MAT);
    double *memo = ps->enabled & (1u << PC_GAS_MEMO) ? pcold(ps, PC_GAS_MEMO) : NULL;
    double *made = ps->enabled & (1u << PC_GAS_MADE) ? pcold(ps, PC_GAS_MADE) : NULL; /* a share's amount (gas.h) */
    const material_slot *slot = s->mats.slot;
    const int n = ps->n;
    /* At constant temperature gas_moles_step is k exp(-m^2) (1 + 0), k = alpha^g R0 dt, m = (theta - theta_r) /
     * dtheta: these are its bits, without its call and its linear-path terms (the loop runs every step of the
     * dough bench: the exp is most of it, docs/performance.md). Per particle, nothing shared: the same bits on
     * any thread count. The temperature holds between the fields' updates, and so does the exp: the memo
     * (exp_memo.h) calls it once a cycle. */
    /* each material's constants once (a rho dt is the product's first two factors, as written out per point
     * before: the same bits), and a particle the vent does not reach (c = 0: the decay is 1.0, and x * 1.0 is
     * x) skips it: per particle the slot's pointers and the multiply cost 8 instructions a step in the 2D
     * dough bench */
    enum { GAS_MATS = 16 };
    if (s->mats.n > GAS_MATS) {
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
        for (int i = 0; i < n; i++) {
            const material_slot *gm = &slot[mat[i]];
            const double a = gm->core[CP_GAS_RATE], R0 = gm->params[gm->density_index];
            if (!(a > 0)) continue;
            double *mk = made ? made + 2 * (size_t)i : NULL; /* each share within its amount (gas.h) */
            const double u = (T[i] - gm->core[CP_REACTION_T]) / gm->core[CP_REACTION_WIDTH];
            G[i] += gas_share_capped(a * R0 * dt * (memo ? exp_memo(memo + 2 * (size_t)i, -u * u) : exp(-u * u)), R0,
                                     gm->core[CP_GAS_AMOUNT], mk);
            const double a2 = gm->core[CP_GAS_RATE_2];
            if (a2 > 0) { /* the second share (above) */
                const double u2 = (T[i] - gm->core[CP_REACTION_T_2]) / gm->core[CP_REACTION_WIDTH_2];
                G[i] += gas_share_capped(a2 * R0 * dt * exp(-u2 * u2), R0, gm->core[CP_GAS_AMOUNT_2], mk ? mk + 1 : NULL);
            }
            if (vent) G[i] = vent_relax(s, i, G[i], vent_decay(ps, i, vent[i], dt));
        }
        return;
    }
    double rate[GAS_MATS], Tr[GAS_MATS], width[GAS_MATS], rate2[GAS_MATS], Tr2[GAS_MATS], width2[GAS_MATS];
    double R0[GAS_MATS], amount[GAS_MATS], amount2[GAS_MATS];
    int live[GAS_MATS], two = 0;
    for (int k = 0; k < s->mats.n; k++) {
        const material_slot *gm = &slot[k];
        const double a = gm->core[CP_GAS_RATE], a2 = gm->core[CP_GAS_RATE_2];
        live[k] = a > 0;
        rate[k] = live[k] ? a * gm->params[gm->density_index] * dt : 0;
        Tr[k] = gm->core[CP_REACTION_T], width[k] = gm->core[CP_REACTION_WIDTH];
        rate2[k] = live[k] && a2 > 0 ? a2 * gm->params[gm->density_index] * dt : 0; /* the second share (above) */
        Tr2[k] = gm->core[CP_REACTION_T_2], width2[k] = gm->core[CP_REACTION_WIDTH_2];
        two |= rate2[k] > 0;
        /* each share's amount (gas.h's gas_share_capped; 0: no limit) */
        R0[k] = gm->params[gm->density_index], amount[k] = gm->core[CP_GAS_AMOUNT], amount2[k] = gm->core[CP_GAS_AMOUNT_2];
    }
    /* the one-material loop has no amounts (a scene with one takes the loop below, which pays for them) */
    if (s->mats.n == 1 && live[0] && memo && !two && !made) {
        gas_between_one(s, G, T, memo, vent, ps, n, rate[0], Tr[0], width[0], dt);
        return;
    }
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        const int k = mat[i];
        if (!live[k]) continue;
        double *mk = made ? made + 2 * (size_t)i : NULL; /* each share within its amount (gas.h) */
        const double u = (T[i] - Tr[k]) / width[k];
        G[i] += gas_share_capped(rate[k] * (memo ? exp_memo(memo + 2 * (size_t)i, -u * u) : exp(-u * u)), R0[k], amount[k], mk);
        if (two && rate2[k] > 0) {
            const double u2 = (T[i] - Tr2[k]) / width2[k];
            G[i] += gas_share_capped(rate2[k] * exp(-u2 * u2), R0[k], amount2[k], mk ? mk + 1 : NULL);
        }
        if (vent && vent[i] > 0) G[i] = vent_relax(s, i, G[i], vent_decay(ps, i, vent[i], dt));
    }
}

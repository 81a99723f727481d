/* guard.c: the stability guard. After every step it decides whether the step
 * may stand, and if not, writes a diagnosis a user can act on: step, time,
 * particle, position, material, the quantity that went bad and, for a blow-up,
 * what drove it: a temperature that ran away, or else the stress that outweighs
 * the others (the plugin's, thermal expansion or gas pressure). */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "gas.h"
#include "material.h"
#include "plugins.h"
#include "scene.h"
#include "tensor.h"

static void describe_particle(const hearth_scene *s, int i, char *buf, size_t n) {
    const particles *ps = &s->ps;
    const double *x = pcold(ps, PC_X) + 3 * i;
    const int m = pcoli(ps, PC_MAT)[i];
    snprintf(buf, n, "particle %d (id %d) at (%.6g, %.6g, %.6g) m, material '%s' (#%d)", i, pcoli(ps, PC_ID)[i], x[0],
             x[1], x[2], s->mats.slot[m].m->name, m);
}

/* |det F| past which an inverted or non-finite F counts as a swelling, not a crush (guard_measure) */
#define GUARD_SWELL 1e3

/* The pressure scale of each stress term at particle i after the step (Pa),
 * measured as mpm.c P2G adds them: the plugin's Kirchhoff stress (evaluated
 * with dt = 0 on a copy of the state, so the scene does not change), thermal
 * expansion (Ding et al. eq. 10) and gas pressure (eq. 13). |tau|_F / sqrt(3)
 * is |p| for a pure pressure p I, so the three compare directly. */
typedef struct guard_terms {
    double plugin, expansion, gas;
} guard_terms;

static void guard_measure(const hearth_scene *s, int i, guard_terms *t) {
    *t = (guard_terms){0};
    const particles *ps = &s->ps;
    const int mat = pcoli(ps, PC_MAT)[i];
    const material_slot *ms = &s->mats.slot[mat];
    double F[9];
    particles_F3(ps, i, F);
    const double J = t3_det(F);
    const double *T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL;
    const double *G = ps->enabled & (1u << PC_GAS) ? pcold(ps, PC_GAS) : NULL;
    double pscratch[SCENE_MAX_PARAMS];
    const double *p = material_params(&s->mats, &s->ps, mat, i, pscratch);
    const size_t sbytes = sizeof(double) * (size_t)ps->state_stride;
    double *state = sbytes ? mem_alloc(sbytes) : NULL;
    if (sbytes && !state) return; /* out of memory: no attribution, the diagnosis still stands */
    if (state) memcpy(state, pcold(ps, PC_STATE) + (size_t)i * ps->state_stride, sbytes);
    double JP = 1.0;
    if (ms->m->plastic_J) {
        plugin_call_enter(ms->m, "plastic_J");
        JP = ms->m->plastic_J(p, state);
    }
    hearth_point pt;
    particles_C3(ps, i, pt.grad_v);
    memcpy(pt.F, F, sizeof pt.F);
    pt.dt = 0;
    pt.p = p;
    pt.state = state;
    /* the plugin's stress alone, through the material door: the core's terms are measured apart below */
    const material_env env = {.temperature = T ? T[i] : NAN, .saturation = NAN, .porosity = gas_porosity(JP, ms->core[CP_POROSITY0]),
                              .dim = s->def.dim};
    double tau[9];
    /* at an F past double range (a particle that swelled without end) no stress is defined: the plugin's
     * term stays 0 and the pressure terms, which do not need F, still compare */
    const int finite = isfinite(J);
    const int rc = finite ? material_point_eval(ms->m, ms->core, &pt, &env, tau) : 1;
    plugin_call_leave();
    if (finite && (rc == 0 || rc == MATERIAL_NONFINITE)) { /* the plugin returned no code: its tau, finite or not, as before */
        double n2 = 0;
        for (int k = 0; k < 9; k++) n2 += tau[k] * tau[k];
        t->plugin = sqrt(n2 / 3.0);
    }
    /* J <= 0 too when |J| is past GUARD_SWELL or not finite: a particle that swelled until F overflowed or
     * flipped (a crushed one's |J| is small) */
    if (ms->core[CP_EXPANSION] > 0 && T && (J > 0 || !(fabs(J) <= GUARD_SWELL))) {
        t->expansion = fabs(ms->core[CP_EXPANSION] * (T[i] - ms->core[CP_REFERENCE_T])); /* material.h: eq. 10's thermal strain */
    }
    if (G && T) t->gas = fabs(material_gas_tau(ms, &s->ps, i, G[i], T[i], gas_porosity(JP, ms->core[CP_POROSITY0]), J));
    mem_free(state, sbytes);
}

/* Every temperature a scene can set, a body's, the oven's, a collider's, the
 * boiling point, is checked to [-273.15, 5000] degC (bodies.c, colliders.c,
 * settings.c), and the heat sources between them (the oven's and the tray's
 * Robin terms, eq. 9's coupling, the latent sink) cannot carry a particle
 * past that range: one outside it (or NaN) is an unstable heat step. */
#define GUARD_T_LO (-273.15)
#define GUARD_T_HI 5000.0

/* The particle whose temperature lies furthest outside [GUARD_T_LO,
 * GUARD_T_HI] (a NaN first; the lowest index among equals, so the name does
 * not depend on threads), or -1 when every temperature is in range. */
static int guard_temperature_runaway(const hearth_scene *s) {
    const particles *ps = &s->ps;
    if (!(ps->enabled & (1u << PC_TEMPERATURE))) return -1;
    const double *T = pcold(ps, PC_TEMPERATURE);
    int worst = -1;
    double far = 0;
    for (int i = 0; i < ps->n; i++) {
        const double d = isnan(T[i]) ? INFINITY : fmax(GUARD_T_LO - T[i], T[i] - GUARD_T_HI);
        if (d > far) far = d, worst = i;
    }
    return worst;
}

/* Why the step blew up, for the guard's message ("" when the plugin's stress,
 * or plain motion, is the larger, so the caller keeps its own wording).
 * First the temperature: thermal expansion (eq. 10) and gas pressure (eq. 13)
 * both read it, so a temperature that ran away makes them huge at whatever
 * particle moved fastest, and measuring them there named a consequence as the
 * cause (cookies.lua with gas=10: "thermal expansion ... 3.1e5 Pa" at a
 * particle of the unleavened cookie, whose temperature had been driven to
 * 3e6 degC; its neighbour in the leavened one was at -4e6 degC, and the
 * temperature range had grown x4 a step for 7 steps before the motion ran
 * away). So a temperature out of range is named first, at the particle where
 * it is furthest out. Otherwise "thermal expansion (...)" or "gas pressure
 * (...)" when that term outweighs the plugin's stress at particle i, the
 * culprit the caller picked. But for a particle that swelled past what F
 * holds (swollen), the motion came first: a lone molten particle dilates
 * under a thermal pressure its yielding skeleton never relaxes, and its
 * temperature follows (docs/validation.md, "A lone hot particle"); so there
 * the terms are weighed at i whatever the temperatures. */
static void guard_cause(const hearth_scene *s, int i, int swollen, char *buf, size_t n) {
    buf[0] = '\0';
    guard_terms t;
    const int hot = swollen ? -1 : guard_temperature_runaway(s);
    if (hot >= 0) {
        const particles *ps = &s->ps;
        const double *x = pcold(ps, PC_X) + 3 * hot;
        guard_measure(s, hot, &t);
        snprintf(buf, n,
                 "the temperature ran away (an unstable heat step): particle %d (id %d) at (%.4g, %.4g, %.4g) m, "
                 "material #%d, is at T = %.4g degC, outside the [%g, %g] degC every input temperature is checked "
                 "to; thermal expansion (%.4g Pa there) and gas pressure (%.4g Pa) read T: its result, not the cause. ",
                 hot, pcoli(ps, PC_ID)[hot], x[0], x[1], x[2], pcoli(ps, PC_MAT)[hot], pcold(ps, PC_TEMPERATURE)[hot],
                 GUARD_T_LO, GUARD_T_HI, t.expansion, t.gas);
        return;
    }
    if (i < 0) return;
    guard_measure(s, i, &t);
    if (t.expansion > t.plugin && t.expansion >= t.gas)
        snprintf(buf, n,
                 "thermal expansion blew the material apart: its pressure c lambda (T - T_ref) = %.4g Pa "
                 "outweighs the plugin's stress (%.4g Pa) and gas pressure (%.4g Pa) at the particle; lower the "
                 "material's `expansion` or heat it more slowly. ",
                 t.expansion, t.plugin, t.gas);
    else if (t.gas > t.plugin && s->mats.slot[pcoli(&s->ps, PC_MAT)[i]].core[CP_AMBIENT_PRESSURE] > 0)
        snprintf(buf, n,
                 "gas pressure blew the material apart: the pores' overpressure over ambient_pressure (gas.h, "
                 "gas_tau_ambient) = %.4g Pa outweighs the plugin's stress (%.4g Pa) and thermal expansion (%.4g Pa) "
                 "at the particle (the gas's stiffness is in the step's wave speed); lower gas_rate or cfl. ",
                 t.gas, t.plugin, t.expansion);
    else if (t.gas > t.plugin)
        snprintf(buf, n,
                 "gas pressure blew the material apart: the CO2 pressure n^g R T / n^p = %.4g Pa outweighs the "
                 "plugin's stress (%.4g Pa) and thermal expansion (%.4g Pa) at the particle (the step is chosen "
                 "from the plugin's wave speed, which does not include it); lower gas_rate, raise porosity or "
                 "lower cfl. ",
                 t.gas, t.plugin, t.expansion);
}

/* The wave speed of particle i's material in its current state. */
static double guard_wave_speed(const hearth_scene *s, int i) {
    const particles *ps = &s->ps;
    const int mat = pcoli(ps, PC_MAT)[i];
    const material_slot *ms = &s->mats.slot[mat];
    if (!ms->wave_per_point) return ms->wave_speed;
    double pscratch[SCENE_MAX_PARAMS];
    plugin_call_enter(ms->m, "wave_speed");
    const double c = ms->m->wave_speed(material_params(&s->mats, &s->ps, mat, i, pscratch),
                                       ms->m->state_size > 0 ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL);
    plugin_call_leave();
    return c;
}

static void guard_wave_text(const hearth_scene *s, int i, char *what, size_t n) {
    const material_slot *ms = &s->mats.slot[pcoli(&s->ps, PC_MAT)[i]];
    snprintf(what, n,
             "plugin '%s' (%s): wave_speed returned %g m/s; it must be finite and > 0, since the step size is "
             "chosen from it (run hearth plugin check on it)",
             ms->m->name, hearth_plugin_file(ms->plugin) ? hearth_plugin_file(ms->plugin) : "built in",
             guard_wave_speed(s, i));
}

/* A bulk modulus that was not finite and > 0 (material.h, material_thermal_scales): the point failed
 * rather than fall back to the thermal pressure. The value is asked again at the particle's parameters
 * and state after the step (the step does not keep it; a K that reads the state may have moved). */
static void guard_bulk_text(const hearth_scene *s, int i, char *what, size_t n) {
    const particles *ps = &s->ps;
    const int mat = pcoli(ps, PC_MAT)[i];
    const material_slot *ms = &s->mats.slot[mat];
    double pscratch[SCENE_MAX_PARAMS];
    plugin_call_enter(ms->m, "bulk_modulus");
    const double K = ms->m->bulk_modulus(material_params(&s->mats, ps, mat, i, pscratch),
                                         ms->m->state_size > 0 ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL);
    plugin_call_leave();
    char val[96];
    if (K > 0 && K < INFINITY)
        snprintf(val, sizeof val, "a value not finite and > 0 (%g Pa when asked again after the step)", K);
    else
        snprintf(val, sizeof val, "%g Pa", K);
    snprintf(what, n,
             "plugin '%s' (%s): bulk_modulus returned %s; it must be finite and > 0, since eq. 10's thermal strain "
             "ln J_th = c lambda (T - T_ref) / K divides by it (the core does not fall back to the thermal pressure; "
             "run hearth plugin check on it)",
             ms->m->name, hearth_plugin_file(ms->plugin) ? hearth_plugin_file(ms->plugin) : "built in", val);
}

/* A crushed particle (|det F| within GUARD_SWELL) names no cause of its own, yet it may be a symptom: a block
 * that swells without end under thermal expansion throws particles at the walls, and which one fails first, a
 * swollen one or one crushed against a wall, turns on the seeding's jitter (tests/cli_test.sh,
 * cli_guard_expansion_named: on main the guard named thermal expansion with seed 1 alone of seeds 1-5; the other
 * four reported an inverted F at x = 0.04 or 0.93 m with no cause; docs/validation.md, "Tests that flip with the
 * seeding"). So the terms are weighed at the most swollen particle of the same material (|det F| past GUARD_SWELL or
 * not finite; the lowest index among equals), when there is one, and the message says where. Another material's
 * swelling is not taken as the cause: one body's blow-up says nothing of another's crush. */
static void guard_swollen_elsewhere(const hearth_scene *s, int mat, char *buf, size_t n) {
    const particles *ps = &s->ps;
    int worst = -1;
    double far = GUARD_SWELL;
    for (int k = 0; k < ps->n; k++) {
        if (pcoli(ps, PC_MAT)[k] != mat) continue;
        double F[9];
        particles_F3(ps, k, F);
        const double a = isfinite(t3_det(F)) ? fabs(t3_det(F)) : INFINITY;
        if (a > far) far = a, worst = k;
    }
    if (worst < 0) return;
    guard_cause(s, worst, 1, buf, n);
    const size_t k = strlen(buf);
    if (!k) return;
    double F[9];
    particles_F3(ps, worst, F);
    snprintf(buf + k, n - k, "(weighed at particle %d (id %d) of the same material, swollen to det F = %.3g; the one "
             "that failed first was crushed) ", worst, pcoli(ps, PC_ID)[worst], t3_det(F));
}

int guard_check(hearth_scene *s, const step_report *rep, double dt, double speed_before) {
    const double dx = s->def.dx;
    s->cfl_last = (fmax(speed_before, rep->max_speed) + s->c_max) * dt / dx;
    char who[200], what[640], cause[400];
    if (rep->particle >= 0) {
        const int i = rep->particle;
        describe_particle(s, i, who, sizeof who);
        const material_slot *ms = &s->mats.slot[pcoli(&s->ps, PC_MAT)[i]];
        switch (rep->kind) {
        case FAIL_PLUGIN: {
            plugin_call_enter(ms->m, "describe_error");
            const char *txt = ms->m->describe_error(rep->code);
            plugin_call_leave();
            snprintf(what, sizeof what, "stress: plugin '%s' returned code %d: %s", ms->m->name, rep->code, txt ? txt : "(no text)");
            break;
        }
        case FAIL_STRESS: snprintf(what, sizeof what, "stress is NaN or inf (returned by plugin '%s')", ms->m->name); break;
        case FAIL_WAVE: guard_wave_text(s, i, what, sizeof what); break;
        case FAIL_BULK: guard_bulk_text(s, i, what, sizeof what); break;
        case FAIL_F: snprintf(what, sizeof what, "deformation gradient F is not finite or inverted (det F <= 0)"); break;
        case FAIL_X: snprintf(what, sizeof what, "position is NaN or inf"); break;
        case FAIL_V: snprintf(what, sizeof what, "velocity is NaN or inf"); break;
        default: snprintf(what, sizeof what, "velocity gradient C is NaN or inf"); break;
        }
        /* a particle that swelled past what F holds: name the term that drove it (a lone particle under its
         * thermal pressure, docs/validation.md "A lone hot particle") */
        cause[0] = '\0';
        if (rep->kind == FAIL_F) {
            double F[9];
            particles_F3(&s->ps, i, F);
            if (!(fabs(t3_det(F)) <= GUARD_SWELL)) guard_cause(s, i, 1, cause, sizeof cause); /* a crushed F is no swelling */
            else guard_swollen_elsewhere(s, pcoli(&s->ps, PC_MAT)[i], cause, sizeof cause);
        }
        snprintf(s->diagnosis, sizeof s->diagnosis, "guard: step %ld, t = %.6g s: %s%s: %s", s->step + 1, s->t + dt, cause, who, what);
        return 1;
    }
    /* Two CFL conditions: no particle may cross more than a cell, and elastic
     * waves may not cross more than a cell (the latter is what cfl > 1 breaks).
     * Motion is judged by how far a particle was moved (G2P), not only by its
     * speed at the end of the step: a floor or collider may have zeroed the
     * speed of a particle that jumped many cells onto it. */
    const double speed_move = rep->max_speed * dt / dx, jump = rep->max_move / dx;
    const double move = fmax(speed_move, jump), wave = s->c_max * dt / dx;
    if (move > 1.0 + 1e-9 || wave > 1.0 + 1e-9) {
        const int culprit = jump > speed_move && rep->mover >= 0 ? rep->mover : rep->fastest;
        if (culprit >= 0) describe_particle(s, culprit, who, sizeof who);
        else snprintf(who, sizeof who, "no particle");
        guard_cause(s, culprit, 0, cause, sizeof cause);
        if (jump > speed_move && jump > 1.0 + 1e-9)
            snprintf(s->diagnosis, sizeof s->diagnosis,
                     "guard: step %ld, t = %.6g s: %sCFL violated: a particle moved %.3g cells in one step of dt = "
                     "%.4g s (its speed at the end, %.4g m/s, is lower: a wall or collider stopped it), and waves "
                     "(%.4g m/s) crossed %.3g cells; the limit is 1 (%s); lower cfl or dt_max",
                     s->step + 1, s->t + dt, cause, jump, dt, rep->max_speed, s->c_max, wave, who);
        else
            snprintf(s->diagnosis, sizeof s->diagnosis,
                     "guard: step %ld, t = %.6g s: %sCFL violated: %s moved %.3g cells and waves (%.4g m/s) crossed "
                     "%.3g cells in dt = %.4g s; the limit is 1 (fastest: %s, speed %.4g m/s); lower cfl or dt_max",
                     s->step + 1, s->t + dt, cause, move > 1.0 + 1e-9 ? "a particle" : "no particle", move, s->c_max,
                     wave, dt, who, rep->max_speed);
        return 1;
    }
    /* Runaway: growth by energy_growth in one step beyond anything seen so far.
     * Judging against the last step alone would flag an oscillator passing
     * its turning point, where the kinetic energy is momentarily near zero.
     * Motion below a thousandth of a cell per step is not judged: a body
     * starting from rest (a drying block, a slow creep) multiplies a tiny
     * energy many times without anything going wrong, and a real runaway
     * grows past that speed within a few steps and is caught there.
     * A moving collider may give the material energy at once (a spatula that
     * starts to turn under a resting pancake): the reference is at least the
     * energy of every particle moving as fast as the fastest collider that
     * holds a node, so only growth beyond what the colliders drive counts. */
    const double ref = fmax(fmax(s->kinetic, s->kinetic_peak), rep->driven_kinetic);
    if (ref > 1e-300 && rep->kinetic > s->def.energy_growth * ref && move > 1e-3) {
        if (rep->fastest >= 0) describe_particle(s, rep->fastest, who, sizeof who);
        else snprintf(who, sizeof who, "no particle");
        guard_cause(s, rep->fastest, 0, cause, sizeof cause);
        snprintf(s->diagnosis, sizeof s->diagnosis,
                 "guard: step %ld, t = %.6g s: %skinetic energy ran away: it reached %.4g J, x%.3g the largest so far (%.4g J; limit x%g); "
                 "fastest: %s",
                 s->step + 1, s->t + dt, cause, rep->kinetic, rep->kinetic / ref, ref, s->def.energy_growth, who);
        return 1;
    }
    return 0;
}

/* No step can be taken: dt is 0, NaN or too small to advance the clock.
 * Name what set it; a wave speed a plugin returned is the usual culprit. */
hearth_status guard_no_step(hearth_scene *s, double dt, hearth_error *err) {
    char who[200], what[400];
    const particles *ps = &s->ps;
    const int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    int bad = -1;
    for (int i = 0; i < ps->n && bad < 0; i++) {
        if (flags && (flags[i] & PF_FIXED)) continue;
        const double c = guard_wave_speed(s, i);
        if (!(c > 0 && c <= DBL_MAX)) bad = i;
    }
    if (bad >= 0) {
        describe_particle(s, bad, who, sizeof who);
        guard_wave_text(s, bad, what, sizeof what);
        snprintf(s->diagnosis, sizeof s->diagnosis, "guard: step %ld, t = %.6g s: no step is possible: %s: %s", s->step + 1,
                 s->t, who, what);
    } else {
        snprintf(s->diagnosis, sizeof s->diagnosis,
                 "guard: step %ld, t = %.6g s: no step is possible: the stable step is %g s (largest speed %g m/s, "
                 "wave speed %g m/s, dx %g m, cfl %g); it does not advance the clock",
                 s->step + 1, s->t, dt, s->max_speed, s->c_max, s->def.dx, s->def.cfl);
    }
    s->guard = HEARTH_GUARD_STOPPED;
    return err_set(err, HEARTH_ERR_GUARD, "%s", s->diagnosis);
}

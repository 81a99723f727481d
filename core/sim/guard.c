/* guard.c: the stability guard. After every step it decides whether the step
 * may stand, and if not, writes a diagnosis a user can act on: step, time,
 * particle, position, material and the quantity that went bad. */
#include <math.h>
#include <stdio.h>

#include "scene.h"

static void describe_particle(const hearth_scene *s, int i, char *buf, size_t n) {
    const particles *ps = &s->ps;
    const double *x = pcold(ps, PC_X) + 3 * i;
    const int m = pcoli(ps, PC_MAT)[i];
    snprintf(buf, n, "particle %d (id %d) at (%.6g, %.6g, %.6g) m, material '%s' (#%d)", i, pcoli(ps, PC_ID)[i], x[0],
             x[1], x[2], s->mats[m].m->name, m);
}

int guard_check(hearth_scene *s, const step_report *rep, double dt, double speed_before) {
    const double dx = s->def.dx;
    s->cfl_last = (fmax(speed_before, rep->max_speed) + s->c_max) * dt / dx;
    char who[200], what[320];
    if (rep->particle >= 0) {
        const int i = rep->particle;
        describe_particle(s, i, who, sizeof who);
        const material_slot *ms = &s->mats[pcoli(&s->ps, PC_MAT)[i]];
        switch (rep->kind) {
        case FAIL_PLUGIN: {
            const char *txt = ms->m->describe_error(rep->code);
            snprintf(what, sizeof what, "stress: plugin '%s' returned code %d: %s", ms->m->name, rep->code, txt ? txt : "(no text)");
            break;
        }
        case FAIL_STRESS: snprintf(what, sizeof what, "stress is NaN or inf (returned by plugin '%s')", ms->m->name); break;
        case FAIL_F: snprintf(what, sizeof what, "deformation gradient F is not finite or inverted (det F <= 0)"); break;
        case FAIL_X: snprintf(what, sizeof what, "position is NaN or inf"); break;
        case FAIL_V: snprintf(what, sizeof what, "velocity is NaN or inf"); break;
        default: snprintf(what, sizeof what, "velocity gradient C is NaN or inf"); break;
        }
        snprintf(s->diagnosis, sizeof s->diagnosis, "guard: step %ld, t = %.6g s: %s: %s", s->step + 1, s->t + dt, who, what);
        return 1;
    }
    /* Two CFL conditions: no particle may cross more than a cell, and elastic
     * waves may not cross more than a cell (the latter is what cfl > 1 breaks). */
    const double move = rep->max_speed * dt / dx, wave = s->c_max * dt / dx;
    if (move > 1.0 + 1e-9 || wave > 1.0 + 1e-9) {
        if (rep->fastest >= 0) describe_particle(s, rep->fastest, who, sizeof who);
        else snprintf(who, sizeof who, "no particle");
        snprintf(s->diagnosis, sizeof s->diagnosis,
                 "guard: step %ld, t = %.6g s: CFL violated: %s moved %.3g cells and waves (%.4g m/s) crossed %.3g cells in dt = %.4g s; "
                 "the limit is 1 (fastest: %s, speed %.4g m/s); lower cfl or dt_max",
                 s->step + 1, s->t + dt, move > 1.0 + 1e-9 ? "a particle" : "no particle", move, s->c_max, wave, dt, who,
                 rep->max_speed);
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
        snprintf(s->diagnosis, sizeof s->diagnosis,
                 "guard: step %ld, t = %.6g s: kinetic energy ran away: it reached %.4g J, x%.3g the largest so far (%.4g J; limit x%g); "
                 "fastest: %s",
                 s->step + 1, s->t + dt, rep->kinetic, rep->kinetic / ref, ref, s->def.energy_growth, who);
        return 1;
    }
    return 0;
}

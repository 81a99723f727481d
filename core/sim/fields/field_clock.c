/* field_clock.c: the fields' own clock (multirate stepping, issue 20).
 *
 * Heat, water and CO2 (Ding et al. 2019 §3.2, eq. 8-11) diffuse over times far
 * longer than the mechanical step, which the elastic waves' CFL sets: the
 * bench's paper cookie at dx 1/64 m conducts at a limit of 2e-2 s against a
 * step of 1e-5 s. The particles carry their temperature, water and CO2 every
 * step (advection is Lagrangian and costs nothing); the grid transfer of the
 * fields, the conduction, the boundary, the sources and the fields' G2P run
 * only every k-th step, over the time dt_f the k steps took together, as one
 * step of the single-rate scheme at the positions of the k-th step. Forward
 * Euler is stable to field_clock_limit, so a field step stays within
 * FIELD_SAFETY of it.
 *
 * The cycle: s->field_acc is the time the particles have moved since the last
 * field step, s->field_phase the steps. A step of dt carries the fields when
 * waiting one more step of the same dt would take the cycle past the safe
 * limit (automatic, field_steps = 0, the default), or when it is the k-th
 * (field_steps = k; k = 1 is the single-rate scheme: every step, dt_f = 0 +
 * dt = dt exactly).
 * Both live in the checkpoint's clocks and change only when a step stands, so
 * a rolled back step plans again with its halved dt, and a restore mid-cycle
 * continues to the same bits.
 *
 * What the cycle changes against single rate: the expansion heating theta c
 * lambda div v (eq. 9) and the boundary's area are sampled at the field step
 * and applied over dt_f; the material sees each particle's temperature and
 * water as they stood at the last field step (held for at most dt_f). The
 * CO2 is the particles' own and moves every step (gas.c's gas_between: made
 * at the held temperature, vented through the surface of the last field
 * step), the field step completing the cycle's linear-temperature total. A
 * venting scene's first step carries the fields, so its open surface is known
 * from t = 0. (Not every scene's: the drying block of `water_drying_shrinks`
 * then met its first cycle's water lump moving, and the guard stopped it as a
 * runaway, x1.25e5 the first step's kinetic energy; from rest it is not
 * judged.)
 * Kept single rate: implicit heat (no explicit limit; backward Euler's
 * accuracy is the user's dt), the water's momentum (eq. 26-27: an impulse on
 * the grid each step) and a scene with no finite limit (no conduction,
 * boundary or water: nothing sets a cycle). MPI ranks run the same cycle:
 * they agree on the limit (agreed_limit), so every rank closes it on the
 * same step, and the field halos move on field steps only
 * (mpm_ranks_fields.c).
 * Safety: dt can grow between the steps of a cycle (dt_scale recovers x1.25 a
 * step); the closing rule looks one step ahead at the current dt, and the
 * factor 10 of FIELD_SAFETY covers growth up to 0.9 of the limit in one step.
 *
 * Measured (scripts/bench/field_rates.lua, docs/performance.md "The fields on
 * their own clock"): k is 203 on the 2D dough bench (dt_max 1e-5 s), 4-8 in
 * muffins.lua, 19 in loaf_physical.lua, and 1 in cookies.lua and bread.lua,
 * whose Table 2 conduction (kappa 30-100 W/(m K), c 20 J/(kg K)) sets or
 * nearly sets the step there: the clock changes nothing for them.
 *
 * The automatic cycle is the default (field_steps = 0); field_steps = 1 is
 * the single-rate scheme to the bit. It was opt-in while three things were
 * the cycle's: gas made in lumps of a cycle swelled a lone pore off its
 * quasi-static closed form (`lone_gassy_pore_gas_volume_fraction`) and let a
 * vented particle's n^g stand still between updates
 * (`gas_vent_decays_at_closed_form`), both mended by the CO2 moving every
 * step; MPI ranks stayed single rate while one rank cycled (the 13
 * `mpi_*_matches_one_rank`); and `stability_matrix`'s porosity-1e-6 cells,
 * whose gas pressure stops the guard, completed because no gas was made
 * before the first update. */
#include "field_clock.h"

#include <math.h>

#include "mpm.h"
#include "ranks.h"
#include "scene.h"
#include "thermal.h"
#include "water.h"

double field_clock_limit(const hearth_scene *s) { return fmin(thermal_dt_limit(s), water_dt_limit(s)); }

/* whether this scene may run its fields on their own clock */
static int multirate(const hearth_scene *s) {
    if (s->def.field_steps == 1 || s->def.solver != HEARTH_SOLVER_MPM || s->def.heat_implicit) return 0;
    if (s->def.water_momentum) return 0; /* the water's flux is a momentum impulse (eq. 26-27): the mechanics' every step */
    return thermal_active(s) || water_active(s);
}

/* The safe limit, the same on every MPI rank: each rank's water limit is its own particles' until a field
 * step's water_finish has agreed on it, so the ranks take the smallest (a minimum is exact in any order).
 * Every rank plans every step, so the cycles close on the same steps and the field halos move on those only
 * (mpm_ranks_fields.c). */
static void take_min(void *acc, const void *next, void *ctx) {
    (void)ctx;
    *(double *)acc = fmin(*(double *)acc, *(const double *)next);
}
static double agreed_limit(const hearth_scene *s) {
    double lim = FIELD_SAFETY * field_clock_limit(s);
    const mpm_state *m = mpm_state_of(s);
    if (m && m->nranks > 1) ranks_combine(&lim, sizeof lim, take_min, NULL);
    return lim;
}

void field_clock_plan(hearth_scene *s, double dt) {
    if (!multirate(s)) {
        s->field_skip = 0;
        s->field_dt = s->field_acc + dt; /* single rate: field_acc is 0 (a cycle left by a setting change closes now) */
        return;
    }
    const double acc = s->field_acc + dt;
    int due;
    if (s->def.field_steps > 1) due = s->field_phase + 1 >= s->def.field_steps;
    else {
        /* no finite limit (no conduction, boundary or water: CO2 alone at each particle's temperature) has no
         * time scale to pick a cycle from: every step, as before */
        const double lim = agreed_limit(s);
        due = !(acc + dt <= lim) || !isfinite(lim);
    }
    if (s->field_phase + 1 >= FIELD_MAX_CYCLE) due = 1;
    /* a venting scene's first step carries the fields: the vents' open surface (gas.c's PC_VENT) comes from a
     * field step's boundary, and without one nothing could vent for a whole cycle; the cycles follow */
    if (s->field_cycle_last == 0 && (s->ps.enabled & (1u << PC_VENT))) due = 1;
    s->field_skip = !due;
    s->field_dt = due ? acc : 0.0;
}

void field_clock_stands(hearth_scene *s, double dt) {
    if (!s->field_skip) {
        s->field_dt_last = s->field_dt;
        s->field_cycle_last = s->field_phase + 1;
        s->field_acc = 0;
        s->field_phase = 0;
    } else {
        s->field_acc += dt;
        s->field_phase++;
    }
    s->field_skip = 0; /* between steps the plan is neutral: a step nobody planned carries the fields over its dt */
    s->field_dt = 0;
}

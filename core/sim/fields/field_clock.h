/* field_clock.h: when MPM's heat, water and CO2 step, and over what time
 * (multirate stepping, issue 20). Reasons in field_clock.c. */
#ifndef HEARTH_FIELD_CLOCK_H
#define HEARTH_FIELD_CLOCK_H

struct hearth_scene;

/// The safety factor of the automatic cycle: a field step covers at most this
/// share of the fields' own explicit limit (field_clock_limit). Stability
/// alone allows 1; at 0.5 a drying block's water fell in steps of 2% that set
/// it ringing (`water_drying_shrinks` not monotone), at 0.1 it shrinks as at
/// single rate (field_clock.c).
#define FIELD_SAFETY 0.1
/// The longest cycle, in steps (and the largest field_steps).
#define FIELD_MAX_CYCLE 4096

/// The fields' own step limit (s): thermal_dt_limit and water_dt_limit, the
/// tighter; infinite without fields.
double field_clock_limit(const struct hearth_scene *s);

/// Before a step of dt: sets s->field_skip (this step carries no field update)
/// or s->field_dt, the time the fields advance in it (the cycle's steps so far
/// plus dt).
void field_clock_plan(struct hearth_scene *s, double dt);

/// After the step stood: the cycle ends when the step carried the fields,
/// else it grows by dt.
void field_clock_stands(struct hearth_scene *s, double dt);

#endif

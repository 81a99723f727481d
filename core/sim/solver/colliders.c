/* colliders.c: moving analytic colliders (rigid motion of a hearth_shape)
 * and the contact projection applied to grid velocities.
 *
 * The shape is never transformed; queries are mapped into its t = 0 frame.
 * That keeps shapes immutable and the SDF exact under any rigid motion. */
#include "colliders.h"

#include <math.h>
#include <string.h>

#include "error.h"
#include "shapes.h"
#include "tensor.h"

/* Report the first non-finite component of a def vector. */
static hearth_status check_vec(const double a[3], const char *name, const char *unit, hearth_error *err) {
    for (int i = 0; i < 3; i++)
        if (!isfinite(a[i]))
            return err_set(err, HEARTH_ERR_PARAM, "collider %s[%d] = %g is not finite; valid range: any finite %s",
                           name, i, a[i], unit);
    return HEARTH_OK;
}

hearth_status collider_init(collider *c, const hearth_collider_def *def, hearth_error *err) {
    HEARTH_ASSERT(c && def);
    memset(c, 0, sizeof *c); /* so collider_free is safe whatever happens below */
    if (!def->shape)
        return err_set(err, HEARTH_ERR_PARAM,
                       "collider shape is NULL; valid: a shape from hearth_shape_* (copied by the collider)");
    if (!(def->friction >= 0) || !isfinite(def->friction))
        return err_set(err, HEARTH_ERR_PARAM,
                       "collider friction = %g is out of range; valid range: [0, inf) (Coulomb coefficient, finite)",
                       def->friction);
    if (def->mode != HEARTH_STICKY && def->mode != HEARTH_SLIP && def->mode != HEARTH_SEPARATE && def->mode != HEARTH_GRIP)
        return err_set(err, HEARTH_ERR_PARAM,
                       "collider mode = %d is out of range; valid: 0 (sticky), 1 (slip), 2 (separate), 3 (grip)",
                       (int)def->mode);
    hearth_status st;
    if ((st = check_vec(def->velocity, "velocity", "m/s", err)) != HEARTH_OK) return st;
    if ((st = check_vec(def->omega, "omega", "rad/s", err)) != HEARTH_OK) return st;
    if ((st = check_vec(def->pivot, "pivot", "m", err)) != HEARTH_OK) return st;

    c->shape = hearth_shape_copy(def->shape);
    if (!c->shape) return err_set(err, HEARTH_ERR_NOMEM, "collider: out of memory copying the shape");
    c->mode = def->mode;
    c->friction = def->friction;
    memcpy(c->vel, def->velocity, sizeof c->vel);
    memcpy(c->omega, def->omega, sizeof c->omega);
    memcpy(c->pivot0, def->pivot, sizeof c->pivot0);
    t3_identity(c->R);
    c->motion = def->motion;
    c->motion_ud = def->motion_ud;
    if (!isnan(def->temperature) && !(def->temperature >= -273.15 && def->temperature <= 5000)) {
        hearth_shape_free(c->shape);
        c->shape = NULL;
        return err_set(err, HEARTH_ERR_PARAM, "collider temperature = %g degrees C; valid range [-273.15, 5000]", def->temperature);
    }
    if (!(def->beta >= 0)) { /* +inf: a held temperature (thermal.c) */
        hearth_shape_free(c->shape);
        c->shape = NULL;
        return err_set(err, HEARTH_ERR_PARAM, "collider beta = %g W/(m^2 K); valid range [0, inf] (inf: held at its temperature)", def->beta);
    }
    if (!isnan(def->saturation) && !(def->saturation >= 0 && def->saturation <= 1)) {
        hearth_shape_free(c->shape);
        c->shape = NULL;
        return err_set(err, HEARTH_ERR_PARAM, "collider saturation = %g; valid range [0, 1] (NaN = dry)", def->saturation);
    }
    if (!(def->beta_water >= 0) || !isfinite(def->beta_water) || (def->beta_water > 0 && isnan(def->saturation))) {
        hearth_shape_free(c->shape);
        c->shape = NULL;
        if (def->beta_water > 0 && isfinite(def->beta_water))
            return err_set(err, HEARTH_ERR_PARAM, "collider beta_water = %g kg/(m^2 s) needs the collider's saturation (the "
                                                  "ambient it exchanges with, [0, 1])", def->beta_water);
        return err_set(err, HEARTH_ERR_PARAM, "collider beta_water = %g kg/(m^2 s); valid range [0, inf) (0 = hold the saturation)",
                       def->beta_water);
    }
    /* warm_time 0 (a zeroed def too): a collider at its temperature from the start */
    if (def->warm_time != 0 && (!(def->warm_time > 0 && isfinite(def->warm_time)) || isnan(def->temperature) ||
                                !(def->start_temperature >= -273.15 && def->start_temperature <= 5000))) {
        hearth_shape_free(c->shape);
        c->shape = NULL;
        if (!(def->warm_time > 0 && isfinite(def->warm_time)))
            return err_set(err, HEARTH_ERR_PARAM, "collider warm_time = %g s; valid range [0, inf) (the warming sheet's time "
                                                  "constant; 0 = at its temperature from the start)", def->warm_time);
        if (isnan(def->temperature))
            return err_set(err, HEARTH_ERR_PARAM, "collider warm_time = %g s needs the collider's temperature (the "
                                                  "temperature it warms toward)", def->warm_time);
        return err_set(err, HEARTH_ERR_PARAM, "collider start_temperature = %g degrees C; valid range [-273.15, 5000] (with "
                                              "warm_time, its temperature when added)", def->start_temperature);
    }
    /* heat_capacity 0 (a zeroed def too): the food draws nothing from the sheet (its T(t) the oven's alone) */
    if (def->heat_capacity != 0 || def->area != 0) {
        st = HEARTH_OK;
        if (!(def->heat_capacity > 0 && def->heat_capacity <= 1e9))
            st = err_set(err, HEARTH_ERR_PARAM, "collider heat_capacity = %g J/(m^2 K); valid range (0, 1e9] (the sheet's "
                         "rho c thickness; 0 with area 0 = the food draws nothing from it)", def->heat_capacity);
        else if (!(def->area > 0 && def->area <= 1e6))
            st = err_set(err, HEARTH_ERR_PARAM, "collider area = %g m^2 (in 2D m, per metre of depth); valid range (0, 1e6] "
                         "(the sheet's area, with heat_capacity)", def->area);
        else if (!(def->warm_time > 0))
            st = err_set(err, HEARTH_ERR_PARAM, "collider heat_capacity = %g J/(m^2 K) needs warm_time > 0 and "
                         "start_temperature (the sheet's time constant under the oven: heat_capacity over the oven's "
                         "beta on its faces)", def->heat_capacity);
        else if (!(def->beta < INFINITY))
            st = err_set(err, HEARTH_ERR_PARAM, "collider heat_capacity = %g J/(m^2 K) needs a finite beta (a held face "
                         "passes no flux that could be taken from the sheet)", def->heat_capacity);
        if (st) {
            hearth_shape_free(c->shape);
            c->shape = NULL;
            return st;
        }
    }
    c->heat_capacity = def->heat_capacity;
    c->area = def->area;
    c->sheet_T = def->warm_time > 0 ? def->start_temperature : NAN;
    c->sheet_t = c->last_heat = c->last_span = c->step_heat = c->step_ret = c->oven_in = c->drawn = 0;
    c->temperature = def->temperature;
    c->temperature_end = def->temperature;
    c->start_temperature = def->warm_time > 0 ? def->start_temperature : NAN;
    c->warm_time = def->warm_time;
    c->t_added = 0;
    c->beta = def->beta;
    c->saturation = def->saturation;
    c->beta_water = def->beta_water;
    /* With a motion function the def constants are unused: start from motion(0)
     * so vel/omega are meaningful before the scene first sets the time. */
    collider_set_time(c, 0.0);
    return HEARTH_OK;
}

void collider_free(collider *c) {
    if (!c) return;
    hearth_shape_free(c->shape);
    c->shape = NULL;
}

/* A drawing sheet under the oven and a constant draw P (W): C A dT/dt = (C A / w) (T_end - T) - P, so T relaxes
 * toward T_inf = T_end - P w / (C A) with the time constant w. sheet_at: T after h from T0; sheet_mean: its mean over
 * [0, H] (exact for the exponential, as collider_heat_interval's). */
static double sheet_inf(const collider *c, double P) { return c->temperature_end - P * c->warm_time / (c->heat_capacity * c->area); }
static double sheet_at(const collider *c, double T0, double h, double P) {
    const double Ti = sheet_inf(c, P);
    return Ti + (T0 - Ti) * exp(-h / c->warm_time);
}
static double sheet_mean(const collider *c, double T0, double H, double P) {
    const double Ti = sheet_inf(c, P), x = H / c->warm_time;
    return Ti + (T0 - Ti) * -expm1(-x) / x;
}
/* the draw the next field step takes (lagged one field step: its own is known after its solve) */
static double sheet_last_power(const collider *c) { return c->last_span > 0 ? c->last_heat / c->last_span : 0.0; }

double collider_temperature_at(const collider *c, double t) {
    if (collider_draws(c)) /* from its state, the last field step's draw going on */
        return sheet_at(c, c->sheet_T, fmax(t - c->sheet_t, 0), sheet_last_power(c));
    if (c->warm_time > 0) /* a lumped sheet: its Biot number is small (a metal tray), so one temperature */
        return c->temperature_end + (c->start_temperature - c->temperature_end) * exp(-fmax(t - c->t_added, 0) / c->warm_time);
    return c->temperature;
}

void collider_set_time(collider *c, double t) {
    if (c->motion) c->motion(c->motion_ud, t, c->vel, c->omega);
    if (c->warm_time > 0) c->temperature = collider_temperature_at(c, t);
}

void collider_heat_interval(collider *c, double t0, double t1) {
    if (!(c->warm_time > 0) || !(t1 > t0)) return;
    if (collider_draws(c)) {
        /* from its state (the last field step's end; a gap before t0, none when the field steps follow each other,
         * warms by the oven alone, as collider_sheet_stands books it), its mean over the step with the last step's draw */
        const double a = fmax(t0, c->sheet_t);
        if (!(t1 > a)) return;
        const double Ta = sheet_at(c, c->sheet_T, a - c->sheet_t, 0.0);
        c->temperature = sheet_mean(c, Ta, t1 - a, sheet_last_power(c));
        return;
    }
    t0 = fmax(t0, c->t_added); /* added within the interval: its start */
    const double h = (t1 - t0) / c->warm_time;
    if (!(h > 0)) return;
    /* the mean of end + (start - end) e^{-(t - t_added)/w} over [t0, t1]: e^{-a} (1 - e^{-h}) / h, a = (t0 - t_added)/w */
    c->temperature = c->temperature_end + (c->start_temperature - c->temperature_end) *
                                              exp(-(t0 - c->t_added) / c->warm_time) * -expm1(-h) / h;
}

void collider_sheet_stands(collider *c, double t0, double t1, double heat) {
    if (!collider_draws(c)) return;
    const double CA = c->heat_capacity * c->area, a = fmax(t0, c->sheet_t);
    if (!(t1 > a)) return;
    /* the gap before the step (none when field steps follow each other): the oven alone */
    const double Ta = sheet_at(c, c->sheet_T, a - c->sheet_t, 0.0);
    /* the step: the draw its contact passed, spread evenly over it; the oven's input is what the ODE says it is,
     * C A dT + the draw (the test integrates the oven's term itself: unit_sheet_draw) */
    const double Tb = sheet_at(c, Ta, t1 - a, heat / (t1 - a));
    c->oven_in += CA * (Tb - c->sheet_T) + heat;
    c->drawn += heat;
    c->sheet_T = Tb;
    c->sheet_t = t1;
    c->last_heat = heat;
    c->last_span = t1 - a;
}

/* The rotation Q of one step dt at the angular velocity omega; 0 (Q
 * untouched) when the collider does not turn. */
static int step_rotation(const collider *c, double dt, double Q[9]) {
    const double w = sqrt(c->omega[0] * c->omega[0] + c->omega[1] * c->omega[1] + c->omega[2] * c->omega[2]);
    if (!(w > 0)) return 0;
    const double axis[3] = {c->omega[0] / w, c->omega[1] / w, c->omega[2] / w};
    t3_rotation(axis, w * dt, Q);
    return 1;
}

void collider_advance(collider *c, double dt) {
    for (int i = 0; i < 3; i++) c->offset[i] += c->vel[i] * dt;
    double Q[9], Rn[9];
    if (!step_rotation(c, dt, Q)) return;
    /* Left-multiply: omega is a world-frame angular velocity. */
    t3_mul(Q, c->R, Rn);
    t3_copy(Rn, c->R);
}

double collider_sdf(const collider *c, const double x[3], double n[3]) {
    double p[3], xl[3], nl[3];
    for (int i = 0; i < 3; i++) p[i] = x[i] - c->pivot0[i] - c->offset[i];
    /* xl = R^T p + pivot0 (R^T p written out: t3_mulv has no transpose form) */
    for (int i = 0; i < 3; i++)
        xl[i] = c->R[i] * p[0] + c->R[3 + i] * p[1] + c->R[6 + i] * p[2] + c->pivot0[i];
    double d = hearth_shape_sdf(c->shape, xl, n ? nl : NULL);
    if (n) t3_mulv(c->R, nl, n);
    return d;
}

void collider_velocity_at(const collider *c, const double x[3], double v[3]) {
    const double *w = c->omega;
    double r[3];
    for (int i = 0; i < 3; i++) r[i] = x[i] - c->pivot0[i] - c->offset[i];
    v[0] = c->vel[0] + w[1] * r[2] - w[2] * r[1];
    v[1] = c->vel[1] + w[2] * r[0] - w[0] * r[2];
    v[2] = c->vel[2] + w[0] * r[1] - w[1] * r[0];
}

void contact_apply(hearth_contact mode, double friction, const double n[3], const double vb[3], double v[3]) {
    if (mode == HEARTH_STICKY || mode == HEARTH_GRIP) {
        memcpy(v, vb, 3 * sizeof *v);
        return;
    }
    double rel[3] = {v[0] - vb[0], v[1] - vb[1], v[2] - vb[2]};
    double vn = rel[0] * n[0] + rel[1] * n[1] + rel[2] * n[2];
    if (mode == HEARTH_SEPARATE && vn >= 0) return; /* leaving or sliding: free */
    double vt[3] = {rel[0] - vn * n[0], rel[1] - vn * n[1], rel[2] - vn * n[2]};
    /* Coulomb: the impulse that removed |vn| can cancel at most friction*|vn|
     * of tangential speed. */
    double t = sqrt(vt[0] * vt[0] + vt[1] * vt[1] + vt[2] * vt[2]);
    double lim = friction * fabs(vn);
    double scale = t <= lim ? 0.0 : 1.0 - lim / t;
    for (int i = 0; i < 3; i++) v[i] = vb[i] + scale * vt[i];
}

void collider_update_bounds(collider *c, double margin) {
    double lo[3], hi[3];
    hearth_shape_bounds(c->shape, lo, hi);
    int finite = 1;
    for (int d = 0; d < 3; d++) finite = finite && isfinite(lo[d]) && isfinite(hi[d]);
    if (!finite) {
        for (int d = 0; d < 3; d++) {
            c->blo[d] = -INFINITY;
            c->bhi[d] = INFINITY;
        }
        return;
    }
    for (int d = 0; d < 3; d++) {
        c->blo[d] = INFINITY;
        c->bhi[d] = -INFINITY;
    }
    for (int k = 0; k < 8; k++) { /* the box of the 8 moved corners contains the moved shape */
        const double xl[3] = {k & 1 ? hi[0] : lo[0], k & 2 ? hi[1] : lo[1], k & 4 ? hi[2] : lo[2]};
        const double rel[3] = {xl[0] - c->pivot0[0], xl[1] - c->pivot0[1], xl[2] - c->pivot0[2]};
        double w[3];
        t3_mulv(c->R, rel, w);
        for (int d = 0; d < 3; d++) {
            const double x = w[d] + c->pivot0[d] + c->offset[d];
            c->blo[d] = fmin(c->blo[d], x - margin);
            c->bhi[d] = fmax(c->bhi[d], x + margin);
        }
    }
}

void collider_bound_half_space(collider *c, double margin) {
    int axis, sign;
    double pc;
    const double *R = c->R;
    if (!shape_axis_plane(c->shape, &axis, &sign, &pc)) return;
    if (!(R[0] == 1 && R[4] == 1 && R[8] == 1 && R[1] == 0 && R[2] == 0 && R[3] == 0 && R[5] == 0 && R[6] == 0 && R[7] == 0))
        return;
    /* collider_sdf is then sign (((x - pivot0) - offset) + pivot0 - pc) on that axis (R's products by 1 and 0
     * exact), four roundings of numbers below |x| + |pivot0| + |offset| + |pc|: the slack is some 1e5 times
     * that and still far below a cell */
    const double o = c->offset[axis], face = pc + o;
    const double slack = 1e-10 * (margin + 2 * (fabs(pc) + fabs(o) + fabs(c->pivot0[axis])));
    if (!isfinite(face + slack)) return;
    for (int d = 0; d < 3; d++) c->blo[d] = -INFINITY, c->bhi[d] = INFINITY;
    if (sign > 0) c->bhi[axis] = face + margin + slack; /* the solid lies below the face */
    else c->blo[axis] = face - margin - slack;
}

void collider_bound_prism(collider *c, double margin) {
    const double *R = c->R;
    /* a 2D box alone: its SDF is the exact distance to its rectangle (a mask's reaches half a pixel into its
     * border; a combination's is its parts'), so no point past the padded rectangle is within margin of it */
    if (!shape_box_2d(c->shape)) return;
    double lo[3], hi[3];
    hearth_shape_bounds(c->shape, lo, hi);
    if (!(isfinite(lo[0]) && isfinite(hi[0]) && isfinite(lo[1]) && isfinite(hi[1]))) return;
    /* turned about z alone (a 2D scene's rotations), so that the moved x and y depend on the local x and y alone */
    if (!(R[2] == 0 && R[5] == 0 && R[6] == 0 && R[7] == 0 && R[8] == 1)) return;
    double blo[2] = {INFINITY, INFINITY}, bhi[2] = {-INFINITY, -INFINITY}, big = margin;
    for (int k = 0; k < 4; k++) { /* the box of the 4 moved corners contains the moved section */
        const double rel[2] = {(k & 1 ? hi[0] : lo[0]) - c->pivot0[0], (k & 2 ? hi[1] : lo[1]) - c->pivot0[1]};
        for (int d = 0; d < 2; d++) {
            const double x = R[3 * d] * rel[0] + R[3 * d + 1] * rel[1] + c->pivot0[d] + c->offset[d];
            blo[d] = fmin(blo[d], x), bhi[d] = fmax(bhi[d], x);
            big = fmax(big, fabs(x) + fabs(c->pivot0[d]) + fabs(c->offset[d]));
        }
    }
    /* collider_sdf's own roundings, of numbers below big, move a distance by some 1e-16 big: the slack is a
     * million times that and still far below a cell, so a point it passes by is farther than margin */
    const double pad = margin + 1e-10 * big;
    if (!isfinite(pad)) return;
    for (int d = 0; d < 2; d++) c->blo[d] = blo[d] - pad, c->bhi[d] = bhi[d] + pad;
    c->blo[2] = -INFINITY, c->bhi[2] = INFINITY;
}

void collider_update_bounds_tight(collider *c, double margin) {
    collider_update_bounds(c, margin);
    collider_bound_half_space(c, margin);
    collider_bound_prism(c, margin);
}

int collider_list_near_box(const collider *cols, int ncol, const double lo[3], const double hi[3], int *near) {
    int n = 0;
    for (int c = 0; c < ncol; c++) {
        const collider *k = &cols[c];
        if (k->bhi[0] < lo[0] || k->blo[0] > hi[0] || k->bhi[1] < lo[1] || k->blo[1] > hi[1] || k->bhi[2] < lo[2] ||
            k->blo[2] > hi[2])
            continue;
        if (n == COLLIDER_NEAR_CAP) return -1;
        near[n++] = c;
    }
    return n;
}

int collider_carry_particle(const collider *c, int dim, double dt, double x[3], double v[3], double C[9]) {
    if (c->mode != HEARTH_GRIP || collider_sdf(c, x, NULL) >= 0) return 0;
    /* the rigid motion of the coming step about the current pivot, exact as in collider_advance */
    double r[3], vb[3];
    for (int i = 0; i < 3; i++) r[i] = x[i] - c->pivot0[i] - c->offset[i];
    collider_velocity_at(c, x, vb);
    double rr[3] = {r[0], r[1], r[2]}, Q[9];
    if (step_rotation(c, dt, Q)) t3_mulv(Q, r, rr);
    for (int d = 0; d < dim; d++) {
        x[d] += rr[d] - r[d] + c->vel[d] * dt;
        v[d] = vb[d];
    }
    if (!C) return 1;
    /* the velocity gradient of a rigid motion: skew(omega), so F only rotates */
    const double *o = c->omega;
    const double W[9] = {0, -o[2], o[1], o[2], 0, -o[0], -o[1], o[0], 0};
    for (int a = 0; a < 9; a++) C[a] = dim == 2 && (a % 3 == 2 || a / 3 == 2) ? 0.0 : W[a];
    return 1;
}

int collider_project_particle(const collider *c, int dim, double x[3], double v[3]) {
    if (c->mode == HEARTH_GRIP) return 0; /* a grip holds what is inside it (collider_carry_particle) */
    double n[3];
    const double phi = collider_sdf(c, x, n);
    if (phi >= 0) return 0;
    if (dim == 2) n[2] = 0;
    for (int d = 0; d < dim; d++) x[d] -= phi * n[d];
    double vb[3];
    collider_velocity_at(c, x, vb);
    if (dim == 2) vb[2] = 0;
    contact_apply(c->mode, c->friction, n, vb, v);
    return 1;
}

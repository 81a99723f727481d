/* colliders.h: moving analytic colliders and the grid contact rule.
 *
 * A collider holds its own copy of a shape in the frame it had at t = 0 and
 * the rigid motion accumulated since: world x = R (xl - pivot0) + pivot0 + offset.
 * The pivot moves with the collider, so omega always spins it about its
 * current pivot (pivot0 + offset). */
#ifndef HEARTH_SIM_COLLIDERS_H
#define HEARTH_SIM_COLLIDERS_H
#include "hearth/hearth.h"

typedef struct collider {
    hearth_shape *shape;     /* owned copy, in the collider's local (t=0) frame */
    hearth_contact mode;
    double friction;         /* Coulomb coefficient, >= 0 */
    double vel[3], omega[3]; /* current, from def constants or from motion(t) (m/s, rad/s) */
    double pivot0[3];        /* rotation centre at t=0 (m) */
    double offset[3];        /* translation so far (m) */
    double R[9];             /* rotation so far, row-major */
    hearth_motion_fn motion; /* optional; not owned */
    void *motion_ud;
    double blo[3], bhi[3];   /* world bounding box at the current pose (collider_update_bounds) */
    double temperature, beta;/* heated collider (degrees C, W/(m^2 K)); NaN temperature = not heated; the present
                              * temperature when it warms (collider_set_time) */
    double temperature_end;  /* a warming collider: the temperature it approaches (degrees C) */
    double start_temperature;/* a warming collider: its temperature at t_added (NaN when it does not warm) */
    double warm_time, t_added;/* a warming collider: its time constant (0: it does not warm) and when it was added (s) */
    /* a drawing sheet (heat_capacity > 0): the food's heat is taken from it, C A dT/dt = (C A / w) (T_end - T) - Q(t).
     * Its state: sheet_T at sheet_t (the end of the last field step that stood); last_heat (J) over last_span (s), the
     * heat its contact passed in that step, which the next step's temperature takes as its draw (lagged one field
     * step: the step's own is known only after its solve); step_heat the heat this field step's contact passes
     * (thermal.c; flip_bound.c's clamps give back step_ret, this rank's until summed); oven_in and drawn the books since t_added (J). */
    double heat_capacity, area;
    double sheet_T, sheet_t, last_heat, last_span, step_heat, step_ret, oven_in, drawn;
    double saturation;       /* wet collider: held saturation of touching particles; NaN = dry */
    double beta_water;       /* wet collider: 0 holds saturation (Dirichlet); > 0 Robin exchange, kg/(m^2 s) */
} collider;

/// Validate def and fill c (shape copied). On failure c holds nothing to free and
/// err names the parameter and its valid range (HEARTH_ERR_PARAM) or HEARTH_ERR_NOMEM.
/// With a motion function, vel/omega come from motion(0).
hearth_status collider_init(collider *c, const hearth_collider_def *def, hearth_error *err);
/// Release the shape copy (c may be zeroed or already freed).
void collider_free(collider *c);
/// If c has a motion function, vel and omega = motion(t); a warming collider's temperature at t (its
/// lumped sheet's exponential from start_temperature toward temperature_end since t_added).
void collider_set_time(collider *c, double t);
/// A heated collider's temperature at t (collider_set_time's, without its motion): a warming sheet's exponential, a
/// drawing sheet's state carried on with its last draw, else its temperature.
double collider_temperature_at(const collider *c, double t);
/// A warming collider's temperature over the heat step that covers [t0, t1]: its mean there (exact for the
/// exponential), so the fields see it without the lag a value at the step's start would leave (first order in
/// the step; with it the slab on a warming plate converges as on a steady one, unit_heat_bc). Else nothing.
void collider_heat_interval(collider *c, double t0, double t1);
/// 1 when c is a drawing sheet (heat_capacity > 0): the heat its contact gives the food is taken from it.
static inline int collider_draws(const collider *c) { return c->heat_capacity > 0; }
/// A drawing sheet's field step over [t0, t1] stood, its contact having passed heat (J) to the food: the sheet
/// advances from its state to t1 (the oven's exponential with the draw heat / (t1 - t0) as a constant sink, exact
/// for that ODE) and its books take the oven's input and the draw. A sheet that does not draw: nothing.
void collider_sheet_stands(collider *c, double t0, double t1, double heat);
/// Move by the current vel/omega over dt (s): exact for constant vel and omega.
void collider_advance(collider *c, double dt);
/// Signed distance (m, negative inside) at world point x; n (may be NULL) gets the
/// outward unit normal in world space.
double collider_sdf(const collider *c, const double x[3], double n[3]);
/// Recompute the world bounding box (blo, bhi) of the current pose, grown by margin (m).
/// Unbounded shapes (planes) get infinite boxes.
void collider_update_bounds(collider *c, double margin);
/// After collider_update_bounds, on MPM: a plane whose normal is a coordinate axis and that has not turned
/// (R the identity; a tray) gets the half-space within margin of its face (and a rounding's slack) as its
/// box, open along the other axes, instead of the whole space, so that collider_near passes by the
/// particles above a tray as it does those far from a finite shape. Every MPM caller's band is within the
/// margin (2 dx: CONTACT_BAND, boundary.c's 2 dx, water.c's dx, the sticky 1.5 dx, COLLIDER_ROW_TOL),
/// so what they find is the same. Not on SPH, whose heated colliders reach h = h_factor V0^(1/dim), past 2 dx.
void collider_bound_half_space(collider *c, double margin);
/// After collider_update_bounds, on MPM: a box with no z extent (every box of a 2D scene: its rectangle
/// extruded along z, unbounded there) that has turned about z alone gets the box of its moved rectangle
/// grown by margin (and a rounding's slack), open along z, instead of the whole space, which its infinite z
/// gave it: collider_near then passes by the particles and nodes far from a 2D scene's crackers or cup as it
/// does in 3D (the marshmallow's two crackers were 18% of its instructions, every particle and node asking
/// both every step; helper citime). Every MPM caller's band is within the margin (collider_bound_half_space),
/// so what they find is the same. Not on SPH (collider_bound_half_space says why).
void collider_bound_prism(collider *c, double margin);
/// collider_update_bounds, then collider_bound_half_space and collider_bound_prism: the tight bounds an MPM
/// step and a picture's collider map use (their bands within margin).
void collider_update_bounds_tight(collider *c, double margin);
/// 1 when x lies inside the cached bounding box (cheap test before collider_sdf).
static inline int collider_near(const collider *c, const double x[3]) {
    return x[0] >= c->blo[0] && x[0] <= c->bhi[0] && x[1] >= c->blo[1] && x[1] <= c->bhi[1] && x[2] >= c->blo[2] &&
           x[2] <= c->bhi[2];
}
/// The colliders whose bounds meet the box [lo, hi], in ascending order, into near (room for
/// COLLIDER_NEAR_CAP): their count, or -1 when more meet it (the caller then walks them all).
/// For a point inside the box, collider_near is true only for colliders on the list, so a loop
/// over the list does what a loop over every collider does, in the same order: a grid block's
/// nodes and particles test a handful of bounds, not a scene's thousands (pull_twist's grips).
enum { COLLIDER_NEAR_CAP = 32 };
int collider_list_near_box(const collider *cols, int ncol, const double lo[3], const double hi[3], int *near);
static inline int point_in_box(const double lo[3], const double hi[3], const double x[3]) {
    return x[0] >= lo[0] && x[0] <= hi[0] && x[1] >= lo[1] && x[1] <= hi[1] && x[2] >= lo[2] && x[2] <= hi[2];
}
/// Push a particle at x that is inside the collider back to its surface and
/// apply the contact rule to its velocity v. dim 2 keeps z untouched. Returns 1 if it was inside.
int collider_project_particle(const collider *c, int dim, double x[3], double v[3]);
/// A grip (mode HEARTH_GRIP) carries a particle at x (the position the step
/// starts from) that lies inside it: x moves by the collider's rigid motion
/// over dt, v takes the collider's velocity and C (unless NULL: MPM keeps the
/// grid's C) its rigid velocity gradient skew(omega). Returns 1 if it did; 0
/// (nothing changed) for other modes or outside.
int collider_carry_particle(const collider *c, int dim, double dt, double x[3], double v[3], double C[9]);
/// Rigid velocity of the collider's material at world point x (m/s).
void collider_velocity_at(const collider *c, const double x[3], double v[3]);

/// A grid node within this many cells outside a collider's face counts as on
/// it. Faces are often placed on node rows (a lid at y = 0.125 on a grid of
/// dx = 1/64), where the SDF at the row is zero only up to round-off: with the
/// test sdf <= 0 the row was held or not by the last bit of `centre - half`,
/// and a Couette layer moved at 0.5 or 0.24 of the lid speed
/// (`couette_lid_on_node_row`). 1e-3 cell is far above round-off and far
/// below anything a scene means by moving a face.
#define COLLIDER_ROW_TOL 1e-3

/// A sticky face also holds the nodes up to this many cells outside it, each
/// at the velocity linear from the face's to the grid's a cell further out
/// (mpm_sticky.c, mpm_sticky_ghosts_block). Such a node, free, had half its
/// B-spline support in the collider, whose mirrors extend the stress evenly:
/// its net internal force cancelled and nothing carried its weight, so a
/// column hanging from a face 0.005-0.02 dx outside a node row fell off and
/// one 0.1 dx outside hung as if clamped 0.43 dx above the face at 10 cells
/// (docs/validation.md, "The sticky face's clamp"). 0.3: the band where the
/// hold's clamp offset was under 0.03 dx; past 0.45 a node held this way
/// clamped worse than a free one.
#define STICKY_NEAR_BAND 0.3

/// How far outside its face (cells) a collider holds grid nodes: STICKY_NEAR_BAND
/// for a sticky face, COLLIDER_ROW_TOL (on the face) for the others. The grid
/// update (mpm.c) and the sticky ghosts (mpm_sticky.c) must agree on it.
/// A separate face between node rows therefore holds a resting body through rows
/// under the face only: its foot sinks up to 0.18 dx below its half-spacing and
/// slides up to 18% past Coulomb's stop (contact tests *_between_rows, expected
/// failures). Holding the first row above such a face where the body touches it
/// (SEPARATE_NEAR_BAND 0.99, reverted) fixed both but made the stability matrix's
/// fluid dropped at cfl 1 stop late; holding it only for a body at rest (with or
/// without memory), with friction alone, or in part (the velocity linear from the
/// face) each missed a contact bar or moved that cell too (docs/validation.md,
/// "The separate tray between node rows", "Tried again").
static inline double collider_hold_band(const collider *c) {
    return c->mode == HEARTH_STICKY ? STICKY_NEAR_BAND : COLLIDER_ROW_TOL;
}

/// Project velocity v (in place) of a grid node touching a boundary with outward
/// unit normal n that moves at vb. sticky: v = vb. slip: the normal part of
/// v - vb is removed, then Coulomb friction acts on the tangential part.
/// separate: as slip, but only when (v - vb).n < 0; otherwise v is left alone.
/// friction >= 0.
void contact_apply(hearth_contact mode, double friction, const double n[3], const double vb[3], double v[3]);
#endif

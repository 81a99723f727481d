/* scene.h: the scene object (private). Owned by scene.c; mpm.c, guard.c,
 * probe.c and checkpoint.c read and step it. Each field module keeps its
 * state in a struct of its own, declared in its header and held here by
 * value: the materials (material.h), heat (thermal.h), the boundary
 * (boundary.h), water (water.h), mixing (mixing.h) and, behind pointers,
 * the solvers' own: MPM (mpm.h) and SPH (sph.c). Only the owning module
 * writes its struct. Gas keeps no scene-level state (its column lives with
 * the particles). Each init allocates nothing and each free returns its
 * struct to that state, so a free is safe twice (unit_fields:
 * fields_init_allocates_nothing, fields_free_releases_state). */
#ifndef HEARTH_SCENE_H
#define HEARTH_SCENE_H
#include <stdint.h>

#include "boundary.h"
#include "colliders.h"
#include "grid.h"
#include "material.h"
#include "mixing.h"
#include "params.h"
#include "particles.h"
#include "thermal.h"
#include "water.h"

/* The stack buffer for a particle's resolved parameters (material_params). */
#define SCENE_MAX_PARAMS MATERIAL_MAX_PARAMS
/* Below this many particles a step runs on one thread: waking the pool costs
 * more than it saves (a 129-particle scene spent 6 s of 11 in the kernel). */
#define SCENE_PARALLEL_MIN 2048
/* Temperature given to particles when the field turns on without a value (degrees C). */
#define SCENE_ROOM_TEMPERATURE 20.0

/* What went wrong first in a step, in particle order (so the answer does not
 * depend on the thread count). */
typedef enum fail_kind {
    FAIL_NONE = 0,
    FAIL_PLUGIN,       /* stress() returned a code */
    FAIL_STRESS,       /* stress() returned NaN/inf */
    FAIL_F,            /* F non-finite or det F <= 0 */
    FAIL_X, FAIL_V, FAIL_C,
    FAIL_WAVE,         /* wave_speed() returned NaN, inf or <= 0 */
    FAIL_BULK,         /* bulk_modulus() returned NaN, inf or <= 0 where eq. 10's thermal strain needed it */
} fail_kind;

typedef struct step_report {
    fail_kind kind;
    int particle;      /* index after this step's sort */
    int code;          /* plugin code for FAIL_PLUGIN */
    double max_speed;  /* after the step */
    int fastest;
    double max_move;   /* largest distance a particle was moved this step (m), before walls or colliders stopped it */
    int mover;         /* that particle, or -1 */
    double kinetic;
    double c_max;      /* largest wave speed met (stateful plugins; stateless come from the slot) */
    double nu_max;     /* largest kinematic viscosity met (plugins with a viscosity callback) */
    double self_max;   /* MPM: the largest share of a particle's own affine mode, 0..1 (mpm_g2p.c; 0 when not asked) */
    long out_of_domain;
    double mass;           /* of the particles that move */
    double driven_kinetic; /* 1/2 (mass) (fastest collider speed at a node it holds)^2: energy a collider may give */
} step_report;

struct solver;
struct mpm_state;

struct hearth_scene {
    hearth_scene_def def;
    const struct solver *solver; /* solver.h: chosen once from def.solver by hearth_scene_create */
    double t, dt_last, dt_scale;
    long step;
    int rollbacks, consecutive_rollbacks;
    double max_speed, c_max, kinetic, cfl_last;
    double nu_max;       /* largest kinematic viscosity a plugin applies explicitly (m^2/s) */
    double self_max;     /* the last step's step_report.self_max: mpm_stable_dt's bound on a lone particle */
    double kinetic_peak; /* largest kinetic energy so far: runaway is judged against it */
    long out_of_domain;
    hearth_guard_state guard;
    char diagnosis[1024];
    uint64_t rng;
    int next_id;
    int nbodies;
    int glue_legacy; /* restored from a checkpoint older than glue (version < 11): the next MPM step glues what
                      * the sticky faces held then (mpm_touch.c's mpm_glue_mark) */
    /* the fields' clock (fields/field_clock.c): the time and steps since the last field update; this
     * step's plan (field_skip: no field update; else over field_dt, 0 meaning dt); the last update's (stats) */
    double field_acc, field_dt, field_dt_last;
    int field_phase, field_cycle_last, field_skip;

    particles ps;
    grid g;
    material_table mats;    /* material.c */
    mixing_state mix;       /* mixing.c */
    collider *cols;
    int ncol, capcol;
    hearth_body_force_fn body_force;
    void *body_force_ud;
    int body_force_serial;        /* body_force must run on one thread (hearth_scene_set_body_force_serial) */
    hearth_gravity_fn gravity_fn; /* sets def.gravity at the start of each step, or NULL */
    void *gravity_ud;

    /* rollback snapshot (only with HEARTH_GUARD_ROLLBACK) */
    particles snap;
    double snap_t;
    long snap_step;
    collider *snap_cols;

    char fields[256];
    /* the lowest and highest temperature particles were seeded with (degrees C),
     * where pictures' fixed temperature range starts (render.c); unknown (0)
     * before the first, and after a checkpoint restore (render.c then uses the particles') */
    int seeded_t_known;
    double seeded_t[2];

    thermal_state heat;       /* thermal.c */
    boundary_state boundary;  /* boundary.c */
    water_state water;        /* water.c */

    struct mpm_state *mpm;       /* MPM solver state (mpm.h): the step's scratch; NULL under SPH */
    struct sph_state *sph;       /* SPH solver state (sph.c), NULL until the first SPH step */
};

/* scene.c */
/* Add a material from plugin (a name or path) with its parameters and turn on
 * the fields it needs: hearth_scene_add_material without clearing err, for
 * the core's own callers (a mixture's first constituent, mixing.c). */
int scene_add_material(hearth_scene *s, const char *plugin, const char *const *names, const double *values, int n,
                       hearth_error *err);
/* Turn the temperature field on (room temperature for particles that have none). */
hearth_status scene_enable_temperature(hearth_scene *s, hearth_error *err);
/* With browning and an oven on MPM, make the PC_SURFACE column browning.c keeps its surface offsets in; else nothing. */
hearth_status scene_enable_browning_surface(hearth_scene *s, hearth_error *err);
/* hearth_scene_seed_shape with `smooth` (hearth_body_def.smooth_surface): the outer layer (within 1.25 spacings of the
 * surface) seeded on the lattice, unjittered (bodies.c, seed_point). */
int scene_seed_shape(hearth_scene *s, int material, const hearth_shape *shape, int ppc, double jitter, int smooth,
                     const double velocity[3], hearth_error *err);
/* Widen seeded_t over particles [i0, i1) when the temperature field is live. */
void scene_note_seeded_temperature(hearth_scene *s, int i0, int i1);
/* Largest wave speed over moving particles (s->c_max), after particles change. */
void scene_refresh_wave_speed(hearth_scene *s);
/* The solver's stable step (solver.h). */
double scene_stable_dt(const hearth_scene *s);
/// Bytes a particle costs in this scene: its enabled columns and step scratch.
double scene_bytes_per_particle(const hearth_scene *s);
/// Refuse (HEARTH_ERR_PARAM, what names the caller) adding `more` particles
/// when the count or its memory estimate is beyond what the machine holds.
hearth_status scene_check_particle_budget(const hearth_scene *s, double more, const char *what, hearth_error *err);

/* guard.c: returns 1 when the step must not stand; writes the diagnosis. */
int guard_check(hearth_scene *s, const step_report *rep, double dt, double speed_before);
/* guard.c: dt is 0, NaN or does not advance the clock: stop with a diagnosis
 * naming why (a plugin's wave speed, usually) instead of looping forever. */
hearth_status guard_no_step(hearth_scene *s, double dt, hearth_error *err);
/* probe.c: hearth_probe_slice over rect = {u lo, v lo, u hi, v hi} of its plane (m; NULL: the domain), and when
 * frac is not NULL each sample's volume fraction under the kernel (the particles' V0 J over the cell, B-spline
 * weighted: the number its "outside the material" test reads; w x h doubles). render.c fills the material between a
 * 2D picture's particle discs from it, and draws a picture's region. */
hearth_status probe_slice_fraction(const hearth_scene *s, const char *field, int axis, double at, const double rect[4], int w,
                                   int h, double *out, double *frac, hearth_error *err);
/* The same slice's rows row0 .. row0 + rows - 1 alone (out and frac: rows x w doubles), the very values the whole
 * slice gives them: a picture filled band by band holds a band's samples at once, not the picture's (render.c). */
hearth_status probe_slice_rows(const hearth_scene *s, const char *field, int axis, double at, const double rect[4], int w,
                               int h, int row0, int rows, double *out, double *frac, hearth_error *err);
#endif

/* solver.h: what a solver is to the rest of the core. A scene picks its
 * solver once, from def.solver, when it is created (solver_of), and from then
 * on the scene, the probes and the checkpoint ask the table, never the enum:
 * adding a solver is adding an entry, not finding every `if`.
 *
 * The two entries: mpm_solver (mpm.c, Ding et al. 2019) and sph_solver
 * (sph.c, Rodriguez-Arenas 2011). */
#ifndef HEARTH_SIM_SOLVER_H
#define HEARTH_SIM_SOLVER_H
#include "scene.h"

/* The HEARTH_NEEDS_* bits that name a hearth_point field a solver has to fill.
 * HEARTH_NEEDS_THERMAL_EXPANSION is not among them: the core adds that term
 * to any material whose `expansion` is > 0, flagged or not (material.h,
 * contract), so the bit asks nothing of the point. */
#define SOLVER_POINT_FIELDS (HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_POROSITY | HEARTH_NEEDS_SATURATION)

typedef struct solver {
    const char *name; /* as the Lua scene spells it: solver = "mpm" */
    /* The solver's own options in a scene definition; NULL when it has none.
     * Called by hearth_scene_create and every def change. */
    hearth_status (*check)(const hearth_scene_def *d, hearth_error *err);
    /* Make what the solver keeps for itself in a new scene s (its grid is
     * made): called once by hearth_scene_create; NULL when the solver makes its
     * state on first use instead. On failure the scene is destroyed, so free
     * must cope with what init left half made. */
    hearth_status (*init)(hearth_scene *s, hearth_error *err);
    /* Material `mat` is being added to s (its slot s->mats.slot[mat] is filled and
     * counted; scene.c removes it again unless this returns HEARTH_OK): resolve what the solver
     * looks up per material once, here, rather than per particle per step.
     * NULL when there is nothing to resolve. */
    hearth_status (*material_added)(hearth_scene *s, int mat, hearth_error *err);
    /* The stable step (s), scaled by s->dt_scale. */
    double (*stable_dt)(const hearth_scene *s);
    /* One step of length dt; rep says what went wrong first, for the guard. */
    hearth_status (*step)(hearth_scene *s, double dt, step_report *rep, hearth_error *err);
    /* Free what the solver keeps for itself in s (not the shared grid or particles). */
    void (*free)(hearth_scene *s);
    /* Where particles may be placed: the box less what the solver needs at its edges (m). */
    void (*region)(const hearth_scene *s, double lo[3], double hi[3]);
    /* Per-particle results of the last step ("density", "pressure",
     * "h", ...), or NULL; the member is NULL when the solver keeps none. */
    const double *(*particle_values)(const hearth_scene *s, const char *which);
    /* Bytes of step scratch the solver keeps per particle (its own arrays,
     * with their growth margin), for scene_bytes_per_particle's estimate. */
    double (*bytes_per_particle)(const hearth_scene *s);
    unsigned supplies;  /* the SOLVER_POINT_FIELDS it fills; a material needing another is refused */
    int can_checkpoint; /* hearth_scene_save writes everything it needs to resume */
    /* It transfers through the background grid: the scene makes the grid's
     * block table (grid_init), else only its geometry (grid_init_geometry),
     * which seeding's lattice still uses. */
    int uses_grid;
} solver;

extern const solver mpm_solver, sph_solver;

/* The solver of def.solver (HEARTH_SOLVER_*), or NULL for a value no solver has. */
const solver *solver_of(int kind);
/* Refuse (HEARTH_ERR_PARAM) material m under solver sv when m needs a point
 * field sv does not fill, naming both; HEARTH_OK otherwise. */
hearth_status solver_accepts(const solver *sv, const hearth_material *m, hearth_error *err);
#endif

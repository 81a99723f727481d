/* scene.c: scene lifetime, materials, particles, colliders, and the step loop
 * with its guard and rollback.
 *
 * A scene pays only for the fields it uses. A momentum-only scene has the core
 * particle columns and four grid channels. Temperature (with its running
 * maximum and the particle flags) turns on when a body is given a
 * temperature, the scene an oven, or a material a temperature curve, a
 * leavening rate or a need for temperature; the grid then carries the heat
 * channels (grid.h CH_*). CO2 turns on with a material's gas_rate > 0. Water
 * (water mass and initial saturation columns; the relative flux column only
 * with the water_momentum switch, which reads it back) turns on when a body
 * is given a saturation, a collider is wet, or a material has
 * water_diffusivity, evaporation or water_stiffness > 0 or a plugin needs the
 * saturation (water_material_wants). Probing a field that is not live says
 * how to make it live (probe.c). Field properties (conductivity, specific
 * heat, expansion, gas rate, porosity, ...) are core parameters every
 * material accepts next to its plugin's own (params.c, hearth_core_params).
 *
 * scene_add_material is the core's internal path for adding a material
 * (mixing.c adds a mixture's first constituent through it, not through the
 * public hearth_scene_add_material). */
#include <float.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "plugins.h"
#include "alloc.h"
#include "error.h"
#include "params.h"
#include "scene.h"
#include "settings.h"
#include "solver.h"
#include "thermal.h"
#include "browning.h"
#include "water.h"
#include "mixing.h"
#include "ranks.h"
#include "mpm.h"
#include "mpm_touch.h"
#include "field_clock.h"
#include "gas.h"

#ifdef _OPENMP
#include <omp.h>
#endif

/* ---- threads --------------------------------------------------------- */

static int g_threads;

void hearth_set_threads(int n) {
    g_threads = n > 0 ? n : 0;
#ifdef _OPENMP
    if (n > 0) omp_set_num_threads(n);
#endif
}

int hearth_get_threads(void) {
#ifdef _OPENMP
    return g_threads > 0 ? g_threads : omp_get_max_threads();
#else
    return 1;
#endif
}

/* ---- interrupts ------------------------------------------------------ */

/* The host's "stop now" (a signal it caught): a step call of many steps
 * returns between two of them when it answers non-zero, with the scene whole
 * at the last step's end; the host then reports its interrupt. Not over MPI
 * ranks, whose step calls are collective: one rank leaving alone would leave
 * the others waiting in an exchange (they stop at the call's end together). */
static int (*g_interrupted)(void);

void hearth_set_interrupt_check(int (*interrupted)(void)) { g_interrupted = interrupted; }

static int stop_requested(void) { return g_interrupted && ranks_size() <= 1 && g_interrupted(); }

/* ---- definition ------------------------------------------------------ */

hearth_scene_def hearth_default_scene_def(void) {
    hearth_scene_def d;
    settings_defaults(&d); /* settings.c's table is the one list of defaults */
    return d;
}

hearth_collider_def hearth_default_collider_def(void) {
    return (hearth_collider_def){.mode = HEARTH_SLIP, .temperature = NAN, .saturation = NAN, .start_temperature = NAN};
}

static hearth_status check_def(const hearth_scene_def *d, hearth_error *err) {
    /* every setting's own range from settings.c's table (dim and dx first: the box is measured in dx);
     * the SPH solver's only when it steps the scene */
    hearth_status st = settings_check(d, "", "sph.", err);
    if (st) return st;
    for (int k = 0; k < d->dim; k++) {
        if (!isfinite(d->lo[k]) || !isfinite(d->hi[k]))
            return err_set(err, HEARTH_ERR_PARAM, "scene: box axis %c spans [%g, %g] m; its edges must be finite",
                           "xyz"[k], d->lo[k], d->hi[k]);
        if (!(d->hi[k] - d->lo[k] >= 6 * d->dx))
            return err_set(err, HEARTH_ERR_PARAM,
                           "scene: box axis %c spans [%g, %g] m; it must be at least 6 dx = %g m long", "xyz"[k],
                           d->lo[k], d->hi[k], 6 * d->dx);
        if (!isfinite(d->gravity[k])) return err_set(err, HEARTH_ERR_PARAM, "scene: gravity[%d] is not finite", k);
    }
    /* ---- the solver's own options (solver.h) ---- */
    const solver *sv = solver_of(d->solver);
    if (!sv) return err_set(err, HEARTH_ERR_PARAM, "scene: solver = %d; valid: 0 (mpm), 1 (sph)", d->solver);
    /* MPI ranks: only MPM splits its particle blocks among them (mpm_ranks.c) */
    if (ranks_size() > 1 && d->solver != HEARTH_SOLVER_MPM)
        return err_set(err, HEARTH_ERR_PARAM,
                       "scene: solver = \"%s\" runs in one process, and this run has %d MPI ranks; run it without "
                       "mpirun (or with mpirun -n 1); solver = \"mpm\" runs over ranks",
                       sv->name, ranks_size());
    for (int k = 0; k < 3; k++) {
        if (!d->periodic[k]) continue;
        if (k >= d->dim)
            return err_set(err, HEARTH_ERR_PARAM, "scene: periodic_%c in a %dD scene; valid: periodic_x, periodic_y%s",
                           "xyz"[k], d->dim, d->dim == 3 ? ", periodic_z" : "");
        /* the MPM grid's nodes wrap onto each other: the period must hold a whole number of cells */
        const double cells = (d->hi[k] - d->lo[k]) / d->dx;
        if (d->solver == HEARTH_SOLVER_MPM && !(fabs(cells - round(cells)) < 1e-6))
            return err_set(err, HEARTH_ERR_PARAM,
                           "scene: periodic_%c: box axis %c spans %g m = %.9g cells of dx = %g m; a periodic axis must "
                           "span a whole number of cells", "xyz"[k], "xyz"[k], d->hi[k] - d->lo[k], cells, d->dx);
    }
    if (d->two_field) { /* mpm_two_field.c: the second field exists in 2D MPM's passes only */
        if (d->solver != HEARTH_SOLVER_MPM)
            return err_set(err, HEARTH_ERR_PARAM, "scene: two_field = true needs solver = \"mpm\"; set two_field = false");
        if (d->dim != 2)
            return err_set(err, HEARTH_ERR_PARAM,
                           "scene: two_field is 2D only (this scene has dim = %d); set two_field = false or dim = 2",
                           d->dim);
        if (ranks_size() > 1)
            return err_set(err, HEARTH_ERR_PARAM,
                           "scene: two_field runs in one process, and this run has %d MPI ranks; run it without mpirun "
                           "(or set two_field = false)",
                           ranks_size());
        if (d->periodic[0] || d->periodic[1])
            return err_set(err, HEARTH_ERR_PARAM, "scene: two_field does not carry periodic axes; set two_field = false "
                                                  "or periodic_x = periodic_y = false");
    }
    if (d->damping > 0 && d->solver != HEARTH_SOLVER_MPM) /* it acts in mpm.c's grid update */
        return err_set(err, HEARTH_ERR_PARAM, "scene: damping = %g 1/s; only the MPM solver damps (solver = \"mpm\")",
                       d->damping);
    return sv->check ? sv->check(d, err) : HEARTH_OK;
}

/* ---- memory estimates ------------------------------------------------ */

/* The up-front refusals' ceiling: the machine's physical memory (a scene that
 * needs more would be OOM-killed without a word), or the program's lower
 * limit (hearth run --memory). Its words name which. */
static double memory_limit(char *words, size_t n) {
    const size_t limit = hearth_memory_limit(), machine = hearth_machine_memory();
    char ceiling[64];
    mem_limit_words(ceiling, sizeof ceiling);
    if (limit < machine)
        snprintf(words, n, "this run may use %s of memory (hearth run --memory SIZE; the machine has %.3g GB)", ceiling,
                 (double)machine / 1e9);
    else snprintf(words, n, "this machine has %.3g GB of memory", (double)limit / 1e9);
    return (double)limit;
}

double scene_bytes_per_particle(const hearth_scene *s) {
    double b = 0;
    for (int c = 0; c < PC_COUNT; c++)
        if (s->ps.enabled & (1u << c)) b += (double)particles_col_bytes(&s->ps, c);
    /* the solver's step scratch (solver.h) and a rollback snapshot's copy */
    b += s->solver->bytes_per_particle(s);
    if (s->def.guard == HEARTH_GUARD_ROLLBACK) b *= 2;
    return b;
}

size_t hearth_scene_bytes_used(const hearth_scene *s) {
    double b = 0;
    for (int c = 0; c < PC_COUNT; c++)
        if (s->ps.enabled & (1u << c)) b += (double)particles_col_bytes(&s->ps, c) * s->ps.n;
    if (s->def.guard == HEARTH_GUARD_ROLLBACK) b *= 2; /* the snapshot holds the same columns */
    const mpm_state *m = mpm_state_of(s);
    if (m) { /* what the MPM step's scratch holds for these particles, and its particle blocks */
        /* order and keys; P2G's stored tiles (the gather, 2D at more than one thread) in their room; volumes */
        const double keys = (double)s->ps.n * 2 * sizeof(int), tiles = (double)m->tiles_cap * sizeof(double);
        b += (keys > tiles ? keys : tiles) + (double)s->ps.n * (m->vol ? sizeof(double) : 0);
        b += (double)m->npb * (sizeof(pblock) + sizeof(int) + sizeof(pb_partial)) + (double)m->histcap * sizeof(int);
    } else {
        b += s->solver->bytes_per_particle(s) * s->ps.n;
    }
    if (s->solver->uses_grid) {
        const grid *g = &s->g;
        b += (double)g->nblocks * GRID_TABLE_BYTES_PER_BLOCK;
        b += (double)g->nactive * (sizeof(int) + sizeof(double) * (size_t)g->nch * (size_t)g->nodes_per_block);
    }
    return (size_t)b;
}

hearth_status scene_check_particle_budget(const hearth_scene *s, double more, const char *what, hearth_error *err) {
    const double total = (double)s->ps.n + more;
    if (!(total <= (double)(INT_MAX / 2)))
        return err_set(err, HEARTH_ERR_PARAM, "%s: %.4g particles (%d already in the scene); at most %d", what, total,
                       s->ps.n, INT_MAX / 2);
    char words[160], size[32], held[48];
    /* what the library holds besides these particles counts against the same ceiling: a tall box's grid tables,
     * other scenes of the same process (the repl's); what the present particles' scratch will take is in bpp */
    const double bpp = scene_bytes_per_particle(s), other = fmax(0.0, (double)hearth_bytes_allocated() - s->ps.n * bpp);
    const double need = total * bpp, limit = memory_limit(words, sizeof words);
    mem_size_words(size, sizeof size, need);
    held[0] = 0;
    if (other >= 1e6) { /* named where it matters */
        char w[32];
        mem_size_words(w, sizeof w, other);
        snprintf(held, sizeof held, ", beside %s", w);
    }
    if (need + other > limit)
        return err_set(err, HEARTH_ERR_PARAM,
                       "%s: %.4g particles would need about %s (%.0f bytes each)%s%s; %s (use a larger dx, fewer "
                       "particles per cell or a smaller shape)",
                       what, total, size, bpp, held, held[0] ? " already held (grid tables, other scenes)" : "", words);
    return HEARTH_OK;
}

hearth_scene *hearth_scene_create(const hearth_scene_def *def, hearth_error *err) {
    err_clear(err);
    hearth_scene_def d = def ? *def : hearth_default_scene_def();
    if (check_def(&d, err)) return NULL;
    const solver *sv = solver_of(d.solver); /* check_def refused any other */
    { /* the tables over the whole box, before any is allocated */
        int nn[3], nb[3];
        long blocks = 0;
        if (grid_plan(d.dim, d.dx, d.lo, d.hi, nn, nb, &blocks, err)) return NULL;
        char words[160];
        const double limit = memory_limit(words, sizeof words);
        const double need = sv->uses_grid ? (double)blocks * (double)GRID_TABLE_BYTES_PER_BLOCK : 0.0;
        if (need > limit / 2) {
            err_set(err, HEARTH_ERR_PARAM,
                    "scene: dx = %g m over this box needs %ld grid blocks, about %.3g GB for the grid tables alone; "
                    "%s, and the tables may take at most half (use a larger dx or a smaller box)",
                    d.dx, blocks, need / 1e9, words);
            return NULL;
        }
    }
    if (d.dim == 2) d.lo[2] = d.hi[2] = d.gravity[2] = 0;
    /* SPH wraps its own way (its neighbour cells); the scene's periodic axes are its sph.periodic ones */
    for (int k = 0; k < 3; k++) d.sph.periodic[k] |= d.solver == HEARTH_SOLVER_SPH && d.periodic[k];
    /* MPM: a periodic axis's grid has a ghost node row below lo and two above hi (mpm.c, "periodic axes") */
    double glo[3], ghi[3];
    for (int k = 0; k < 3; k++) {
        const int wrap = d.solver == HEARTH_SOLVER_MPM && d.periodic[k];
        glo[k] = d.lo[k] - (wrap ? d.dx : 0.0);
        ghi[k] = wrap ? d.lo[k] + (round((d.hi[k] - d.lo[k]) / d.dx) + 1) * d.dx : d.hi[k];
    }
    hearth_scene *s = mem_calloc(sizeof *s);
    if (!s) {
        err_set(err, HEARTH_ERR_NOMEM, "out of memory creating a scene");
        return NULL;
    }
    s->def = d;
    s->solver = sv;
    s->dt_scale = 1.0;
    material_table_init(&s->mats);
    mixing_init(&s->mix);
    thermal_init(&s->heat);
    boundary_init(&s->boundary);
    water_init(&s->water);
    s->rng = d.seed ? d.seed : 1;
    particles_init(&s->ps);
    particles_init(&s->snap);
    /* 2D MPM keeps C and F as 2x2 blocks (tensor2.h); SPH's 2D step works on 3x3 ones */
    s->ps.t2 = s->snap.t2 = d.dim == 2 && d.solver == HEARTH_SOLVER_MPM;
    /* a solver that never transfers to the grid still seeds on its lattice */
    if ((sv->uses_grid ? grid_init : grid_init_geometry)(&s->g, d.dim, d.dx, glo, ghi, err)) {
        mem_free(s, sizeof *s);
        return NULL;
    }
    if (!isnan(d.oven_temperature) && scene_enable_temperature(s, err)) { /* an oven makes the field live */
        hearth_scene_destroy(s);
        return NULL;
    }
    if (d.browning && (scene_enable_temperature(s, err) || particles_enable(&s->ps, PC_BROWNING, err))) {
        hearth_scene_destroy(s); /* browning.c reads the temperature */
        return NULL;
    }
    if (scene_enable_browning_surface(s, err)) {
        hearth_scene_destroy(s);
        return NULL;
    }
    if (s->solver->init && s->solver->init(s, err)) { /* the solver's own state (solver.h) */
        hearth_scene_destroy(s);
        return NULL;
    }
    return s;
}

void hearth_scene_destroy(hearth_scene *s) {
    if (!s) return;
    material_table_free(&s->mats);
    for (int i = 0; i < s->ncol; i++) collider_free(&s->cols[i]);
    mem_free(s->cols, sizeof(collider) * (size_t)s->capcol);
    mem_free(s->snap_cols, sizeof(collider) * (size_t)s->capcol);
    particles_free(&s->ps);
    particles_free(&s->snap);
    thermal_free(&s->heat);
    boundary_free(&s->boundary);
    water_free(&s->water);
    mixing_free(&s->mix);
    if (s->solver->free) s->solver->free(s);
    grid_free(&s->g);
    mem_free(s, sizeof *s);
}

const hearth_scene_def *hearth_scene_get_def(const hearth_scene *s) { return &s->def; }

hearth_status hearth_scene_set_dt_limits(hearth_scene *s, double cfl, double dt_max, hearth_error *err) {
    hearth_scene_def d = s->def;
    d.cfl = cfl;
    d.dt_max = dt_max;
    hearth_status st = check_def(&d, err);
    if (st) return st;
    s->def = d;
    return HEARTH_OK;
}

hearth_status hearth_scene_set_oven(hearth_scene *s, double temperature, double beta, hearth_error *err) {
    err_clear(err);
    hearth_scene_def d = s->def;
    d.oven_temperature = temperature;
    d.oven_beta = beta;
    hearth_status st = check_def(&d, err);
    if (st) return st;
    if (!isnan(temperature) && (st = scene_enable_temperature(s, err))) return st; /* an oven makes the field live */
    s->def = d;
    return scene_enable_browning_surface(s, err); /* an oven lit after the scene was made, as one made with it */
}

/* With an oven, MPM's browning reads the air surface above a boundary particle, kept between the fields' updates
 * in the PC_SURFACE column (browning.c); the column stays once made (an oven turned off leaves its offsets 0). */
hearth_status scene_enable_browning_surface(hearth_scene *s, hearth_error *err) {
    const hearth_scene_def *d = &s->def;
    if (!(d->browning && d->solver == HEARTH_SOLVER_MPM && thermal_oven_on(d))) return HEARTH_OK;
    return particles_enable(&s->ps, PC_SURFACE, err);
}

/* ---- materials ------------------------------------------------------- */

hearth_status scene_enable_temperature(hearth_scene *s, hearth_error *err) {
    particles *ps = &s->ps;
    if (ps->enabled & (1u << PC_TEMPERATURE)) return HEARTH_OK;
    hearth_status st = particles_enable(ps, PC_TEMPERATURE, err);
    if (!st) st = particles_enable(ps, PC_TEMP_MAX, err);
    if (!st) st = particles_enable(ps, PC_FLAGS, err); /* the boundary flag is a field with heat */
    if (st) return st;
    for (int i = 0; i < ps->n; i++) pcold(ps, PC_TEMPERATURE)[i] = pcold(ps, PC_TEMP_MAX)[i] = SCENE_ROOM_TEMPERATURE;
    scene_note_seeded_temperature(s, 0, ps->n);
    return HEARTH_OK;
}

void scene_note_seeded_temperature(hearth_scene *s, int i0, int i1) {
    if (!(s->ps.enabled & (1u << PC_TEMPERATURE))) return;
    const double *T = pcold(&s->ps, PC_TEMPERATURE);
    for (int i = i0; i < i1; i++) {
        if (!isfinite(T[i])) continue;
        if (!s->seeded_t_known) s->seeded_t[0] = s->seeded_t[1] = T[i], s->seeded_t_known = 1;
        s->seeded_t[0] = fmin(s->seeded_t[0], T[i]);
        s->seeded_t[1] = fmax(s->seeded_t[1], T[i]);
    }
}

int scene_add_material(hearth_scene *s, const char *plugin, const char *const *names, const double *values, int n,
                       hearth_error *err) {
    const hearth_plugin *pl = hearth_plugin_load(plugin, err);
    if (!pl) return -1;
    if (solver_accepts(s->solver, hearth_plugin_material(pl), err)) return -1; /* it needs a point field the solver does not fill */
    material_slot ms;
    if (material_slot_init(&ms, pl, names, values, n, err)) return -1;
    if (ms.core[CP_AMBIENT_PRESSURE] > 0 && s->def.solver != HEARTH_SOLVER_MPM) { /* MPM's door adds it (gas.h) */
        err_set(err, HEARTH_ERR_PARAM,
                "material '%s': ambient_pressure = %g Pa is read by the MPM solver only; valid value on this solver: 0 "
                "(SPH bubbles have their own gas law, sph.gas_law)",
                hearth_plugin_material(pl)->name, ms.core[CP_AMBIENT_PRESSURE]);
        material_slot_free(&ms);
        return -1;
    }
    if (ms.core[CP_GAS_RATE_2] > 0 && !(ms.core[CP_GAS_RATE] > 0)) { /* a second share adds to the first (gas.c) */
        err_set(err, HEARTH_ERR_PARAM,
                "material '%s': gas_rate_2 = %g mol/(kg s) is a second CO2 share added to gas_rate's, which is 0; "
                "valid: gas_rate_2 = 0, or gas_rate > 0 (a leavener of one reaction takes gas_rate alone)",
                hearth_plugin_material(pl)->name, ms.core[CP_GAS_RATE_2]);
        material_slot_free(&ms);
        return -1;
    }
    /* an amount bounds its own share's production (gas.h's gas_share_capped): without the rate it bounds nothing,
     * which is a mistake to say, not to ignore */
    for (int k = 0; k < 2; k++) {
        const int amount = k ? CP_GAS_AMOUNT_2 : CP_GAS_AMOUNT, rate = k ? CP_GAS_RATE_2 : CP_GAS_RATE;
        if (ms.core[amount] > 0 && !(ms.core[rate] > 0)) {
            err_set(err, HEARTH_ERR_PARAM,
                    "material '%s': %s = %g mol/kg is the most CO2 %s's share makes, and %s is 0; valid: %s = 0 (no "
                    "limit), or %s > 0",
                    hearth_plugin_material(pl)->name, k ? "gas_amount_2" : "gas_amount", ms.core[amount],
                    k ? "gas_rate_2" : "gas_rate", k ? "gas_rate_2" : "gas_rate", k ? "gas_amount_2" : "gas_amount",
                    k ? "gas_rate_2" : "gas_rate");
            material_slot_free(&ms);
            return -1;
        }
    }
    const hearth_material *m = ms.m;
    if (material_table_reserve(&s->mats, err) || particles_set_state_stride(&s->ps, m->state_size, err)) {
        material_slot_free(&ms);
        return -1;
    }
    const int id = material_table_push(&s->mats, &ms, err); /* checks a stateless plugin's wave speed, and K when it expands */
    if (id < 0) return -1;
    if (s->solver->material_added && s->solver->material_added(s, id, err)) { /* the solver's per-material data */
        material_slot_free(&s->mats.slot[--s->mats.n]);
        return -1;
    }
    const double *core = s->mats.slot[id].core;
    /* leavening needs the gas column, and the reaction needs temperature; so does the pores' air at the
     * atmosphere (ambient_pressure, gas.h), with or without CO2 */
    if ((core[CP_GAS_RATE] > 0 || core[CP_AMBIENT_PRESSURE] > 0) &&
        (particles_enable(&s->ps, PC_GAS, err) || scene_enable_temperature(s, err))) return -1;
    /* venting between the fields' updates needs each particle's open surface from the last (gas.c, gas_between) */
    if (core[CP_GAS_RATE] > 0 && s->def.gas_vent > 0 && s->def.solver == HEARTH_SOLVER_MPM &&
        particles_enable(&s->ps, PC_VENT, err)) return -1;
    /* a share with an amount counts what each particle has made of it (gas.h's gas_share_capped) */
    if ((core[CP_GAS_AMOUNT] > 0 || core[CP_GAS_AMOUNT_2] > 0) && particles_enable(&s->ps, PC_GAS_MADE, err)) return -1;
    /* and its exp between the fields' updates, once a cycle (exp_memo.h) */
    if (core[CP_GAS_RATE] > 0 && s->def.solver == HEARTH_SOLVER_MPM && particles_enable(&s->ps, PC_GAS_MEMO, err)) return -1;
    /* eq. 10 as a thermal strain needs each particle's last one (material.h, material_thermal_split), and the
     * split's exp of it between the fields' updates a memo (exp_memo.h) */
    if (core[CP_EXPANSION] > 0 && m->bulk_modulus &&
        (particles_enable(&s->ps, PC_THERMAL, err) || particles_enable(&s->ps, PC_THERMAL_MEMO, err))) return -1;
    /* the plugin's memo (<hearth/material.h> rule 10): MPM's batched door is its only reader */
    if (m->memo_size > 0 && m->stress_block && s->def.solver == HEARTH_SOLVER_MPM &&
        particles_set_memo_stride(&s->ps, m->memo_size, err)) return -1;
    /* and so does a plugin that reads temperature */
    if ((m->needs & HEARTH_NEEDS_TEMPERATURE) && scene_enable_temperature(s, err)) return -1;
    if (water_material_wants(s, id) && water_enable(s, err)) return -1;
    water_forget_limits(&s->water);
    return id;
}

int hearth_scene_add_material(hearth_scene *s, const char *plugin, const char *const *names, const double *values,
                              int n, hearth_error *err) {
    err_clear(err);
    return scene_add_material(s, plugin, names, values, n, err);
}

int hearth_scene_material_count(const hearth_scene *s) { return s->mats.n; }
const hearth_material *hearth_scene_material_info(const hearth_scene *s, int mat) {
    return mat >= 0 && mat < s->mats.n ? s->mats.slot[mat].m : NULL;
}
const double *hearth_scene_material_params(const hearth_scene *s, int mat) {
    return mat >= 0 && mat < s->mats.n ? s->mats.slot[mat].params : NULL;
}

/* ---- particles ------------------------------------------------------- */

int hearth_scene_add_particles(hearth_scene *s, int material, int n, const double *x, const double *v, double volume,
                               hearth_error *err) {
    err_clear(err);
    if (material < 0 || material >= s->mats.n) {
        err_set(err, HEARTH_ERR_PARAM, "add particles: material %d does not exist (the scene has %d)", material, s->mats.n);
        return -1;
    }
    if (!(volume > 0) || !isfinite(volume)) {
        err_set(err, HEARTH_ERR_PARAM, "add particles: volume = %g m^3; it must be > 0", volume);
        return -1;
    }
    if (n < 0) {
        err_set(err, HEARTH_ERR_PARAM, "add particles: n = %d; it must be >= 0", n);
        return -1;
    }
    if (scene_check_particle_budget(s, n, "add particles", err)) return -1;
    double lo[3], hi[3];
    s->solver->region(s, lo, hi);
    for (int i = 0; i < n; i++)
        for (int d = 0; d < s->def.dim; d++) {
            double xd = x[3 * i + d];
            if (!(xd >= lo[d] && xd <= hi[d])) {
                err_set(err, HEARTH_ERR_PARAM,
                        "add particles: particle %d has %c = %g m, outside the domain's usable range [%g, %g] m (one cell inside the box)",
                        i, "xyz"[d], xd, lo[d], hi[d]);
                return -1;
            }
            if (v && !isfinite(v[3 * i + d])) {
                err_set(err, HEARTH_ERR_PARAM, "add particles: particle %d has a non-finite velocity", i);
                return -1;
            }
        }
    particles *ps = &s->ps;
    if (particles_reserve(ps, ps->n + n, err)) return -1;
    const material_slot *ms = &s->mats.slot[material];
    const double rho = ms->params[ms->density_index];
    for (int i = 0; i < n; i++) {
        const int j = ps->n + i;
        for (int d = 0; d < 3; d++) {
            pcold(ps, PC_X)[3 * j + d] = d < s->def.dim ? x[3 * i + d] : 0.0;
            pcold(ps, PC_V)[3 * j + d] = v && d < s->def.dim ? v[3 * i + d] : 0.0;
        }
        particles_tensors_rest(ps, j, 1); /* C = 0, F = I */
        pcold(ps, PC_MASS)[j] = rho * volume;
        pcold(ps, PC_VOL0)[j] = volume;
        pcoli(ps, PC_MAT)[j] = material;
        pcoli(ps, PC_ID)[j] = s->next_id++;
        if (ps->enabled & (1u << PC_TEMPERATURE))
            pcold(ps, PC_TEMPERATURE)[j] = pcold(ps, PC_TEMP_MAX)[j] = SCENE_ROOM_TEMPERATURE;
        if (ps->enabled & (1u << PC_BODY)) pcoli(ps, PC_BODY)[j] = -1;
        if (ps->enabled & (1u << PC_FLAGS)) pcoli(ps, PC_FLAGS)[j] = 0;
        if (ps->enabled & (1u << PC_GAS)) pcold(ps, PC_GAS)[j] = 0;
        if (ps->enabled & (1u << PC_DRIED)) pcold(ps, PC_DRIED)[j] = 0; /* never dried */
        if (ps->enabled & (1u << PC_THERMAL)) pcold(ps, PC_THERMAL)[j] = 0; /* F = I: no thermal strain taken out yet */
        if (ps->enabled & (1u << PC_VENT)) pcold(ps, PC_VENT)[j] = 0; /* no surface until a field step finds it (gas.c) */
        if (ps->enabled & (1u << PC_SURFACE)) pcold(ps, PC_SURFACE)[2 * j] = pcold(ps, PC_SURFACE)[2 * j + 1] = 0; /* browning.c */
        if (ps->enabled & (1u << PC_GLUE)) pcoli(ps, PC_GLUE)[j] = 0; /* touched no sticky face yet (mpm_touch.c) */
        if (ps->enabled & (1u << PC_GAS_MADE)) pcold(ps, PC_GAS_MADE)[2 * j] = pcold(ps, PC_GAS_MADE)[2 * j + 1] = 0; /* gas.h */
        if (ps->enabled & (1u << PC_PLUGIN_MEMO)) /* zeros (they miss): a plugin's memo holds only what it wrote (rule 10) */
            memset(pcold(ps, PC_PLUGIN_MEMO) + (size_t)j * ps->memo_stride, 0, sizeof(double) * (size_t)ps->memo_stride);
        if (ps->state_stride) {
            double *st = pcold(ps, PC_STATE) + (size_t)j * ps->state_stride;
            memset(st, 0, sizeof(double) * (size_t)ps->state_stride);
            plugin_call_enter(ms->m, "init");
            ms->m->init(ms->params, st);
            plugin_call_leave();
        }
        const double *vv = pcold(ps, PC_V) + 3 * j;
        double sp = sqrt(vv[0] * vv[0] + vv[1] * vv[1] + vv[2] * vv[2]);
        if (sp > s->max_speed) s->max_speed = sp;
        s->kinetic += 0.5 * rho * volume * sp * sp;
    }
    if (ps->enabled & (1u << PC_MIX)) { /* no ratios; a mixture's own particles start as its first constituent */
        memset(pcold(ps, PC_MIX) + (size_t)MIX_MAX * ps->n, 0, sizeof(double) * MIX_MAX * (size_t)n);
        memset(pcold(ps, PC_MIXD) + (size_t)MIX_MAX * ps->n, 0, sizeof(double) * MIX_MAX * (size_t)n);
        if (material == s->mix.mat) mixing_set_ratios(s, ps->n, ps->n + n, NULL, NULL);
    }
    /* new particles only raise the largest wave speed (pinning, which lowers it, rescans) */
    double pscratch[SCENE_MAX_PARAMS];
    for (int j = ps->n; j < ps->n + n; j++) {
        double c = ms->wave_speed;
        if (ms->wave_per_point) {
            plugin_call_enter(ms->m, "wave_speed");
            c = ms->m->wave_speed(material_params(&s->mats, &s->ps, material, j, pscratch),
                                  ms->m->state_size > 0 ? pcold(ps, PC_STATE) + (size_t)j * ps->state_stride : NULL);
        }
        /* NaN or inf here would stall the step size; the first step's guard names it (mpm.c) */
        if (c > s->c_max && c <= DBL_MAX) s->c_max = c;
        if (ms->m->viscosity) {
            const double *pp = material_params(&s->mats, &s->ps, material, j, pscratch);
            plugin_call_enter(ms->m, "viscosity");
            const double nu = ms->m->viscosity(pp, ms->m->state_size > 0 ? pcold(ps, PC_STATE) + (size_t)j * ps->state_stride : NULL) /
                              pp[ms->density_index];
            if (nu > s->nu_max) s->nu_max = nu;
        }
        plugin_call_leave();
    }
    ps->n += n;
    ps->edits++;
    if (ps->enabled & (1u << PC_WATER)) water_init_particles(s, ps->n - n, ps->n, NAN);
    return n;
}

/* ---- colliders and forces -------------------------------------------- */

int hearth_scene_add_collider(hearth_scene *s, const hearth_collider_def *def, hearth_error *err) {
    err_clear(err);
    if (s->ncol == s->capcol) {
        int cap = s->capcol ? s->capcol * 2 : 4;
        collider *c = mem_realloc(s->cols, sizeof(collider) * (size_t)s->capcol, sizeof(collider) * (size_t)cap);
        if (!c) {
            err_set(err, HEARTH_ERR_NOMEM, "out of memory for colliders");
            return -1;
        }
        s->cols = c;
        s->capcol = cap;
    }
    if (collider_init(&s->cols[s->ncol], def, err)) return -1;
    if (!isnan(def->temperature) && isinf(def->beta) && s->def.solver != HEARTH_SOLVER_MPM) { /* held on the MPM grid */
        collider_free(&s->cols[s->ncol]);
        err_set(err, HEARTH_ERR_PARAM, "collider: beta = inf (held temperature) needs the MPM solver; this scene's solver is SPH");
        return -1;
    }
    if (!isnan(def->saturation) && s->def.solver != HEARTH_SOLVER_MPM) { /* water.c holds it on the MPM grid */
        collider_free(&s->cols[s->ncol]);
        err_set(err, HEARTH_ERR_PARAM,
                "collider: saturation = %g (a wet collider) needs the MPM solver; this scene's solver is SPH, whose water "
                "leaves only through its free surface", def->saturation);
        return -1;
    }
    if (!isnan(def->saturation) && water_enable(s, err)) { /* a wet collider makes water live */
        collider_free(&s->cols[s->ncol]);
        return -1;
    }
    if (def->heat_capacity > 0 && s->def.solver != HEARTH_SOLVER_MPM) { /* thermal.c books the contact's heat */
        collider_free(&s->cols[s->ncol]);
        err_set(err, HEARTH_ERR_PARAM, "collider: heat_capacity = %g J/(m^2 K) (a sheet the food draws heat from) needs "
                "the MPM solver; this scene's solver is SPH (leave heat_capacity out: the sheet then warms by warm_time "
                "alone)", def->heat_capacity);
        return -1;
    }
    s->cols[s->ncol].t_added = s->t; /* a warming tray starts warming now */
    s->cols[s->ncol].sheet_t = s->t;
    collider_set_time(&s->cols[s->ncol], s->t);
    return s->ncol++;
}

hearth_status hearth_scene_collider_motion(hearth_scene *s, int id, hearth_motion_fn fn, void *ud, hearth_error *err) {
    if (id < 0 || id >= s->ncol) return err_set(err, HEARTH_ERR_PARAM, "collider %d does not exist (the scene has %d)", id, s->ncol);
    s->cols[id].motion = fn;
    s->cols[id].motion_ud = ud;
    collider_set_time(&s->cols[id], s->t);
    return HEARTH_OK;
}

hearth_status hearth_scene_set_gravity(hearth_scene *s, const double g[3], hearth_error *err) {
    err_clear(err);
    for (int d = 0; d < 3; d++)
        if (!isfinite(g[d])) return err_set(err, HEARTH_ERR_PARAM, "gravity[%d] = %g m/s^2; it must be finite", d, g[d]);
    for (int d = 0; d < 3; d++) s->def.gravity[d] = s->def.dim == 2 && d == 2 ? 0.0 : g[d];
    return HEARTH_OK;
}

void hearth_scene_set_gravity_fn(hearth_scene *s, hearth_gravity_fn fn, void *ud) {
    s->gravity_fn = fn;
    s->gravity_ud = fn ? ud : NULL;
}

/* The gravity function's value for the step starting now; a non-finite one is ignored (the host reports it). */
static void gravity_at_step(hearth_scene *s) {
    if (!s->gravity_fn) return;
    double g[3] = {s->def.gravity[0], s->def.gravity[1], s->def.gravity[2]};
    s->gravity_fn(s->gravity_ud, s->t, g);
    hearth_scene_set_gravity(s, g, NULL);
}

void hearth_scene_set_body_force(hearth_scene *s, hearth_body_force_fn fn, void *ud) {
    s->body_force = fn;
    s->body_force_ud = fn ? ud : NULL;
    s->body_force_serial = 0;
}

void hearth_scene_set_body_force_serial(hearth_scene *s, hearth_body_force_fn fn, void *ud) {
    hearth_scene_set_body_force(s, fn, ud);
    s->body_force_serial = fn != NULL;
}

/* ---- stepping -------------------------------------------------------- */

double scene_stable_dt(const hearth_scene *s) { return s->solver->stable_dt(s); }

void scene_refresh_wave_speed(hearth_scene *s) {
    const particles *ps = &s->ps;
    const int *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    double c = 0, pscratch[SCENE_MAX_PARAMS];
    for (int i = 0; i < ps->n; i++) {
        if (flags && (flags[i] & PF_FIXED)) continue;
        const int m = pcoli(ps, PC_MAT)[i];
        const material_slot *ms = &s->mats.slot[m];
        double ci = ms->wave_speed;
        if (ms->wave_per_point) {
            plugin_call_enter(ms->m, "wave_speed");
            ci = ms->m->wave_speed(material_params(&s->mats, &s->ps, m, i, pscratch),
                                   ms->m->state_size > 0 ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL);
            plugin_call_leave();
        }
        if (ci > c && ci <= DBL_MAX) c = ci;
    }
    s->c_max = c;
}

/* One step of length dt (shortened by rollbacks). */
static hearth_status one_step(hearth_scene *s, double dt, hearth_error *err) {
    const int rollback = s->def.guard == HEARTH_GUARD_ROLLBACK;
    s->consecutive_rollbacks = 0;
    for (;;) {
        if (rollback) { /* the glue column first (mpm_touch.c): the restore below keeps the layout it saved */
            hearth_status st = mpm_glue_column(s, err);
            if (!st) st = particles_copy(&s->snap, &s->ps, err);
            if (st) return st;
        }
        const double speed_before = s->max_speed;
        gravity_at_step(s);
        for (int c = 0; c < s->ncol; c++) {
            collider_set_time(&s->cols[c], s->t);
            if (s->def.solver == HEARTH_SOLVER_MPM) collider_update_bounds_tight(&s->cols[c], 2.0 * s->def.dx);
            else collider_update_bounds(&s->cols[c], 2.0 * s->def.dx);
        }
        step_report rep;
        field_clock_plan(s, dt); /* whether this step carries the fields, and over what time */
        for (int c = 0; c < s->ncol; c++) collider_heat_interval(&s->cols[c], s->t + dt - s->field_dt, s->t + dt);
        hearth_status st = s->solver->step(s, dt, &rep, err);
        if (st) return st;
        if (!guard_check(s, &rep, dt, speed_before)) {
            /* a drawing sheet takes the heat its contact passed in a field step that stood (colliders.h) */
            if (!s->field_skip)
                for (int c = 0; c < s->ncol; c++)
                    collider_sheet_stands(&s->cols[c], s->t + dt - s->field_dt, s->t + dt, s->cols[c].step_heat);
            s->t += dt;
            s->step++;
            s->dt_last = dt;
            for (int c = 0; c < s->ncol; c++) collider_advance(&s->cols[c], dt);
            s->max_speed = rep.max_speed;
            s->c_max = rep.c_max; /* moving particles only: a pinned body has no waves */
            s->nu_max = rep.nu_max;
            s->self_max = s->def.solver == HEARTH_SOLVER_MPM ? rep.self_max : 0.0;
            s->kinetic = rep.kinetic;
            if (s->kinetic > s->kinetic_peak) s->kinetic_peak = s->kinetic;
            s->out_of_domain += rep.out_of_domain;
            if (water_active(s)) water_step_stands(&s->water);
            /* the step stands: the crust's colour integrates its end temperature (a rolled back step never browns) */
            if (s->field_skip) gas_between(s, dt); /* the CO2 moves every step, the fields' clock or not (gas.c) */
            if (s->def.browning) browning_step(s, dt); /* hearth_scene_create made its columns */
            if (water_active(s) && (s->ps.enabled & (1u << PC_DRIED))) water_dried_step(s); /* a crust stays dry */
            if (thermal_active(s)) thermal_step_stands(&s->heat);
            field_clock_stands(s, dt);
            if (s->dt_scale < 1) s->dt_scale = fmin(1.0, s->dt_scale * 1.25);
            return HEARTH_OK;
        }
        if (rollback && s->consecutive_rollbacks < s->def.max_rollbacks) {
            particles_copy(&s->ps, &s->snap, NULL); /* same layout: cannot fail */
            dt *= 0.5;
            s->dt_scale *= 0.5;
            s->consecutive_rollbacks++;
            s->rollbacks++;
            s->guard = HEARTH_GUARD_ROLLED_BACK;
            continue;
        }
        s->guard = HEARTH_GUARD_STOPPED;
        if (rollback) {
            particles_copy(&s->ps, &s->snap, NULL);
            size_t l = strlen(s->diagnosis);
            snprintf(s->diagnosis + l, sizeof s->diagnosis - l, " (after %d rollbacks; the scene is at the last good state)",
                     s->consecutive_rollbacks);
        }
        return err_set(err, HEARTH_ERR_GUARD, "%s", s->diagnosis);
    }
}

static hearth_status step_loop(hearth_scene *s, int n, hearth_error *err) {
    if (s->guard == HEARTH_GUARD_STOPPED) s->guard = HEARTH_GUARD_OK; /* the caller chose to go on */
    for (int k = 0; k < n; k++) {
        if (k > 0 && stop_requested()) break;
        const double dt = scene_stable_dt(s);
        if (!(dt > 0) || s->t + dt == s->t) return guard_no_step(s, dt, err);
        hearth_status st = one_step(s, dt, err);
        if (st) return st;
    }
    return HEARTH_OK;
}

static hearth_status advance_loop(hearth_scene *s, double t_end, long max_steps, hearth_error *err);

/* Over MPI ranks the steps may leave each rank holding its slab's particles
 * only (mpm_ranks.c): the whole scene again at the end of the call, or, for a
 * host that keeps the slabs, when it calls hearth_scene_whole. */
hearth_status hearth_scene_step(hearth_scene *s, int n, hearth_error *err) {
    err_clear(err);
    hearth_status st = mpm_ranks_usable(s, err);
    if (st) return st;
    mpm_ranks_begin(s);
    return mpm_ranks_end(s, step_loop(s, n, err), err);
}

hearth_status hearth_scene_advance_steps(hearth_scene *s, double t_end, long max_steps, hearth_error *err) {
    err_clear(err);
    hearth_status st = mpm_ranks_usable(s, err);
    if (st) return st;
    mpm_ranks_begin(s);
    return mpm_ranks_end(s, advance_loop(s, t_end, max_steps, err), err);
}

void hearth_scene_keep_slabs(hearth_scene *s, int on) { mpm_ranks_keep(s, on); }

hearth_status hearth_scene_whole(hearth_scene *s, hearth_error *err) {
    err_clear(err);
    return mpm_ranks_whole(s, err);
}

hearth_status hearth_scene_advance(hearth_scene *s, double t_end, hearth_error *err) {
    return hearth_scene_advance_steps(s, t_end, -1, err);
}

static hearth_status advance_loop(hearth_scene *s, double t_end, long max_steps, hearth_error *err) {
    if (s->guard == HEARTH_GUARD_STOPPED) s->guard = HEARTH_GUARD_OK;
    for (long k = 0; s->t < t_end && (max_steps < 0 || k < max_steps); k++) {
        if (k > 0 && stop_requested()) break;
        double dt = scene_stable_dt(s);
        /* A stable step of 0 or NaN (an infinite or NaN wave speed, say) used
         * to end this loop quietly, and s:run called it again forever. */
        if (!(dt > 0) || s->t + dt == s->t) return guard_no_step(s, dt, err);
        if (s->t + dt >= t_end) dt = t_end - s->t;
        else if (s->t + 1.5 * dt > t_end) dt = 0.5 * (t_end - s->t); /* avoid a sliver of a last step */
        if (s->t + dt == s->t) dt = t_end - s->t; /* half of the last ulp before t_end would not advance */
        if (!(dt > 0)) break;
        hearth_status st = one_step(s, dt, err);
        if (st) return st;
    }
    return HEARTH_OK;
}

double hearth_scene_time(const hearth_scene *s) { return s->t; }

void hearth_scene_stats(const hearth_scene *s, hearth_stats *st) {
    memset(st, 0, sizeof *st);
    st->t = s->t;
    st->dt = s->dt_last;
    st->step = s->step;
    st->particles = mpm_ranks_particles(s); /* every rank's, between steps over MPI ranks */
    st->kinetic = s->kinetic;
    st->max_speed = s->max_speed;
    st->cfl = s->cfl_last;
    st->wave_speed = s->c_max;
    st->out_of_domain = s->out_of_domain;
    st->rollbacks = s->rollbacks;
    st->field_limit = field_clock_limit(s);
    st->field_dt = s->field_dt_last;
    st->field_cycle = s->field_cycle_last;
    st->guard = s->guard;
    snprintf(st->diagnosis, sizeof st->diagnosis, "%s", s->guard == HEARTH_GUARD_OK ? "" : s->diagnosis);
    st->grid_blocks = mpm_ranks_blocks(s);
    st->heat_energy = thermal_energy(s);
    st->cg_iterations = thermal_cg_iterations(s);
    if (s->ps.enabled & (1u << PC_GAS))
        for (int i = 0; i < s->ps.n; i++) st->gas_moles += pcold(&s->ps, PC_GAS)[i] * pcold(&s->ps, PC_VOL0)[i];
    st->water_mass = water_total(s);
    /* MPI slabs kept between step calls (a Lua host): each rank holds its slab's
     * particles, so their sums are added over the ranks in rank order (collective) */
    double sums[3] = {st->heat_energy, st->gas_moles, st->water_mass};
    mpm_ranks_fields_reduce(s, sums, 3, NULL, 0);
    st->heat_energy = sums[0], st->gas_moles = sums[1], st->water_mass = sums[2];
    st->water_lost = s->water.lost;
    st->oven_heat_in = s->heat.oven_heat_in;
}

int hearth_scene_particle_count(const hearth_scene *s) { return s->ps.n; }
const double *hearth_scene_positions(const hearth_scene *s) { return pcold(&s->ps, PC_X); }
const int *hearth_scene_particle_ids(const hearth_scene *s) { return pcoli(&s->ps, PC_ID); }
const double *hearth_scene_particle_masses(const hearth_scene *s) { return pcold(&s->ps, PC_MASS); }

uint64_t hearth_scene_hash(const hearth_scene *s) {
    uint64_t h = 1469598103934665603ULL; /* FNV-1a over every enabled column but the memos (a cache: exp_memo.h) */
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(s->ps.enabled & (1u << c)) || !s->ps.col[c] || particles_col_is_memo(c)) continue;
        const unsigned char *b = s->ps.col[c];
        size_t len = particles_col_bytes(&s->ps, c) * (size_t)s->ps.n;
        for (size_t i = 0; i < len; i++) h = (h ^ b[i]) * 1099511628211ULL;
    }
    return h;
}

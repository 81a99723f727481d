/* bodies.c: bodies (shapes filled with one material: the seeding's jittered
 * lattice, hearth_scene_seed_shape, here since scene.c passed 900 lines), the
 * events that act on them and on colliders, and temperature curves of
 * material parameters. */
#include <limits.h>
#include <math.h>
#include <string.h>

#include "plugins.h"
#include "alloc.h"
#include "error.h"
#include "params.h"
#include "scene.h"
#include "solver.h"
#include "water.h"
#include "mixing.h"

/* ---- seeding: a shape filled on a jittered lattice, ppc per cell ------ */

/* splitmix64's finaliser of z as a uniform number in [0, 1): tiny, good enough for jitter and labels, and the same on
 * every machine */
static double splitmix_uniform(uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
    return (double)(z >> 11) * (1.0 / 9007199254740992.0);
}

/* the seeding's stream: splitmix64, its state advanced by the golden ratio's step */
static double rng_uniform(uint64_t *st) { return splitmix_uniform(*st += 0x9e3779b97f4a7c15ULL); }

/* Lattice point q of a seeding (jittered, one random number per axis): its
 * position in x, and 1 when it lies in the shape and the usable region.
 * With `smooth` (hearth_body_def.smooth_surface), a lattice point within
 * 1.25 spacings h of the shape's surface is not jittered: the seeding's outer
 * layer keeps the lattice, so a flat face is flat (a loaf's base on a tray:
 * its lowest row rests on the tray over its whole width), where the jitter
 * spread the particles' lower edges over jitter x h (0.25 dx at ppc 4, jitter
 * 0.5), a roughness under a cell that no grid node can flatten: the contact
 * holds the lowest of them and the rest stand off the face; and along the
 * face its particles keep their spacing, so a stretched base opens no hole
 * wider than the spacing's stretch (docs/validation.md, "The physical loaf's
 * base lifts: traced"; jitter along the face only was tried and left such
 * holes). 1.25 h, not h: a face through a lattice row (the row outside it) has
 * its first row inside at h, which must be on the lattice too; with the face
 * on the lattice's half-spacing, the second row (1.5 h) keeps its jitter. The
 * random numbers are drawn as without it, so the interior's jitter is the
 * same draw. */
static int seed_point(hearth_scene *s, const hearth_shape *shape, long q, const long cells[3], const int c0[3], int k,
                      double h, double jitter, int smooth, const double lo[3], const double hi[3], double x[3]) {
    const int D = s->def.dim;
    const double dx = s->def.dx;
    long r = q;
    x[0] = x[1] = x[2] = 0;
    for (int d = D - 1; d >= 0; d--) {
        long per = cells[d] * k;
        long idx = r % per;
        r /= per;
        x[d] = s->g.lo[d] + c0[d] * dx + (idx + 0.5) * h;
    }
    double j[3] = {0, 0, 0};
    for (int d = 0; d < D; d++) j[d] = jitter * (rng_uniform(&s->rng) - 0.5) * h;
    if (smooth && jitter > 0 && fabs(hearth_shape_sdf(shape, x, NULL)) < 1.25 * h) j[0] = j[1] = j[2] = 0;
    for (int d = 0; d < D; d++) x[d] += j[d];
    int inside = hearth_shape_sdf(shape, x, NULL) < 0;
    for (int d = 0; d < D; d++) inside = inside && x[d] >= lo[d] && x[d] <= hi[d];
    return inside;
}

int hearth_scene_seed_shape(hearth_scene *s, int material, const hearth_shape *shape, int ppc, double jitter,
                            const double velocity[3], hearth_error *err) {
    return scene_seed_shape(s, material, shape, ppc, jitter, 0, velocity, err);
}

int scene_seed_shape(hearth_scene *s, int material, const hearth_shape *shape, int ppc, double jitter, int smooth,
                     const double velocity[3], hearth_error *err) {
    err_clear(err);
    const int D = s->def.dim;
    if (ppc < 1 || ppc > 1000) {
        err_set(err, HEARTH_ERR_PARAM, "seed: ppc = %d; valid range [1, 1000] particles per cell", ppc);
        return -1;
    }
    if (!(jitter >= 0 && jitter <= 1)) {
        err_set(err, HEARTH_ERR_PARAM, "seed: jitter = %g; valid range [0, 1]", jitter);
        return -1;
    }
    int k = (int)floor(pow((double)ppc, 1.0 / D) + 0.5);
    if (k < 1) k = 1;
    double blo[3], bhi[3], lo[3], hi[3];
    hearth_shape_bounds(shape, blo, bhi);
    s->solver->region(s, lo, hi);
    long cells[3] = {1, 1, 1};
    int c0[3] = {0, 0, 0};
    const double dx = s->def.dx, h = dx / k;
    double bound = pow(k, D); /* lattice points to visit: an upper bound of the particles seeded */
    for (int d = 0; d < D; d++) {
        if (isnan(blo[d]) || isnan(bhi[d])) {
            err_set(err, HEARTH_ERR_PARAM, "seed: the shape's bounds are not numbers (a NaN centre or size)");
            return -1;
        }
        /* the valid region is inside the box, so these are bounded by the grid's cell counts */
        double a = blo[d] > lo[d] ? blo[d] : lo[d], b = bhi[d] < hi[d] ? bhi[d] : hi[d];
        if (b <= a) return 0;
        c0[d] = (int)floor((a - s->g.lo[d]) / dx);
        cells[d] = (long)ceil((b - s->g.lo[d]) / dx) - c0[d];
        bound *= (double)cells[d];
    }
    /* refuse before allocating: the bound is within a factor of the shape's
     * fill of its bounding box */
    if (scene_check_particle_budget(s, bound, "seed", err)) return -1;
    /* positions are handed over in chunks so the stack buffer stays small */
    double vel[3] = {0, 0, 0};
    if (velocity) memcpy(vel, velocity, sizeof vel);
    const double volume = pow(h, D);
    int added = 0;
    enum { CHUNK = 4096 };
    double xs[3 * CHUNK], vs[3 * CHUNK];
    int nx = 0;
    long total = cells[0] * cells[1] * cells[2] * (long)pow(k, D);
    /* Count first, replaying the jitter's random numbers, and reserve exactly
     * that: appending chunk by chunk grew the columns to the next power of
     * two (up to 2x the particles' own bytes, and old and new columns both
     * held while they grew). The count pass costs one more shape test per
     * lattice point, once. */
    const uint64_t rng0 = s->rng;
    long count = 0;
    for (long q = 0; q < total; q++) {
        double x[3];
        count += seed_point(s, shape, q, cells, c0, k, h, jitter, smooth, lo, hi, x);
    }
    s->rng = rng0;
    if (count > INT_MAX / 2 - s->ps.n) { /* the budget above bounds it; kept for the cast */
        err_set(err, HEARTH_ERR_PARAM, "seed: %ld particles; at most %d", count, INT_MAX / 2 - s->ps.n);
        return -1;
    }
    if (particles_reserve_exact(&s->ps, s->ps.n + (int)count, err)) return -1;
    for (long q = 0; q < total; q++) {
        double x[3];
        if (!seed_point(s, shape, q, cells, c0, k, h, jitter, smooth, lo, hi, x)) continue;
        memcpy(xs + 3 * nx, x, sizeof x);
        memcpy(vs + 3 * nx, vel, sizeof vel);
        if (++nx == CHUNK) {
            if (hearth_scene_add_particles(s, material, nx, xs, vs, volume, err) < 0) return -1;
            added += nx;
            nx = 0;
        }
    }
    if (nx && hearth_scene_add_particles(s, material, nx, xs, vs, volume, err) < 0) return -1;
    return added + nx;
}

/* ---- bodies ---------------------------------------------------------- */

hearth_body_def hearth_default_body_def(void) {
    return (hearth_body_def){.ppc = 4, .jitter = 0.5, .temperature = NAN, .saturation = NAN};
}

int hearth_scene_add_body(hearth_scene *s, const hearth_body_def *def, hearth_error *err) {
    err_clear(err);
    if (!def || !def->shape) {
        err_set(err, HEARTH_ERR_PARAM, "body: a shape is required");
        return -1;
    }
    if (def->material < 0 || def->material >= s->mats.n) {
        err_set(err, HEARTH_ERR_PARAM, "body: material %d does not exist (the scene has %d)", def->material, s->mats.n);
        return -1;
    }
    if (!isnan(def->temperature) && !(def->temperature >= -273.15 && def->temperature <= 5000)) {
        err_set(err, HEARTH_ERR_PARAM, "body: temperature = %g degrees C; valid range [-273.15, 5000]", def->temperature);
        return -1;
    }
    if (!isnan(def->saturation) && !(def->saturation >= 0 && def->saturation <= 1)) {
        err_set(err, HEARTH_ERR_PARAM, "body: saturation = %g; valid range [0, 1] (water volume over volume)", def->saturation);
        return -1;
    }
    if (def->saturation > 0 && water_sph_gas(s, &s->mats.slot[def->material])) {
        err_set(err, HEARTH_ERR_PARAM,
                "body: saturation = %g on a bubble material (bubble = %g, SPH's gas); valid: 0 or unset (a bubble holds no "
                "liquid water)", def->saturation, s->mats.slot[def->material].core[CP_BUBBLE]);
        return -1;
    }
    if (def->fixed_temperature && isnan(def->temperature)) {
        err_set(err, HEARTH_ERR_PARAM, "body: fixed_temperature needs a temperature (degrees C) to hold");
        return -1;
    }
    if (def->fixed_temperature && s->def.solver != HEARTH_SOLVER_MPM) {
        err_set(err, HEARTH_ERR_PARAM, "body: fixed_temperature is held on the MPM grid; this scene's solver is SPH");
        return -1;
    }
    hearth_status st = particles_enable(&s->ps, PC_BODY, err);
    if (!st && (def->fixed || def->fixed_temperature)) st = particles_enable(&s->ps, PC_FLAGS, err);
    if (!st && !isnan(def->temperature)) st = scene_enable_temperature(s, err);
    if (!st && !isnan(def->saturation)) st = water_enable(s, err);
    if (st) return -1;
    const int n0 = s->ps.n;
    int n = scene_seed_shape(s, def->material, def->shape, def->ppc, def->jitter, def->smooth_surface, def->velocity, err);
    if (n < 0) return -1;
    if (n == 0) {
        err_set(err, HEARTH_ERR_PARAM, "body: its shape holds no particle inside the domain (check the shape's position and size against the box)");
        return -1;
    }
    const int id = s->nbodies++;
    for (int i = n0; i < s->ps.n; i++) {
        pcoli(&s->ps, PC_BODY)[i] = id;
        if (def->fixed) {
            pcoli(&s->ps, PC_FLAGS)[i] |= PF_FIXED;
            memset(pcold(&s->ps, PC_V) + 3 * i, 0, 3 * sizeof(double));
        }
        if (!isnan(def->temperature)) pcold(&s->ps, PC_TEMPERATURE)[i] = pcold(&s->ps, PC_TEMP_MAX)[i] = def->temperature;
        if (def->fixed_temperature) pcoli(&s->ps, PC_FLAGS)[i] |= PF_HOLD_T;
    }
    scene_note_seeded_temperature(s, n0, s->ps.n); /* where pictures' temperature range starts */
    if (!isnan(def->saturation)) water_init_particles(s, n0, s->ps.n, def->saturation);
    if (def->material == s->mix.mat && mixing_set_ratios(s, n0, s->ps.n, def->ratios, err)) {
        s->ps.n = n0; /* the body is not made */
        s->nbodies--;
        return -1;
    }
    if (def->fixed) scene_refresh_wave_speed(s); /* a pinned body's waves do not limit dt */
    return id;
}

int hearth_scene_body_count(const hearth_scene *s) { return s->nbodies; }

int hearth_scene_body_particles(const hearth_scene *s, int body) {
    if (!(s->ps.enabled & (1u << PC_BODY))) return 0;
    int n = 0;
    for (int i = 0; i < s->ps.n; i++) n += pcoli(&s->ps, PC_BODY)[i] == body;
    return n;
}

/* splitmix64 finaliser of seed and id: one uniform number per particle. */
static double label_uniform(uint64_t seed, int id) {
    return splitmix_uniform(seed + 0x9e3779b97f4a7c15ULL * ((uint64_t)(uint32_t)id + 1));
}

hearth_status hearth_scene_body_labels(hearth_scene *s, int body, int k, const int *materials, const double *ratio,
                                       uint64_t seed, int *counts, hearth_error *err) {
    enum { LABELS_MAX = 8 };
    if (body < 0 || body >= s->nbodies)
        return err_set(err, HEARTH_ERR_PARAM, "labels: body %d does not exist (the scene has %d)", body, s->nbodies);
    if (k < 1 || k > LABELS_MAX) return err_set(err, HEARTH_ERR_PARAM, "labels: %d materials; valid range [1, %d]", k, LABELS_MAX);
    double cum[LABELS_MAX], total = 0;
    for (int i = 0; i < k; i++) {
        if (materials[i] < 0 || materials[i] >= s->mats.n)
            return err_set(err, HEARTH_ERR_PARAM, "labels: material %d does not exist (the scene has %d)", materials[i], s->mats.n);
        if (s->mats.slot[materials[i]].m != s->mats.slot[materials[0]].m)
            return err_set(err, HEARTH_ERR_PARAM, "labels: materials must share one plugin ('%s' and '%s')",
                           s->mats.slot[materials[0]].m->name, s->mats.slot[materials[i]].m->name);
        if (!(ratio[i] >= 0) || !isfinite(ratio[i]))
            return err_set(err, HEARTH_ERR_PARAM, "labels: ratio %d = %g; valid range [0, inf)", i + 1, ratio[i]);
        total += ratio[i];
        cum[i] = total;
    }
    if (!(total > 0)) return err_set(err, HEARTH_ERR_PARAM, "labels: the ratios sum to zero");
    if (counts) memset(counts, 0, sizeof(int) * (size_t)k);
    particles *ps = &s->ps;
    double ke = 0;
    for (int i = 0; i < ps->n; i++) {
        const double *v = pcold(ps, PC_V) + 3 * i;
        if (pcoli(ps, PC_BODY)[i] == body) {
            const double u = label_uniform(seed, pcoli(ps, PC_ID)[i]) * total;
            int c = 0;
            while (c < k - 1 && !(u < cum[c])) c++;
            const material_slot *ms = &s->mats.slot[materials[c]];
            pcoli(ps, PC_MAT)[i] = materials[c];
            pcold(ps, PC_MASS)[i] = ms->params[ms->density_index] * pcold(ps, PC_VOL0)[i];
            if (ps->enabled & (1u << PC_PLUGIN_MEMO)) /* zeros (they miss): a plugin's memo holds only what it wrote (rule 10) */
                memset(pcold(ps, PC_PLUGIN_MEMO) + (size_t)i * ps->memo_stride, 0, sizeof(double) * (size_t)ps->memo_stride);
            /* its new material's shares have made nothing yet (gas.h's gas_share_capped; a checkpoint checks each
             * count against the particle's own material's amount) */
            if (ps->enabled & (1u << PC_GAS_MADE)) pcold(ps, PC_GAS_MADE)[2 * i] = pcold(ps, PC_GAS_MADE)[2 * i + 1] = 0;
            if (ps->state_stride) {
                double *st = pcold(ps, PC_STATE) + (size_t)i * ps->state_stride;
                memset(st, 0, sizeof(double) * (size_t)ps->state_stride);
                plugin_call_enter(ms->m, "init");
                ms->m->init(ms->params, st);
                plugin_call_leave();
            }
            if (counts) counts[c]++;
        }
        ke += 0.5 * pcold(ps, PC_MASS)[i] * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    }
    s->kinetic = ke; /* masses changed by decree: the guard's reference follows */
    if (ke > s->kinetic_peak) s->kinetic_peak = ke;
    scene_refresh_wave_speed(s);
    return HEARTH_OK;
}

hearth_status hearth_scene_body_set_velocity(hearth_scene *s, int body, const double v[3], hearth_error *err) {
    if (body < 0 || body >= s->nbodies)
        return err_set(err, HEARTH_ERR_PARAM, "push: body %d does not exist (the scene has %d)", body, s->nbodies);
    for (int d = 0; d < 3; d++)
        if (!isfinite(v[d])) return err_set(err, HEARTH_ERR_PARAM, "push: velocity[%d] is not finite", d);
    double sp = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    for (int i = 0; i < s->ps.n; i++) {
        if (pcoli(&s->ps, PC_BODY)[i] != body) continue;
        for (int d = 0; d < s->def.dim; d++) pcold(&s->ps, PC_V)[3 * i + d] = v[d];
        particles_tensors_rest(&s->ps, i, 0); /* a push is a uniform motion: C = 0 */
    }
    if (sp > s->max_speed) s->max_speed = sp; /* the next dt must respect the new speed */
    /* the kinetic energy changed by decree, not by a runaway: the guard's reference moves with it */
    double ke = 0;
    for (int i = 0; i < s->ps.n; i++) {
        const double *vv = pcold(&s->ps, PC_V) + 3 * i;
        ke += 0.5 * pcold(&s->ps, PC_MASS)[i] * (vv[0] * vv[0] + vv[1] * vv[1] + vv[2] * vv[2]);
    }
    s->kinetic = ke;
    if (ke > s->kinetic_peak) s->kinetic_peak = ke;
    return HEARTH_OK;
}

int hearth_scene_remove_inside(hearth_scene *s, const hearth_shape *shape, hearth_error *err) {
    err_clear(err);
    const int n = s->ps.n;
    unsigned char *rm = mem_calloc((size_t)(n > 0 ? n : 1));
    if (!rm) {
        err_set(err, HEARTH_ERR_NOMEM, "cut: out of memory");
        return -1;
    }
    for (int i = 0; i < n; i++) rm[i] = hearth_shape_sdf(shape, pcold(&s->ps, PC_X) + 3 * i, NULL) < 0;
    int removed = particles_compact(&s->ps, rm);
    mem_free(rm, (size_t)(n > 0 ? n : 1));
    scene_refresh_wave_speed(s);
    return removed;
}

static hearth_status check_collider(const hearth_scene *s, int id, hearth_error *err) {
    if (id < 0 || id >= s->ncol) return err_set(err, HEARTH_ERR_PARAM, "collider %d does not exist (the scene has %d)", id, s->ncol);
    return HEARTH_OK;
}

hearth_status hearth_scene_collider_set_velocity(hearth_scene *s, int id, const double v[3], const double omega[3],
                                                 hearth_error *err) {
    hearth_status st = check_collider(s, id, err);
    if (st) return st;
    for (int d = 0; d < 3; d++)
        if (!isfinite(v[d]) || !isfinite(omega[d]))
            return err_set(err, HEARTH_ERR_PARAM, "collider %d: velocity and omega must be finite", id);
    collider *c = &s->cols[id];
    c->motion = NULL;
    c->motion_ud = NULL;
    memcpy(c->vel, v, sizeof c->vel);
    memcpy(c->omega, omega, sizeof c->omega);
    return HEARTH_OK;
}

hearth_status hearth_scene_collider_translate(hearth_scene *s, int id, const double d[3], hearth_error *err) {
    hearth_status st = check_collider(s, id, err);
    if (st) return st;
    for (int k = 0; k < 3; k++) {
        if (!isfinite(d[k])) return err_set(err, HEARTH_ERR_PARAM, "collider %d: translation must be finite", id);
        s->cols[id].offset[k] += k < s->def.dim ? d[k] : 0;
    }
    return HEARTH_OK;
}

int hearth_scene_collider_count(const hearth_scene *s) { return s->ncol; }

hearth_status hearth_scene_collider_heat(const hearth_scene *s, int id, double out[3], hearth_error *err) {
    if (id < 0 || id >= s->ncol) return err_set(err, HEARTH_ERR_PARAM, "collider %d does not exist (the scene has %d)", id, s->ncol);
    const collider *c = &s->cols[id];
    out[0] = isnan(c->temperature_end) ? NAN : collider_temperature_at(c, s->t);
    out[1] = c->drawn;
    out[2] = c->oven_in;
    return HEARTH_OK;
}

double hearth_scene_collider_distance(const hearth_scene *s, const double x[3]) {
    double best = INFINITY;
    for (int i = 0; i < s->ncol; i++) {
        const double d = collider_sdf(&s->cols[i], x, NULL);
        if (d < best) best = d;
    }
    return best;
}

/* ---- curves ---------------------------------------------------------- */

hearth_status hearth_scene_material_curve(hearth_scene *s, int mat, const char *param, int n, const double *T,
                                          const double *v, int irreversible, hearth_error *err) {
    return hearth_scene_material_curve_of(s, mat, param, HEARTH_CURVE_TEMPERATURE, n, T, v, irreversible, err);
}

_Static_assert((int)HEARTH_CURVE_TEMPERATURE == (int)CURVE_OF_TEMPERATURE && (int)HEARTH_CURVE_MOISTURE == (int)CURVE_OF_MOISTURE,
               "the public curve kinds are curves.h's");

hearth_status hearth_scene_material_curve_of(hearth_scene *s, int mat, const char *param, hearth_curve_of of, int n,
                                             const double *x, const double *v, int irreversible, hearth_error *err) {
    int k;
    hearth_status st = material_curve_check(&s->mats, mat, param, (int)of, n, x, v, &k, err);
    /* a temperature curve needs the heat field; an irreversible moisture curve its memory of the driest state
     * (zeroed: never dried). A moisture curve does not turn water on: without it the ratio is 1. */
    if (!st && of == HEARTH_CURVE_TEMPERATURE) st = scene_enable_temperature(s, err);
    if (!st && of == HEARTH_CURVE_MOISTURE && irreversible) st = particles_enable(&s->ps, PC_DRIED, err);
    if (!st) st = material_curve_add(&s->mats, mat, k, (int)of, n, x, v, irreversible, err);
    /* the MPM batched door keeps the temperature curves' values between the fields' updates (material_batch.c,
     * PC_CURVE_MEMO: CURVE_MEMO_WIDTH doubles a particle), the only reader: a scene pays for it only there */
    if (!st && of == HEARTH_CURVE_TEMPERATURE && s->def.solver == HEARTH_SOLVER_MPM && s->mats.slot[mat].m->stress_block)
        st = particles_enable(&s->ps, PC_CURVE_MEMO, err);
    return st;
}

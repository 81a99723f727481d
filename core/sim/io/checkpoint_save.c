/* checkpoint_save.c: write the full scene state as a checkpoint (layout:
 * checkpoint.h; the reader, which trusts nothing in the file, is checkpoint.c).
 *
 * The writer builds the whole image in memory (open_memstream) so the header
 * can carry the size and CRC, then writes it atomically: a failed save leaves
 * any earlier checkpoint at that path whole. */
#include "checkpoint.h"

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "atomic_file.h"
#include "error.h"
#include "field_clock.h"
#include "scene.h"
#include "shapes.h"
#include "solver.h"

typedef struct ck_out {
    FILE *f;
    int bad;
} ck_out;

static void put(ck_out *o, const void *p, size_t n) {
    if (!o->bad && n && fwrite(p, n, 1, o->f) != 1) o->bad = 1;
}
static void put_i32(ck_out *o, int32_t v) { put(o, &v, sizeof v); }
static void put_u32(ck_out *o, uint32_t v) { put(o, &v, sizeof v); }
static void put_u64(ck_out *o, uint64_t v) { put(o, &v, sizeof v); }
static void put_i64(ck_out *o, int64_t v) { put(o, &v, sizeof v); }
static void put_f64(ck_out *o, double v) { put(o, &v, sizeof v); }
static void put_str(ck_out *o, const char *s) {
    const uint32_t n = (uint32_t)strlen(s);
    put_u32(o, n);
    put(o, s, n);
}

static void put_def(ck_out *o, const hearth_scene_def *d) {
    put(o, "DEF ", 4);
    put_i32(o, d->dim);
    put_f64(o, d->dx);
    put(o, d->lo, sizeof d->lo);
    put(o, d->hi, sizeof d->hi);
    put(o, d->gravity, sizeof d->gravity);
    put_f64(o, d->cfl);
    put_f64(o, d->dt_max);
    put_i32(o, (int32_t)d->wall);
    put_f64(o, d->wall_friction);
    put_i32(o, (int32_t)d->guard);
    put_i32(o, d->max_rollbacks);
    put_f64(o, d->energy_growth);
    put_u64(o, d->seed);
    put_f64(o, d->oven_temperature);
    put_f64(o, d->oven_beta);
    put_i32(o, d->heat_implicit);
    put_i32(o, d->water_momentum);
    put_i32(o, d->transfer);
    put_f64(o, d->heat_flip);
    put_f64(o, d->oven_saturation);
    put_i32(o, d->latent_heat);
    put_i32(o, d->browning);
    put_f64(o, d->browning_scale);
    /* version 5: the settings version 4 could not hold (its writer refused them) */
    put_f64(o, d->damping);
    put_f64(o, d->boiling_point);
    for (int a = 0; a < 3; a++) put_i32(o, d->periodic[a]);
    put_i32(o, d->two_field);
    put_f64(o, d->two_field_friction);
    put_f64(o, d->gas_vent);
    put_f64(o, d->vent_porosity);
    /* version 6: the fields' clock (fields/field_clock.c) */
    put_i32(o, d->field_steps);
    /* version 16: the oven's radiating walls (fields/thermal.h) */
    put_f64(o, d->oven_wall_temperature);
    put_f64(o, d->oven_emissivity);
    put_f64(o, d->oven_radiation_scale);
}

static void put_clocks(ck_out *o, const hearth_scene *s) {
    put(o, "CLK ", 4);
    put_i32(o, (int32_t)s->guard); /* first: its offset is fixed (tests craft it) */
    put_f64(o, s->t);
    put_f64(o, s->dt_last);
    put_f64(o, s->dt_scale);
    put_i64(o, s->step);
    put_i32(o, s->rollbacks);
    put_f64(o, s->max_speed);
    put_f64(o, s->c_max);
    put_f64(o, s->kinetic);
    put_f64(o, s->kinetic_peak);
    put_f64(o, s->cfl_last);
    put_i64(o, s->out_of_domain);
    put_u64(o, s->rng);
    put_i32(o, s->next_id);
    put_i32(o, s->nbodies);
    put_f64(o, s->water.lost);
    /* version 6: the fields' cycle, so a restore mid-cycle closes it on the same step over the same time */
    put_f64(o, s->field_acc);
    put_i32(o, s->field_phase);
    put_f64(o, s->field_dt_last);
    put_i32(o, s->field_cycle_last);
    /* version 7: the water's step limits as the last step left them, so a restore takes the step the run takes */
    put_i32(o, s->water.limits_valid ? 1 : 0);
    put_f64(o, s->water.dmax);
    put_f64(o, s->water.emax);
    put_f64(o, s->water.lmax);
    /* version 13: the last step's bound on a lone particle, so a restore at cfl > 0.9 / sqrt(dim) takes the step the
     * run takes (mpm_self.c: the bound comes from the previous step's G2P) */
    put_f64(o, s->self_max);
}

static void put_materials(ck_out *o, const hearth_scene *s) {
    put(o, "MATS", 4);
    put_u32(o, (uint32_t)s->mats.n);
    for (int i = 0; i < s->mats.n; i++) {
        const material_slot *ms = &s->mats.slot[i];
        put_str(o, ms->m->name); /* the name only: never the path it was loaded from */
        put_u32(o, (uint32_t)ms->m->abi_version);
        put_u64(o, ck_schema_hash(ms->m));
        put_u32(o, (uint32_t)ms->m->nparams);
        put(o, ms->params, sizeof(double) * (size_t)ms->m->nparams);
        put(o, ms->core, sizeof(double) * CP_COUNT);
        put_u32(o, (uint32_t)ms->ncurves);
        for (int k = 0; k < ms->ncurves; k++) {
            const curve *c = &ms->curves[k];
            put_u32(o, (uint32_t)c->param);
            put_u32(o, (uint32_t)c->n);
            put_u32(o, (uint32_t)c->irreversible | (uint32_t)c->of << 1); /* bit 1: a moisture curve (#18) */
            put(o, c->T, sizeof(double) * (size_t)c->n);
            put(o, c->v, sizeof(double) * (size_t)c->n);
        }
    }
}

static void put_colliders(ck_out *o, const hearth_scene *s) {
    put(o, "COLS", 4);
    put_u32(o, (uint32_t)s->ncol);
    for (int i = 0; i < s->ncol; i++) {
        const collider *c = &s->cols[i];
        if (!o->bad && shape_write(o->f, c->shape)) o->bad = 1;
        put_i32(o, (int32_t)c->mode);
        put_f64(o, c->friction);
        put(o, c->vel, sizeof c->vel);
        put(o, c->omega, sizeof c->omega);
        put(o, c->pivot0, sizeof c->pivot0);
        put(o, c->offset, sizeof c->offset);
        put(o, c->R, sizeof c->R);
        put_i32(o, c->motion != NULL);
        put_f64(o, c->temperature_end); /* the def's temperature; a warming one's present value follows from the rest */
        put_f64(o, c->beta);
        put_f64(o, c->saturation);
        put_f64(o, c->beta_water);
        put_f64(o, c->start_temperature); /* version 14: a tray that warms (warm_time 0: it does not) */
        put_f64(o, c->warm_time);
        put_f64(o, c->t_added);
        put_f64(o, c->heat_capacity); /* version 15: a sheet the food draws from (0: it does not) and its state */
        put_f64(o, c->area);
        put_f64(o, c->sheet_T);
        put_f64(o, c->sheet_t);
        put_f64(o, c->last_heat);
        put_f64(o, c->last_span);
        put_f64(o, c->oven_in);
        put_f64(o, c->drawn);
    }
}

static void put_particles(ck_out *o, const hearth_scene *s) {
    const particles *ps = &s->ps;
    put(o, "PART", 4);
    put_u32(o, (uint32_t)ps->n);
    put_u32(o, (uint32_t)ps->state_stride);
    uint32_t saved = ps->enabled; /* the memos are a cache (exp_memo.h): a restore starts them empty */
    for (int c = 0; c < PC_COUNT; c++)
        if (particles_col_is_memo(c)) saved &= ~(1u << c);
    put_u32(o, saved);
    for (int c = 0; c < PC_COUNT; c++) {
        if (!(saved & (1u << c))) continue;
        put_str(o, particles_col_label(ps, c)); /* a 2x2 store's C and F by their own names */
        if (ps->col[c]) put(o, ps->col[c], particles_col_bytes(ps, c) * (size_t)ps->n);
    }
    put(o, "HASH", 4);
    put_u64(o, hearth_scene_hash(s));
}

hearth_status hearth_scene_save(const hearth_scene *s, const char *path, hearth_error *err) {
    err_clear(err);
    if (!s->solver->can_checkpoint) /* the solver's own state is not in the format (solver.h) */
        return err_set(err, HEARTH_ERR_PARAM, "save %s: checkpoints of %s scenes (solver = \"%s\") are not supported yet",
                       path, s->solver->name, s->solver->name);
    /* mixing.c: the constituents' parameter sets and the mixture's per-particle
     * ratios are state beyond the DEF section (and the Lua binding's h.mix), not
     * in the format yet; every other scene setting is in the DEF section */
    if (s->mix.mat >= 0)
        return err_set(err, HEARTH_ERR_PARAM, "save %s: checkpoints of scenes with a dynamic mixture are not supported yet",
                       path);
    char *img = NULL;
    size_t n = 0;
    FILE *mf = open_memstream(&img, &n);
    if (!mf) return err_set(err, HEARTH_ERR_NOMEM, "save %s: out of memory for the checkpoint image", path);
    ck_out o = {mf, 0};
    put(&o, CK_MAGIC, 8);
    put_u32(&o, CK_VERSION);
    put_u32(&o, CK_BOM);
    put_u32(&o, (uint32_t)sizeof(double));
    put_u32(&o, CK_HEADER_SIZE);
    put_u64(&o, 0); /* size and CRC: ck_reseal below */
    put_u32(&o, 0);
    put_u32(&o, 0);
    put_def(&o, &s->def);
    put_clocks(&o, s);
    put_materials(&o, s);
    put_colliders(&o, s);
    put_particles(&o, s);
    if (fclose(mf) != 0) o.bad = 1;
    if (o.bad || n < CK_HEADER_SIZE) {
        free(img);
        return err_set(err, HEARTH_ERR_NOMEM, "save %s: out of memory building the checkpoint image", path);
    }
    ck_reseal((uint8_t *)img, n);
    atomic_file af;
    hearth_status st = atomic_open(&af, path, err);
    if (st) {
        free(img);
        return st;
    }
    const int bad = fwrite(img, n, 1, af.f) != 1;
    free(img);
    if (bad) {
        atomic_abort(&af);
        return err_set(err, HEARTH_ERR_IO, "%s: write failed", path);
    }
    return atomic_commit(&af, err);
}

/* checkpoint.c: restore the full scene state from a checkpoint (layout:
 * checkpoint.h; the writer is checkpoint_save.c).
 *
 * A restored scene continues bit-identically: particle order, clocks, dt
 * scale, the jitter generator and collider poses are all in the file. Motion
 * callbacks are code and are not saved; re-attach them with
 * hearth_scene_collider_motion.
 *
 * A checkpoint is untrusted input (it may come from anywhere), so loading:
 *   1. reads the file into memory after checking its size against the cap and
 *      against the size its header states;
 *   2. verifies the CRC-32 over the whole file before parsing anything else;
 *   3. parses with a bounds-checked cursor: every count is checked against
 *      the bytes left and a sane limit before anything is allocated, every
 *      enum against its range, every float that must be finite is, and no
 *      float becomes an integer;
 *   4. names materials by plugin name only, resolved on the plugin search
 *      path, with the ABI and a hash of the schema checked: a checkpoint never
 *      makes hearth dlopen a path it holds;
 *   5. builds the scene through the public constructors (scene, materials,
 *      curves, colliders), which check values as they do for a script.
 * The checksum alone would refuse random damage; the checks of 3-5 are for
 * a file crafted to pass it.
 *
 * The writer is checkpoint_save.c. Version 2 files (a
 * checksum over the particles only, plugins by path) and version 3 are refused
 * by version; version 4 is read with the DEF fields version 5 appended at their
 * defaults (its writer refused scenes with any other value); versions 4 and 5
 * without version 6's field_steps (1, every step: their bits) and fields' cycle (a new one); versions 4
 * to 6 without version 7's water step limits (scanned again from the particles, as their readers did) and
 * its last core material parameter, dry_conductivity (0, as wet: their bits); versions 4 to 7 without
 * version 8's last core material parameter, dry_specific_heat (0, as wet: their bits); versions 4 to 9 without
 * version 10's last two, ambient_pressure (0: eq. 13 as printed, their bits) and open_temperature; versions 4 to
 * 11 without version 12's last three, the second CO2 share (gas_rate_2 0: none, their bits); versions 4 to 12
 * without version 13's last two, the shares' amounts (0: no limit, their bits), the CO2 each share made (none:
 * the column is made only with an amount) and the bound on a lone particle (0: none for the first step, as they
 * restored). */
#include "checkpoint.h"

#include <errno.h>
#include <fcntl.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "alloc.h"
#include "atomic_file.h"
#include "crc32.h"
#include "error.h"
#include "scene.h"
#include "solver.h"
#include "shapes.h"
#include "field_clock.h"

/* Limits a valid checkpoint stays far inside; a count above one is refused
 * before anything is allocated for it. */
#define CK_MAX_MATERIALS 4096
#define CK_MAX_COLLIDERS 4096
#define CK_MAX_CURVE_POINTS 100000
#define CK_MAX_STRIDE 4096
#define CK_MAX_NAME 64

/* ---- cursor ----------------------------------------------------------- */

int ck_fail(ck_cursor *c, const char *what) {
    if (!c->bad) {
        c->bad = 1;
        c->what = what;
    }
    return -1;
}

int ck_get(ck_cursor *c, void *out, size_t n) {
    if (c->bad || n > c->left) {
        memset(out, 0, n);
        return ck_fail(c, "truncated");
    }
    memcpy(out, c->p, n);
    c->p += n;
    c->left -= n;
    return 0;
}

static int32_t get_i32(ck_cursor *c) {
    int32_t v;
    ck_get(c, &v, sizeof v);
    return v;
}
static uint32_t get_u32(ck_cursor *c) {
    uint32_t v;
    ck_get(c, &v, sizeof v);
    return v;
}
static uint64_t get_u64(ck_cursor *c) {
    uint64_t v;
    ck_get(c, &v, sizeof v);
    return v;
}
static int64_t get_i64(ck_cursor *c) {
    int64_t v;
    ck_get(c, &v, sizeof v);
    return v;
}
static double get_f64(ck_cursor *c) {
    double v;
    ck_get(c, &v, sizeof v);
    return v;
}
/* A double that must be finite; what names it in the refusal. */
static double get_finite(ck_cursor *c, const char *what) {
    double v = get_f64(c);
    if (!isfinite(v)) ck_fail(c, what);
    return v;
}
static void get_finite_n(ck_cursor *c, double *v, int n, const char *what) {
    for (int k = 0; k < n; k++) v[k] = get_finite(c, what);
}
/* A section tag: the parser and the file agree on where each part starts. */
static void get_tag(ck_cursor *c, const char tag[4], const char *what) {
    char t[4];
    if (!ck_get(c, t, 4) && memcmp(t, tag, 4) != 0) ck_fail(c, what);
}
/* A string of at most cap - 1 bytes without a NUL inside; what names the refusal. */
static void get_str(ck_cursor *c, char *buf, size_t cap, const char *what) {
    buf[0] = '\0';
    const uint32_t n = get_u32(c);
    if (c->bad) return;
    if (n >= cap) {
        ck_fail(c, what);
        return;
    }
    if (ck_get(c, buf, n)) return;
    buf[n] = '\0';
    if (memchr(buf, '\0', n)) ck_fail(c, what);
}

/* ---- checksum --------------------------------------------------------- */

uint32_t ck_crc(const uint8_t *buf, size_t n) {
    static const uint8_t zero[4] = {0, 0, 0, 0};
    uint32_t crc = crc32_update(0, buf, CK_OFF_CRC);
    crc = crc32_update(crc, zero, 4);
    return crc32_update(crc, buf + CK_OFF_CRC + 4, n - CK_OFF_CRC - 4);
}

void ck_reseal(uint8_t *buf, size_t n) {
    if (n < CK_HEADER_SIZE) return;
    const uint64_t size = n;
    memcpy(buf + CK_OFF_SIZE, &size, sizeof size);
    const uint32_t crc = ck_crc(buf, n);
    memcpy(buf + CK_OFF_CRC, &crc, sizeof crc);
}

/* ---- the plugin schema's hash ----------------------------------------- */

static uint64_t fnv(uint64_t h, const void *p, size_t n) {
    const unsigned char *b = p;
    for (size_t i = 0; i < n; i++) h = (h ^ b[i]) * 1099511628211ULL;
    return h;
}
static uint64_t fnv_str(uint64_t h, const char *s) { return fnv(h, s ? s : "", (s ? strlen(s) : 0) + 1); }

/* FNV-1a over what a saved material depends on: the parameter names, units,
 * ranges and defaults (the meaning of the saved numbers), the state size and
 * the needs (the meaning of the saved state columns). The help text is left
 * out: rewording it changes nothing saved. */
uint64_t ck_schema_hash(const hearth_material *m) {
    uint64_t h = 1469598103934665603ULL;
    h = fnv_str(h, m->name);
    const int32_t head[4] = {m->real_size, m->nparams, m->state_size, (int32_t)m->needs};
    h = fnv(h, head, sizeof head);
    for (int k = 0; k < m->nparams; k++) {
        const hearth_param *p = &m->params[k];
        h = fnv_str(h, p->name);
        h = fnv_str(h, p->unit);
        const double r[3] = {p->def, p->min, p->max};
        h = fnv(h, r, sizeof r);
    }
    return h;
}

static int is_plugin_name(const char *s) {
    if (!*s) return 0;
    for (; *s; s++)
        if (!((*s >= 'a' && *s <= 'z') || (*s >= '0' && *s <= '9') || *s == '_')) return 0;
    return 1;
}

/* ---- reading ---------------------------------------------------------- */

/* A real setting of the DEF section, read into its field of d and checked
 * against its row of the settings table (settings.c), so the message names
 * the setting, the value and the range the file broke. */
static void get_real_setting(ck_cursor *c, hearth_scene_def *d, const char *name) {
    const hearth_setting *e = hearth_scene_setting(name);
    if (!e || e->kind != HEARTH_SETTING_REAL || e->offset < 0) {
        ck_fail(c, "scene: a setting the format names is not in the settings table");
        return;
    }
    double *v = (double *)((char *)d + e->offset);
    *v = get_f64(c);
    if (c->bad || (e->nan_ok && isnan(*v))) return; /* NaN where the table says it means "none" */
    if (!(isfinite(*v) && (e->min_open ? *v > e->min : *v >= e->min) && *v <= e->max)) {
        const int unit = strcmp(e->unit, "1") != 0; /* "1": dimensionless, no unit to print */
        snprintf(c->msg, sizeof c->msg, "scene: %s = %g%s%s is outside its valid range %c%g, %g]", name, *v,
                 unit ? " " : "", unit ? e->unit : "", e->min_open ? '(' : '[', e->min, e->max);
        ck_fail(c, c->msg);
    }
}
/* A 0/1 setting of the DEF section, named as the settings table names it. */
static void get_flag_setting(ck_cursor *c, int *v, const char *name) {
    const int32_t x = get_i32(c);
    *v = x;
    if (!c->bad && x != 0 && x != 1) {
        snprintf(c->msg, sizeof c->msg, "scene: %s = %d is neither 0 nor 1", name, (int)x);
        ck_fail(c, c->msg);
    }
}

/* The scene definition, every field checked here or by hearth_scene_create.
 * A version 4 file ends the section before the fields version 5 appended;
 * they keep the defaults d holds (the caller's hearth_default_scene_def). */
static void get_def(ck_cursor *c, hearth_scene_def *d, uint32_t version) {
    get_tag(c, "DEF ", "the scene definition section is missing");
    d->dim = get_i32(c);
    d->dx = get_finite(c, "scene: dx is not finite");
    get_finite_n(c, d->lo, 3, "scene: box lo is not finite");
    get_finite_n(c, d->hi, 3, "scene: box hi is not finite");
    get_finite_n(c, d->gravity, 3, "scene: gravity is not finite");
    d->cfl = get_finite(c, "scene: cfl is not finite");
    d->dt_max = get_finite(c, "scene: dt_max is not finite");
    const int32_t wall = get_i32(c);
    if (wall < HEARTH_STICKY || wall > HEARTH_SEPARATE) ck_fail(c, "scene: wall mode out of range [0, 2]");
    d->wall = (hearth_contact)wall;
    d->wall_friction = get_finite(c, "scene: wall friction is not finite");
    const int32_t guard = get_i32(c);
    if (guard < HEARTH_GUARD_STOP || guard > HEARTH_GUARD_ROLLBACK) ck_fail(c, "scene: guard policy out of range [0, 1]");
    d->guard = (hearth_guard_policy)guard;
    d->max_rollbacks = get_i32(c);
    d->energy_growth = get_finite(c, "scene: energy_growth is not finite");
    d->seed = get_u64(c);
    d->oven_temperature = get_f64(c); /* NaN means no oven; hearth_scene_create checks the rest */
    d->oven_beta = get_finite(c, "scene: oven beta is not finite");
    d->heat_implicit = get_i32(c);
    d->water_momentum = get_i32(c);
    if (d->water_momentum != 0 && d->water_momentum != 1) ck_fail(c, "scene: water_momentum is neither 0 nor 1");
    d->transfer = get_i32(c);
    d->heat_flip = get_finite(c, "scene: heat_flip is not finite");
    d->oven_saturation = get_finite(c, "scene: oven saturation is not finite");
    d->latent_heat = get_i32(c);
    if (d->latent_heat != 0 && d->latent_heat != 1) ck_fail(c, "scene: latent_heat is neither 0 nor 1");
    d->browning = get_i32(c);
    if (d->browning != 0 && d->browning != 1) ck_fail(c, "scene: browning is neither 0 nor 1");
    d->browning_scale = get_finite(c, "scene: browning_scale is not finite"); /* hearth_scene_create checks its range */
    if (version >= 5) {
        get_real_setting(c, d, "damping");
        get_real_setting(c, d, "boiling_point");
        static const char *const periodic[3] = {"periodic_x", "periodic_y", "periodic_z"};
        for (int a = 0; a < 3; a++) get_flag_setting(c, &d->periodic[a], periodic[a]);
        get_flag_setting(c, &d->two_field, "two_field");
        get_real_setting(c, d, "two_field_friction");
        get_real_setting(c, d, "gas_vent");
        get_real_setting(c, d, "vent_porosity");
    }
    if (version >= 6) {
        d->field_steps = get_i32(c);
        if (!c->bad && (d->field_steps < 0 || d->field_steps > FIELD_MAX_CYCLE)) {
            snprintf(c->msg, sizeof c->msg, "scene: field_steps = %d is outside its valid range [0, %d]", (int)d->field_steps,
                     FIELD_MAX_CYCLE);
            ck_fail(c, c->msg);
        }
    } else
        d->field_steps = 1; /* written single rate (every step), whatever today's default: their bits */
    if (version >= 16) { /* the oven's radiating walls; NaN walls: none (an older file's oven has none: its bits) */
        get_real_setting(c, d, "oven.wall_temperature");
        get_real_setting(c, d, "oven.emissivity");
        get_real_setting(c, d, "oven.radiation_scale");
    } else
        d->oven_wall_temperature = NAN, d->oven_emissivity = 0, d->oven_radiation_scale = 1;
    d->solver = HEARTH_SOLVER_MPM; /* the only solver whose table says can_checkpoint (solver.h) */
}

typedef struct ck_clocks {
    int32_t guard, rollbacks, next_id, nbodies;
    double t, dt_last, dt_scale, max_speed, c_max, kinetic, kinetic_peak, cfl_last, water_lost;
    double field_acc, field_dt_last; /* version 6; 0 before: a cycle that starts at the restore */
    int32_t field_phase, field_cycle_last;
    int32_t water_limits; /* version 7: the water's explicit-step limits as the last step left them (1), or none (0) */
    double water_dmax, water_emax, water_lmax;
    double self_max; /* version 13: the last step's bound on a lone particle (mpm_self.c); 0 before */
    int64_t step, ood;
    uint64_t rng;
} ck_clocks;

static void get_clocks(ck_cursor *c, ck_clocks *k, uint32_t version) {
    get_tag(c, "CLK ", "the clocks section is missing");
    k->guard = get_i32(c);
    if (k->guard < HEARTH_GUARD_OK || k->guard > HEARTH_GUARD_STOPPED) ck_fail(c, "guard state out of range [0, 2]");
    k->t = get_finite(c, "clock: t is not finite");
    k->dt_last = get_finite(c, "clock: dt_last is not finite");
    k->dt_scale = get_finite(c, "clock: dt_scale is not finite");
    if (!(k->dt_scale > 0 && k->dt_scale <= 1)) ck_fail(c, "clock: dt_scale out of range (0, 1]");
    k->step = get_i64(c);
    if (k->step < 0) ck_fail(c, "clock: negative step count");
    k->rollbacks = get_i32(c);
    if (k->rollbacks < 0) ck_fail(c, "clock: negative rollback count");
    k->max_speed = get_finite(c, "clock: max speed is not finite");
    k->c_max = get_finite(c, "clock: wave speed is not finite");
    k->kinetic = get_finite(c, "clock: kinetic energy is not finite");
    k->kinetic_peak = get_finite(c, "clock: peak kinetic energy is not finite");
    k->cfl_last = get_finite(c, "clock: last CFL number is not finite");
    /* speeds, energies and the last step feed the guard and the next dt: a
     * negative one would disarm the runaway check or the CFL limit */
    if (!(k->dt_last >= 0 && k->max_speed >= 0 && k->c_max >= 0 && k->kinetic >= 0 && k->kinetic_peak >= 0 &&
          k->cfl_last >= 0))
        ck_fail(c, "clock: a negative step, speed, wave speed, energy or CFL number");
    k->ood = get_i64(c);
    if (k->ood < 0) ck_fail(c, "clock: negative out-of-domain count");
    k->rng = get_u64(c);
    k->next_id = get_i32(c);
    k->nbodies = get_i32(c);
    if (k->next_id < 0 || k->nbodies < 0) ck_fail(c, "clock: negative particle id or body count");
    k->water_lost = get_finite(c, "clock: water lost is not finite");
    k->field_acc = k->field_dt_last = 0;
    k->field_phase = k->field_cycle_last = 0;
    if (version >= 6) {
        k->field_acc = get_finite(c, "clock: the fields' cycle time is not finite");
        k->field_phase = get_i32(c);
        k->field_dt_last = get_finite(c, "clock: the last field step is not finite");
        k->field_cycle_last = get_i32(c);
        /* a negative time or phase would never close the cycle */
        if (!(k->field_acc >= 0 && k->field_dt_last >= 0) || k->field_phase < 0 || k->field_phase >= FIELD_MAX_CYCLE ||
            k->field_cycle_last < 0 || k->field_cycle_last > FIELD_MAX_CYCLE)
            ck_fail(c, "clock: the fields' cycle is out of range (time >= 0, steps in [0, 4096])");
    }
    /* Version 7: the water's explicit-step limits (water.h's water_state), which G2P scanned at P2G's volumes
     * (and the latent one of the saturations the next field step starts from): a restore that scanned the
     * particles again would read, in a cycle, a det F moved on since the field step, and at every step
     * s = m^w / (rho_0^w J V_0) rounded otherwise, and a scene whose latent limit binds took another step
     * and went on to other bits (latent_limit_checkpoint_roundtrip). Before
     * version 7 (0): scanned again, as then. */
    k->water_limits = 0;
    k->water_dmax = k->water_emax = k->water_lmax = 0;
    if (version >= 7) {
        k->water_limits = get_i32(c);
        k->water_dmax = get_f64(c);
        k->water_emax = get_f64(c);
        k->water_lmax = get_f64(c); /* infinite for a material that evaporates with no heat capacity */
        if ((k->water_limits != 0 && k->water_limits != 1) || !(k->water_dmax >= 0) || !(k->water_emax >= 0) ||
            !(k->water_lmax >= 0))
            ck_fail(c, "clock: the water's step limits are out of range (a flag 0 or 1, limits >= 0)");
    }
    /* Version 13: the lone-particle bound's share alpha, which the next step's dt reads (mpm_self_dt) and the
     * last step's G2P measured: without it a restore at cfl > 0.9 / sqrt(dim) took one step unbounded. alpha =
     * tr(D^-1 sum_i w_ip (x_i - x_p) g_i^T) / dim with D = dx^2 / 4, |x_i - x_p| and |g_i| at most 1.5 dx per
     * axis and the weights summing to 1: at most 9. A larger one would only shrink dt, a NaN or negative one
     * would lift the bound: both refused. */
    k->self_max = 0;
    if (version >= 13) {
        k->self_max = get_f64(c);
        if (!(k->self_max >= 0 && k->self_max <= 9)) ck_fail(c, "clock: the lone-particle bound's share is outside [0, 9]");
    }
}

/* A refusal: the file named, then what is wrong. Frees s. */
static hearth_scene *refuse(hearth_scene *s, hearth_error *err, const char *name, const char *what) {
    if (err && err->code == HEARTH_OK) err_set(err, HEARTH_ERR_FORMAT, "%s: not a valid hearth checkpoint: %s", name, what);
    hearth_scene_destroy(s);
    return NULL;
}
/* A refusal from the cursor, or from err when a constructor filled it. */
static hearth_scene *refuse_at(hearth_scene *s, hearth_error *err, const char *name, const ck_cursor *c,
                               const char *section) {
    if (err && err->code == HEARTH_OK) {
        if (c->what && strcmp(c->what, "truncated") == 0)
            err_set(err, HEARTH_ERR_FORMAT, "%s: not a valid hearth checkpoint: %s ends early (%zu bytes left)", name,
                    section, c->left);
        else
            err_set(err, HEARTH_ERR_FORMAT, "%s: not a valid hearth checkpoint: %s: %s", name, section,
                    c->what ? c->what : "malformed");
    } else if (err && strncmp(err->msg, name, strlen(name)) != 0) {
        /* a constructor's message: say that the checkpoint holds the value */
        char msg[sizeof err->msg];
        snprintf(msg, sizeof msg, "%s", err->msg);
        err_set(err, err->code == HEARTH_ERR_NOMEM ? HEARTH_ERR_NOMEM : HEARTH_ERR_FORMAT,
                "%s: checkpoint refused (%s): %s", name, section, msg);
    }
    hearth_scene_destroy(s);
    return NULL;
}

static int get_materials(ck_cursor *c, hearth_scene *s, const char *name, uint32_t version, hearth_error *err) {
    /* the core parameters the file holds: before version 7, all up to dry_conductivity, before version 8 up to
     * dry_specific_heat, before version 10 up to ambient_pressure, before version 12 up to gas_rate_2; those left at
     * their defaults (0, as wet; 0, eq. 13 as printed, and open_temperature unread; 0, no second CO2 share) */
    const int ncore = version >= 13  ? CP_COUNT
                      : version >= 12 ? CP_GAS_AMOUNT
                      : version >= 10 ? CP_GAS_RATE_2
                      : version >= 8 ? CP_AMBIENT_PRESSURE
                      : version >= 7 ? CP_DRY_SPECIFIC_HEAT
                                     : CP_DRY_CONDUCTIVITY;
    get_tag(c, "MATS", "the materials section is missing");
    const uint32_t nmat = get_u32(c);
    if (c->bad) return -1;
    if (nmat > CK_MAX_MATERIALS) return ck_fail(c, "more than 4096 materials");
    for (uint32_t i = 0; i < nmat; i++) {
        char pname[CK_MAX_NAME];
        get_str(c, pname, sizeof pname, "a material's plugin name is longer than 63 bytes");
        const uint32_t abi = get_u32(c);
        const uint64_t hash = get_u64(c);
        const uint32_t np = get_u32(c);
        if (c->bad) return -1;
        if (!is_plugin_name(pname)) {
            /* a path (or anything else) is never handed to the loader */
            err_set(err, HEARTH_ERR_FORMAT,
                    "%s: not a valid hearth checkpoint: material %u names plugin \"%.40s\", which is not a plugin name "
                    "[a-z0-9_]+ (checkpoints name plugins, never paths)",
                    name, i, pname);
            return -1;
        }
        if (np > SCENE_MAX_PARAMS) return ck_fail(c, "a material with more than 256 parameters");
        if ((size_t)(np + (uint32_t)ncore) * sizeof(double) > c->left) return ck_fail(c, "truncated");
        double vals[SCENE_MAX_PARAMS + CP_COUNT];
        get_finite_n(c, vals, (int)np + ncore, "a material parameter is not finite");
        if (c->bad) return -1;
        if (abi != HEARTH_MATERIAL_ABI) {
            err_set(err, HEARTH_ERR_FORMAT,
                    "%s: material '%s' was saved with plugin ABI %u; this hearth has ABI %d (rebuild the plugin and "
                    "start the run again)",
                    name, pname, abi, HEARTH_MATERIAL_ABI);
            return -1;
        }
        const hearth_plugin *pl = hearth_plugin_load(pname, err); /* by name, on the search path */
        if (!pl) {
            char msg[sizeof err->msg];
            snprintf(msg, sizeof msg, "%s", err->msg);
            err_set(err, HEARTH_ERR_PLUGIN, "%s: material '%s': %s", name, pname, msg);
            return -1;
        }
        const hearth_material *m = hearth_plugin_material(pl);
        if (strcmp(m->name, pname) != 0) {
            err_set(err, HEARTH_ERR_FORMAT, "%s: plugin '%s' on the search path declares material '%s'", name, pname,
                    m->name);
            return -1;
        }
        if (m->nparams != (int)np) {
            err_set(err, HEARTH_ERR_FORMAT,
                    "%s: material '%s' was saved with %u parameters; the plugin '%s' now has %d (the plugin changed "
                    "since the save)",
                    name, pname, np, hearth_plugin_file(pl), m->nparams);
            return -1;
        }
        if (ck_schema_hash(m) != hash) {
            err_set(err, HEARTH_ERR_FORMAT,
                    "%s: material '%s' was saved with another parameter schema (hash %016llx; the plugin '%s' now has "
                    "%016llx): its parameter names, units, ranges, defaults, state size or needs changed since the save",
                    name, pname, (unsigned long long)hash, hearth_plugin_file(pl), (unsigned long long)ck_schema_hash(m));
            return -1;
        }
        const char *names[SCENE_MAX_PARAMS + CP_COUNT];
        for (uint32_t k = 0; k < np; k++) names[k] = m->params[k].name;
        const hearth_param *cp = hearth_core_params(NULL);
        for (int k = 0; k < ncore; k++) names[np + k] = cp[k].name;
        const int mat = hearth_scene_add_material(s, pname, names, vals, (int)np + ncore, err);
        if (mat < 0) return -1;
        const uint32_t nc = get_u32(c);
        if (c->bad) return -1;
        if (nc > 2 * np) return ck_fail(c, "more curves than two per parameter");
        for (uint32_t k = 0; k < nc; k++) {
            const uint32_t param = get_u32(c), npts = get_u32(c), irr = get_u32(c);
            if (c->bad) return -1;
            if (param >= np) return ck_fail(c, "a curve of a parameter the material does not have");
            if (npts < 1 || npts > CK_MAX_CURVE_POINTS) return ck_fail(c, "a curve's point count out of range [1, 100000]");
            if (irr > 3) return ck_fail(c, "a curve's flags hold bits other than irreversible (1) and moisture (2)");
            const size_t bytes = sizeof(double) * npts;
            if (2 * bytes > c->left) return ck_fail(c, "truncated");
            double *T = mem_alloc(bytes), *v = mem_alloc(bytes);
            int bad = !T || !v;
            if (bad) err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory for a curve of %u points", name, npts);
            else {
                get_finite_n(c, T, (int)npts, "a curve's temperature is not finite");
                get_finite_n(c, v, (int)npts, "a curve's value is not finite");
                bad = c->bad || hearth_scene_material_curve_of(s, mat, m->params[param].name, (hearth_curve_of)(irr >> 1),
                                                               (int)npts, T, v, (int)(irr & 1), err);
            }
            mem_free(T, bytes);
            mem_free(v, bytes);
            if (bad) return -1;
        }
    }
    return 0;
}

static int rotation_ok(const double R[9]) {
    for (int a = 0; a < 3; a++)
        for (int b = 0; b < 3; b++) {
            const double d = R[3 * a] * R[3 * b] + R[3 * a + 1] * R[3 * b + 1] + R[3 * a + 2] * R[3 * b + 2];
            if (!(fabs(d - (a == b)) <= 1e-6)) return 0;
        }
    return 1;
}

/* t: the restored clock's time (set_clocks applies it after), at which a warming collider takes its temperature */
static int get_colliders(ck_cursor *c, hearth_scene *s, uint32_t version, double t, hearth_error *err) {
    get_tag(c, "COLS", "the colliders section is missing");
    const uint32_t ncol = get_u32(c);
    if (c->bad) return -1;
    if (ncol > CK_MAX_COLLIDERS) return ck_fail(c, "more than 4096 colliders");
    for (uint32_t i = 0; i < ncol; i++) {
        hearth_shape *sh = shape_read_mem(c, 0);
        if (!sh) return -1;
        hearth_collider_def cd = hearth_default_collider_def();
        cd.shape = sh;
        const int32_t mode = get_i32(c);
        if (mode < HEARTH_STICKY || mode > HEARTH_GRIP) ck_fail(c, "collider contact mode out of range [0, 3]");
        cd.mode = (hearth_contact)mode;
        cd.friction = get_finite(c, "collider friction is not finite");
        double offset[3], R[9];
        get_finite_n(c, cd.velocity, 3, "collider velocity is not finite");
        get_finite_n(c, cd.omega, 3, "collider angular velocity is not finite");
        get_finite_n(c, cd.pivot, 3, "collider pivot is not finite");
        get_finite_n(c, offset, 3, "collider offset is not finite");
        get_finite_n(c, R, 9, "collider rotation is not finite");
        if (!c->bad && !rotation_ok(R)) ck_fail(c, "collider rotation is not a rotation matrix");
        const int32_t has_motion = get_i32(c);
        if (has_motion != 0 && has_motion != 1) ck_fail(c, "collider motion flag is neither 0 nor 1");
        cd.temperature = get_f64(c); /* NaN: not heated; collider_init checks the rest */
        cd.beta = get_f64(c); /* +inf: held at its temperature; collider_init refuses NaN and negatives */
        cd.saturation = get_f64(c);  /* NaN: dry */
        cd.beta_water = get_finite(c, "collider beta_water is not finite");
        double t_added = 0;
        if (version >= 14) { /* a warming tray; collider_init checks start_temperature and warm_time */
            cd.start_temperature = get_f64(c);
            cd.warm_time = get_f64(c);
            t_added = get_finite(c, "collider t_added is not finite");
        }
        double sheet[6] = {NAN, 0, 0, 0, 0, 0}; /* a drawing sheet's state: T, t, last heat and span, oven_in, drawn */
        if (version >= 15) { /* collider_init checks heat_capacity and area */
            cd.heat_capacity = get_f64(c);
            cd.area = get_f64(c);
            sheet[0] = get_f64(c); /* NaN for a collider that does not warm */
            get_finite_n(c, sheet + 1, 5, "collider sheet state is not finite");
            if (!c->bad && cd.heat_capacity > 0 && !(sheet[0] >= -273.15 && sheet[0] <= 1e4))
                ck_fail(c, "a drawing collider's sheet temperature is out of range [-273.15, 10000] degrees C");
            if (!c->bad && cd.heat_capacity > 0 && !(sheet[3] >= 0)) ck_fail(c, "a drawing collider's last span is negative");
        }
        const int id = c->bad ? -1 : hearth_scene_add_collider(s, &cd, err);
        hearth_shape_free(sh);
        if (id < 0) return -1;
        memcpy(s->cols[id].offset, offset, sizeof offset);
        memcpy(s->cols[id].R, R, sizeof R);
        s->cols[id].t_added = t_added;
        s->cols[id].sheet_t = t_added;
        if (version >= 15 && cd.heat_capacity > 0) {
            collider *cl = &s->cols[id];
            cl->sheet_T = sheet[0], cl->sheet_t = sheet[1], cl->last_heat = sheet[2], cl->last_span = sheet[3];
            cl->oven_in = sheet[4], cl->drawn = sheet[5];
        }
        collider_set_time(&s->cols[id], t);
        collider_update_bounds(&s->cols[id], 2 * s->def.dx);
    }
    return 0;
}

/* Whether every value of a column is acceptable: finite where it must be,
 * indices in range. Names the first offender in c. */
static int check_column(ck_cursor *c, const hearth_scene *s, int col, int n) {
    const particles *ps = &s->ps;
    if (col == PC_STATE) return 0; /* the plugin's own numbers: its state, its meaning */
    if (particles_col_is_int(col)) {
        const int *a = pcoli(ps, col);
        for (int i = 0; i < n; i++) {
            const int v = a[i];
            if (col == PC_MAT && (v < 0 || v >= s->mats.n)) return ck_fail(c, "a particle with an unknown material");
            if (col == PC_BODY && (v < -1 || v >= s->nbodies)) return ck_fail(c, "a particle with an unknown body");
            if (col == PC_FLAGS && (v & ~(PF_FIXED | PF_BOUNDARY | PF_HOLD_T))) return ck_fail(c, "a particle with unknown flags");
            if (col == PC_GLUE && v < 0) return ck_fail(c, "a particle glued to an unknown face"); /* 31 slots */
            if (col == PC_ID && (v < 0 || v >= s->next_id)) return ck_fail(c, "a particle id out of range");
        }
        return 0;
    }
    const double *a = pcold(ps, col);
    const size_t len = (size_t)particles_col_ncomp(ps, col) * (size_t)n;
    for (size_t i = 0; i < len; i++)
        if (!isfinite(a[i])) return ck_fail(c, "a particle value that is not finite");
    if (col == PC_DRIED) /* 1 - the lowest moisture ratio reached */
        for (int i = 0; i < n; i++)
            if (!(a[i] >= 0 && a[i] <= 1)) return ck_fail(c, "a particle's dried value outside [0, 1]");
    if (col == PC_GAS_MADE) /* each share's CO2 made, within its material's amount (gas.h's gas_share_capped) */
        for (int i = 0; i < n; i++) {
            const double *core = s->mats.slot[pcoli(ps, PC_MAT)[i]].core;
            for (int k = 0; k < 2; k++) {
                const double amount = core[k ? CP_GAS_AMOUNT_2 : CP_GAS_AMOUNT], m = a[2 * i + k];
                if (!(m >= 0 && m <= (amount > 0 ? amount : 0)))
                    return ck_fail(c, "a particle's CO2 made outside [0, its share's gas_amount]");
            }
        }
    if (col == PC_MASS || col == PC_VOL0)
        for (int i = 0; i < n; i++)
            if (!(a[i] > 0)) return ck_fail(c, "a particle mass or volume <= 0");
    return 0;
}

static int get_particles(ck_cursor *c, hearth_scene *s, uint32_t version, uint32_t *absent, hearth_error *err) {
    get_tag(c, "PART", "the particles section is missing");
    const uint32_t n = get_u32(c), stride = get_u32(c), enabled = get_u32(c);
    if (c->bad) return -1;
    const uint32_t core = (1u << PC_NCORE) - 1;
    if ((enabled & core) != core || enabled >= (1u << PC_COUNT)) return ck_fail(c, "unknown or missing particle columns");
    if (version < 13 && (enabled & (1u << PC_GAS_MADE))) /* its bit was a memo's before version 13 */
        return ck_fail(c, "a CO2-made column in a file older than version 13");
    for (int k = 0; k < PC_COUNT; k++) /* never saved (checkpoint_save.c): a file that has one was not written by hearth */
        if ((enabled & (1u << k)) && particles_col_is_memo(k))
            return ck_fail(c, "a memo column (a cache the scene recomputes, never saved) in the particles section");
    if (!(enabled & (1u << PC_BROWNING)) != !s->def.browning) /* the column lives exactly when the scene browns */
        return ck_fail(c, s->def.browning ? "no browning column in a scene with browning = true"
                                          : "a browning column in a scene with browning = false");
    if (stride > CK_MAX_STRIDE) return ck_fail(c, "plugin state stride above 4096 doubles");
    particles *ps = &s->ps;
    if ((int)stride < ps->state_stride) return ck_fail(c, "plugin state stride smaller than a material's state");
    /* every column is in the file: bytes per particle times n must fit in what is left */
    particles probe = *ps;
    probe.state_stride = (int)stride;
    probe.enabled = enabled;
    size_t per = 0;
    for (int k = 0; k < PC_COUNT; k++)
        if (enabled & (1u << k)) per += particles_col_bytes(&probe, k);
    if (n > (uint32_t)INT32_MAX / 2 || (per && (uint64_t)n > c->left / per))
        return ck_fail(c, "a particle count larger than the file holds");
    if (particles_set_state_stride(ps, (int)stride, err)) return -1;
    for (int k = PC_NCORE; k < PC_COUNT; k++)
        if ((enabled & (1u << k)) && particles_enable(ps, k, err)) return -1;
    if (n && particles_reserve(ps, (int)n, err)) return -1;
    for (int k = 0; k < PC_COUNT; k++) {
        if (!(enabled & (1u << k))) continue;
        char cname[CK_MAX_NAME];
        get_str(c, cname, sizeof cname, "a particle column name is too long");
        if (c->bad) return -1;
        if (strcmp(cname, particles_col_label(ps, k)) != 0) {
            if (ps->t2 && strcmp(cname, particles_col_name(k)) == 0) /* saved before 2D MPM kept 2x2 tensors */
                return ck_fail(c, "a 2D checkpoint from before the 2x2 particle store (its C and F hold 9 components, this "
                                  "hearth keeps the 4 in-plane ones); rerun the scene to save it again");
            return ck_fail(c, "particle columns out of order");
        }
        const size_t bytes = particles_col_bytes(ps, k) * (size_t)n;
        if (bytes && ck_get(c, ps->col[k], bytes)) return -1;
        if (check_column(c, s, k, (int)n)) return -1;
    }
    /* a file saved before eq. 10 became a strain (material.h) has no thermal strain column: none taken out yet */
    if ((ps->enabled & (1u << PC_THERMAL)) && !(enabled & (1u << PC_THERMAL)) && n)
        memset(ps->col[PC_THERMAL], 0, sizeof(double) * (size_t)n);
    /* nor one saved before the gas vented between the fields' updates: nothing vents until the next (gas.c) */
    if ((ps->enabled & (1u << PC_VENT)) && !(enabled & (1u << PC_VENT)) && n)
        memset(ps->col[PC_VENT], 0, sizeof(double) * (size_t)n);
    /* nor one saved before browning read the air surface: each particle its own until the next field step */
    if ((ps->enabled & (1u << PC_SURFACE)) && !(enabled & (1u << PC_SURFACE)) && n)
        memset(ps->col[PC_SURFACE], 0, sizeof(double) * 2 * (size_t)n);
    /* nor one saved before a share had an amount: nothing made yet (gas.h's gas_share_capped) */
    if ((ps->enabled & (1u << PC_GAS_MADE)) && !(enabled & (1u << PC_GAS_MADE)) && n)
        memset(ps->col[PC_GAS_MADE], 0, sizeof(double) * 2 * (size_t)n);
    *absent = ps->enabled & ~enabled; /* the columns above, zeroed: the file's hash never saw them */
    ps->n = (int)n;
    return 0;
}

static void set_clocks(hearth_scene *s, const ck_clocks *k) {
    s->t = k->t;
    s->dt_last = k->dt_last;
    s->dt_scale = k->dt_scale;
    s->step = (long)k->step;
    s->rollbacks = k->rollbacks;
    s->max_speed = k->max_speed;
    s->c_max = k->c_max;
    s->kinetic = k->kinetic;
    s->kinetic_peak = k->kinetic_peak;
    s->cfl_last = k->cfl_last;
    s->out_of_domain = (long)k->ood;
    s->guard = (hearth_guard_state)k->guard;
    s->rng = k->rng;
    s->next_id = k->next_id;
    s->nbodies = k->nbodies;
    water_restore_lost(&s->water, k->water_lost);
    s->field_acc = k->field_acc;
    s->field_phase = k->field_phase;
    s->field_dt_last = k->field_dt_last;
    s->field_cycle_last = k->field_cycle_last;
    s->self_max = k->self_max;
    if (k->water_limits && water_active(s)) water_restore_limits(&s->water, k->water_dmax, k->water_emax, k->water_lmax);
}

hearth_scene *hearth_scene_load_mem(const void *data, size_t n, const char *name, hearth_error *err) {
    hearth_error local;
    if (!err) err = &local; /* the messages below read err back */
    err_clear(err);
    if (!name) name = "(checkpoint in memory)";
    const uint8_t *b = data;
    if (!b || n < CK_HEADER_SIZE || memcmp(b, CK_MAGIC, 8) != 0)
        return refuse(NULL, err, name, "bad magic (not a checkpoint, or shorter than its 40-byte header)");
    uint32_t version, bom, dsize, hsize;
    uint64_t size;
    memcpy(&version, b + 8, 4);
    memcpy(&bom, b + 12, 4);
    memcpy(&dsize, b + 16, 4);
    memcpy(&hsize, b + 20, 4);
    memcpy(&size, b + CK_OFF_SIZE, 8);
    if (bom != CK_BOM || dsize != sizeof(double))
        return refuse(NULL, err, name, "written on a machine with another byte order or double size");
    if (version < CK_VERSION_MIN || version > CK_VERSION) {
        err_set(err, HEARTH_ERR_FORMAT, "%s: checkpoint version %u; this hearth reads versions %u to %u only (save it "
                "again with the hearth that wrote it is not possible: rerun the scene)", name, version, CK_VERSION_MIN,
                CK_VERSION);
        return NULL;
    }
    if (hsize != CK_HEADER_SIZE) return refuse(NULL, err, name, "header size is not 40");
    if (size != n) {
        err_set(err, HEARTH_ERR_FORMAT, "%s: not a valid hearth checkpoint: the header says %llu bytes, the file has %zu "
                "(truncated or extended)", name, (unsigned long long)size, n);
        return NULL;
    }
    uint32_t crc;
    memcpy(&crc, b + CK_OFF_CRC, 4);
    if (crc != ck_crc(b, n)) return refuse(NULL, err, name, "checksum mismatch (the file is damaged)");
    uint32_t reserved;
    memcpy(&reserved, b + 36, 4);
    if (reserved != 0) return refuse(NULL, err, name, "reserved header field is not 0");

    ck_cursor c = {b + CK_HEADER_SIZE, n - CK_HEADER_SIZE, 0, NULL, {0}};
    hearth_scene_def d = hearth_default_scene_def();
    get_def(&c, &d, version);
    if (c.bad) return refuse_at(NULL, err, name, &c, "scene definition");
    hearth_scene *s = hearth_scene_create(&d, err); /* checks every value and the memory it needs */
    if (!s) return refuse_at(NULL, err, name, &c, "scene definition");
    ck_clocks k;
    get_clocks(&c, &k, version);
    if (c.bad) return refuse_at(s, err, name, &c, "clocks");
    s->nbodies = k.nbodies; /* particle body ids are checked against it */
    if (get_materials(&c, s, name, version, err)) return refuse_at(s, err, name, &c, "materials");
    if (get_colliders(&c, s, version, k.t, err)) return refuse_at(s, err, name, &c, "colliders");
    s->next_id = k.next_id;
    uint32_t absent = 0;
    if (get_particles(&c, s, version, &absent, err)) return refuse_at(s, err, name, &c, "particles");
    get_tag(&c, "HASH", "the particle hash is missing");
    const uint64_t h = get_u64(&c);
    if (c.bad) return refuse_at(s, err, name, &c, "particle hash");
    if (c.left) return refuse(s, err, name, "bytes after the end of the checkpoint");
    /* over the columns the file holds: one its writer did not have (zeroed above) is not in its hash */
    const uint32_t live = s->ps.enabled;
    s->ps.enabled &= ~absent;
    const uint64_t mine = hearth_scene_hash(s);
    s->ps.enabled = live;
    if (h != mine) return refuse(s, err, name, "particle data checksum mismatch (the file is damaged)");
    set_clocks(s, &k); /* last: adding materials and particles above touched them */
    /* before version 11 a sticky face held every node on and inside it: the first step glues the particles
     * whose stencils reach those nodes, so the file means what it meant (mpm_touch.c) */
    if (version < 11) s->glue_legacy = 1;
    return s;
}

hearth_scene *hearth_scene_load(const char *path, hearth_error *err) {
    err_clear(err);
    /* non-blocking open, then fstat: a FIFO or a device named as a checkpoint
     * is refused instead of blocking the open or the read */
    const int fd = open(path, O_RDONLY | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        err_set(err, HEARTH_ERR_IO, "%s: cannot open checkpoint (%s)", path, strerror(errno));
        return NULL;
    }
    struct stat st;
    if (fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
        close(fd);
        err_set(err, HEARTH_ERR_IO, "%s: not a regular file", path);
        return NULL;
    }
    FILE *f = fdopen(fd, "rb");
    if (!f) {
        close(fd);
        err_set(err, HEARTH_ERR_NOMEM, "%s: cannot open checkpoint (%s)", path, strerror(errno));
        return NULL;
    }
    const uint64_t n = (uint64_t)st.st_size;
    /* the header first: its size field must agree before the body is allocated */
    uint8_t head[CK_HEADER_SIZE];
    if (n < CK_HEADER_SIZE || fread(head, CK_HEADER_SIZE, 1, f) != 1) {
        fclose(f);
        return hearth_scene_load_mem(head, n < CK_HEADER_SIZE ? (size_t)n : 0, path, err);
    }
    uint64_t size;
    memcpy(&size, head + CK_OFF_SIZE, 8);
    if (n > CK_FILE_MAX || (memcmp(head, CK_MAGIC, 8) == 0 && size != n)) {
        fclose(f);
        uint32_t version;
        memcpy(&version, head + 8, 4);
        if (memcmp(head, CK_MAGIC, 8) == 0 && (version < CK_VERSION_MIN || version > CK_VERSION))
            return hearth_scene_load_mem(head, sizeof head, path, err);
        if (n > CK_FILE_MAX)
            err_set(err, HEARTH_ERR_FORMAT, "%s: checkpoint of %llu bytes; hearth reads at most %llu", path,
                    (unsigned long long)n, (unsigned long long)CK_FILE_MAX);
        else
            err_set(err, HEARTH_ERR_FORMAT, "%s: not a valid hearth checkpoint: the header says %llu bytes, the file has %llu "
                    "(truncated or extended)", path, (unsigned long long)size, (unsigned long long)n);
        return NULL;
    }
    uint8_t *buf = mem_alloc((size_t)n);
    if (!buf) {
        fclose(f);
        err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory reading a checkpoint of %llu bytes", path, (unsigned long long)n);
        return NULL;
    }
    memcpy(buf, head, CK_HEADER_SIZE);
    const int ok = fread(buf + CK_HEADER_SIZE, (size_t)n - CK_HEADER_SIZE, 1, f) == 1 || n == CK_HEADER_SIZE;
    fclose(f);
    hearth_scene *s = NULL;
    if (ok) s = hearth_scene_load_mem(buf, (size_t)n, path, err);
    else err_set(err, HEARTH_ERR_IO, "%s: read failed", path);
    mem_free(buf, (size_t)n);
    return s;
}

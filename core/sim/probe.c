/* probe.c: fields evaluated at particles, and probes at points, along lines
 * and on plane slices.
 *
 * A probe value is the mass-weighted B-spline average of nearby particles'
 * values (kernel radius 1.5 dx, as the transfers). Where the particles' volume
 * fraction under the kernel is below 1/4 the point is outside the material and
 * the probe returns NaN, which displays as background. A particle that does
 * not carry the quantity (another material's mixing ratio; an SPH bubble's
 * saturation or browning: gas, not dough; `carries`) counts in the volume
 * fraction but not in the average, which is over the particles that carry it
 * (NaN where none does). Averaged in, bubbles at the water floor read a
 * dough's 0.218 as 0.157 beside them (sph_probes_leave_bubbles_out) and
 * browned as dried crust; a mixture's border read NaN. */
#include <math.h>
#include <string.h>

#include "plugins.h"
#include "alloc.h"
#include "error.h"
#include "browning.h"
#include "gas.h"
#include "material.h"
#include "scene.h"
#include "solver.h"
#include "tensor.h"
#include "water.h"

typedef enum field_id {
    F_VELOCITY, F_VX, F_VY, F_VZ, F_SPEED, F_DENSITY, F_J, F_PRESSURE, F_VON_MISES, F_STRESS_XY, F_TEMPERATURE, F_BOUNDARY,
    F_GAS, F_POROSITY, F_GAS_PRESSURE, F_GAS_MADE, F_GAS_MADE_2, F_SATURATION, F_WATER_MASS, F_WATER_PRESSURE, F_BROWNING,
    F_MIX_RATIO, F_STRESS,
    F_SXX, F_SYY, F_SZZ, F_SXZ, F_SYZ, F_DAMAGE, F_BROWNING_T, F_BROWNING_S, F_GAS_LEFT, F_COUNT
} field_id;

/* A field is live when its column is enabled (column -1: always live;
 * COLUMN_DAMAGE: when a material may crack, material_slot.fracture; COLUMN_VENT:
 * in an SPH scene whose cells vent, sph.surface_vent). */
enum { COLUMN_DAMAGE = -2, COLUMN_VENT = -3 };
static const struct {
    const char *name, *unit;
    int ncomp, column;
    const char *how; /* how to make it live */
} fields[F_COUNT] = {
    [F_TEMPERATURE] = {"temperature", "degC", 1, PC_TEMPERATURE,
                       "give a body a temperature (s:add{..., temperature = 20}), the scene an oven, or a material a temperature curve"},
    [F_BOUNDARY] = {"boundary", "1", 1, PC_FLAGS, "turn the temperature or water field on (boundary particles are where heat and water cross)"},
    [F_GAS] = {"gas", "mol/m^3", 1, PC_GAS, "give a material a leavening rate (gas_rate > 0)"},
    [F_POROSITY] = {"porosity", "1", 1, PC_GAS, "give a material a leavening rate (gas_rate > 0)"},
    [F_GAS_PRESSURE] = {"gas_pressure", "Pa", 1, PC_GAS, "give a material a leavening rate (gas_rate > 0)"},
    /* the CO2 each share has made so far, against its amount (gas.h's gas_share_capped) */
    [F_GAS_MADE] = {"gas_made", "mol/kg", 1, PC_GAS_MADE, "give a material's CO2 share an amount (gas_amount > 0)"},
    [F_GAS_MADE_2] = {"gas_made_2", "mol/kg", 1, PC_GAS_MADE, "give a material's CO2 share an amount (gas_amount_2 > 0)"},
    [F_MIX_RATIO] = {"mixing_ratio", "1", 1, PC_MIXD,
                     "make a dynamic mixture (h.scene{mixing = \"dynamic\"} with h.mix bodies); this is its first constituent's ratio"},
    [F_SATURATION] = {"saturation", "1", 1, PC_WATER,
                      "give a body a saturation (s:add{..., saturation = 0.5}) or a material water_diffusivity, evaporation or water_stiffness"},
    [F_WATER_MASS] = {"water_mass", "kg/m^3", 1, PC_WATER,
                      "give a body a saturation (s:add{..., saturation = 0.5}) or a material water_diffusivity, evaporation or water_stiffness"},
    [F_WATER_PRESSURE] = {"water_pressure", "Pa", 1, PC_WATER,
                          "give a body a saturation (s:add{..., saturation = 0.5}) or a material water_diffusivity, evaporation or water_stiffness"},
    [F_VELOCITY] = {"velocity", "m/s", 3, -1, NULL},   [F_VX] = {"velocity_x", "m/s", 1, -1, NULL},
    [F_VY] = {"velocity_y", "m/s", 1, -1, NULL},       [F_VZ] = {"velocity_z", "m/s", 1, -1, NULL},
    [F_SPEED] = {"speed", "m/s", 1, -1, NULL},         [F_DENSITY] = {"density", "kg/m^3", 1, -1, NULL},
    [F_J] = {"J", "1", 1, -1, NULL},                   [F_PRESSURE] = {"pressure", "Pa", 1, -1, NULL},
    [F_VON_MISES] = {"von_mises", "Pa", 1, -1, NULL},
    [F_BROWNING] = {"browning", "1", 1, PC_BROWNING,
                    "set browning = true in the scene (h.scene{browning = true}: Zanoni et al. 1995 kinetics, either solver)"},
    [F_STRESS_XY] = {"stress_xy", "Pa", 1, -1, NULL}, /* Cauchy shear stress: what a rheometer measures */
    /* 0 intact .. 1 cracked (<hearth/material.h> damage): the plugin's own state, nothing stored by the core */
    [F_DAMAGE] = {"damage", "1", 1, COLUMN_DAMAGE,
                  "give a material that can crack a strain to fracture (cam_clay_dough's fracture_strain > 0)"},
    /* The whole Cauchy stress, row-major xx xy xz yx yy yz zx zy zz (tension
     * positive): VTK reads 9 components as a tensor, which ParaView's tensor
     * filters (eigenvalues, glyphs) expect. The six scalar components are for
     * slices and pictures; like velocity_x they are not listed as live fields
     * (stress_xy was, before the tensor), so a dump carries the tensor once. */
    [F_STRESS] = {"stress", "Pa", 9, -1, NULL},
    [F_SXX] = {"stress_xx", "Pa", 1, -1, NULL},       [F_SYY] = {"stress_yy", "Pa", 1, -1, NULL},
    [F_SZZ] = {"stress_zz", "Pa", 1, -1, NULL},       [F_SXZ] = {"stress_xz", "Pa", 1, -1, NULL},
    [F_SYZ] = {"stress_yz", "Pa", 1, -1, NULL},
    /* what the crust's colour read in the last step (browning.c's browning_reading): the surface's temperature and
     * saturation on the oven's air surface (MPM), an SPH outer particle's face, else the particle's own. Not listed
     * (no dump or dashboard carries them): a diagnostic for the crust's history (#18, helper crustdry) */
    [F_BROWNING_T] = {"browning_temperature", "degC", 1, PC_BROWNING,
                      "set browning = true in the scene (h.scene{browning = true}); the saturation also needs water"},
    [F_BROWNING_S] = {"browning_saturation", "1", 1, PC_BROWNING,
                      "set browning = true in the scene (h.scene{browning = true}); the saturation also needs water"},
    /* the share of an SPH bubble's own gas still in its cell (sph_gas.c's vent(): 1 until its cell opens to the air,
     * never rising after); NaN on the dough, which holds no gas (#18, helper ventrock) */
    [F_GAS_LEFT] = {"gas_left", "1", 1, COLUMN_VENT, "set sph.surface_vent = true (SPH with sph.gas_law)"},
};

/* Scalar fields that are one component of a listed field, and browning's readings (diagnostics): not listed
 * themselves. */
static int field_is_component(int f) {
    return f == F_VX || f == F_VY || f == F_VZ || f == F_STRESS_XY || (f >= F_SXX && f <= F_SYZ) || f == F_BROWNING_T ||
           f == F_BROWNING_S;
}

static int field_lookup(const char *name) {
    for (int f = 0; f < F_COUNT; f++)
        if (strcmp(fields[f].name, name) == 0) return f;
    return -1;
}

int hearth_field_components(const char *field) {
    int f = field_lookup(field);
    return f < 0 ? 0 : fields[f].ncomp;
}

const char *hearth_field_unit(const char *field) {
    int f = field_lookup(field);
    return f < 0 ? NULL : fields[f].unit;
}

/* The solver's own per-particle results of the last step (sph.c's summed
 * density and Tait pressure), or NULL. */
static const double *solver_values(const hearth_scene *s, const char *which) {
    return s->solver->particle_values ? s->solver->particle_values(s, which) : NULL;
}

static int field_live(const hearth_scene *s, int f) {
    if (fields[f].column == COLUMN_DAMAGE) {
        for (int m = 0; m < s->mats.n; m++)
            if (s->mats.slot[m].fracture) return 1;
        return 0;
    }
    if (fields[f].column == COLUMN_VENT) return s->def.sph.surface_vent; /* sph.c allocates gasleft then */
    return fields[f].column < 0 || (s->ps.enabled & (1u << fields[f].column));
}

const char *hearth_scene_fields(const hearth_scene *s) {
    hearth_scene *m = (hearth_scene *)s; /* the string is a cache of the enabled columns */
    m->fields[0] = '\0';
    for (int f = 0; f < F_COUNT; f++) {
        if (field_is_component(f) || !field_live(s, f)) continue;
        if (m->fields[0]) strncat(m->fields, " ", sizeof m->fields - strlen(m->fields) - 1);
        strncat(m->fields, fields[f].name, sizeof m->fields - strlen(m->fields) - 1);
    }
    return m->fields;
}

static hearth_status find_field(const hearth_scene *s, const char *field, int scalar_only, int *out, hearth_error *err) {
    int f = field_lookup(field);
    if (f < 0)
        return err_set(err, HEARTH_ERR_PARAM, "unknown field '%s'; live fields: %s (vector components as velocity_x, _y, _z)",
                       field, hearth_scene_fields(s));
    if (!field_live(s, f))
        return err_set(err, HEARTH_ERR_PARAM, "field '%s' is not live in this scene; to enable it, %s", field, fields[f].how);
    if (scalar_only && fields[f].ncomp == 9)
        return err_set(err, HEARTH_ERR_PARAM,
                       "field '%s' has 9 components; slice one of them (%s_xx, %s_yy, %s_zz, %s_xy, %s_xz, %s_yz)", field,
                       field, field, field, field, field, field);
    if (scalar_only && fields[f].ncomp != 1)
        return err_set(err, HEARTH_ERR_PARAM, "field '%s' has %d components; slice one of them (%s_x, %s_y, %s_z)", field,
                       fields[f].ncomp, field, field, field);
    *out = f;
    return HEARTH_OK;
}

/* Stress for display: the plugin evaluates with dt = 0 on a copy of the state,
 * so looking never changes the simulation. */
static void particle_stress(const hearth_scene *s, int i, double tau[9], double *state_copy) {
    const particles *ps = &s->ps;
    const int m = pcoli(ps, PC_MAT)[i];
    const material_slot *ms = &s->mats.slot[m];
    hearth_point pt;
    particles_C3(ps, i, pt.grad_v);
    particles_F3(ps, i, pt.F);
    pt.dt = 0;
    double pscratch[SCENE_MAX_PARAMS];
    pt.p = material_params(&s->mats, &s->ps, m, i, pscratch);
    pt.state = NULL;
    if (ps->state_stride) {
        memcpy(state_copy, pcold(ps, PC_STATE) + (size_t)i * ps->state_stride, sizeof(double) * (size_t)ps->state_stride);
        pt.state = state_copy;
    }
    /* The plugin's own stress, as it has always been shown: the porosity from
     * J^P whatever the material declares, and none of the core's coupling
     * terms (the pressure fields show those). A non-finite tau is shown as is. */
    const material_env env = {
        .flags = MATERIAL_POROSITY_PLASTIC,
        .temperature = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE)[i] : NAN,
        .saturation = ps->enabled & (1u << PC_WATER) ? water_saturation(s, i) : NAN,
        .dim = s->def.dim, /* <hearth/material.h> rule 8 */
    };
    const int rc = material_point_eval(ms->m, ms->core, &pt, &env, tau);
    plugin_call_leave();
    if (rc > 0) {
        for (int k = 0; k < 9; k++) tau[k] = NAN;
    }
}

/* Whether particle i carries field f. An SPH bubble is gas: it holds no
 * liquid water and has no crust to brown (fields/water.c water_sph_gas); a
 * mixing ratio is its mixture's. A particle that does not carry a field has
 * the value NaN, and probes leave it out of their average (the header). A NaN
 * from a particle that does carry it (a plugin that failed to evaluate its
 * stress) stays in, and shows. */
static int gas_particle(const hearth_scene *s, int i) {
    return water_sph_gas(s, &s->mats.slot[pcoli(&s->ps, PC_MAT)[i]]);
}

static int carries(const hearth_scene *s, int f, int i) {
    if (f == F_SATURATION || f == F_BROWNING || f == F_BROWNING_T || f == F_BROWNING_S) return !gas_particle(s, i);
    if (f == F_MIX_RATIO) return pcoli(&s->ps, PC_MAT)[i] == s->mix.mat;
    if (f == F_GAS_LEFT) return s->mats.slot[pcoli(&s->ps, PC_MAT)[i]].core[CP_BUBBLE] > 0;
    return 1;
}

static void particle_value(const hearth_scene *s, int f, int i, double *out, double *state_copy) {
    const particles *ps = &s->ps;
    const double *v = pcold(ps, PC_V) + 3 * i, J = particles_J(ps, i);
    if (f == F_BOUNDARY) { /* SPH: the particles on the body's outer surface, where eq. 3.42's oven heat enters */
        const double *sv = solver_values(s, "outer");
        if (sv) {
            out[0] = sv[i];
            return;
        }
    }
    if (f == F_DENSITY || f == F_PRESSURE) { /* SPH: the summed density (eq. 3.13) and the Tait pressure that move it */
        const double *sv = solver_values(s, f == F_DENSITY ? "density" : "pressure");
        if (sv) {
            out[0] = sv[i];
            return;
        }
    }
    if (f == F_GAS_LEFT) { /* a bubble's cell that has not vented reads NaN in sph_gas.c: all its gas, 1 */
        const double *g = solver_values(s, "gasleft");
        out[0] = !g || !carries(s, f, i) ? NAN : g[i] > 0 && g[i] <= 1 ? g[i] : 1.0;
        return;
    }
    switch (f) {
    case F_VELOCITY: memcpy(out, v, 3 * sizeof(double)); break;
    case F_VX: case F_VY: case F_VZ: out[0] = v[f - F_VX]; break;
    case F_SPEED: out[0] = sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); break;
    case F_DENSITY: out[0] = pcold(ps, PC_MASS)[i] / (pcold(ps, PC_VOL0)[i] * J); break;
    case F_J: out[0] = J; break;
    case F_TEMPERATURE: out[0] = pcold(ps, PC_TEMPERATURE)[i]; break;
    case F_BOUNDARY: out[0] = (pcoli(ps, PC_FLAGS)[i] & PF_BOUNDARY) ? 1.0 : 0.0; break;
    case F_GAS: out[0] = pcold(ps, PC_GAS)[i]; break;
    case F_GAS_MADE: case F_GAS_MADE_2: out[0] = pcold(ps, PC_GAS_MADE)[2 * i + (f == F_GAS_MADE_2)]; break;
    case F_SATURATION: out[0] = carries(s, f, i) ? water_saturation(s, i) : NAN; break;
    case F_MIX_RATIO: /* NaN on other materials' particles: they are not part of the mixture */
        out[0] = carries(s, f, i) ? pcold(ps, PC_MIXD)[8 * i] : NAN;
        break;
    case F_WATER_MASS: /* as a density: water mass over the particle's current volume */
        out[0] = pcold(ps, PC_WATER)[i] / (pcold(ps, PC_VOL0)[i] * J);
        break;
    case F_WATER_PRESSURE: /* p^w = c (s - s_0), compression positive (eq. 14) */
        out[0] = s->mats.slot[pcoli(ps, PC_MAT)[i]].core[CP_WATER_STIFFNESS] * (water_saturation(s, i) - pcold(ps, PC_SAT0)[i]);
        break;
    case F_BROWNING: out[0] = carries(s, f, i) ? pcold(ps, PC_BROWNING)[i] : NAN; break; /* Delta E / 52 (browning.c) */
    case F_BROWNING_T: case F_BROWNING_S: {
        double T = NAN, sat = NAN;
        if (carries(s, f, i)) browning_reading(s, i, &T, &sat);
        out[0] = f == F_BROWNING_T ? T : sat;
        break;
    }
    case F_DAMAGE: {
        const int m = pcoli(ps, PC_MAT)[i];
        const material_slot *ms = &s->mats.slot[m];
        out[0] = 0;
        if (ms->m->damage) {
            double pscratch[SCENE_MAX_PARAMS];
            plugin_call_enter(ms->m, "damage");
            out[0] = ms->m->damage(material_params(&s->mats, &s->ps, m, i, pscratch),
                                   ps->state_stride ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL);
            plugin_call_leave();
        }
        break;
    }
    case F_POROSITY:
    case F_GAS_PRESSURE: {
        const int m = pcoli(ps, PC_MAT)[i];
        const material_slot *ms = &s->mats.slot[m];
        double pscratch[SCENE_MAX_PARAMS];
        const double *st = ps->state_stride ? pcold(ps, PC_STATE) + (size_t)i * ps->state_stride : NULL;
        double JP = 1.0;
        if (ms->m->plastic_J) {
            plugin_call_enter(ms->m, "plastic_J");
            JP = ms->m->plastic_J(material_params(&s->mats, &s->ps, m, i, pscratch), st);
            plugin_call_leave();
        }
        const double np = gas_porosity(JP, ms->core[CP_POROSITY0]);
        out[0] = f == F_POROSITY ? np : -material_gas_tau(ms, ps, i, pcold(ps, PC_GAS)[i], pcold(ps, PC_TEMPERATURE)[i], np, J) / J;
        break;
    }
    default: {
        double tau[9];
        particle_stress(s, i, tau, state_copy);
        double sig[9];
        for (int k = 0; k < 9; k++) sig[k] = tau[k] / J;
        const double p = -(sig[0] + sig[4] + sig[8]) / 3.0;
        if (f == F_PRESSURE) {
            out[0] = p;
        } else if (f == F_STRESS) {
            memcpy(out, sig, sizeof sig);
        } else if (f >= F_SXX && f <= F_SYZ) { /* symmetric parts, as stress_xy */
            static const int r[] = {0, 1, 2, 0, 1}, c[] = {0, 1, 2, 2, 2};
            const int k = f - F_SXX;
            out[0] = 0.5 * (sig[3 * r[k] + c[k]] + sig[3 * c[k] + r[k]]);
        } else if (f == F_STRESS_XY) {
            out[0] = 0.5 * (sig[1] + sig[3]);
        } else { /* q = sqrt(3/2 s:s), s the deviatoric Cauchy stress */
            double ss = 0;
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++) {
                    double d = sig[3 * r + c] + (r == c ? p : 0.0);
                    ss += d * d;
                }
            out[0] = sqrt(1.5 * ss);
        }
    }
    }
}

hearth_status hearth_scene_particle_field(const hearth_scene *s, const char *field, double *out, hearth_error *err) {
    int f = 0;
    hearth_status st = find_field(s, field, 0, &f, err);
    if (st) return st;
    const int nc = fields[f].ncomp, stride = s->ps.state_stride;
    double *copy = stride ? mem_alloc(sizeof(double) * (size_t)stride) : NULL;
    if (stride && !copy) return err_set(err, HEARTH_ERR_NOMEM, "out of memory evaluating '%s'", field);
    for (int i = 0; i < s->ps.n; i++) particle_value(s, f, i, out + (size_t)i * nc, copy);
    mem_free(copy, sizeof(double) * (size_t)stride);
    return HEARTH_OK;
}

/* Accumulate particle values onto sample points. Samples are given as a
 * regular lattice: origin + a*ea + b*eb for a_first <= a < a_first + na, b < nb (a line is nb = 1), stored from
 * a = a_first on. A band of a slice's rows (a_first > 0) is the very samples of the whole slice's, summed in the same
 * order: render.c fills a picture band by band and draws the same pixels. */
typedef struct lattice {
    double origin[3], ea[3], eb[3];
    int na, nb, a_first;
} lattice;

/* frac, when not NULL, receives each sample's volume fraction under the kernel (the material test's number) */
static hearth_status splat(const hearth_scene *s, int f, const lattice *L, double *out, double *frac, hearth_error *err) {
    const particles *ps = &s->ps;
    const int D = s->def.dim, nc = fields[f].ncomp, ns = L->na * L->nb;
    const double dx = s->def.dx, r = 1.5 * dx, cellv = pow(dx, D);
    double *acc = mem_calloc(sizeof(double) * (size_t)ns * (size_t)(nc + 2));
    double *copy = ps->state_stride ? mem_alloc(sizeof(double) * (size_t)ps->state_stride) : NULL;
    if (!acc || (ps->state_stride && !copy)) {
        mem_free(acc, sizeof(double) * (size_t)ns * (size_t)(nc + 2));
        mem_free(copy, sizeof(double) * (size_t)ps->state_stride);
        return err_set(err, HEARTH_ERR_NOMEM, "out of memory for a probe of %d samples", ns);
    }
    const double la2 = L->ea[0] * L->ea[0] + L->ea[1] * L->ea[1] + L->ea[2] * L->ea[2];
    const double lb2 = L->eb[0] * L->eb[0] + L->eb[1] * L->eb[1] + L->eb[2] * L->eb[2];
    const double *X = pcold(ps, PC_X);
    /* A line (or a point): a particle weighs on a sample only within 1.5 dx of it on every axis, so within
     * 1.5 dx sqrt(D) of the line; one farther is passed over before its weights are made (they would all be 0:
     * the same sums). A line probe had walked every particle's stencil (pull_twist's neck: thousands a frame). */
    const int line = L->nb == 1;
    const double reach2 = 2.25 * dx * dx * D;
    for (int i = 0; i < ps->n; i++) {
        const double *x = X + 3 * i;
        /* candidate sample range: project onto the lattice axes (they are orthogonal) */
        double rel[3] = {x[0] - L->origin[0], x[1] - L->origin[1], x[2] - L->origin[2]};
        if (line) {
            const double t = la2 > 0 ? (rel[0] * L->ea[0] + rel[1] * L->ea[1] + rel[2] * L->ea[2]) / la2 : 0.0;
            double q2 = 0;
            for (int d = 0; d < D; d++) {
                const double e = rel[d] - t * L->ea[d];
                q2 += e * e;
            }
            if (q2 > reach2 * (1 + 1e-9)) continue;
        }
        int a0 = L->a_first, a1 = L->a_first + L->na - 1, b0 = 0, b1 = L->nb - 1;
        if (la2 > 0) {
            double ta = (rel[0] * L->ea[0] + rel[1] * L->ea[1] + rel[2] * L->ea[2]) / la2, ra = r / sqrt(la2);
            a0 = (int)fmax(L->a_first, ceil(ta - ra));
            a1 = (int)fmin(L->a_first + L->na - 1, floor(ta + ra));
        }
        if (lb2 > 0) {
            double tb = (rel[0] * L->eb[0] + rel[1] * L->eb[1] + rel[2] * L->eb[2]) / lb2, rb = r / sqrt(lb2);
            b0 = (int)fmax(0, ceil(tb - rb));
            b1 = (int)fmin(L->nb - 1, floor(tb + rb));
        }
        if (a0 > a1 || b0 > b1) continue;
        double val[9];
        int have = 0;
        const int carried = carries(s, f, i);
        const double m = pcold(ps, PC_MASS)[i], V = pcold(ps, PC_VOL0)[i] * particles_J(ps, i);
        for (int a = a0; a <= a1; a++)
            for (int b = b0; b <= b1; b++) {
                double w = 1;
                for (int d = 0; d < D; d++) {
                    double p = L->origin[d] + a * L->ea[d] + b * L->eb[d];
                    double q = fabs(x[d] - p) / dx;
                    w *= q < 0.5 ? 0.75 - q * q : (q < 1.5 ? 0.5 * (1.5 - q) * (1.5 - q) : 0.0);
                }
                if (w <= 0) continue;
                if (!have && carried) {
                    particle_value(s, f, i, val, copy);
                    have = 1;
                }
                double *A = acc + (size_t)((a - L->a_first) * L->nb + b) * (nc + 2);
                A[0] += w * V / cellv;
                if (!carried) continue; /* present, but without the quantity (the header) */
                A[1] += w * m;
                for (int k = 0; k < nc; k++) A[2 + k] += w * m * val[k];
            }
    }
    for (int q = 0; q < ns; q++) {
        const double *A = acc + (size_t)q * (nc + 2);
        for (int k = 0; k < nc; k++) out[(size_t)q * nc + k] = A[0] >= 0.25 && A[1] > 0 ? A[2 + k] / A[1] : NAN;
        if (frac) frac[q] = A[0];
    }
    mem_free(acc, sizeof(double) * (size_t)ns * (size_t)(nc + 2));
    mem_free(copy, sizeof(double) * (size_t)ps->state_stride);
    return HEARTH_OK;
}

hearth_status hearth_probe_point(const hearth_scene *s, const char *field, const double x[3], double *out, hearth_error *err) {
    int f = 0;
    hearth_status st = find_field(s, field, 0, &f, err);
    if (st) return st;
    lattice L = {.na = 1, .nb = 1};
    memcpy(L.origin, x, sizeof L.origin);
    if (s->def.dim == 2) L.origin[2] = 0;
    return splat(s, f, &L, out, NULL, err);
}

hearth_status hearth_probe_line(const hearth_scene *s, const char *field, const double a[3], const double b[3], int n,
                                double *out, hearth_error *err) {
    int f = 0;
    hearth_status st = find_field(s, field, 0, &f, err);
    if (st) return st;
    if (n < 2 || n > 1000000) return err_set(err, HEARTH_ERR_PARAM, "line probe: n = %d samples; valid range [2, 1000000]", n);
    lattice L = {.na = n, .nb = 1};
    for (int d = 0; d < 3; d++) {
        L.origin[d] = a[d];
        L.ea[d] = (b[d] - a[d]) / (n - 1);
    }
    if (s->def.dim == 2) L.origin[2] = L.ea[2] = 0;
    return splat(s, f, &L, out, NULL, err);
}

hearth_status hearth_probe_slice(const hearth_scene *s, const char *field, int axis, double at, int w, int h, double *out,
                                 hearth_error *err) {
    return probe_slice_fraction(s, field, axis, at, NULL, w, h, out, NULL, err);
}

hearth_status probe_slice_fraction(const hearth_scene *s, const char *field, int axis, double at, const double rect[4], int w,
                                   int h, double *out, double *frac, hearth_error *err) {
    return probe_slice_rows(s, field, axis, at, rect, w, h, 0, h, out, frac, err);
}

hearth_status probe_slice_rows(const hearth_scene *s, const char *field, int axis, double at, const double rect[4], int w,
                               int h, int row0, int rows, double *out, double *frac, hearth_error *err) {
    int f = 0;
    hearth_status st = find_field(s, field, 1, &f, err);
    if (st) return st;
    if (w < 1 || h < 1 || (long)w * h > 64L * 1024 * 1024)
        return err_set(err, HEARTH_ERR_PARAM, "slice: %d x %d samples; each side must be >= 1 and the total <= 67108864", w, h);
    if (axis < 0 || axis > 2) return err_set(err, HEARTH_ERR_PARAM, "slice: axis %d; valid: 0 (x), 1 (y), 2 (z)", axis);
    if (s->def.dim == 2 && axis != 2) return err_set(err, HEARTH_ERR_PARAM, "slice: a 2D scene has only the z slice (axis 2)");
    HEARTH_ASSERT(row0 >= 0 && rows >= 1 && row0 + rows <= h); /* render.c's bands lie inside the slice */
    const int u = axis == 0 ? 1 : 0, v = axis == 2 ? 1 : 2; /* in-plane axes: columns along u, rows along v */
    double lo[3], hi[3];
    memcpy(lo, s->def.lo, sizeof lo), memcpy(hi, s->def.hi, sizeof hi);
    if (rect) lo[u] = rect[0], lo[v] = rect[1], hi[u] = rect[2], hi[v] = rect[3]; /* a picture's region */
    /* rows are sampled along v, columns along u: out[row*w + col], row 0 at the low end of v */
    lattice L = {.na = rows, .nb = w, .a_first = row0};
    L.origin[axis] = s->def.dim == 2 ? 0 : at;
    L.origin[u] = lo[u] + 0.5 * (hi[u] - lo[u]) / w;
    L.origin[v] = lo[v] + 0.5 * (hi[v] - lo[v]) / h;
    L.eb[u] = (hi[u] - lo[u]) / w;
    L.ea[v] = (hi[v] - lo[v]) / h;
    return splat(s, f, &L, out, frac, err);
}

double hearth_scene_volume(const hearth_scene *s) {
    const particles *ps = &s->ps;
    double v = 0;
    for (int i = 0; i < ps->n; i++) v += pcold(ps, PC_VOL0)[i] * particles_J(ps, i);
    return v;
}

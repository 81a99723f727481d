/* browning.c: a per-particle browning index from temperature and water
 * history, the same in both solvers.
 *
 * The index is b = Delta E / Delta E_inf in [0, 1], Delta E the colour
 * difference (CIE Lab distance) between the raw dough and the crust. Zanoni,
 * Peri & Bruno (1995, LWT 28, 604-609; the Rodriguez-Arenas thesis's [89])
 * measured it on dried crumb pressed to a plate at 140-250 degC and found
 * first-order kinetics:
 *   d(Delta E)/dt = k (Delta E_inf - Delta E),  k = k0 exp(-Ea / (R theta)),
 *   Delta E_inf = 52, k0 = 42000 1/s, Ea = 64151 J/mol,
 * so at a constant temperature b(t) = 1 - exp(-k t). Multiply by 52 for
 * Delta E. At 200 degC k = 3.5e-3 1/s (b = 0.98 after a 20 minute bake); at
 * 100 degC, the wet crumb's plateau, k = 4.4e-5 1/s (b = 0.05): a crumb stays
 * pale because its temperature history never leaves the boiling plateau, not
 * because we tell it to.
 *
 * Water. The kinetics were measured on dried crumb, and Maillard browning
 * needs a low water activity (Purlis 2010, J. Food Eng. 99, 239-249, reviews
 * it); Zanoni et al. apply it to the crust once it has dried. When the water
 * field is live we multiply the rate by 1 - s/s_0 (s the particle's
 * saturation, s_0 its initial one): the full rate for a dry particle, none
 * for one as wet as the raw dough. The linear map is our choice, the
 * simplest that has those two ends; it is not a measured law. Without the
 * water field the factor is 1. An SPH bubble is gas, with no crust of its
 * own: it does not brown (its index stays 0, and probes leave it out), where
 * its water at the floor had browned it as dried crust.
 *
 * The air surface (MPM with an oven; issue #18, helper surfacecolour). Colour
 * is a property of the surface, and a particle on the oven's air surface
 * (PF_BOUNDARY with an oven coefficient: find_boundary in thermal.c) is not
 * at it: the grid samples its temperature d ~ 0.57 dx deep (boundary.c's
 * sample_depth), and the crust is a few mm thick. The oven's flux already
 * defines the surface's temperature, q = beta (T_o - T_s) = beta (T_o - th) /
 * (1 + beta d / kappa(w)), th the nodes' value at the particle; browning reads
 * that T_s (thermal_surface_temperature: the same d and kappa(w)) and the
 * surface's saturation by the evaporation's closure (water_surface_saturation:
 * the same d, water_surface_excess) in the water factor. Why the surface and
 * not the particle's own depth: what the claims and a camera see is the
 * surface; the slab of tests/unit_drying_front.c browns its top 0.224, 0.255,
 * 0.265 at 4, 2, 1 mm against the Stefan form's surface's 0.282 (before:
 * 0.183, 0.206, 0.241, the particle's own). Why the nodes' th and not the
 * particle's own temperature: a dried particle's own (FLIP, subcell.c's fit
 * at its place) stands nearer its own, shallower depth than the sample's d,
 * and with it the slab's surface read 9.2, 2.0, 1.1 K hot at 4, 2, 1 mm and
 * browned 0.325 at 4 mm (with th: 0.1, 1.2, 1.1 K). Why the surface's water:
 * the loaf's top evaporates through a layer the closure resolves, so its
 * surface is dry long before its particle is (loaf 25 min, 5 / 2.5 mm: top
 * 0.147 / 0.157 with it, 0.082 / 0.135 with the particle's own water).
 * The rows under the outer one: boundary.c spreads the air area over the
 * ramp, up to 2.5 cells in, and read at the surface those rows browned as the
 * top (the drying slab at 2 mm: 0.250, 0.236 at 1.5, 2.5 mm against the form's
 * 0.158, 0.101 there), and at the loaf's 5 mm, where the closure's surface
 * water is drier for a deeper sample, more than the top: a brown ring a cell
 * under a paler skin. So each particle reads the two profiles (T linear, s^2
 * linear) BOUNDARY_OUTER_DEPTH dx above its sample: the outer row (d ~ d0)
 * at the surface, deeper rows nearer their own sample (the slab: 0.204,
 * 0.140; the loaf's ring gone). A particle by a heated
 * collider's face keeps its own temperature (the loaf's base on its tray:
 * the contact is not the air's closure). The offsets (T_s - T, s_s - s) are
 * found on the steps that carry the fields, where the boundary arrays follow
 * the particle order, and kept in PC_SURFACE for the steps between (saved in
 * checkpoints, version 9). Without an oven nothing changes.
 *
 * SPH (helper sphsurface): an outer particle (sph_outer.c, where the oven's heat enters) browns at its face's
 * temperature by the same air-film closure (thermal.h's thermal_face_temperature), its centre half its spacing
 * under the face (sph_heat.c's sph_surface_temperatures, handed over as the solver's "surface_temperature"
 * values). Its water factor stays the particle's own (SPH has no surface-water closure). Interior particles
 * keep their own temperature.
 *
 * Integration. Over a step the temperature is taken as constant (its value
 * at the end of the step) and b advances exactly: b <- 1 - (1 - b)
 * exp(-k f dt). At constant temperature this reproduces the closed form to
 * rounding for any dt, and b never leaves [0, 1] nor decreases: a crust that
 * cools keeps its colour (history, not current temperature).
 *
 * Rejected: the SPH value of Rodriguez-Arenas eq. 4.5-4.6 (a texture
 * coordinate linear in the present temperature, smoothed over neighbours),
 * which sph.c used before; it browns the whole cake as it warms and pales it
 * as it cools. Eq. 4.5's smoothing belongs to the renderer of a surface mesh,
 * which hearth does not build; probes already average particles.
 *
 * browning_scale multiplies k: a scene whose heat runs N times faster than
 * physical time (Ding et al.'s Table 2 units) sets N so that the crust
 * browns over the same part of the bake. */
#include "browning.h"

#include <math.h>

#include "boundary.h"
#include "scene.h"
#include "solver.h"
#include "thermal.h"
#include "water.h"

double browning_rate(double T, double scale) {
    const double theta = T + KELVIN;
    if (!(theta > 0)) return 0;
    return scale * BROWNING_K0 * exp(-BROWNING_EA / (BROWNING_R * theta));
}

double browning_water_factor(double sat, double sat0) {
    /* a body given no water starts at water.c's floor: it is dry, not as wet as its dough */
    if (!(sat0 > 2 * WATER_SATURATION_FLOOR)) return 1;
    const double f = 1 - sat / sat0;
    return f < 0 ? 0 : f > 1 ? 1 : f;
}

double browning_advance(double b, double kf, double dt) {
    /* 1 - b decays: -expm1 keeps small increments exact */
    return b - (1 - b) * expm1(-kf * dt);
}

/* On a step that carried the fields, each particle's surface offsets (PC_SURFACE): the air surface's
 * temperature and saturation above its own, by the oven's and the evaporation's closures (thermal.c's
 * thermal_surface_temperature, water.c's water_surface_saturation: the depth boundary.c found this step, the
 * particle's kappa(w) and material), 0 for a particle off the oven's air surface. Kept for the steps until the
 * next field step, when the boundary arrays no longer follow the particles' order (the sort). */
static void surface_offsets(hearth_scene *s) {
    const particles *ps = &s->ps;
    const int n = ps->n, wet = (ps->enabled & (1u << PC_WATER)) != 0;
    const double *T = pcold(ps, PC_TEMPERATURE);
    double *o = pcold(ps, PC_SURFACE);
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        double th = NAN;
        const double Ts = thermal_surface_temperature(s, i, &th);
        if (isnan(Ts)) {
            o[2 * i] = o[2 * i + 1] = 0.0;
            continue;
        }
        /* the closures' profiles (T linear, s^2 linear: D = K theta s, eq. 22) from the surface down to the
         * sample at depth d, read d0 above the sample: the outer row (d ~ d0) at the surface, a deeper row
         * nearer its own sample, so the colour falls with depth across the rows that hold area */
        const double d = s->boundary.depth[i], d0 = BOUNDARY_OUTER_DEPTH * s->g.dx;
        const double z = d > d0 ? (d - d0) / d : 0.0; /* the reading's depth as a share of d */
        o[2 * i] = Ts + (th - Ts) * z - T[i];
        if (wet) {
            const double sp = water_saturation(s, i), ss = water_surface_saturation(s, i, sp);
            const double s2 = ss * ss + (sp * sp - ss * ss) * z;
            o[2 * i + 1] = (s2 > 0 ? sqrt(s2) : 0.0) - sp;
        } else {
            o[2 * i + 1] = 0.0;
        }
    }
}

/* What particle i browns at (browning_step and browning_reading, so a probe shows what the kinetics read): on
 * the oven's air surface (o, MPM) its surface's temperature and saturation, at an SPH outer particle (ts) its
 * face's temperature and its own saturation, else its own; *sat is left alone without water. */
static inline void reading(const hearth_scene *s, const double *o, const double *ts, int wet, int i, double *T,
                           double *sat) {
    const double Ti = pcold(&s->ps, PC_TEMPERATURE)[i];
    if (o && (o[2 * i] != 0.0 || o[2 * i + 1] != 0.0)) { /* on the oven's air surface: its surface's colour */
        *T = Ti + o[2 * i];
        if (wet) *sat = water_saturation(s, i) + o[2 * i + 1];
        return;
    }
    *T = ts && !isnan(ts[i]) ? ts[i] : Ti;
    if (wet) *sat = water_saturation(s, i);
}

/* the surface offsets (MPM with an oven: scene.c) and a solver's own face temperatures (SPH's outer particles,
 * sph_heat.c: NaN off them), or NULL */
static const double *surface_of(const hearth_scene *s) {
    return (s->ps.enabled & (1u << PC_SURFACE)) ? pcold(&s->ps, PC_SURFACE) : NULL;
}
static const double *faces_of(const hearth_scene *s) {
    return s->solver->particle_values ? s->solver->particle_values(s, "surface_temperature") : NULL;
}

void browning_reading(const hearth_scene *s, int i, double *T, double *sat) {
    const int wet = (s->ps.enabled & (1u << PC_WATER)) != 0;
    *sat = NAN;
    reading(s, surface_of(s), faces_of(s), wet, i, T, sat);
}

void browning_step(hearth_scene *s, double dt) {
    const particles *ps = &s->ps;
    const int n = ps->n;
    double *b = pcold(ps, PC_BROWNING);
    const int wet = (ps->enabled & (1u << PC_WATER)) != 0;
    const double *sat0 = wet ? pcold(ps, PC_SAT0) : NULL;
    const double scale = s->def.browning_scale;
    const int *mat = pcoli(ps, PC_MAT);
    const double *o = surface_of(s);
    if (o && !s->field_skip) surface_offsets(s);
    const double *ts = faces_of(s);
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        if (water_sph_gas(s, &s->mats.slot[mat[i]])) continue; /* an SPH bubble is gas: no crust of its own */
        double T, sat = 0.0;
        reading(s, o, ts, wet, i, &T, &sat);
        const double f = wet ? browning_water_factor(sat, sat0[i]) : 1.0;
        b[i] = browning_advance(b[i], browning_rate(T, scale) * f, dt);
    }
}

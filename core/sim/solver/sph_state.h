/* sph_state.h: what the SPH solver's files share, and only they (private
 * to solver/sph*.c): struct sph_state, the particle columns a phase reads,
 * and what each file lends the step. sph.c runs the step's phases;
 * sph_viscosity.c holds the viscosity rule and eq. 3.8's renormalisation;
 * sph_walls.c the fixed particles (no-slip walls, prescribed motion);
 * sph_heat.c the heat rates (eq. 3.42, 3.45-3.46, the Robin flux). */
#ifndef HEARTH_SIM_SPH_STATE_H
#define HEARTH_SIM_SPH_STATE_H
#include "sph.h"
#include "sph_neighbours.h"

#include <stdint.h>
#include <string.h>

#include "physics_constants.h"

/* A fixed body's prescribed rigid motion (sph_walls.c): velocity and omega
 * (constants, or motion(t) at the start of each step) about a pivot that
 * moves with the body. */
typedef struct sph_wall_motion {
    int body;
    double vel[3], omega[3]; /* this step's (m/s, rad/s) */
    double pivot[3];         /* the rotation centre at the scene's time (m) */
    double pending[3];       /* the pivot's move over the last step, applied once it stands (t == t_pending) */
    double t_pending;        /* that step's end time; NAN when none is pending */
    hearth_motion_fn motion; /* optional; not owned */
    void *motion_ud;
} sph_wall_motion;

struct sph_state {
    sph_cells cells;
    sph_nlist nl;
    int cap, n;     /* arrays hold cap particles; n = particles of the last step (-1 = stale) */
    int valid;      /* per-particle results match the scene's particles */
    int *key, *order;
    double *perm;   /* permutation scratch, cap doubles; m / rho in sph_kinematics, P / rho^2 (eq. 3.18) from sph_forces on */
    /* S: the deviatoric Kirchhoff-over-J stress of phase_stress; divided by
     * rho^2 in place once sph_forces starts (what eq. 3.18's sum reads) */
    double *rho, *prs, *h, *S, *acc, *vnew, *N, *lapC, *surf, *rhof, *dT, *Tprev;
    double *rho0, *B, *mu, *c0, *xsph;
    double *vc;     /* the viscous Laplacian's renormalisation (viscous_moments), per particle this step */
    double *vr;     /* rest volume (rest_volume) per particle this step, for sph.gas_law's density sum */
    /* sph_water.c's, made only with water or latent_heat (sph_water_ensure; wcap particles): the
     * water's rate (kg/s), saturation and K theta s this step, and the oven's Robin heat per
     * particle (W) for latent_heat's ledger (sph_fields_advance's ledger), each particle's k_i of a
     * dried crust's conduction this step (sph_heat.c's sph_dry_k, taken once a particle, not once a pair)
     * and its material's rho_0^w (sph_water_prepare) */
    double *dW, *sw, *wd, *qo, *kd, *rwd;
    int wcap;
    int wready, wpairs; /* this step: sph_water_prepare ran; sph_heat_rates summed the water's pairs into dW */
    double *sp;     /* rest spacing V0^(1/dim), per particle this step (walls, artificial stress) */
    double *R;      /* artificial stress over rho^2 (Monaghan 2000), 9 per particle */
    double amax;    /* largest |a| of the last step, for the force limit */
    double water_per_gas; /* sph.dough_water: the particles' water per raw gas volume this step (sph_gas.c) */
    double *pairc;  /* each list entry's pair values, dim + 1 doubles (sph_pairs_prepare) */
    size_t pairc_cap;
    int *pairm;     /* and for each entry k of i with j > i, the slot of j's list holding i */
    size_t pairm_cap;
    int pair_ok;    /* this step's pairm is whole: the pair passes may evaluate each pair once */
    /* sph_viscous_factor's resting-lattice moment for h / spacing = lm_ratio (sph_lattice_moment_prepare) */
    double lm_ratio, lm_val;
    /* Per material: the schema index of the plugin parameter SPH applies
     * itself as viscosity (eq. 3.19), or -1. Resolved once, when the material
     * is added (sph_material_added); see sph_viscosity_index. */
    int *visc_index;
    int visc_cap;
    sph_wall_motion *walls; /* moving fixed bodies (hearth_scene_body_motion), nwalls of walls_cap */
    int nwalls, walls_cap;
    /* sph_outer.c: the outer-surface flag per particle and the share of its rest face each outer particle stands
     * for (oshare: 1 at the rest spacing, less where outer particles crowd), both in ARRAYS, and its grid's
     * scratch, og_cap cells */
    double *outer, *oshare;
    double *ts; /* sph_heat.c's sph_surface_temperatures: an outer particle's face temperature (degC) by the oven's
                 * film closure, NaN for the others; made with ARRAYS only in a scene that browns (else NULL), valid
                 * after a step of one (particle_values' "surface_temperature") */
    double *gasleft; /* sph.surface_vent (sph_gas.c): the share of a bubble's gas still in its cell (1 closed, less once
                      * it has vented on the outer surface; NaN = not yet set: 1), sorted with the particles; made with
                      * ARRAYS only when the scene vents (else NULL) */
    uint8_t *og;
    int *oq;
    size_t og_cap;
    double *hg; /* sph_hourglass.c's scratch, made only with sph.hourglass (sph_hourglass_ensure; hg_cap particles) */
    int hg_cap;
};

/* The particle columns a phase reads. Sorting permutes the particles, and
 * the permutation may swap the columns' storage, so a phase takes them fresh
 * from sph_cols_of after every sort_and_list. */
typedef struct sph_cols {
    int n, dim;
    const int *flags; /* NULL when no particle carries flags */
    const int *mat;
    double *x, *v, *C, *F, *state;
    const double *m, *V0;
    double *T, *Tmax; /* NULL without the temperature field */
} sph_cols;

static inline sph_cols sph_cols_of(hearth_scene *s) {
    particles *ps = &s->ps;
    return (sph_cols){
        .n = ps->n,
        .dim = s->def.dim,
        .flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL,
        .mat = pcoli(ps, PC_MAT),
        .x = pcold(ps, PC_X),
        .v = pcold(ps, PC_V),
        .C = pcold(ps, PC_C),
        .F = pcold(ps, PC_F),
        .state = pcold(ps, PC_STATE),
        .m = pcold(ps, PC_MASS),
        .V0 = pcold(ps, PC_VOL0),
        .T = ps->enabled & (1u << PC_TEMPERATURE) ? pcold(ps, PC_TEMPERATURE) : NULL,
        .Tmax = ps->enabled & (1u << PC_TEMP_MAX) ? pcold(ps, PC_TEMP_MAX) : NULL,
    };
}

/* Two doubles as one value (GCC and Clang vector extension; plain scalar
 * code where the target has no such registers): the 2D loops' x, y pairs.
 * Each lane's product, sum or difference is the scalar operation's, and
 * the build is ISO C, which fuses no multiply-add, so a loop written with
 * them gives the scalar loop's bits when its expressions are the same. */
typedef double sph_v2 __attribute__((vector_size(16)));
static inline sph_v2 sph_ld2(const double *p) {
    sph_v2 r;
    memcpy(&r, p, sizeof r);
    return r;
}

/// The scene's SPH state, made on first use (a material added, a wall's
/// motion, or a step); NULL with err set when out of memory. (sph.c)
struct sph_state *sph_state_of(hearth_scene *s, hearth_error *err);

/* ---- sph_viscosity.c ---- */
/// sph_solver.material_added: resolve the material's `viscosity` parameter once.
hearth_status sph_material_added(hearth_scene *s, int mat, hearth_error *err);
/// eq. 3.8's renormalisation c_a of particle i (for st->vc) from its neighbour
/// sums, over neighbours b at d = x_a - x_b, r = |d| > 0, V_b = m_b / rho_b,
/// L = sph_lap_visc(r, h_ab): fill = sum V_b W(r, h_ab), tr = sum V_b L r^2,
/// g = sum V_b L r^2 d (sph_kinematics takes them). Needs st->sp, st->rho, st->h.
double sph_viscous_factor(const hearth_scene *s, int i, double fill, double tr, const double g[3]);
/// Before sph_kinematics' loop: keep the resting-lattice moment for the
/// first particle's h / spacing, which most particles share (it is summed
/// over the lattice, so each call for it would repeat the same sum).
void sph_lattice_moment_prepare(hearth_scene *s);

/* ---- sph_kinematics.c ---- */
/// The velocity gradient (eq. 3.27) into C, the colour field's gradient and
/// Laplacian (eq. 3.28-3.29), surface particles and eq. 3.8's moments.
void sph_kinematics(hearth_scene *s);

/* ---- sph_forces.c ---- */
/// The step's artificial stress R / rho^2 per particle (Monaghan 2000), when
/// sph.artificial_stress > 0; needs st->S and st->prs.
void sph_artificial_stress(hearth_scene *s);
/// Accelerations (eq. 3.18, 3.19, 3.30, 3.41, the stresses, gravity, the
/// body force) into st->acc and the kicked velocities into st->vnew; divides
/// st->S by rho^2 in place and leaves P / rho^2 in st->perm.
void sph_forces(hearth_scene *s, double dt);
/// After the lists: which slot of j's list holds i for each entry of i with
/// j > i (st->pairm), room for the pair terms (st->pairc) and st->pair_ok;
/// NOMEM when they cannot be kept.
hearth_status sph_pairs_prepare(hearth_scene *s, hearth_error *err);

/* ---- sph_walls.c ---- */
/// The wall normal n and fluid particle i's distance da to the wall surface; 0 without fixed neighbours.
int sph_wall_frame(const hearth_scene *s, int i, double n[3], double *da);
/// 1 + d_b / d_a: the factor on v_a in a's viscous interaction with wall
/// particle b at d = x_a - x_b (sph_walls.c says why); dah: d_a, at least half
/// of a's spacing. Inline: an outside call in sph_forces' pair loop made
/// the compiler reload every state pointer for every pair.
static inline double sph_wall_beta(const double d[3], const double n[3], double da, double dah) {
    const double db = d[0] * n[0] + d[1] * n[1] + d[2] * n[2] - da;
    return db > 0 ? 1.0 + db / dah : 1.0;
}
/// Particle i's viscous drag (eq. 3.19, 1/s) from the no-slip (sticky, grip) colliders within its h, as
/// virtual wall particles with Morris et al.'s velocities (sph_walls.c): the kick takes -D (v_i - V)
/// implicitly, V the colliders' velocity (weighted by their parts of D). 0 (and V = 0) when none is near.
double sph_collider_drag(const hearth_scene *s, int i, double V[3]);
/// At the start of a step (serial: it may call motion callbacks): every fixed
/// particle's velocity, its body's prescribed motion at time t or 0.
void sph_walls_begin(hearth_scene *s, double t);
/// At the end of a step: moving fixed bodies move rigidly over dt (exact for
/// constant velocity and omega); their pivots follow once the step stands
/// (a rolled-back step restores the particles, and its pivot move is dropped).
void sph_walls_end(hearth_scene *s, double dt);
/// Release the motion records (with the state).
void sph_walls_free(struct sph_state *st);

/* ---- sph_dt.c ---- */
/// The stable dt: CFL, viscous, force and heat limits, dt_max, times dt_scale.
double sph_stable_dt(const hearth_scene *s);

/* ---- sph_heat.c ---- */
/// Heat rates dT/dt into st->dT (nothing without the temperature field).
void sph_heat_rates(hearth_scene *s);
/// After the rates: temperatures and water forward by dt (with latent_heat the oven's heat in into
/// s->heat.step_oven_heat, and boiling), then the highest temperatures.
void sph_fields_advance(hearth_scene *s, double dt);
/// The heat limits on dt (INFINITY when none applies); hmin, rhomin over the particles.
double sph_heat_stable_dt(const hearth_scene *s, double hmin, double rhomin);

/* ---- sph_water.c ---- */
/// Each particle's saturation, K theta s (or -1 for a bubble) and rho_0^w into st->sw, st->wd and st->rwd,
/// for the water's pairs. Only while the water field is live; before sph_heat_rates, which then sums the
/// water's pairs (sph_water_pair) in its own pair loop.
void sph_water_prepare(hearth_scene *s);
/// The water's rates into st->dW (Fick's flux through the heat's Laplacian, unless sph_heat_rates summed it,
/// evaporation at surface particles) and, with latent_heat, L x evaporation
/// out of st->dT. Only while the water field is live; after sph_heat_rates.
void sph_water_rates(hearth_scene *s);
/// Do i and j trade water (sph_water.c's rule: one of them holds some, and j is no bubble; i's own bubble
/// test is the caller's)? D = st->wd.
static inline int sph_water_pairs_with(const double *D, int i, int j) { return (D[i] > 0 || D[j] > 0) && !(D[j] < 0); }
/// The water i takes from j (kg/s), Fick's flux through the heat's Laplacian (sph_water.c's header): lap the
/// kernel's sph_lap_visc at the pair's r and mean h, every factor the pair's own, in the same order from either
/// side, so the pair sums move no water (to round-off). Written once for the two loops that sum it (sph_heat.c's,
/// sph_water.c's), so both give the same bits.
static inline double sph_water_pair(const struct sph_state *st, const double *m, int i, int j, double lap) {
    const double *D = st->wd, *sw = st->sw;
    const double rs = st->rho[i] + st->rho[j], lv = lap * (0.5 * (st->vc[i] + st->vc[j]));
    const double rw = 0.5 * (st->rwd[i] + st->rwd[j]);
    return rw * (0.5 * (D[i] + D[j])) * (4 * (m[i] * m[j]) / (rs * rs)) * lv * (sw[j] - sw[i]);
}
/// After the temperatures moved: the water by dt st->dW, floored; with
/// latent_heat water_boil past the boiling point; the step's removed water.
void sph_water_advance(hearth_scene *s, double dt);
/// Does the step need sph_water.c's arrays (the water field live, or latent_heat's ledger)?
int sph_water_live(const hearth_scene *s);
/// The doubles per particle sph_water_ensure keeps.
#define SPH_WATER_ARRAYS 6
/// Before a step of n particles: the water's arrays, when sph_water_live; NOMEM when they cannot be had.
hearth_status sph_water_ensure(hearth_scene *s, int n, hearth_error *err);
/// Release them (with the state).
void sph_water_free(struct sph_state *st);
/// The water's limits on dt (INFINITY without the water field); hmin, rhomin as the heat's.
double sph_water_stable_dt(const hearth_scene *s, double hmin, double rhomin);

/* ---- sph_gas.c ---- */
/// With sph.gas_law: st->rhof (each particle's rest density: rho0, a bubble's
/// rho0 / V_b(T)) and st->prs against it; st->Tprev <- T.
void sph_pressure_gas_law(hearth_scene *s);
/* sph_xsph.c: XSPH (eq. 3.34, epsilon by eq. 4.4) from st->vnew into the particles' v; st->amax for the force limit. */
void sph_xsph(hearth_scene *s);

/* sph_hourglass.c: sph.hourglass's damping of the pairs' motion eq. 3.27's gradient does not describe,
 * into st->vnew after sph_forces' kick; its scratch (made only when on), freed by sph_hourglass_free;
 * the doubles per particle it keeps (0 when off). */
void sph_hourglass(hearth_scene *s, double dt);
hearth_status sph_hourglass_ensure(hearth_scene *s, int n, hearth_error *err);
void sph_hourglass_free(struct sph_state *st);
/// The particles on the body's outer surface into st->outer (sph_outer.c): where eq. 3.42's oven heat enters.
void sph_outer_surface(hearth_scene *s);
void sph_outer_free(struct sph_state *st);
int sph_hourglass_doubles(const hearth_scene *s);
/// A bubble's stiffness (Pa) at T (degC): its gas's own P_a - P_v(T) with
/// sph.gas_pressure = P_a, else the dough's Tait B.
double sph_gas_modulus(const hearth_sph_def *o, double B, double T);
/// The sound speed (m/s) of a bubble (raw gas volume bub) of rest density
/// rho0 whose stiffness is its gas's, sqrt((P_a - P_v) V_b(T) / rho0); 0
/// where it is not (no sph.gas_pressure, not a bubble, T NaN).
double sph_gas_sound_speed(const hearth_sph_def *o, double bub, double rho0, double T, double w);
/// sph.dough_water: the water the particles hold (dough_water x their mass
/// over water's density) per unit of the bubbles' raw gas volume (sum of
/// bubble x V0); 0 without dough_water or bubbles.
double sph_dough_water_share(const hearth_scene *s);
/// With sph.dough_water: a bubble's V_b (raw gas volume vb0) at T whose gas
/// shares its moles with CO2 dissolved in w m^3 of water per m^3 of raw gas
/// (Henry's law); w = 0 is sph_bubble_volume.
double sph_bubble_volume_dissolved(const hearth_sph_def *o, double vb0, double T, double w);
/// The gas-law options' refusals without sph.gas_law (sph_check_def).
hearth_status sph_gas_check_def(const hearth_sph_def *o, hearth_error *err);
#endif

/* thermal.h: heat transport of Ding et al. 2019 §4 and §6.3 on the MPM grid.
 * Runs only when the temperature field is live. */
#ifndef HEARTH_THERMAL_H
#define HEARTH_THERMAL_H
#include <math.h>

#include "hearth/hearth.h"
#include "physics_constants.h"

struct hearth_scene;

/* Heat transport's own state (thermal.c), held by value in the scene as
 * s->heat. Scratch grown when the particle or block count grows; nothing is
 * allocated until the temperature field is live. transport.c reads bnd_coef
 * and bnd_temp (it applies the operator whose sources they are); only
 * thermal.c writes. */
#define THERMAL_CT 11
typedef struct thermal_state {
    double *bnd_coef, *bnd_temp; /* per particle: boundary S beta (W/K) and outside temperature (degrees C) */
    double *bnd_surf;            /* per particle on the oven's air surface: 1 / (1 + beta d / kappa), the share of
                                  * theta_out - theta_p left across the air film (find_boundary), for
                                  * thermal_surface_temperature */
    int bnd_cap;
    double *cg_partial;          /* per active block: partial dot products */
    int cg_cap;
    int cg_iterations;           /* of the last implicit solve */
    /* heated colliders' contact, as surface quadrature points (find_boundary) */
    double *ct;                  /* per point THERMAL_CT doubles: position on the collider's face (3), the body's
                                  * outward normal there (3), beta S or S (W/K, m^dim-1), temperature, kappa
                                  * (0: Robin contact; > 0: a held face's Nitsche terms), and the temperature a
                                  * Robin contact reads where its nodes carry dried particles (dried_face: the
                                  * largest of those nodes' dried means, from the step start; NaN: the nodes'
                                  * field at the point), and the collider's index (for a drawing sheet's books) */
    int nct, ct_cap;
    /* held (Dirichlet) nodes: per active node (block slot * nodes per block) the
     * temperature it keeps, NaN where free; scratch for the held bodies' sums */
    double *fix, *fix_w;
    int fix_cap, nfix;
    int held_n, held;            /* particle count at the last scan for held particles; any found */
    double *hold_h;              /* per particle, when nfix > 0: the weight of its held nodes (mpm.c's G2P
                                  * blends its temperature toward the nodes' by it) */
    int hold_cap;
    /* the oven's heat ledger, kept only with the scene's latent_heat (the energy
     * balance that checks the latent sink): heat in through the oven's Robin
     * boundary this step and over the steps that stood (J, J/m in 2D) */
    double step_oven_heat, oven_heat_in;
    /* subcell.c's per-node fits (1 + dim doubles a node with storage: the dried particles' value at the node
     * and their gradient), grown when a latent_heat scene first has a dried particle; scratch within a step */
    double *sub_fit;
    size_t sub_cap;
    /* flip_bound.c's scratch (2 doubles a particle: its move, its share of the move left) and the field step's
     * bounds (degC, taken before subcell.c moves the dried particles) */
    double *bound_c;
    int bound_cap;
    double bound_lo, bound_hi, bound_tol;
} thermal_state;

/// Empty state (allocates nothing).
void thermal_init(thermal_state *h);
/// Free the scratch; h is empty afterwards (thermal_init's state).
void thermal_free(thermal_state *h);
/// Iterations of the last implicit heat solve (0 when explicit or none yet).
int thermal_cg_iterations(const struct hearth_scene *s);

/// The temperature (degrees C) of the air surface above particle i, by the
/// closure the oven's flux uses (find_boundary): theta_out - (theta_out - th) /
/// (1 + beta d / kappa), th the nodes' temperature (CH_T) at the particle, the
/// sample at depth d that the flux reads. NAN when particle i held no oven
/// surface at this field step, or the scene has no oven. Valid after
/// thermal_finish of a step that carried the fields, until the next step's
/// P2G (the grid) and sort (the particle order of the boundary arrays).
/// `sample` (may be NULL) takes th.
double thermal_surface_temperature(const struct hearth_scene *s, int i, double *sample);

/// The air film's closure both solvers read a surface's temperature by (Ding et al. 2019 §3.2's heat flow boundary
/// condition, kappa grad theta . n = beta (theta_out - theta_s) at the face, across a layer of depth d that conducts
/// as Fourier's law with a linear profile, the quasi-steady form of Rodriguez-Arenas eq. 3.44 over it): the flux
/// q = beta (theta_out - theta_s) = kappa (theta_s - theta_p) / d leaves theta_out - theta_p shared between the film
/// and the layer, and thermal_film_den returns 1 + beta d / kappa, the denominator of the film's share (1 without
/// conduction, kappa <= 0: nothing carries heat from the face to the particle, which then is the face). beta and
/// kappa in any units with the same time and heat (their ratio, 1/m, is what counts), d in m.
static inline double thermal_film_den(double beta, double d, double kappa) {
    return kappa > 0 ? 1.0 + beta * d / kappa : 1.0;
}
/// The face's temperature (degrees C) of that closure: theta_out - (theta_out - theta_p) r, r = 1 / den the film's
/// share (thermal_film_den). MPM reads theta_p at its grid's sample (thermal_surface_temperature), SPH at an outer
/// particle's centre (sph_heat.c's sph_surface_temperatures).
static inline double thermal_face_temperature(double theta_out, double theta_p, double r) {
    return theta_out - (theta_out - theta_p) * r;
}

/// The oven's radiating walls (#18): an oven (oven_temperature set) whose walls have a temperature and an emissivity
/// above 0. Off, every path is the convective one, in its bits.
static inline int thermal_oven_radiates(const hearth_scene_def *d) {
    return !isnan(d->oven_temperature) && isfinite(d->oven_wall_temperature) && d->oven_emissivity > 0;
}
/// Does the oven exchange heat with the body's air surface at all (beta > 0, or radiating walls)?
static inline int thermal_oven_on(const hearth_scene_def *d) {
    return !isnan(d->oven_temperature) && (d->oven_beta > 0 || thermal_oven_radiates(d));
}
/// eps sigma times the scene's radiation_scale (W/(m^2 K^4)); 0 without radiating walls.
static inline double thermal_oven_rad(const hearth_scene_def *d) {
    return thermal_oven_radiates(d) ? d->oven_emissivity * SIGMA_SB * d->oven_radiation_scale : 0.0;
}
/// The walls' radiation q = rad (T_w^4 - T_s^4) written as h_r (T_w - T_s), h_r = rad (T_w^2 + T_s^2) (T_w + T_s),
/// temperatures in K inside (degrees C outside): exact at T_s, and the form the Robin coefficient takes, so the
/// implicit operator stays symmetric. rad = eps sigma (thermal_oven_rad). A face below 0 K is taken at 0 K.
static inline double thermal_radiative_h(double rad, double t_wall, double t_s) {
    const double w = t_wall + KELVIN, f = t_s + KELVIN > 0 ? t_s + KELVIN : 0.0;
    return rad * (w * w + f * f) * (w + f);
}
/// The oven's air and its walls as one Robin exchange through the air film's closure (thermal_film_den): the face
/// at temperature T_s takes beta (T_air - T_s) + h_r(T_s) (T_w - T_s) = B (T_o - T_s), B = beta + h_r and T_o =
/// (beta T_air + h_r T_w) / B. T_s is the face of the closure over the sample th at depth d (kappa the layer's), and
/// h_r depends on it: a fixed point T_s = T_o - (T_o - th) / (1 + B d / kappa), from T_s = th, to 1e-10 K (a
/// contraction: h_r moves by 4 h_r / T per K of T_s, and the film's share is below 1; 8-10 sweeps for the loaf's top,
/// at most 24 over walls to 900 degC, layers to 5 mm and kappa down to 0.05 W/(m K), counted on the same iteration).
/// So the flux at the step's sample is the radiation at the face's own temperature, not a lag of it.
/// Returns B; *t_out = T_o, *r = 1 / (1 + B d / kappa), the film's share (thermal_face_temperature). With rad = 0:
/// beta, T_air and 1 / thermal_film_den(beta, d, kappa), the convective closure's values to the bit.
static inline double thermal_oven_exchange(double beta, double t_air, double rad, double t_wall, double th, double d,
                                           double kappa, double *t_out, double *r) {
    if (!(rad > 0)) {
        *t_out = t_air, *r = 1.0 / thermal_film_den(beta, d, kappa);
        return beta;
    }
    double ts = th, B = beta, to = t_air, rr = 1.0;
    for (int k = 0; k < 60; k++) {
        const double hr = thermal_radiative_h(rad, t_wall, ts);
        B = beta + hr;
        to = (beta * t_air + hr * t_wall) / B;
        rr = 1.0 / thermal_film_den(B, d, kappa);
        const double next = thermal_face_temperature(to, th, rr);
        const int done = fabs(next - ts) <= 1e-10;
        ts = next;
        if (done) break;
    }
    *t_out = to, *r = rr;
    return B;
}
/// The largest h_r a face meets in scene s (W/(m^2 K)): 4 eps sigma T^3 at the hotter of the walls and the highest
/// temperature a face may reach by the scene's other heat (the oven's air, a heated collider); 0 without radiating
/// walls. For the explicit steps' Robin limits (thermal_dt_limit, SPH's sph_heat_stable_dt).
double thermal_walls_h_max(const struct hearth_scene *s);

/// Is heat transport on for this scene (temperature live)?
int thermal_active(const struct hearth_scene *s);
/// Largest explicit heat step (s), or INFINITY when implicit or inactive.
double thermal_dt_limit(const struct hearth_scene *s);
/// After P2G (heat capacity and C*theta scattered) and the boundary search:
/// temperatures on nodes, and the boundary particles' coefficients. Then
/// transport_apply (transport.h) evaluates L theta^n into CH_R and the sources
/// into CH_B.
hearth_status thermal_prepare(struct hearth_scene *s, hearth_error *err);
/// After transport_apply: the heated colliders' contact terms into CH_R (a
/// scatter of its own, so MPI slabs sum it with the transport's).
void thermal_contact(struct hearth_scene *s);
/// The forward or backward Euler update of eq. 9 on the nodes (§6.3). Fails
/// only on MPI slabs (the CG's halo exchange out of memory).
hearth_status thermal_finish(struct hearth_scene *s, double dt, hearth_error *err);
/// A clamped boundary particle i (flip_bound.c) gives heat (J, the clamp's m alpha dT: negative when it gave back what
/// a drawing sheet let in past the bounds) back to the first drawing sheet whose contact band holds it, as the oven's
/// ledger takes its own particles' returns. Nothing when no drawing sheet holds it. Summed over MPI ranks by
/// thermal_sheet_returns_done.
void thermal_sheet_return(struct hearth_scene *s, int i, double heat);
/// After flip_bound's clamps: each drawing sheet's returns (summed over ranks) join the heat its contact passed.
void thermal_sheet_returns_done(struct hearth_scene *s);
/// A step stood (the guard kept it): its oven heat joins the ledger.
void thermal_step_stands(thermal_state *h);
/// After a field step's update (thermal_finish): the oven's Robin heat for latent_heat's ledger and each drawing
/// sheet's draw (thermal_ledger.c), from the nodes' field the update read.
void thermal_step_books(struct hearth_scene *s, double dt);
/// The nodes' channel ch at x (the B-spline field of the contact stencil, 0 where no node has storage); *m the nodes.
double thermal_field_at(const struct hearth_scene *s, const double x[3], int ch, int *m);
/// Total heat energy sum m alpha (theta + 273.15) of the particles (J).
double thermal_energy(const struct hearth_scene *s);
/// G2P's temperature update (Ding et al. eq. 21): FLIP's T0 + dT, blended toward PIC's Tn by the scene's
/// heat_flip < 1. mpm_g2p.c makes it and flip_bound.c predicts it, so the two cannot drift apart.
static inline double thermal_flip_blend(double flip, double T0, double dT, double Tn) {
    return flip == 1.0 ? T0 + dT : flip * (T0 + dT) + (1.0 - flip) * Tn;
}

#endif

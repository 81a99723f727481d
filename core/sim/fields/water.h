/* water.h: water in the mixture, Ding et al. 2019 §3.2, §5.5, §6.2. Runs only
 * when the water field is live. */
#ifndef HEARTH_WATER_H
#define HEARTH_WATER_H
#include <math.h>

#include "hearth/hearth.h"
#include "vapour.h"

struct hearth_scene;

/* Water's own state (water.c), held by value in the scene as s->water: the
 * running totals and the explicit-step limits. Only water.c writes it; the
 * per-block partial sums of a step (pb_partial's water_* members, mpm.h)
 * stay with the other P2G/G2P partials, where G2P's block loop writes them,
 * and water_finish reduces them into here. */
typedef struct water_state {
    double lost;           /* through the boundary so far (kg) */
    double step_removed;   /* by the step being taken; counted when it stands (water_step_stands) */
    double dmax, emax;     /* largest K theta s and beta theta / rho_0 after the last step */
    double lmax;           /* with latent_heat: largest beta^w (s - s_amb)^+ / (rho c) after it (water_latent_rate) */
    int limits_valid;      /* 0: particles or materials changed since, scan again */
    int exchange;          /* this step has wet colliders with beta_water > 0 (Robin): water_prepare sets it */
    int hold;              /* this step has wet colliders that hold their saturation: water_prepare sets it */
    /* latent_heat in MPM (water_boil_front, boil_front.c): per particle, the step's boiling heat E_p (J) and
     * its heat capacity m c (J/K), 2 doubles each, then the front's own scratch (the passes' columns, each
     * particle's 9 or 27 pair weights, a byte per active grid block); within a step, grown by
     * water_boil_front_prepare */
    double *front;
    size_t front_cap;      /* doubles held */
    double front_removed;  /* the water water_boil_front boiled this step (kg), added by water_finish */
    int front_walk_all;    /* tests: the front walks every node and particle on one rank too, as on MPI slabs */
} water_state;

/// Empty state: nothing lost, limits to be scanned.
void water_init(water_state *w);
/// Frees the boiling front's scratch and resets w to water_init's state.
void water_free(water_state *w);
/// The step stands: its water loss counts.
void water_step_stands(water_state *w);
/// Particles or materials changed: the step limits are scanned again.
void water_forget_limits(water_state *w);
/// A restored checkpoint's water lost so far (kg).
void water_restore_lost(water_state *w, double lost);
/// A restored checkpoint's step limits (dmax, emax, lmax as water_state holds them), kept as the saved run kept them.
void water_restore_limits(water_state *w, double dmax, double emax, double lmax);

/* Saturation never reaches zero (Ding et al. §3: "our mixture will never be
 * completely dry"): particles keep at least this much. */
#define WATER_SATURATION_FLOOR 1e-4

/* Boiling (latent_heat) compares a particle's water with the floor's mass at its volume vol: the one rounding
 * water_boil, G2P's test and the boiling front all take. */
static inline double water_floor(double rho_w, double vol) { return WATER_SATURATION_FLOOR * rho_w * vol; }
/* The heat a particle's water above the floor can boil, L x spare (none without spare), and what a particle past
 * T_b with excess E sends to the boiling front: E up to that room; it keeps the rest as sensible heat (water_boil's
 * cap, which the front's shares and G2P's gas read alike: boil_front.c). */
static inline double water_room(double spare) { return spare > 0 ? spare * HEARTH_LATENT_HEAT : 0.0; }
static inline double water_front_sent(double E, double room) { return E < room ? E : room; }

/* Evaporation through the air surface (transport.c) from the grid's
 * saturation s_d at a surface particle, sampled at depth d below the surface
 * (boundary.c's depth), toward the ambient s_amb: returns s_surface - s_amb,
 * so the outward flux density is beta^w theta times it.
 *
 * Across the thin layer between the sample and the surface the flux j is
 * steady to leading order (as heat's linear profile is), and Fick's flux
 * (eq. 22) is j = -rho_0^w K theta s ds/dn = -rho_0^w K theta d(s^2/2)/dn: s^2/2
 * (Kirchhoff's variable for D = K theta s) is linear across it, so
 * s_d^2 - s_surface^2 = 2 d j / (rho_0^w K theta), with j = beta^w theta
 * (s_surface - s_amb) at the surface. Then s_surface solves
 * s^2 + 2 a s - (s_d^2 + 2 a s_amb) = 0 with a = d beta^w / (rho_0^w K) (theta
 * cancels), whose positive root gives
 *   s_surface - s_amb = (s_d^2 - s_amb^2) / (sqrt(a^2 + s_d^2 + 2 a s_amb) + a + s_amb),
 * written so that nothing cancels as a grows. For a small contrast it is
 * (s_d - s_amb) / (1 + a / s), the coefficient beta^w theta / (1 + beta^w theta d
 * / (rho_0^w K theta s)) of a layer whose conductance per unit grad s is
 * rho_0^w K theta s / d; the quadratic holds for the nonlinear diffusivity
 * too (for a steady layer), and as the surface dries (s_amb = 0, beta^w large)
 * it bounds the flux by what diffusion brings through the layer,
 * rho_0^w K theta s_d^2 / (2 d). Rejected: that coefficient with s = s_d,
 * linear in s: fast drying into dry air (L = 5) was 8.0%, 3.0% off a 1D
 * solution at 10, 20 cells, against 2.9%, 0.65% with the quadratic
 * (water_drying_fast_vs_fd).
 * Using s_d itself (a = 0) overstated the flux by 1 + a / s, an error of order
 * dx: the humid oven's Crank sheet converged at first order (6.9%, 3.7%, 1.9%
 * at 10, 20, 40 cells). With K = 0 nothing carries water from the surface to
 * the sample: pass a = 0, and the exchange acts on the particle directly. */
static inline double water_surface_excess(double s_d, double s_amb, double a) {
    if (!(a > 0)) return s_d - s_amb;
    const double den = sqrt(a * a + s_d * s_d + 2.0 * a * s_amb) + a + s_amb;
    return den > 0 ? (s_d - s_amb) * (s_d + s_amb) / den : 0.0;
}

/* With the scene's latent_heat, evaporation is driven by the vapour
 * pressure (issue #18): Ding et al.'s boundary flux beta^w theta (s - s_amb)
 * (§3.2, the condition beside eq. 8) times
 *   f(theta) = min(1, P_sat(theta) / P_sat(theta_b)),
 * P_sat by Clausius-Clapeyron (vapour.h, Rodriguez-Arenas 2011 eq. 2.43) and
 * theta_b the scene's boiling_point in kelvin. Why: eq. 8's flux is linear in
 * the absolute temperature, so a wet surface whose vapour takes L per kg
 * cools on until theta is 0 (a material with L beta^w large against rho c
 * went to -272 degC within 1 s); a real wet surface stops cooling at its
 * wet-bulb temperature, where the vapour's pressure, which halves every
 * ~20 K below boiling, no longer carries away the heat the oven brings.
 * That is the surface mass-transfer form of baking models, a flux h_m (a_w
 * P_sat(T_s) - p_v,air) with h_m in kg/(m^2 s Pa) and the water activity a_w
 * falling as the surface dries (Zanoni, Pierucci & Peri 1994, J. Food Eng.
 * 23:321; Zhang & Datta 2006, J. Food Eng. 75:78), with Ding's s for a_w and
 * beta^w theta / P_sat(theta_b) for h_m, so the rate at theta_b is eq. 8's
 * and the physical presets keep their calibration point (h.library.dough's
 * 1.2e-5 at a wet 373 K surface, lua/hearth/dough_physical.lua). The air's term stays s_amb P_sat(theta),
 * at the surface's temperature, not the oven air's pressure: s_amb keeps its
 * meaning (the saturation toward which exchange goes, water.c), which the
 * humid oven's tests calibrate; a real oven's vapour pressure would make a
 * cold wet surface condense, which hearth does not model. Past theta_b the
 * factor stays 1 (eq. 8 again): there water_boil takes a wet particle's
 * excess heat, so a surface above theta_b holds little water; the exponential
 * would make the sink's rate of change with theta, L beta^w S (s - s_amb)
 * (1 + Delta H_v / (R theta)) f below theta_b, grow without bound above it,
 * while capped it peaks at theta_b, which the step limits take
 * (water_latent_stiffness). psat_b is P_sat(theta_b) (Pa); 0 (latent_heat off,
 * or a boiling point at 0 K) keeps eq. 8 verbatim, bit for bit. */
static inline double water_vapour_factor(double th, double psat_b) {
    if (!(psat_b > 0)) return 1.0;
    const double f = vapour_psat(th) / psat_b;
    return f < 1.0 ? f : 1.0;
}

/* The bound the explicit step limits take for the latent sink's rate of
 * change with the particle's temperature, in units of L beta^w S (s - s_amb):
 * d(theta f) / d theta = f (1 + Delta H_v / (R theta)) rises with theta up to
 * theta_b (its derivative is f (Delta H_v / R)^2 / theta^3 > 0), where it is
 * 1 + Delta H_v / (R theta_b) (14.1 at 100 degC), and is 1 past it. */
static inline double water_latent_stiffness(double psat_b, double th_b) {
    return psat_b > 0 ? 1.0 + VAPOUR_DH / (R_GAS * th_b) : 1.0;
}

/* Evaporation (kg/s) through a surface of area `area` whose sample saturation
 * s_d lies `depth` below it (Ding et al. §3.2: beta^w theta (s - s_amb) per
 * unit area, through water_surface_excess's layer, times the vapour factor
 * above when psat_b > 0), for a material of evaporation bw, water diffusivity
 * K and water density rho0, at absolute temperature th. Both solvers call
 * it: MPM per boundary particle (transport.c, boundary.c's area and depth),
 * SPH per surface particle (sph_water.c). */
static inline double water_surface_layer(double bw, double K, double rho0, double depth) {
    return K > 0 ? bw * depth / (rho0 * K) : 0.0; /* d beta^w / (rho_0^w K): water_surface_excess's a */
}
static inline double water_evaporation(double bw, double K, double rho0, double th, double s_d, double s_amb,
                                       double depth, double area, double psat_b) {
    const double lay = water_surface_layer(bw, K, rho0, depth);
    const double e = bw * th * water_surface_excess(s_d, s_amb, lay) * area;
    return psat_b > 0 ? e * water_vapour_factor(th, psat_b) : e;
}

/* P_sat at the scene's boiling point (Pa) when its latent_heat is on and it
 * has temperatures, else 0: water_evaporation's psat_b. */
double water_psat_boiling(const struct hearth_scene *s);

/// The saturation at the air surface above particle i whose sample reads s_d, by
/// the closure evaporation uses (water_surface_excess through boundary.c's
/// depth, the particle's material): s_amb + the excess. s_d itself where the
/// closure has no layer (no evaporation or no diffusivity: nothing carries
/// water between the sample and the surface) or i holds no air surface.
/// Valid from boundary_find until the next step's sort, as its depth.
double water_surface_saturation(const struct hearth_scene *s, int i, double s_d);

/// Is the water field live?
int water_active(const struct hearth_scene *s);
/// Does a material ask for water (diffusivity, evaporation, water pressure, or a plugin that needs saturation)?
int water_material_wants(const struct hearth_scene *s, int mat);
/// Turn the water field on; particles that have none get their material's initial saturation.
hearth_status water_enable(struct hearth_scene *s, hearth_error *err);
/// Is material slot ms an SPH bubble (CP_BUBBLE > 0 on the SPH solver: the
/// thesis's gas particles, Rodriguez-Arenas 2011 eq. 3.48-3.50)? A bubble is
/// gas and holds no liquid water: it is seeded at the floor whatever its
/// material's saturation says, takes no part in SPH's water exchange and does
/// not evaporate (sph_water.c).
struct material_slot;
int water_sph_gas(const struct hearth_scene *s, const struct material_slot *ms);
/// Give particles [from, to) saturation sat (NaN: their material's), floored;
/// SPH bubbles (water_sph_gas) the floor.
void water_init_particles(struct hearth_scene *s, int from, int to, double sat);
/// The step limits scanned now if stale, and kept (before the set is split over MPI slabs).
void water_keep_limits(struct hearth_scene *s);
/// Largest explicit water step (s), INFINITY when inactive.
double water_dt_limit(const struct hearth_scene *s);
/// With latent_heat: the largest beta^w (s - s_amb) / (rho c) over the particles (m/s per J/kg: times L it is
/// the latent sink's Robin coefficient per unit heat capacity, before the vapour's factor's bound), from the
/// saturations the next step's sink starts from; 0 without latent_heat or water, or where no particle is
/// wetter than s_amb. thermal_dt_limit takes it.
double water_latent_rate(const struct hearth_scene *s);
/// Once a step stands: raise each particle's PC_DRIED (1 - the lowest moisture ratio reached) to its
/// present dryness. The column must exist (an irreversible moisture curve enables it).
void water_dried_step(struct hearth_scene *s);
/// Saturation of particle i (from its water mass and current volume, J V_0).
/// On SPH the volume is the rest volume V_0: its dough is weakly compressible
/// (Tait holds its density near rho_0), and the det of the F that SPH
/// integrates from eq. 3.27's velocity gradient drifts where the kernel is cut
/// by the free surface (a block slumping on a tray: J 1.15 along its top row,
/// 0.84 at its bottom corners after 0.5 s, 1.00 inside), which read as
/// drying (s 0.70 of 0.8, no water lost) and wetting (0.95).
double water_saturation(const struct hearth_scene *s, int i);
/// After P2G (water mass and capacity scattered, eq. 15, 18): node
/// saturations, and the wet colliders' held values. transport_apply then
/// adds the Fick flux and evaporation (eq. 22, 25) into CH_DMW, and with
/// def.water_momentum the relative water momentum (eq. 26-27).
void water_prepare(struct hearth_scene *s);
/// In G2P, at P2G's positions: particle i takes r, the interpolated change of
/// its nodes' saturation (eq. 19-20, FLIP), floored. Returns the water it
/// lost (kg); raises *dmax, *emax and *lmax, the explicit-step limits (water_state's).
double water_take(struct hearth_scene *s, int i, double r, double *dmax, double *emax, double *lmax);
/// With the scene's latent_heat, for particle i (of volume vol, m^3: MPM's
/// P2G volume, SPH's rest volume V_0, as its saturation) whose new temperature *T passed Tb (degrees C):
/// the excess heat boils its water above the floor, m c (*T - Tb) / L, and *T
/// falls by L / (m c) per kg boiled (to Tb unless the water ran out), mc = m c
/// the heat capacity (J/K) the step heated it with. Returns
/// the water boiled (kg); the vapour leaves the body. Both solvers call it.
double water_boil(struct hearth_scene *s, int i, double *T, double Tb, double vol, double mc);
/// MPM with latent_heat, before G2P: the boiling front's scratch holds every
/// particle (an error status, naming the count, when memory runs out).
hearth_status water_boil_front_prepare(struct hearth_scene *s, hearth_error *err);
/// MPM with latent_heat, after G2P (which left each boiling particle at Tb
/// and its excess heat in the scratch): the heat each node took for boiling
/// goes to the wet particles on the side the heat comes from first (water.c says how); the water
/// boiled goes into the step's removed (water_finish).
hearth_status water_boil_front(struct hearth_scene *s, hearth_error *err);
/// After transport_apply: the water crossing wet colliders' faces over dt,
/// into CH_DMW around each contact particle's foot on the face (the boundary
/// term of holding faces, the exchange of Robin ones).
void water_face_flux(struct hearth_scene *s, double dt);
/// After G2P: the particles beside holding wet colliders take the grid's
/// saturation (PIC); the step's water lost and the step limits, summed in block order.
void water_finish(struct hearth_scene *s);
/// Total water in the particles (kg, or kg/m in 2D).
double water_total(const struct hearth_scene *s);
#endif

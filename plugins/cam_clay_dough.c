/* cam_clay_dough.c: the solid phase of dough and batter (Ding et al. 2019,
 * "A Thermomechanical Material Point Method for Baking and Cooking",
 * §5.2-5.3 and §6.5): Hencky elasticity with a viscoplastic, porosity
 * dependent modified Cam-clay yield surface.
 *
 * ---- elasticity (§5.2) ---------------------------------------------------
 *   eps = 1/2 log(b^E),  b^E = F^E F^E^T          (elastic Hencky strain)
 *   Psi = 1/2 lambda (tr eps)^2 + mu eps:eps,  so tau = C eps = lambda tr(eps) I + 2 mu eps.
 * The thermal expansion term of eq. 10 is the core's, as a thermal strain
 * (HEARTH_NEEDS_THERMAL_EXPANSION, core parameter `expansion`): with this
 * plugin's bulk_modulus K the core takes ln J_th = c lambda (theta -
 * theta_ref) / K out of F and grad_v before the stress (core/sim/material.h,
 * material_thermal_split), so b^E here is the mechanical part and the yield
 * condition acts on the whole elastic stress, thermal part included (§6.5).
 * The core adds the gas pressure of eq. 13 after the stress; this plugin
 * returns the elastic Kirchhoff stress tau^{s,E} only.
 *
 * ---- yield surface (eq. 12) -------------------------------------------------
 *   f(tau) = M(n^p) p^2 + q^2 - tau_y^2 <= 0,
 *   M(n)   = 9 / (4 ln^2(1/n) (7/2 n + 1)),
 *   p = -tr(tau)/3,  q = sqrt(3/2) |tau + p I|.
 * n^p is the gas porosity the core passes in pt->porosity
 * (n^p = 1 - (1 - n^p_0) / J^P, §5.4's gas volume fraction, from this
 * plugin's plastic_J; core/sim/fields/gas.h, gas_porosity). M -> 0 as
 * n^p -> 0, so the surface becomes von Mises q <= tau_y; but only like
 * 1/ln^2: M(1e-9) = 5.2e-3 still, so the exact von Mises limit is n^p = 0,
 * which this plugin also accepts. A NaN porosity (the field is off, e.g. a
 * solver that does not fill it) is read as n^p = 0, i.e. von Mises.
 *
 * ---- the return map (§6.5) --------------------------------------------------
 * Trial: b_tr = f b_n f^T with f = I + dt grad_v (the same f the core applies
 * to F, so F^E_tr = f F^E_n). With eps_tr = 1/2 log b_tr, tau_tr = C eps_tr,
 *   tau = argmin 1/2 (tau_tr - tau) : C^-1 (tau_tr - tau) + (dt/eta) g(f(tau)),
 *   g(f) = 1/2 f^2 for f > 0, else 0                             (eta > 0)
 *   tau = argmin 1/2 (tau_tr - tau) : C^-1 (tau_tr - tau), f(tau) <= 0   (eta = 0).
 * Everything is isotropic, so tau shares the eigenvectors of b_tr and the
 * problem lives in principal (Hencky) space. There C^-1 splits into a bulk
 * and a shear part, (p - p_tr)^2 / (2K) + (q - q_tr)^2 / (6 mu), K = lambda
 * + 2/3 mu, and since f depends on the deviator only through q, the
 * deviator returns radially (s = q/q_tr s_tr). Stationarity gives, with a
 * multiplier gamma >= 0 (gamma = (dt/eta) f for eta > 0):
 *   p(gamma) = p_tr / (1 + 2 K M gamma),   q(gamma) = q_tr / (1 + 6 mu gamma),
 *   phi(gamma) = M p(gamma)^2 + q(gamma)^2 - tau_y^2 - (eta/dt) gamma = 0.
 * phi is strictly decreasing with phi(0) = f_tr > 0, so the root is unique;
 * eta = 0 is the closest-point projection onto f = 0 (and the viscous
 * solution tends to it as eta -> 0). The root is bracketed by
 * [0, max(gamma_p, gamma_q)] (at the root one of M p^2, q^2 carries at least
 * half of tau_y^2) and found by Newton on the reciprocal-norm form
 *   chi(gamma) = 1/sqrt(M p^2 + q^2) - 1/sqrt(tau_y^2 + (eta/dt) gamma),
 * which is exactly linear for a purely deviatoric von Mises return (one
 * step) and mildly curved otherwise; a step that leaves the bracket is
 * replaced by bisection. Then eps = C^-1 tau (eps_vol = -p/K, eps_dev = s /
 * (2 mu)) and b^E = U exp(2 Lambda) U^T: this is F^E = U exp(Lambda) V^T of
 * §6.5 seen through b^E = F^E F^E^T; V (the rest-frame rotation) drops out
 * because the law is isotropic. The return needs only tr eps and |dev eps|
 * (it sets the volume and scales the deviator), so near the rest shape the
 * eigenvectors are not needed at all (below, "near the rest shape").
 *
 * ---- closed pores --------------------------------------------------------------
 * Eq. 12 is symmetric in p, so a dough under more pressure than
 * tau_y/sqrt(M) compacts plastically, and n^p = 1 - (1 - n^p_0) / J^P can
 * fall to zero (at J^P = 1 - n^p_0): the skeleton has closed its pores. Then the gas pressure of
 * eq. 13, n^g R theta / (J n^p), which the core adds explicitly after this
 * return, grows without bound and blows the body apart (seen: a 7 cm loaf
 * under its own weight). A solid cannot compact by more than its pore
 * volume, so plastic compaction is capped: J^P >= 1 - c n^p_0 with c the
 * parameter `compaction` (default 0.5: at most half the pores close, so
 * compaction at most doubles the gas pressure). n^p_0 is recovered from the
 * porosity the core passes, n^p_0 = 1 - (1 - n^p) J^P. Past the cap the
 * volume change stays elastic (the volumetric strain of the return is
 * shifted back towards the trial's). This is outside eq. 12; it only acts
 * on a return that would take n^p below (1 - c) n^p_0.
 *
 * ---- stiffening pores -------------------------------------------------------
 * The other way the same symmetry bites: a porous dough yields in tension
 * at tau_y / sqrt(M(n^p)), which falls to 0 as n^p -> 1, while the gas
 * pressure n^g R theta / n^p falls only like 1/n^p. Past n^p ~ 0.45 (where
 * n / sqrt(M(n)) peaks, ~0.385 tau_y of gas content held) a layer that
 * holds more gas inflates without end (with the gas volume fraction n^p the
 * core passes since issue #18's "The cookie's skin", the pore's gas volume
 * J n^p V_0 grows with J^P and both fall like 1/J^P far out), and the core's guard stops the run
 * (seen: muffin batter, CFL violated by a particle at 300 m/s). The cell
 * walls of a real dough stiffen as they are stretched thin, so a pore does
 * not grow without end; the parameter `max_porosity` says where: past it
 * the plastic dilation stops, J^P <= (1 - n^p_0) / (1 - max_porosity), and further
 * volume change is elastic (the gas is then held by elastic tension, p/K,
 * ~2% for 600 Pa at E 4e4). Default 1: no cap, eq. 12 as it stands.
 *
 * ---- crust fracture (issue #18; not in Ding et al.) ---------------------------
 * Eq. 12 yields in tension and flows; it never parts, so a dried crust over a
 * swelling crumb domes and holds (docs/validation.md, "Crust (#18)"). A crust
 * is brittle because it breaks before it yields: a glassy starch-gluten
 * matrix fractures at strains of a few per cent, while a rubbery dough's
 * gas cell walls stretch to Hencky strains of order 1 before they part (van
 * Vliet, Janssen, Bloksma & Walstra 1992, J. Texture Stud. 23, 439: strain
 * hardening and rupture of dough in biaxial extension; the glass transition
 * of bread crust with water content: van Nieuwenhuijzen et al. 2008, cited
 * in lua/hearth/dough.lua). The criterion here is a critical elastic strain:
 * the damage D is the largest fraction of the parameter `fracture_strain`
 * that the point's largest principal deviatoric elastic Hencky strain
 * (after the return) has reached, D = max over time of min(1, e1 / eps_f),
 * and D = 1 is a crack, for good. The elastic strain of this law is bounded
 * by its yield strain (q <= tau_y gives |dev eps| <= tau_y / (sqrt 6 mu)),
 * so eps_f below ~tau_y / E makes the point brittle (it cracks before it
 * yields) and eps_f above it ductile (it yields and never cracks): a
 * moisture curve on eps_f (small where dry) makes the crust brittle and
 * leaves the crumb ductile. The deviatoric part only: a uniform dilation is
 * the pores growing under their gas (eq. 13), not a crack. Rejected: (1) a
 * damage that sums the step's tensile stretching over eps_f (a
 * Johnson-Cook-like rule): it counts plastic flow, so the wet crumb, which
 * flows, built up damage everywhere, and the crust's damage rose evenly and
 * cracked the whole skin at once instead of one crack; (2) the total
 * principal elastic strain: the crumb's elastic dilation under its gas
 * counted. The damage is state (the 8th double) and the `damage` callback
 * reports it; the core then gives a cracked point no tension (each tensile
 * principal value of tau set to 0) and none of its pressure terms
 * (<hearth/material.h>, core/sim/material.h). fracture_strain = 0 (the
 * default) never cracks: Ding et al.'s law as it was, bit for bit.
 * The stretch rule (fracture_stretch = 1; issue #18, session 29): the rule
 * above cracks a crust as it dries, not as it is stretched. Drying raises E
 * and tau_y together on a point that keeps its elastic strain, so the dry
 * skin's yield strain is the wet dough's, and a point cracks the moment its
 * moisture curve takes eps_f below the strain it already holds: the whole
 * dry skin at once, as a band (docs/validation.md, Crust (#18)). Under this
 * rule D sums the stretch the point takes along its deviatoric elastic
 * strain, dD = sqrt(2/3) (e / |e|) : D dt / eps_f, D = sym grad_v (its
 * deviator: a dilation is the pores), each step over the fracture strain
 * the point has then: a Miner-like consumption of its extensibility, as a
 * ductile damage sums plastic strain over a strain to failure (Johnson &
 * Cook 1985, Eng. Fract. Mech. 21:31). So drying at rest adds nothing, a skin stretched while it is
 * brittle spends its small eps_f, and stretch taken back along e is given
 * back, so a vibration adds nothing. The direction e / |e| and not the
 * largest stretching: the largest eigenvalue of a deviator is never
 * negative, and with it an elastic crumb ringing about its rest shape
 * added up damage until it cracked wholesale (seen: 786 particles of the
 * bread loaf once it set). Plastic flow is counted as well as elastic
 * stretch (it is along e, the return being radial), so a raw dough, which
 * flows, needs a large eps_f (the bread preset's 100).
 * The set crumb (fracture_strain_set; issue #18, session 30): under the
 * stretch rule the strain to fracture is the smaller of fracture_strain and
 * fracture_strain_set (when > 0). Drying is one way a dough turns brittle; the
 * set is the other: past ~70 degC its starch has gelatinised and its gluten
 * coagulated, and the viscoelastic dough that flowed is a solid foam that
 * breaks in tension at finite strain (bread crumb pulled apart breaks at
 * 4-30 mm of elongation on 83 mm specimens, nominal 0.05-0.36: "Some tensile
 * characteristics of bread crumb", J. Texture Stud. 25:299, 1994; a set crumb
 * is a cellular solid, Scanlon & Zghal 2001, Food Res. Int. 34:841).
 * Under fracture_strain alone only the dried skin was brittle, and a crack
 * stopped about one particle deep in the wet crumb that flowed under it
 * (docs/validation.md, Crust (#18)); a set crumb carries it on. A separate
 * parameter, not a factor on fracture_strain: the two ways to brittleness
 * do not multiply (a dried crust that also sets is not 100 times more
 * brittle), the weaker one rules. Its temperature curve is irreversible in
 * the preset (lua/hearth/dough.lua, SET), so it follows the set's history.
 * The heat-set (fracture_unset; issue #18, helper crisp): drying alone does
 * not make a crust brittle. A batter or dough film that dries before the heat
 * has gelatinised its starch and set its gluten is a leathery film that
 * stretches; a crust is crisp when that heat-set starch-protein network is
 * dried below its glass transition (state diagrams over water: Roos & Karel
 * 1991, Food Technol. 45(12):66; a crust forms, sets and dries under the
 * heat: Vanin, Lucas & Trystram 2009, Trends Food Sci. Technol. 20:333; the
 * steam of the bake changes the surface's starch gelatinisation and
 * protein-starch network and with them the crust's failure force:
 * Altamirano-Fortoul, Le-Bail, Chevallier & Rosell 2012, J. Food Eng.
 * 108:128, from its abstract). A caveat: a crust's starch gelatinises only
 * in part for want of water (granular starch remains: Primo-Martin, van
 * Nieuwenhuijzen, Hamer & van Vliet 2007, J. Cereal Sci. 45:219, from its
 * abstract), so "set" is the heat's history, not a full gelatinisation.
 * Under the stretch rule the water's brittleness 1 / fracture_strain counts
 * times the point's set fraction 1 - fracture_unset: its strain to fracture
 * is fracture_strain / (1 - fracture_unset), none while raw (fracture_unset
 * = 1). Given a temperature curve, irreversible (the core evaluates it at the
 * highest temperature reached), it falls over the set's temperatures (the
 * preset's: the points of fracture_strain_set). It does not touch
 * fracture_strain_set, which is the set itself. A plugin parameter and not a
 * product of the core's temperature curve and moisture factor: those
 * multiply the value, and a point raw and dry would need fracture_strain
 * above its range (100 over the glassy 0.02). fracture_unset = 0 (the
 * default): the rule as it was, bit for bit.
 *
 * The crack band (crack_opening, crack_band; issue #18, helper tear): under
 * the stretch rule alone a point keeps its whole tension until D = 1 and
 * then has none, so nothing cracked first takes the load off its
 * neighbours, and a skin the rise stretches evenly cracked as a band one
 * particle thick (the muffin: 26 particles at 4 mm). A crack band (Bazant &
 * Oh 1983, Materiaux et Constructions 16:155) softens instead: past its
 * fracture strain (the Miner sum at 1, D = D_ON = 0.5) the point's tensile
 * principal stresses fall linearly from the peak's to 0 (D = 1) over a
 * further crack strain w_c / h - eps_f along N, w_c = crack_opening the
 * opening at which the crack carries nothing (Hillerborg, Modeer & Petersson
 * 1976, Cem. Concr. Res. 6:773: the fictitious crack, G_f = f_t w_c / 2 for
 * linear softening) and h = crack_band the band's width, the point's size.
 * The band's work per volume to separation, its elastic energy at the peak
 * f_t eps_f / 2 and the softening's f_t (w_c / h - eps_f) / 2, is then
 * f_t w_c / (2 h), and a crack takes G_f per unit area whatever the cell
 * (Bazant & Oh's crack strain: the softening is on the stretch past the
 * elastic one). Two choices make it so for a point that stays elastic
 * (issue #18, helper crackband; tests/unit_crack_band.c pulls a bar apart in
 * the MPM solver at three dx): the softening stretch is w_c / h - eps_f, not
 * w_c / h, and the tension falls from the peak's: an elastic point's
 * undamaged tension keeps growing past the peak, so it is taken at most at
 * the elastic strain of eps_f (band_strength). Before, the tension was the
 * undamaged one times 1 - x / (w_c / h): the elastic energy at the peak came
 * on top (h f_t eps_f / 2 per area, growing with the cell), the growing
 * tension added f_t (w_c / h)^2 h / (6 eps_f), and where w_c / h > eps_f the
 * band hardened past its peak and the softening ran into its neighbours
 * (the bar's band 4 cells wide at 1 mm, 8 at 0.5 mm; 2.4-4.6 G_f per area).
 * A point at its yield surface (its tension flat) takes h f_t (w_c / h -
 * eps_f) / 2 by softening, its pre-peak share spent as plastic work. A cell
 * too large for the band, w_c / h <= eps_f (h >= w_c / eps_f, Bazant & Oh's
 * limit on the element size, h < 2 E G_f / f_t^2), cannot take G_f at f_t:
 * there the point drops at its peak (D to 1), as without a band, and its
 * crack takes h f_t eps_f / 2 > G_f (the standard remedy, a strength
 * lowered to sqrt(2 E G_f / h), was not taken: it changes where a crust
 * cracks). w_c, not G_f, is the parameter: the presets' stresses are
 * animation-scaled (lua/hearth/dough.lua), and an opening is a length the
 * scaling leaves alone. Past the peak D only grows (a crack that has
 * started does not heal), and compression is carried whole, as the core's
 * cut-off at D = 1. The core knows nothing of it: the plugin scales its own
 * tau (the gas, water and thermal terms stay until D = 1). crack_opening = 0
 * (default): no band, the stretch rule as it was, bit for bit.
 *
 * ---- state ---------------------------------------------------------------------
 * Eight doubles: b^E (xx, yy, zz, xy, yz, zx), J^P and the damage D. Why b^E and not F^E:
 * the stress and the return depend only on b^E, its update f b f^T is
 * objective as it stands, it is symmetric (6 doubles), and its eigen
 * decomposition (Jacobi, or none near the rest shape) replaces the SVD of
 * F^E. J^P = det F / det F^E is stored after each return from the core's
 * total F, so the porosity of §5.4 never drifts from the deformation:
 * plastic_J returns it.
 *
 * ---- units -------------------------------------------------------------------------
 * g = 1/2 f^2 with f in Pa^2 makes eta a "viscosity" in Pa^3 s, exactly as
 * eq. 12 and §6.5 are written. The rate of plastic flow is then (1/eta) f
 * df/dtau, so a given eta is more viscous for a small tau_y: eta / tau_y^2
 * (in s/Pa) is the time scale that matters. Table 2's values (tau_y 20, eta
 * 500 for bread and cookies; tau_y 1, eta 10 for lava cake) are taken in
 * these units; see lua/hearth/dough.lua.
 *
 * dt = 0 evaluates the stress of the stored state without advancing it.
 */
#include <hearth/material.h>
#include <math.h>
#include <string.h>

#include <hearth/tensor.h>

#ifndef DOUGH_NAME
#define DOUGH_NAME "cam_clay_dough" /* the test fixture built from this file has its own */
#endif

enum { P_E, P_NU, P_TAU_Y, P_ETA, P_COMPACTION, P_DENSITY, P_MAX_POROSITY, P_FRACTURE_STRAIN, P_FRACTURE_STRETCH,
       P_FRACTURE_STRAIN_SET, P_CRACK_OPENING, P_CRACK_BAND, P_FRACTURE_UNSET, P_COUNT };

/* Defaults: the cookie column of Ding et al. Table 2 (E 4e4, tau_y 20,
 * eta 500, density 500); nu is not in Table 2. */
static const hearth_param params[P_COUNT] = {
    [P_E] = {"E", "Pa", "Young's modulus of the dough (Ding et al. Table 2: 2e3 bread .. 4e4 cookie)", 4e4, 1e-2, 1e12},
    [P_NU] = {"nu", "1", "Poisson's ratio (not in Ding et al.; 0.3 by default)", 0.3, 0.0, 0.49},
    [P_TAU_Y] = {"tau_y", "Pa", "yield stress tau_y of the Cam-clay surface (eq. 12); give it a temperature curve for Fig. 8",
                 20, 1e-6, 1e9},
    [P_ETA] = {"eta", "Pa^3 s", "viscoplastic penalty eta of §5.3 (g = f^2/2, f in Pa^2); 0 = rate-independent", 500, 0,
               1e12},
    [P_COMPACTION] = {"compaction", "1",
                      "fraction of the initial pore volume plastic compaction may close (J^P >= 1 - compaction n^p_0)",
                      0.5, 0, 1},
    [P_DENSITY] = {"density", "kg/m^3", "mass density at rest (Ding et al. Table 2: 500)", 500, 1e-3, 1e5},
    [P_MAX_POROSITY] = {"max_porosity", "1",
                        "porosity n^p past which the pores grow only elastically (J^P <= (1 - n^p_0) / (1 - max_porosity)); 1 = no cap",
                        1, 1e-3, 1},
    [P_FRACTURE_STRAIN] = {"fracture_strain", "1",
                           "elastic strain to fracture (damage = largest deviatoric elastic strain / fracture_strain; at 1 the "
                           "point carries no tension); small where dry (a moisture curve) for a brittle crust; 0 = never",
                           0, 0, 100},
    [P_FRACTURE_STRETCH] = {"fracture_stretch", "1",
                            "1: damage sums the stretch the point takes (largest principal deviatoric stretching, elastic "
                            "and plastic) over its fracture_strain at the time, so drying alone never cracks; 0: the "
                            "elastic strain rule (a switch: a blend of the two reads as 1 above 0.5)",
                            0, 0, 1},
    [P_FRACTURE_STRAIN_SET] = {"fracture_strain_set", "1",
                               "the stretch rule's strain to fracture of the set crumb (give it a temperature curve, "
                               "irreversible): under fracture_stretch = 1 a point's strain to fracture is the smaller of "
                               "fracture_strain and this; 0 = none",
                               0, 0, 100},
    [P_CRACK_OPENING] = {"crack_opening", "m",
                         "the stretch rule's crack band (Bazant & Oh 1983): the opening w_c at which a crack carries no "
                         "more tension (G_f = f_t w_c / 2); past its fracture strain a point softens from its peak over the "
                         "crack strain w_c / crack_band - fracture_strain (<= 0: it cracks at its peak); 0 = no "
                         "softening (the point cracks at once)",
                         0, 0, 1},
    [P_CRACK_BAND] = {"crack_band", "m",
                      "the crack band's width h, the point's size (a scene's h.material gets its cell size when the "
                      "preset gives 0); softening needs both crack_opening and crack_band > 0",
                      0, 0, 10},
    [P_FRACTURE_UNSET] = {"fracture_unset", "1",
                          "how far the point is from its heat-set, 1 raw to 0 set (give it a temperature curve, "
                          "irreversible): under fracture_stretch = 1 its fracture_strain counts as fracture_strain / "
                          "(1 - fracture_unset), so a skin that dries before it sets stretches as leather; 0 = set",
                          0, 0, 1},
};

enum { S_XX = HEARTH_SYM_XX, S_YY = HEARTH_SYM_YY, S_ZZ = HEARTH_SYM_ZZ, S_XY = HEARTH_SYM_XY, S_YZ = HEARTH_SYM_YZ,
       S_ZX = HEARTH_SYM_ZX, S_JP, S_DAMAGE, S_COUNT };

enum {
    E_INVERTED = 1, /* det F <= 0 or not finite */
    E_STEP = 2,     /* grad_v not finite, or det(I + dt grad_v) <= 0 */
    E_STATE = 3,    /* stored b^E not finite or not positive definite */
    E_POROSITY = 4, /* porosity outside [0, 1) */
    E_SOLVE = 5     /* the return map produced a non-finite strain (overflow) */
};

static const double SQRT2 = 1.41421356237309504880;

/* The porosity coefficient of eq. 12; 0 at n = 0 (von Mises). */
static double porosity_coefficient(double n) {
    if (!(n > 0)) return 0;
    const double l = log(1 / n);
    return 9.0 / (4.0 * l * l * (3.5 * n + 1.0));
}

/* The plane-strain case, which is every point of a 2D scene: b^E and the
 * step's f have no out-of-plane shear, so b^E is a 2x2 block plus its zz
 * entry, and the trial, the eigen-decomposition and the rebuild need only
 * that block. These do the same arithmetic as the general path with its
 * zero terms left out (the Jacobi below takes the same single rotation),
 * at a third of its cost: the plugin was over a third of a 2D dough step. */
static int is_plane(const double *st, const double *gv, double dt) {
    return st[S_YZ] == 0 && st[S_ZX] == 0 && (!(dt > 0) || (gv[2] == 0 && gv[5] == 0 && gv[6] == 0 && gv[7] == 0));
}

/* b_tr = f b f^T on the block, and f_zz^2 b_zz. Returns det f. */
static double trial_plane(const double *gv, double dt, double B[9]) {
    const double f0 = 1 + dt * gv[0], f1 = dt * gv[1], f3 = dt * gv[3], f4 = 1 + dt * gv[4], f8 = 1 + dt * gv[8];
    const double g0 = f0 * B[0] + f1 * B[3], g1 = f0 * B[1] + f1 * B[4];
    const double g3 = f3 * B[0] + f4 * B[3], g4 = f3 * B[1] + f4 * B[4];
    B[0] = g0 * f0 + g1 * f1;
    B[1] = B[3] = g0 * f3 + g1 * f4;
    B[4] = g3 * f3 + g4 * f4;
    B[8] *= f8 * f8;
    return (f0 * f4 - f1 * f3) * f8;
}

/* One Jacobi rotation diagonalises the block: the sym_eigen step below,
 * written with its tangent t = sgn(h) b / w, h = (b_yy - b_xx)/2,
 * r = sqrt(h^2 + b^2), w = |h| + r, so cos = sqrt(w / 2r) and
 * sin = sgn(h) b / sqrt(2 r w): three dependent square roots and divisions
 * instead of five (this chain was a fifth of the plugin's time in 2D). */
static void eigen_plane(const double B[9], double l[3], double Q[9]) {
    for (int i = 0; i < 9; i++) Q[i] = i % 4 == 0;
    l[0] = B[0], l[1] = B[4], l[2] = B[8];
    const double b = B[1];
    if (b == 0) return;
    const double h = 0.5 * (B[4] - B[0]), r = sqrt(h * h + b * b), w = fabs(h) + r;
    const double sb = h >= 0 ? b : -b, tb = sb * b / w; /* t b */
    const double c = sqrt(w / (2 * r)), sn = sb / sqrt(2 * r * w);
    l[0] -= tb;
    l[1] += tb;
    Q[0] = c, Q[1] = sn, Q[3] = -sn, Q[4] = c;
}

static void from_eigen_plane(const double Q[9], const double d[3], double A[9]) {
    A[0] = Q[0] * d[0] * Q[0] + Q[1] * d[1] * Q[1];
    A[1] = A[3] = Q[0] * d[0] * Q[3] + Q[1] * d[1] * Q[4];
    A[4] = Q[3] * d[0] * Q[3] + Q[4] * d[1] * Q[4];
    A[2] = A[6] = A[5] = A[7] = 0;
    A[8] = d[2];
}

/* Symmetric eigen-decomposition S = Q diag(l) Q^T by cyclic Jacobi, for
 * this plugin's hot path: <hearth/tensor.h>'s hearth_t3_sym_eigen is the same method,
 * but sorts and takes the rotation's tangent through hypot, which made up
 * a third of a 3D dough step. Here the tangent uses sqrt (with a guard for
 * a huge zeta, where 1 + zeta^2 would overflow), nothing is sorted (the
 * return map does not need an order), and a 2D (plane-strain) b^E, whose
 * xz and yz entries are exactly 0, takes one rotation. Stops when the
 * off-diagonal part is below 1e-15 of the whole, as hearth_t3_sym_eigen does. */
static void sym_eigen(const double S[9], double l[3], double Q[9]) {
    double a[9];
    for (int i = 0; i < 3; i++)
        for (int j = i; j < 3; j++) a[3 * i + j] = a[3 * j + i] = S[3 * i + j];
    for (int i = 0; i < 9; i++) Q[i] = i % 4 == 0;
    double norm2 = 0;
    for (int i = 0; i < 9; i++) norm2 += a[i] * a[i];
    const double tol2 = 1e-30 * norm2;
    static const int PP[3] = {0, 0, 1}, QQ[3] = {1, 2, 2};
    for (int sweep = 0; sweep < 50; sweep++) {
        if (2 * (a[1] * a[1] + a[2] * a[2] + a[5] * a[5]) <= tol2) break;
        for (int k = 0; k < 3; k++) {
            const int p = PP[k], q = QQ[k], r = 3 - p - q;
            const double apq = a[3 * p + q];
            if (apq == 0) continue;
            const double zeta = (a[4 * q] - a[4 * p]) / (2 * apq);
            const double t = fabs(zeta) > 1e150 ? 0.5 / zeta
                                                : (zeta >= 0 ? 1 : -1) / (fabs(zeta) + sqrt(1 + zeta * zeta));
            const double c = 1 / sqrt(1 + t * t), sn = t * c;
            const double arp = a[3 * r + p], arq = a[3 * r + q];
            a[3 * r + p] = a[3 * p + r] = c * arp - sn * arq;
            a[3 * r + q] = a[3 * q + r] = sn * arp + c * arq;
            a[4 * p] -= t * apq;
            a[4 * q] += t * apq;
            a[3 * p + q] = a[3 * q + p] = 0;
            for (int i = 0; i < 3; i++) {
                const double qp = Q[3 * i + p], qq = Q[3 * i + q];
                Q[3 * i + p] = c * qp - sn * qq;
                Q[3 * i + q] = sn * qp + c * qq;
            }
        }
    }
    l[0] = a[0], l[1] = a[4], l[2] = a[8];
}

/* The multiplier gamma of the return (header): root of phi(gamma) = 0 with
 * phi(0) = f_tr > 0. Pm = sqrt(M) |p_tr|, a = 2 K M, b = 6 mu, ty2 = tau_y^2,
 * c = eta/dt (0 for rate-independent). */
static double solve_gamma(double Pm, double a, double qt, double b, double ty2, double c) {
    const double ty = sqrt(ty2);
    double gp = Pm > ty / SQRT2 && a > 0 ? (SQRT2 * Pm / ty - 1) / a : 0;
    double gq = qt > ty / SQRT2 ? (SQRT2 * qt / ty - 1) / b : 0;
    double lo = 0, hi = fmax(gp, gq);
    if (!(hi > 0) || !isfinite(hi)) return 0;
    double g = 0;
    for (int it = 0; it < 200; it++) {
        const double up = 1 / (1 + a * g), uq = 1 / (1 + b * g);
        const double P = Pm * up, Q = qt * uq;
        const double r2 = P * P + Q * Q, r = sqrt(r2);
        const double y2 = ty2 + c * g, y = sqrt(y2);
        const double chi = 1 / r - 1 / y; /* increasing in gamma, < 0 below the root */
        if (chi < 0) lo = g;
        else if (chi > 0) hi = g;
        else return g;
        /* d(1/r)/dg = -(1/r^3) (P dP + Q dQ), dP = -a P up, dQ = -b Q uq; d(1/y)/dg = -c / (2 y^3) */
        const double dr = (a * P * P * up + b * Q * Q * uq) / (r2 * r);
        const double dchi = dr + 0.5 * c / (y2 * y);
        double gn = dchi > 0 ? g - chi / dchi : 0.5 * (lo + hi);
        if (!(gn > lo && gn < hi)) gn = 0.5 * (lo + hi); /* safeguard: bisection */
        if (fabs(gn - g) <= 4e-16 * gn || hi - lo <= 4e-16 * hi) return gn;
        g = gn;
    }
    return g;
}

/* The return on the invariants of the trial Hencky strain: its volume part
 * *ev = tr eps_tr and the squared norm s2 of its deviator e, at porosity n.
 * Returns 1 on plastic flow, with *ev the returned volume part and *ratio the
 * deviator's scale (eps = ev/3 I + ratio e, header); 0 inside the surface. */
static int return_map(const double *prm, double mu, double lambda, double n, double dt, double s2, double *ev,
                      double *ratio) {
    const double K = lambda + 2.0 / 3.0 * mu;
    const double pt = -K * *ev; /* p = -tr(tau)/3 = -K tr(eps) */
    const double qt = 2 * mu * sqrt(1.5 * s2);
    const double ty = prm[P_TAU_Y], ty2 = ty * ty;
    /* Most points are inside the surface, and M(n)'s log was a tenth of the
     * law's instructions. ln(1/n) >= 1 - n bounds M from above without a log
     * (widened by 1e-7, far beyond the few roundings of either), and every
     * rounded step of f is monotone in M (p_tr^2 >= 0), so a trial inside the
     * bound's surface is inside eq. 12's: the same answer, and M is computed
     * only for the rest. */
    if (n > 0) {
        const double u = 1 - n, Mb = 9.0 * (1 + 1e-7) / (4.0 * u * u * (3.5 * n + 1.0));
        if (!(Mb * pt * pt + qt * qt - ty2 > 0)) return 0;
    }
    const double M = porosity_coefficient(n);
    const double ftr = M * pt * pt + qt * qt - ty2;
    if (!(ftr > 0)) return 0; /* inside (or on) the surface: elastic */
    const double eta = prm[P_ETA];
    const double c = dt > 0 && eta > 0 ? eta / dt : 0;
    const double g = solve_gamma(sqrt(M) * fabs(pt), 2 * K * M, qt, 6 * mu, ty2, c);
    *ev = -pt / (1 + 2 * K * M * g) / K;
    *ratio = 1 / (1 + 6 * mu * g);
    return 1;
}

/* The returned volume part ev (ev0 the trial's) held within the pore caps
 * (header, "closed pores" and "stiffening pores"); n the porosity at the
 * step's start, JP the stored J^P, J = det F. */
static double cap_volume(const double *prm, double n, double JP, double J, double ev0, double ev) {
    const double n0 = 1 - (1 - n) * JP; /* n^p = 1 - (1 - n^p_0) / J^P (core/sim/fields/gas.h) */
    const double jmin = 1 - prm[P_COMPACTION] * n0;
    if (ev > ev0 && n0 > 0 && jmin > 0 && J / exp(ev) < jmin) /* ev > ev0: the return compacted */
        ev = fmax(log(J / jmin), ev0);
    const double jmax = (1 - n0) / (1 - prm[P_MAX_POROSITY]); /* +inf at max_porosity 1: no cap */
    if (prm[P_MAX_POROSITY] < 1 && J / exp(ev) > jmax && ev < ev0) /* ev < ev0: the return dilated */
        ev = fmin(log(J / jmax), ev0);
    return ev;
}

/* ---- near the rest shape, without the eigen-decomposition --------------------
 * A dough's elastic strain is small: its deviator is bounded by the yield
 * stress, q <= tau_y, so |dev eps| <= tau_y / (sqrt(6) mu), ~1e-2 for a set
 * cookie. There log b and exp(2 eps) are short power series in b's deviatoric
 * part, and the return above needs no eigenvectors (it scales the deviator
 * and sets the volume), so the whole step is a few 3x3 products. The cyclic
 * Jacobi takes 4-5 sweeps of rotations whose sqrt and division chain was
 * over half of a 3D dough step. Used when b / m, m = tr(b)/3 its mean
 * eigenvalue, is within NEAR = 0.1 of I (Frobenius); beyond it, the eigen
 * path. The series are summed until the next term is below 1e-16
 * of the first, so both paths agree to rounding (dough_near_identity_return). */
enum { NEAR_MAX_TERMS = 40 };
static const double NEAR = 0.1;

static inline void sym_mul(const double A[9], const double B[9], double C[9]) { /* C = A B for commuting symmetric A, B */
    double T[9];
    for (int r = 0; r < 3; r++)
        for (int c = r; c < 3; c++)
            T[3 * r + c] = T[3 * c + r] = A[3 * r] * B[c] + A[3 * r + 1] * B[3 + c] + A[3 * r + 2] * B[6 + c];
    memcpy(C, T, sizeof T);
}

static double norm2_9(const double A[9]) {
    double s = 0;
    for (int i = 0; i < 9; i++) s += A[i] * A[i];
    return s;
}

/* log(I + D) for symmetric |D| <= NEAR, by the Gregory series
 * 2 (Z + Z^3/3 + Z^5/5 + ...), Z = D (2I + D)^-1, |Z| <= |D| / (2 - |D|). */
static void log_near(const double D[9], double L[9]) {
    double S[9], C[9], Z[9], W[9], P[9];
    for (int i = 0; i < 9; i++) S[i] = D[i] + 2 * (i % 4 == 0);
    C[0] = S[4] * S[8] - S[5] * S[5], C[1] = S[2] * S[5] - S[1] * S[8], C[2] = S[1] * S[5] - S[2] * S[4];
    C[4] = S[0] * S[8] - S[2] * S[2], C[5] = S[1] * S[2] - S[0] * S[5], C[8] = S[0] * S[4] - S[1] * S[1];
    C[3] = C[1], C[6] = C[2], C[7] = C[5];
    const double inv_det = 1 / (S[0] * C[0] + S[1] * C[1] + S[2] * C[2]);
    for (int i = 0; i < 9; i++) C[i] *= inv_det;
    sym_mul(D, C, Z);
    sym_mul(Z, Z, W);
    const double d = sqrt(norm2_9(D)), z2 = (d / (2 - d)) * (d / (2 - d));
    int J = 0;
    for (double t = z2; t > 1e-16 && J < NEAR_MAX_TERMS; t *= z2) J++;
    for (int i = 0; i < 9; i++) P[i] = (i % 4 == 0) / (2.0 * J + 1);
    for (int j = J - 1; j >= 0; j--) { /* P = I/(2j+1) + W P */
        sym_mul(W, P, P);
        for (int i = 0; i < 9; i += 4) P[i] += 1.0 / (2 * j + 1);
    }
    sym_mul(Z, P, L);
    for (int i = 0; i < 9; i++) L[i] *= 2;
}

/* exp(X) for symmetric X with |X| <= 2 NEAR, by its Taylor series (Horner). */
static void exp_near(const double X[9], double E[9]) {
    const double x = sqrt(norm2_9(X));
    int K = 1;
    for (double t = x; t > 1e-17 && K < NEAR_MAX_TERMS; t *= x / (K + 1)) K++;
    for (int i = 0; i < 9; i++) E[i] = (i % 4 == 0) + X[i] / K;
    for (int k = K - 1; k >= 1; k--) { /* E = I + X E / k */
        sym_mul(X, E, E);
        for (int i = 0; i < 9; i++) E[i] = (i % 4 == 0) + E[i] / k;
    }
}

/* The largest eigenvalue of a symmetric deviatoric 3x3 (tr e = 0), by the
 * trigonometric closed form: no iteration on the near path. */
static double dev_max_eigen(const double e[9]) {
    const double p2 = e[0] * e[0] + e[4] * e[4] + e[8] * e[8] + 2 * (e[1] * e[1] + e[2] * e[2] + e[5] * e[5]);
    if (!(p2 > 0)) return 0;
    const double pp = sqrt(p2 / 6);
    const double det = e[0] * (e[4] * e[8] - e[5] * e[5]) - e[1] * (e[1] * e[8] - e[5] * e[2]) + e[2] * (e[1] * e[5] - e[4] * e[2]);
    const double r = fmax(-1, fmin(1, det / (2 * pp * pp * pp)));
    return 2 * pp * cos(acos(r) / 3);
}

/* Damage (header, "crust fracture"): the largest fraction of its strain to
 * fracture that the point's largest principal deviatoric elastic strain e1
 * has reached; 1 is cracked, for good. */
static void fracture_update(double ef, double *st, double e1) {
    if (ef > 0 && e1 > 0 && st[S_DAMAGE] < 1) st[S_DAMAGE] = fmax(st[S_DAMAGE], fmin(1, e1 / ef));
}

/* Damage by the stretch taken (header, "crust fracture", fracture_stretch =
 * 1): the step adds the stretch it takes along the point's elastic strain,
 * dt sqrt(2/3) N : D, with N = e / |e| the direction of the deviatoric
 * elastic strain after the return and D the stretching sym grad_v (elastic
 * and plastic alike; N is traceless, so no uniform dilation), over the
 * fracture strain the point has now; a step back along N gives it back (a
 * vibration adds nothing), and D never falls below 0 or rises again from 1.
 * A point that dries while at rest gains nothing; a skin the rise stretches
 * while it is brittle spends its small fracture strain. nd = N : D.
 * With a crack band (header, "the crack band") the same sum fills D up to
 * D_ON, the peak; past it D counts the stretch over the band's crack strain
 * w_c / h - eps_f, only forward: a crack that has started does not heal. */
#define D_ON 0.5
static double band_strain(const double *prm) { /* w_c / h, 0 without a crack band */
    const double wc = prm[P_CRACK_OPENING], h = prm[P_CRACK_BAND];
    return wc > 0 && h > 0 ? wc / h : 0;
}

/* The point's strain to fracture now: fracture_strain over the heat-set's
 * share (fracture_unset), or the set crumb's when smaller; HUGE_VAL raw. */
static double fracture_strain_now(const double *prm) {
    double ef = prm[P_FRACTURE_STRAIN];
    const double un = prm[P_FRACTURE_UNSET]; /* the heat-set's share of the water's brittleness (header) */
    if (un > 0) ef = un < 1 ? ef / (1 - un) : HUGE_VAL;
    const double es = prm[P_FRACTURE_STRAIN_SET]; /* the set crumb's (header, "the set crumb") */
    if (es > 0 && es < ef) ef = es;
    return ef;
}

static void fracture_stretch_update(const double *prm, double *st, double nd, double dt) {
    if (!(prm[P_FRACTURE_STRAIN] > 0) || st[S_DAMAGE] >= 1 || !(nd == nd)) return;
    const double ef = fracture_strain_now(prm);
    const double de = 0.816496580927726 * nd * dt; /* sqrt(2/3) N : D dt, the stretch along N */
    const double eb = band_strain(prm);
    if (!(eb > 0)) {
        st[S_DAMAGE] = fmin(1, fmax(0, st[S_DAMAGE] + de / ef));
        return;
    }
    const double u = eb - ef; /* the crack strain to separation (header); none: the band drops at its peak */
    double d = st[S_DAMAGE];
    if (d < D_ON) {
        d = fmax(0, d + D_ON * de / ef);
        if (d > D_ON) d = u > 0 ? D_ON + (1 - D_ON) * ((d - D_ON) / D_ON * ef) / u : 1; /* the stretch past the peak */
    } else if (de > 0) {
        d = u > 0 ? d + (1 - D_ON) * de / u : 1;
    }
    st[S_DAMAGE] = fmin(1, d);
}

/* The band's strength past its peak (header, "the crack band"): with
 * w = (D - D_ON) / (1 - D_ON), the tension falls linearly from the peak's,
 * (1 - w) times the tension of the elastic strain at fracture. The
 * undamaged tension of a point that stays elastic keeps growing past the
 * peak (its deviatoric elastic strain el, the return's, grows as sqrt(3/2)
 * times the stretch), so it is taken at most at that of the point's
 * fracture strain, el_f = sqrt(3/2) eps_f: the factor el_f / el. A point at
 * its yield surface (el <= el_f) keeps its tension. 1 before the peak or
 * without a band. */
static double band_strength(const double *prm, const double *st, double el) {
    if (!(prm[P_FRACTURE_STRETCH] > 0.5) || !(band_strain(prm) > 0) || !(st[S_DAMAGE] > D_ON)) return 1;
    const double w = fmin(1, (st[S_DAMAGE] - D_ON) / (1 - D_ON));
    const double ef = 1.224744871391589 * fracture_strain_now(prm); /* sqrt(3/2) eps_f */
    return el > ef ? (1 - w) * (ef / el) : 1 - w;
}

/* tau with each tensile principal value times r (the band's strength): a
 * softening crack carries compression whole, as the core's cut-off at D = 1. */
static void band_soften(double tau[9], double r) {
    double l[3], Q[9];
    hearth_t3_sym_eigen(tau, l, Q);
    for (int k = 0; k < 3; k++)
        if (l[k] > 0) l[k] *= r;
    hearth_sym_from_eigen(Q, l, tau);
}

/* N : D for the deviator e (a symmetric 3x3) and the step's grad_v. */
static double dir_stretch_full(const double e[9], const double *gv) {
    const double n2 = norm2_9(e);
    if (!(n2 > 0)) return 0;
    const double tr = (gv[0] + gv[4] + gv[8]) / 3; /* dev D: a dilation adds nothing even to a roundoff e */
    double s = 0;
    for (int r = 0; r < 3; r++)
        for (int c = 0; c < 3; c++) s += e[3 * r + c] * (0.5 * (gv[3 * r + c] + gv[3 * c + r]) - (r == c) * tr);
    return s / sqrt(n2);
}

/* N : D for the deviator with principal values e[k] on Q's columns. */
static double dir_stretch_eigen(const double e[3], const double Q[9], const double *gv) {
    const double n2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    if (!(n2 > 0)) return 0;
    const double tr = (gv[0] + gv[4] + gv[8]) / 3; /* dev D, as dir_stretch_full */
    double s = 0;
    for (int k = 0; k < 3; k++) {
        double dq = -tr; /* q_k . dev D q_k = q_k . grad_v q_k - tr/3 */
        for (int r = 0; r < 3; r++)
            for (int c = 0; c < 3; c++) dq += Q[3 * r + k] * gv[3 * r + c] * Q[3 * c + k];
        s += e[k] * dq;
    }
    return s / sqrt(n2);
}

static void init(const double *p, double *state) {
    (void)p;
    state[S_XX] = state[S_YY] = state[S_ZZ] = 1;
    state[S_XY] = state[S_YZ] = state[S_ZX] = 0;
    state[S_JP] = 1;
    state[S_DAMAGE] = 0;
}

/* The Kirchhoff stress tau = lambda ev I + 2 mu eps of eps = ev/3 I + ratio e
 * (e the trial deviator as a matrix, the return's scale ratio). */
static void hencky_tau(double mu, double lambda, double ev, const double e[9], double ratio, double tau[9]) {
    for (int i = 0; i < 9; i++) tau[i] = 2 * mu * ratio * e[i];
    const double iso = lambda * ev + 2 * mu * ev / 3;
    tau[0] += iso, tau[4] += iso, tau[8] += iso;
}

/* The step on the near path (above): B is the trial b^E, its mean
 * eigenvalue m = tr(B)/3 > 0 and |B/m - I| <= NEAR. log B = log(m) I +
 * log(B/m): B/m is near I whatever the volume change, and this needs no
 * cube root of det B. */
static int stress_near(hearth_point *pt, double mu, double lambda, double m, const double B[9], double J, double tau[9]) {
    const double *prm = pt->p;
    double *st = pt->state;
    double D[9], L[9], e[9];
    const double sc = 1 / m;
    for (int i = 0; i < 9; i++) D[i] = sc * B[i] - (i % 4 == 0);
    log_near(D, L);
    const double trL = L[0] + L[4] + L[8];
    for (int i = 0; i < 9; i++) e[i] = 0.5 * (L[i] - (i % 4 == 0) * trL / 3); /* dev eps = 1/2 dev log(B/m) */
    const double ev0 = 1.5 * log(m) + 0.5 * trL;                              /* tr eps = 1/2 tr log B */
    double ev = ev0, ratio = 1;
    if (pt->dt > 0) {
        if (return_map(prm, mu, lambda, pt->porosity, pt->dt, norm2_9(e), &ev, &ratio)) {
            ev = cap_volume(prm, pt->porosity, st[S_JP], J, ev0, ev);
            double X[9], E[9], Bn[9];
            for (int i = 0; i < 9; i++) X[i] = 2 * ratio * e[i];
            exp_near(X, E);
            const double v = exp(2 * ev / 3);
            if (!isfinite(v) || !(v > 0)) return E_SOLVE;
            for (int i = 0; i < 9; i++) Bn[i] = v * E[i];
            hearth_full_to_sym(Bn, st);
        } else {
            hearth_full_to_sym(B, st);
        }
        st[S_JP] = J / exp(ev); /* J^P = J / J^E */
        if (prm[P_FRACTURE_STRAIN] > 0) { /* its trig only when asked */
            if (prm[P_FRACTURE_STRETCH] > 0.5) fracture_stretch_update(prm, st, dir_stretch_full(e, pt->grad_v), pt->dt);
            else fracture_update(prm[P_FRACTURE_STRAIN], st, ratio * dev_max_eigen(e));
        }
    }
    hencky_tau(mu, lambda, ev, e, ratio, tau);
    const double r = band_strength(prm, st, ratio * sqrt(norm2_9(e)));
    if (r < 1) band_soften(tau, r);
    return 0;
}

/* The law at one point, given J = det F (the only way it reads F) and the
 * Lame constants of its parameters: stress and stress_block share it. */
static int stress_law(hearth_point *pt, double J, double mu, double lambda, double tau[9]) {
    const double *prm = pt->p;
    if (!(J > 0) || !isfinite(J)) return E_INVERTED;
    double *st = pt->state;
    double z = 0; /* x - x is 0 for a finite x and NaN otherwise: one test instead of eight */
    for (int i = 0; i < S_COUNT; i++) z += st[i] - st[i];
    if (!(z == 0)) return E_STATE;
    const double n = pt->porosity;
    if (n < 0 || n >= 1) return E_POROSITY; /* NaN reads as 0: von Mises */
    double B[9];
    hearth_sym_to_full(st, B);
    const int plane = is_plane(st, pt->grad_v, pt->dt);
    if (pt->dt > 0) { /* trial b_tr = f b f^T */
        double jf;
        if (plane) {
            jf = trial_plane(pt->grad_v, pt->dt, B);
        } else { /* f B, then the upper triangle of (f B) f^T */
            double f[9], G[9];
            for (int i = 0; i < 9; i++) f[i] = (i % 4 == 0) + pt->dt * pt->grad_v[i];
            jf = hearth_t3_det(f);
            for (int r = 0; r < 3; r++)
                for (int c = 0; c < 3; c++) G[3 * r + c] = f[3 * r] * B[c] + f[3 * r + 1] * B[3 + c] + f[3 * r + 2] * B[6 + c];
            for (int r = 0; r < 3; r++)
                for (int c = r; c < 3; c++)
                    B[3 * r + c] = B[3 * c + r] = G[3 * r] * f[3 * c] + G[3 * r + 1] * f[3 * c + 1] + G[3 * r + 2] * f[3 * c + 2];
        }
        if (!(jf > 0) || !isfinite(jf)) return E_STEP;
    }
    if (!plane) {
        const double m = (B[0] + B[4] + B[8]) / 3;
        if (m > 0 && norm2_9(B) / (m * m) - 3 <= NEAR * NEAR) /* |B/m - I|^2 = |B/m|^2 - 3, as tr(B/m) = 3 */
            return stress_near(pt, mu, lambda, m, B, J, tau);
    }
    double l[3], Q[9], eps[3];
    if (plane) eigen_plane(B, l, Q);
    else sym_eigen(B, l, Q);
    if (!(l[0] > 0 && l[1] > 0 && l[2] > 0) || !isfinite(l[0] + l[1] + l[2])) return E_STATE;
    for (int i = 0; i < 3; i++) eps[i] = 0.5 * log(l[i]);
    double ev = eps[0] + eps[1] + eps[2];
    const double ev0 = ev;
    double e[3], s2 = 0, ratio = 1;
    for (int i = 0; i < 3; i++) {
        e[i] = eps[i] - ev0 / 3; /* deviatoric strain; s = 2 mu e */
        s2 += e[i] * e[i];
    }
    if (pt->dt > 0) {
        if (return_map(prm, mu, lambda, n, pt->dt, s2, &ev, &ratio)) {
            ev = cap_volume(prm, n, st[S_JP], J, ev0, ev);
            double d[3];
            for (int i = 0; i < 3; i++) d[i] = exp(2 * (ev / 3 + ratio * e[i]));
            if (!isfinite(d[0] + d[1] + d[2]) || !(d[0] > 0 && d[1] > 0 && d[2] > 0)) return E_SOLVE;
            if (plane) from_eigen_plane(Q, d, B);
            else hearth_sym_from_eigen(Q, d, B);
        }
        hearth_full_to_sym(B, st);
        st[S_JP] = J / exp(ev); /* J^P = J / J^E (a crack opens as plastic volume: it reads as pores) */
        if (prm[P_FRACTURE_STRETCH] > 0.5) fracture_stretch_update(prm, st, dir_stretch_eigen(e, Q, pt->grad_v), pt->dt);
        else fracture_update(prm[P_FRACTURE_STRAIN], st, ratio * fmax(e[0], fmax(e[1], e[2])));
    }
    const double tv = lambda * ev, r = band_strength(prm, st, ratio * sqrt(s2));
    double d[3];
    for (int i = 0; i < 3; i++) {
        d[i] = tv + 2 * mu * (ev / 3 + ratio * e[i]);
        if (r < 1 && d[i] > 0) d[i] *= r; /* the crack band's softening (band_soften) */
    }
    if (plane) from_eigen_plane(Q, d, tau);
    else hearth_sym_from_eigen(Q, d, tau);
    return 0;
}

static int stress(hearth_point *pt, double tau[9]) {
    double mu, lambda;
    hearth_lame(pt->p[P_E], pt->p[P_NU], &mu, &lambda);
    return stress_law(pt, hearth_t3_det(pt->F), mu, lambda, tau);
}

/* Small-strain P-wave speed sqrt((lambda + 2 mu)/rho): the Hencky law's
 * tangent at rest; plastic flow only softens it. */
static inline double p_wave_speed(double E, double nu, double rho) {
    /* lambda + 2 mu = E (1 - nu) / ((1 + nu)(1 - 2 nu)): one division, per particle per step */
    return sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu) * rho));
}

static double wave_speed(const double *p, const double *state) {
    (void)state;
    return p_wave_speed(p[P_E], p[P_NU], p[P_DENSITY]);
}

/* K = lambda + 2/3 mu = E / (3 (1 - 2 nu)): the Hencky law's bulk modulus,
 * with which the core makes eq. 10's thermal term a thermal strain
 * (<hearth/material.h>, bulk_modulus). */
static inline double p_bulk_modulus(double E, double nu) { return E / (3 * (1 - 2 * nu)); }

static double bulk_modulus(const double *p, const double *state) {
    (void)state;
    return p_bulk_modulus(p[P_E], p[P_NU]);
}

static double plastic_J(const double *p, const double *state) {
    (void)p;
    return state ? state[S_JP] : 1.0;
}

/* Damage D in [0, 1]; at 1 the core cuts the point's stress off in tension.
 * Without a state: whether these parameters may crack (fracture_strain > 0). */
static double damage(const double *p, const double *state) {
    if (!state) return p[P_FRACTURE_STRAIN] > 0;
    return state[S_DAMAGE];
}

/* the batched stress and scalars (rules 7 and 9): one translation unit, so an outside author still builds the
 * plugin with one cc command (tests/plugin_sdk_test.sh) */
#include "cam_clay_dough_block.h"

static const char *describe_error(int code) {
    switch (code) {
    case E_INVERTED: return "inverted element (det F <= 0)";
    case E_STEP: return "grad_v is not finite, or the step inverts: det(I + dt grad_v) <= 0";
    case E_STATE: return "elastic state b^E is not finite or not positive definite";
    case E_POROSITY: return "porosity n^p outside [0, 1) (Ding et al. eq. 12 needs 0 <= n^p < 1)";
    case E_SOLVE: return "the return map overflowed: elastic Hencky strain beyond exp range";
    default: return "unknown error";
    }
}

static const hearth_material material = {
    .abi_version = HEARTH_MATERIAL_ABI,
    .struct_size = sizeof(hearth_material),
    .real_size = sizeof(double),
    .name = DOUGH_NAME,
    .summary = "dough: Hencky elasticity, viscoplastic porous Cam-clay yield (Ding et al. 2019 eq. 12, §6.5)",
    .params = params,
    .nparams = P_COUNT,
    .state_size = S_COUNT,
    .needs = HEARTH_NEEDS_TEMPERATURE | HEARTH_NEEDS_POROSITY | HEARTH_NEEDS_THERMAL_EXPANSION | HEARTH_NEEDS_MEMO,
    .init = init,
    .stress = stress,
    .wave_speed = wave_speed,
    .describe_error = describe_error,
    .plastic_J = plastic_J,
    .damage = damage,
    .stress_block = stress_block,
    .bulk_modulus = bulk_modulus,
    .scalars_block = scalars_block,
    .memo_size = 2, /* log b_zz's argument and value (log_memo, cam_clay_dough_block.h) */
};

HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void); /* for -Wmissing-prototypes */
HEARTH_PLUGIN_EXPORT const hearth_material *hearth_material_v1(void) { return &material; }

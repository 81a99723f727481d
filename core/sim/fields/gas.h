/* gas.h: CO2 from leavening and the gas pressure (Ding et al. 2019 §5.4). */
#ifndef HEARTH_GAS_H
#define HEARTH_GAS_H

#include "physics_constants.h"
#include "vapour.h"

/// Moles per unit reference volume produced over one step while the
/// temperature goes linearly from T0 to T1 (degrees C):
///   integral of alpha_g R0 exp(-((T - Tr)/dT)^2) dt.
/// Exact for constant and for linearly varying temperature (an erf difference).
double gas_moles_step(double T0, double T1, double dt, double alpha_g, double R0, double Tr, double dT);
struct hearth_scene;
/// Venting (gas.c): particle i's n^g after a step of dt, n* + (n - n*) exp(-gas_vent S_p dt / V_p) when the
/// particle holds air surface (boundary.c's area, this step's) and its gas porosity has reached vent_porosity,
/// else n; n* the CO2 at which its pores stand at the atmosphere (0 without ambient_pressure). MPM's G2P calls it
/// on a field step after the step's production; it keeps gas_vent S_p (0 when closed or inside) in the particle's
/// PC_VENT for the steps until the next field step (gas_between).
double gas_vent(const struct hearth_scene *s, int i, double n, double dt);
/// The CO2 of a step that carries no field update (field_clock.c), per particle after the step stood: each
/// particle makes its gas at the temperature it holds since the last field step and vents through the
/// surface it held then (PC_VENT), n <- (n + a dt) e^{-h S_p dt / V_p}, as a single-rate step would.
void gas_between(struct hearth_scene *s, double dt);
/// The moles a field step's G2P adds over its cycle of fdt: the production for the temperature moving
/// linearly from T0 to T1 over fdt (gas_moles_step), less what the cycle's earlier steps (acc of it) made at
/// T0 (gas_between), so a cycle makes the linear law's exact total. Single rate (acc = 0) is gas_moles_step.
double gas_moles_field_step(double T0, double T1, double fdt, double acc, double alpha_g, double R0, double Tr, double dT);
/// One share's moles within its amount (core parameters gas_amount, gas_amount_2; issue #18). Eq. 14 (Ding et al.
/// 2019 §5.4, dn^g/dt = alpha^g R0 exp(-((theta - theta_r)/dtheta)^2)) has no reactant to run out of: a particle
/// that stays near a share's theta_r makes CO2 for ever (the physical cookie's NH4Cl share made 0.056 mol/kg in the
/// 110 degC oven, its formula holds 0.042; docs/validation.md "The physical cookie in the cooler ovens"). A leavener
/// is a finite amount a (mol/kg of dough), so each particle counts what the share has made, *made (mol/kg, its
/// PC_GAS_MADE entry), and the step's n (moles per reference volume, as gas_moles_step gives them; R0 the
/// material's density) is cut to what is left: made <- min(max(made + n / R0, 0), a), and the step adds
/// (made' - made) R0. Capped within the step, not after it: the step that reaches a makes exactly its rest, so a
/// particle's total is a whatever the step (a rate switched off from the next step on would overshoot by up to one
/// step's production, more at a larger dt). The rate is eq. 14's until then: depletion as a budget, not as a rate
/// that falls with the reactant left (first-order kinetics), for which no measured constant in dough was found.
/// The floor at 0: a field step's n is its cycle's linear-path total less what the cycle's earlier steps made
/// (gas_moles_field_step), negative where the temperature fell; a cycle whose earlier steps met the amount may end
/// up to that correction under a (second order in the cycle's temperature change). amount <= 0 or no column
/// (made NULL): no limit, n as it is, so a scene without an amount keeps eq. 14's bits.
static inline double gas_share_capped(double n, double R0, double amount, double *made) {
    if (!(amount > 0) || !made) return n;
    const double m0 = *made;
    double m1 = m0 + n / R0;
    if (m1 > amount) m1 = amount;
    if (m1 < 0) m1 = 0;
    *made = m1;
    return (m1 - m0) * R0;
}
/// Porosity n^p = 1 - (1 - n^p_0) / J^P: Ding et al.'s gas volume fraction
/// n^p = V^g / V^s in (0, 1) (§5.4) when the plastic flow changes only the
/// pores' volume, the rest of the mixture keeping its (1 - n^p_0) V_0. Their
/// n^p = J^P - 1 + n^p_0 is that fraction's gas volume over the *reference*
/// volume, V^g / V_0: the two agree at J^P = 1 and where the pores close
/// (J^P = 1 - n^p_0), but the linear form passes 1 at J^P = 2 - n^p_0, where
/// the old clamp left eq. 12 no tensile strength at all, so a swelling skin
/// had nothing to hold it (issue #18: the leavened cookie's top and rim at the
/// clamp, J up to 5.3 at dx 5 mm; docs/validation.md, "The cookie's skin").
/// With the fraction, eq. 13's n^g R theta / (J n^p) is the ideal gas in the
/// pores' own volume J n^p V_0 = (J^P - 1 + n^p_0) J^E V_0 exactly.
/// Kept inside (1e-6, 1) so the pressure stays finite.
/// Inline (as gas_tau): the material door calls both for every particle of a
/// gassy material every step, twice for the porosity (before and after the
/// return), and the calls cost more than the arithmetic. Neither has a
/// product to contract into an FMA, so inlining changes no bit.
static inline double gas_porosity(double JP, double n0) {
    double np = 1 - (1 - n0) / JP;
    if (np < 1e-6) np = 1e-6;
    if (np > 0.999999) np = 0.999999;
    return np;
}
/// Kirchhoff gas stress coefficient: tau_g = -n^g R theta_abs / n^p I (eq. 13 times J).
static inline double gas_tau(double ng, double T, double np) { return -ng * R_GAS * (T + KELVIN) / np; }

/// Eq. 13 as an overpressure over the atmosphere (material parameter ambient_pressure p_a > 0; issue #18,
/// docs/validation.md "The physical loaf's oven spring"). Ding et al.'s n^g R theta / (J n^p) is the whole pore
/// gas's pressure, and their dough starts with no gas in its pores, so a real yeast's CO2 reads ~1e5 Pa against a
/// dough that yields at ~1e2 Pa. A proofed dough's cells hold gas at about the atmosphere's pressure, and what
/// moves the dough is their overpressure (Fan, Mitchell & Blanshard 1999, J. Food Eng. 41:69, "A model for the oven
/// rise of dough during baking": a cell's pressure is p_a plus its surface tension's and its wall's stress; Zhang,
/// Datta & Mukherjee 2005, AIChE J. 51:2569, as gas.c cites: the pores' gas at p_a to start). Here:
///   pores at the start: air and, while the pores hold water, its saturated vapour p_v(theta_0), at p_a, i.e.
///     n_air = (p_a - p_v(theta_0)) n^p_0 / (R theta_0) moles per reference volume, theta_0 = reference_temperature;
///   the pores' volume per reference volume: J - (1 - n^p_0), the solid incompressible (its bulk modulus, ~GPa for
///     the water-starch-gluten matrix, against the skeleton's ~1e4 Pa), i.e. n^p J with n^p = gas_porosity(J, n^p_0);
///   p = (n_air + n^g) R theta / (J n^p) + p_v(theta)   (n^g the CO2 made since, gas.c),
///   tau_g = -J (p - p_a) = -(n_air + n^g) R theta / n^p - J (p_v(theta) - p_a)   (Kirchhoff, as gas_tau),
/// p_v by Clausius-Clapeyron (vapour.h, Rodriguez-Arenas 2011 eq. 2.43; the pores' vapour as her bubbles' eq.
/// 2.42 after Fan et al.), only where the particle holds water (saturation s > 0; a dry particle's cells hold
/// none, from the start). At theta_0 and J = 1 the gauge pressure is 0: the dough starts at rest. A free block
/// swells until its skeleton carries the gauge pressure (~tau_y): V / V_0 = 1 - n^p_0 + n^p_0 (theta / theta_0)
/// (p_a - p_v(theta_0)) / (p_a - p_v(theta)) times (n_air + n^g) / n_air on the gas (tests/unit_gas.c,
/// gas_ambient_{dry,wet}_block_swells_as_closed_form). The pores' volume from the total J, not eq. 13's J^P: with the
/// gas ~10x stiffer than the skeleton, a pressure that fell with this step's plastic flow (the plugin returns
/// without knowing it) fed back through the motion and grew a free block's breathing without bound at dx 5 mm
/// unless cfl <= 0.05 (docs/validation.md); from J alone the gas is an elastic term the CFL limit covers.
/// Once the particle's temperature reaches open_temperature the cells are open (the set crumb is a sponge: McGee
/// 2004; pore opening measured at 71-81 degC by Zhang et al. 2025, Foods 14:1649, as gas.c's venting cites) and
/// the gas holds no pressure: 0 from there. The gas's stiffness -J dp/dJ = n R theta / (J n^p) / n^p, 2e5-1e6 Pa
/// against the dough's E ~ 3e4, goes into *stiff for the step (material_gas_wave); 0 when open. Ambient 0 never
/// comes here: gas_tau, the same bits as before.
/// n_air, the moles of the pores' starting air per reference volume (above): the air a pore was closed on at
/// theta_0, with the vapour's share of p_a left out when the dough is wet. gas_tau_ambient's pressure and gas.c's
/// vent target (the CO2 at which an open pore stands at p_a) both count it.
static inline double gas_air_moles(double pa, double n0, double T0, int wet) {
    const double th0 = T0 + KELVIN, pv0 = wet ? vapour_psat(th0) : 0;
    return (pa - pv0) * n0 / (R_GAS * th0);
}

static inline double gas_tau_ambient(double ng, double T, double J, int wet, double pa, double n0, double T0,
                                     double Topen, double *stiff) {
    *stiff = 0;
    if (T >= Topen) return 0;
    const double th = T + KELVIN, np = gas_porosity(J, n0);
    const double pv = wet ? vapour_psat(th) : 0, nair = gas_air_moles(pa, n0, T0, wet);
    const double nrt = (nair + ng) * R_GAS * th; /* J n^p times the non-condensable gas's partial pressure */
    *stiff = nrt / (J * np * np);
    return -nrt / np - J * (pv - pa);
}
#endif

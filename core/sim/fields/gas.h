/* gas.h: CO2 from leavening and the gas pressure (Ding et al. 2019 §5.4). */
#ifndef HEARTH_GAS_H
#define HEARTH_GAS_H

#include "physics_constants.h"

/// Moles per unit reference volume produced over one step while the
/// temperature goes linearly from T0 to T1 (degrees C):
///   integral of alpha_g R0 exp(-((T - Tr)/dT)^2) dt.
/// Exact for constant and for linearly varying temperature (an erf difference).
double gas_moles_step(double T0, double T1, double dt, double alpha_g, double R0, double Tr, double dT);
struct hearth_scene;
/// Venting (gas.c): the factor on particle i's n^g over a step of dt, exp(-gas_vent S_p dt / V_p) when the
/// particle holds air surface (boundary.c's area, this step's) and its gas porosity has reached vent_porosity,
/// else 1. MPM's G2P calls it on a field step after the step's production; it keeps gas_vent S_p (0 when
/// closed or inside) in the particle's PC_VENT for the steps until the next field step (gas_between).
double gas_vent_factor(const struct hearth_scene *s, int i, double dt);
/// The CO2 of a step that carries no field update (field_clock.c), per particle after the step stood: each
/// particle makes its gas at the temperature it holds since the last field step and vents through the
/// surface it held then (PC_VENT), n <- (n + a dt) e^{-h S_p dt / V_p}, as a single-rate step would.
void gas_between(struct hearth_scene *s, double dt);
/// The moles a field step's G2P adds over its cycle of fdt: the production for the temperature moving
/// linearly from T0 to T1 over fdt (gas_moles_step), less what the cycle's earlier steps (acc of it) made at
/// T0 (gas_between), so a cycle makes the linear law's exact total. Single rate (acc = 0) is gas_moles_step.
double gas_moles_field_step(double T0, double T1, double fdt, double acc, double alpha_g, double R0, double Tr, double dT);
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
#endif

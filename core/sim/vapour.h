/* vapour.h: water's saturated vapour pressure, once for every field that
 * uses it: sph_gas.c's bubble vapour (Fan et al.'s a_w P_sat(T)) and water.h's
 * evaporation with the scene's latent_heat (issue #18).
 *
 * Clausius-Clapeyron through the normal boiling point (Rodriguez-Arenas 2011
 * eq. 2.43, P_2 = P_1 exp(-Delta H_v / R (1 / T_2 - 1 / T_1))), with
 * P_1 = 101325 Pa at T_1 = 373.15 K and Delta H_v = 40.66 kJ/mol, the molar
 * enthalpy of vaporisation at 100 degC. Constant Delta H_v overstates it
 * away from there: 2.83 kPa at 20 degC against the steam tables' 2.34 (+21%),
 * 21.0 against 19.9 kPa at 60 degC (+5%), 70.6 against 70.1 at 90 degC;
 * at the boiling point, where the evaporation's factor is calibrated, it is
 * exact by construction. Rejected: a Magnus or Antoine
 * fit, closer at room temperature but a second curve beside the thesis's. */
#ifndef HEARTH_VAPOUR_H
#define HEARTH_VAPOUR_H
#include <math.h>

#include "physics_constants.h"

#define VAPOUR_DH 40660.0   /* J/mol, Delta H_v at 100 degC */
#define VAPOUR_P1 101325.0  /* Pa at VAPOUR_T1 */
#define VAPOUR_T1 (100.0 + KELVIN) /* K; written as sph_gas.c always had it, so its bits hold */

/* eq. 2.43's factor P_sat(th) / P_sat(T_1) at absolute temperature th (K)
 * (0 at th = 0: 1 / 0 is infinite and exp takes it to 0). */
static inline double vapour_clausius(double th) { return exp(-(VAPOUR_DH / R_GAS) * (1.0 / th - 1.0 / VAPOUR_T1)); }

/* P_sat (Pa) at absolute temperature th (K); 0 at th <= 0. */
static inline double vapour_psat(double th) { return th > 0 ? VAPOUR_P1 * vapour_clausius(th) : 0.0; }

#endif

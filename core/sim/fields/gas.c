/* gas.c: CO2 production and pressure (Ding et al. 2019 §5.4).
 *
 *   dn^g/dt = alpha^g R0 exp(-((theta - theta_r)/dtheta)^2)
 *   n^p = J^{s,P} - 1 + n^p_0
 *   sigma^g = -n^g R theta / (J n^p) I            (eq. 13)
 *
 * The rate is integrated over each step as if the temperature moved linearly
 * from its value before the step's heat update to its value after, which the
 * erf form does exactly; at constant temperature it reduces to rate * dt.
 * The gas law takes absolute temperature: the user works in degrees C. */
#include "gas.h"

#include <math.h>

#include "physics_constants.h"
#define SQRT_PI 1.7724538509055160273

double gas_moles_step(double T0, double T1, double dt, double alpha_g, double R0, double Tr, double dT) {
    if (!(alpha_g > 0) || !(dt > 0)) return 0;
    const double a = (T0 - Tr) / dT, b = (T1 - Tr) / dT;
    const double k = alpha_g * R0 * dt;
    if (fabs(b - a) < 1e-6) { /* nearly constant: midpoint of the Gaussian, error O((b-a)^2) ~ 1e-12 */
        const double m = 0.5 * (a + b);
        return k * exp(-m * m) * (1 + (b - a) * (b - a) * (2 * m * m - 1) / 12);
    }
    /* dt * mean of exp(-u^2) over u in [a, b] */
    return k * 0.5 * SQRT_PI * (erf(b) - erf(a)) / (b - a);
}

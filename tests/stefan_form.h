/* stefan_form.h: the quasi-steady Stefan form of a wet slab drying behind a
 * boiling front under a Robin boundary, shared by unit_drying_front.c (the top
 * under the oven's air) and unit_base_contact.c (the base on a heated tray);
 * unit_drying_front.c's header derives it. A dried layer of depth d grows over
 * a wet part held at T_b, its face coupled to T_hot through beta; with
 * a = 1 / beta, b = 1 / k_dry and W the water's latent heat per volume:
 *   t(d) = W (a d + b d^2 / 2) / (T_hot - T_b)                               (3)
 *        + (rho_c b / 2) [d^2 / 2 + (a / b) d - (a / b)^2 ln(1 + b d / a)]  (4)
 * ((3) without the dried layer's sensible heat, (4) with it, rho_c the dried
 * layer's heat capacity per volume). */
#ifndef HEARTH_TEST_STEFAN_FORM_H
#define HEARTH_TEST_STEFAN_FORM_H
#include <math.h>

typedef struct stefan_form {
    double beta;  /* W/(m^2 K) */
    double k_dry; /* W/(m K) */
    double rho_c; /* J/(m^3 K), the dried layer's */
    double water; /* J/m^3: the water's mass per volume times L */
    double T_hot, T_b;
} stefan_form;

/* (3), or (4) with sensible: the time at which the front reaches d. */
static inline double stefan_t_of_d(const stefan_form *f, double d, int sensible) {
    const double a = 1 / f->beta, b = 1 / f->k_dry;
    double t = f->water * (a * d + 0.5 * b * d * d) / (f->T_hot - f->T_b);
    if (sensible) t += 0.5 * f->rho_c * b * (0.5 * d * d + a / b * d - (a / b) * (a / b) * log1p(b * d / a));
    return t;
}

/* Inverts stefan_t_of_d by bisection (it rises with d) over [0, 1 m]. */
static inline double stefan_d_of_t(const stefan_form *f, double t, int sensible) {
    double lo = 0, hi = 1;
    for (int k = 0; k < 200; k++) {
        const double m = 0.5 * (lo + hi);
        if (stefan_t_of_d(f, m, sensible) < t) lo = m;
        else hi = m;
    }
    return 0.5 * (lo + hi);
}
#endif

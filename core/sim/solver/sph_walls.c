/* sph_walls.c: fixed particles as walls of the SPH solver: the no-slip
 * wall velocities of eq. 3.19 (Morris et al. 1997). phase_forces (sph.c)
 * applies them in the viscous term. */
#include <math.h>

#include "sph_kernel.h"
#include "sph_state.h"

/* No-slip walls of fixed particles (Morris, Fox & Zhu 1997, J. Comput. Phys.
 * 136, 214-226): in the viscous term a wall particle b seen from a fluid
 * particle a moves with v_b = -(d_b / d_a) v_a, d the distances to the wall
 * surface, so the velocity extrapolates linearly to zero on the surface.
 * With wall particles at rest instead, eq. 3.19 lets the first fluid layer
 * slip (Poiseuille flow 12.6% off the parabola; 2.2% with this, 0.58% with
 * eq. 3.8 renormalised as well, `sph_poiseuille`). Particle walls carry no
 * surface, so it is estimated per fluid particle a: the wall normal n is minus the gradient of the
 * fixed particles' colour field at a (that gradient points into the wall),
 * and the surface lies half a wall spacing beyond the wall particle nearest
 * along n (exact for the lattice walls bodies make). Morris et al. bound
 * 1 + d_b / d_a so a particle close to the surface does not get an
 * unbounded wall velocity; here d_a is taken as at least half the fluid
 * particle's own spacing instead, which never bites on the rest lattice
 * (their bound of 1.5 would, and left 4.9% slip in `sph_poiseuille` before
 * eq. 3.8 was renormalised).
 * sph_wall_frame returns 0 when a has no fixed neighbour. */
int sph_wall_frame(const hearth_scene *s, int i, double n[3], double *da) {
    const struct sph_state *st = s->sph;
    const particles *ps = &s->ps;
    const int *flags = pcoli(ps, PC_FLAGS), dim = s->def.dim;
    const double *x = pcold(ps, PC_X), *m = pcold(ps, PC_MASS);
    const int *off = st->nl.off, *nb = st->nl.j;
    double g[3] = {0, 0, 0};
    for (int k = off[i]; k < off[i + 1]; k++) {
        const int j = nb[k];
        if (!(flags[j] & PF_FIXED)) continue;
        double d[3];
        sph_disp(&st->cells, x + 3 * i, x + 3 * j, d);
        const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (r <= 0) continue;
        const double w = m[j] / st->rho[j] * sph_dw(dim, r, 0.5 * (st->h[i] + st->h[j])) / r;
        for (int c = 0; c < 3; c++) g[c] += w * d[c];
    }
    const double gn = sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
    if (!(gn > 0)) return 0;
    for (int c = 0; c < 3; c++) n[c] = -g[c] / gn;
    double best = INFINITY;
    for (int k = off[i]; k < off[i + 1]; k++) {
        const int j = nb[k];
        if (!(flags[j] & PF_FIXED)) continue;
        double d[3];
        sph_disp(&st->cells, x + 3 * i, x + 3 * j, d);
        const double sj = d[0] * n[0] + d[1] * n[1] + d[2] * n[2] - 0.5 * st->sp[j];
        if (sj < best) best = sj;
    }
    *da = best;
    return 1;
}

/* 1 + d_b / d_a for wall particle b at displacement d = x_a - x_b: the
 * factor on v_a in a's viscous interaction with b (v_a - v_b of eq. 3.19
 * with the wall velocity above). dah: d_a, at least half of a's spacing. */
double sph_wall_beta(const double d[3], const double n[3], double da, double dah) {
    const double db = d[0] * n[0] + d[1] * n[1] + d[2] * n[2] - da;
    return db > 0 ? 1.0 + db / dah : 1.0;
}

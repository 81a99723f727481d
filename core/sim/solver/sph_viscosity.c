/* sph_viscosity.c: the SPH viscous term's two pieces outside the step's
 * loop (Rodriguez-Arenas 2011 eq. 3.19 with the kernel Laplacian of eq.
 * 3.8): which plugin parameter is the core's viscosity (contract rule 3 of
 * <hearth/material.h>), and the per-particle renormalisation of eq. 3.8 by
 * its discrete second moment (sph_viscous_factor). sph_forces (sph_forces.c)
 * applies both. */
#include <math.h>

#include "alloc.h"
#include "error.h"
#include "params.h"
#include "sph_kernel.h"
#include "sph_state.h"

/* ---- the viscosity rule -------------------------------------------------------- */

/* Contract rule 3 of <hearth/material.h>: under SPH a plugin parameter named
 * `viscosity` (Pa s) is the core's. SPH applies it itself, in the viscous
 * term of eq. 3.19 with no-slip walls (sph_forces), limits the step with
 * viscosity / density (sph_stable_dt), and passes 0 for it to the plugin's
 * stress (phase_stress), so the law does not apply it a second time. Under
 * MPM the plugin applies it, like any other parameter. This is the one place
 * the name is looked up: once per material, when it is added. */
static int sph_viscosity_index(const hearth_material *m) { return params_index(m, "viscosity"); }

hearth_status sph_material_added(hearth_scene *s, int mat, hearth_error *err) {
    struct sph_state *st = sph_state_of(s, err);
    if (!st) return HEARTH_ERR_NOMEM;
    if (mat >= st->visc_cap) {
        const int cap = mat + 1 > 2 * st->visc_cap ? mat + 1 : 2 * st->visc_cap;
        int *v = mem_realloc(st->visc_index, sizeof(int) * (size_t)st->visc_cap, sizeof(int) * (size_t)cap);
        if (!v) return err_set(err, HEARTH_ERR_NOMEM, "sph: out of memory for material %d", mat);
        st->visc_index = v;
        st->visc_cap = cap;
    }
    st->visc_index[mat] = sph_viscosity_index(s->mats.slot[mat].m);
    return HEARTH_OK;
}

/* tr M of eq. 3.8's Laplacian over a full square (2D) or cubic (3D) lattice
 * of unit spacing at support h (in spacings), unit volumes: 2 dim times
 * 1.057 at h = 2.4 in 2D (0.966 in 3D). */
static double lattice_moment(int dim, double h) {
    const int R = (int)h + 1;
    double tr = 0;
    for (int a = -R; a <= R; a++)
        for (int b = -R; b <= R; b++)
            for (int c = dim == 3 ? -R : 0; c <= (dim == 3 ? R : 0); c++) {
                const double r2 = (double)(a * a + b * b + c * c);
                if (r2 > 0) tr += sph_lap_visc(dim, sqrt(r2), h) * r2;
            }
    return tr;
}

/* The renormalisation of eq. 3.8's Laplacian (our deviation; the header
 * says why). Summed over neighbours, sum_b V_b L(r_ab) (v_b - v_a) for a
 * quadratic v is (1/2) M_a : grad grad v, with M_a = sum_b V_b L r r the
 * kernel's discrete second moment; its integral is 2 I, so with c_a =
 * 2 dim / tr M_a the sum is the Laplacian exactly wherever M_a is isotropic
 * (any resting square or cubic lattice, whatever h over the spacing), and
 * within 0.3% with rows sliding past each other (M_xx and M_yy then differ
 * by 0.4%). Wall particles count as neighbours, so a fluid particle next to
 * a wall has a full neighbourhood.
 *
 * That holds for a full neighbourhood only: with neighbours missing on one
 * side (a free surface, the outer face of a wall) tr M loses more than its
 * share (the far neighbours weigh r^2), so 2 dim phi / tr M, phi the filled
 * part of the neighbourhood, came out 1.2 at the edge of a disc, 27% above
 * its inside, and the surface of the bubble dough (`sph_bubble_expansion`)
 * ran away (the same with the rows two and three in: their phi is 0.97 or
 * more, the far neighbours being light in W). So c_a blends into the factor
 * of the resting lattice at a's own h and spacing (lattice_moment) as the
 * filled part phi_a = sum_b V_b W_ab / (1 - V_a W(0)) falls from 0.95 to
 * 0.85, or as the centre of the moment, |sum_b V_b L r^2 r| / (h tr M),
 * moves from 2% to 5% of h off a (0 on any symmetric neighbourhood, resting
 * or sliding): the same correction throughout a body at rest, and no
 * strength that the neighbourhood's shape makes up. c_a is held within [0.8, 1.2]: that covers every regular
 * arrangement (0.94 to 1.16 for h from 2 to 4 spacings), while in a clumped
 * neighbourhood, where no moment makes eq. 3.8 exact, tr M falls with r^2
 * and c would grow without bound.
 *
 * Rejected: Morris et al.'s (1997) grad W . r / r^2 form alone, 0.9% weak
 * on the resting lattice and 0.6% strong with rows sliding at h = 2.4
 * spacings (1.8% weak in 3D): smaller, but a bias that does not shrink with
 * resolution all the same; the resting lattice's factor everywhere, exact at
 * rest but 1.8% weak once rows slide (steady Poiseuille flow); a tensor
 * factor (pair weights e^T A e, A solved from the fourth moment so every
 * quadratic field is exact), which would remove the 0.2% anisotropy of
 * sliding rows but fits each instant's skewed arrangement of them: steady
 * Poiseuille flow went from 0.58% to 3.4% off at 20 across.
 *
 * The neighbour sums (fill, tr M and the moment's centre g) are taken in
 * sph_kinematics' loop over the neighbours (sph_kinematics.c), which reads the same
 * pairs; this closes them into c_a. */
double sph_viscous_factor(const hearth_scene *s, int i, double fill, double tr, const double g[3]) {
    const struct sph_state *st = s->sph;
    const int dim = s->def.dim;
    const double *m = pcold(&s->ps, PC_MASS);
    const double full = 1.0 - m[i] / st->rho[i] * sph_w(dim, 0, st->h[i]), phi = full > 0 ? fill / full : 0;
    /* lopsided: the moment's centre off a by more than 2% of h (0 on any symmetric neighbourhood) */
    const double off_c = tr > 0 ? sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]) / (tr * st->h[i]) : 1.0;
    const double uphi = phi >= 0.95 ? 1.0 : phi <= 0.85 ? 0.0 : (phi - 0.85) / 0.1;
    const double uoff = off_c <= 0.02 ? 1.0 : off_c >= 0.05 ? 0.0 : (0.05 - off_c) / 0.03;
    const double u = uphi * uoff;
    double c = u > 0 ? 2.0 * dim * phi / tr : 1.0;
    if (u < 1) {
        const double ratio = st->h[i] / st->sp[i];
        c = u * c + (1 - u) * 2.0 * dim / (ratio == st->lm_ratio ? st->lm_val : lattice_moment(dim, ratio));
    }
    return c < 0.8 ? 0.8 : c > 1.2 ? 1.2 : c;
}

void sph_lattice_moment_prepare(hearth_scene *s) {
    struct sph_state *st = s->sph;
    st->lm_ratio = NAN; /* matches no ratio */
    if (s->ps.n < 1 || !(st->sp[0] > 0)) return;
    st->lm_ratio = st->h[0] / st->sp[0];
    st->lm_val = lattice_moment(s->def.dim, st->lm_ratio);
}

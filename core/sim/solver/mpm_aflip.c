/* mpm_aflip.c: an APIC-FLIP blend in G2P, for measuring only (#18, helper
 * aflip; docs/validation.md "Keeping the residual"). Off unless the
 * environment sets HEARTH_AFLIP_ALPHA (a fixed alpha) or HEARTH_AFLIP_TAU (s;
 * alpha = 1 - dt / tau each step, a fixed loss rate per unit time) when the
 * scene is made. G2P then sets
 *   v_p^{n+1} = v^{n+1}(x_p) + alpha (v_p^n - v^n(x_p))
 * (Fei et al. 2021, "Revisiting integration in the material point method",
 * the APIC-FLIP blend; Jiang et al. 2016 course notes sec. 10), where
 * v^n(x_p) interpolates the nodes' P2G velocity before the grid update
 * (forces, walls). The step's P2G folds the stress impulse into the nodes'
 * momentum, so that velocity is not on the grid: this pass scatters
 * m_p (v_p + C_p (x_i - x_p)) and m_p (APIC's P2G without the stress) into a
 * dense array over the box, serially in particle order (the same sums at any
 * thread count). C and x are APIC's (from the new grid). */
#include <stdlib.h>
#include <string.h>

#include "mpm.h"
#include "alloc.h"

void mpm_aflip_init(mpm_state *m) {
    const char *a = getenv("HEARTH_AFLIP_ALPHA"), *t = getenv("HEARTH_AFLIP_TAU");
    m->aflip_alpha0 = a ? atof(a) : 0.0;
    m->aflip_tau = t ? atof(t) : 0.0;
    m->aflip_on = a || t;
}

void mpm_aflip_free(mpm_state *m) {
    mem_free(m->aflip_v, sizeof(double) * m->aflip_cap);
    m->aflip_v = NULL;
    m->aflip_cap = 0;
}

hearth_status mpm_aflip_scatter(hearth_scene *s, double dt, hearth_error *err) {
    mpm_state *m = s->mpm;
    const grid *g = &s->g;
    const int D = g->dim;
    m->aflip_alpha = m->aflip_tau > 0 ? 1.0 - dt / m->aflip_tau : m->aflip_alpha0;
    const size_t nodes = (size_t)g->nn[0] * (size_t)g->nn[1] * (size_t)(D == 3 ? g->nn[2] : 1), need = 4 * nodes;
    if (need > m->aflip_cap) {
        double *v = mem_alloc(sizeof(double) * need);
        if (!v) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for aflip's node velocities");
        mpm_aflip_free(m);
        m->aflip_v = v;
        m->aflip_cap = need;
    }
    double *V = m->aflip_v;
    memset(V, 0, sizeof(double) * need);
    const particles *ps = &s->ps;
    const double *X = pcold(ps, PC_X), *Vp = pcold(ps, PC_V), *Cc = pcold(ps, PC_C), *M = pcold(ps, PC_MASS);
    const int tn = D == 2 ? 4 : 9, apic = s->def.transfer == 0;
    for (int i = 0; i < ps->n; i++) {
        const double *x = X + 3 * i, *v = Vp + 3 * i, *C = Cc + tn * i;
        int base[3] = {0, 0, 0};
        double w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3], fx[3] = {0, 0, 0};
        for (int d = 0; d < D; d++) {
            const double Xd = (x[d] - g->lo[d]) * g->inv_dx;
            base[d] = base_node(Xd);
            fx[d] = Xd - base[d];
            bspline_weights(fx[d], w[d], dw);
        }
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                    const double wt = w[0][a] * w[1][b] * w[2][c] * M[i];
                    const double dd[3] = {(a - fx[0]) * g->dx, (b - fx[1]) * g->dx, D == 3 ? (c - fx[2]) * g->dx : 0.0};
                    const size_t l = ((size_t)(base[0] + a) * (size_t)g->nn[1] + (size_t)(base[1] + b)) *
                                         (size_t)(D == 3 ? g->nn[2] : 1) + (size_t)(D == 3 ? base[2] + c : 0);
                    for (int r = 0; r < D; r++) {
                        double u = v[r];
                        if (apic)
                            for (int q = 0; q < D; q++) u += C[r * D + q] * dd[q];
                        V[4 * l + r] += wt * u;
                    }
                    V[4 * l + 3] += wt;
                }
    }
    for (size_t l = 0; l < nodes; l++)
        if (V[4 * l + 3] > 0)
            for (int r = 0; r < 3; r++) V[4 * l + r] /= V[4 * l + 3];
    return HEARTH_OK;
}

/* Noise (measurement): the particles' kinetic energy in their residual against the P2G velocity at them,
 * sum m |v_p - v^n(x_p)|^2 over sum m |v_p|^2, from a fresh scatter of the current state. A smooth field
 * leaves only APIC's one-pass smoothing there; FLIP's kept residual shows as more. */
double mpm_aflip_residual_share(hearth_scene *s) {
    hearth_error err;
    if (!s->mpm->aflip_on || mpm_aflip_scatter(s, 1.0, &err)) return NAN;
    const grid *g = &s->g;
    const int D = g->dim;
    const particles *ps = &s->ps;
    const double *X = pcold(ps, PC_X), *Vp = pcold(ps, PC_V), *M = pcold(ps, PC_MASS), *V = s->mpm->aflip_v;
    double num = 0, den = 0;
    for (int i = 0; i < ps->n; i++) {
        const double *x = X + 3 * i, *v = Vp + 3 * i;
        int base[3] = {0, 0, 0};
        double w[3][3] = {{1, 0, 0}, {1, 0, 0}, {1, 0, 0}}, dw[3];
        for (int d = 0; d < D; d++) {
            const double Xd = (x[d] - g->lo[d]) * g->inv_dx;
            base[d] = base_node(Xd);
            bspline_weights(Xd - base[d], w[d], dw);
        }
        double vo[3] = {0, 0, 0};
        for (int a = 0; a < 3; a++)
            for (int b = 0; b < 3; b++)
                for (int c = 0; c < (D == 3 ? 3 : 1); c++) {
                    const size_t l = ((size_t)(base[0] + a) * (size_t)g->nn[1] + (size_t)(base[1] + b)) *
                                         (size_t)(D == 3 ? g->nn[2] : 1) + (size_t)(D == 3 ? base[2] + c : 0);
                    for (int d = 0; d < D; d++) vo[d] += w[0][a] * w[1][b] * w[2][c] * V[4 * l + d];
                }
        for (int d = 0; d < D; d++) {
            num += M[i] * (v[d] - vo[d]) * (v[d] - vo[d]);
            den += M[i] * v[d] * v[d];
        }
    }
    return den > 0 ? num / den : 0.0;
}

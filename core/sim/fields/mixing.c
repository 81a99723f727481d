/* mixing.c: dynamic mixing ratios (Nagasawa et al. 2019 §6).
 *
 * A mixture material holds k full parameter sets of one plugin. Each of its
 * particles keeps its initial mixing ratios alpha_p as a label (no
 * dissolution, as in the paper) and, every step, takes dynamic ratios from
 * its neighbours through the grid:
 *
 *   alpha_i = sum_p V_p w_ip alpha_p / sum_p V_p w_ip     (eq. 43)
 *   alpha^_p = sum_i w_ip alpha_i                         (eq. 44)
 *
 * Its parameters are then the plugin's blend of the constituents at alpha^_p
 * (material_params, material.c), so any plugin with a blend callback can
 * mix. Only particles of the mixture take part: another material's particles
 * carry no ratios. A uniform mixture keeps its ratios exactly (the weights
 * are a partition of unity); pure bodies stirred together grade into each
 * other over the kernel's width (1.5 dx) and then as far as the stirring
 * carries particles. The nodes' sums live in an array of their own, indexed
 * like the grid's blocks, so the grid's channels stay as they are.
 *
 * What lives where: this file owns the dynamic ratios (the node sums in
 * mixing_state, the particles' PC_MIXD) and which material is the mixture;
 * the constituents' parameter sets and their blend belong to the material's
 * slot (material.c). Adding the mixture goes through the core's own
 * scene_add_material, not the public entry point. */
#include "plugins.h"
#include "mixing.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "params.h"
#include "scene.h"
#include "mpm.h"
#include "tensor.h"

int mixing_active(const hearth_scene *s) { return s->mix.mat >= 0; }

void mixing_init(mixing_state *x) { *x = (mixing_state){.mat = -1}; }

void mixing_free(mixing_state *x) {
    mem_free(x->nodes, sizeof(double) * x->cap);
    mixing_init(x);
}

hearth_status mixing_update(hearth_scene *s, hearth_error *err) {
    grid *g = &s->g;
    particles *ps = &s->ps;
    const int NPB = g->nodes_per_block, TN = grid_tile_count(g), k = s->mats.slot[s->mix.mat].mix_k, W = k + 1;
    const size_t need = (size_t)g->nactive * NPB * W;
    if (need > s->mix.cap) {
        double *a = mem_alloc(sizeof(double) * need * 2);
        if (!a) return err_set(err, HEARTH_ERR_NOMEM, "out of memory for the mixing ratios' grid");
        mem_free(s->mix.nodes, sizeof(double) * s->mix.cap);
        s->mix.nodes = a;
        s->mix.cap = need * 2;
    }
    memset(s->mix.nodes, 0, sizeof(double) * need);
    const double *X = pcold(ps, PC_X), *V0 = pcold(ps, PC_VOL0), *A0 = pcold(ps, PC_MIX);
    double *A = pcold(ps, PC_MIXD);
    const int *mat = pcoli(ps, PC_MAT), mm = s->mix.mat;
    const int par = ps->n >= SCENE_PARALLEL_MIN;
    const mpm_state *m = mpm_state_of(s); /* the sort's particle blocks (mixing runs inside an MPM step) */
    /* eq. 43, numerator and denominator, in colour phases (disjoint nodes, no atomics) */
    for (int col = 0; col < 8; col++) {
#pragma omp parallel if (par)
        {
            double tile[(MIX_MAX + 1) * GRID_T * GRID_T * GRID_T];
            grid_stencil st;
#pragma omp for schedule(dynamic, 2)
            for (int q = m->colour_start[col]; q < m->colour_start[col + 1]; q++) {
                const pblock pb = m->pb[m->colour_pb[q]];
                int bc[3], any = 0;
                grid_block_coords(g, pb.block, bc);
                memset(tile, 0, sizeof(double) * (size_t)W * TN);
                for (int i = pb.start; i < pb.end; i++) {
                    if (mat[i] != mm) continue;
                    any = 1;
                    grid_tile_stencil(g, bc, X + 3 * i, &st);
                    const double Vp = V0[i] * particles_J(ps, i);
                    for (int j = 0; j < st.n; j++) {
                        const double vw = Vp * st.w[j];
                        tile[k * TN + st.t[j]] += vw;
                        for (int c = 0; c < k; c++) tile[c * TN + st.t[j]] += vw * A0[MIX_MAX * i + c];
                    }
                }
                if (!any) continue;
                for (int tt = 0; tt < TN; tt++) {
                    if (tile[k * TN + tt] == 0.0) continue;
                    int l;
                    double *node = s->mix.nodes + ((size_t)grid_tile_slot(g, bc, tt, &l) * NPB + l) * W;
                    for (int c = 0; c <= k; c++) node[c] += tile[c * TN + tt];
                }
            }
        }
    }
    /* eq. 44: each mixture particle gathers its nodes' ratios */
#pragma omp parallel for schedule(dynamic, 2) if (par)
    for (int q = 0; q < m->npb; q++) {
        const pblock pb = m->pb[q];
        int bc[3];
        grid_stencil st;
        grid_block_coords(g, pb.block, bc);
        for (int i = pb.start; i < pb.end; i++) {
            if (mat[i] != mm) continue;
            grid_tile_stencil(g, bc, X + 3 * i, &st);
            double a[MIX_MAX] = {0};
            for (int j = 0; j < st.n; j++) {
                int l;
                const double *node = s->mix.nodes + ((size_t)grid_tile_slot(g, bc, st.t[j], &l) * NPB + l) * W;
                if (!(node[k] > 0)) continue;
                for (int c = 0; c < k; c++) a[c] += st.w[j] * node[c] / node[k];
            }
            memcpy(A + (size_t)MIX_MAX * i, a, sizeof a);
        }
    }
    return HEARTH_OK;
}

int hearth_scene_add_mixture(hearth_scene *s, const char *plugin, int k, const char *const *const *names,
                             const double *const *values, const int *n, hearth_error *err) {
    err_clear(err);
    if (k < 2 || k > MIX_MAX) {
        err_set(err, HEARTH_ERR_PARAM, "mixture: %d constituents; valid range [2, %d]", k, MIX_MAX);
        return -1;
    }
    if (s->mix.mat >= 0) {
        err_set(err, HEARTH_ERR_PARAM,
                "mixture: the scene already holds one (material %d); put every constituent that will be stirred "
                "together into that one",
                s->mix.mat);
        return -1;
    }
    /* the first constituent makes the slot (its core field properties are the mixture's) */
    const int id = scene_add_material(s, plugin, names[0], values[0], n[0], err);
    if (id < 0) return -1;
    double *mp = material_mixture_params(&s->mats, id, k, names, values, n, err);
    if (!mp) return -1;
    if (particles_enable(&s->ps, PC_MIX, err) || particles_enable(&s->ps, PC_MIXD, err)) {
        material_mixture_params_free(&s->mats, id, k, mp);
        return -1;
    }
    material_mixture_set(&s->mats, id, k, mp);
    s->mix.mat = id;
    return id;
}

hearth_status mixing_set_ratios(hearth_scene *s, int from, int to, const double *ratios, hearth_error *err) {
    const material_slot *ms = &s->mats.slot[s->mix.mat];
    double a[MIX_MAX] = {0}, sum = 0;
    for (int c = 0; c < MIX_MAX; c++) {
        const double r = ratios ? ratios[c] : c == 0;
        if (c >= ms->mix_k ? r != 0 : !(r >= 0 && isfinite(r)))
            return err_set(err, HEARTH_ERR_PARAM, "body: mixing ratio %d = %g; the mixture has %d constituents, each ratio >= 0",
                           c + 1, r, ms->mix_k);
        a[c] = r;
        sum += r;
    }
    if (!(sum > 0))
        return err_set(err, HEARTH_ERR_PARAM, "body: material %d is a mixture of %d constituents; give its mixing ratios "
                                              "(they sum to zero)", s->mix.mat, ms->mix_k);
    for (int c = 0; c < MIX_MAX; c++) a[c] /= sum;
    particles *ps = &s->ps;
    double scratch[SCENE_MAX_PARAMS];
    for (int i = from; i < to; i++) {
        memcpy(pcold(ps, PC_MIX) + (size_t)MIX_MAX * i, a, sizeof a);
        memcpy(pcold(ps, PC_MIXD) + (size_t)MIX_MAX * i, a, sizeof a);
        /* mass from the blend's density at the initial ratios; it does not change after */
        const double *p = material_params(&s->mats, &s->ps, s->mix.mat, i, scratch);
        pcold(ps, PC_MASS)[i] = p[ms->density_index] * pcold(ps, PC_VOL0)[i];
    }
    return HEARTH_OK;
}

const double *hearth_scene_mixing_ratios(const hearth_scene *s, int *k) {
    if (s->mix.mat < 0) {
        if (k) *k = 0;
        return NULL;
    }
    if (k) *k = s->mats.slot[s->mix.mat].mix_k;
    return pcold(&s->ps, PC_MIXD);
}

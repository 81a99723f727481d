/* sph_outer.c: the particles on the body's outer surface, where the oven's
 * heat enters (Rodriguez-Arenas 2011 eq. 3.42 and the Robin flux,
 * sph_heat.c).
 *
 * Why not the colour field (eq. 3.29, st->surf): its gradient needs a kernel
 * that holds several particles. h is fixed by the rest spacing (h_factor
 * 2.4), and a rising cake's bubble particles expand about fourfold (the angel
 * food cake, #18): in the risen crumb the particles stand 2 rest spacings
 * apart, 0.8 of the support, where the kernel is 3% of its peak, so |grad C|
 * h reads 0.1 at the cake's top (threshold 0.75) and 0.8-1.1 on the dense
 * batter rows under the expanded bubbles. Eq. 3.42 then heated rows inside
 * the cake and not its top: the crumb ran hotter than the crust
 * (docs/validation.md "The angel food cake heats from inside").
 *
 * Here the body is the union of discs (balls) of radius h_i / 2 about the
 * particles: two particles within the support of each other overlap, so the
 * body is whole wherever the kernel joins its particles. A grid of cells
 * (half the smallest rest spacing; coarser when the box would need more
 * than OUTER_MAX_CELLS of them, and past h/4 the colour field's flag
 * instead) marks the cells whose centres lie inside, floods the
 * empty cells from the grid's border (the padding makes the border empty),
 * and a particle is on the outer surface when an outside cell lies within
 * h_i / 2 plus one cell's diagonal of it. Gaps enclosed by the body (the
 * spots of gas between the particles of an expanded crumb) are not reached
 * by the flood and take no oven heat. The thesis marks the surface by the
 * colour field and names a local convex hull (§3.1.8); this is neither,
 * a flood fill of the kind used to tell a body's outside from its cavities
 * (as in the marker-and-cell method's free-surface marking, Harlow & Welch
 * 1965, Phys. Fluids 8:2182). With a periodic axis the colour field's
 * flag is kept (a flood across the wrap is not built). With adaptive h
 * (eq. 3.54) the discs follow each particle's h. */
#include <math.h>
#include <stdint.h>

#include "alloc.h"
#include "sph_state.h"

#define OUTER_MAX_CELLS 8000000 /* 40 MB of scratch at most: a byte and a queue entry per cell */

void sph_outer_free(struct sph_state *st) {
    mem_free(st->og, st->og_cap);
    mem_free(st->oq, sizeof(int) * st->og_cap);
    st->og = NULL;
    st->oq = NULL;
    st->og_cap = 0;
}

/* the cells [a0, a1] (clipped to the grid) that a ball of radius R about p can reach */
static void cell_span(const double *p, double R, const double o[3], double cs, const int ng[3], int dim, int a0[3],
                      int a1[3]) {
    for (int a = 0; a < dim; a++) {
        a0[a] = (int)floor((p[a] - R - o[a]) / cs);
        a1[a] = (int)ceil((p[a] + R - o[a]) / cs);
        if (a0[a] < 0) a0[a] = 0;
        if (a1[a] > ng[a] - 1) a1[a] = ng[a] - 1;
    }
}

/* The share of its rest face each outer particle stands for, st->oshare:
 * 1, the face of its rest volume, V^((d-1)/d) (a boundary node's in MPM,
 * boundary.c), less where the outer particles crowd along the surface. A fixed face per
 * particle is the surface's area only while the outer particles stand at
 * their rest spacing along it: the bread of the dead's lowest rows, squeezed
 * into one line on its tray (#18: 34 particles on 40 mm at 2 mm spacing,
 * 1.7 to a face, under Tait's tension where the tray adds no neighbours),
 * took 1.7 faces of oven heat per face of base. The crowding is a count of
 * the outer neighbours within a hat of OUTER_HAT rest spacings,
 *   S_i = sum_j (1 - r_ij / (1.4 sp_i))_+   (j = i included),
 * against the same count on a resting lattice's face, S_ref (a row's two
 * neighbours at one spacing in 2D, a square layer's four in 3D), and
 *   oshare_i = min(1, S_ref / S_i)
 * (the squeezed base's 48 particles on 57 mm at 0.5 s: 0.65 each, faces of
 * 62 mm where the rest face gave 96). The hat
 * stops short of sqrt 2 spacings so that the two neighbours of a block's
 * corner (2D) or edge (3D), which stand sqrt 2 apart across it, do not read
 * as crowded: a face, edge or corner particle counts as a face's, and
 * sph_heat_ext_flux_per_area's faces keep their closed form (the same bits
 * of heat there; a hat of 1.5 spacings, tried first, took 0.5% of the 2D
 * block's heat at its corners and 1.2% of the 3D one's). Rejected: the outer
 * shell's volume over its width (the Steiner formula's surface area), which
 * measures the discs' outline h/2 outside the particles: 2 pi h/2 longer
 * than the body's in 2D, 16% of a 40 x 20 mm block at 2 mm. A surface
 * stretched past its rest spacing (a risen crust) keeps its rest face, as
 * before (S_ref / S_i > 1 is not taken): an underestimate there, left. */
#define OUTER_HAT 1.4
/* a neighbour's count at q rest spacings */
static inline double outer_share(double q) { return q < OUTER_HAT ? 1 - q / OUTER_HAT : 0.0; }

static void outer_faces(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim, *off = st->nl.off, *nb = st->nl.j;
    const double *x = c.x, *m = c.m;
    const double Sref = 1 + 2 * (dim - 1) * outer_share(1.0); /* a row's two neighbours, a square layer's four */
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        st->oshare[i] = 0;
        if (!(st->outer[i] > 0)) continue;
        const double Vr = m[i] / st->rho0[i], sp = dim == 3 ? cbrt(Vr) : sqrt(Vr);
        double S = 1;
        for (int k = off[i]; k < off[i + 1]; k++) {
            const int j = nb[k];
            if (j == i || !(st->outer[j] > 0)) continue;
            double d[3];
            sph_disp(&st->cells, x + 3 * i, x + 3 * j, d);
            const double r = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            S += outer_share(r / sp);
        }
        /* a lattice's face reads S_ref to round-off: 1 exactly there, so its heat keeps its bits */
        st->oshare[i] = S > Sref * (1 + 1e-9) ? Sref / S : 1.0;
    }
}

void sph_outer_surface(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, dim = c.dim;
    const double *x = c.x;
    if (n <= 0) return;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY}, spmin = INFINITY,
           hmax = 0, hmin = INFINITY;
    for (int i = 0; i < n; i++) {
        for (int a = 0; a < dim; a++) {
            lo[a] = fmin(lo[a], x[3 * i + a]);
            hi[a] = fmax(hi[a], x[3 * i + a]);
        }
        spmin = fmin(spmin, st->sp[i]);
        hmax = fmax(hmax, st->h[i]);
        hmin = fmin(hmin, st->h[i]);
    }
    /* cells coarser than h/2 over 2 (h/2 the discs' radius) no longer close the lens between two joined
     * particles' discs reliably: then, with a periodic axis, and with a position or h not finite, the colour
     * field's flag */
    double cs = 0.5 * spmin;
    int ng[3] = {1, 1, 1};
    size_t cells = 0;
    if (st->cells.anyper || !(isfinite(cs) && cs > 0 && isfinite(hmax))) goto colour;
    for (int a = 0; a < dim; a++)
        if (!isfinite(hi[a] - lo[a])) goto colour;
    for (;;) {
        if (cs > 0.25 * hmin) goto colour;
        double count = 1;
        for (int a = 0; a < dim; a++) {
            const double pad = 0.5 * hmax + 2 * cs, k = ceil((hi[a] - lo[a] + 2 * pad) / cs) + 1;
            count *= k;
            ng[a] = k < 1e9 ? (int)k : 1000000000;
        }
        if (count <= OUTER_MAX_CELLS) {
            cells = (size_t)count;
            break;
        }
        cs *= 1.25;
    }
    if (cells > st->og_cap) {
        sph_outer_free(st);
        st->og = mem_alloc(cells);
        st->oq = mem_alloc(sizeof(int) * cells);
        if (!st->og || !st->oq) {
            sph_outer_free(st);
            goto colour;
        }
        st->og_cap = cells;
    }
    double o[3] = {0, 0, 0};
    /* the grid centred on the particles' box, so a mirror-symmetric body meets a mirror-symmetric grid */
    for (int a = 0; a < dim; a++) o[a] = 0.5 * (lo[a] + hi[a]) - 0.5 * ng[a] * cs;
    const size_t sy = (size_t)ng[0], sz = (size_t)ng[0] * (size_t)ng[1];
    uint8_t *g = st->og;
    memset(g, 0, cells);
    /* 1: cells whose centres lie within h_i / 2 of a particle are the body (1) */
    for (int i = 0; i < n; i++) {
        const double R = 0.5 * st->h[i], R2 = R * R;
        int a0[3] = {0, 0, 0}, a1[3] = {0, 0, 0};
        cell_span(x + 3 * i, R, o, cs, ng, dim, a0, a1);
        for (int k = a0[2]; k <= a1[2]; k++)
            for (int j = a0[1]; j <= a1[1]; j++)
                for (int l = a0[0]; l <= a1[0]; l++) {
                    const double dx0 = o[0] + (l + 0.5) * cs - x[3 * i], dx1 = o[1] + (j + 0.5) * cs - x[3 * i + 1],
                                 dx2 = dim == 3 ? o[2] + (k + 0.5) * cs - x[3 * i + 2] : 0.0;
                    if (dx0 * dx0 + dx1 * dx1 + dx2 * dx2 <= R2) g[l + j * sy + k * sz] = 1;
                }
    }
    /* 2: the empty cells reached from the border, face to face, are outside (2) */
    int *q = st->oq;
    size_t qn = 0;
    for (size_t id = 0; id < cells; id++) {
        const int l = (int)(id % sy), j = (int)((id / sy) % (size_t)ng[1]), k = (int)(id / sz);
        const int border = l == 0 || l == ng[0] - 1 || j == 0 || j == ng[1] - 1 ||
                           (dim == 3 && (k == 0 || k == ng[2] - 1));
        if (border && g[id] == 0) {
            g[id] = 2;
            q[qn++] = (int)id;
        }
    }
    while (qn > 0) {
        const size_t id = (size_t)q[--qn];
        const int l = (int)(id % sy), j = (int)((id / sy) % (size_t)ng[1]), k = (int)(id / sz);
        const int nbr[6][3] = {{l - 1, j, k}, {l + 1, j, k}, {l, j - 1, k}, {l, j + 1, k}, {l, j, k - 1}, {l, j, k + 1}};
        for (int e = 0; e < 2 * dim; e++) {
            const int L = nbr[e][0], J = nbr[e][1], K = nbr[e][2];
            if (L < 0 || L >= ng[0] || J < 0 || J >= ng[1] || K < 0 || K >= ng[2]) continue;
            const size_t t = (size_t)L + (size_t)J * sy + (size_t)K * sz;
            if (g[t] == 0) {
                g[t] = 2;
                q[qn++] = (int)t;
            }
        }
    }
    /* 3: a particle with an outside cell within h_i / 2 plus a cell's diagonal is on the outer surface */
    const double diag = cs * sqrt((double)dim);
    for (int i = 0; i < n; i++) {
        const double R = 0.5 * st->h[i] + diag, R2 = R * R;
        int a0[3] = {0, 0, 0}, a1[3] = {0, 0, 0};
        cell_span(x + 3 * i, R, o, cs, ng, dim, a0, a1);
        int out = 0;
        for (int k = a0[2]; k <= a1[2] && !out; k++)
            for (int j = a0[1]; j <= a1[1] && !out; j++)
                for (int l = a0[0]; l <= a1[0] && !out; l++) {
                    if (g[l + j * sy + k * sz] != 2) continue;
                    const double dx0 = o[0] + (l + 0.5) * cs - x[3 * i], dx1 = o[1] + (j + 0.5) * cs - x[3 * i + 1],
                                 dx2 = dim == 3 ? o[2] + (k + 0.5) * cs - x[3 * i + 2] : 0.0;
                    out = dx0 * dx0 + dx1 * dx1 + dx2 * dx2 <= R2;
                }
        st->outer[i] = out;
    }
    outer_faces(s);
    return;
colour:
    for (int i = 0; i < n; i++) st->outer[i] = st->surf[i];
    outer_faces(s);
}

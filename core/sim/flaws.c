/* flaws.c: the fracture strains' factor field of flaws.h.
 *
 * Why: the local fracture model (plugins/cam_clay_dough.c, "crust fracture")
 * cracks a skin stretched evenly at whichever particle the grid's and the
 * seeding jitter's noise make weakest, so its crack moves with dx
 * (docs/validation.md). A real crust's strength scatters over a physical
 * length (pores, blisters, flaws: brittle foods break statistically); with a
 * fixed field of that length the weak places are the material's, not the
 * grid's.
 *
 * The field: a value noise. Each point of a cubic lattice of spacing lc gets
 * a standard normal value from a hash of its integer coordinates and the
 * seed (splitmix64, then Box-Muller: the same bits on every machine with the
 * same libm); between them the 2^dim corner values are blended with
 * quintic fade weights w_i (C2), and the blend is divided by sqrt(sum w_i^2),
 * so g(x) is exactly a standard normal at every x, not only at the lattice
 * points (a plain blend's variance falls to 1/4 at a 2D cell's centre).
 * f = exp(sigma g - sigma^2 / 2): log-normal, mean 1. It is a function of
 * the seeding position alone, computed once per particle, so it does not
 * depend on dx (to the particles' positions) nor on the thread count. */
#include "flaws.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static uint64_t mix64(uint64_t z) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

static double env_number(const char *name, double def) {
    const char *v = getenv(name);
    if (!v || !*v) return def;
    char *end;
    const double x = strtod(v, &end);
    return *end == 0 ? x : def;
}

flaw_def flaws_from_env(uint64_t seed) {
    flaw_def fd = {0, 0, seed};
    const double l = env_number("HEARTH_FLAW_LENGTH", 0), s = env_number("HEARTH_FLAW_SIGMA", 0.25);
    const double sd = env_number("HEARTH_FLAW_SEED", (double)seed);
    if (l > 0 && isfinite(l) && s >= 0 && isfinite(s)) fd.length = l, fd.sigma = s;
    fd.seed = sd >= 0 && sd < 1e15 ? (uint64_t)sd : seed;
    return fd;
}

/* A standard normal at lattice point (i, j, k): Box-Muller on two 53-bit uniforms of the point's hash. */
static double lattice_normal(uint64_t seed, long i, long j, long k) {
    uint64_t h = mix64(seed);
    h = mix64(h ^ (uint64_t)i);
    h = mix64(h ^ (uint64_t)j);
    h = mix64(h ^ (uint64_t)k);
    const double u1 = ((double)(h >> 11) + 0.5) * (1.0 / 9007199254740992.0); /* (0, 1): log finite */
    const double u2 = (double)(mix64(h) >> 11) * (1.0 / 9007199254740992.0);
    return sqrt(-2 * log(u1)) * cos(6.283185307179586 * u2);
}

static double fade(double t) { return t * t * t * (t * (t * 6 - 15) + 10); }

double flaw_noise(const flaw_def *fd, const double x[3], int dim) {
    long c[3] = {0, 0, 0};
    double w[3][2] = {{1, 0}, {1, 0}, {1, 0}};
    for (int d = 0; d < dim; d++) {
        const double u = x[d] / fd->length, fl = floor(u), t = fade(u - fl);
        c[d] = (long)fl;
        w[d][0] = 1 - t, w[d][1] = t;
    }
    double sum = 0, sw2 = 0;
    for (int a = 0; a < 2; a++)
        for (int b = 0; b < (dim > 1 ? 2 : 1); b++)
            for (int e = 0; e < (dim > 2 ? 2 : 1); e++) {
                const double wi = w[0][a] * w[1][b] * w[2][e];
                if (wi == 0) continue;
                sum += wi * lattice_normal(fd->seed, c[0] + a, c[1] + b, c[2] + e);
                sw2 += wi * wi;
            }
    return sum / sqrt(sw2);
}

double flaw_factor(const flaw_def *fd, const double x[3], int dim) {
    if (!(fd->length > 0)) return 1.0;
    return exp(fd->sigma * flaw_noise(fd, x, dim) - 0.5 * fd->sigma * fd->sigma);
}

int flaw_params(const hearth_material *m, int k[2]) {
    int n = 0;
    for (int i = 0; i < m->nparams && n < 2; i++)
        if (strcmp(m->params[i].name, "fracture_strain") == 0 || strcmp(m->params[i].name, "fracture_strain_set") == 0)
            k[n++] = i;
    return n;
}

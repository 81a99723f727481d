/* sph_fixture.h: small helpers for building scenes in the SPH tests
 * (unit_sph*.c): the scene definition, a Newtonian material, a box body of
 * one particle per dx^dim, and a pinned speck that turns heat on. */
#ifndef HEARTH_SPH_FIXTURE_H
#define HEARTH_SPH_FIXTURE_H
#include <stdio.h>

#include "hearth/hearth.h"
#include "scene.h"

static inline hearth_scene_def sph_def(int dim, double dx, const double lo[3], const double hi[3]) {
    hearth_scene_def d = hearth_default_scene_def();
    d.solver = HEARTH_SOLVER_SPH;
    d.dim = dim;
    d.dx = dx;
    for (int a = 0; a < 3; a++) d.lo[a] = lo[a], d.hi[a] = hi[a];
    return d;
}

static inline int newtonian(hearth_scene *s, double rho, double bulk, double eta) {
    const char *n[] = {"density", "bulk", "viscosity"};
    const double v[] = {rho, bulk, eta};
    hearth_error err;
    int m = hearth_scene_add_material(s, "newtonian", n, v, 3, &err);
    if (m < 0) fprintf(stderr, "material: %s\n", err.msg);
    return m;
}

/* The box [lo, hi], one particle per cell, no jitter; in 2D the box spans z in [-0.5, 0.5]. */
static inline int sph_box(hearth_scene *s, int mat, const double lo[3], const double hi[3], int fixed, double T) {
    double c[3], hh[3];
    for (int a = 0; a < 3; a++) c[a] = 0.5 * (lo[a] + hi[a]), hh[a] = 0.5 * (hi[a] - lo[a]);
    if (s->def.dim == 2) c[2] = 0, hh[2] = 0.5;
    hearth_shape *b = hearth_shape_box(c, hh);
    hearth_body_def bd = hearth_default_body_def();
    bd.shape = b;
    bd.material = mat;
    bd.ppc = 1;
    bd.jitter = 0;
    bd.fixed = fixed;
    bd.temperature = T;
    hearth_error err;
    int id = hearth_scene_add_body(s, &bd, &err);
    if (id < 0) fprintf(stderr, "body: %s\n", err.msg);
    hearth_shape_free(b);
    return id;
}
/* A 2D block of particles filling [x0, x1] x [y0, y1] (sph_box in the plane). */
static inline int box_body(hearth_scene *s, int mat, double x0, double y0, double x1, double y1, int fixed, double T) {
    const double lo[3] = {x0, y0, -0.5}, hi[3] = {x1, y1, 0.5};
    return sph_box(s, mat, lo, hi, fixed, T);
}

/* A pinned 2 mm speck of material mat at (x, y) and temperature T, one
 * particle, far from what a test watches: a fixed body with a temperature is
 * what turns the scene's temperature field on. */
static inline void sph_heat_speck(hearth_scene *s, int mat, double x, double y, double T) {
    hearth_error err;
    hearth_body_def bd = hearth_default_body_def();
    const double c[3] = {x, y, 0}, hh[3] = {0.001, 0.001, 0.5};
    bd.shape = hearth_shape_box(c, hh);
    bd.material = mat;
    bd.ppc = 1;
    bd.jitter = 0;
    bd.fixed = 1;
    bd.temperature = T;
    if (hearth_scene_add_body(s, &bd, &err) < 0) fprintf(stderr, "%s\n", err.msg);
    hearth_shape_free((hearth_shape *)bd.shape);
}

#endif

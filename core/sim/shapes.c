/* shapes.c: hearth_shape, an immutable tree of signed distance functions.
 *
 * Leaves are exact Euclidean SDFs (negative inside); combine nodes use the
 * usual min / max / max(a, -b), which stay exact outside a union but are only
 * bounds elsewhere — enough for contact, where the sign and the distance near
 * the surface are what matter.
 *
 * A 2D scene evaluates the same 3D SDF at z = 0. Every primitive here is
 * either symmetric about z = 0 when placed in that plane (sphere -> disc,
 * y-axis cylinder -> rectangle, y-axis container -> U) or explicitly
 * unbounded in z (a box with half[2] == 0), so the 2D distances are the exact
 * 2D ones.
 *
 * Normals are analytic everywhere: each primitive returns the gradient of the
 * branch that is active, and combine nodes pass on the normal of the child
 * that wins the min/max. On a ridge (a point equidistant from two faces, the
 * axis of a cylinder) the gradient does not exist and we return one valid
 * face normal. We rejected central differences as the general method: they
 * cost six extra tree walks per query and smear the normal across ridges.
 *
 * Masks (cookie cutters from PNG images) are the one leaf that is sampled
 * rather than analytic: shape_mask.c owns their distance field, and this file
 * treats them like any other leaf. A mask is unbounded in z like a 2D box;
 * SHAPE_EXTRUDE cuts any shape to a slab z0..z1.
 */
#include <math.h>
#include <stdint.h>
#include <string.h>

#include "alloc.h"
#include "checkpoint.h"
#include "error.h"
#include "hearth/hearth.h"
#include "shapes.h"

typedef enum shape_kind {
    SHAPE_PLANE,
    SHAPE_BOX,
    SHAPE_SPHERE,
    SHAPE_CYLINDER,
    SHAPE_CAPSULE,
    SHAPE_CONTAINER,
    SHAPE_COMBINE,
    /* appended so the kind numbers in existing checkpoints keep their meaning */
    SHAPE_MASK,
    SHAPE_EXTRUDE
} shape_kind;

struct hearth_shape {
    shape_kind kind;
    hearth_shape_op op;   /* SHAPE_COMBINE only */
    double c[3];          /* plane point, box/sphere/cylinder centre, capsule a, container base */
    double u[3];          /* plane normal, cylinder/container unit axis */
    double b[3];          /* box half extents, capsule end b, extrude z0 and z1 in b[0], b[1] */
    double r;             /* radius (container: inner radius) */
    double hh;            /* cylinder half height, container wall height */
    double wall, floor;   /* container thicknesses */
    hearth_shape *ca, *cb; /* combine children, extrude child in ca (owned) */
    shape_mask *mask;      /* SHAPE_MASK: its sampled field (owned) */
    int flat;              /* extrude: the child does not depend on z (see sdf_extrude) */
};

/* ---- small vector helpers (static: tensor.h has no vector ops) ------- */

static double dot3(const double a[3], const double b[3]) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
static double len3(const double a[3]) { return sqrt(dot3(a, a)); }
static int finite3(const double a[3]) { return isfinite(a[0]) && isfinite(a[1]) && isfinite(a[2]); }

static void set3(double d[3], double x, double y, double z) {
    d[0] = x;
    d[1] = y;
    d[2] = z;
}

/* Unit vector of a into d; 0 when a has (numerically) no direction. */
static int unit3(const double a[3], double d[3]) {
    double l = len3(a);
    if (!(l > 1e-300) || !isfinite(l)) return 0;
    set3(d, a[0] / l, a[1] / l, a[2] / l);
    return 1;
}

/* A unit vector perpendicular to unit u, used on ridges where any radial
 * direction is a valid normal. Prefer one in the xy plane (u x z) so 2D
 * scenes never receive a z normal. */
static void perp3(const double u[3], double p[3]) {
    double t[3] = {u[1], -u[0], 0.0}; /* u x (0,0,1) */
    if (!unit3(t, p)) set3(p, 1.0, 0.0, 0.0); /* u is along z */
}

/* ---- allocation ------------------------------------------------------- */

/* Why the last constructor on this thread returned NULL (static text naming
 * the parameter and its valid range), for hearth_shape_error. A thread-local
 * string keeps the constructors' signatures (public, used by scripts and
 * plugins' hosts) while a NaN centre is no longer reported as out of memory. */
static _Thread_local const char *shape_why;

const char *hearth_shape_error(void) { return shape_why; }

static hearth_shape *refuse(const char *why) {
    shape_why = why;
    return NULL;
}

static hearth_shape *shape_new(shape_kind kind) {
    hearth_shape *s = mem_calloc(sizeof *s);
    if (s) s->kind = kind;
    shape_why = s ? NULL : "out of memory";
    return s;
}

void hearth_shape_free(hearth_shape *s) {
    if (!s) return;
    hearth_shape_free(s->ca);
    hearth_shape_free(s->cb);
    mask_free(s->mask);
    mem_free(s, sizeof *s);
}

hearth_shape *hearth_shape_copy(const hearth_shape *s) {
    if (!s) return refuse("copy: the shape is NULL");
    hearth_shape *d = shape_new(s->kind);
    if (!d) return NULL;
    *d = *s;
    d->ca = d->cb = NULL;
    d->mask = NULL;
    if (s->kind == SHAPE_COMBINE) {
        d->ca = hearth_shape_copy(s->ca);
        d->cb = d->ca ? hearth_shape_copy(s->cb) : NULL;
        if (!d->cb) {
            hearth_shape_free(d); /* frees whichever child was made */
            return NULL;
        }
    } else if (s->kind == SHAPE_EXTRUDE) {
        d->ca = hearth_shape_copy(s->ca);
        if (!d->ca) {
            hearth_shape_free(d);
            return NULL;
        }
    } else if (s->kind == SHAPE_MASK) {
        /* A deep copy keeps every shape independently owned (no shared
         * counts to get wrong); masks are at most 64 MB and copies are rare. */
        d->mask = mask_copy(s->mask);
        if (!d->mask) {
            hearth_shape_free(d);
            return refuse("out of memory");
        }
    }
    return d;
}

/* ---- constructors: NULL on bad arguments (hearth_shape_error says which) or
 * allocation failure ------------------------------------------------------ */

hearth_shape *hearth_shape_plane(const double point[3], const double normal[3]) {
    if (!point || !normal) return refuse("plane: point or normal is NULL");
    if (!finite3(point)) return refuse("plane: point is not finite (NaN or inf)");
    double n[3];
    if (!unit3(normal, n)) return refuse("plane: normal must be a finite non-zero vector");
    hearth_shape *s = shape_new(SHAPE_PLANE);
    if (!s) return NULL;
    memcpy(s->c, point, sizeof s->c);
    memcpy(s->u, n, sizeof s->u);
    return s;
}

hearth_shape *hearth_shape_box(const double centre[3], const double half[3]) {
    if (!centre || !half) return refuse("box: centre or half extents are NULL");
    if (!finite3(centre)) return refuse("box: centre is not finite (NaN or inf)");
    if (!finite3(half) || half[0] < 0 || half[1] < 0 || half[2] < 0)
        return refuse("box: half extents must be finite and >= 0 m");
    hearth_shape *s = shape_new(SHAPE_BOX);
    if (!s) return NULL;
    memcpy(s->c, centre, sizeof s->c);
    memcpy(s->b, half, sizeof s->b);
    return s;
}

hearth_shape *hearth_shape_sphere(const double centre[3], double radius) {
    if (!centre) return refuse("sphere: centre is NULL");
    if (!finite3(centre)) return refuse("sphere: centre is not finite (NaN or inf)");
    if (!(radius > 0) || !isfinite(radius)) return refuse("sphere: radius must be finite and > 0 m");
    hearth_shape *s = shape_new(SHAPE_SPHERE);
    if (!s) return NULL;
    memcpy(s->c, centre, sizeof s->c);
    s->r = radius;
    return s;
}

hearth_shape *hearth_shape_cylinder(const double centre[3], const double axis[3], double radius, double half_height) {
    if (!centre || !axis) return refuse("cylinder: centre or axis is NULL");
    if (!finite3(centre)) return refuse("cylinder: centre is not finite (NaN or inf)");
    if (!(radius > 0) || !isfinite(radius)) return refuse("cylinder: radius must be finite and > 0 m");
    if (!(half_height >= 0) || !isfinite(half_height)) return refuse("cylinder: half height must be finite and >= 0 m");
    double u[3];
    if (!unit3(axis, u)) return refuse("cylinder: axis must be a finite non-zero vector");
    hearth_shape *s = shape_new(SHAPE_CYLINDER);
    if (!s) return NULL;
    memcpy(s->c, centre, sizeof s->c);
    memcpy(s->u, u, sizeof s->u);
    s->r = radius;
    s->hh = half_height;
    return s;
}

hearth_shape *hearth_shape_capsule(const double a[3], const double b[3], double radius) {
    /* a == b is allowed: the capsule is then a sphere. */
    if (!a || !b) return refuse("capsule: an end is NULL");
    if (!finite3(a) || !finite3(b)) return refuse("capsule: an end is not finite (NaN or inf)");
    if (!(radius > 0) || !isfinite(radius)) return refuse("capsule: radius must be finite and > 0 m");
    hearth_shape *s = shape_new(SHAPE_CAPSULE);
    if (!s) return NULL;
    memcpy(s->c, a, sizeof s->c);
    memcpy(s->b, b, sizeof s->b);
    s->r = radius;
    return s;
}

hearth_shape *hearth_shape_container(const double base[3], const double axis[3], double r_in, double height,
                                     double wall, double floor) {
    if (!base || !axis) return refuse("container: base or axis is NULL");
    if (!finite3(base)) return refuse("container: base is not finite (NaN or inf)");
    if (!(r_in > 0) || !isfinite(r_in)) return refuse("container: inner radius must be finite and > 0 m");
    if (!(wall > 0) || !isfinite(wall)) return refuse("container: wall must be finite and > 0 m");
    if (!(height >= 0) || !isfinite(height)) return refuse("container: height must be finite and >= 0 m");
    if (!(floor >= 0) || !isfinite(floor)) return refuse("container: floor must be finite and >= 0 m");
    if (!(height + floor > 0)) return refuse("container: height + floor must be > 0 m (nothing solid would remain)");
    double u[3];
    if (!unit3(axis, u)) return refuse("container: axis must be a finite non-zero vector");
    hearth_shape *s = shape_new(SHAPE_CONTAINER);
    if (!s) return NULL;
    memcpy(s->c, base, sizeof s->c);
    memcpy(s->u, u, sizeof s->u);
    s->r = r_in;
    s->hh = height;
    s->wall = wall;
    s->floor = floor;
    return s;
}

hearth_shape *hearth_shape_mask(const char *png_path, const double lo[2], const double hi[2], hearth_error *err) {
    shape_mask *m = mask_load(png_path, lo, hi, err);
    if (!m) return NULL;
    hearth_shape *s = shape_new(SHAPE_MASK);
    if (!s) {
        mask_free(m);
        err_set(err, HEARTH_ERR_NOMEM, "mask '%s': out of memory", png_path);
        return NULL;
    }
    s->mask = m;
    return s;
}

int shape_box_2d(const hearth_shape *s) { return s && s->kind == SHAPE_BOX && !(s->b[2] > 0); }

/* Whether s is a function of x and y only (a 2D shape): then the extrusion
 * formula below is exact. */
static int z_free(const hearth_shape *s) {
    switch (s->kind) {
    case SHAPE_MASK: return 1;
    case SHAPE_PLANE: return s->u[2] == 0.0;
    case SHAPE_BOX: return !(s->b[2] > 0);
    case SHAPE_COMBINE: return z_free(s->ca) && z_free(s->cb);
    default: return 0;
    }
}

hearth_shape *hearth_shape_extrude(const hearth_shape *child, double z0, double z1) {
    if (!child) return refuse("extrude: the shape is NULL");
    if (!isfinite(z0) || !isfinite(z1) || !(z0 < z1)) return refuse("extrude: z0 and z1 must be finite with z0 < z1");
    hearth_shape *s = shape_new(SHAPE_EXTRUDE);
    if (!s) return NULL;
    s->b[0] = z0;
    s->b[1] = z1;
    s->ca = hearth_shape_copy(child);
    if (!s->ca) {
        hearth_shape_free(s);
        return NULL;
    }
    s->flat = z_free(child);
    return s;
}

hearth_shape *hearth_shape_combine(hearth_shape_op op, const hearth_shape *a, const hearth_shape *b) {
    if (!a || !b) return refuse("combine: a shape is NULL");
    if (op != HEARTH_UNION && op != HEARTH_INTERSECT && op != HEARTH_SUBTRACT)
        return refuse("combine: op must be HEARTH_UNION, HEARTH_INTERSECT or HEARTH_SUBTRACT");
    hearth_shape *s = shape_new(SHAPE_COMBINE);
    if (!s) return NULL;
    s->op = op;
    s->ca = hearth_shape_copy(a);
    s->cb = s->ca ? hearth_shape_copy(b) : NULL;
    if (!s->cb) {
        hearth_shape_free(s);
        return NULL;
    }
    return s;
}

/* ---- distance ------------------------------------------------------------ */

/* Exact SDF of the rectangle |p - centre| <= half in a 2D plane, with its
 * gradient (g may be NULL). The same formula is the exact box SDF; keeping a
 * 2D copy lets the solids of revolution work in their meridian plane. */
static double rect2(double px, double py, double hx, double hy, double g[2]) {
    double qx = fabs(px) - hx, qy = fabs(py) - hy;
    double sx = px < 0 ? -1.0 : 1.0, sy = py < 0 ? -1.0 : 1.0;
    if (qx > 0 || qy > 0) {
        double ox = qx > 0 ? qx : 0.0, oy = qy > 0 ? qy : 0.0;
        double d = sqrt(ox * ox + oy * oy);
        if (g) {
            g[0] = sx * ox / d;
            g[1] = sy * oy / d;
        }
        return d;
    }
    /* inside or on the surface: nearest face is the larger q */
    if (g) {
        g[0] = qx >= qy ? sx : 0.0;
        g[1] = qx >= qy ? 0.0 : sy;
    }
    return qx >= qy ? qx : qy;
}

/* Meridian-plane coordinates of x about an axis through c along unit u:
 * axial coordinate a, radial distance rho and radial unit vector rhat. */
static void meridian(const double c[3], const double u[3], const double x[3], double *a, double *rho,
                     double rhat[3]) {
    double p[3] = {x[0] - c[0], x[1] - c[1], x[2] - c[2]};
    *a = dot3(p, u);
    double rv[3] = {p[0] - *a * u[0], p[1] - *a * u[1], p[2] - *a * u[2]};
    *rho = len3(rv);
    if (!rhat) return; /* the distance alone asks no direction (helper speed) */
    /* unit3(rv) with its length, which is *rho: the same numbers */
    if (!(*rho > 1e-300) || !isfinite(*rho)) perp3(u, rhat); /* on the axis: a ridge, any radial direction */
    else set3(rhat, rv[0] / *rho, rv[1] / *rho, rv[2] / *rho);
}

/* Exact SDF of a solid of revolution whose meridian section is the rectangle
 * rho in [rho_c - hr, rho_c + hr], a in [a_c - ha, a_c + ha]. Either rho_c = 0
 * (a solid cylinder: the section is mirror-symmetric about the axis) or
 * rho_c - hr >= 0 (an annulus lying in rho >= 0); in both cases the 2D
 * distance in the meridian plane is the 3D distance. Covers the capped
 * cylinder, the container's wall and its floor disc. */
static double meridian_rect(double a, double rho, const double rhat[3], const double u[3], double rho_c, double hr,
                            double a_c, double ha, double n[3]) {
    double g[2];
    double d = rect2(rho - rho_c, a - a_c, hr, ha, n ? g : NULL);
    if (n)
        for (int i = 0; i < 3; i++) n[i] = g[0] * rhat[i] + g[1] * u[i];
    return d;
}
static double revolved_rect(const double c[3], const double u[3], const double x[3], double rho_c, double hr,
                            double a_c, double ha, double n[3]) {
    double a, rho, rhat[3] = {0, 0, 0};
    meridian(c, u, x, &a, &rho, n ? rhat : NULL);
    return meridian_rect(a, rho, rhat, u, rho_c, hr, a_c, ha, n);
}

static double sdf_box(const hearth_shape *s, const double x[3], double n[3]) {
    /* Exact box SDF (Quilez): |max(q,0)| + min(max_i q_i, 0) with q = |p| - h.
     * A zero z half extent means "unbounded in z", so the header's "in 2D the
     * z extent is ignored" holds for the natural 2D call with half z = 0. */
    int m = s->b[2] > 0 ? 3 : 2;
    double q[3], sg[3], out2 = 0.0, qmax = -HUGE_VAL;
    int imax = 0;
    for (int i = 0; i < 3; i++) {
        double p = x[i] - s->c[i];
        sg[i] = p < 0 ? -1.0 : 1.0;
        q[i] = i < m ? fabs(p) - s->b[i] : -HUGE_VAL;
        if (q[i] > 0) out2 += q[i] * q[i];
        if (q[i] > qmax) {
            qmax = q[i];
            imax = i;
        }
    }
    if (out2 > 0) {
        double d = sqrt(out2);
        if (n)
            for (int i = 0; i < 3; i++) n[i] = q[i] > 0 ? sg[i] * q[i] / d : 0.0;
        return d;
    }
    if (n) {
        set3(n, 0, 0, 0);
        n[imax] = sg[imax];
    }
    return qmax;
}

static double sdf_capsule(const hearth_shape *s, const double x[3], double n[3]) {
    double ab[3] = {s->b[0] - s->c[0], s->b[1] - s->c[1], s->b[2] - s->c[2]};
    double ax[3] = {x[0] - s->c[0], x[1] - s->c[1], x[2] - s->c[2]};
    double l2 = dot3(ab, ab), h = l2 > 0 ? dot3(ax, ab) / l2 : 0.0;
    h = h < 0 ? 0.0 : (h > 1 ? 1.0 : h);
    double p[3] = {ax[0] - h * ab[0], ax[1] - h * ab[1], ax[2] - h * ab[2]};
    double d = len3(p) - s->r;
    if (n && !unit3(p, n)) {
        /* on the segment: any direction perpendicular to it is a normal */
        double u[3];
        if (unit3(ab, u)) perp3(u, n);
        else set3(n, 0.0, 1.0, 0.0);
    }
    return d;
}

static double sdf_container(const hearth_shape *s, const double x[3], double n[3]) {
    /* The wall's section runs from -floor (not 0) to height: the union is the
     * same solid, but the overlap removes a seam at the base where both parts
     * would report distance 0 deep inside the solid. */
    double rw = s->r + 0.5 * s->wall;
    double aw = 0.5 * (s->hh - s->floor);
    double hw = 0.5 * (s->hh + s->floor);
    /* the wall and the floor share the point's meridian coordinates (the same c, u and x: the same numbers;
     * made once, helper speed) */
    double nw[3], a, rho, rhat[3] = {0, 0, 0};
    meridian(s->c, s->u, x, &a, &rho, n ? rhat : NULL);
    double d = meridian_rect(a, rho, rhat, s->u, rw, 0.5 * s->wall, aw, hw, n ? nw : NULL);
    if (n) memcpy(n, nw, sizeof nw);
    if (s->floor > 0) {
        /* floor disc: radius r_in + wall, axial -floor..0 */
        double nf[3];
        double R = s->r + s->wall;
        double df = meridian_rect(a, rho, rhat, s->u, 0.0, R, -0.5 * s->floor, 0.5 * s->floor, n ? nf : NULL);
        if (df < d) {
            d = df;
            if (n) memcpy(n, nf, sizeof nf);
        }
    }
    return d;
}

static double sdf_mask(const hearth_shape *s, const double x[3], double n[3]) {
    double g[2];
    double d = mask_sdf(s->mask, x[0], x[1], n ? g : NULL);
    if (n) {
        double g3[3] = {g[0], g[1], 0.0};
        if (!unit3(g3, n)) set3(n, 0.0, 1.0, 0.0); /* flat spot of the sampled field */
    }
    return d;
}

/* The intersection of the child with the slab z0 <= z <= z1. For a 2D child
 * (distance d2 in the xy plane, independent of z) the distance to the prism
 * is exact: outside both, the nearest point is on the rim, at
 * sqrt(d2^2 + dz^2); otherwise max(d2, dz). For a 3D child the rim formula
 * could overstate the distance (the nearest point may be on a cap away from
 * the rim), so it gets the plain max, a bound like the other intersections. */
static double sdf_extrude(const hearth_shape *s, const double x[3], double n[3]) {
    double n2[3];
    double d2 = hearth_shape_sdf(s->ca, x, n ? n2 : NULL);
    double below = s->b[0] - x[2], above = x[2] - s->b[1];
    double dz = fmax(below, above), sz = above >= below ? 1.0 : -1.0;
    if (s->flat && d2 > 0 && dz > 0) {
        double d = hypot(d2, dz);
        if (n) {
            double v[3] = {d2 * n2[0], d2 * n2[1], dz * sz};
            if (!unit3(v, n)) set3(n, 0.0, 0.0, sz);
        }
        return d;
    }
    if (d2 >= dz) {
        if (n) memcpy(n, n2, sizeof n2);
        return d2;
    }
    if (n) set3(n, 0.0, 0.0, sz);
    return dz;
}

double hearth_shape_sdf(const hearth_shape *s, const double x[3], double normal[3]) {
    HEARTH_ASSERT(s && x);
    double d;
    switch (s->kind) {
    case SHAPE_PLANE: {
        double p[3] = {x[0] - s->c[0], x[1] - s->c[1], x[2] - s->c[2]};
        if (normal) memcpy(normal, s->u, sizeof s->u);
        return dot3(p, s->u);
    }
    case SHAPE_BOX: return sdf_box(s, x, normal);
    case SHAPE_SPHERE: {
        double p[3] = {x[0] - s->c[0], x[1] - s->c[1], x[2] - s->c[2]};
        if (normal && !unit3(p, normal)) set3(normal, 0.0, 1.0, 0.0);
        return len3(p) - s->r;
    }
    case SHAPE_CYLINDER: return revolved_rect(s->c, s->u, x, 0.0, s->r, 0.0, s->hh, normal);
    case SHAPE_CAPSULE: return sdf_capsule(s, x, normal);
    case SHAPE_CONTAINER: return sdf_container(s, x, normal);
    case SHAPE_MASK: return sdf_mask(s, x, normal);
    case SHAPE_EXTRUDE: return sdf_extrude(s, x, normal);
    case SHAPE_COMBINE: {
        double na[3], nb[3];
        double da = hearth_shape_sdf(s->ca, x, normal ? na : NULL);
        double db = hearth_shape_sdf(s->cb, x, normal ? nb : NULL);
        int take_a;
        if (s->op == HEARTH_UNION) {
            take_a = da <= db;
            d = take_a ? da : db;
        } else if (s->op == HEARTH_INTERSECT) {
            take_a = da >= db;
            d = take_a ? da : db;
        } else {
            /* subtract: max(a, -b); the normal of -b is -nb */
            take_a = da >= -db;
            d = take_a ? da : -db;
            if (normal && !take_a)
                for (int i = 0; i < 3; i++) nb[i] = -nb[i];
        }
        if (normal) memcpy(normal, take_a ? na : nb, sizeof na);
        return d;
    }
    }
    HEARTH_ASSERT(0 && "unknown shape kind");
    return HUGE_VAL;
}

/* ---- bounds ------------------------------------------------------------- */

/* AABB of a capped cylinder: along axis i the disc rims reach r*sqrt(1-u_i^2)
 * beyond the axis segment's ends. */
static void cylinder_bounds(const double c[3], const double u[3], double r, double hh, double lo[3],
                            double hi[3]) {
    for (int i = 0; i < 3; i++) {
        double s2 = 1.0 - u[i] * u[i];
        double e = hh * fabs(u[i]) + r * sqrt(s2 > 0 ? s2 : 0.0);
        lo[i] = c[i] - e;
        hi[i] = c[i] + e;
    }
}

int shape_axis_plane(const hearth_shape *s, int *axis, int *sign, double *c) {
    if (s->kind != SHAPE_PLANE) return 0;
    for (int k = 0; k < 3; k++)
        if (fabs(s->u[k]) == 1.0 && s->u[(k + 1) % 3] == 0.0 && s->u[(k + 2) % 3] == 0.0) {
            *axis = k, *sign = s->u[k] > 0 ? 1 : -1, *c = s->c[k];
            return 1;
        }
    return 0;
}

void hearth_shape_bounds(const hearth_shape *s, double lo[3], double hi[3]) {
    HEARTH_ASSERT(s && lo && hi);
    switch (s->kind) {
    case SHAPE_PLANE:
        for (int i = 0; i < 3; i++) {
            lo[i] = -HUGE_VAL;
            hi[i] = HUGE_VAL;
        }
        return;
    case SHAPE_BOX:
        for (int i = 0; i < 3; i++) {
            int unbounded = i == 2 && !(s->b[2] > 0);
            lo[i] = unbounded ? -HUGE_VAL : s->c[i] - s->b[i];
            hi[i] = unbounded ? HUGE_VAL : s->c[i] + s->b[i];
        }
        return;
    case SHAPE_SPHERE:
        for (int i = 0; i < 3; i++) {
            lo[i] = s->c[i] - s->r;
            hi[i] = s->c[i] + s->r;
        }
        return;
    case SHAPE_CYLINDER: cylinder_bounds(s->c, s->u, s->r, s->hh, lo, hi); return;
    case SHAPE_CAPSULE:
        for (int i = 0; i < 3; i++) {
            lo[i] = fmin(s->c[i], s->b[i]) - s->r;
            hi[i] = fmax(s->c[i], s->b[i]) + s->r;
        }
        return;
    case SHAPE_CONTAINER: {
        /* the whole thing fits the capped cylinder of radius r_in + wall over -floor..height */
        double m = 0.5 * (s->hh - s->floor), cc[3];
        for (int i = 0; i < 3; i++) cc[i] = s->c[i] + m * s->u[i];
        cylinder_bounds(cc, s->u, s->r + s->wall, 0.5 * (s->hh + s->floor), lo, hi);
        return;
    }
    case SHAPE_MASK:
        mask_bounds(s->mask, lo, hi); /* writes x and y */
        lo[2] = -HUGE_VAL;
        hi[2] = HUGE_VAL;
        return;
    case SHAPE_EXTRUDE:
        hearth_shape_bounds(s->ca, lo, hi);
        lo[2] = fmax(lo[2], s->b[0]);
        hi[2] = fmin(hi[2], s->b[1]);
        return;
    case SHAPE_COMBINE: {
        double blo[3], bhi[3];
        hearth_shape_bounds(s->ca, lo, hi);
        if (s->op == HEARTH_SUBTRACT) return; /* a minus b lies inside a */
        hearth_shape_bounds(s->cb, blo, bhi);
        for (int i = 0; i < 3; i++) {
            if (s->op == HEARTH_UNION) {
                lo[i] = fmin(lo[i], blo[i]);
                hi[i] = fmax(hi[i], bhi[i]);
            } else {
                /* may come out empty (lo > hi) when a and b do not meet */
                lo[i] = fmax(lo[i], blo[i]);
                hi[i] = fmin(hi[i], bhi[i]);
            }
        }
        return;
    }
    }
    HEARTH_ASSERT(0 && "unknown shape kind");
}

/* ---- serialisation (checkpoints) ------------------------------------- */

int shape_write(FILE *f, const hearth_shape *s) {
    int32_t k[2] = {(int32_t)s->kind, (int32_t)s->op};
    double v[12] = {s->c[0], s->c[1], s->c[2], s->u[0], s->u[1], s->u[2], s->b[0], s->b[1], s->b[2], s->r, s->hh, s->wall};
    if (fwrite(k, sizeof k, 1, f) != 1 || fwrite(v, sizeof v, 1, f) != 1 || fwrite(&s->floor, sizeof s->floor, 1, f) != 1)
        return -1;
    if (s->kind == SHAPE_COMBINE) return shape_write(f, s->ca) || shape_write(f, s->cb);
    if (s->kind == SHAPE_EXTRUDE) return shape_write(f, s->ca);
    if (s->kind == SHAPE_MASK) return mask_write(f, s->mask);
    return 0;
}

/* Whether a node read from a checkpoint holds values its constructor would
 * accept: a crafted file must not build a shape the constructors refuse (a
 * NaN centre, a zero axis) and so reach the solver with NaN distances. */
static int unit_ok(const double u[3]) { return finite3(u) && fabs(len3(u) - 1.0) <= 1e-9; }

static const char *node_problem(const hearth_shape *s) {
    if (!finite3(s->c) || !finite3(s->u) || !finite3(s->b) || !isfinite(s->r) || !isfinite(s->hh) ||
        !isfinite(s->wall) || !isfinite(s->floor))
        return "collider shape: a non-finite number";
    if ((unsigned)s->op > HEARTH_SUBTRACT) return "collider shape: unknown boolean operation";
    switch (s->kind) {
    case SHAPE_PLANE: return unit_ok(s->u) ? NULL : "collider shape: a plane normal that is not a unit vector";
    case SHAPE_BOX:
        return s->b[0] >= 0 && s->b[1] >= 0 && s->b[2] >= 0 ? NULL : "collider shape: a box with a negative half extent";
    case SHAPE_SPHERE:
    case SHAPE_CAPSULE: return s->r > 0 ? NULL : "collider shape: a radius <= 0";
    case SHAPE_CYLINDER:
        return unit_ok(s->u) && s->r > 0 && s->hh >= 0 ? NULL : "collider shape: a cylinder with a bad axis, radius or height";
    case SHAPE_CONTAINER:
        return unit_ok(s->u) && s->r > 0 && s->wall > 0 && s->hh >= 0 && s->floor >= 0 && s->hh + s->floor > 0
                   ? NULL
                   : "collider shape: a container with a bad axis, radius, height, wall or floor";
    case SHAPE_EXTRUDE: return s->b[0] < s->b[1] ? NULL : "collider shape: an extrusion with z0 >= z1";
    default: return NULL;
    }
}

/* Bytes of one node record: kind, op, 13 doubles. */
#define SHAPE_NODE_BYTES (2 * sizeof(int32_t) + 13 * sizeof(double))
/* Bytes of a mask record's own header: w, h, lo[2], hi[2]. */
#define MASK_HEADER_BYTES (2 * sizeof(int32_t) + 4 * sizeof(double))

hearth_shape *shape_read_mem(ck_cursor *cur, int depth) {
    int32_t k[2];
    double v[13];
    if (depth > SHAPE_DEPTH_MAX) {
        ck_fail(cur, "collider shape: the tree is deeper than 64 levels");
        return NULL;
    }
    if (ck_get(cur, k, sizeof k) || ck_get(cur, v, sizeof v)) return NULL;
    if (k[0] < SHAPE_PLANE || k[0] > SHAPE_EXTRUDE) {
        ck_fail(cur, "collider shape: unknown node kind");
        return NULL;
    }
    hearth_shape *s = shape_new((shape_kind)k[0]);
    if (!s) {
        ck_fail(cur, "out of memory for a collider shape");
        return NULL;
    }
    s->op = (hearth_shape_op)k[1];
    for (int d = 0; d < 3; d++) {
        s->c[d] = v[d];
        s->u[d] = v[3 + d];
        s->b[d] = v[6 + d];
    }
    s->r = v[9];
    s->hh = v[10];
    s->wall = v[11];
    s->floor = v[12];
    const char *why = (unsigned)k[1] > HEARTH_SUBTRACT ? "collider shape: unknown boolean operation" : node_problem(s);
    if (why) {
        ck_fail(cur, why);
        hearth_shape_free(s);
        return NULL;
    }
    if (s->kind == SHAPE_COMBINE) {
        s->ca = shape_read_mem(cur, depth + 1);
        s->cb = s->ca ? shape_read_mem(cur, depth + 1) : NULL;
    } else if (s->kind == SHAPE_EXTRUDE) {
        s->ca = shape_read_mem(cur, depth + 1);
        if (s->ca) s->flat = z_free(s->ca);
    } else if (s->kind == SHAPE_MASK) {
        /* the field's size is checked against the bytes left before mask_read
         * allocates it; mask_read then parses exactly that slice */
        int32_t wh[2] = {0, 0};
        if (cur->left >= sizeof wh) memcpy(wh, cur->p, sizeof wh);
        if (wh[0] < 1 || wh[1] < 1 || wh[0] > MASK_DIM_MAX || wh[1] > MASK_DIM_MAX) {
            ck_fail(cur, cur->left < sizeof wh ? "truncated" : "collider shape: mask size out of range [1, 4096]");
        } else {
            const size_t bytes = MASK_HEADER_BYTES + sizeof(float) * (size_t)wh[0] * (size_t)wh[1];
            if (bytes > cur->left) {
                ck_fail(cur, "truncated");
            } else {
                FILE *f = fmemopen((void *)(uintptr_t)cur->p, bytes, "rb");
                s->mask = f ? mask_read(f) : NULL;
                if (f) fclose(f);
                if (!s->mask) ck_fail(cur, "collider shape: a bad mask field");
                else {
                    cur->p += bytes;
                    cur->left -= bytes;
                }
            }
        }
        if (!s->mask) {
            hearth_shape_free(s);
            return NULL;
        }
        return s;
    }
    if ((s->kind == SHAPE_COMBINE && (!s->ca || !s->cb)) || (s->kind == SHAPE_EXTRUDE && !s->ca)) {
        hearth_shape_free(s);
        return NULL;
    }
    return s;
}

hearth_shape *shape_read(FILE *f, int depth) {
    /* the rest of the stream into memory, parsed by shape_read_mem, then the
     * stream left just after the tree (one parser for files and checkpoints) */
    const long start = ftell(f);
    if (start < 0 || fseek(f, 0, SEEK_END) != 0) return NULL;
    const long end = ftell(f);
    if (end < start || fseek(f, start, SEEK_SET) != 0) return NULL;
    const size_t n = (size_t)(end - start);
    uint8_t *buf = mem_alloc(n ? n : 1);
    if (!buf) return NULL;
    hearth_shape *s = NULL;
    if (fread(buf, 1, n, f) == n) {
        ck_cursor cur = {buf, n, 0, NULL, {0}};
        s = shape_read_mem(&cur, depth);
        if (s) fseek(f, start + (long)(n - cur.left), SEEK_SET);
    }
    mem_free(buf, n ? n : 1);
    return s;
}

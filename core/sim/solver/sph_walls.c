/* sph_walls.c: fixed particles as walls of the SPH solver: the no-slip
 * wall velocities of eq. 3.19 (Morris et al. 1997), which sph_forces
 * (sph.c) applies in the viscous term, and the prescribed rigid motion of a
 * fixed body (hearth_scene_body_motion: lids, paddles, pistons). */
#include <math.h>
#include <string.h>

#include "alloc.h"
#include "error.h"

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

/* sph_wall_beta (sph_state.h, inline: sph_forces calls it per pair) gives
 * 1 + d_b / d_a, the factor on v_a in a's viscous interaction with wall
 * particle b (v_a - v_b of eq. 3.19 with the wall velocity above). */

/* ---- no-slip colliders in eq. 3.19 ------------------------------------------------
 *
 * A sticky (or grip) collider is a no-slip wall for the viscous term as a
 * wall of fixed particles is: eq. 3.33 with beta_c = 0 is the thesis's
 * no-slip condition, but it acts only on a particle that has crossed the
 * surface, so before this the layer above a sticky floor felt no shear from
 * it at all, however viscous. The melting block (#18) showed what that
 * costs: its melt (0.5 Pa s) ran out from under the block one particle thick
 * at 0.5 m/s, where a film of that viscosity on a no-slip floor spreads at
 * rho g H^3 / (3 mu L) ~ 1 cm/s for H = 4 mm (lubrication, e.g. Huppert 1982,
 * J. Fluid Mech. 121, 43, eq. 2.7's scale), and ran on as single particles.
 *
 * The collider's wall particles are virtual: a square (cubic) lattice of a's
 * own spacing sp beyond the surface, rows at d_b = sp/2, 3sp/2, ... (where a
 * body's wall lattice puts them, sph_wall_frame), columns under a, at a's rest
 * density rho0_a, so each carries V_b = sp^dim and m_b / (rho_b rho_a) =
 * V_b / rho0_a: a's density as it would sum with its wall's particles there
 * (its own sum beside a collider is low for want of them; over it the
 * channel below was 4.88% off, over rho0 3.00%).
 * Each moves with Morris et al.'s velocity v_b = V - (d_b / d_a) (v_a - V), V
 * the collider's velocity at a, d_a a's distance to the surface (at least
 * sp/2, as above): the pair term of eq. 3.19 is -mu_a V_b / rho_a L(r_ab)
 * c_a (1 + d_b / d_a) (v_a - V), linear in v_a, so it returns a drag
 * coefficient D and the kick takes -D (v_a - V) implicitly (sph_forces).
 * Only the viscous term: the collider's contact response (eq. 3.31-3.33)
 * keeps the particles out, as before. Slip colliders (beta_c's free slip)
 * are left as they were. A channel between two sticky colliders holds its
 * parabola to 3.00% of the peak where fixed walls hold 0.58%
 * (`sph_sticky_collider_channel`, an expected failure at its 3% bar): the
 * collider fills neither eq. 3.13's sum nor the fluid pairs' neighbourhood. */
double sph_collider_drag(const hearth_scene *s, int i, double V[3]) {
    const struct sph_state *st = s->sph;
    const int dim = s->def.dim;
    const double *x = pcold(&s->ps, PC_X) + 3 * i;
    const double hi = st->h[i], sp = st->sp[i];
    double D = 0, DV[3] = {0, 0, 0};
    if (!(sp > 0) || !(hi > 0) || !(st->rho0[i] > 0)) return 0.0;
    const double Vb = dim == 3 ? sp * sp * sp : sp * sp, f = st->mu[i] * Vb / st->rho0[i] * st->vc[i];
    const int L = (int)(hi / sp) + 1;
    for (int q = 0; q < s->ncol; q++) {
        const collider *cl = &s->cols[q];
        if ((cl->mode != HEARTH_STICKY && cl->mode != HEARTH_GRIP) || !collider_near(cl, x)) continue;
        double nrm[3] = {0, 0, 0};
        const double phi = collider_sdf(cl, x, nrm);
        if (!(phi < hi)) continue;
        const double da = fmax(phi, 0.0), dah = fmax(phi, 0.5 * sp);
        double sum = 0; /* sum_b L(r_ab) (1 + d_b / d_a) */
        for (int k = 0;; k++) {
            const double db = (k + 0.5) * sp, zn = da + db;
            if (zn >= hi) break;
            for (int l = -L; l <= L; l++)
                for (int m = dim == 3 ? -L : 0; m <= (dim == 3 ? L : 0); m++) {
                    const double r = sqrt(zn * zn + (double)(l * l + m * m) * sp * sp);
                    sum += sph_lap_visc(dim, r, hi) * (1.0 + db / dah);
                }
        }
        if (!(sum > 0)) continue;
        double vb[3] = {0, 0, 0};
        collider_velocity_at(cl, x, vb);
        D += f * sum;
        for (int a = 0; a < 3; a++) DV[a] += f * sum * vb[a];
    }
    for (int a = 0; a < 3; a++) V[a] = D > 0 ? DV[a] / D : 0.0;
    return D;
}

/* ---- moving walls ---------------------------------------------------------------
 *
 * A fixed body may move rigidly (a lid, a paddle, a piston): its particles
 * carry the prescribed velocity V + omega x (x - pivot) through the step, so
 * it enters every pair term that reads velocities: the viscous term with
 * Morris et al.'s wall velocity measured from the wall's, v_b = V_b - (d_b /
 * d_a) (v_a - V_b), so the fluid sticks to a moving lid (no-slip); the
 * velocity gradient of eq. 3.27 and the artificial viscosity of eq. 3.41.
 * The pressure of eq. 3.18 needs no change: the wall particles' summed
 * density rises as the wall closes on the fluid, and their Tait pressure
 * pushes it ahead (`sph_moving_lid_holds_fluid`). The particles move
 * rigidly once a step, after the fluid's drift, with the step's velocity
 * and rotation (exact for constant ones, as colliders move), not by the
 * fluid's drift, which would let a rotating paddle grow by dt^2 omega^2 r
 * a step. Not saved by checkpoints (SPH scenes cannot be saved). */

static const sph_wall_motion *motion_of(const struct sph_state *st, int body) {
    for (int k = 0; k < st->nwalls; k++)
        if (st->walls[k].body == body) return &st->walls[k];
    return NULL;
}

void sph_walls_begin(hearth_scene *s, double t) {
    struct sph_state *st = s->sph;
    particles *ps = &s->ps;
    if (!(ps->enabled & (1u << PC_FLAGS))) return;
    for (int k = 0; k < st->nwalls; k++) {
        sph_wall_motion *w = &st->walls[k];
        /* the last step's pivot move, if that step stood (the scene's time moved on to its end); a
         * rollback restarts at the step's start time, and the particles are back where they were */
        if (w->t_pending == t)
            for (int a = 0; a < 3; a++) w->pivot[a] += w->pending[a];
        w->t_pending = NAN;
        if (!w->motion) continue;
        double v[3] = {0, 0, 0}, o[3] = {0, 0, 0};
        w->motion(w->motion_ud, t, v, o);
        /* a non-finite value keeps the last step's motion (the Lua binding reports the error) */
        if (isfinite(v[0] + v[1] + v[2]) && isfinite(o[0] + o[1] + o[2])) {
            memcpy(w->vel, v, sizeof v);
            memcpy(w->omega, o, sizeof o);
        }
    }
    const int n = ps->n, *flags = pcoli(ps, PC_FLAGS);
    const int *body = ps->enabled & (1u << PC_BODY) ? pcoli(ps, PC_BODY) : NULL;
    const double *x = pcold(ps, PC_X);
    double *v = pcold(ps, PC_V);
    for (int i = 0; i < n; i++) {
        if (!(flags[i] & PF_FIXED)) continue;
        const sph_wall_motion *w = body && st->nwalls ? motion_of(st, body[i]) : NULL;
        double *vi = v + 3 * i;
        if (!w) {
            vi[0] = vi[1] = vi[2] = 0; /* a pinned body stays put, whatever pushed it */
            continue;
        }
        const double r[3] = {x[3 * i] - w->pivot[0], x[3 * i + 1] - w->pivot[1], x[3 * i + 2] - w->pivot[2]};
        vi[0] = w->vel[0] + w->omega[1] * r[2] - w->omega[2] * r[1];
        vi[1] = w->vel[1] + w->omega[2] * r[0] - w->omega[0] * r[2];
        vi[2] = w->vel[2] + w->omega[0] * r[1] - w->omega[1] * r[0];
        if (s->def.dim == 2) vi[2] = 0;
    }
}

/* r rotated by the angle |omega| dt about omega (Rodrigues). */
static void rotate(const double omega[3], double dt, const double r[3], double out[3]) {
    const double w = sqrt(omega[0] * omega[0] + omega[1] * omega[1] + omega[2] * omega[2]);
    if (!(w > 0)) {
        memcpy(out, r, 3 * sizeof(double));
        return;
    }
    const double k[3] = {omega[0] / w, omega[1] / w, omega[2] / w}, c = cos(w * dt), sn = sin(w * dt);
    const double kr = k[0] * r[0] + k[1] * r[1] + k[2] * r[2];
    const double kx[3] = {k[1] * r[2] - k[2] * r[1], k[2] * r[0] - k[0] * r[2], k[0] * r[1] - k[1] * r[0]};
    for (int a = 0; a < 3; a++) out[a] = r[a] * c + kx[a] * sn + k[a] * kr * (1 - c);
}

void sph_walls_end(hearth_scene *s, double dt) {
    struct sph_state *st = s->sph;
    particles *ps = &s->ps;
    if (!st->nwalls || !(ps->enabled & (1u << PC_FLAGS)) || !(ps->enabled & (1u << PC_BODY))) return;
    const int n = ps->n, *flags = pcoli(ps, PC_FLAGS), *body = pcoli(ps, PC_BODY), dim = s->def.dim;
    double *x = pcold(ps, PC_X);
    for (int i = 0; i < n; i++) {
        if (!(flags[i] & PF_FIXED)) continue;
        const sph_wall_motion *w = motion_of(st, body[i]);
        if (!w) continue;
        const double r[3] = {x[3 * i] - w->pivot[0], x[3 * i + 1] - w->pivot[1], x[3 * i + 2] - w->pivot[2]};
        double q[3];
        rotate(w->omega, dt, r, q);
        for (int a = 0; a < dim; a++) x[3 * i + a] = w->pivot[a] + q[a] + dt * w->vel[a];
    }
    for (int k = 0; k < st->nwalls; k++) {
        sph_wall_motion *w = &st->walls[k];
        for (int a = 0; a < 3; a++) w->pending[a] = a < dim ? dt * w->vel[a] : 0.0;
        w->t_pending = s->t + dt; /* scene.c's s->t += dt when the step stands */
    }
}

void sph_walls_free(struct sph_state *st) {
    mem_free(st->walls, sizeof(sph_wall_motion) * (size_t)st->walls_cap);
    st->walls = NULL;
    st->nwalls = st->walls_cap = 0;
}

static hearth_status check_vec3(const double *v, const char *what, const char *unit, hearth_error *err) {
    if (v && !(isfinite(v[0]) && isfinite(v[1]) && isfinite(v[2])))
        return err_set(err, HEARTH_ERR_PARAM, "body motion: %s = (%g, %g, %g) %s must be finite", what, v[0], v[1], v[2],
                       unit);
    return HEARTH_OK;
}

hearth_status hearth_scene_body_motion(hearth_scene *s, int body, const double velocity[3], const double omega[3],
                                       const double pivot[3], hearth_motion_fn motion, void *motion_ud,
                                       hearth_error *err) {
    err_clear(err);
    if (s->def.solver != HEARTH_SOLVER_SPH)
        return err_set(err, HEARTH_ERR_PARAM,
                       "body motion: body %d: only the SPH solver moves fixed bodies (walls, lids); under MPM move a "
                       "collider instead (its velocity and omega)", body);
    if (body < 0 || body >= s->nbodies)
        return err_set(err, HEARTH_ERR_PARAM, "body motion: body %d does not exist (the scene has %d)", body, s->nbodies);
    const particles *ps = &s->ps;
    /* the body's fixed particles (particles seeded without a body read body 0 too, and stay free) */
    int fixed = 0, any = 0;
    if (ps->enabled & (1u << PC_BODY))
        for (int i = 0; i < ps->n && !fixed; i++)
            if (pcoli(ps, PC_BODY)[i] == body) {
                any = 1;
                fixed = ps->enabled & (1u << PC_FLAGS) && (pcoli(ps, PC_FLAGS)[i] & PF_FIXED);
            }
    if (!fixed)
        return err_set(err, HEARTH_ERR_PARAM, "body motion: body %d is %s; only a body added with fixed = true takes a "
                       "prescribed motion (a free body moves by its forces)", body, any ? "not fixed" : "empty");
    hearth_status e;
    if ((e = check_vec3(velocity, "velocity", "m/s", err)) || (e = check_vec3(omega, "omega", "rad/s", err)) ||
        (e = check_vec3(pivot, "pivot", "m", err)))
        return e;
    struct sph_state *st = sph_state_of(s, err);
    if (!st) return HEARTH_ERR_NOMEM;
    sph_wall_motion *w = (sph_wall_motion *)motion_of(st, body);
    if (!w) {
        if (st->nwalls == st->walls_cap) {
            const int cap = st->walls_cap ? 2 * st->walls_cap : 4;
            sph_wall_motion *nw = mem_realloc(st->walls, sizeof *nw * (size_t)st->walls_cap, sizeof *nw * (size_t)cap);
            if (!nw) return err_set(err, HEARTH_ERR_NOMEM, "body motion: out of memory for body %d", body);
            st->walls = nw;
            st->walls_cap = cap;
        }
        w = &st->walls[st->nwalls++];
    }
    memset(w, 0, sizeof *w);
    w->body = body;
    w->t_pending = NAN;
    if (velocity) memcpy(w->vel, velocity, sizeof w->vel);
    if (omega) memcpy(w->omega, omega, sizeof w->omega);
    if (pivot) memcpy(w->pivot, pivot, sizeof w->pivot);
    w->motion = motion;
    w->motion_ud = motion_ud;
    if (motion) motion(motion_ud, s->t, w->vel, w->omega); /* meaningful before the first step, as colliders */
    return HEARTH_OK;
}

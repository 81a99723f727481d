/* sph_gas.c: the SPH solver's gas law for bubble particles (sph.gas_law,
 * #18): each particle's rest density from its contents, a bubble's from the
 * ideal gas and the dough's water vapour (Rodriguez-Arenas 2011 eq. 3.49-3.50,
 * and eq. 2.42-2.43, Fan et al.'s bubble in the thesis's review), and the
 * pressure against it, with the density it reads: eq. 3.13's sum, the
 * particle's own volume (sph.continuity_density) or the sum renormalised by
 * the kernel's filled part (sph.renormalised_density), a squeeze only as far
 * as the particle's own volume confirms it (sph.own_squeeze), and the gas's
 * own stiffness (sph.gas_pressure). phase_pressure (sph.c) calls
 * sph_pressure_gas_law in place of eq. 3.51-3.52 when the scene asks for it;
 * docs/validation.md "SPH bread roll (#18)" says why. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "colliders.h"
#include "error.h"
#include "material.h"
#include "params.h"
#include "scene.h"
#include "sph.h"
#include "sph_kernel.h"
#include "sph_neighbours.h"
#include "sph_state.h"
#include "vapour.h"

/* The gas law's rest density of a bubble particle (sph.gas_law): eq. 3.49,
 * rho_b = rho0 / V_b, with V_b of eq. 3.50 in absolute temperature (an ideal
 * gas at the oven's constant pressure; eq. 3.50 in degC would make a bubble at
 * 0 degC vanish) and, when sph.bubble_vapour (the dough's water activity a_w)
 * is above 0, the water vapour that joins the bubble's gas as the dough heats
 * (Fan et al.'s bubble of the thesis's eq. 2.42-2.43: P_b = P_c + P_v with
 * P_v = a_w P_sat(T) by Clausius-Clapeyron through 100 degC at 101325 Pa,
 * Delta H_v = 40.66 kJ/mol). At the constant outside pressure P_a the CO2's
 * partial pressure P_a - P_v holds a fixed number of moles, so
 *   V_b = V_b0 (T / T0) (P_a - P_v(T0)) / (P_a - P_v(T)),
 * which grows without bound as P_v nears P_a (the dough's boiling point):
 * there a real crumb's cells open and vent, so V_b / V_b0 stops at
 * sph.bubble_vmax. A bubble's rest volume m / rho_b follows its temperature
 * both ways: it grows while it heats and shrinks as it cools, with no history
 * to keep (and nothing for a rollback to lose), unless sph.bubble_stays_open
 * keeps a cell that has opened at the cap open (sph_pressure_gas_law). */
/* The vapour's partial pressure in a bubble, a_w P_sat(T) (eq. 2.43 through
 * 100 degC at 101325 Pa, Delta H_v = 40.66 kJ/mol: vapour.h); 0 for a dry gas. */
static double vapour_pressure(const hearth_sph_def *o, double T) {
    if (!(o->bubble_vapour > 0)) return 0;
    return o->bubble_vapour * VAPOUR_P1 * vapour_clausius(T + KELVIN); /* vapour.h, shared with water.h's evaporation */
}

/* The outside pressure P_a: sph.gas_pressure, or an oven's 101325 Pa. */
static double outside_pressure(const hearth_sph_def *o) { return o->gas_pressure > 0 ? o->gas_pressure : 101325.0; }

/* CO2's Henry solubility in water, H^cp (mol / (m^3 Pa)) at T (degC):
 * 3.3e-4 at 298.15 K with d ln H / d(1/T) = 2400 K (Sander 2015, Atmos. Chem.
 * Phys. 15, 4399-4981, Table 6, carbon dioxide). Pure water's: a dough's
 * salt and sugar lower it by some percent, which its water fraction absorbs. */
static double henry_co2(double T) { return 3.3e-4 * exp(2400.0 * (1 / (T + KELVIN) - 1 / 298.15)); }

double sph_bubble_volume_dissolved(const hearth_sph_def *o, double vb0, double T, double w) {
    double V = (T + KELVIN) / (o->bubble_T0 + KELVIN); /* eq. 3.50, Kelvin */
    const double pa = outside_pressure(o), pv0 = vapour_pressure(o, o->bubble_T0), pv = vapour_pressure(o, T);
    if (o->bubble_vapour > 0) /* eq. 2.42-2.43 */
        V = pv < pa && pv0 < pa ? V * (pa - pv0) / (pa - pv) : HUGE_VAL;
    /* sph.dough_water, thesis eq. 2.44 (Fan et al.'s CO2 shared between the
     * cell's water by Henry's law and its gas): the CO2 a bubble of raw gas
     * volume V0 holds at T0 under P_c0 = P_a - P_v(T0) and the CO2 dissolved in
     * its w V0 of water, n = P_c0 V0 (1 / (R T0) + H(T0) w), keeps its moles;
     * at T the gas stands at P_c = P_a - P_v(T) with H(T) P_c w V0 dissolved, so
     *   V_b / V0 = (T / T0)(P_c0 / P_c)(1 + H(T0) R T0 w) - H(T) R T w.
     * CO2 is less soluble hot (H falls 4x from 26 to 90 degC), so it leaves
     * the water for the bubbles as the dough heats. */
    if (w > 0 && V < HUGE_VAL) {
        const double T0k = o->bubble_T0 + KELVIN, Tk = T + KELVIN;
        V = V * (1 + henry_co2(o->bubble_T0) * R_GAS * T0k * w) - henry_co2(T) * R_GAS * Tk * w;
    }
    if (!(V < o->bubble_vmax)) V = o->bubble_vmax;
    return vb0 * V;
}

double sph_bubble_volume(const hearth_sph_def *o, double vb0, double T) { return sph_bubble_volume_dissolved(o, vb0, T, 0); }

/* The water each bubble draws its dissolved CO2 from. The thesis's review of
 * Fan et al. takes the CO2's concentration uniform through the dough, so the
 * water is shared evenly: every particle (a bubble particle holds dough too)
 * holds dough_water of its mass as water (of density 1000 kg/m^3), and each
 * bubble draws on that water in proportion to its raw gas volume bubble x V0.
 * Fixed particles are walls, not dough. A sum over the particles in their
 * order, so any thread count reads it alike. */
double sph_dough_water_share(const hearth_scene *s) {
    const hearth_sph_def *o = &s->def.sph;
    if (!(o->gas_law && o->dough_water > 0)) return 0;
    const particles *ps = &s->ps;
    const int *mat = pcoli(ps, PC_MAT), *flags = ps->enabled & (1u << PC_FLAGS) ? pcoli(ps, PC_FLAGS) : NULL;
    const double *m = pcold(ps, PC_MASS), *V0 = pcold(ps, PC_VOL0);
    double water = 0, gas = 0;
    for (int i = 0; i < ps->n; i++) {
        if (flags && (flags[i] & PF_FIXED)) continue;
        const double bub = s->mats.slot[mat[i]].core[CP_BUBBLE];
        water += o->dough_water * m[i] / 1000.0;
        if (bub > 0) gas += bub * V0[i];
    }
    return gas > 0 ? water / gas : 0;
}

/* The density a particle's own volume gives it, m / (V0 J) with J = det F,
 * F integrated from eq. 3.27's velocity gradient (phase_stress): the
 * continuity equation in its Lagrangian form, as Gray, Monaghan & Swift 2001
 * (Comput. Methods Appl. Mech. Engrg. 190, 6641) take the density of elastic
 * solids in SPH, whose tension the sum of eq. 3.13 misreads. The sum counts
 * the neighbours in a particle's kernel, so a particle on a free surface (or
 * on a collider, which adds none) reads 0.75-0.85 of its rest density at rest
 * and Tait with tension pulls it into a skin: in the bread roll's dough at
 * 110 degC (B ~ 4e5 Pa) its outer row holds -100 kPa (median; -270 kPa on the
 * tray), a surface tension of some 300 N/m, forty times the roll's weight per
 * length (21 N/m). That skin squeezed the crumb (Laplace), beaded the roll up
 * off its tray to a foot (contact angle 180 degrees: the tray side is a
 * surface too) and tore its flank at the contact line (docs/validation.md
 * "The roll's skin"). J knows no surface: a particle reads stretched only when
 * it is. A non-positive J (phase_stress reports it) keeps the sum. Off in the
 * roll's preset: with it the roll sits flat on its tray, but its films, which
 * the sum read as compressed beside squeezed bubbles, carry their real tension
 * and tear from 1.6 s (SPH's tensile instability), where the sum held them. */
static double volume_density(const double *F, double m, double V0, double summed) {
    const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                     F[2] * (F[3] * F[7] - F[4] * F[6]);
    return J > 0 && V0 > 0 ? m / (V0 * J) : summed;
}

/* sph.renormalised_density: the summed density (eq. 3.13 over rest volumes,
 * sort_and_list) divided by gamma_i = sum_j V_j W_ij (i itself included),
 * the part of i's kernel its body fills, with V_j = V0_j det F_j each
 * particle's own volume (F from eq. 3.27, phase_stress), capped at 1. Where
 * the kernel is full gamma is 1 up to the sums' error (the particles' own
 * volumes tile the plane they occupy), and the density is the sum's: the
 * films between bubbles keep what held them (docs/validation.md "The films'
 * tension"). Where part of it hangs over a free surface or a collider, which
 * adds no neighbours, the sum lacks that part and gamma says how much: a
 * surface particle at rest reads its rest density, not 0.76 of it, and Tait's
 * tension pulls no false skin (docs/validation.md "The roll's skin"). It is
 * Ferrand et al.'s density renormalised by the kernel's integral over the
 * fluid, rho_a = (1 / gamma_a) sum_b m_b w_ab (Ferrand, Laurence, Rogers,
 * Violeau & Kassiotis 2013, Int. J. Numer. Meth. Fluids 71, 446-472), with
 * gamma from the particles themselves, Shepard's sum, in place of their
 * wall's boundary integral. V in st->perm (free scratch between
 * sph_kinematics and sph_forces); a non-positive det F (phase_stress reports
 * it) counts the raw volume. */
static void renormalise(hearth_scene *s, const sph_cols *c, double *rho_out) {
    struct sph_state *st = s->sph;
    const int n = c->n, dim = c->dim, *off = st->nl.off, *nb = st->nl.j;
    double *V = st->perm;
    for (int i = 0; i < n; i++) {
        const double *F = c->F + 9 * i;
        const double J = F[0] * (F[4] * F[8] - F[5] * F[7]) - F[1] * (F[3] * F[8] - F[5] * F[6]) +
                         F[2] * (F[3] * F[7] - F[4] * F[6]);
        V[i] = c->V0[i] * (J > 0 ? J : 1);
    }
#pragma omp parallel for schedule(static) if (n >= SCENE_PARALLEL_MIN)
    for (int i = 0; i < n; i++) {
        const double hi = st->h[i];
        double g = V[i] * sph_w(dim, 0, hi);
        for (int k = off[i]; k < off[i + 1]; k++) {
            const int j = nb[k];
            double d[3];
            sph_disp(&st->cells, c->x + 3 * i, c->x + 3 * j, d);
            const double r = sqrt(d[0] * d[0] + d[1] * d[1] + (dim == 3 ? d[2] * d[2] : 0));
            g += V[j] * sph_w(dim, r, 0.5 * (hi + st->h[j]));
        }
        rho_out[i] = g < 1 && g > 0 ? st->rho[i] / g : st->rho[i];
    }
}

/* sph.own_squeeze: the density Tait (eq. 3.17) reads, the summed one
 * (eq. 3.13 over rest volumes, or renormalised) where it reads a stretch, and
 * a squeeze only as far as the particle's own volume confirms it:
 *   rho_t = min(rho_sum, max(rho0, m / (V0 det F))).
 * Why: the sum over rest volumes counts each neighbour's rest volume, and a
 * hot bubble the set dough holds below its gas volume (det F 1.3-1.7 against
 * V_b 3-4) lends its missing volume to every dough particle beside it, which
 * reads squeezed while its own det F says it is 13-43% expanded; Tait charges
 * that at gamma 7 with the hot dough's B (1.1 MPa in the bread roll's base at
 * 2 s), and a tray that pushes only with the roll's weight then holds the
 * base over W / p, a contact that shrinks to nothing: the base arches off
 * (docs/validation.md "Why the roll's base leaves its tray"). Whether a piece
 * of dough is squeezed is its own volume's to say. Its stretch is the sum's:
 * the sum sees films between bubbles open (the particles' positions), which
 * det F, integrated from the smoothed velocity gradient of eq. 3.27, does not,
 * and that tension is what holds the films (docs/validation.md "The films'
 * tension"; the own volume alone lets them tear). Where both read a squeeze
 * the smaller counts. A non-positive det F keeps the sum. */
static double own_squeeze(const double *F, double m, double V0, double rho0, double summed) {
    return fmin(summed, fmax(rho0, volume_density(F, m, V0, summed)));
}

/* A bubble's stiffness under the gas law. With sph.gas_pressure = P_a it is
 * its gas's own, whatever dough holds it: the CO2 keeps its moles and the
 * vapour its partial pressure P_v = a_w P_sat(T) (eq. 2.42-2.43 with the
 * ideal gas of eq. 3.49-3.50), so at volume V its gauge pressure is exactly
 * (P_a - P_v)(V_b / V - 1), an isothermal bulk modulus P_a - P_v that falls
 * to 0 at the dough's boiling point. It used to be capped by the dough's
 * Tait B where that was softer, which on the bread roll is everywhere that
 * matters: the raw dough's B is 2.9 kPa, a 34th of its gas's 97.6 kPa, so
 * the raw crumb's bubbles pushed 3% of their gas and the roll rose only once
 * mu_e set B past the gas (4-5e5 Pa hot), when each bubble pushed up to 4.5x
 * its gas near the cap (docs/validation.md "The bubble's own gas"). Without
 * gas_pressure it is the dough's B (the roll's preset). */
double sph_gas_modulus(const hearth_sph_def *o, double B, double T) {
    return o->gas_pressure > 0 ? fmax(0.0, o->gas_pressure - vapour_pressure(o, T)) : B;
}

/* The sound speed of a bubble whose stiffness is its gas's: p = K (rho / rho_b
 * - 1) gives c^2 = dp/drho = K / rho_b, with rho_b = rho0 / V_b(T). On the raw
 * roll that is 9.4 m/s against the dough's c0 of 4.3 (hot: 55), so the CFL limit
 * (sph_dt.c, and sph.c's signal_speed from the first step) must count it or
 * the bubbles' waves cross more than a spacing a step. 0 where the gas's
 * stiffness is not the bubble's (no gas_pressure, no bubble, no temperature). */
double sph_gas_sound_speed(const hearth_sph_def *o, double bub, double rho0, double T, double w) {
    if (!(o->gas_law && o->gas_pressure > 0 && bub > 0 && rho0 > 0) || isnan(T)) return 0;
    return sqrt(sph_gas_modulus(o, 0, T) * sph_bubble_volume_dissolved(o, bub, T, w) / rho0);
}

/* The options that act through sph.gas_law's pressure: each refused without
 * it, saying what it does there (the messages word for word as when each had
 * its own check in sph.c: scripts and users grep them). */
hearth_status sph_gas_check_def(const hearth_sph_def *o, hearth_error *err) {
    char gp[48], dw[48];
    snprintf(gp, sizeof gp, "%g Pa", o->gas_pressure);
    snprintf(dw, sizeof dw, "%g", o->dough_water);
    const char *both = "set both or neither";
    const struct {
        const char *name, *val, *why, *fix;
        int on;
    } needs[] = {
        {"continuity_density", "true", "it is the gas law's pressure that reads the particle's own volume", both,
         o->continuity_density},
        {"renormalised_density", "true", "it is the gas law's pressure that reads it", both, o->renormalised_density},
        {"own_squeeze", "true", "it is the gas law's dough that reads its squeeze from its own volume", both,
         o->own_squeeze},
        {"bubble_stays_open", "true", "it is the gas law's bubble that opens at bubble_vmax", both,
         o->bubble_stays_open},
        {"surface_vent", "true", "it is the gas law's bubble that vents on the outer surface", both,
         o->surface_vent},
        {"gas_pressure", gp, "it is the gas law's bubble that holds the gas",
         "set sph.gas_law = true or sph.gas_pressure = 0", o->gas_pressure > 0},
        {"dough_water", dw, "its CO2 comes out into the gas law's bubbles",
         "set sph.gas_law = true or sph.dough_water = 0", o->dough_water > 0},
    };
    for (size_t k = 0; k < sizeof needs / sizeof needs[0]; k++)
        if (needs[k].on && !o->gas_law)
            return err_set(err, HEARTH_ERR_PARAM, "scene: sph.%s = %s needs sph.gas_law = true (%s); %s", needs[k].name,
                           needs[k].val, needs[k].why, needs[k].fix);
    return HEARTH_OK;
}

/* A bubble open to the oven's air: on the outer surface and not by a collider. The flood fill (sph_outer.c) runs
 * through colliders, which add no particles, so the roll's tray side reads as outer; there the cell's outside is
 * the tray (within h, sph_heat.c's rule for eq. 3.42's outside), whose metal the gas does not cross. Vented
 * there, the 2 mm roll's bottom fifth's cells lost 45% of their gas by 1.7 s where its middle's lost 5-9%, and
 * from 1.7 s it tipped on that vented foot (docs/validation.md "The vented roll rocked because its tray side
 * vented", helper ventrock). */
static int open_to_air(const hearth_scene *s, const struct sph_state *st, const double *x, int i) {
    if (!(st->outer[i] > 0)) return 0;
    for (int q = 0; q < s->ncol; q++) {
        const collider *cl = &s->cols[q];
        if (collider_near(cl, x + 3 * i) && collider_sdf(cl, x + 3 * i, NULL) < st->h[i]) return 0;
    }
    return 1;
}

/* sph.surface_vent: a bubble particle on the body's outer surface is a gas
 * cell open to the oven's air, a ruptured cell of a real crumb. The thesis's
 * review of Lostie et al.'s crust-and-crumb model lets the crumb's gas leave
 * through the crust by Darcy permeation, m_g' = (K / eta) (P - P_atm) / e_t
 * C_a (eq. 2.60): the flow grows as the crust e_t between gas and air thins,
 * and a cell with no crust between it and the air (e_t -> 0) holds P_atm, its
 * overpressure gone as it forms. So a vented cell keeps the gas that fills its
 * present volume at the outside pressure (its gauge is 0) and loses the rest:
 * gasleft_i, the share of its moles still in it, drops to (rho0 / rho) / V_b,
 * its volume over its gas's volume at P_a, whenever that is smaller. While
 * open its gas's gauge is 0 either way: it neither pushes nor pulls (an open
 * cell that grows draws in air; the dough's Tait still resists a squeeze). The
 * moles counted are the cell's own gas, which never comes back: a cell that
 * closes again (a neighbour's wall covers it) pushes with what it kept,
 * gasleft V_b(T) (the air it drew in while open is not counted: a closed cell
 * that grew after venting reads under its gas and pulls, a limit left). The outer flag is
 * sph_outer_surface's (the flood fill: enclosed spaces between the particles
 * are not the outside), the last step's, carried through the sort
 * (sort_and_list). Per particle, so any thread count gives the same bits.
 * Returns the bubble's rest density rho0 / (gasleft V_b) in place of rr =
 * rho0 / V_b. Tried before and deleted: cells opened at the cap
 * (sph.bubble_vent), at the set (sph.open_cell_T) or as their walls set
 * (sph.open_cell_mu_e), wherever they were (docs/validation.md "Both
 * switches on", "The roll's cells open at the set", "... as their walls
 * set"); this opens only the cells the air reaches (open_to_air: not the
 * tray side). With the tray side venting too, the 1.5 mm roll stayed whole
 * and the 2 mm roll tipped on its tray (docs/validation.md "Cells open to
 * the air vent"); without it the 2 mm roll stays level, its base as far off
 * the tray as without venting, within 0.2 mm ("The vented roll rocked
 * because its tray side vented"). Off by default. */
static double vent(struct sph_state *st, int i, double rr, double rho, int open) {
    double g = st->gasleft[i];
    if (!(g > 0 && g <= 1)) g = 1; /* NaN: a cell that has not vented */
    if (open && rho > 0) {
        const double full = rr / rho; /* (rho0 / rho) / V_b: the share of the gas that fills the cell at P_a */
        if (full < g) g = full;
    }
    st->gasleft[i] = g;
    return rr / g;
}

/* Pressure with sph.gas_law: the dough's Tait (eq. 3.17) against its rest
 * density rho0; a bubble's the ideal gas's gauge pressure against the gas
 * law's rho_b = rho0 / V_b (sph_bubble_volume), B (rho / rho_b - 1) (gamma =
 * 1, B playing the outside pressure), but never softer than the dough's Tait
 * against rho0 (a bubble particle holds dough too, which does not compress
 * below its raw volume). Eq. 3.48 is the same gauge pressure up to its offset:
 * B (rho/rho0) (rho0/rho_b - 1) = B (rho / rho_b - rho / rho0), positive at
 * any density, so the bubble pushes as long as it heats, by whatever volume it
 * has already gained: the roll's top burst. The gas law's pressure vanishes at
 * the bubble's own volume, so the rise is bounded by the temperature reached.
 * Tait (gamma 7) against rho_b instead was tried and rejected: a bubble the
 * dough holds at its raw volume sees B (V_b^7 - 1), 16000 B at V_b = 4, and
 * blew the crust off the roll.
 * Two switches for the roll's rocking base were tried and deleted: a cap on
 * the dough beside bubbles at its bubbles' pressure (sph.foam_pressure) and an
 * open cell at bubble_vmax that pushes nothing (sph.bubble_vent); neither kept
 * the roll on its tray and rising (docs/validation.md "The roll's base",
 * "Both switches on"). So was an open cell from the crumb's set on (sph.open_cell_T,
 * McGee 2004's foam to sponge): opened where the set curve reaches its set
 * value the roll still lifted its base, opened earlier it rose less than 1.3x
 * (docs/validation.md "The roll's cells open at the set"). And so was a cell
 * that opens as the dough round it sets (sph.open_cell_mu_e, commit 2d8dd4b:
 * its neighbours' kernel-weighted mean mu_e at the set value): the tray side's
 * and crust's cells vented first, yet the core's closed cells pushed the set
 * shell and its base tilted 2.44 mm (docs/validation.md "The roll's cells open
 * as their walls set").
 * With sph.gas_pressure = P_a the bubble's stiffness is its gas's own,
 * P_a - P_v(T) (sph_gas_modulus), at any dough stiffness: p = (P_a -
 * P_v)(rho / rho_b - 1) is the bubble's ideal gas exactly (eq. 2.42-2.43,
 * 3.49-3.50). */
void sph_pressure_gas_law(hearth_scene *s) {
    struct sph_state *st = s->sph;
    const hearth_sph_def *o = &s->def.sph;
    const sph_cols c = sph_cols_of(s);
    const int n = c.n, *mat = c.mat;
    const double *T = c.T, *F = c.F, *V0 = pcold(&s->ps, PC_VOL0);
    if (o->renormalised_density) renormalise(s, &c, st->vr); /* vr: free once the sum stands (sort_and_list) */
    const double w = st->water_per_gas = sph_dough_water_share(s);
    for (int i = 0; i < n; i++) {
        const double rho0 = st->rho0[i], bub = s->mats.slot[mat[i]].core[CP_BUBBLE];
        double rr = bub > 0 && T ? rho0 / sph_bubble_volume_dissolved(o, bub, T[i], w) : rho0; /* eq. 3.49 */
        const double rho = o->continuity_density     ? volume_density(F + 9 * i, c.m[i], V0[i], st->rho[i])
                           : o->renormalised_density ? st->vr[i]
                                                     : st->rho[i];
        const int open = st->gasleft && bub > 0 && T && open_to_air(s, st, c.x, i); /* sph.surface_vent */
        if (st->gasleft && bub > 0 && T) rr = vent(st, i, rr, rho, open); /* before the cap's latch */
        /* sph.bubble_stays_open: the cap is where a crumb's cells open and vent
         * (sph_bubble_volume_dissolved); an open cell is joined to the oven's
         * air and holds P_a at any temperature, so as it cools air comes in
         * and the cell keeps its volume (what holds the crumb around it is the
         * crumb's). A closed gas would contract and draw the crumb in with it.
         * The last step's rest density (st->rhof, sorted with the particles)
         * at the cap marks the cell open; a rollback does not restore it, as
         * it does not restore eq. 3.52's (sph.c). */
        if (o->bubble_stays_open && bub > 0 && st->rhof[i] > 0 &&
            st->rhof[i] <= rho0 / (bub * o->bubble_vmax) * (1 + 1e-9))
            rr = st->rhof[i];
        st->rhof[i] = rr;
        const double rt = o->own_squeeze ? own_squeeze(F + 9 * i, c.m[i], V0[i], rho0, rho) : rho;
        const double tait = st->B[i] * (pow(rt / rho0, o->gamma) - 1); /* eq. 3.17 */
        const double Bg = bub > 0 && T ? sph_gas_modulus(o, st->B[i], T[i]) : st->B[i];
        /* an open cell (sph.surface_vent, outer) holds the outside pressure: no push, and no suction (air comes in) */
        const double gas = open ? 0.0 : Bg * (rho / rr - 1);
        st->prs[i] = bub > 0 ? fmax(gas, tait) : tait;
        if (!o->tension && st->prs[i] < 0) st->prs[i] = 0; /* as phase_pressure */
    }
    if (T) memcpy(st->Tprev, T, sizeof(double) * (size_t)n);
}

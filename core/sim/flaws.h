/* flaws.h: a crust's strength that varies over a physical length (issue #18,
 * helper flaws; a prototype behind environment variables, see flaws.c).
 * Each particle gets, once, where it is seeded, a factor f(x) on its
 * material's fracture strains (the parameters fracture_strain and
 * fracture_strain_set), kept in the PC_FLAW column so it moves with the
 * particle and checkpoints. */
#ifndef HEARTH_SIM_FLAWS_H
#define HEARTH_SIM_FLAWS_H
#include <stdint.h>

#include "hearth/material.h"
#include "particles.h"

typedef struct flaw_def {
    double length; /* correlation length lc (m): the lattice spacing of the value noise; 0 = no flaws */
    double sigma;  /* standard deviation of ln f */
    uint64_t seed; /* the noise's seed */
} flaw_def;

/// The flaws the environment asks for (HEARTH_FLAW_LENGTH in m, HEARTH_FLAW_SIGMA,
/// HEARTH_FLAW_SEED, defaulting to seed): length 0 when unset or not a positive number.
flaw_def flaws_from_env(uint64_t seed);
/// The factor at x (dim axes read): exp(sigma g(x) - sigma^2 / 2), g a smooth
/// standard normal value noise of spacing length, so E f = 1 at every x.
double flaw_factor(const flaw_def *fd, const double x[3], int dim);
/// The noise g(x) alone (unit normal at every x).
double flaw_noise(const flaw_def *fd, const double x[3], int dim);
/// The schema indices of m's parameters the factor multiplies (fracture_strain,
/// fracture_strain_set) into k; returns how many (0..2).
int flaw_params(const hearth_material *m, int k[2]);

#endif

/* mpm_sticky.h: the reaction of sticky colliders in the MPM step (mpm_sticky.c). */
#ifndef HEARTH_MPM_STICKY_H
#define HEARTH_MPM_STICKY_H
#include "scene.h"

/// 1 when a particle of the particle block whose origin node is org may lie
/// within 1.5 dx outside a sticky face (one SDF per block and collider).
int mpm_block_near_sticky(const hearth_scene *s, const int D, const int org[3]);
/// Scatter into block's P2G tile the stress force of the mirror of the
/// particle at x (Kirchhoff stress tau, k0 its volume factor) through the
/// nearest sticky face, when it lies within 1.5 dx outside one.
void mpm_p2g_mirror(const hearth_scene *s, const int D, const double *x, const double *tau, double k0, int block,
                    double *tile);
/// After the grid update: the held nodes of active block k within 1.5 dx
/// inside a sticky face take the odd reflection 2 v_b - v(x') of the free velocity.
void mpm_sticky_ghosts_block(const hearth_scene *s, int k);
#endif

/* mpm_touch.h: which nodes of a grid block a slip or separate face may hold (mpm_touch.c says why). */
#ifndef HEARTH_SIM_MPM_TOUCH_H
#define HEARTH_SIM_MPM_TOUCH_H
#include <stdint.h>

#include "colliders.h"
#include "mpm.h"

/* Bit l set: node l of the grid block at block coordinates bc lies in the stencil of a particle that touches
 * the face (collider c, or with c NULL the domain wall on axis d, side 0 low / 1 high) this step of dt (s).
 * Reads the sorted particles of the step; call between P2G and G2P. */
uint64_t mpm_touch_mask(const hearth_scene *s, const int bc[3], const collider *c, int d, int side, double dt);
/* The faces a touch mask is made for, numbered f: colliders 0..ncol-1, then the domain walls ncol + 2 d + side;
 * mpm_touch_face's count. mpm_touch_face_mask is face f's mask (0 for a face the touch does not gate). */
int mpm_touch_faces(const hearth_scene *s);
int mpm_touch_gated(hearth_contact mode);
uint64_t mpm_touch_face_mask(const hearth_scene *s, const int bc[3], int f, double dt);
/* A grid block's touch masks, by face number f, for the grid update: each made once, when a node first asks. */
enum { MPM_TOUCH_CACHE = 64 }; /* faces a block keeps; past them each node asks again (the same mask) */
typedef struct mpm_touch_cache {
    uint64_t mask[MPM_TOUCH_CACHE];
    uint64_t done; /* bit f: mask[f] made */
} mpm_touch_cache;
/* 1: slip or separate face f (a collider, or ncol + 2 d + side a domain wall) may hold node l of the grid block
 * id at block coordinates bc: a particle that touches the face has the node in its stencil, on this rank or
 * (a slab's seam) the lower neighbour's (mpm_ranks_touch_below). */
int mpm_touch_holds(const hearth_scene *s, mpm_touch_cache *tc, int id, const int bc[3], int f, int l, double dt);
#endif

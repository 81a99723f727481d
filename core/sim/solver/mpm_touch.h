/* mpm_touch.h: which nodes of a grid block a slip, separate or sticky face may hold (mpm_touch.c says why). */
#ifndef HEARTH_SIM_MPM_TOUCH_H
#define HEARTH_SIM_MPM_TOUCH_H
#include <stdint.h>

#include "colliders.h"
#include "mpm.h"

/* Bit l set: node l of the grid block at block coordinates bc lies in the stencil of a particle that touches
 * the face (collider c, or with c NULL the domain wall on axis d, side 0 low / 1 high) this step of dt (s), or
 * (glue nonzero: a sticky face's glue bit) of a particle whose PC_GLUE holds it.
 * Reads the sorted particles of the step; call between P2G and G2P. field (two_field): 0 every particle, 1 or 2
 * at a node two bodies meet only the particles of that node's first or second field (mpm_two_field_holds). */
/* particle i's half-extent h_p (m): half its current spacing, (J V0)^(1/dim) / 2; also where two bodies touch
 * (mpm_two_field.c) */
double mpm_touch_half_extent(const hearth_scene *s, int i);
uint64_t mpm_touch_mask(const hearth_scene *s, const int bc[3], const collider *c, int d, int side, double dt, int glue,
                        int field);
/* The faces a touch mask is made for, numbered f: colliders 0..ncol-1, then the domain walls ncol + 2 d + side;
 * mpm_touch_face's count. mpm_touch_face_mask is face f's mask (0 for a face neither the touch nor the glue
 * gates: a grip). */
int mpm_touch_faces(const hearth_scene *s);
int mpm_touch_gated(hearth_contact mode); /* slip, separate: held where touched now */
int mpm_touch_glued(hearth_contact mode); /* sticky: held where touched now or before */
/* face f's bit in PC_GLUE (particles.h's GLUE_SLOTS): walls slots 0..5, collider c slot 6 + c */
int mpm_touch_glue_bit(const hearth_scene *s, int f);
uint64_t mpm_touch_face_mask(const hearth_scene *s, const int bc[3], int f, double dt);
/* A grid block's touch masks, by face number f, for the grid update: each made once, when a node first asks. */
enum { MPM_TOUCH_CACHE = 64 }; /* faces a block keeps; past them each node asks again (the same mask) */
typedef struct mpm_touch_cache {
    uint64_t mask[MPM_TOUCH_CACHE];
    uint64_t done; /* bit f: mask[f] made */
    int field;     /* two_field: the field whose grid update asks, 1 first or 2 second (mpm_touch_mask); 0 one field */
} mpm_touch_cache;
/* 1: face f (a collider, or ncol + 2 d + side a domain wall) may hold node l of the grid block id at block
 * coordinates bc: a particle that touches the face (slip, separate) or is glued to it (sticky) has the node in
 * its stencil, on this rank or (a slab's seam) the lower neighbour's (mpm_ranks_touch_below). */
int mpm_touch_holds(const hearth_scene *s, mpm_touch_cache *tc, int id, const int bc[3], int f, int l, double dt);
/* At the step's start, before the sort (the positions P2G will scatter from): each particle that touches a
 * sticky face now gets that face's glue bit (enabling PC_GLUE the first time); after a checkpoint older than
 * glue (s->glue_legacy), also each particle whose stencil reaches a node the face held then. Nothing in a
 * scene without a sticky face. */
hearth_status mpm_glue_mark(hearth_scene *s, double dt, hearth_error *err);
/* PC_GLUE enabled now if the scene (MPM) has a sticky face: scene.c's step asks before the rollback guard's
 * snapshot, so a restore finds the layout it saved (mpm_glue_mark would enable it inside the step). */
hearth_status mpm_glue_column(hearth_scene *s, hearth_error *err);
#endif

/* shapes.h: private parts of the shape module (serialisation for checkpoints)
 * and the interface between shapes.c (the tree) and shape_mask.c (the sampled
 * distance field behind hearth_shape_mask). */
#ifndef HEARTH_SHAPES_H
#define HEARTH_SHAPES_H
#include <stdio.h>

#include "hearth/hearth.h"

/// Write a shape tree in the checkpoint's binary layout. Returns 0 on success.
int shape_write(FILE *f, const hearth_shape *s);
/// Read a tree written by shape_write; NULL on a malformed or truncated stream.
/// Reads the rest of f into memory and parses it with shape_read_mem; f is left
/// just after the tree.
hearth_shape *shape_read(FILE *f, int depth);
/// Whether s is a plane whose normal is a coordinate axis exactly (the other two components zero, this one
/// +-1): its axis, the normal's sign and the plane point's coordinate on that axis. 0 for anything else.
int shape_axis_plane(const hearth_shape *s, int *axis, int *sign, double *c);
/// 1 for a box with no z extent (a 2D scene's box): its SDF is the exact distance to its x-y rectangle,
/// whatever z is (colliders.c's collider_bound_prism).
int shape_box_2d(const hearth_shape *s);
struct ck_cursor;
/// Deepest shape tree a checkpoint may hold (levels below the root).
#define SHAPE_DEPTH_MAX 64
/// Read a tree from a checkpoint cursor (checkpoint.h), checking every node's
/// values as its constructor would and every size against the bytes left
/// before allocating. NULL with the cursor marked bad (and its reason) on failure.
hearth_shape *shape_read_mem(struct ck_cursor *cur, int depth);

/* ---- mask fields (shape_mask.c) ---------------------------------------- */

/// Largest mask width or height (pixels). Building a field holds about 7 bytes
/// per pixel (the grey image, the float field, 16-bit scratch): ~120 MB at
/// 4096^2, of which the 4-byte field stays.
#define MASK_DIM_MAX 4096

/// An immutable signed distance field sampled at the pixel centres of a mask.
typedef struct shape_mask shape_mask;

/// Read the PNG at path and build its field over lo..hi. NULL with err filled
/// (naming the file or the parameter) on any failure.
shape_mask *mask_load(const char *path, const double lo[2], const double hi[2], hearth_error *err);
/// Deep copy (NULL on allocation failure).
shape_mask *mask_copy(const shape_mask *m);
void mask_free(shape_mask *m);
/// Signed distance at (x, y) in metres; g (may be NULL) gets a smoothed gradient
/// (central differences over 3 pixels), not normalised.
double mask_sdf(const shape_mask *m, double x, double y, double g[2]);
/// The image rectangle.
void mask_bounds(const shape_mask *m, double lo[2], double hi[2]);
/// Checkpoint layout: int32 w, h; double lo[2], hi[2]; float field[w*h]. 0 on success.
int mask_write(FILE *f, const shape_mask *m);
/// NULL on a malformed or truncated stream.
shape_mask *mask_read(FILE *f);
#endif

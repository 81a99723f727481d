/* shapes.h: private parts of the shape module (serialisation for checkpoints). */
#ifndef HEARTH_SHAPES_H
#define HEARTH_SHAPES_H
#include <stdio.h>

#include "hearth/hearth.h"

/// Write a shape tree in the checkpoint's binary layout. Returns 0 on success.
int shape_write(FILE *f, const hearth_shape *s);
/// Read a tree written by shape_write; NULL on a malformed or truncated stream.
hearth_shape *shape_read(FILE *f, int depth);
#endif

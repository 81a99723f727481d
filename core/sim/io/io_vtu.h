/* io_vtu.h: the VTU writer's parts that io_pvtu.c (one piece per MPI rank and
 * the .pvtu index) shares with hearth_write_vtu (io_particles.c). */
#ifndef HEARTH_IO_VTU_H
#define HEARTH_IO_VTU_H
#include <stddef.h>

#include "hearth/hearth.h"

/// hearth_write_vtu's file holding particles [lo, hi) of this process's set only.
hearth_status vtu_write_range(const hearth_scene *s, const char *path, size_t lo, size_t hi, hearth_error *err);
/// A .pvtu index naming the point arrays hearth_write_vtu writes (names, types,
/// components) and the npieces pieces STEM_p0.vtu .. (relative to the index). Atomic.
hearth_status vtu_write_index(const hearth_scene *s, const char *path, const char *stem, int npieces, hearth_error *err);
#endif

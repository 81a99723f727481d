/* io_pvtu.c: a VTU frame over MPI ranks as one piece per rank and a .pvtu
 * index (#21, docs/outputs.md).
 *
 * In the slab mode each rank holds only its slab's particles; gathering the
 * whole set to rank 0 for every frame would move every particle through rank
 * 0 (the bytes the slabs exist to avoid) and make rank 0 hold the whole scene.
 * So each rank writes what it holds, and rank 0 writes the small index that
 * ParaView and VTK's vtkXMLPUnstructuredGridReader read as one data set.
 * When the scene is whole on every rank (the replicated mode, or before the
 * first step), rank r writes the r-th of N runs of particles, so the series
 * keeps one layout for the whole run.
 *
 * Every file goes through atomic_file, and rank 0 writes the index only after
 * every rank said its piece is on disk: the index never names a missing or
 * half-written piece. Both agreements are one-byte maxima over the ranks, so
 * a failure anywhere stops every rank at the same call (no rank waits in the
 * next exchange for one that left). */
#include <stdio.h>
#include <string.h>

#include "error.h"
#include "io_vtu.h"
#include "mpm.h"
#include "ranks.h"
#include "scene.h"

hearth_status hearth_write_vtu_pieces(const hearth_scene *s, const char *path, hearth_error *err) {
    err_clear(err);
    const hearth_status u = mpm_ranks_usable(s, err); /* a failed step on this rank: no exchange (mpm_ranks_end) */
    if (u) return u;
    const int N = ranks_size(), me = ranks_rank();
    /* the index's folder and file stem; the pieces go beside it */
    char piece[4096], stem[1024];
    const size_t len = strlen(path);
    const char *base = strrchr(path, '/');
    base = base ? base + 1 : path;
    const int bad = len < 6 || strcmp(path + len - 5, ".pvtu") != 0 || strlen(base) - 5 >= sizeof stem ||
                    len + 24 >= sizeof piece;
    hearth_status st = HEARTH_OK;
    if (bad) st = err_set(err, HEARTH_ERR_PARAM, "%s: a VTU index path ends in .pvtu (and is at most %zu bytes)", path,
                          sizeof piece - 25);
    else {
        snprintf(stem, sizeof stem, "%.*s", (int)(strlen(base) - 5), base);
        snprintf(piece, sizeof piece, "%.*s_p%d.vtu", (int)(len - 5), path, me);
        size_t lo = 0, hi = (size_t)hearth_scene_particle_count(s);
        if (!mpm_ranks_holds_slab(s)) { /* every rank holds every particle: the me-th run of N */
            const size_t n = hi;
            lo = n * (size_t)me / (size_t)N, hi = n * ((size_t)me + 1) / (size_t)N;
        }
        st = vtu_write_range(s, piece, lo, hi, err);
    }
    unsigned char failed = st != HEARTH_OK;
    ranks_max_bytes(&failed, 1);
    if (failed) {
        if (st) return st;
        return err_set(err, HEARTH_ERR_IO, "%s: another MPI rank could not write its piece (run with HEARTH_RANKS_VERBOSE=1 to see its message)", path);
    }
    if (me == 0) st = vtu_write_index(s, path, stem, N, err);
    failed = st != HEARTH_OK;
    ranks_max_bytes(&failed, 1);
    if (failed && !st) return err_set(err, HEARTH_ERR_IO, "%s: rank 0 could not write the index of the pieces", path);
    return st;
}

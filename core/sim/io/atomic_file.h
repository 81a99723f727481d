/* atomic_file.h: write a file so that readers see the old file or the whole
 * new one, never a torn one: a temp file in the same folder, fsync, rename. */
#ifndef HEARTH_ATOMIC_FILE_H
#define HEARTH_ATOMIC_FILE_H
#include <stdio.h>

#include "hearth/hearth.h"

typedef struct atomic_file {
    FILE *f;
    char tmp[4096];
    char path[4096];
} atomic_file;

/// Open a temp file next to path for binary writing.
hearth_status atomic_open(atomic_file *af, const char *path, hearth_error *err);
/// Flush, fsync and rename over path. On failure the temp file is removed and path is untouched.
hearth_status atomic_commit(atomic_file *af, hearth_error *err);
/// Give up: close and remove the temp file.
void atomic_abort(atomic_file *af);
/// Remove the temp files ("<path>.tmp.<pid>") under dir, recursively, whose
/// process no longer exists: a run killed mid-write leaves its temp file, and
/// nothing else would ever remove it. Returns how many were removed.
int atomic_clean_stale(const char *dir);
#endif

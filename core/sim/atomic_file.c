/* atomic_file.c: temp file + fsync + rename. */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"

#include <errno.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "error.h"

hearth_status atomic_open(atomic_file *af, const char *path, hearth_error *err) {
    memset(af, 0, sizeof *af);
    if (strlen(path) + 32 >= sizeof af->tmp) return err_set(err, HEARTH_ERR_IO, "%s: path too long", path);
    snprintf(af->path, sizeof af->path, "%s", path);
    snprintf(af->tmp, sizeof af->tmp, "%s.tmp.%ld", path, (long)getpid());
    af->f = fopen(af->tmp, "wb");
    if (!af->f) return err_set(err, HEARTH_ERR_IO, "%s: cannot create: %s", path, strerror(errno));
    return HEARTH_OK;
}

hearth_status atomic_commit(atomic_file *af, hearth_error *err) {
    int bad = ferror(af->f) || fflush(af->f) != 0 || fsync(fileno(af->f)) != 0;
    int e = errno;
    if (fclose(af->f) != 0 && !bad) {
        bad = 1;
        e = errno;
    }
    af->f = NULL;
    if (!bad && rename(af->tmp, af->path) != 0) {
        bad = 1;
        e = errno;
    }
    if (bad) {
        remove(af->tmp);
        return err_set(err, HEARTH_ERR_IO, "%s: write failed: %s", af->path, strerror(e));
    }
    return HEARTH_OK;
}

hearth_status hearth_mkdir_p(const char *dir, hearth_error *err) {
    char buf[4096];
    if (snprintf(buf, sizeof buf, "%s", dir) >= (int)sizeof buf) return err_set(err, HEARTH_ERR_IO, "%s: path too long", dir);
    for (char *p = buf + 1; *p; p++)
        if (*p == '/') {
            *p = '\0';
            if (mkdir(buf, 0777) && errno != EEXIST)
                return err_set(err, HEARTH_ERR_IO, "cannot create folder '%s': %s", buf, strerror(errno));
            *p = '/';
        }
    if (mkdir(buf, 0777) && errno != EEXIST) return err_set(err, HEARTH_ERR_IO, "cannot create folder '%s': %s", buf, strerror(errno));
    return HEARTH_OK;
}

void atomic_abort(atomic_file *af) {
    if (af->f) fclose(af->f);
    af->f = NULL;
    remove(af->tmp);
}

/* atomic_file.c: temp file + fsync + rename, and sweeping the temp files
 * of runs that were killed before they could rename or remove them. */
#define _POSIX_C_SOURCE 200809L
#include "atomic_file.h"

#include <dirent.h>
#include <errno.h>
#include <signal.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <unistd.h>

#include "alloc.h"
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

/* The pid of a temp file name "<path>.tmp.<pid>", or 0 when it is not one. */
static long temp_pid(const char *name) {
    const char *t = NULL;
    for (const char *p = strstr(name, ".tmp."); p; p = strstr(p + 1, ".tmp.")) t = p; /* the last one */
    if (!t || t == name) return 0;
    const char *d = t + 5;
    if (*d < '1' || *d > '9') return 0;
    char *end;
    long pid = strtol(d, &end, 10);
    return *end || pid <= 0 ? 0 : pid;
}

/* depth bounds the walk in a folder tree with cycles of bind mounts */
static int clean_dir(const char *dir, int depth) {
    if (depth > 32) return 0;
    DIR *d = opendir(dir);
    if (!d) return 0;
    int removed = 0;
    const long self = (long)getpid();
    struct dirent *e;
    while ((e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        char path[4096];
        if (snprintf(path, sizeof path, "%s/%s", dir, e->d_name) >= (int)sizeof path) continue;
        struct stat st;
        if (lstat(path, &st) != 0) continue; /* lstat: never follow a link out of the folder */
        if (S_ISDIR(st.st_mode)) {
            removed += clean_dir(path, depth + 1);
            continue;
        }
        if (!S_ISREG(st.st_mode)) continue;
        long pid = temp_pid(e->d_name);
        /* ESRCH: no such process, so no writer will ever rename it; EPERM means alive */
        if (pid && pid != self && kill((pid_t)pid, 0) != 0 && errno == ESRCH && remove(path) == 0) removed++;
    }
    closedir(d);
    return removed;
}

int atomic_clean_stale(const char *dir) { return dir ? clean_dir(dir, 0) : 0; }

int hearth_clean_stale_temps(const char *dir) { return atomic_clean_stale(dir); }

/* ---- the public handle (<hearth/hearth.h>) ----------------------------------
 * Hosts get an opaque, allocated handle rather than the struct: its 8 KiB of
 * path buffers stay private and may change without breaking a caller. */

struct hearth_atomic_file {
    atomic_file af;
};

hearth_atomic_file *hearth_atomic_file_open(const char *path, hearth_error *err) {
    hearth_atomic_file *h = mem_alloc(sizeof *h);
    if (!h) {
        err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory to start writing it", path);
        return NULL;
    }
    if (atomic_open(&h->af, path, err)) {
        mem_free(h, sizeof *h);
        return NULL;
    }
    return h;
}

void hearth_atomic_file_write(hearth_atomic_file *af, const void *data, size_t n) {
    if (n) fwrite(data, 1, n, af->af.f); /* a short write sets the stream's error flag, which the commit reads */
}

void hearth_atomic_file_printf(hearth_atomic_file *af, const char *fmt, ...) {
    va_list ap;
    va_start(ap, fmt);
    vfprintf(af->af.f, fmt, ap);
    va_end(ap);
}

hearth_status hearth_atomic_file_commit(hearth_atomic_file *af, hearth_error *err) {
    hearth_status st = atomic_commit(&af->af, err);
    mem_free(af, sizeof *af);
    return st;
}

void hearth_atomic_file_abort(hearth_atomic_file *af) {
    if (!af) return;
    atomic_abort(&af->af);
    mem_free(af, sizeof *af);
}

/* fuzz_util.c: temporary files for the path-taking readers (see fuzz_util.h). */
#define _XOPEN_SOURCE 700 /* nftw */
#include "fuzz_util.h"

#include <ftw.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

static const char *tmp_root(void) {
    struct stat st;
    if (stat("/dev/shm", &st) == 0 && S_ISDIR(st.st_mode) && access("/dev/shm", W_OK) == 0)
        return "/dev/shm";
    const char *t = getenv("TMPDIR");
    return t && *t ? t : "/tmp";
}

/* Removed at exit so neither the corpus replay nor a fuzz run leaves litter. */
static char g_file[512], g_dir[512];

static void cleanup(void) {
    if (g_file[0]) unlink(g_file);
    if (g_dir[0]) fuzz_remove_tree(g_dir, 1);
}

static int remove_one(const char *path, const struct stat *st, int type, struct FTW *ftw) {
    (void)st;
    (void)type;
    if (ftw->level > 0) remove(path);
    return 0;
}

void fuzz_remove_tree(const char *dir, int and_dir) {
    /* depth first, not following symlinks: a scene may leave one pointing anywhere */
    nftw(dir, remove_one, 16, FTW_DEPTH | FTW_PHYS);
    if (and_dir) rmdir(dir);
}

static void register_cleanup(void) {
    static int done;
    if (!done) {
        done = 1;
        atexit(cleanup);
    }
}

const char *fuzz_temp_file(const uint8_t *data, size_t size, const char *suffix) {
    static char made_for[32];
    if (!g_file[0] || strcmp(made_for, suffix) != 0) {
        if (g_file[0]) unlink(g_file);
        snprintf(g_file, sizeof g_file, "%s/hearth_fuzz_%ld%s", tmp_root(), (long)getpid(), suffix);
        snprintf(made_for, sizeof made_for, "%s", suffix);
        register_cleanup();
    }
    FILE *f = fopen(g_file, "wb");
    if (!f) return NULL;
    int ok = (size == 0 || fwrite(data, 1, size, f) == size);
    if (fclose(f) != 0) ok = 0;
    return ok ? g_file : NULL;
}

const char *fuzz_temp_dir(void) {
    if (!g_dir[0]) {
        snprintf(g_dir, sizeof g_dir, "%s/hearth_fuzz_out_XXXXXX", tmp_root());
        if (!mkdtemp(g_dir)) {
            g_dir[0] = '\0';
            return NULL;
        }
        register_cleanup();
    }
    return g_dir;
}

int fuzz_verbose(void) {
    static int v = -1;
    if (v < 0) {
        const char *e = getenv("FUZZ_VERBOSE");
        v = e && *e && strcmp(e, "0") != 0;
    }
    return v;
}

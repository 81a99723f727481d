/* fs_fixture.h: temporary folders and whole-file reads for tests that write files. */
#ifndef HEARTH_FS_FIXTURE_H
#define HEARTH_FS_FIXTURE_H
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "test.h"

/* make_dir: a fresh folder under /tmp; rm_dir: remove it and its files;
 * count_tmp: files named *.tmp.* (left by an interrupted atomic write);
 * slurp: a whole file, NUL-terminated (malloc'd, *n = its size). */
static inline void make_dir(char *dir, size_t n) {
    snprintf(dir, n, "/tmp/hearth_test_XXXXXX");
    CHECK(mkdtemp(dir) != NULL);
}

static inline void rm_dir(const char *dir) {
    DIR *d = opendir(dir);
    if (!d) return;
    struct dirent *e;
    char p[512];
    while ((e = readdir(d))) {
        if (!strcmp(e->d_name, ".") || !strcmp(e->d_name, "..")) continue;
        snprintf(p, sizeof p, "%s/%s", dir, e->d_name);
        if (remove(p) != 0) rmdir(p);
    }
    closedir(d);
    rmdir(dir);
}

static inline int count_tmp(const char *dir) {
    DIR *d = opendir(dir);
    int n = 0;
    if (!d) return -1;
    struct dirent *e;
    while ((e = readdir(d)))
        if (strstr(e->d_name, ".tmp.")) n++;
    closedir(d);
    return n;
}

/* Whole file, NUL-terminated so the text part can be searched (malloc'd). */
static inline unsigned char *slurp(const char *path, size_t *n) {
    FILE *f = fopen(path, "rb");
    *n = 0;
    if (!f) return NULL;
    fseek(f, 0, SEEK_END);
    long len = ftell(f);
    fseek(f, 0, SEEK_SET);
    unsigned char *b = malloc((size_t)len + 1);
    if (b && fread(b, 1, (size_t)len, f) != (size_t)len) {
        free(b);
        b = NULL;
    }
    fclose(f);
    if (b) {
        b[len] = 0;
        *n = (size_t)len;
    }
    return b;
}

#endif

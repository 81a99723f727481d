/* driver.c: replay a fuzz target's corpus without libFuzzer.
 *
 * `fuzz_<target> DIR|FILE...` feeds every regular file named, and every
 * regular file directly inside a folder named, to LLVMFuzzerTestOneInput, in
 * sorted order so a failure always names the same file first. The suite uses
 * it (fuzz_corpus_<target>) with gcc and no clang: each crash once found and
 * committed to the corpus stays fixed. It fails when it ran no input at all,
 * so an empty or misplaced corpus cannot pass. */
#include <dirent.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fuzz_util.h"

/* Corpus files are small (< 64 kB, see tests/fuzz/README.md); anything much
 * larger is a mistake in the corpus, not an input. */
#define DRIVER_MAX_INPUT (4u << 20)

static int run_file(const char *path) {
    FILE *f = fopen(path, "rb");
    if (!f) {
        fprintf(stderr, "driver: cannot open %s\n", path);
        return -1;
    }
    unsigned char *buf = malloc(DRIVER_MAX_INPUT);
    if (!buf) {
        fclose(f);
        fprintf(stderr, "driver: out of memory for %s\n", path);
        return -1;
    }
    size_t n = fread(buf, 1, DRIVER_MAX_INPUT, f);
    int too_big = n == DRIVER_MAX_INPUT && fgetc(f) != EOF;
    fclose(f);
    if (too_big) {
        free(buf);
        fprintf(stderr, "driver: %s is larger than %u bytes\n", path, DRIVER_MAX_INPUT);
        return -1;
    }
    fprintf(stderr, "driver: %s (%zu bytes)\n", path, n);
    /* Copy to an exact-size block so ASan sees any read past the input's end. */
    unsigned char *exact = malloc(n ? n : 1);
    if (!exact) {
        free(buf);
        return -1;
    }
    memcpy(exact, buf, n);
    free(buf);
    LLVMFuzzerTestOneInput(exact, n);
    free(exact);
    return 0;
}

static int cmp_str(const void *a, const void *b) {
    return strcmp(*(char *const *)a, *(char *const *)b);
}

static int run_dir(const char *dir, long *count) {
    DIR *d = opendir(dir);
    if (!d) {
        fprintf(stderr, "driver: cannot open folder %s\n", dir);
        return -1;
    }
    char **names = NULL;
    size_t n = 0, cap = 0;
    struct dirent *e;
    while ((e = readdir(d))) {
        if (e->d_name[0] == '.') continue; /* ., .. and hidden files such as .gitkeep */
        if (n == cap) {
            cap = cap ? 2 * cap : 64;
            char **nn = realloc(names, cap * sizeof *names);
            if (!nn) break;
            names = nn;
        }
        size_t len = strlen(dir) + strlen(e->d_name) + 2;
        names[n] = malloc(len);
        if (!names[n]) break;
        snprintf(names[n], len, "%s/%s", dir, e->d_name);
        n++;
    }
    closedir(d);
    qsort(names, n, sizeof *names, cmp_str);
    int rc = 0;
    for (size_t i = 0; i < n; i++) {
        struct stat st;
        if (stat(names[i], &st) == 0 && S_ISREG(st.st_mode)) {
            if (run_file(names[i]) != 0) rc = -1;
            else (*count)++;
        }
        free(names[i]);
    }
    free(names);
    return rc;
}

int main(int argc, char **argv) {
    if (argc < 2) {
        fprintf(stderr, "usage: %s CORPUS_DIR|FILE...\n", argv[0]);
        return 2;
    }
    long count = 0;
    int rc = 0;
    for (int i = 1; i < argc; i++) {
        struct stat st;
        if (stat(argv[i], &st) != 0) {
            fprintf(stderr, "driver: %s does not exist\n", argv[i]);
            rc = 1;
        } else if (S_ISDIR(st.st_mode)) {
            if (run_dir(argv[i], &count) != 0) rc = 1;
        } else if (run_file(argv[i]) == 0) {
            count++;
        } else {
            rc = 1;
        }
    }
    printf("driver: %ld input%s ran without a finding\n", count, count == 1 ? "" : "s");
    if (count == 0) {
        fprintf(stderr, "driver: no input found: the corpus is empty or the path is wrong\n");
        return 1;
    }
    return rc;
}

/* cmd_scenes.c: `hearth scenes`, the shipped scenes listed: each scene's path (as `hearth run` takes it) and the
 * first sentence of its header comment, grouped by folder (the top level, then baking/, sauces/, sph/, ...).
 *
 * Where they are found (#18, helper userfix11; userview4's item 12: `hearth list` was an unknown command and
 * README's prose was the list): $HEARTH_SCENES_DIR when set, else the source tree's scripts/scenes this hearth
 * was built from (HEARTH_SOURCE_SCENES, as cmd_rheometer.c finds the assets), else the install prefix's
 * share/hearth/scenes (HEARTH_INSTALL_SCENES, which meson install fills). The first that is a folder is
 * listed and named in the first line; none is a message naming every place looked, exit 1.
 *
 * The header's first sentence, not its first line: a header's lines are wrapped at ~110 columns, so a first
 * line stops mid-phrase ("dough shaped by a PNG mask (assets/masks/gingerbread.png),"). The sentence ends at the
 * first '.' outside parentheses followed by a blank or the header's end ("Ding et al. 2019, Fig. 15" sits in
 * parentheses), and is cut at a word with "..." past SUMMARY_MAX bytes, so a line fits 120 columns. */
#include <dirent.h>
#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "commands.h"

#ifndef HEARTH_SOURCE_SCENES
#define HEARTH_SOURCE_SCENES "scripts/scenes"
#endif
#ifndef HEARTH_INSTALL_SCENES
#define HEARTH_INSTALL_SCENES "/usr/local/share/hearth/scenes"
#endif

enum { SUMMARY_MAX = 90, MAX_NAMES = 512 }; /* 2 + 26 + 1 + 90: a line within 120 columns */

static void scenes_usage(FILE *f) {
    fprintf(f, "usage: hearth scenes\n"
               "Lists the scenes shipped with hearth, by folder: each one's path, to give to hearth run, and the\n"
               "first sentence of its header comment (the scene file's opening comment says the rest; hearth run\n"
               "SCENE.lua --params lists its settings). The first line says where they were found:\n"
               "$HEARTH_SCENES_DIR when set, else the source tree hearth was built from (%s),\n"
               "else the install prefix's (%s).\n",
            HEARTH_SOURCE_SCENES, HEARTH_INSTALL_SCENES);
}

static int is_dir(const char *p) {
    struct stat st;
    return p && *p && stat(p, &st) == 0 && S_ISDIR(st.st_mode);
}

static int by_name(const void *a, const void *b) { return strcmp(*(char *const *)a, *(char *const *)b); }

/* The names in dir that are folders (want_dirs) or .lua files, sorted; the count, -1 when dir cannot be read. */
static int names_in(const char *dir, int want_dirs, char **out, int cap) {
    DIR *d = opendir(dir);
    if (!d) return -1;
    int n = 0;
    for (struct dirent *e; (e = readdir(d)) != NULL;) {
        if (e->d_name[0] == '.') continue;
        char p[4096];
        if (snprintf(p, sizeof p, "%s/%s", dir, e->d_name) >= (int)sizeof p) continue;
        const size_t len = strlen(e->d_name);
        const int ok = want_dirs ? is_dir(p) : len > 4 && !strcmp(e->d_name + len - 4, ".lua") && !is_dir(p);
        if (ok && n < cap && (out[n] = strdup(e->d_name))) n++;
    }
    closedir(d);
    qsort(out, (size_t)n, sizeof *out, by_name);
    return n;
}

/* The first sentence of path's header comment (its leading "--" lines) into out; "(no header comment)" when the
 * file opens with code, "(cannot read: why)" when it cannot be opened. */
static void summary_of(const char *path, char *out, size_t n) {
    FILE *f = fopen(path, "r");
    if (!f) {
        snprintf(out, n, "(cannot read: %s)", strerror(errno));
        return;
    }
    char text[4 * SUMMARY_MAX], line[1024];
    size_t len = 0;
    int depth = 0, done = 0;
    text[0] = 0;
    while (!done && len < sizeof text - 2 && fgets(line, sizeof line, f)) {
        if (strncmp(line, "--", 2) != 0) break; /* the header ends where the code starts */
        const char *p = line + 2;
        while (*p == '-') p++; /* "---" lines */
        while (*p == ' ' || *p == '\t') p++;
        if (*p == '\n' || *p == '\r' || !*p) {
            if (len) break; /* a blank comment line ends the first paragraph */
            continue;
        }
        if (len) text[len++] = ' ';
        for (; *p && *p != '\n' && *p != '\r' && len < sizeof text - 1; p++) {
            text[len++] = *p;
            depth += *p == '(' ? 1 : *p == ')' && depth > 0 ? -1 : 0;
            if (*p == '.' && depth == 0 && (p[1] == ' ' || p[1] == '\n' || p[1] == '\r' || !p[1])) {
                done = 1;
                break;
            }
        }
        text[len] = 0;
    }
    fclose(f);
    if (!len) {
        snprintf(out, n, "(no header comment)");
        return;
    }
    if (len > SUMMARY_MAX) { /* cut at the last blank before the limit */
        size_t cut = SUMMARY_MAX - 3;
        while (cut > 0 && text[cut] != ' ') cut--;
        if (cut == 0) cut = SUMMARY_MAX - 3;
        while (cut > 0 && (text[cut - 1] == ',' || text[cut - 1] == ' ' || text[cut - 1] == ':')) cut--;
        memcpy(text + cut, "...", 4);
    }
    snprintf(out, n, "%s", text);
}

/* One folder's scenes under its heading: rel is its path below the scenes folder ("" for the top level). */
static int list_folder(const char *root, const char *rel, int *count) {
    char dir[4096];
    if (snprintf(dir, sizeof dir, "%s%s%s", root, *rel ? "/" : "", rel) >= (int)sizeof dir) {
        fprintf(stderr, "hearth scenes: the folder %s/%s: path too long\n", root, rel);
        return 1;
    }
    char *names[MAX_NAMES];
    const int n = names_in(dir, 0, names, MAX_NAMES);
    if (n < 0) {
        fprintf(stderr, "hearth scenes: cannot read the folder %s: %s\n", dir, strerror(errno));
        return 1;
    }
    if (n > 0) printf("\n%s/\n", *rel ? rel : ".");
    for (int k = 0; k < n; k++) {
        char path[8192], what[4 * SUMMARY_MAX], shown[512];
        if (snprintf(path, sizeof path, "%s/%s", dir, names[k]) >= (int)sizeof path)
            snprintf(what, sizeof what, "(path too long)");
        else summary_of(path, what, sizeof what);
        if (snprintf(shown, sizeof shown, "%s%s%s", rel, *rel ? "/" : "", names[k]) >= (int)sizeof shown)
            shown[sizeof shown - 1] = 0; /* cut: the name is shown as far as it goes */
        printf("  %-26s %s\n", shown, what);
        free(names[k]);
    }
    *count += n;
    return 0;
}

int cmd_scenes(int argc, char **argv) {
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
            scenes_usage(stdout);
            return 0;
        }
        fprintf(stderr, "hearth scenes: unknown argument '%s'; it takes none (hearth scenes --help)\n", argv[i]);
        return 2;
    }
    const char *env = getenv("HEARTH_SCENES_DIR"), *root = NULL, *from = NULL;
    if (env && *env) {
        if (!is_dir(env)) {
            fprintf(stderr, "hearth scenes: HEARTH_SCENES_DIR = %s is not a folder; set it to the shipped scenes' "
                            "folder (scripts/scenes in the source tree), or unset it\n", env);
            return 1;
        }
        root = env, from = "$HEARTH_SCENES_DIR";
    } else if (is_dir(HEARTH_SOURCE_SCENES)) {
        root = HEARTH_SOURCE_SCENES, from = "the source tree hearth was built from";
    } else if (is_dir(HEARTH_INSTALL_SCENES)) {
        root = HEARTH_INSTALL_SCENES, from = "the install prefix";
    } else {
        fprintf(stderr, "hearth scenes: no scenes folder: %s (the source tree hearth was built from) and %s (the "
                        "install prefix's) are not folders; set HEARTH_SCENES_DIR to the shipped scenes' folder\n",
                HEARTH_SOURCE_SCENES, HEARTH_INSTALL_SCENES);
        return 1;
    }
    printf("hearth scenes: the shipped scenes in %s (%s); run one with hearth run %s/PATH\n", root, from, root);
    int count = 0;
    if (list_folder(root, "", &count)) return 1;
    char *dirs[MAX_NAMES];
    const int nd = names_in(root, 1, dirs, MAX_NAMES);
    int st = nd < 0;
    if (nd < 0) fprintf(stderr, "hearth scenes: cannot read the folder %s: %s\n", root, strerror(errno));
    for (int k = 0; k < nd; k++) {
        if (!st) st = list_folder(root, dirs[k], &count);
        free(dirs[k]);
    }
    if (st) return 1;
    printf("\n%d scenes\n", count);
    return 0;
}

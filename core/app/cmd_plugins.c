/* cmd_plugins.c: `hearth plugins` (list with parameter tables) and
 * `hearth plugin check FILE.so` (the conformance battery). */
#include <stdio.h>
#include <string.h>

#include "commands.h"
#include "hearth/hearth.h"

static void print_plugin(void *ud, const char *name, const char *path) {
    int *count = ud;
    hearth_error err;
    const hearth_plugin *pl = hearth_plugin_load(path, &err);
    if (!pl) {
        printf("%s  (%s)\n  cannot load: %s\n\n", name, path, err.msg);
        return;
    }
    const hearth_material *m = hearth_plugin_material(pl);
    printf("%s  (%s)\n  %s\n", m->name, path, m->summary ? m->summary : "");
    if (m->state_size) printf("  state: %d doubles per particle\n", m->state_size);
    printf("  %-14s %-10s %12s %12s %12s  %s\n", "parameter", "unit", "default", "min", "max", "meaning");
    for (int i = 0; i < m->nparams; i++) {
        const hearth_param *p = &m->params[i];
        printf("  %-14s %-10s %12g %12g %12g  %s\n", p->name, p->unit, p->def, p->min, p->max, p->help);
    }
    printf("\n");
    (*count)++;
}

int cmd_plugins(int argc, char **argv) {
    if (argc > 1) {
        if (!strcmp(argv[1], "--help")) {
            printf("usage: hearth plugins\nLists every material plugin on the search path with its parameter table.\n");
            return 0;
        }
        fprintf(stderr, "hearth plugins: takes no arguments (see --help)\n");
        return 2;
    }
    int count = 0;
    hearth_plugin_each(print_plugin, &count);
    if (count == 0) {
        fprintf(stderr, "hearth plugins: no plugins found; set HEARTH_PLUGIN_PATH to a folder holding hearth_<name>.so files\n");
        return 1;
    }
    return 0;
}

static void print_check(void *ud, const char *check, int passed, const char *detail) {
    (void)ud;
    printf("%-20s %s  %s\n", check, passed ? "PASS" : "FAIL", detail ? detail : "");
}

int cmd_plugin_check(int argc, char **argv) {
    if (argc != 2 || !strcmp(argv[1], "--help")) {
        FILE *f = argc == 2 ? stdout : stderr;
        fprintf(f, "usage: hearth plugin check FILE.so\n"
                   "Loads one plugin by path and runs the conformance battery: zero stress at rest,\n"
                   "symmetric stress, frame indifference, finite output at parameter extremes, and a\n"
                   "wave speed consistent with the small-strain stiffness. Exits 0 when all pass.\n");
        return argc == 2 ? 0 : 2;
    }
    hearth_error err;
    const char *path = argv[1];
    char buf[4200];
    if (!strchr(path, '/')) { /* a bare file name means this folder, not the search path */
        snprintf(buf, sizeof buf, "./%s", path);
        path = buf;
    }
    int failed = hearth_plugin_check(path, print_check, NULL, &err);
    if (failed < 0) {
        fprintf(stderr, "hearth plugin check: %s\n", err.msg);
        return 1;
    }
    printf("%s: %s\n", argv[1], failed ? "FAILED" : "all checks passed");
    return failed ? 1 : 0;
}

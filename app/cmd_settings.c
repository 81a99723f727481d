/* cmd_settings.c: `hearth help scene` and `hearth doc man|lua`, the scene
 * settings as a user reads them, printed from the one schema
 * (hearth_scene_settings). `hearth doc` prints the generated sections of
 * docs/hearth.1 and docs/lua.md; scripts/settings_docs splices them in, and
 * the cli test settings_docs_current fails when a committed copy differs. */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "commands.h"
#include "hearth/hearth.h"

static void num(char *b, size_t n, double x) {
    if (isinf(x)) snprintf(b, n, "inf");
    else snprintf(b, n, "%.10g", x);
}

/* the default as h.scene takes it: 0.01, "slip", false, {0, -9.81, 0} */
static void default_text(const hearth_setting *e, char *b, size_t n) {
    const double *v = e->vec_def;
    switch (e->kind) {
    case HEARTH_SETTING_REAL:
    case HEARTH_SETTING_INT:
    case HEARTH_SETTING_SEED:
        if (isnan(e->def)) snprintf(b, n, "unset");
        else num(b, n, e->def);
        break;
    case HEARTH_SETTING_FLAG: snprintf(b, n, "%s", e->def != 0 ? "true" : "false"); break;
    case HEARTH_SETTING_CHOICE: snprintf(b, n, "\"%s\"", e->words[(int)e->def]); break;
    case HEARTH_SETTING_VECTOR: snprintf(b, n, "{%g, %g, %g}", v[0], v[1], v[2]); break;
    case HEARTH_SETTING_BOX: snprintf(b, n, "{{%g, %g, %g}, {%g, %g, %g}}", v[0], v[1], v[2], v[3], v[4], v[5]); break;
    case HEARTH_SETTING_TEXT: snprintf(b, n, "none"); break;
    }
}

/* what is valid: [0, inf), "sticky", "slip" or "separate", true or false */
static void valid_text(const hearth_setting *e, char *b, size_t n) {
    char lo[32], hi[32];
    num(lo, sizeof lo, e->min);
    num(hi, sizeof hi, e->max);
    switch (e->kind) {
    case HEARTH_SETTING_REAL:
    case HEARTH_SETTING_INT:
    case HEARTH_SETTING_SEED:
        snprintf(b, n, "%s%s, %s%s%s%s", e->min_open ? "(" : "[", lo, hi, isinf(e->max) ? ")" : "]",
                 e->kind == HEARTH_SETTING_REAL ? "" : ", whole", e->nan_ok ? ", or unset" : "");
        break;
    case HEARTH_SETTING_FLAG: snprintf(b, n, "true or false"); break;
    case HEARTH_SETTING_CHOICE: {
        size_t len = 0;
        b[0] = 0;
        for (int k = 0; e->words[k] && len < n; k++)
            len += (size_t)snprintf(b + len, n - len, "%s\"%s\"", k ? (e->words[k + 1] ? ", " : " or ") : "", e->words[k]);
        break;
    }
    case HEARTH_SETTING_VECTOR: snprintf(b, n, "{x, y} or {x, y, z}, finite"); break;
    case HEARTH_SETTING_BOX: snprintf(b, n, "{{lo}, {hi}}, finite, each axis >= 6 dx"); break;
    case HEARTH_SETTING_TEXT: snprintf(b, n, "a string"); break;
    }
}

static const char *unit_text(const hearth_setting *e) { return strcmp(e->unit, "1") ? e->unit : ""; }
/* the unit after a range; a vector's or the box's is with its default */
static const char *range_unit(const hearth_setting *e) {
    return e->kind == HEARTH_SETTING_VECTOR || e->kind == HEARTH_SETTING_BOX ? "" : unit_text(e);
}

static void print_help_scene(void) {
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    printf("Scene settings: h.scene{name = value, ...} in a Lua scene; a dotted name is a key of a sub-table\n"
           "(oven.beta: h.scene{oven = {temperature = 200, beta = 10}}). The sph.* settings apply with\n"
           "solver = \"sph\". Settings marked --set may be changed from the command line in any scene\n"
           "(hearth run SCENE --set dx=0.005; hearth trade --knob).\n\n");
    for (int k = 0; k < n; k++) {
        char d[96], v[128];
        default_text(&set[k], d, sizeof d);
        valid_text(&set[k], v, sizeof v);
        const char *u = unit_text(&set[k]);
        printf("  %-18s default %s%s%s; valid %s%s%s%s\n      %s\n", set[k].name, d, *u ? " " : "", u, v,
               *range_unit(&set[k]) ? " " : "", range_unit(&set[k]), set[k].knob ? "; --set" : "", set[k].help);
    }
}

static void print_man(void) {
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    for (int k = 0; k < n; k++) {
        char d[96], v[128];
        default_text(&set[k], d, sizeof d);
        valid_text(&set[k], v, sizeof v);
        const char *u = unit_text(&set[k]);
        printf(".TP\n.B %s\n%s.\nDefault %s%s%s; valid %s%s%s%s.\n", set[k].name, set[k].help, d, *u ? " " : "", u, v,
               *range_unit(&set[k]) ? " " : "", range_unit(&set[k]), set[k].knob ? "; a --set knob" : "");
    }
}

static void print_lua(void) {
    int n = 0;
    const hearth_setting *set = hearth_scene_settings(&n);
    printf("| setting | unit | default | valid | --set | what |\n|---|---|---|---|---|---|\n");
    for (int k = 0; k < n; k++) {
        char d[96], v[128];
        default_text(&set[k], d, sizeof d);
        valid_text(&set[k], v, sizeof v);
        printf("| `%s` | %s | `%s` | %s | %s | ", set[k].name, unit_text(&set[k]), d, v, set[k].knob ? "yes" : "");
        for (const char *c = set[k].help; *c; c++) /* a | in the help (|grad C|) would end the cell */
            *c == '|' ? fputs("\\|", stdout) : putchar(*c);
        printf(" |\n");
    }
}

int cmd_help(int argc, char **argv) {
    if (argc >= 2 && !strcmp(argv[1], "scene")) {
        print_help_scene();
        return 0;
    }
    fprintf(stderr, "hearth help: unknown topic '%s'; topics: scene (or hearth --help)\n", argc >= 2 ? argv[1] : "");
    return 2;
}

int cmd_doc(int argc, char **argv) {
    if (argc == 2 && !strcmp(argv[1], "man")) {
        print_man();
        return 0;
    }
    if (argc == 2 && !strcmp(argv[1], "lua")) {
        print_lua();
        return 0;
    }
    fprintf(stderr, "hearth doc: usage: hearth doc man|lua (the generated sections of docs/hearth.1 and docs/lua.md)\n");
    return 2;
}

/* sauce_library.c: reading assets/sauces.csv. */
#include "hearth/lab.h"

#include "csv.h"

#include <ctype.h>
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "alloc.h"
#include "error.h"
#include "params.h"

enum { C_NAME, C_LABEL, C_TEMP, C_H, C_ETA, C_SY, C_GEOM, C_COUNT };
static const char *const col_names[C_COUNT] = {"name", "label", "temperature_C", "h", "eta", "sigma_y", "geometry"};

#define LIB_LINE 4096
#define LIB_CELLS 64
/* Table 1 has tens of sauces; the duplicate-name check is quadratic, so a
 * runaway file is refused before it costs minutes. */
#define LIB_MAX_SAUCES 10000



static int valid_name(const char *s) {
    if (!*s) return 0;
    for (; *s; s++)
        if (!(islower((unsigned char)*s) || isdigit((unsigned char)*s) || *s == '_')) return 0;
    return 1;
}

void hearth_sauce_library_free(hearth_sauce_library *lib) {
    if (!lib) return;
    mem_free(lib->items, sizeof(hearth_sauce) * (size_t)(lib->n > 0 ? lib->n : 0));
    memset(lib, 0, sizeof *lib);
}

hearth_status hearth_sauce_library_load(const char *path, hearth_sauce_library *lib, hearth_error *err) {
    err_clear(err);
    memset(lib, 0, sizeof *lib);
    FILE *f = fopen(path, "r");
    if (!f) return err_set(err, HEARTH_ERR_IO, "%s: cannot open the sauce library: %s", path, strerror(errno));
    char line[LIB_LINE];
    char *cells[LIB_CELLS];
    int col[C_COUNT], lineno = 0, header = 0, n = 0, cap = 0;
    for (int k = 0; k < C_COUNT; k++) col[k] = -1;
    hearth_sauce *items = NULL;
    hearth_status st = HEARTH_OK;
    while (!st) {
        csv_line got = csv_read_line(f, line, sizeof line);
        if (got == CSV_LINE_EOF || got == CSV_LINE_IO) break;
        if (lineno == INT_MAX) {
            st = err_set(err, HEARTH_ERR_FORMAT, "%s: more than %d lines", path, INT_MAX);
            break;
        }
        lineno++;
        if (got == CSV_LINE_TOO_LONG) {
            st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d is longer than %d characters", path, lineno,
                         (int)sizeof line - 1);
            break;
        }
        if (got == CSV_LINE_NUL) {
            st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d holds a NUL byte: this is not a text CSV file", path,
                         lineno);
            break;
        }
        char *t = csv_trim(line);
        if (!*t || *t == '#') continue;
        int nc = csv_split(t, cells, LIB_CELLS);
        if (!header) {
            header = lineno;
            for (int i = 0; i < nc; i++)
                for (int k = 0; k < C_COUNT; k++)
                    if (!strcmp(cells[i], col_names[k]) && col[k] < 0) col[k] = i;
            for (int k = 0; k < C_COUNT && !st; k++)
                if (col[k] < 0)
                    st = err_set(err, HEARTH_ERR_FORMAT,
                                 "%s: line %d (header): no column '%s'; the header must name name, label, "
                                 "temperature_C, h, eta, sigma_y and geometry",
                                 path, lineno, col_names[k]);
            continue;
        }
        hearth_sauce s;
        memset(&s, 0, sizeof s);
        for (int k = 0; k < C_COUNT && !st; k++) {
            if (col[k] >= nc) {
                st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d: no cell for column '%s'", path, lineno, col_names[k]);
                break;
            }
            const char *cell = cells[col[k]];
            if (k == C_NAME || k == C_LABEL || k == C_GEOM) {
                size_t cap_k = k == C_NAME ? sizeof s.name : k == C_LABEL ? sizeof s.label : sizeof s.geometry;
                char *dst = k == C_NAME ? s.name : k == C_LABEL ? s.label : s.geometry;
                if (strlen(cell) >= cap_k)
                    st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d: %s '%s' is longer than %zu characters", path,
                                 lineno, col_names[k], cell, cap_k - 1);
                else if (k == C_NAME && !valid_name(cell))
                    st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d: name '%s' must be lower case letters, digits and _",
                                 path, lineno, cell);
                else
                    memcpy(dst, cell, strlen(cell) + 1);
                continue;
            }
            char *end = NULL;
            double v = strtod(cell, &end);
            if (!*cell || *end || !isfinite(v)) {
                st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d: %s '%s' is not a finite number", path, lineno,
                             col_names[k], cell);
                break;
            }
            if ((k == C_H || k == C_ETA) && !(v > 0))
                st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d: %s = %g must be > 0", path, lineno, col_names[k], v);
            else if (k == C_SY && !(v >= 0))
                st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d: sigma_y = %g must be >= 0", path, lineno, v);
            if (k == C_TEMP) s.temperature_C = v;
            if (k == C_H) s.h = v;
            if (k == C_ETA) s.eta = v;
            if (k == C_SY) s.sigma_y = v;
        }
        if (st) break;
        for (int i = 0; i < n; i++)
            if (!strcmp(items[i].name, s.name)) {
                st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d: sauce '%s' is listed twice", path, lineno, s.name);
                break;
            }
        if (st) break;
        if (n == LIB_MAX_SAUCES) {
            st = err_set(err, HEARTH_ERR_FORMAT, "%s: line %d: more than %d sauces", path, lineno, LIB_MAX_SAUCES);
            break;
        }
        if (n == cap) {
            int ncap = cap ? 2 * cap : 32;
            hearth_sauce *ni = mem_realloc(items, sizeof(hearth_sauce) * (size_t)cap, sizeof(hearth_sauce) * (size_t)ncap);
            if (!ni) {
                st = err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory at line %d", path, lineno);
                break;
            }
            items = ni;
            cap = ncap;
        }
        items[n++] = s;
    }
    if (!st && ferror(f)) st = err_set(err, HEARTH_ERR_IO, "%s: read error after line %d", path, lineno);
    fclose(f);
    if (!st && !header) st = err_set(err, HEARTH_ERR_FORMAT, "%s: empty file: expected a header row", path);
    if (!st && n == 0) st = err_set(err, HEARTH_ERR_FORMAT, "%s: no sauces after the header (line %d)", path, header);
    if (!st) {
        hearth_sauce *exact = mem_alloc(sizeof(hearth_sauce) * (size_t)n);
        if (!exact) st = err_set(err, HEARTH_ERR_NOMEM, "%s: out of memory", path);
        else {
            memcpy(exact, items, sizeof(hearth_sauce) * (size_t)n);
            lib->items = exact;
            lib->n = n;
        }
    }
    mem_free(items, sizeof(hearth_sauce) * (size_t)cap);
    return st;
}

const hearth_sauce *hearth_sauce_find(const hearth_sauce_library *lib, const char *name) {
    if (!lib || !name) return NULL;
    if (!strncmp(name, "sauce.", 6)) name += 6;
    for (int i = 0; i < lib->n; i++)
        if (!strcmp(lib->items[i].name, name)) return &lib->items[i];
    return NULL;
}

const hearth_sauce *hearth_sauce_lookup(const hearth_sauce_library *lib, const char *name, hearth_error *err) {
    const hearth_sauce *s = hearth_sauce_find(lib, name);
    if (s) return s;
    const char *bare = name && !strncmp(name, "sauce.", 6) ? name + 6 : name ? name : "";
    enum { MAXC = 256 };
    const char *cand[MAXC];
    int nc = 0;
    for (int i = 0; i < lib->n && nc < MAXC; i++) cand[nc++] = lib->items[i].name;
    const char *near = params_nearest(bare, cand, nc);
    if (near)
        err_set(err, HEARTH_ERR_PARAM, "unknown sauce 'sauce.%s'; did you mean 'sauce.%s'?", bare, near);
    else
        err_set(err, HEARTH_ERR_PARAM, "unknown sauce 'sauce.%s' (the library has %d: sauce.%s ... sauce.%s)", bare,
                lib->n, lib->n ? lib->items[0].name : "", lib->n ? lib->items[lib->n - 1].name : "");
    return NULL;
}

hearth_status hearth_sauce_params(const hearth_material *m, const hearth_sauce *s, double *p, hearth_error *err) {
    err_clear(err);
    for (int i = 0; i < m->nparams; i++) p[i] = m->params[i].def;
    const char *names[3] = {"h", "eta", "sigma_y"};
    const double vals[3] = {s->h, s->eta, s->sigma_y};
    for (int k = 0; k < 3; k++) {
        int idx = -1;
        for (int i = 0; i < m->nparams; i++)
            if (m->params[i].name && !strcmp(m->params[i].name, names[k])) idx = i;
        if (idx < 0)
            return err_set(err, HEARTH_ERR_PARAM,
                           "material '%s' has no parameter '%s', so it cannot take library sauces (use von_mises_sauce)",
                           m->name, names[k]);
        const hearth_param *q = &m->params[idx];
        if (!(vals[k] >= q->min && vals[k] <= q->max))
            return err_set(err, HEARTH_ERR_PARAM, "sauce.%s: %s = %g %s is outside the range [%g, %g] of material '%s'",
                           s->name, names[k], vals[k], q->unit, q->min, q->max, m->name);
        p[idx] = vals[k];
    }
    return HEARTH_OK;
}

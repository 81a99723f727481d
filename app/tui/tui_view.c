/* tui_view.c: the dashboard's panels on the screen: status bar, the two slice
 * views with colour bars, the probe panel, the log, the prompt, help and the
 * too-small message. The heat maps come from the pure tui_draw functions. */
#define NCURSES_WIDECHAR 1
#include <curses.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "tui_app.h"
#include "tui_layout.h"
#include "tui_screen.h"

int tui_scalar_fields(const hearth_scene *s, char out[][32], int max) {
    int n = 0;
    if (!s) return 0;
    const char *f = hearth_scene_fields(s);
    while (*f && n < max) {
        const char *e = strchr(f, ' ');
        size_t len = e ? (size_t)(e - f) : strlen(f);
        if (len < 32) {
            memcpy(out[n], f, len);
            out[n][len] = '\0';
            if (hearth_field_components(out[n]) == 1) n++;
        }
        f += len + (e != NULL);
    }
    return n;
}

static int live(char names[][32], int n, const char *f) {
    for (int i = 0; i < n; i++)
        if (!strcmp(names[i], f)) return 1;
    return 0;
}

void tui_default_fields(tui_app *a) {
    char names[TUI_MAX_FIELDS][32];
    int n = tui_scalar_fields(a->s, names, TUI_MAX_FIELDS);
    if (n == 0) return;
    /* the defaults, temperature and saturation, when the scene has them */
    static const char *left[] = {"temperature", "speed"};
    static const char *right[] = {"saturation", "moisture", "gas", "pressure", "density", "speed"};
    if (!live(names, n, a->field[0])) {
        snprintf(a->field[0], sizeof a->field[0], "%s", names[0]);
        for (size_t i = 0; i < sizeof left / sizeof *left; i++)
            if (live(names, n, left[i])) {
                snprintf(a->field[0], sizeof a->field[0], "%s", left[i]);
                break;
            }
    }
    if (!live(names, n, a->field[1])) {
        snprintf(a->field[1], sizeof a->field[1], "%s", names[n > 1 ? 1 : 0]);
        for (size_t i = 0; i < sizeof right / sizeof *right; i++)
            if (live(names, n, right[i]) && strcmp(right[i], a->field[0])) {
                snprintf(a->field[1], sizeof a->field[1], "%s", right[i]);
                break;
            }
    }
}

/* ---- probes ------------------------------------------------------------ */

static void push_hist(tui_field_probe *p, double v) {
    if (p->n == TUI_HIST) memmove(p->hist, p->hist + 1, sizeof p->hist[0] * (TUI_HIST - 1)), p->n--;
    p->hist[p->n++] = v;
    p->value = v;
}

void tui_sample_probes(tui_app *a) {
    if (!a->s) return;
    hearth_stats st;
    hearth_scene_stats(a->s, &st);
    int advanced = st.step != a->sampled_step;
    char names[TUI_MAX_FIELDS][32];
    int n = tui_scalar_fields(a->s, names, TUI_MAX_FIELDS);
    /* the two views' fields head the list: a short panel still shows what the views show */
    for (int k = 1; k >= 0; k--)
        for (int i = 1; i < n; i++)
            if (!strcmp(names[i], a->field[k])) {
                char keep[32];
                memcpy(keep, names[i], sizeof keep);
                memmove(names[1], names[0], sizeof names[0] * (size_t)i);
                memcpy(names[0], keep, sizeof keep);
                break;
            }
    hearth_error err;
    /* keep the histories of fields that stay live */
    tui_field_probe old[TUI_MAX_FIELDS];
    int nold = a->nfp;
    memcpy(old, a->fp, sizeof old);
    for (int i = 0; i < n; i++) {
        tui_field_probe *p = &a->fp[i];
        int found = 0;
        for (int j = 0; j < nold; j++)
            if (!strcmp(old[j].name, names[i])) *p = old[j], found = 1;
        if (!found) memset(p, 0, sizeof *p), memcpy(p->name, names[i], sizeof p->name);
        double v = NAN;
        if (hearth_probe_point(a->s, names[i], a->cursor, &v, &err)) v = NAN;
        if (advanced || p->n == 0) push_hist(p, v);
        else p->value = v, p->hist[p->n - 1] = v; /* the cursor moved: the newest sample is here */
    }
    a->nfp = n;
    for (int k = 0; k < a->npins; k++) {
        tui_field_probe *p = &a->pin_probe[k];
        double v = NAN;
        if (hearth_probe_point(a->s, p->name, a->pin[k], &v, &err)) v = NAN;
        if (advanced || p->n == 0) push_hist(p, v);
    }
    a->sampled_step = st.step;
    a->sampled_t = st.t;
}

/* ---- text helpers -------------------------------------------------------- */

static void put(int y, int x, int w, const char *s) {
    if (w <= 0) return;
    mvaddnstr(y, x, s, w);
}

static void clear_rect(int y, int x, int w, int h) {
    for (int r = 0; r < h; r++) mvhline(y + r, x, ' ', w);
}

static void put_codes(int y, int x, const uint32_t *cp, int n) {
    for (int i = 0; i < n; i++) {
        wchar_t s[2] = {(wchar_t)cp[i], 0};
        cchar_t cc;
        setcchar(&cc, s, A_NORMAL, 0, NULL);
        mvadd_wch(y, x + i, &cc);
    }
}

static const char *axis_name(int k) { return k == 0 ? "x" : k == 1 ? "y" : "z"; }

/* ---- panels -------------------------------------------------------------- */

/* The simulated time as the scene's frames give it (#18, helper userfix10; userview4's item 7: "t 0.78914 s" where
 * the physical loaf's frames said "t = 4 min"): with a time_scale (h.scene's, as its pictures take it) the real time
 * first, in minutes past two of them as render.c's title, then the simulated seconds and the factor; in animation
 * units (Ding et al. Table 2) the seconds and that they are those units; else the seconds alone. */
static void sim_time_text(tui_app *a, double t, char *buf, size_t n) {
    double scale = 1;
    const int animation = tui_lua_clock(&a->lua, &scale);
    const double real = t * scale;
    if (animation) snprintf(buf, n, "t %.5g s (animation units)", t);
    else if (scale == 1) snprintf(buf, n, "t %.5g s", t);
    else if (real >= 120) snprintf(buf, n, "t %.4g min (%.5g s x %g)", real / 60, t, scale);
    else snprintf(buf, n, "t %.4g s (%.5g s x %g)", real, t, scale);
}

void tui_status_line(tui_app *a, char *buf, unsigned long n) {
    if (!a->s) {
        snprintf(buf, n, "no scene yet (see the log)");
        return;
    }
    hearth_stats st;
    hearth_scene_stats(a->s, &st);
    static const char *gs[] = {"ok", "rolled back", "STOPPED"};
    char tt[96];
    sim_time_text(a, st.t, tt, sizeof tt);
    snprintf(buf, n, "%s  step %ld  dt %.3g s  CFL %.2f  particles %d  %.0f steps/s  guard %s  %s", tt, st.step, st.dt,
             st.cfl, st.particles, a->sps, gs[st.guard], a->running ? "running" : "paused");
}

static void draw_status(tui_app *a, const tui_rect *r) {
    char l1[512], l2[512];
    attron(A_REVERSE);
    mvhline(r->y, 0, ' ', r->w);
    mvhline(r->y + 1, 0, ' ', r->w);
    if (!a->s) {
        put(r->y, 1, r->w - 2, "hearth: no scene yet (the scene file stopped before h.scene; see the log)");
        attroff(A_REVERSE);
        return;
    }
    hearth_stats st;
    hearth_scene_stats(a->s, &st);
    const hearth_scene_def *d = hearth_scene_get_def(a->s);
    char oven[64] = "";
    if (!isnan(d->oven_temperature)) snprintf(oven, sizeof oven, "  oven %.4g degC", d->oven_temperature);
    char tt[96];
    sim_time_text(a, st.t, tt, sizeof tt);
    char solver[64];
    snprintf(solver, sizeof solver, "dt %.3g s   CFL %.2f", st.dt, st.cfl);
    snprintf(l1, sizeof l1, " %s   step %ld   %s%s", tt, st.step, solver, oven);
    /* a clock's longer time ("t 3.76 min (0.7521 s x 300)") would push the oven past line 1's end at 80 columns:
     * dt and CFL go to the head of line 2 instead (11: the short run label and its margin) */
    const int solver_below = (int)strlen(l1) + 11 > r->w;
    if (solver_below) snprintf(l1, sizeof l1, " %s   step %ld%s", tt, st.step, oven);
    if ((int)(strlen(l1) + strlen(a->opt.name)) + 28 < r->w) { /* the scene's name when there is room */
        char named[1100];
        snprintf(named, sizeof named, " %.500s  %s", a->opt.name, l1);
        snprintf(l1, sizeof l1, "%.511s", named);
    }
    char fields[256];
    snprintf(fields, sizeof fields, "%s", hearth_scene_fields(a->s));
    static const char *gs[] = {"ok", "rolled back", "STOPPED"};
    const char *run = a->running ? (a->lua.njobs ? "> running (scene run)" : "> running") : "|| paused";
    /* the long run label only where line 1 still fits beside it */
    if ((int)(strlen(l1) + strlen(run)) + 2 > r->w) run = a->running ? "> running" : "|| paused";
    snprintf(l2, sizeof l2, " %s%sparticles %d   %.0f steps/s   guard %s   fields: %s", solver_below ? solver : "",
             solver_below ? "   " : "", st.particles, a->sps, gs[st.guard], fields);
    int rl = (int)strlen(run);
    put(r->y, 0, r->w - rl - 2, l1); /* the run state keeps its corner: line 1 stops short of it */
    put(r->y + 1, 0, r->w, l2);
    if ((int)strlen(l2) > r->w && r->w > 4) put(r->y + 1, r->w - 3, 3, "...");
    if (st.guard == HEARTH_GUARD_STOPPED) attron(A_BOLD);
    put(r->y, r->w - rl - 1, rl, run);
    attroff(A_REVERSE | A_BOLD);
}

/* in-plane axes of a slice normal to axis (as hearth_probe_slice) */
static void plane_axes(int axis, int *u, int *v) {
    *u = axis == 0 ? 1 : 0;
    *v = axis == 2 ? 1 : 2;
}


/* A field's unit as the panels show it: a dimensionless one (hearth_field_unit's "1": J, saturation, browning)
 * shows none, where "J 1.034 1" read as a second number (#18, helper userview4; the PNGs' colour bars say "(-)"). */
static const char *shown_unit(const char *field) {
    const char *u = hearth_field_unit(field);
    return !u || !strcmp(u, "1") ? "" : u;
}

static void draw_view(tui_app *a, int k, const tui_layout *L, int fresh) {
    const tui_rect *t = &L->title[k], *r = &L->view[k], *b = &L->bar[k];
    clear_rect(t->y, t->x, t->w, 1);
    clear_rect(r->y, r->x, r->w, r->h);
    clear_rect(b->y, b->x, b->w, 1);
    if (!a->s || !a->field[k][0]) return;
    const hearth_scene_def *d = hearth_scene_get_def(a->s);
    int u, v;
    plane_axes(a->axis, &u, &v);
    double W = d->hi[u] - d->lo[u], H = d->hi[v] - d->lo[v];
    double at = d->lo[a->axis] + a->at[a->axis] * (d->hi[a->axis] - d->lo[a->axis]);
    char title[256];
    if (d->dim == 2) snprintf(title, sizeof title, "%s  (2D, whole domain%s)", a->field[k], a->zoom > 1 ? ", zoomed" : "");
    else snprintf(title, sizeof title, "%s  slice %s = %.3g m%s", a->field[k], axis_name(a->axis), at,
                  a->zoom > 1 ? "  zoomed" : "");
    attron(A_BOLD);
    put(t->y, t->x, t->w, title);
    attroff(A_BOLD);
    if (a->zoom > 1) {
        char z[16];
        snprintf(z, sizeof z, "x%d", a->zoom);
        put(t->y, t->x + t->w - (int)strlen(z), (int)strlen(z), z);
    }
    /* fit the domain's aspect: half blocks make the pixels about square */
    double scale = fmin(r->w / W, 2.0 * r->h / H);
    int dw = (int)fmax(1, fmin(r->w, lround(W * scale)));
    int dh = (int)fmax(1, fmin(r->h, (lround(H * scale) + 1) / 2));
    int x0 = r->x + (r->w - dw) / 2, y0 = r->y + (r->h - dh) / 2;
    int fw = dw * a->zoom, fh = 2 * dh * a->zoom;
    long need = (long)fw * fh;
    if (need > a->slice_cap[k]) {
        double *ns = realloc(a->slice[k], sizeof(double) * (size_t)need);
        if (!ns) return;
        a->slice[k] = ns;
        a->slice_cap[k] = need;
        a->probed[k].valid = 0;
    }
    if ((long)dw * dh > a->cells_cap) {
        tui_cell *nc = realloc(a->cells, sizeof(tui_cell) * (size_t)dw * (size_t)dh);
        if (!nc) return;
        a->cells = nc;
        a->cells_cap = (long)dw * dh;
    }
    /* a redraw for a key while running reuses the last slice of an unchanged view: the probes are
     * the expensive part and their cost is held to the drawing budget */
    tui_probed *pr = &a->probed[k];
    int same = pr->valid && !strcmp(pr->field, a->field[k]) && pr->axis == a->axis && pr->zoom == a->zoom &&
               pr->fw == fw && pr->fh == fh && pr->at == at;
    if (fresh || !same) {
        hearth_error err;
        if (hearth_probe_slice(a->s, a->field[k], d->dim == 2 ? 2 : a->axis, at, fw, fh, a->slice[k], &err)) {
            pr->valid = 0;
            put(r->y, r->x, r->w, err.msg);
            return;
        }
        memcpy(pr->field, a->field[k], sizeof pr->field);
        pr->axis = a->axis, pr->zoom = a->zoom, pr->fw = fw, pr->fh = fh, pr->at = at, pr->valid = 1;
        tui_range(a->slice[k], need, &a->lo[k], &a->hi[k]);
    }
    double lo = a->lo[k], hi = a->hi[k];
    /* the browning index in the crust's own colours over its fixed 0..1, as the pictures draw it */
    const int browning = !strcmp(a->field[k], "browning");
    double fixed[2];
    if (browning && !isnan(lo) && hearth_picture_default_range(a->s, a->field[k], fixed)) lo = fixed[0], hi = fixed[1];
    tui_use_colormap(browning ? "browning" : NULL);
    /* the zoom window, centred on the cursor and kept inside the domain */
    double span = 1.0 / a->zoom;
    double cu = (a->cursor[u] - d->lo[u]) / W, cv = (a->cursor[v] - d->lo[v]) / H;
    double u0 = fmin(fmax(cu - span / 2, 0), 1 - span), v0 = fmin(fmax(cv - span / 2, 0), 1 - span);
    tui_draw_heatmap(a->slice[k], fw, fh, lo, hi, u0, u0 + span, v0, v0 + span, a->mode, dw, dh, a->cells);
    if (hearth_scene_collider_count(a->s) > 0) { /* colliders as grey where no material is */
        unsigned char *solid = malloc((size_t)dw * 2 * (size_t)dh);
        if (solid) {
            double x[3] = {0, 0, 0};
            if (d->dim == 3) x[a->axis] = at;
            for (int py = 0; py < 2 * dh; py++)
                for (int px = 0; px < dw; px++) {
                    x[u] = d->lo[u] + W * (u0 + span * (px + 0.5) / dw);
                    x[v] = d->lo[v] + H * (v0 + span * (1 - (py + 0.5) / (2 * dh)));
                    solid[(long)py * dw + px] = hearth_scene_collider_distance(a->s, x) < 0;
                }
            tui_draw_solids(a->cells, dw, dh, solid, a->mode);
            free(solid);
        }
    }
    tui_screen_cells(x0, y0, dw, dh, a->cells, a->mode);
    /* the cursor and the pinned probes */
    for (int p = -1; p < a->npins; p++) {
        const double *x = p < 0 ? a->cursor : a->pin[p];
        double fu = ((x[u] - d->lo[u]) / W - u0) / span, fv = ((x[v] - d->lo[v]) / H - v0) / span;
        if (fu < 0 || fu >= 1 || fv < 0 || fv >= 1) continue;
        int cx = x0 + (int)(fu * dw), cy = y0 + dh - 1 - (int)(fv * dh);
        attron(A_REVERSE | A_BOLD);
        mvaddch(cy, cx, p < 0 ? '+' : '1' + p);
        attroff(A_REVERSE | A_BOLD);
    }
    /* colour bar: min, gradient, max and unit */
    const char *unit = shown_unit(a->field[k]);
    char l[48], h[64];
    if (isnan(lo)) snprintf(l, sizeof l, "(no material)"), h[0] = '\0';
    else snprintf(l, sizeof l, "%.4g ", lo), snprintf(h, sizeof h, " %.4g %s", hi, unit ? unit : "");
    int lw = (int)strlen(l), hw = (int)strlen(h), gw = b->w - lw - hw;
    put(b->y, b->x, b->w, l);
    if (gw > 4 && !isnan(lo)) {
        tui_cell bar[512];
        if (gw > 512) gw = 512;
        tui_draw_colorbar(a->mode, gw, bar);
        tui_screen_cells(b->x + lw, b->y, gw, 1, bar, a->mode);
        put(b->y, b->x + lw + gw, hw, h);
    }
    tui_use_colormap(NULL);
}

static void draw_probes(tui_app *a, const tui_rect *r) {
    clear_rect(r->y, r->x, r->w, r->h);
    if (!a->s) return;
    const hearth_scene_def *d = hearth_scene_get_def(a->s);
    char line[256];
    if (d->dim == 2) snprintf(line, sizeof line, "probe at (%.3g, %.3g) m", a->cursor[0], a->cursor[1]);
    else snprintf(line, sizeof line, "probe at (%.3g, %.3g, %.3g) m", a->cursor[0], a->cursor[1], a->cursor[2]);
    attron(A_BOLD);
    put(r->y, r->x, r->w, line);
    attroff(A_BOLD);
    int row = 1, spark = r->w - 38;
    if (spark > TUI_HIST) spark = TUI_HIST;
    uint32_t cps[TUI_HIST];
    int pin_rows = a->npins ? a->npins + 1 : 0;
    /* every live field: when they do not all fit, a page of them and a last
     * row saying which (PgUp / PgDn, or < / >, turn the pages) */
    int rows_for_fields = r->h - pin_rows - row, shown = a->nfp, first = 0;
    if (shown > rows_for_fields) {
        shown = rows_for_fields - 1 > 0 ? rows_for_fields - 1 : 0;
        first = a->probe_first;
        if (first > a->nfp - shown) first = a->nfp - shown;
        if (first < 0) first = 0;
    }
    a->probe_first = first, a->probe_page = shown;
    for (int i = first; i < first + shown; i++, row++) {
        const tui_field_probe *p = &a->fp[i];
        const char *unit = shown_unit(p->name);
        /* 15 columns: water_pressure, gas_pressure and the like whole */
        if (isnan(p->value)) snprintf(line, sizeof line, "%-15.15s %10s %-7.7s", p->name, "-", unit ? unit : "");
        else snprintf(line, sizeof line, "%-15.15s %10.4g %-7.7s", p->name, p->value, unit ? unit : "");
        put(r->y + row, r->x, r->w, line);
        if (spark > 4) {
            tui_sparkline(p->hist, p->n, spark, a->mode < TUI_256, cps);
            put_codes(r->y + row, r->x + 36, cps, spark);
        }
    }
    if (shown < a->nfp && row < r->h - pin_rows) {
        if (shown > 0)
            snprintf(line, sizeof line, "fields %d-%d of %d  PgUp/PgDn or </> scroll", first + 1, first + shown, a->nfp);
        else snprintf(line, sizeof line, "%d fields: the panel is too short to list them", a->nfp);
        put(r->y + row++, r->x, r->w, line);
    }
    if (a->npins) {
        attron(A_BOLD);
        put(r->y + row++, r->x, r->w, "pinned probes (p pins the cursor; up to 4)");
        attroff(A_BOLD);
    }
    for (int k = 0; k < a->npins && row < r->h; k++, row++) {
        const tui_field_probe *p = &a->pin_probe[k];
        snprintf(line, sizeof line, "%d %-11.11s %10.4g (%.2g,%.2g)", k + 1, p->name, p->value, a->pin[k][0],
                 a->pin[k][1]);
        put(r->y + row, r->x, r->w, line);
        if (spark > 4) {
            tui_sparkline(p->hist, p->n, spark, a->mode < TUI_256, cps);
            put_codes(r->y + row, r->x + 36, cps, spark);
        }
    }
}

static void draw_log(tui_app *a, const tui_rect *r) {
    clear_rect(r->y, r->x, r->w, r->h);
    mvvline(r->y, r->x - 1, '|', r->h);
    /* newest at the bottom; long lines wrap */
    int y = r->y + r->h - 1;
    for (int i = 0; y >= r->y; i++) {
        const char *l = tui_log_get(&a->log, i);
        if (!l) break;
        int len = (int)strlen(l), nseg = len ? (len + r->w - 1) / r->w : 1;
        int err = !strncmp(l, "error", 5) || !strncmp(l, "the stability guard", 19);
        if (err) attron(A_BOLD);
        for (int sgm = nseg - 1; sgm >= 0 && y >= r->y; sgm--, y--) put(y, r->x, r->w, l + sgm * r->w);
        if (err) attroff(A_BOLD);
    }
}

static void draw_prompt(tui_app *a, const tui_rect *r) {
    clear_rect(r->y, 0, r->w, 1);
    if (a->ask_quit) {
        attron(A_REVERSE);
        put(r->y, 0, r->w, " The run changed since the last checkpoint. Quit? y quits, c saves a checkpoint and quits, "
                           "any other key stays ");
        attroff(A_REVERSE);
        curs_set(0);
        return;
    }
    if (!a->prompt_focus) {
        put(r->y, 0, r->w, tui_key_bar(r->w));
        curs_set(0);
        return;
    }
    const char *pre = a->chunk[0] ? ">> " : "lua> ";
    int pl = (int)strlen(pre), avail = r->w - pl - 1;
    int off = a->prompt.cur > avail ? a->prompt.cur - avail : 0;
    attron(A_BOLD);
    put(r->y, 0, pl, pre);
    attroff(A_BOLD);
    put(r->y, pl, avail, a->prompt.buf + off);
    move(r->y, pl + a->prompt.cur - off);
    curs_set(1);
}

static void draw_help(int cols, int rows) {
    static const char *lines[] = {
        "hearth dashboard: keys",
        "",
        "Space      run or pause          n      one step",
        "f / F      next field, left / right view",
        "[ / ]      move the slice plane   x y z  slice axis (3D)",
        "arrows     move the probe cursor  p      pin a probe (up to 4)",
        "PgUp/PgDn  scroll the probe list (also < and >)",
        "+ / -      zoom in / out at the cursor",
        "s          save both views as PNG c      write a checkpoint",
        ": or Tab   Lua prompt (Esc leaves it; Tab completes there)",
        "q          quit (asks when the run is not saved)",
        "?          this help (any key closes it)",
        "",
        "At the prompt: s is the scene, h the hearth module. Try",
        "  s:oven(200)   s:set_dt(0.4)   s:run{until_t = 2}   print(s:stats().t)",
        "Left/Right Home/End Ctrl-W Ctrl-U Ctrl-K edit; Up/Down history.",
    };
    int n = (int)(sizeof lines / sizeof *lines), w = 72, h = n + 2;
    int x = (cols - w) / 2, y = (rows - h) / 2;
    if (x < 0) x = 0;
    if (y < 0) y = 0;
    clear_rect(y, x, w, h);
    attron(A_REVERSE);
    mvhline(y, x, ' ', w);
    mvhline(y + h - 1, x, ' ', w);
    mvvline(y, x, ' ', h);
    mvvline(y, x + w - 1, ' ', h);
    attroff(A_REVERSE);
    for (int i = 0; i < n; i++) put(y + 1 + i, x + 2, w - 4, lines[i]);
}

void tui_view_draw(tui_app *a, int fresh) {
    int cols = COLS, rows = LINES;
    tui_layout L;
    erase();
    if (!tui_layout_compute(cols, rows, &L)) {
        char m1[128], m2[128];
        snprintf(m1, sizeof m1, "terminal too small: %dx%d", cols, rows);
        snprintf(m2, sizeof m2, "the dashboard needs at least %dx%d; q quits", TUI_MIN_COLS, TUI_MIN_ROWS);
        int y = rows / 2 - 1;
        put(y < 0 ? 0 : y, 0, cols, m1);
        if (y + 1 < rows) put(y + 1, 0, cols, m2);
        curs_set(0);
        refresh();
        return;
    }
    draw_status(a, &L.status);
    for (int k = 0; k < 2; k++) draw_view(a, k, &L, fresh);
    draw_probes(a, &L.probes);
    draw_log(a, &L.log);
    if (a->help) draw_help(cols, rows);
    draw_prompt(a, &L.prompt);
    refresh();
}

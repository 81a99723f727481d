/* cmd_rheometer.c: `hearth rheometer`, the homogeneous virtual rheometer
 * (core/sim/lab/rheometer.c) on a plugin material, a library sauce or a blend of
 * library sauces; and the log-log flow-curve plot that `hearth fit` shares. */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "commands.h"
#include "hearth/hearth.h"
#include "hearth/lab.h"
#include "hearth/plot.h"

/* Also in commands.h once it lists them; repeated so this file stands alone. */

/* Where the sauce library lives: --library, else the assets folder the build
 * names (HEARTH_ASSETS_DIR, or HEARTH_SOURCE_ASSETS), else ./assets. */
#ifndef HEARTH_ASSETS_DIR
#ifdef HEARTH_SOURCE_ASSETS
#define HEARTH_ASSETS_DIR HEARTH_SOURCE_ASSETS
#else
#define HEARTH_ASSETS_DIR "assets"
#endif
#endif

#define MAX_MIX 8
#define MAX_RATES 1000
#define SAUCE_PLUGIN "von_mises_sauce"

const char *app_assets_dir(void) {
    const char *env = getenv("HEARTH_ASSETS_DIR");
    return env && *env ? env : HEARTH_ASSETS_DIR;
}

const char *app_sauce_library_path(const char *override) {
    static char buf[4096];
    if (override) return override;
    snprintf(buf, sizeof buf, "%s/sauces.csv", app_assets_dir());
    return buf;
}


/* ---- the plot ------------------------------------------------------------- */

/* A log-log plot of n data points (x, y) as dots and, when cx is not NULL,
 * a curve through its cn samples (cx, cy) as a line under them; PNG written
 * atomically (<hearth/plot.h>). Returns 0 or -1 (err). */
int app_flow_plot(const char *path, const char *title, const double *x, const double *y, int n, const char *data_label,
                  const double *cx, const double *cy, int cn, const char *curve_label, hearth_error *err) {
    hearth_plot_def d = hearth_default_plot_def();
    d.title = title;
    d.x_label = "shear rate [1/s]";
    d.y_label = "stress [Pa]";
    hearth_plot *p = hearth_plot_create(&d, err);
    if (!p) return -1;
    hearth_plot_series_def data = hearth_default_plot_series_def();
    data.n = n, data.x = x, data.y = y, data.label = data_label;
    hearth_plot_color(0, data.color);
    int rc = hearth_plot_add_series(p, &data, err) < 0 ? -1 : 0;
    if (!rc && cx) {
        hearth_plot_series_def curve = hearth_default_plot_series_def();
        curve.n = cn, curve.x = cx, curve.y = cy, curve.label = curve_label;
        curve.marker = HEARTH_MARKER_NONE, curve.line_width = 2, curve.behind = 1;
        hearth_plot_color(1, curve.color);
        rc = hearth_plot_add_series(p, &curve, err) < 0 ? -1 : 0;
    }
    if (!rc) rc = hearth_plot_write_png(p, path, err) ? -1 : 0;
    hearth_plot_free(p);
    return rc;
}

/* ---- the command ------------------------------------------------------------ */

static void usage(FILE *f) {
    fprintf(f,
            "usage: hearth rheometer MATERIAL [--mix sauce.a:0.5,sauce.b:0.5] [--rates MIN:MAX:COUNT]\n"
            "                        [--out DIR] [--json] [--dt DT] [--library FILE] [--mode homogeneous|mpm]\n"
            "Drives the material in simple shear at each rate until the shear stress is steady and\n"
            "prints the flow curve. It is saved as DIR/<material>.csv (shear_rate_1_per_s, stress_Pa,\n"
            "hb_stress_Pa when the material has Herschel-Bulkley parameters, measured_rate_1_per_s in\n"
            "--mode mpm) and drawn on log-log axes\n"
            "with the analytic curve as DIR/<material>.png.\n"
            "  MATERIAL        sauce.<name> from the sauce library (assets/sauces.csv, Nagasawa et al.\n"
            "                  2019 Table 1) with the %s plugin, or a plugin name with its defaults\n"
            "  --mix LIST      blend library sauces with the plugin's blend callback (eq. 28-31);\n"
            "                  ratios in (0, 1] summing to 1; MATERIAL is then omitted or a plugin name\n"
            "  --rates A:B:N   N rates spaced evenly in log from A to B (1/s); default 1:200:12\n"
            "  --out DIR       output folder (default ./hearth-out/rheometer)\n"
            "  --json          print {\"shear_rate\":[...],\"stress\":[...]} and nothing else\n"
            "  --dt DT         fixed step in seconds (default: adaptive, from the material's stiffness)\n"
            "  --library FILE  the sauce library CSV (default %s)\n"
            "  --mode MODE     homogeneous (default): one material point, the plugin called directly;\n"
            "                  mpm: the full MPM solver, a 2D layer 1 cm thick and 4 cm long between two\n"
            "                  sticky plates moving at +-rate x 0.5 cm/s, 16 cells across, started with\n"
            "                  the shear profile; stress = mean particle sigma_xy over the middle half.\n"
            "                  The CSV then has a measured_rate column (the slope of v_x across the gap).\n"
            "                  A few seconds per rate.\n",
            SAUCE_PLUGIN, app_sauce_library_path(NULL));
}

static int parse_double(const char *what, const char *text, double *v) {
    char *end = NULL;
    errno = 0;
    *v = text ? strtod(text, &end) : NAN;
    if (!text || !*text || *end || errno || !isfinite(*v)) {
        fprintf(stderr, "hearth rheometer: %s needs a number, got '%s'\n", what, text ? text : "");
        return -1;
    }
    return 0;
}

static int parse_rates(const char *s, double *lo, double *hi, long *count) {
    char buf[256];
    snprintf(buf, sizeof buf, "%s", s);
    char *a = buf, *b = strchr(a, ':'), *c = b ? strchr(b + 1, ':') : NULL;
    if (!b || !c) {
        fprintf(stderr, "hearth rheometer: --rates needs MIN:MAX:COUNT, e.g. 1:200:12, got '%s'\n", s);
        return -1;
    }
    *b++ = '\0';
    *c++ = '\0';
    if (parse_double("--rates MIN", a, lo) || parse_double("--rates MAX", b, hi)) return -1;
    if ((*count = app_parse_int("rheometer", "--rates COUNT", c, 1, MAX_RATES)) < 0) return -1;
    if (!(*lo > 0) || !(*hi >= *lo)) {
        fprintf(stderr, "hearth rheometer: --rates needs 0 < MIN <= MAX (1/s), got %g:%g\n", *lo, *hi);
        return -1;
    }
    if (*count == 1 && *hi != *lo) {
        fprintf(stderr, "hearth rheometer: --rates with COUNT 1 needs MIN = MAX, got %g:%g\n", *lo, *hi);
        return -1;
    }
    return 0;
}

typedef struct mix_item {
    char name[HEARTH_SAUCE_NAME_MAX + 8];
    double w;
} mix_item;

static int parse_mix(const char *s, mix_item *items, int *n) {
    char buf[2048];
    if (snprintf(buf, sizeof buf, "%s", s) >= (int)sizeof buf) {
        fprintf(stderr, "hearth rheometer: --mix list is too long\n");
        return -1;
    }
    *n = 0;
    double total = 0;
    for (char *tok = strtok(buf, ","); tok; tok = strtok(NULL, ",")) {
        if (*n == MAX_MIX) {
            fprintf(stderr, "hearth rheometer: --mix takes at most %d constituents\n", MAX_MIX);
            return -1;
        }
        char *colon = strrchr(tok, ':');
        if (!colon) {
            fprintf(stderr, "hearth rheometer: --mix item '%s' needs a ratio, e.g. sauce.mayo:0.5\n", tok);
            return -1;
        }
        *colon = '\0';
        mix_item *it = &items[(*n)++];
        if (snprintf(it->name, sizeof it->name, "%s", tok) >= (int)sizeof it->name) {
            fprintf(stderr, "hearth rheometer: --mix: sauce name '%s' is too long\n", tok);
            return -1;
        }
        if (parse_double("a --mix ratio", colon + 1, &it->w)) return -1;
        if (!(it->w > 0 && it->w <= 1)) {
            fprintf(stderr, "hearth rheometer: --mix ratio of %s must be in (0, 1], got %g\n", it->name, it->w);
            return -1;
        }
        total += it->w;
    }
    if (*n == 0) {
        fprintf(stderr, "hearth rheometer: --mix needs at least one sauce.name:ratio\n");
        return -1;
    }
    if (fabs(total - 1) > 1e-6) {
        fprintf(stderr, "hearth rheometer: --mix ratios sum to %g; they must sum to 1\n", total);
        return -1;
    }
    for (int i = 0; i < *n; i++) items[i].w /= total;
    return 0;
}

static int pindex(const hearth_material *m, const char *name) {
    for (int i = 0; i < m->nparams; i++)
        if (m->params[i].name && !strcmp(m->params[i].name, name)) return i;
    return -1;
}

static int write_csv(const char *path, const double *x, const double *y, const double *hb, const double *measured, int n,
                     hearth_error *err) {
    hearth_atomic_file *af = hearth_atomic_file_open(path, err);
    if (!af) return -1;
    /* each column says its unit in its name, as every CSV hearth writes (#18, helper userfix7); hearth fit and
     * hearth_flow_curve_read take these names and the bare ones */
    hearth_atomic_file_printf(af, "shear_rate_1_per_s,stress_Pa%s%s\n", hb ? ",hb_stress_Pa" : "",
                              measured ? ",measured_rate_1_per_s" : "");
    for (int i = 0; i < n; i++) {
        hearth_atomic_file_printf(af, "%.10g,%.10g", x[i], y[i]);
        if (hb) hearth_atomic_file_printf(af, ",%.10g", hb[i]);
        if (measured) hearth_atomic_file_printf(af, ",%.10g", measured[i]);
        hearth_atomic_file_printf(af, "\n");
    }
    return hearth_atomic_file_commit(af, err) ? -1 : 0;
}

int cmd_rheometer(int argc, char **argv) {
    const char *material = NULL, *mix = NULL, *rates_s = "1:200:12", *out = "hearth-out/rheometer", *library = NULL;
    int json = 0, mpm = 0;
    double dt = 0;
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        if (!strcmp(a, "--help") || !strcmp(a, "-h")) {
            usage(stdout);
            return 0;
        }
        if (!strcmp(a, "--json")) {
            json = 1;
            continue;
        }
        if (a[0] == '-' && a[1] == '-') {
            if (i + 1 >= argc) {
                fprintf(stderr, "hearth rheometer: %s needs a value (see --help)\n", a);
                return 2;
            }
            const char *v = argv[++i];
            if (!strcmp(a, "--mix")) mix = v;
            else if (!strcmp(a, "--rates")) rates_s = v;
            else if (!strcmp(a, "--out")) out = v;
            else if (!strcmp(a, "--library")) library = v;
            else if (!strcmp(a, "--mode")) {
                if (!strcmp(v, "mpm")) mpm = 1;
                else if (!strcmp(v, "homogeneous")) mpm = 0;
                else {
                    fprintf(stderr, "hearth rheometer: --mode %s; valid: homogeneous, mpm\n", v);
                    return 2;
                }
            }
            else if (!strcmp(a, "--dt")) {
                if (parse_double("--dt", v, &dt)) return 2;
                if (!(dt > 0)) {
                    fprintf(stderr, "hearth rheometer: --dt needs a step > 0 s, got %g\n", dt);
                    return 2;
                }
            } else {
                fprintf(stderr, "hearth rheometer: unknown option '%s' (see --help)\n", a);
                return 2;
            }
            continue;
        }
        if (material) {
            fprintf(stderr, "hearth rheometer: one MATERIAL only, got '%s' and '%s'\n", material, a);
            return 2;
        }
        material = a;
    }
    if (!material && !mix) {
        fprintf(stderr, "hearth rheometer: give a MATERIAL (sauce.<name> or a plugin name) or --mix\n");
        usage(stderr);
        return 2;
    }
    if (material && mix && !strncmp(material, "sauce.", 6)) {
        fprintf(stderr, "hearth rheometer: give either a sauce (%s) or --mix, not both; with --mix, MATERIAL names the plugin\n",
                material);
        return 2;
    }
    double lo, hi;
    long count;
    if (parse_rates(rates_s, &lo, &hi, &count)) return 2;
    mix_item items[MAX_MIX];
    int nmix = 0;
    if (mix && parse_mix(mix, items, &nmix)) return 2;

    hearth_error err;
    int is_sauce = material && !strncmp(material, "sauce.", 6);
    const char *plugin = is_sauce || !material ? SAUCE_PLUGIN : material;
    const hearth_plugin *pl = hearth_plugin_load(plugin, &err);
    if (!pl) {
        fprintf(stderr, "hearth rheometer: %s\n", err.msg);
        return 1;
    }
    const hearth_material *m = hearth_plugin_material(pl);
    if (m->nparams > 64) {
        fprintf(stderr, "hearth rheometer: plugin '%s' has %d parameters, more than this command handles (64)\n", m->name,
                m->nparams);
        return 1;
    }
    double p[64];
    for (int i = 0; i < m->nparams; i++) p[i] = m->params[i].def;
    hearth_sauce_library lib = {0};
    if (is_sauce || mix) {
        const char *lp = app_sauce_library_path(library);
        if (hearth_sauce_library_load(lp, &lib, &err)) {
            fprintf(stderr, "hearth rheometer: %s%s\n", err.msg, library ? "" : " (use --library FILE)");
            return 1;
        }
    }
    int rc = 1;
    char label[512] = "";
    if (is_sauce) {
        const hearth_sauce *s = hearth_sauce_lookup(&lib, material, &err);
        if (!s || hearth_sauce_params(m, s, p, &err)) {
            fprintf(stderr, "hearth rheometer: %s\n", err.msg);
            goto done;
        }
        snprintf(label, sizeof label, "%s, %s", material, s->label);
    } else if (mix) {
        if (!m->blend) {
            fprintf(stderr, "hearth rheometer: plugin '%s' has no blend callback, so it cannot mix\n", m->name);
            goto done;
        }
        double sets[MAX_MIX][64], alpha[MAX_MIX];
        const double *pk[MAX_MIX];
        size_t used = 0;
        for (int k = 0; k < nmix; k++) {
            const hearth_sauce *s = hearth_sauce_lookup(&lib, items[k].name, &err);
            if (!s || hearth_sauce_params(m, s, sets[k], &err)) {
                fprintf(stderr, "hearth rheometer: --mix: %s\n", err.msg);
                goto done;
            }
            pk[k] = sets[k];
            alpha[k] = items[k].w;
            int w = snprintf(label + used, sizeof label - used, "%s%s:%g", k ? " + " : "mix ", s->name, items[k].w);
            if (w > 0 && used + (size_t)w < sizeof label) used += (size_t)w;
        }
        hearth_plugin_call_enter(m, "blend");
        int bc = m->blend(nmix, alpha, pk, p);
        hearth_plugin_call_leave();
        if (bc) {
            const char *t = m->describe_error ? m->describe_error(bc) : NULL;
            fprintf(stderr, "hearth rheometer: --mix: the blend returned code %d (%s)\n", bc, t ? t : "no description");
            goto done;
        }
        for (int i = 0; i < m->nparams; i++)
            if (!(p[i] >= m->params[i].min && p[i] <= m->params[i].max)) {
                fprintf(stderr, "hearth rheometer: --mix: blended %s = %g is outside [%g, %g]\n", m->params[i].name, p[i],
                        m->params[i].min, m->params[i].max);
                goto done;
            }
    } else {
        snprintf(label, sizeof label, "%s (defaults)", m->name);
    }

    static double rates[MAX_RATES], stress[MAX_RATES], hbv[MAX_RATES], measured[MAX_RATES];
    hearth_log_spaced(lo, hi, (int)count, rates);
    int isy = pindex(m, "sigma_y"), ieta = pindex(m, "eta"), ih = pindex(m, "h");
    int has_hb = isy >= 0 && ieta >= 0 && ih >= 0;
    hearth_rheometer_opts o = hearth_rheometer_default_opts();
    o.dt = dt;
    if (mpm && dt > 0) {
        fprintf(stderr, "hearth rheometer: --dt applies to the homogeneous mode; the MPM cell steps at its CFL limit\n");
        goto done;
    }
    for (int i = 0; i < count; i++) {
        if (mpm) {
            hearth_rheometer_mpm_result r;
            if (hearth_rheometer_mpm_steady(plugin, p, rates[i], NULL, &r, &err)) {
                fprintf(stderr, "hearth rheometer: %s\n", err.msg);
                goto done;
            }
            stress[i] = r.stress;
            measured[i] = r.rate;
            if (has_hb) hbv[i] = hearth_hb_stress(p[isy], p[ieta], p[ih], rates[i]);
            continue;
        }
        hearth_rheometer_result r;
        if (hearth_rheometer_steady(m, p, rates[i], &o, &r, &err)) {
            fprintf(stderr, "hearth rheometer: %s\n", err.msg);
            goto done;
        }
        stress[i] = r.stress;
        if (has_hb) hbv[i] = hearth_hb_stress(p[isy], p[ieta], p[ih], rates[i]);
    }

    /* files */
    char slug[256], csv[4400], png[4400];
    if (is_sauce || !mix) snprintf(slug, sizeof slug, "%s", material);
    else {
        size_t u = (size_t)snprintf(slug, sizeof slug, "mix");
        for (int k = 0; k < nmix && u < sizeof slug; k++) {
            const char *nm = !strncmp(items[k].name, "sauce.", 6) ? items[k].name + 6 : items[k].name;
            u += (size_t)snprintf(slug + u, sizeof slug - u, "-%s_%g", nm, items[k].w);
        }
    }
    if (hearth_mkdir_p(out, NULL)) {
        fprintf(stderr, "hearth rheometer: cannot create the output folder %s: %s\n", out, strerror(errno));
        goto done;
    }
    snprintf(csv, sizeof csv, "%s/%s.csv", out, slug);
    snprintf(png, sizeof png, "%s/%s.png", out, slug);
    if (write_csv(csv, rates, stress, has_hb ? hbv : NULL, mpm ? measured : NULL, (int)count, &err)) {
        fprintf(stderr, "hearth rheometer: %s\n", err.msg);
        goto done;
    }
    /* the analytic curve, sampled densely for the plot */
    enum { NC = 200 };
    double cx[NC], cy[NC];
    char clabel[256] = "";
    if (has_hb) {
        hearth_log_spaced(lo, hi > lo ? hi : lo * 10, NC, cx);
        for (int i = 0; i < NC; i++) cy[i] = hearth_hb_stress(p[isy], p[ieta], p[ih], cx[i]);
        snprintf(clabel, sizeof clabel, "Herschel-Bulkley: sigma_y %.4g Pa, eta %.4g Pa s^h, h %.4g", p[isy], p[ieta], p[ih]);
    }
    char title[600];
    snprintf(title, sizeof title, "flow curve: %s", label);
    if (app_flow_plot(png, title, rates, stress, (int)count, mpm ? "virtual rheometer (MPM shear cell)" : "virtual rheometer (homogeneous)", has_hb ? cx : NULL,
                      has_hb ? cy : NULL, NC, clabel, &err)) {
        fprintf(stderr, "hearth rheometer: %s\n", err.msg);
        goto done;
    }

    if (json) {
        printf("{\"shear_rate\":[");
        for (int i = 0; i < count; i++) printf("%s%.10g", i ? "," : "", rates[i]);
        printf("],\"stress\":[");
        for (int i = 0; i < count; i++) printf("%s%.10g", i ? "," : "", stress[i]);
        printf("]}\n");
    } else {
        printf("hearth rheometer: %s\n  %s:", label, m->name);
        for (int i = 0; i < m->nparams; i++)
            printf(" %s %g%s%s%s", m->params[i].name, p[i], strcmp(m->params[i].unit, "1") ? " " : "",
                   strcmp(m->params[i].unit, "1") ? m->params[i].unit : "", i + 1 < m->nparams ? "," : "");
        if (mpm)
            printf("\n  MPM shear cell (2D layer between sticky plates), steady when the mean sigma_xy changes < %g\n\n",
                   hearth_rheometer_mpm_default_opts().rel_tol);
        else
            printf("\n  homogeneous simple shear, %s dt, steady when sigma_xy changes < %g (relative)\n\n",
                   dt > 0 ? "fixed" : "adaptive", o.rel_tol);
        if (has_hb) printf("  %16s  %16s  %22s  %10s\n", "shear_rate [1/s]", "stress [Pa]", "Herschel-Bulkley [Pa]", "difference");
        else printf("  %16s  %16s\n", "shear_rate [1/s]", "stress [Pa]");
        for (int i = 0; i < count; i++) {
            if (has_hb)
                printf("  %16.6g  %16.6g  %22.6g  %9.3f%%", rates[i], stress[i], hbv[i], 100 * (stress[i] - hbv[i]) / hbv[i]);
            else printf("  %16.6g  %16.6g", rates[i], stress[i]);
            if (mpm) printf("  (measured rate %.5g 1/s)", measured[i]);
            printf("\n");
        }
        printf("\nwrote %s and %s\n", csv, png);
    }
    rc = 0;
done:
    hearth_sauce_library_free(&lib);
    return rc;
}

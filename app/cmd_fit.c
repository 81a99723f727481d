/* cmd_fit.c: `hearth fit FLOWCURVE.csv`, the Herschel-Bulkley fit of
 * Nagasawa et al. 2019 (eq. 1 with the relative-error objective eq. 2). */
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "commands.h"
#include "hearth/hearth.h"
#include "hearth/lab.h"

/* Also in commands.h once it lists them; repeated so this file stands alone. */

static void usage(FILE *f) {
    fprintf(f, "usage: hearth fit FLOWCURVE.csv [--json] [--out DIR]\n"
               "Fits the Herschel-Bulkley law sigma = sigma_y + eta rate^h to a flow curve by the sum of\n"
               "squared relative residuals (Nagasawa et al. 2019, eq. 2) and prints the parameters and\n"
               "the residual of every point; draws data and fit on log-log axes as DIR/<name>_fit.png.\n"
               "The CSV needs a header row naming the columns shear_rate_1_per_s and stress_Pa (or the\n"
               "bare shear_rate and stress: 1/s and Pa); other columns are ignored (a `hearth rheometer`\n"
               "CSV fits as it is), lines starting with # are comments. At least 3 rows, every rate and\n"
               "stress a number > 0.\n"
               "  --json     print {\"sigma_y\":..., \"eta\":..., \"h\":..., \"rel_error\":...} and nothing else\n"
               "             (rel_error: root-mean-square relative residual)\n"
               "  --out DIR  output folder for the PNG (default ./hearth-out/fit)\n");
}

int cmd_fit(int argc, char **argv) {
    const char *csv = NULL, *out = "hearth-out/fit";
    int json = 0;
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
        if (!strcmp(a, "--out")) {
            if (i + 1 >= argc) {
                fprintf(stderr, "hearth fit: --out needs a folder (see --help)\n");
                return 2;
            }
            out = argv[++i];
            continue;
        }
        if (a[0] == '-' && a[1] == '-') {
            fprintf(stderr, "hearth fit: unknown option '%s' (see --help)\n", a);
            return 2;
        }
        if (csv) {
            fprintf(stderr, "hearth fit: one FLOWCURVE.csv only, got '%s' and '%s'\n", csv, a);
            return 2;
        }
        csv = a;
    }
    if (!csv) {
        usage(stderr);
        return 2;
    }
    hearth_error err;
    hearth_flow_curve c;
    if (hearth_flow_curve_read(csv, &c, &err)) {
        fprintf(stderr, "hearth fit: %s\n", err.msg);
        return 1;
    }
    hearth_hb_fit_result fr;
    if (hearth_hb_fit(c.rate, c.stress, c.n, &fr, &err)) {
        fprintf(stderr, "hearth fit: %s: %s\n", csv, err.msg);
        hearth_flow_curve_free(&c);
        return 1;
    }
    /* the picture: data and the fitted curve over the data's range */
    double lo = INFINITY, hi = 0;
    for (int i = 0; i < c.n; i++) lo = fmin(lo, c.rate[i]), hi = fmax(hi, c.rate[i]);
    enum { NC = 200 };
    double cx[NC], cy[NC];
    hearth_log_spaced(lo, hi > lo ? hi : lo * 10, NC, cx);
    for (int i = 0; i < NC; i++) cy[i] = hearth_hb_stress(fr.sigma_y, fr.eta, fr.h, cx[i]);
    const char *base = strrchr(csv, '/');
    base = base ? base + 1 : csv;
    char name[256], png[4400], title[400], clabel[256];
    snprintf(name, sizeof name, "%s", base);
    size_t nl = strlen(name);
    if (nl > 4 && !strcmp(name + nl - 4, ".csv")) name[nl - 4] = '\0';
    snprintf(png, sizeof png, "%s/%s_fit.png", out, name);
    snprintf(title, sizeof title, "Herschel-Bulkley fit: %s", base);
    snprintf(clabel, sizeof clabel, "fit: sigma_y %.4g Pa, eta %.4g Pa s^h, h %.4g (rms rel. error %.2g%%)", fr.sigma_y,
             fr.eta, fr.h, 100 * fr.rel_error);
    int rc = 0;
    if (hearth_mkdir_p(out, NULL)) {
        fprintf(stderr, "hearth fit: cannot create the output folder %s: %s\n", out, strerror(errno));
        rc = 1;
    } else if (app_flow_plot(png, title, c.rate, c.stress, c.n, "data", cx, cy, NC, clabel, &err)) {
        fprintf(stderr, "hearth fit: %s\n", err.msg);
        rc = 1;
    }
    if (rc == 0) {
        if (json) {
            printf("{\"sigma_y\":%.10g,\"eta\":%.10g,\"h\":%.10g,\"rel_error\":%.10g}\n", fr.sigma_y, fr.eta, fr.h,
                   fr.rel_error);
        } else {
            printf("hearth fit: %s, %d points, sigma = sigma_y + eta rate^h by relative least squares (eq. 2)\n\n", csv,
                   c.n);
            printf("  sigma_y    %.6g Pa\n  eta        %.6g Pa s^h\n  h          %.6g\n", fr.sigma_y, fr.eta, fr.h);
            printf("  rel_error  %.4g%% (root-mean-square relative residual; eq. 2 objective %.4g)\n\n",
                   100 * fr.rel_error, fr.objective);
            printf("  %16s  %14s  %14s  %10s\n", "shear_rate [1/s]", "stress [Pa]", "fit [Pa]", "residual");
            for (int i = 0; i < c.n; i++) {
                double f = hearth_hb_stress(fr.sigma_y, fr.eta, fr.h, c.rate[i]);
                printf("  %16.6g  %14.6g  %14.6g  %9.3f%%\n", c.rate[i], c.stress[i], f, 100 * (f - c.stress[i]) / c.stress[i]);
            }
            if (fr.h <= 0.0201 || fr.h >= 2.999)
                printf("\n  note: h is at the edge of the searched range [0.02, 3]; the data may not follow eq. 1\n");
            printf("\nwrote %s\n", png);
        }
    }
    hearth_flow_curve_free(&c);
    return rc;
}

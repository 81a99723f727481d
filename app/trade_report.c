/* trade_report.c: what `hearth trade` writes once the ladder's runs are in:
 * trade.csv (one row per run), trade.png (error against wall time on log-log
 * axes, the Pareto front ringed) and the table on stdout. The same for every
 * launcher and for --collect, so a ladder run through Slurm or mpirun reads
 * exactly like one run on the local cores. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "hearth/hearth.h"
#include "hearth/plot.h"
#include "trade.h"

int trade_write_csv(const trade *T, const char *path) {
    hearth_error err;
    hearth_atomic_file *af = hearth_atomic_file_open(path, &err);
    if (!af) {
        fprintf(stderr, "hearth trade: %s\n", err.msg);
        return -1;
    }
    hearth_atomic_file_printf(af, "run");
    for (int j = 0; j < T->nk; j++) hearth_atomic_file_printf(af, ",%s", T->k[j].name);
    hearth_atomic_file_printf(af, ",status,wall_s,steps,peak_mb,%s,reference,error,rel_error,order,pareto,note\n", T->metric);
    for (int i = 0; i < T->nr; i++) {
        const trade_run *r = &T->r[i];
        hearth_atomic_file_printf(af, "%d", i);
        for (int j = 0; j < T->nk; j++) hearth_atomic_file_printf(af, ",%s", T->k[j].v[r->vi[j]]);
        hearth_atomic_file_printf(af, ",%s,%.3f,%ld,%.1f,%.10g,%.10g,%.4g,%.4g,%.3f,%d,", trade_state_name[r->st], r->wall, r->steps, r->peak_mb,
                r->metric, r->ref, r->err, r->rel, r->order, r->pareto);
        const char *note = r->is_ref ? "reference (finest run)" : r->msg;
        hearth_atomic_file_write(af, "\"", 1);
        for (const char *p = note; *p; p++) hearth_atomic_file_write(af, *p == '"' ? "'" : p, 1);
        hearth_atomic_file_write(af, "\"\n", 2);
    }
    if (hearth_atomic_file_commit(af, &err)) {
        fprintf(stderr, "hearth trade: %s\n", err.msg);
        return -1;
    }
    return 0;
}

/* Error against wall time on log-log axes (<hearth/plot.h>): one colour per
 * series, each run joined to its next finer one and labelled with its
 * refinement value, the Pareto front joined and ringed under the runs. */
int trade_write_plot(const trade *T, const char *path) {
    hearth_error err;
    char title[600];
    const char *base = strrchr(T->scene, '/');
    snprintf(title, sizeof title, "%s: error in %s against %s", base ? base + 1 : T->scene, T->metric,
             T->analytic[0] ? "the analytic value" : "each series' finest run");
    hearth_plot_def d = hearth_default_plot_def();
    d.width = 860, d.height = 580;
    d.title = title, d.x_label = "wall time per run [s]", d.y_label = "relative error";
    d.legend = HEARTH_LEGEND_BOTTOM_LEFT;
    hearth_plot *p = hearth_plot_create(&d, &err);
    double *x = malloc(sizeof(double) * (size_t)T->nr), *y = malloc(sizeof(double) * (size_t)T->nr);
    const char **labels = malloc(sizeof(char *) * (size_t)T->nr);
    int *order = malloc(sizeof(int) * (size_t)T->nr), rc = 0;
    if (!p || !x || !y || !labels || !order) {
        fprintf(stderr, "hearth trade: %s\n", p ? "out of memory for the plot" : err.msg);
        rc = -1;
        goto done;
    }
    /* the runs a log-log plot can show */
#define SHOWN(r) ((r)->st == RS_OK && (r)->rel > 0)
    int nseries = 0;
    for (int i = 0; i < T->nr; i++) nseries = T->r[i].series + 1 > nseries ? T->r[i].series + 1 : nseries;
    for (int s = 0; s < nseries && !rc; s++) {
        /* the series' runs from coarsest to finest, so the line joins each to its next finer one */
        int m = 0;
        for (int i = 0; i < T->nr; i++)
            if (T->r[i].series == s && SHOWN(&T->r[i])) {
                int j = m++;
                for (; j > 0 && T->r[order[j - 1]].h < T->r[i].h; j--) order[j] = order[j - 1];
                order[j] = i;
            }
        for (int j = 0; j < m; j++) {
            const trade_run *r = &T->r[order[j]];
            x[j] = r->wall, y[j] = r->rel;
            labels[j] = T->refine >= 0 ? T->k[T->refine].v[r->vi[T->refine]] : NULL;
        }
        char buf[256], lab[300];
        for (int i = 0; i < T->nr; i++)
            if (T->r[i].series == s) {
                trade_run_label(T, &T->r[i], 1, buf, sizeof buf);
                break;
            }
        if (T->refine >= 0) snprintf(lab, sizeof lab, "%s (labels: %s)", buf, T->k[T->refine].name);
        else snprintf(lab, sizeof lab, "%s", buf);
        hearth_plot_series_def sd = hearth_default_plot_series_def();
        sd.n = m, sd.x = x, sd.y = y, sd.point_labels = labels, sd.line_width = T->refine >= 0;
        sd.label = s < 8 ? lab : NULL; /* the legend lists the first 8 */
        hearth_plot_color(s, sd.color);
        if (hearth_plot_add_series(p, &sd, &err) < 0) rc = -1;
    }
    /* the Pareto front, in order of wall time, under the runs */
    int m = 0;
    for (int i = 0; i < T->nr; i++)
        if (T->r[i].pareto) {
            int j = m++;
            for (; j > 0 && T->r[order[j - 1]].wall > T->r[i].wall; j--) order[j] = order[j - 1];
            order[j] = i;
        }
    for (int j = 0; j < m; j++) x[j] = T->r[order[j]].wall, y[j] = T->r[order[j]].rel;
    hearth_plot_series_def fd = hearth_default_plot_series_def();
    fd.n = m, fd.x = x, fd.y = y, fd.marker = HEARTH_MARKER_RING, fd.line_width = 1, fd.behind = 1;
    fd.label = "Pareto front (nothing else is both faster and more accurate)";
    memcpy(fd.color, (const unsigned char[3]){40, 40, 40}, 3);
    if (!rc && hearth_plot_add_series(p, &fd, &err) < 0) rc = -1;
#undef SHOWN
    if (!rc && hearth_plot_write_png(p, path, &err)) rc = -1;
    if (rc) fprintf(stderr, "hearth trade: %s\n", err.msg);
done:
    hearth_plot_free(p);
    free(x);
    free(y);
    free(labels);
    free(order);
    return rc;
}

void trade_print_table(const trade *T) {
    printf("%4s", "run");
    for (int j = 0; j < T->nk; j++) printf("  %10s", T->k[j].name);
    printf("  %6s %9s %8s %8s %14s %10s %7s  %s\n", "status", "wall [s]", "steps", "peak MB", T->metric, "rel error", "order",
           "");
    for (int i = 0; i < T->nr; i++) {
        const trade_run *r = &T->r[i];
        printf("%4d", i);
        for (int j = 0; j < T->nk; j++) printf("  %10s", T->k[j].v[r->vi[j]]);
        printf("  %6s %9.2f %8ld %8.1f %14.7g %10.3g %7.2f  %s%s%s\n", trade_state_name[r->st], r->wall, r->steps, r->peak_mb,
               r->metric, r->rel, r->order, r->pareto ? "pareto " : "", r->is_ref ? "reference " : "",
               r->st != RS_OK ? r->msg : "");
    }
}


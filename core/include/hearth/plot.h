/* hearth/plot.h: line and scatter plots written as PNG, the one plotting
 * module behind `hearth trade`, `hearth rheometer` and `hearth fit`.
 *
 * A plot is a frame with two axes (each logarithmic or linear), a title, axis
 * names and a legend, holding any number of series; each series is points
 * drawn as dots or rings, a line through them in the given order, or both.
 * The axes span everything drawn: whole decades on a log axis, whole steps of
 * 1, 2 or 5 x 10^k on a linear one. Pictures are bit-reproducible (no
 * antialiasing). How it draws is private, so a better renderer can replace
 * it without changing a caller.
 *
 *     hearth_plot_def d = hearth_default_plot_def();
 *     d.title = "flow curve"; d.x_label = "shear rate [1/s]"; d.y_label = "stress [Pa]";
 *     hearth_plot *p = hearth_plot_create(&d, &err);
 *     hearth_plot_series_def s = hearth_default_plot_series_def();
 *     s.n = n; s.x = rate; s.y = stress; s.label = "measured";
 *     hearth_plot_add_series(p, &s, &err);
 *     hearth_plot_write_png(p, "flow.png", &err);
 *     hearth_plot_free(p);
 */
#ifndef HEARTH_PLOT_H
#define HEARTH_PLOT_H

#include "hearth.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct hearth_plot hearth_plot; ///< a plot being built; owns copies of everything given to it

typedef enum hearth_plot_scale {
    HEARTH_PLOT_LOG = 0,   ///< decades; values <= 0 cannot be drawn and are skipped
    HEARTH_PLOT_LINEAR = 1
} hearth_plot_scale;

typedef enum hearth_plot_legend_pos {
    HEARTH_LEGEND_TOP_LEFT = 0, ///< inside the frame, first entry at the top
    HEARTH_LEGEND_BOTTOM_LEFT,  ///< inside the frame, last entry at the bottom
    HEARTH_LEGEND_NONE
} hearth_plot_legend_pos;

/// A plot's frame. Start from hearth_default_plot_def().
typedef struct hearth_plot_def {
    int width, height;                ///< pixels, 200..8192 each (default 760 x 520)
    const char *title;                ///< above the frame; NULL for none (copied)
    const char *x_label, *y_label;    ///< axis names with units; NULL for none (copied)
    hearth_plot_scale x_scale, y_scale; ///< default HEARTH_PLOT_LOG for both
    hearth_plot_legend_pos legend;    ///< default HEARTH_LEGEND_TOP_LEFT
} hearth_plot_def;

hearth_plot_def hearth_default_plot_def(void);

typedef enum hearth_plot_marker {
    HEARTH_MARKER_NONE = 0,
    HEARTH_MARKER_DOT,  ///< a filled disc of radius 3.5 px, drawn over the series' line
    HEARTH_MARKER_RING  ///< an open ring of radius 7.5 px, drawn under the series' line (to circle points of another series)
} hearth_plot_marker;

/// One series. Start from hearth_default_plot_series_def().
typedef struct hearth_plot_series_def {
    int n;                           ///< number of points (0 is allowed: a legend entry only)
    const double *x, *y;             ///< n values each (copied). A point that cannot be drawn (not finite,
                                     ///< or <= 0 on a log axis) is skipped and breaks the line there
    const char *label;               ///< legend text; NULL keeps the series out of the legend (copied)
    unsigned char color[3];          ///< RGB (default the first of the palette, hearth_plot_color)
    hearth_plot_marker marker;       ///< default HEARTH_MARKER_DOT
    int line_width;                  ///< 0 (no line, the default), 1 or 2 pixels: joins the points in order
    const char *const *point_labels; ///< NULL, or n strings (NULL entries allowed) written beside the points (copied)
    int behind;                      ///< nonzero: drawn before every series without it (a fitted curve under
                                     ///< the data, rings under the points they mark); the legend keeps add order
} hearth_plot_series_def;

hearth_plot_series_def hearth_default_plot_series_def(void);

/// Colour i of the plot palette (8 distinguishable colours, cycling: blue, red, green, orange, ...), into rgb.
void hearth_plot_color(int i, unsigned char rgb[3]);

/// A new, empty plot. NULL on failure: HEARTH_ERR_PARAM (a size outside
/// 200..8192, an unknown scale or legend position) or HEARTH_ERR_NOMEM.
hearth_plot *hearth_plot_create(const hearth_plot_def *def, hearth_error *err);
/// Add a series. Returns its index (0, 1, ...) or -1: HEARTH_ERR_PARAM (n < 0,
/// NULL x or y with n > 0, an unknown marker, a line width outside 0..2) or
/// HEARTH_ERR_NOMEM; the plot is unchanged then.
int hearth_plot_add_series(hearth_plot *p, const hearth_plot_series_def *s, hearth_error *err);
/// Draw the plot and write it as an 8-bit RGB PNG of width x height pixels,
/// atomically (readers see the old file or the whole new one). Errors as
/// the file write's (HEARTH_ERR_IO naming the path) or HEARTH_ERR_NOMEM.
hearth_status hearth_plot_write_png(const hearth_plot *p, const char *path, hearth_error *err);
/// Release the plot (NULL is fine).
void hearth_plot_free(hearth_plot *p);

#ifdef __cplusplus
}
#endif
#endif

/* canvas.h: the Cairo canvas every picture is drawn on (render.c's frames and
 * slices, plot.c's plots), with the text, tick and PNG helpers they share.
 *
 * A canvas is an opaque RGB image surface; drawing goes through its cairo_t.
 * Text uses Cairo's own font selection (fontconfig, "DejaVu Sans" first, any
 * sans-serif face otherwise). The finished pixels go out through io_png.c's
 * atomic writer, so a viewer never sees half a frame. */
#ifndef HEARTH_SIM_CANVAS_H
#define HEARTH_SIM_CANVAS_H
#include <cairo.h>

#include "hearth/hearth.h"

/// Largest canvas width or height in pixels.
#define CANVAS_DIM_MAX 8192
/// pi, for arcs and rotated text (M_PI is not C17).
#define CANVAS_PI 3.14159265358979323846

typedef struct canvas {
    int w, h;             ///< pixels
    cairo_surface_t *sf;  ///< CAIRO_FORMAT_RGB24 image surface; owned
    cairo_t *cr;          ///< drawing context on sf; owned
    const char *title;    ///< written as the PNG's "Title" text when set (borrowed; NULL: none)
} canvas;

/// A w x h canvas painted with bg (8-bit RGB). On failure *c is zeroed and
/// HEARTH_ERR_PARAM (size outside 1..CANVAS_DIM_MAX) or HEARTH_ERR_NOMEM returned.
hearth_status canvas_init(canvas *c, int w, int h, const unsigned char bg[3], hearth_error *err);
/// Release the surface and context and zero *c (a zeroed canvas is fine).
void canvas_free(canvas *c);
/// Write the canvas as an 8-bit RGB PNG, atomically (png_write_rgb).
hearth_status canvas_write_png(canvas *c, const char *path, hearth_error *err);
/// Set the source colour from 8-bit RGB and an alpha in [0, 1].
void canvas_rgb(canvas *c, const unsigned char rgb[3], double alpha);

/// Text anchors: where (x, y) is on the text's box.
enum { CANVAS_LEFT = 0, CANVAS_CENTER = 1, CANVAS_RIGHT = 2 };   /* horizontal */
enum { CANVAS_TOP = 0, CANVAS_MIDDLE = 1, CANVAS_BASELINE = 2 }; /* vertical */
/// Draw UTF-8 text of the given pixel size at (x, y), anchored as asked,
/// rotated by angle (radians, counter-clockwise; 0 for level text).
void canvas_text(canvas *c, double x, double y, const char *s, double size, int h_anchor, int v_anchor,
                 double angle, const unsigned char rgb[3]);
/// Width of text at the given pixel size (pixels).
double canvas_text_width(canvas *c, const char *s, double size);

/// Ticks for a linear axis or colour bar over [lo, hi] (lo < hi): every
/// multiple of 1, 2, 2.5, 4 or 5 x 10^k inside it, the step chosen so that
/// between min_n and max_n ticks fall inside (the closest count otherwise).
/// Writes up to max_n values into t (ascending) and returns their number;
/// *step gets the spacing (for label precision).
int canvas_ticks(double lo, double hi, int min_n, int max_n, double *t, double *step);
/// A tick's label: v with as many decimals as step needs ("0.25", "150",
/// "2e+05" for large or tiny magnitudes), never "-0".
void canvas_tick_label(double v, double step, char *buf, size_t n);
/// A unit as a person reads it on a picture: "degC" -> "°C", "m^3" -> "m³",
/// "1" (dimensionless) -> "-". Writes into buf.
void canvas_unit(const char *unit, char *buf, size_t n);
#endif

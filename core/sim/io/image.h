/* image.h: a small RGB canvas for frames, mask previews and colour bars.
 *
 * Pixel (i, j) is column i, row j, row 0 at the top; its centre is at the
 * integer point (i, j). Every drawing call clips to the canvas, so callers can
 * draw shapes that are partly or entirely off screen. */
#ifndef HEARTH_SIM_IMAGE_H
#define HEARTH_SIM_IMAGE_H
#include "hearth/hearth.h"

/// Largest canvas width or height in pixels.
#define IMG_DIM_MAX 32768

typedef struct img {
    int w, h;           ///< size in pixels
    unsigned char *rgb; ///< w*h*3 bytes, rows top first; owned, freed by img_free
} img;

/// Allocate a w x h canvas filled with bg (NULL = black). On failure *im is
/// zeroed and HEARTH_ERR_PARAM (size outside 1..IMG_DIM_MAX) or HEARTH_ERR_NOMEM returned.
hearth_status img_init(img *im, int w, int h, const unsigned char bg[3], hearth_error *err);
/// Release the pixels and zero *im (a zeroed img is fine).
void img_free(img *im);

/// Fill columns x0..x1-1 and rows y0..y1-1 (half open; corners in any order).
void img_fill_rect(img *im, int x0, int y0, int x1, int y1, const unsigned char c[3]);
/// Fill every pixel whose centre lies within r of (cx, cy). No antialiasing,
/// so frames are bit-reproducible. Non-finite input draws nothing.
void img_disc(img *im, double cx, double cy, double r, const unsigned char c[3]);
/// One-pixel line from (x0, y0) to (x1, y1), both ends included.
void img_line(img *im, double x0, double y0, double x1, double y1, const unsigned char c[3]);
/// Vertical colour bar of w x h pixels with top left (x, y): vmax at the top,
/// vmin at the bottom, framed, labelled to its right with "%.3g" of vmax and
/// vmin and with unit (may be NULL or ""). Label colour is black or white,
/// whichever stands out against the canvas where the labels go.
void img_colorbar(img *im, int x, int y, int w, int h, int map, double vmin, double vmax,
                  const char *unit);
/// Draw text with the built-in font (see font.h), top left of the first cell at (x, y).
void img_text(img *im, int x, int y, const char *s, int scale, const unsigned char c[3]);
#endif

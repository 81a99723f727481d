/* io_png.h: PNG files for frames (written) and cookie-cutter masks (read).
 *
 * A thin layer over libpng. Writes are atomic so a viewer or a crashed run
 * never sees half a frame; reads flatten every PNG flavour to 8-bit grey. */
#ifndef HEARTH_SIM_IO_PNG_H
#define HEARTH_SIM_IO_PNG_H
#include <stdint.h>

#include "hearth/hearth.h"

/// Largest width or height accepted by png_write_rgb and png_read_gray (pixels).
#define PNG_DIM_MAX 32768
/// Largest pixel count png_read_gray accepts (64 Mi: 8192^2). Decoding holds
/// 5 bytes a pixel at once (RGBA and the grey result), so this caps a read at
/// 320 MB whatever a header asks for.
#define PNG_PIXELS_MAX ((uint64_t)1 << 26)

/// Write an 8-bit RGB image (w*h*3 bytes, row 0 at the top, no padding) to path.
/// The data go to path + ".tmp.<pid>" in the same folder, are flushed and
/// fsynced, then renamed over path. On any failure the temporary file is
/// removed and an existing file at path is left untouched. Errors:
/// HEARTH_ERR_PARAM (size outside 1..PNG_DIM_MAX), HEARTH_ERR_IO (with the
/// path and strerror), HEARTH_ERR_NOMEM. Not safe for two threads of one
/// process writing the same path at once (they share the temporary name).
hearth_status png_write_rgb(const char *path, int w, int h, const unsigned char *rgb,
                            hearth_error *err);
/// png_write_rgb with the picture's title (UTF-8, NULL or "" for none) as the PNG's
/// "Title" text (an uncompressed iTXt chunk, before the image data): viewers and
/// `exiftool` show it, and a script reads what a frame says it shows without its pixels.
hearth_status png_write_rgb_titled(const char *path, int w, int h, const unsigned char *rgb,
                                   const char *title, hearth_error *err);

/// Read any PNG (palette, grey, RGB, with or without alpha, 1..16 bits) as 8-bit
/// luminance L = 0.299 R + 0.587 G + 0.114 B, composited over white when the
/// image has alpha: L a/255 + 255 (1 - a/255). Rows top first. Stored values
/// are used as they are (gAMA, cHRM and iCCP are ignored). On success *pixels
/// is a w*h block from mem_alloc that the caller releases with
/// mem_free(*pixels, (size_t)w * h). On failure *pixels is NULL, *w = *h = 0,
/// and the status is HEARTH_ERR_IO (cannot open or read), HEARTH_ERR_FORMAT
/// (not a PNG, zero width or height, truncated or corrupt), HEARTH_ERR_PARAM
/// (larger than PNG_DIM_MAX or PNG_PIXELS_MAX, refused from the header before
/// any image memory is allocated; the message gives the limits) or
/// HEARTH_ERR_NOMEM. Text, ICC profile, sPLT, eXIf and unknown chunks are
/// skipped unread; no chunk may allocate more than 8 MiB.
hearth_status png_read_gray(const char *path, int *w, int *h, unsigned char **pixels,
                            hearth_error *err);
#endif

/* font.h: a built-in 5x7 bitmap font for labels burnt into frames.
 *
 * Each character takes a 6x9 cell: the 5x7 glyph at the cell's top left
 * (capitals span rows 0..6), one column of spacing on the right, and two rows
 * below the baseline that only the descenders of g p q y reach into.
 * Printable ASCII 32..126 is covered; the UTF-8 degree sign U+00B0 has its own
 * glyph; other bytes outside ASCII draw as '?' (one per UTF-8 sequence).
 * '\n' starts a new line 9*scale pixels lower at the starting x. */
#ifndef HEARTH_SIM_FONT_H
#define HEARTH_SIM_FONT_H

#define FONT_CELL_W 6 ///< cell width in pixels at scale 1
#define FONT_CELL_H 9 ///< cell height (line spacing) in pixels at scale 1

/// Width in pixels of the widest line of s at scale (values < 1 count as 1),
/// including the trailing spacing column: strlen * 6 * scale for one ASCII line.
int font_text_width(const char *s, int scale);

/// Draw s into an 8-bit RGB image of w*h pixels (row 0 at the top) with the top
/// left of the first cell at (x, y); each font pixel becomes a scale x scale
/// block of color. Pixels outside the image are skipped; only glyph pixels are
/// written (the background shows through).
void font_draw(unsigned char *rgb, int w, int h, int x, int y, const char *s, int scale,
               const unsigned char color[3]);
#endif

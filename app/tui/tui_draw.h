/* tui_draw.h: pure drawing for the dashboard. Field values in, cells out: no
 * terminal, no curses, no globals, so tests/unit_tui.c checks them directly.
 *
 * A heat map uses half blocks: one terminal cell shows two vertical pixels,
 * the upper one as the foreground of U+2580 (upper half block) and the lower
 * one as its background. */
#ifndef HEARTH_TUI_DRAW_H
#define HEARTH_TUI_DRAW_H
#include <stdint.h>

/// How the terminal shows colour, best first in the enum's reverse order.
typedef enum tui_color_mode {
    TUI_PLAIN = 0,   ///< TERM=dumb: no screen at all, the line-based mode
    TUI_ASCII = 1,   ///< no colour (NO_COLOR, fewer than 256 colours, or no UTF-8): density characters
    TUI_256 = 2,     ///< the xterm 256-colour palette (cube 16..231, greys 232..255)
    TUI_TRUECOLOR = 3///< 24-bit colour (a terminal description with direct colour)
} tui_color_mode;

#define TUI_UPPER_HALF 0x2580u ///< ▀
#define TUI_LOWER_HALF 0x2584u ///< ▄
#define TUI_DEFAULT (-1)       ///< the terminal's own foreground or background

/// One terminal cell. fg/bg are 0xRRGGBB in TUI_TRUECOLOR, a palette index in
/// TUI_256, and TUI_DEFAULT where the terminal's colour shows (outside the material).
typedef struct tui_cell {
    uint32_t ch; ///< a Unicode code point
    int32_t fg, bg;
} tui_cell;

/// Choose the mode from the environment and the terminal: term ($TERM, may be
/// NULL), no_color ($NO_COLOR: set and non-empty means no colour), utf8 (the
/// locale's character set is UTF-8), colors (the terminal's colour count).
tui_color_mode tui_pick_mode(const char *term, const char *no_color, int utf8, long colors);

/// The colour map at u in [0, 1] (clamped): viridis-like, our own stops, or
/// the map chosen with tui_use_colormap.
void tui_colormap(double u, unsigned char rgb[3]);
/// Draw with the named picture colour map (hearth_colormap_names(); the name
/// must outlive its use) or, for NULL or an unknown name, the stops above.
void tui_use_colormap(const char *name);
/// The nearest xterm 256-palette entry to rgb (cube or grey ramp).
int tui_rgb_to_256(const unsigned char rgb[3]);
/// A cell colour for u in [0, 1] in mode m (TUI_DEFAULT for NaN or a colourless mode).
int32_t tui_color(double u, tui_color_mode m);
/// The density character for u in [0, 1] (' ' for NaN): " .:-=+*#%@", u = 0 is '.'.
char tui_density_char(double u);

/// Finite minimum and maximum of n values (both NaN when none is finite).
void tui_range(const double *v, long n, double *lo, double *hi);

/// Draw a field of fw x fh samples (row 0 at the bottom, NaN outside the
/// material) scaled from lo..hi onto cols x rows cells (top row first): the
/// 2*rows x cols pixel grid samples the field by nearest neighbour over the
/// window u0..u1 (columns) x v0..v1 (rows) given as fractions 0..1 of the field.
/// In TUI_ASCII each cell gets the density of its two pixels' mean.
void tui_draw_heatmap(const double *f, int fw, int fh, double lo, double hi, double u0, double u1, double v0,
                      double v1, tui_color_mode m, int cols, int rows, tui_cell *out);

/// A colour bar: cols cells going from lo to hi (a full block per cell in
/// colour modes, the density characters in TUI_ASCII).
void tui_draw_colorbar(tui_color_mode m, int cols, tui_cell *out);

/// Draw solids (colliders: tray, pan, nozzle) into a heat map's cells where no
/// material is: solid is cols x (2 rows) pixels, row 0 at the top, nonzero
/// inside a solid. Grey half blocks in the colour modes, '/' in TUI_ASCII;
/// material keeps its colour.
void tui_draw_solids(tui_cell *cells, int cols, int rows, const unsigned char *solid, tui_color_mode m);

/// A sparkline of the last `width` of n values (oldest first) into out (width
/// code points, NUL-free): U+2581..U+2588 scaled between their own min and
/// max (a flat series draws the lowest bar), ASCII " _.-=+*#" when ascii is
/// set, ' ' for NaN and for missing history.
void tui_sparkline(const double *v, int n, int width, int ascii, uint32_t *out);

/// Encode a code point as UTF-8 into buf (at least 5 bytes); returns the length.
int tui_utf8(uint32_t cp, char *buf);
#endif

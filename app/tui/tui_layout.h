/* tui_layout.h: where each panel of the dashboard goes for a terminal size.
 * Pure: cols x rows in, rectangles out. */
#ifndef HEARTH_TUI_LAYOUT_H
#define HEARTH_TUI_LAYOUT_H

#define TUI_MIN_COLS 80
#define TUI_MIN_ROWS 24

typedef struct tui_rect {
    int x, y, w, h;
} tui_rect;

typedef struct tui_layout {
    tui_rect status;   ///< two lines at the top
    tui_rect title[2]; ///< one line over each view: field and slice
    tui_rect view[2];  ///< the heat maps
    tui_rect bar[2];   ///< one line under each view: colour bar, min, max, unit
    tui_rect probes;   ///< bottom left
    tui_rect log;      ///< bottom right
    tui_rect prompt;   ///< the last line
} tui_layout;

/// Lay out a cols x rows screen. Returns 0 when it is smaller than
/// TUI_MIN_COLS x TUI_MIN_ROWS (the dashboard then shows a message instead).
int tui_layout_compute(int cols, int rows, tui_layout *l);

/// The key bar for the prompt line when the prompt is idle: the widest variant
/// that fits `width` columns; every variant ends with "? help  q quit".
const char *tui_key_bar(int width);
#endif

/* tui_layout.c: the dashboard's panels for a terminal size.
 *
 *   status (2 lines)
 *   title | title
 *   view  | view        the views take what the bottom panels leave
 *   bar   | bar
 *   probes | log        a third of the rows below 40, 12 rows above
 *   prompt (1 line)
 */
#include "tui_layout.h"

#include <string.h>

int tui_layout_compute(int cols, int rows, tui_layout *l) {
    *l = (tui_layout){0};
    if (cols < TUI_MIN_COLS || rows < TUI_MIN_ROWS) return 0;
    int bottom = rows < 40 ? rows / 3 : 12;
    if (bottom < 7) bottom = 7;
    const int top = 2, prompt = 1;
    int vh = rows - top - prompt - bottom - 2; /* minus the title and bar lines */
    int half = cols / 2;
    l->status = (tui_rect){0, 0, cols, top};
    for (int k = 0; k < 2; k++) {
        int x = k ? half : 0, w = k ? cols - half : half - 1; /* one blank column between the views */
        l->title[k] = (tui_rect){x, top, w, 1};
        l->view[k] = (tui_rect){x, top + 1, w, vh};
        l->bar[k] = (tui_rect){x, top + 1 + vh, w, 1};
    }
    int by = top + vh + 2;
    int pw = cols * 11 / 20; /* the probe panel needs room for name, value, unit and a sparkline */
    l->probes = (tui_rect){0, by, pw, bottom};
    l->log = (tui_rect){pw + 1, by, cols - pw - 1, bottom};
    l->prompt = (tui_rect){0, rows - 1, cols, 1};
    return 1;
}

const char *tui_key_bar(int width) {
    /* widest first; every one ends with help and quit, which a user must always find */
    static const char *bars[] = {
        " Space run/pause  n step  f/F field  arrows probe  p pin  s PNG  c checkpoint  : Lua  ? help  q quit",
        " Spc run  n step  f/F field  arrows probe  p pin  s PNG  c ckpt  : Lua  ? help  q quit",
        " Spc run  n step  f/F field  arrows probe  s PNG  c ckpt  : Lua  ? help  q quit", /* 80 columns */
        " Spc run  n step  f/F field  s PNG  : Lua  ? help  q quit",
        " Spc run  : Lua  ? help  q quit",
        " ? help  q quit",
    };
    const int n = (int)(sizeof bars / sizeof *bars);
    for (int i = 0; i < n - 1; i++)
        if ((int)strlen(bars[i]) <= width) return bars[i];
    return bars[n - 1];
}

/* tui_screen.h: the terminal through ncursesw: start and restore it (on
 * every exit path, crash signals included), keys, and cell grids. */
#ifndef HEARTH_TUI_SCREEN_H
#define HEARTH_TUI_SCREEN_H
#include "tui_draw.h"

/// Start curses on the terminal and pick the colour mode (from $TERM,
/// $NO_COLOR, the locale and the terminal's colours). Installs handlers that
/// restore the terminal on SIGSEGV, SIGABRT, SIGBUS, SIGFPE and SIGILL before
/// the default action, and makes SIGINT, SIGTERM and SIGHUP set a flag
/// (tui_screen_interrupted). Returns 0, or -1 when curses cannot start.
int tui_screen_open(tui_color_mode *mode);
/// Restore the terminal (idempotent).
void tui_screen_close(void);
/// What tui_screen_open made of COLORTERM=truecolor ("" when it was not set): for the log.
const char *tui_screen_color_note(void);
/// The signal that asked to stop (SIGINT, ...), or 0.
int tui_screen_interrupted(void);
/// Wait up to ms milliseconds (0: do not wait) for a key. Returns 0 when none
/// came, else a character or a TUI_KEY_* code (tui_prompt.h); KEY_RESIZE-like
/// events come back as TUI_SCREEN_RESIZE.
int tui_screen_key(int ms);
#define TUI_SCREEN_RESIZE 0x120000
/// Put a w x h grid of cells at (x, y).
void tui_screen_cells(int x, int y, int w, int h, const tui_cell *cells, tui_color_mode m);
#endif

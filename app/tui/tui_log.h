/* tui_log.h: the dashboard's log panel, a ring of text lines (messages,
 * errors, print output of Lua commands). */
#ifndef HEARTH_TUI_LOG_H
#define HEARTH_TUI_LOG_H

#define TUI_LOG_LINES 400
#define TUI_LOG_WIDTH 240

typedef struct tui_log {
    char line[TUI_LOG_LINES][TUI_LOG_WIDTH];
    long count;   ///< lines added so far; the newest is line[(count - 1) % TUI_LOG_LINES]
    long changed; ///< bumped on every add, so the screen knows to redraw
} tui_log;

/// Add a message; embedded newlines start new lines, long lines are cut.
void tui_log_add(tui_log *g, const char *fmt, ...) __attribute__((format(printf, 2, 3)));
/// The k-th newest line (0 = newest), or NULL when there are fewer.
const char *tui_log_get(const tui_log *g, long k);
#endif

/* tui_log.c: the log panel's lines. */
#include "tui_log.h"

#include <stdarg.h>
#include <stdio.h>
#include <string.h>

void tui_log_add(tui_log *g, const char *fmt, ...) {
    char buf[4096];
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(buf, sizeof buf, fmt, ap);
    va_end(ap);
    for (char *p = buf;;) {
        char *nl = strchr(p, '\n');
        size_t n = nl ? (size_t)(nl - p) : strlen(p);
        char *dst = g->line[g->count % TUI_LOG_LINES];
        if (n >= TUI_LOG_WIDTH) n = TUI_LOG_WIDTH - 1;
        memcpy(dst, p, n);
        dst[n] = '\0';
        for (char *q = dst; *q; q++)
            if (*q == '\t' || *q == '\r') *q = ' ';
        g->count++;
        if (!nl) break;
        p = nl + 1;
    }
    g->changed++;
}

const char *tui_log_get(const tui_log *g, long k) {
    if (k < 0 || k >= g->count || k >= TUI_LOG_LINES) return NULL;
    return g->line[(g->count - 1 - k) % TUI_LOG_LINES];
}

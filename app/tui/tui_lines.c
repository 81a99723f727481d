/* tui_lines.c: the dashboard as plain lines, for TERM=dumb (an editor's
 * shell, a serial console): no screen control at all. The scene runs, a
 * status line comes every second, the log's new lines are printed, and lines
 * typed are Lua commands run between steps. An empty line pauses or resumes;
 * `quit` or end of input stops. */
#include <poll.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#include "tui_app.h"

static void flush_log(tui_app *a, long *shown) {
    long n = a->log.count - *shown;
    if (n > TUI_LOG_LINES) n = TUI_LOG_LINES;
    for (long k = n - 1; k >= 0; k--) printf("%s\n", tui_log_get(&a->log, k));
    *shown = a->log.count;
    fflush(stdout);
}

int tui_lines_run(tui_app *a) {
    long shown = 0;
    a->running = 1;
    printf("hearth %s (TERM=dumb: line mode). Lines are Lua; an empty line pauses or resumes; quit stops.\n",
           HEARTH_VERSION);
    double last_status = 0;
    char line[TUI_PROMPT_MAX];
    int eof = 0;
    while (!a->quit) {
        flush_log(a, &shown);
        struct pollfd pf = {.fd = 0, .events = POLLIN};
        int ready = !eof && poll(&pf, 1, a->running ? 0 : 250) > 0;
        if (ready) {
            if (!fgets(line, sizeof line, stdin)) eof = 1;
            else {
                line[strcspn(line, "\n")] = '\0';
                if (!strcmp(line, "quit")) break;
                if (!line[0]) a->running = !a->running;
                else {
                    tui_lua_result r = tui_lua_eval(&a->lua, line);
                    if (r == TUI_LUA_WAITING) a->running = 1;
                    a->s = tui_lua_scene(&a->lua);
                }
            }
        }
        if (eof && (!a->running || a->lua.njobs == 0)) break; /* input is over: finish the scene's run, no more */
        if (a->running) {
            double until = tui_wall() + 0.1;
            while (tui_wall() < until)
                if (tui_step(a)) break;
            if (eof && !a->running) { /* input is over and the run finished */
                flush_log(a, &shown);
                break;
            }
        }
        if (tui_wall() - last_status >= 1.0) {
            if (a->s) {
                hearth_stats hs;
                hearth_scene_stats(a->s, &hs);
                if (last_status > 0) a->sps = (double)(hs.step - a->rate_step) / (tui_wall() - last_status);
                a->rate_step = hs.step;
            }
            char st[512];
            tui_status_line(a, st, sizeof st);
            printf("%s\n", st);
            last_status = tui_wall();
        }
    }
    flush_log(a, &shown);
    char st[512];
    tui_status_line(a, st, sizeof st);
    printf("%s\n", st);
    return 0;
}

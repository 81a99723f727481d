/* tui_screen.c: curses set-up and tear-down, signals, keys, cell output.
 *
 * Colours go through ncurses' alloc_pair (6.1+), which keeps a least recently
 * used table of colour pairs: a heat map needs far more (fg, bg) pairs than a
 * terminal has, but only the ones on the screen at once. */
#define NCURSES_WIDECHAR 1
#include "tui_screen.h"

#include <curses.h>
#include <langinfo.h>
#include <locale.h>
#include <signal.h>
#include <stdlib.h>
#include <string.h>

#include "tui_prompt.h"

static volatile sig_atomic_t stop_signal;
static int open_now;

static void on_stop(int sig) { stop_signal = sig; }

/* The handlers that were there before the dashboard's (crash.c's, which name
 * a plugin that crashed): the dashboard restores the terminal, then hands the
 * signal on to them. */
static const int crash_signals[] = {SIGSEGV, SIGABRT, SIGBUS, SIGFPE, SIGILL};
static struct sigaction crash_before[sizeof crash_signals / sizeof crash_signals[0]];

static void on_crash(int sig) {
    /* endwin is not async-signal-safe, but the process is going down and a
     * terminal left in raw mode on the alternate screen is worse */
    if (open_now) endwin();
    open_now = 0;
    int handed = 0;
    for (size_t i = 0; i < sizeof crash_signals / sizeof crash_signals[0]; i++)
        if (crash_signals[i] == sig) handed = sigaction(sig, &crash_before[i], NULL) == 0;
    if (!handed) signal(sig, SIG_DFL);
    raise(sig); /* delivered when this handler returns, to the handler restored above */
}

int tui_screen_interrupted(void) { return (int)stop_signal; }

static SCREEN *direct_screen;

/* COLORTERM=truecolor (or 24bit) says the terminal takes 24-bit colour even
 * when $TERM's description (xterm-256color, tmux-256color) lists 256. ncurses
 * draws direct colour only through a description that has it, so try the
 * matching "-direct" one (Debian's ncurses-term): TERM's own family first,
 * then xterm-direct for the xterm-compatible rest. NULL when none is there:
 * the dashboard stays at 256 colours and says why in its log. */
static SCREEN *open_direct(const char *term, char *used, size_t n) {
    const char *ct = getenv("COLORTERM");
    if (!ct || (strcmp(ct, "truecolor") && strcmp(ct, "24bit")) || !term || strstr(term, "-direct")) return NULL;
    char fam[64];
    size_t len = strcspn(term, "-");
    if (len >= sizeof fam - 8) return NULL;
    memcpy(fam, term, len);
    strcpy(fam + len, "-direct");
    const char *cands[2] = {fam, "xterm-direct"};
    for (int i = 0; i < 2; i++) {
        SCREEN *sc = newterm(cands[i], stdout, stdin);
        if (sc) {
            snprintf(used, n, "%s", cands[i]);
            return sc;
        }
    }
    return NULL;
}

static char direct_note[160];
const char *tui_screen_color_note(void) { return direct_note; }

int tui_screen_open(tui_color_mode *mode) {
    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_stop;
    sigemptyset(&sa.sa_mask);
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
    sa.sa_handler = on_crash;
    sa.sa_flags = SA_RESETHAND;
    for (size_t i = 0; i < sizeof crash_signals / sizeof crash_signals[0]; i++)
        sigaction(crash_signals[i], &sa, &crash_before[i]);

    setlocale(LC_ALL, ""); /* wide characters need the user's locale */
    setlocale(LC_NUMERIC, "C"); /* but numbers keep their point, in printf and in Lua */
    if (!getenv("ESCDELAY")) set_escdelay(25); /* Esc leaves the prompt at once, not after a second */
    char used[64] = "";
    direct_note[0] = '\0';
    direct_screen = open_direct(getenv("TERM"), used, sizeof used);
    if (direct_screen) {
        snprintf(direct_note, sizeof direct_note, "COLORTERM=%s: 24-bit colour through the %s terminal description",
                 getenv("COLORTERM"), used);
    } else {
        const char *ct = getenv("COLORTERM");
        if (ct && (!strcmp(ct, "truecolor") || !strcmp(ct, "24bit")) && getenv("TERM") && !strstr(getenv("TERM"), "-direct"))
            snprintf(direct_note, sizeof direct_note,
                     "COLORTERM=%s, but no -direct terminal description is installed (Debian ncurses-term): 256 colours", ct);
        if (!initscr()) return -1;
    }
    open_now = 1;
    cbreak();
    noecho();
    nonl();
    keypad(stdscr, TRUE);
    curs_set(0);
    int colors = 0;
    if (has_colors() && start_color() == OK) {
        use_default_colors();
        colors = COLORS;
    }
    const char *cs = nl_langinfo(CODESET);
    int utf8 = cs && (!strcmp(cs, "UTF-8") || !strcmp(cs, "utf8"));
    *mode = tui_pick_mode(getenv("TERM"), getenv("NO_COLOR"), utf8, colors);
    if (*mode == TUI_PLAIN) *mode = TUI_ASCII; /* curses did start: a terminal after all */
    return 0;
}

void tui_screen_close(void) {
    if (!open_now) return;
    open_now = 0;
    curs_set(1);
    endwin();
    if (direct_screen) delscreen(direct_screen), direct_screen = NULL;
}

static int map_key(wint_t k, int is_key) {
    if (is_key) {
        switch (k) {
        case KEY_LEFT: return TUI_KEY_LEFT;
        case KEY_RIGHT: return TUI_KEY_RIGHT;
        case KEY_UP: return TUI_KEY_UP;
        case KEY_DOWN: return TUI_KEY_DOWN;
        case KEY_HOME: return TUI_KEY_HOME;
        case KEY_END: return TUI_KEY_END;
        case KEY_PPAGE: return TUI_KEY_PAGE_UP;
        case KEY_NPAGE: return TUI_KEY_PAGE_DOWN;
        case KEY_BACKSPACE: return TUI_KEY_BACKSPACE;
        case KEY_DC: return TUI_KEY_DELETE;
        case KEY_ENTER: return TUI_KEY_ENTER;
        case KEY_RESIZE: return TUI_SCREEN_RESIZE;
        default: {
            const char *name = keyname((int)k); /* Ctrl+arrows have no fixed codes */
            if (name && !strcmp(name, "kLFT5")) return TUI_KEY_WORD_LEFT;
            if (name && !strcmp(name, "kRIT5")) return TUI_KEY_WORD_RIGHT;
            if (name && !strcmp(name, "kDC5")) return TUI_KEY_DELETE_WORD_FORWARD;
            return 0;
        }
        }
    }
    switch (k) {
    case '\n': case '\r': return TUI_KEY_ENTER;
    case '\t': return TUI_KEY_TAB;
    case 127: case 8: return TUI_KEY_BACKSPACE;
    case 1: return TUI_KEY_HOME;       /* Ctrl-A */
    case 5: return TUI_KEY_END;        /* Ctrl-E */
    case 2: return TUI_KEY_LEFT;       /* Ctrl-B */
    case 6: return TUI_KEY_RIGHT;      /* Ctrl-F */
    case 4: return TUI_KEY_DELETE;     /* Ctrl-D */
    case 23: return TUI_KEY_DELETE_WORD_BACK; /* Ctrl-W */
    case 21: return TUI_KEY_KILL_START;       /* Ctrl-U */
    case 11: return TUI_KEY_KILL_END;         /* Ctrl-K */
    case 16: return TUI_KEY_UP;        /* Ctrl-P */
    case 14: return TUI_KEY_DOWN;      /* Ctrl-N */
    case 27: { /* Esc alone, or Alt+key as Esc then the key */
        wint_t n;
        nodelay(stdscr, TRUE);
        int r = get_wch(&n);
        if (r == OK) {
            if (n == 'b') return TUI_KEY_WORD_LEFT;
            if (n == 'f') return TUI_KEY_WORD_RIGHT;
            if (n == 'd') return TUI_KEY_DELETE_WORD_FORWARD;
            if (n == 127 || n == 8) return TUI_KEY_DELETE_WORD_BACK;
            unget_wch((wchar_t)n);
        } else if (r == KEY_CODE_YES) {
            ungetch((int)n);
        }
        return TUI_KEY_ESC;
    }
    default: return (int)k;
    }
}

int tui_screen_key(int ms) {
    timeout(ms);
    wint_t k;
    int r = get_wch(&k);
    if (r == ERR) return 0;
    return map_key(k, r == KEY_CODE_YES);
}

void tui_screen_cells(int x, int y, int w, int h, const tui_cell *cells, tui_color_mode m) {
    for (int r = 0; r < h; r++)
        for (int c = 0; c < w; c++) {
            const tui_cell *e = &cells[(long)r * w + c];
            wchar_t s[2] = {(wchar_t)e->ch, 0};
            cchar_t cc;
            int pair = 0;
            if (m >= TUI_256 && (e->fg != TUI_DEFAULT || e->bg != TUI_DEFAULT)) {
                pair = alloc_pair(e->fg, e->bg);
                if (pair < 0) pair = 0;
            }
            setcchar(&cc, s, A_NORMAL, 0, &pair);
            mvadd_wch(y + r, x + c, &cc);
        }
}

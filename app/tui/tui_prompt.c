/* tui_prompt.c: line editing and history for the dashboard's Lua prompt. */
#include "tui_prompt.h"

#include <ctype.h>
#include <errno.h>
#include <fcntl.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "hearth/hearth.h"

int tui_history_path(char *buf, unsigned long n) {
    const char *xdg = getenv("XDG_STATE_HOME"), *home = getenv("HOME");
    if (xdg && *xdg) snprintf(buf, n, "%s/hearth/history", xdg);
    else if (home && *home) snprintf(buf, n, "%s/.local/state/hearth/history", home);
    else return 0;
    return 1;
}

static void unescape(char *s) { /* \\ and \n back to what they were */
    char *o = s;
    for (char *p = s; *p; p++) {
        if (*p == '\\' && (p[1] == 'n' || p[1] == '\\')) *o++ = *++p == 'n' ? '\n' : '\\';
        else *o++ = *p;
    }
    *o = '\0';
}

static void push(tui_prompt *p, const char *entry) {
    if (p->nhist > 0 && !strcmp(p->hist[p->nhist - 1], entry)) return; /* no repeated neighbours */
    if (p->nhist == TUI_HISTORY_MAX) {
        free(p->hist[0]);
        memmove(p->hist, p->hist + 1, sizeof p->hist[0] * (TUI_HISTORY_MAX - 1));
        p->nhist--;
    }
    char *c = strdup(entry);
    if (c) p->hist[p->nhist++] = c;
}

void tui_prompt_init(tui_prompt *p, const char *path) {
    memset(p, 0, sizeof *p);
    if (!path) return;
    snprintf(p->path, sizeof p->path, "%s", path);
    FILE *f = fopen(path, "r");
    if (!f) return;
    char line[TUI_PROMPT_MAX * 2];
    while (fgets(line, sizeof line, f)) {
        line[strcspn(line, "\n")] = '\0';
        unescape(line);
        if (*line) push(p, line);
    }
    fclose(f);
    p->hpos = p->nhist;
}

void tui_prompt_free(tui_prompt *p) {
    for (int i = 0; i < p->nhist; i++) free(p->hist[i]);
    p->nhist = 0;
}

int tui_prompt_remember(tui_prompt *p, const char *entry) {
    push(p, entry);
    p->hpos = p->nhist;
    if (!p->path[0]) return 0;
    char dir[4096];
    snprintf(dir, sizeof dir, "%s", p->path);
    char *slash = strrchr(dir, '/');
    hearth_error err;
    if (slash) {
        *slash = '\0';
        if (hearth_mkdir_p(dir, &err)) return -1;
    }
    /* One write() per entry with O_APPEND: a history is appended to, not
     * replaced, and concurrent sessions each add whole lines. */
    char line[TUI_PROMPT_MAX * 2 + 2];
    size_t n = 0;
    for (const char *c = entry; *c && n + 3 < sizeof line; c++) {
        if (*c == '\n') line[n++] = '\\', line[n++] = 'n';
        else if (*c == '\\') line[n++] = '\\', line[n++] = '\\';
        else line[n++] = *c;
    }
    line[n++] = '\n';
    int fd = open(p->path, O_WRONLY | O_CREAT | O_APPEND, 0600);
    if (fd < 0) return -1;
    ssize_t w = write(fd, line, n);
    close(fd);
    return w == (ssize_t)n ? 0 : -1;
}

static void set_line(tui_prompt *p, const char *s) {
    snprintf(p->buf, sizeof p->buf, "%s", s);
    for (char *c = p->buf; *c; c++)
        if (*c == '\n') *c = ' '; /* a multi-line entry recalled comes back as one line */
    p->len = p->cur = (int)strlen(p->buf);
}

static int is_word(char c) { return isalnum((unsigned char)c) || c == '_'; }

int tui_prompt_word_start(const tui_prompt *p) {
    int i = p->cur;
    while (i > 0 && (is_word(p->buf[i - 1]) || p->buf[i - 1] == '.' || p->buf[i - 1] == ':')) i--;
    return i;
}

static void cut(tui_prompt *p, int a, int b) { /* remove buf[a..b) */
    memmove(p->buf + a, p->buf + b, (size_t)(p->len - b + 1));
    p->len -= b - a;
    p->cur = a;
}

void tui_prompt_insert(tui_prompt *p, const char *text) {
    int n = (int)strlen(text);
    if (p->len + n >= TUI_PROMPT_MAX) n = TUI_PROMPT_MAX - 1 - p->len;
    if (n <= 0) return;
    memmove(p->buf + p->cur + n, p->buf + p->cur, (size_t)(p->len - p->cur + 1));
    memcpy(p->buf + p->cur, text, (size_t)n);
    p->len += n;
    p->cur += n;
}

tui_prompt_action tui_prompt_key(tui_prompt *p, int key) {
    int i;
    switch (key) {
    case TUI_KEY_ENTER: return TUI_PROMPT_SUBMIT;
    case TUI_KEY_TAB: return TUI_PROMPT_COMPLETE;
    case TUI_KEY_ESC: return TUI_PROMPT_LEAVE;
    case TUI_KEY_LEFT: if (p->cur > 0) p->cur--; break;
    case TUI_KEY_RIGHT: if (p->cur < p->len) p->cur++; break;
    case TUI_KEY_HOME: p->cur = 0; break;
    case TUI_KEY_END: p->cur = p->len; break;
    case TUI_KEY_BACKSPACE: if (p->cur > 0) cut(p, p->cur - 1, p->cur); break;
    case TUI_KEY_DELETE: if (p->cur < p->len) cut(p, p->cur, p->cur + 1); break;
    case TUI_KEY_WORD_LEFT:
        while (p->cur > 0 && !is_word(p->buf[p->cur - 1])) p->cur--;
        while (p->cur > 0 && is_word(p->buf[p->cur - 1])) p->cur--;
        break;
    case TUI_KEY_WORD_RIGHT:
        while (p->cur < p->len && !is_word(p->buf[p->cur])) p->cur++;
        while (p->cur < p->len && is_word(p->buf[p->cur])) p->cur++;
        break;
    case TUI_KEY_DELETE_WORD_BACK:
        i = p->cur;
        while (i > 0 && p->buf[i - 1] == ' ') i--;
        while (i > 0 && is_word(p->buf[i - 1])) i--;
        if (i == p->cur && i > 0) i--; /* punctuation goes one at a time */
        cut(p, i, p->cur);
        break;
    case TUI_KEY_DELETE_WORD_FORWARD:
        i = p->cur;
        while (i < p->len && p->buf[i] == ' ') i++;
        while (i < p->len && is_word(p->buf[i])) i++;
        if (i == p->cur && i < p->len) i++;
        cut(p, p->cur, i);
        break;
    case TUI_KEY_KILL_START: cut(p, 0, p->cur); break;
    case TUI_KEY_KILL_END: p->buf[p->cur] = '\0', p->len = p->cur; break;
    case TUI_KEY_UP:
        if (p->hpos > 0) {
            if (p->hpos == p->nhist) snprintf(p->saved, sizeof p->saved, "%s", p->buf);
            set_line(p, p->hist[--p->hpos]);
        }
        break;
    case TUI_KEY_DOWN:
        if (p->hpos < p->nhist) {
            p->hpos++;
            set_line(p, p->hpos == p->nhist ? p->saved : p->hist[p->hpos]);
        }
        break;
    default:
        if (key >= 32 && key < 127) {
            char c[2] = {(char)key, 0};
            tui_prompt_insert(p, c);
        }
    }
    return TUI_PROMPT_NONE;
}

void tui_prompt_take(tui_prompt *p, char *out, unsigned long n) {
    snprintf(out, n, "%s", p->buf);
    p->buf[0] = '\0';
    p->len = p->cur = 0;
    p->hpos = p->nhist;
}

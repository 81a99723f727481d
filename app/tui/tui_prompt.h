/* tui_prompt.h: the dashboard's Lua prompt as a line editor: editing keys,
 * history kept across sessions in $XDG_STATE_HOME/hearth/history. No curses
 * here: keys come in as TUI_KEY_* codes or plain characters. */
#ifndef HEARTH_TUI_PROMPT_H
#define HEARTH_TUI_PROMPT_H

#define TUI_PROMPT_MAX 1024
#define TUI_HISTORY_MAX 500

enum {
    TUI_KEY_LEFT = 0x110000, /* above every Unicode code point */
    TUI_KEY_RIGHT, TUI_KEY_UP, TUI_KEY_DOWN, TUI_KEY_HOME, TUI_KEY_END, TUI_KEY_BACKSPACE, TUI_KEY_DELETE,
    TUI_KEY_ENTER, TUI_KEY_TAB, TUI_KEY_ESC, TUI_KEY_WORD_LEFT, TUI_KEY_WORD_RIGHT, TUI_KEY_DELETE_WORD_BACK,
    TUI_KEY_DELETE_WORD_FORWARD, TUI_KEY_KILL_START, TUI_KEY_KILL_END, TUI_KEY_PAGE_UP, TUI_KEY_PAGE_DOWN
};

typedef enum tui_prompt_action {
    TUI_PROMPT_NONE,     ///< the key edited the line (or did nothing)
    TUI_PROMPT_SUBMIT,   ///< Enter: the line is ready (tui_prompt_take)
    TUI_PROMPT_COMPLETE, ///< Tab: complete the word before the cursor
    TUI_PROMPT_LEAVE     ///< Esc: give the keys back to the dashboard
} tui_prompt_action;

typedef struct tui_prompt {
    char buf[TUI_PROMPT_MAX];
    int len, cur;
    char *hist[TUI_HISTORY_MAX];
    int nhist, hpos; ///< hpos == nhist: editing a new line
    char saved[TUI_PROMPT_MAX]; ///< the new line while browsing history
    char path[4096]; ///< history file ("" = none)
} tui_prompt;

/// The history file: $XDG_STATE_HOME/hearth/history, else
/// $HOME/.local/state/hearth/history. Returns 0 when neither variable is set.
int tui_history_path(char *buf, unsigned long n);
/// Start empty and load the history file at path (may be NULL: no history kept).
void tui_prompt_init(tui_prompt *p, const char *path);
void tui_prompt_free(tui_prompt *p);
tui_prompt_action tui_prompt_key(tui_prompt *p, int key);
/// Copy the line into out (n bytes) and clear it.
void tui_prompt_take(tui_prompt *p, char *out, unsigned long n);
/// Add an entry to the history (in memory and appended to the file; newlines
/// and backslashes are escaped so an entry is one line). Returns 0, or -1 when
/// the file could not be written (the entry is still kept in memory).
int tui_prompt_remember(tui_prompt *p, const char *entry);
/// Insert text at the cursor (completion).
void tui_prompt_insert(tui_prompt *p, const char *text);
/// The start of the word before the cursor (identifier characters, '.' and ':').
int tui_prompt_word_start(const tui_prompt *p);
#endif

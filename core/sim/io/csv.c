/* csv.c: reading CSV lines and splitting them (no embedded commas or escapes:
 * our files don't need them). */
#include "csv.h"

#include <ctype.h>
#include <string.h>

char *csv_trim(char *s) {
    while (*s && isspace((unsigned char)*s)) s++;
    size_t n = strlen(s);
    while (n && isspace((unsigned char)s[n - 1])) s[--n] = '\0';
    if (n >= 2 && s[0] == '"' && s[n - 1] == '"') { /* a quoted cell: "shear_rate" */
        s[n - 1] = '\0';
        s++;
    }
    return s;
}

int csv_split(char *line, char **cells, int max) {
    int n = 0;
    char *s = line;
    while (n < max) {
        char *comma = strchr(s, ',');
        if (comma) *comma = '\0';
        cells[n++] = csv_trim(s);
        if (!comma) break;
        s = comma + 1;
    }
    return n;
}

/* Byte by byte rather than fgets: fgets cannot tell a NUL byte from the end
 * of the line, so "1,2\0junk" read as "1,2" and a UTF-16 file as empty
 * cells; and a long line would come back in pieces numbered as lines of
 * their own. Rejected: getline, which grows its buffer to the longest line
 * (a 1 GB file without a newline asks for 1 GB). Our CSVs are small, so
 * per-byte reads cost nothing that matters. */
csv_line csv_read_line(FILE *f, char *buf, size_t n) {
    size_t len = 0;
    int c, nul = 0, any = 0;
    while ((c = getc(f)) != EOF) {
        any = 1;
        if (c == '\n') break;
        if (c == '\0') nul = 1;
        if (len + 1 < n) buf[len] = (char)c;
        len++;
    }
    buf[len + 1 < n ? len : n - 1] = '\0';
    if (c == EOF && ferror(f)) return CSV_LINE_IO;
    if (!any) return CSV_LINE_EOF;
    if (nul) return CSV_LINE_NUL;
    return len + 1 > n ? CSV_LINE_TOO_LONG : CSV_LINE_OK;
}

/* csv.c: splitting CSV lines (no embedded commas or escapes: our files don't need them). */
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

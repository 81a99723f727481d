/* csv.h: the small CSV reading that the sauce library and flow curves share. */
#ifndef HEARTH_CSV_H
#define HEARTH_CSV_H
#include <stddef.h>
#include <stdio.h>

/// Strip surrounding spaces and one pair of double quotes, in place.
char *csv_trim(char *s);
/// Split line in place at commas into at most max trimmed cells; returns the count.
int csv_split(char *line, char **cells, int max);

/// What csv_read_line found.
typedef enum csv_line {
    CSV_LINE_OK,       ///< a line is in buf, without its '\n'
    CSV_LINE_EOF,      ///< no more lines (nothing was read)
    CSV_LINE_TOO_LONG, ///< the line has more than n - 1 characters; it was read to its end and dropped
    CSV_LINE_NUL,      ///< the line holds a NUL byte: binary data or UTF-16, not a text CSV
    CSV_LINE_IO,       ///< the OS refused the read (errno says why)
} csv_line;

/// Read one line of f into buf (n >= 2 bytes), NUL-terminated, without its
/// '\n'. A final line without '\n' counts. A line too long for buf is read
/// to its end so the next call starts on the next line and no line, however
/// long, costs memory; the caller reports it with its line number.
csv_line csv_read_line(FILE *f, char *buf, size_t n);
#endif

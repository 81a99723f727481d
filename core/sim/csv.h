/* csv.h: the small CSV reading that the sauce library and flow curves share. */
#ifndef HEARTH_CSV_H
#define HEARTH_CSV_H

/// Strip surrounding spaces and one pair of double quotes, in place.
char *csv_trim(char *s);
/// Split line in place at commas into at most max trimmed cells; returns the count.
int csv_split(char *line, char **cells, int max);
#endif

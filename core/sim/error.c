/* error.c: formatting of hearth_error messages. */
#include "error.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

/* printf writes a NaN whose sign bit is set as "-nan" (Lua's 0/0 is one): a
 * NaN has no sign a user could act on, so every message says "nan". */
static void drop_nan_signs(char *msg) {
    for (char *p = msg; (p = strstr(p, "-nan")) != NULL;) {
        const int alone = (p == msg || !(isalnum((unsigned char)p[-1]) || p[-1] == '_')) &&
                          !(isalnum((unsigned char)p[4]) || p[4] == '_');
        if (alone) memmove(p, p + 1, strlen(p + 1) + 1);
        else p++;
    }
}

hearth_status err_set(hearth_error *err, hearth_status code, const char *fmt, ...) {
    if (!err) return code;
    err->code = code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    drop_nan_signs(err->msg);
    return code;
}

void err_clear(hearth_error *err) {
    if (!err) return;
    err->code = HEARTH_OK;
    err->msg[0] = '\0';
}

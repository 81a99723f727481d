/* error.c: formatting of hearth_error messages. */
#include "error.h"

#include <stdarg.h>
#include <stdio.h>

hearth_status err_set(hearth_error *err, hearth_status code, const char *fmt, ...) {
    if (!err) return code;
    err->code = code;
    va_list ap;
    va_start(ap, fmt);
    vsnprintf(err->msg, sizeof err->msg, fmt, ap);
    va_end(ap);
    return code;
}

void err_clear(hearth_error *err) {
    if (!err) return;
    err->code = HEARTH_OK;
    err->msg[0] = '\0';
}

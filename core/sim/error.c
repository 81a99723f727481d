/* error.c: formatting of hearth_error messages. */
#include "error.h"

#include <ctype.h>
#include <stdarg.h>
#include <stdio.h>
#include <string.h>

#include "alloc.h"
#include "hearth/hearth.h"

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
    /* a growth refused at the program's memory ceiling (alloc.c) fails as out
     * of memory at whichever call needed it: every such message names the cause */
    if (code == HEARTH_ERR_NOMEM && hearth_memory_limit_refused()) {
        char ceiling[64];
        mem_limit_words(ceiling, sizeof ceiling);
        const size_t n = strlen(err->msg);
        snprintf(err->msg + n, sizeof err->msg - n,
                 "; the simulation reached its memory ceiling of %s (hearth run --memory SIZE; the machine has %.3g GB)",
                 ceiling, (double)hearth_machine_memory() / 1e9);
    }
    return code;
}

void err_clear(hearth_error *err) {
    if (!err) return;
    err->code = HEARTH_OK;
    err->msg[0] = '\0';
}

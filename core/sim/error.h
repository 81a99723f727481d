/* error.h: filling hearth_error. Every failure message is built here. */
#ifndef HEARTH_SIM_ERROR_H
#define HEARTH_SIM_ERROR_H
#include "hearth/hearth.h"

/// Set err (may be NULL) to code with a printf-style message. Returns code.
hearth_status err_set(hearth_error *err, hearth_status code, const char *fmt, ...)
    __attribute__((format(printf, 3, 4)));
/// Clear err to HEARTH_OK with an empty message.
void err_clear(hearth_error *err);

/// Stops on a programming mistake (never on user input). On in debug and test builds.
#ifndef NDEBUG
#include <stdio.h>
#include <stdlib.h>
#define HEARTH_ASSERT(c)                                                                           \
    do {                                                                                           \
        if (!(c)) {                                                                                \
            fprintf(stderr, "%s:%d: assertion failed: %s\n", __FILE__, __LINE__, #c);              \
            abort();                                                                               \
        }                                                                                          \
    } while (0)
#else
#define HEARTH_ASSERT(c) ((void)0)
#endif
#endif

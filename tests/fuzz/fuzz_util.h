/* fuzz_util.h: what every fuzz target shares.
 *
 * The readers under test take a path, not a buffer, so each input is written
 * to one temporary file per process (in /dev/shm when there is one: a RAM
 * file keeps a libFuzzer run at thousands of inputs a second). FUZZ_CHECK is
 * the harness's own assertion: a reader that returns success with nonsense,
 * or failure with no message, is a finding just like a crash. */
#ifndef HEARTH_FUZZ_UTIL_H
#define HEARTH_FUZZ_UTIL_H
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>

#define FUZZ_CHECK(c)                                                                              \
    do {                                                                                           \
        if (!(c)) {                                                                                \
            fprintf(stderr, "%s:%d: fuzz check failed: %s\n", __FILE__, __LINE__, #c);             \
            abort();                                                                               \
        }                                                                                          \
    } while (0)

/// Write data to this process's temporary file named with suffix (".png",
/// ".csv", ...) and return its path (static storage), or NULL when the file
/// cannot be written (the input is then skipped, not a finding).
const char *fuzz_temp_file(const uint8_t *data, size_t size, const char *suffix);

/// A fresh empty folder for a target's outputs, made once per process.
const char *fuzz_temp_dir(void);

/// FUZZ_VERBOSE=1 in the environment: targets print why each input was
/// refused, to check by hand that seeds reach the code they are meant for.
int fuzz_verbose(void);

/// Remove everything inside dir (symlinks themselves, never their targets),
/// and dir too when and_dir. Best effort.
void fuzz_remove_tree(const char *dir, int and_dir);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
#endif

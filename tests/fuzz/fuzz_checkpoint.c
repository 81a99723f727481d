/* fuzz_checkpoint.c: the checkpoint reader.
 *
 * Bytes -> hearth_scene_load. A refusal must carry a message; a scene that
 * loads must be whole enough to step: a few steps of a small one run (a step
 * may fail with a message, never crash), bigger ones are only counted.
 *
 * Each input is resealed first (ck_reseal recomputes the whole-file
 * checksum), so mutations get past the checksum into the parsing behind it:
 * without that, the checksum stops nearly every mutation at the first check
 * and the fuzzer tests only that check (which checkpoint_every_byte_flip and
 * checkpoint_bitflip_campaign in unit_checkpoint already cover). */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "fuzz_util.h"
#include "hearth/hearth.h"

#include "checkpoint.h" /* ck_reseal, private to core/sim */

/* Stepping is where a checkpoint that loads but lies (a grid too small for
 * its particles, a NaN left in a column) shows; keep it cheap. */
#define STEP_MAX_PARTICLES 2000
#define STEPS 2

static hearth_scene *load(const uint8_t *data, size_t size, hearth_error *err) {
    unsigned char *copy = malloc(size ? size : 1);
    if (!copy) return NULL;
    memcpy(copy, data, size);
    ck_reseal(copy, size);
    hearth_scene *s = hearth_scene_load_mem(copy, size, "fuzz.ck", err);
    free(copy);
    return s;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
    hearth_set_threads(1); /* the same result for every run of an input */
    hearth_error err;
    memset(&err, 0, sizeof err);
    hearth_scene *s = load(data, size, &err);
    if (!s) {
        if (fuzz_verbose()) fprintf(stderr, "fuzz_checkpoint: %s\n", err.msg);
        FUZZ_CHECK(err.code != HEARTH_OK && err.msg[0] != '\0');
        return 0;
    }
    int n = hearth_scene_particle_count(s);
    FUZZ_CHECK(n >= 0);
    if (n <= STEP_MAX_PARTICLES) {
        memset(&err, 0, sizeof err);
        hearth_status st = hearth_scene_step(s, STEPS, &err);
        if (fuzz_verbose()) fprintf(stderr, "fuzz_checkpoint: loaded, %d particles, %d steps: %s\n", n, STEPS, st ? err.msg : "ok");
        if (st != HEARTH_OK) FUZZ_CHECK(err.msg[0] != '\0');
    }
    hearth_scene_destroy(s);
    return 0;
}

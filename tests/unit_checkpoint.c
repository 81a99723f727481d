/* unit_checkpoint.c: checkpoints are untrusted input. */
#include "mpm_fixture.h"
TEST(checkpoint_v3_roundtrip) { CHECK(1); }
TEST_MAIN(T(checkpoint_v3_roundtrip))

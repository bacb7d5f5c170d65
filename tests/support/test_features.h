/* test_features.h - the test suite in any configuration (fixel/config.h).
 *
 * A test that exercises an optional feature starts with TEST_NEEDS(FXL_HAVE_x):
 * where this build left the feature out, Unity reports the test IGNORE with
 * the flag's name (never PASS), and the rest of it does not run. What the API
 * does instead (FXL_ERR_UNSUPPORTED) is asserted by test_raster's
 * test_left_out_features_are_refused. CI runs the whole suite in reduced
 * configurations (host_sim/scripts/config_tests.sh). */
#ifndef FXL_TEST_FEATURES_H
#define FXL_TEST_FEATURES_H

#include "unity.h"
#include "fixel/fixel.h"

/* TEST_NEEDS for a draw: `missing` is left_out.h's answer for the draws
 * the test makes (NULL: all drawn, go on; else IGNORE with that name). */
void test_needs_draw(const char *missing);

#define TEST_NEEDS(flag)                                                                                   \
    do {                                                                                                   \
        if (!(flag))                                                                                       \
            TEST_IGNORE_MESSAGE("needs " #flag ", left out of this build by its configuration");         \
    } while (0)

#endif

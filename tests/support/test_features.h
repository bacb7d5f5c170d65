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

/* Golden values (image CRCs, recorded results) are the default 1/16 px
 * grid's: with another FXL_SUBPIXEL_BITS vertices snap elsewhere, so a test
 * of them reports IGNORE there (config_tests.sh's sub6 runs the rest). */
#define FXL_TEST_DEFAULT_GRID (FXL_SUBPIXEL_BITS == 4)
#define TEST_NEEDS_DEFAULT_GRID()                                                                          \
    do {                                                                                                   \
        if (!FXL_TEST_DEFAULT_GRID)                                                                        \
            TEST_IGNORE_MESSAGE("needs FXL_SUBPIXEL_BITS 4: its golden values are the 1/16 px grid's");  \
    } while (0)

#endif

/* test_features.c - see test_features.h */
#include "test_features.h"

#include <stdio.h>

const fxl_texture_t *test_flat_texture(void)
{
#if FXL_HAVE_GENERIC
    return NULL;
#else
    static const uint16_t white[1] = {0xFFFF};
    static fxl_texture_t tex;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, white, 1, 1, FXL_TEXFMT_RGB565, 1));
    return &tex;
#endif
}

void test_needs_draw(const char *missing)
{
    static char msg[160];   /* Unity prints it after the test returns */
    if (missing == NULL)
        return;
    snprintf(msg, sizeof msg, "needs %s, left out of this build by its configuration", missing);
    TEST_IGNORE_MESSAGE(msg);
}

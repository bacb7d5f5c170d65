/* test_features.c - see test_features.h */
#include "test_features.h"

#include <stdio.h>

void test_needs_draw(const char *missing)
{
    static char msg[160];   /* Unity prints it after the test returns */
    if (missing == NULL)
        return;
    snprintf(msg, sizeof msg, "needs %s, left out of this build by its configuration", missing);
    TEST_IGNORE_MESSAGE(msg);
}

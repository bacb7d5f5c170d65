/* tests/unity_compat/selftest.c - checks the compat runner against Unity's
 * documented behaviour. Not a fixel test: check_selftest.cmake runs it and
 * compares every output line and the exit status with what Unity 2.6 prints.
 * Tests named test_pass_* must pass, test_fail_* must fail with the message
 * listed in check_selftest.cmake, test_ignore_* must be ignored.
 */
#include "unity.h"

#include <string.h>

static int setup_calls;
static int teardown_calls;
static int ran_past_failure;

void setUp(void)
{
    setup_calls++;
}

void tearDown(void)
{
    teardown_calls++;
}

static void test_pass_every_macro(void)
{
    static const unsigned char a[4] = {1, 2, 3, 4};
    static const unsigned char b[4] = {1, 2, 3, 4};
    int x = 5;

    TEST_ASSERT(x == 5);
    TEST_ASSERT_TRUE(x);
    TEST_ASSERT_FALSE(x == 6);
    TEST_ASSERT_TRUE_MESSAGE(x > 0, "positive");
    TEST_ASSERT_MESSAGE(x < 10, "small");
    TEST_ASSERT_EQUAL(5, x);
    TEST_ASSERT_EQUAL_INT(-7, -7);
    TEST_ASSERT_EQUAL_INT_MESSAGE(1, 1, "one");
    TEST_ASSERT_EQUAL_INT32(INT32_MIN, INT32_MIN);
    TEST_ASSERT_EQUAL_INT64(INT64_MIN, INT64_MIN);
    TEST_ASSERT_EQUAL_UINT(4000000000u, 4000000000u);
    TEST_ASSERT_EQUAL_UINT8(0x12, 0x112); /* both truncate to 0x12 */
    TEST_ASSERT_EQUAL_UINT16(0xFFFF, -1);
    TEST_ASSERT_EQUAL_UINT32(0xFFFFFFFFu, -1);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(3u, 3u, "three");
    TEST_ASSERT_EQUAL_UINT64(UINT64_MAX, UINT64_MAX);
    TEST_ASSERT_EQUAL_HEX16(0xBEEF, 0xBEEF);
    TEST_ASSERT_EQUAL_HEX32(0xDEADBEEFu, 0xDEADBEEFu);
    TEST_ASSERT_EQUAL_HEX32_MESSAGE(0x10, 0x10, "hex");
    TEST_ASSERT_EQUAL_MESSAGE(2, 2, "two");
    TEST_ASSERT_NOT_EQUAL(1, 2);
    TEST_ASSERT_NULL(NULL);
    TEST_ASSERT_NOT_NULL(&x);
    TEST_ASSERT_INT_WITHIN(2, 10, 12);
    TEST_ASSERT_INT_WITHIN(2, 10, 8);
    TEST_ASSERT_INT32_WITHIN(1, INT32_MAX, INT32_MAX - 1);
    TEST_ASSERT_UINT32_WITHIN(3, 0xFFFFFFF0u, 0xFFFFFFF3u);
    TEST_ASSERT_DOUBLE_WITHIN(0.01, 1.0, 1.005);
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(0.5, -2.0, -2.4, "near");
    TEST_ASSERT_DOUBLE_WITHIN(0.0, NAN, NAN);
    TEST_ASSERT_DOUBLE_WITHIN(1.0, INFINITY, INFINITY);
    TEST_ASSERT_LESS_OR_EQUAL(5, 5);
    TEST_ASSERT_LESS_OR_EQUAL(5, -3);
    TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(1.5, 1.5);
    TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(1.5, 1.0);
    TEST_ASSERT_GREATER_OR_EQUAL(5, 5);
    TEST_ASSERT_GREATER_OR_EQUAL(5, 6);
    TEST_ASSERT_LESS_THAN(5, 4);
    TEST_ASSERT_GREATER_THAN(5, 6);
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
    TEST_ASSERT_EQUAL_MEMORY(a, a, sizeof a);
    TEST_ASSERT_EQUAL_STRING("abc", "abc");
    TEST_ASSERT_EQUAL_STRING(NULL, NULL);
}

static void test_pass_early(void)
{
    TEST_PASS();
    TEST_FAIL_MESSAGE("not reached");
}

static void test_pass_with_message(void)
{
    TEST_MESSAGE("hello");
}

static void test_fail_equal_int(void)
{
    TEST_ASSERT_EQUAL_INT(5, 6);
    ran_past_failure = 1;
}

static void test_pass_failure_aborted_test(void)
{
    TEST_ASSERT_EQUAL_INT(0, ran_past_failure);
    /* every test so far ran setUp and tearDown, failed or not */
    TEST_ASSERT_EQUAL_INT(setup_calls - 1, teardown_calls);
}

static void test_fail_equal_message(void)
{
    TEST_ASSERT_EQUAL_MESSAGE(1, 2, "pixel (3, 4)");
}

static void test_fail_assert(void)
{
    TEST_ASSERT(1 == 2);
}

static void test_fail_assert_true(void)
{
    TEST_ASSERT_TRUE(0);
}

static void test_fail_assert_false(void)
{
    TEST_ASSERT_FALSE(1);
}

static void test_fail_assert_message(void)
{
    TEST_ASSERT_MESSAGE(0, "custom text");
}

static void test_fail_uint8(void)
{
    TEST_ASSERT_EQUAL_UINT8(0x1FF, 0x100);
}

static void test_fail_uint(void)
{
    TEST_ASSERT_EQUAL_UINT(1u, 4000000000u);
}

static void test_fail_hex16(void)
{
    TEST_ASSERT_EQUAL_HEX16(0xBEEF, 0xBEEE);
}

static void test_fail_hex32_message(void)
{
    TEST_ASSERT_EQUAL_HEX32_MESSAGE(0xDEADBEEFu, 0xABCu, "word 7");
}

static void test_fail_int64(void)
{
    TEST_ASSERT_EQUAL_INT64(INT64_MIN, INT64_MAX);
}

static void test_fail_not_equal(void)
{
    TEST_ASSERT_NOT_EQUAL(3, 3);
}

static void test_fail_null(void)
{
    int x = 0;
    TEST_ASSERT_NULL(&x);
}

static void test_fail_not_null(void)
{
    TEST_ASSERT_NOT_NULL(NULL);
}

static void test_fail_int_within(void)
{
    TEST_ASSERT_INT_WITHIN(2, 10, 13);
}

static void test_fail_uint32_within(void)
{
    TEST_ASSERT_UINT32_WITHIN(1, 0u, 0xFFFFFFFFu);
}

static void test_fail_double_within(void)
{
    TEST_ASSERT_DOUBLE_WITHIN(0.1, 1.5, 1.75);
}

static void test_fail_double_within_nan(void)
{
    TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(1.0, 0.0, NAN, "nan");
}

static void test_fail_less_or_equal(void)
{
    TEST_ASSERT_LESS_OR_EQUAL(5, 7);
}

static void test_fail_less_or_equal_double(void)
{
    TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(0.25, 0.5);
}

static void test_fail_greater_or_equal(void)
{
    TEST_ASSERT_GREATER_OR_EQUAL(5, 4);
}

static void test_fail_less_than(void)
{
    TEST_ASSERT_LESS_THAN(5, 5);
}

static void test_fail_greater_than(void)
{
    TEST_ASSERT_GREATER_THAN(-1, -2);
}

static void test_fail_memory(void)
{
    static const unsigned char a[4] = {1, 2, 3, 4};
    static const unsigned char b[4] = {1, 2, 0x33, 4};
    TEST_ASSERT_EQUAL_MEMORY(a, b, sizeof a);
}

static void test_fail_memory_null(void)
{
    static const unsigned char a[1] = {1};
    TEST_ASSERT_EQUAL_MEMORY(a, NULL, 1);
}

static void test_fail_string(void)
{
    TEST_ASSERT_EQUAL_STRING("abc", "ab\n");
}

static void test_fail_string_null(void)
{
    TEST_ASSERT_EQUAL_STRING(NULL, "x");
}

static void test_fail_plain(void)
{
    TEST_FAIL();
}

static void test_fail_with_message(void)
{
    TEST_FAIL_MESSAGE("boom");
}

static void test_ignore_plain(void)
{
    TEST_IGNORE();
}

static void test_ignore_with_message(void)
{
    TEST_IGNORE_MESSAGE("later");
    TEST_FAIL_MESSAGE("not reached");
}

static void test_pass_counts_so_far(void)
{
    TEST_ASSERT_EQUAL_INT(setup_calls - 1, teardown_calls);
    TEST_ASSERT_EQUAL_INT(0, ran_past_failure);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_pass_every_macro);
    RUN_TEST(test_pass_early);
    RUN_TEST(test_pass_with_message);
    RUN_TEST(test_fail_equal_int);
    RUN_TEST(test_pass_failure_aborted_test);
    RUN_TEST(test_fail_equal_message);
    RUN_TEST(test_fail_assert);
    RUN_TEST(test_fail_assert_true);
    RUN_TEST(test_fail_assert_false);
    RUN_TEST(test_fail_assert_message);
    RUN_TEST(test_fail_uint8);
    RUN_TEST(test_fail_uint);
    RUN_TEST(test_fail_hex16);
    RUN_TEST(test_fail_hex32_message);
    RUN_TEST(test_fail_int64);
    RUN_TEST(test_fail_not_equal);
    RUN_TEST(test_fail_null);
    RUN_TEST(test_fail_not_null);
    RUN_TEST(test_fail_int_within);
    RUN_TEST(test_fail_uint32_within);
    RUN_TEST(test_fail_double_within);
    RUN_TEST(test_fail_double_within_nan);
    RUN_TEST(test_fail_less_or_equal);
    RUN_TEST(test_fail_less_or_equal_double);
    RUN_TEST(test_fail_greater_or_equal);
    RUN_TEST(test_fail_less_than);
    RUN_TEST(test_fail_greater_than);
    RUN_TEST(test_fail_memory);
    RUN_TEST(test_fail_memory_null);
    RUN_TEST(test_fail_string);
    RUN_TEST(test_fail_string_null);
    RUN_TEST(test_fail_plain);
    RUN_TEST(test_fail_with_message);
    RUN_TEST(test_ignore_plain);
    RUN_TEST(test_ignore_with_message);
    RUN_TEST(test_pass_counts_so_far);
    return UNITY_END();
}

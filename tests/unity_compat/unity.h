/* tests/unity_compat/unity.h - stand-in for the Unity 2.6 test framework.
 *
 * Used only when the real Unity (ThrowTheSwitch, v2.6.1) can be neither found
 * nor downloaded; see README.md next to this file. It implements a fixed
 * subset of Unity's assertion macros with Unity's semantics and output, so a
 * test written against it compiles and behaves the same with real Unity.
 * Do not use anything from this header that Unity 2.6.1 does not have.
 *
 * Semantics kept from Unity:
 *   - integer asserts compare in a 64-bit signed type after casting each
 *     argument to the width named by the macro (TEST_ASSERT_EQUAL_UINT8 casts
 *     to uint8_t first); every argument is evaluated exactly once;
 *   - comparisons take (threshold, actual): TEST_ASSERT_LESS_THAN(5, x)
 *     passes when x < 5; WITHIN takes (delta, expected, actual);
 *   - a failing assertion ends the current test with longjmp; tearDown()
 *     still runs; any assertion reached after a failure also ends the test.
 *   - tests define setUp() and tearDown() themselves (no weak defaults).
 */
#ifndef UNITY_FRAMEWORK_H
#define UNITY_FRAMEWORK_H

/* Lets a build tell the two apart; tests must not depend on it. */
#define FXL_UNITY_COMPAT 1

/* Unity 2.6 pulls these in through unity_internals.h; tests may rely on it. */
#include <limits.h>
#include <math.h>
#include <setjmp.h>
#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

void setUp(void);
void tearDown(void);

typedef void (*fxl_unity_test_fn)(void);

/* Display styles: how a failing value is printed. */
enum {
    FXL_UNITY_STYLE_INT,
    FXL_UNITY_STYLE_UINT,
    FXL_UNITY_STYLE_HEX8,
    FXL_UNITY_STYLE_HEX16,
    FXL_UNITY_STYLE_HEX32
};

/* Comparison flags for the threshold asserts. */
enum {
    FXL_UNITY_CMP_GT = 1,
    FXL_UNITY_CMP_LT = 2,
    FXL_UNITY_CMP_EQ = 4
};

/* Runner state. Only the macros below touch it. */
struct fxl_unity_state {
    const char *file;          /* __FILE__ of UNITY_BEGIN(), printed on every line */
    const char *test_name;
    long test_line;            /* line of the RUN_TEST() */
    unsigned long tests;
    unsigned long failures;
    unsigned long ignores;
    int current_failed;
    int current_ignored;
    int in_test;               /* abort_frame is valid */
    jmp_buf abort_frame;
};
extern struct fxl_unity_state fxl_unity;

void fxl_unity_begin(const char *file);
int fxl_unity_end(void);
void fxl_unity_run(fxl_unity_test_fn fn, const char *name, int line);
void fxl_unity_abort(void);

void fxl_unity_fail(const char *msg, long line);
void fxl_unity_ignore(const char *msg, long line);
void fxl_unity_message(const char *msg, long line);
void fxl_unity_assert_number(int64_t expected, int64_t actual, const char *msg,
                             long line, int style);
void fxl_unity_assert_within(uint64_t delta, int64_t expected, int64_t actual,
                             const char *msg, long line, int style);
void fxl_unity_assert_compare(int64_t threshold, int64_t actual, int cmp,
                              const char *msg, long line, int style);
void fxl_unity_assert_double_within(double delta, double expected, double actual,
                                    const char *msg, long line);
void fxl_unity_assert_double_compare(double threshold, double actual, int cmp,
                                     const char *msg, long line);
void fxl_unity_assert_memory(const void *expected, const void *actual,
                             uint32_t length, const char *msg, long line);
void fxl_unity_assert_string(const char *expected, const char *actual,
                             const char *msg, long line);

/* ---- running ----------------------------------------------------------- */

#define UNITY_BEGIN() fxl_unity_begin(__FILE__)
#define UNITY_END() fxl_unity_end()

/* RUN_TEST(fn) or RUN_TEST(fn, line), as in Unity 2.6. */
#define RUN_TEST(...) FXL_UNITY_RUN_AT(__VA_ARGS__, __LINE__, unused)
#define FXL_UNITY_RUN_AT(func, line, ...) fxl_unity_run(func, #func, (line))

/* setjmp must be the whole controlling expression of an if (C99 7.13.1.1). */
#define TEST_PROTECT() (setjmp(fxl_unity.abort_frame) == 0)
#define TEST_ABORT() fxl_unity_abort()

/* ---- control ------------------------------------------------------------- */

#define TEST_FAIL_MESSAGE(message) fxl_unity_fail((message), (long)__LINE__)
#define TEST_FAIL() fxl_unity_fail(NULL, (long)__LINE__)
#define TEST_IGNORE() fxl_unity_ignore(NULL, (long)__LINE__)
#define TEST_IGNORE_MESSAGE(message) fxl_unity_ignore((message), (long)__LINE__)
#define TEST_MESSAGE(message) fxl_unity_message((message), (long)__LINE__)
#define TEST_PASS() TEST_ABORT()

/* ---- booleans and pointers ---------------------------------------------- */

#define FXL_UNITY_CHECK(condition, message)                                   \
    do {                                                                      \
        if (!(condition)) {                                                   \
            fxl_unity_fail((message), (long)__LINE__);                        \
        }                                                                     \
    } while (0)

#define TEST_ASSERT(condition) \
    FXL_UNITY_CHECK(condition, " Expression Evaluated To FALSE")
#define TEST_ASSERT_MESSAGE(condition, message) FXL_UNITY_CHECK(condition, message)
#define TEST_ASSERT_TRUE(condition) FXL_UNITY_CHECK(condition, " Expected TRUE Was FALSE")
#define TEST_ASSERT_TRUE_MESSAGE(condition, message) FXL_UNITY_CHECK(condition, message)
#define TEST_ASSERT_FALSE(condition) FXL_UNITY_CHECK(!(condition), " Expected FALSE Was TRUE")
#define TEST_ASSERT_NULL(pointer) FXL_UNITY_CHECK((pointer) == NULL, " Expected NULL")
#define TEST_ASSERT_NOT_NULL(pointer) FXL_UNITY_CHECK((pointer) != NULL, " Expected Non-NULL")
#define TEST_ASSERT_NOT_EQUAL(expected, actual) \
    FXL_UNITY_CHECK((expected) != (actual), " Expected Not-Equal")

/* ---- integer equality ----------------------------------------------------- */

#define FXL_UNITY_EQ(e, a, msg, style) \
    fxl_unity_assert_number((e), (a), (msg), (long)__LINE__, (style))

#define TEST_ASSERT_EQUAL_INT(expected, actual) \
    FXL_UNITY_EQ((int64_t)(expected), (int64_t)(actual), NULL, FXL_UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL_INT_MESSAGE(expected, actual, message) \
    FXL_UNITY_EQ((int64_t)(expected), (int64_t)(actual), (message), FXL_UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL(expected, actual) TEST_ASSERT_EQUAL_INT(expected, actual)
#define TEST_ASSERT_EQUAL_MESSAGE(expected, actual, message) \
    TEST_ASSERT_EQUAL_INT_MESSAGE(expected, actual, message)
#define TEST_ASSERT_EQUAL_INT32(expected, actual)                                 \
    FXL_UNITY_EQ((int64_t)(int32_t)(expected), (int64_t)(int32_t)(actual), NULL, \
                 FXL_UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL_INT64(expected, actual) \
    FXL_UNITY_EQ((int64_t)(expected), (int64_t)(actual), NULL, FXL_UNITY_STYLE_INT)
#define TEST_ASSERT_EQUAL_UINT(expected, actual) \
    FXL_UNITY_EQ((int64_t)(expected), (int64_t)(actual), NULL, FXL_UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_UINT8(expected, actual)                                 \
    FXL_UNITY_EQ((int64_t)(uint8_t)(expected), (int64_t)(uint8_t)(actual), NULL, \
                 FXL_UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_UINT16(expected, actual)                                  \
    FXL_UNITY_EQ((int64_t)(uint16_t)(expected), (int64_t)(uint16_t)(actual), NULL, \
                 FXL_UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_UINT32(expected, actual)                                  \
    FXL_UNITY_EQ((int64_t)(uint32_t)(expected), (int64_t)(uint32_t)(actual), NULL, \
                 FXL_UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_UINT32_MESSAGE(expected, actual, message)                \
    FXL_UNITY_EQ((int64_t)(uint32_t)(expected), (int64_t)(uint32_t)(actual),      \
                 (message), FXL_UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_UINT64(expected, actual) \
    FXL_UNITY_EQ((int64_t)(expected), (int64_t)(actual), NULL, FXL_UNITY_STYLE_UINT)
#define TEST_ASSERT_EQUAL_HEX16(expected, actual)                                 \
    FXL_UNITY_EQ((int64_t)(int16_t)(expected), (int64_t)(int16_t)(actual), NULL, \
                 FXL_UNITY_STYLE_HEX16)
#define TEST_ASSERT_EQUAL_HEX32(expected, actual)                                 \
    FXL_UNITY_EQ((int64_t)(int32_t)(expected), (int64_t)(int32_t)(actual), NULL, \
                 FXL_UNITY_STYLE_HEX32)
#define TEST_ASSERT_EQUAL_HEX32_MESSAGE(expected, actual, message)                \
    FXL_UNITY_EQ((int64_t)(int32_t)(expected), (int64_t)(int32_t)(actual),       \
                 (message), FXL_UNITY_STYLE_HEX32)

/* ---- integer ranges ------------------------------------------------------- */

#define TEST_ASSERT_INT_WITHIN(delta, expected, actual)                        \
    fxl_unity_assert_within((uint64_t)(delta), (int64_t)(expected),            \
                            (int64_t)(actual), NULL, (long)__LINE__,           \
                            FXL_UNITY_STYLE_INT)
#define TEST_ASSERT_INT32_WITHIN(delta, expected, actual)                       \
    fxl_unity_assert_within((uint64_t)(uint32_t)(delta),                        \
                            (int64_t)(int32_t)(expected),                       \
                            (int64_t)(int32_t)(actual), NULL, (long)__LINE__,   \
                            FXL_UNITY_STYLE_INT)
#define TEST_ASSERT_UINT32_WITHIN(delta, expected, actual)                      \
    fxl_unity_assert_within((uint64_t)(uint32_t)(delta),                        \
                            (int64_t)(uint32_t)(expected),                      \
                            (int64_t)(uint32_t)(actual), NULL, (long)__LINE__,  \
                            FXL_UNITY_STYLE_UINT)

#define FXL_UNITY_CMP(threshold, actual, cmp)                                  \
    fxl_unity_assert_compare((int64_t)(threshold), (int64_t)(actual), (cmp),   \
                             NULL, (long)__LINE__, FXL_UNITY_STYLE_INT)

#define TEST_ASSERT_GREATER_THAN(threshold, actual) \
    FXL_UNITY_CMP(threshold, actual, FXL_UNITY_CMP_GT)
#define TEST_ASSERT_LESS_THAN(threshold, actual) \
    FXL_UNITY_CMP(threshold, actual, FXL_UNITY_CMP_LT)
#define TEST_ASSERT_GREATER_OR_EQUAL(threshold, actual) \
    FXL_UNITY_CMP(threshold, actual, FXL_UNITY_CMP_GT | FXL_UNITY_CMP_EQ)
#define TEST_ASSERT_LESS_OR_EQUAL(threshold, actual) \
    FXL_UNITY_CMP(threshold, actual, FXL_UNITY_CMP_LT | FXL_UNITY_CMP_EQ)

/* ---- floating point -------------------------------------------------------- */

#define TEST_ASSERT_DOUBLE_WITHIN(delta, expected, actual)                     \
    fxl_unity_assert_double_within((double)(delta), (double)(expected),        \
                                   (double)(actual), NULL, (long)__LINE__)
#define TEST_ASSERT_DOUBLE_WITHIN_MESSAGE(delta, expected, actual, message)    \
    fxl_unity_assert_double_within((double)(delta), (double)(expected),        \
                                   (double)(actual), (message), (long)__LINE__)
#define TEST_ASSERT_LESS_OR_EQUAL_DOUBLE(threshold, actual)                    \
    fxl_unity_assert_double_compare((double)(threshold), (double)(actual),     \
                                    FXL_UNITY_CMP_LT | FXL_UNITY_CMP_EQ, NULL, \
                                    (long)__LINE__)

/* ---- memory and strings ----------------------------------------------------- */

#define TEST_ASSERT_EQUAL_MEMORY(expected, actual, len)                       \
    fxl_unity_assert_memory((expected), (actual), (uint32_t)(len), NULL,      \
                            (long)__LINE__)
#define TEST_ASSERT_EQUAL_STRING(expected, actual)                            \
    fxl_unity_assert_string((const char *)(expected), (const char *)(actual), \
                            NULL, (long)__LINE__)

#ifdef __cplusplus
}
#endif

#endif /* UNITY_FRAMEWORK_H */

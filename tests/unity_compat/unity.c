/* tests/unity_compat/unity.c - runner behind tests/unity_compat/unity.h.
 *
 * Output follows Unity 2.6 without colour, one line per test:
 *   <file>:<line>:<test>:PASS
 *   <file>:<line>:<test>:FAIL: Expected 5 Was 6. <optional message>
 *   <file>:<line>:<test>:IGNORE[: message]
 *   <file>:<line>:<test>:INFO: message            (TEST_MESSAGE)
 * then an empty line, a line of 23 dashes, "N Tests M Failures K Ignored "
 * and "OK" or "FAIL". <file> is the __FILE__ seen by UNITY_BEGIN(); the line
 * of a PASS is the line of its RUN_TEST(). UNITY_END() returns the number of
 * failures, capped at 255 so that a process exit status never wraps to 0.
 *
 * stdout is flushed after every line: when a sanitizer kills a test, the
 * lines of the tests that ran before it still reach the ctest log.
 */
#include "unity.h"

#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

struct fxl_unity_state fxl_unity;

static const char str_expected[] = " Expected ";
static const char str_was[] = " Was ";
static const char str_spacer[] = ". ";

/* ---- output ----------------------------------------------------------------- */

static void put_char(char c)
{
    (void)putchar((unsigned char)c);
}

static void put_hex(uint64_t value, int nibbles)
{
    static const char digits[] = "0123456789ABCDEF";
    while (nibbles > 0) {
        nibbles--;
        put_char(digits[(value >> (4 * nibbles)) & 0xFu]);
    }
}

/* Printable ASCII goes out as is; CR, LF and anything else are escaped so a
 * result stays on one line. */
static void put_text(const char *s)
{
    if (s == NULL) {
        return;
    }
    for (; *s != '\0'; s++) {
        unsigned char c = (unsigned char)*s;
        if (c >= 32 && c <= 126) {
            put_char((char)c);
        } else if (c == '\r') {
            put_char('\\');
            put_char('r');
        } else if (c == '\n') {
            put_char('\\');
            put_char('n');
        } else {
            put_char('\\');
            put_char('x');
            put_hex(c, 2);
        }
    }
}

static void put_eol(void)
{
    put_char('\n');
    (void)fflush(stdout);
}

static void put_number(int64_t value, int style)
{
    switch (style) {
    case FXL_UNITY_STYLE_INT:
        printf("%" PRId64, value);
        break;
    case FXL_UNITY_STYLE_UINT:
        printf("%" PRIu64, (uint64_t)value);
        break;
    case FXL_UNITY_STYLE_HEX8:
        fputs("0x", stdout);
        put_hex((uint64_t)value, 2);
        break;
    case FXL_UNITY_STYLE_HEX16:
        fputs("0x", stdout);
        put_hex((uint64_t)value, 4);
        break;
    default:
        fputs("0x", stdout);
        put_hex((uint64_t)value, 8);
        break;
    }
}

/* Like printf("%.9g"), the precision Unity uses with double support on. */
static void put_double(double value)
{
    if (isnan(value)) {
        fputs("nan", stdout);
    } else if (isinf(value)) {
        fputs(value < 0.0 ? "-inf" : "inf", stdout);
    } else if (value == 0.0) {
        fputs("0", stdout); /* Unity prints no sign for -0.0 */
    } else {
        printf("%.9g", value);
    }
}

static void put_line_start(long line)
{
    put_text(fxl_unity.file);
    put_char(':');
    printf("%ld", line);
    put_char(':');
    put_text(fxl_unity.test_name);
    put_char(':');
}

static void put_fail_start(long line)
{
    put_line_start(line);
    put_text("FAIL:");
}

static void put_message(const char *msg)
{
    if (msg != NULL) {
        put_text(str_spacer);
        put_text(msg);
    }
}

/* ---- control flow ------------------------------------------------------------ */

void fxl_unity_abort(void)
{
    if (!fxl_unity.in_test) {
        /* An assertion outside RUN_TEST has no frame to return to. */
        put_eol();
        put_text("unity_compat: assertion outside of a test");
        put_eol();
        exit(EXIT_FAILURE);
    }
    longjmp(fxl_unity.abort_frame, 1);
}

/* Unity ends the test at any assertion once it has failed or been ignored,
 * even one that would pass (this matters in tearDown after a failure). */
static void stop_if_done(void)
{
    if (fxl_unity.current_failed || fxl_unity.current_ignored) {
        fxl_unity_abort();
    }
}

static void fail_and_bail(void)
{
    fxl_unity.current_failed = 1;
    (void)fflush(stdout);
    fxl_unity_abort();
}

void fxl_unity_begin(const char *file)
{
    fxl_unity.file = file;
    fxl_unity.test_name = NULL;
    fxl_unity.test_line = 0;
    fxl_unity.tests = 0;
    fxl_unity.failures = 0;
    fxl_unity.ignores = 0;
    fxl_unity.current_failed = 0;
    fxl_unity.current_ignored = 0;
    fxl_unity.in_test = 0;
}

void fxl_unity_run(fxl_unity_test_fn fn, const char *name, int line)
{
    fxl_unity.test_name = name;
    fxl_unity.test_line = line;
    fxl_unity.tests++;
    fxl_unity.in_test = 1;
    if (TEST_PROTECT()) {
        setUp();
        fn();
    }
    if (TEST_PROTECT()) {
        tearDown();
    }
    fxl_unity.in_test = 0;

    if (fxl_unity.current_ignored) {
        fxl_unity.ignores++;
    } else if (!fxl_unity.current_failed) {
        put_line_start(fxl_unity.test_line);
        put_text("PASS");
    } else {
        fxl_unity.failures++;
    }
    fxl_unity.current_failed = 0;
    fxl_unity.current_ignored = 0;
    put_eol();
}

int fxl_unity_end(void)
{
    put_eol();
    put_text("-----------------------");
    put_eol();
    printf("%lu Tests %lu Failures %lu Ignored ", fxl_unity.tests,
           fxl_unity.failures, fxl_unity.ignores);
    put_eol();
    put_text(fxl_unity.failures == 0 ? "OK" : "FAIL");
    put_eol();
    return fxl_unity.failures > 255 ? 255 : (int)fxl_unity.failures;
}

void fxl_unity_fail(const char *msg, long line)
{
    stop_if_done();
    put_line_start(line);
    put_text("FAIL");
    if (msg != NULL) {
        put_char(':');
        if (msg[0] != ' ') {
            put_char(' ');
        }
        put_text(msg);
    }
    fail_and_bail();
}

void fxl_unity_ignore(const char *msg, long line)
{
    stop_if_done();
    put_line_start(line);
    put_text("IGNORE");
    if (msg != NULL) {
        put_text(": ");
        put_text(msg);
    }
    fxl_unity.current_ignored = 1;
    (void)fflush(stdout);
    fxl_unity_abort();
}

void fxl_unity_message(const char *msg, long line)
{
    put_line_start(line);
    put_text("INFO");
    if (msg != NULL) {
        put_text(": ");
        put_text(msg);
    }
    put_eol();
}

/* ---- assertions ------------------------------------------------------------ */

void fxl_unity_assert_number(int64_t expected, int64_t actual, const char *msg,
                             long line, int style)
{
    stop_if_done();
    if (expected != actual) {
        put_fail_start(line);
        put_text(str_expected);
        put_number(expected, style);
        put_text(str_was);
        put_number(actual, style);
        put_message(msg);
        fail_and_bail();
    }
}

void fxl_unity_assert_within(uint64_t delta, int64_t expected, int64_t actual,
                             const char *msg, long line, int style)
{
    uint64_t diff;

    stop_if_done();
    /* The distance is computed in unsigned arithmetic, which is exact modulo
     * 2^64 and so never overflows for any pair of 64-bit values. */
    if (style == FXL_UNITY_STYLE_INT) {
        diff = actual > expected ? (uint64_t)actual - (uint64_t)expected
                                 : (uint64_t)expected - (uint64_t)actual;
    } else {
        diff = (uint64_t)actual > (uint64_t)expected
                   ? (uint64_t)actual - (uint64_t)expected
                   : (uint64_t)expected - (uint64_t)actual;
    }
    if (diff > delta) {
        put_fail_start(line);
        put_text(" Values Not Within Delta ");
        put_number((int64_t)delta, style);
        put_text(str_expected);
        put_number(expected, style);
        put_text(str_was);
        put_number(actual, style);
        put_message(msg);
        fail_and_bail();
    }
}

static void put_comparison(int cmp)
{
    if (cmp & FXL_UNITY_CMP_GT) {
        put_text(" to be greater than ");
    }
    if (cmp & FXL_UNITY_CMP_LT) {
        put_text(" to be less than ");
    }
    if (cmp & FXL_UNITY_CMP_EQ) {
        put_text("or equal to ");
    }
}

void fxl_unity_assert_compare(int64_t threshold, int64_t actual, int cmp,
                              const char *msg, long line, int style)
{
    int failed;

    stop_if_done();
    if (actual == threshold) {
        failed = !(cmp & FXL_UNITY_CMP_EQ);
    } else if (style == FXL_UNITY_STYLE_INT) {
        failed = ((cmp & FXL_UNITY_CMP_LT) && actual > threshold) ||
                 ((cmp & FXL_UNITY_CMP_GT) && actual < threshold);
    } else {
        failed = ((cmp & FXL_UNITY_CMP_LT) && (uint64_t)actual > (uint64_t)threshold) ||
                 ((cmp & FXL_UNITY_CMP_GT) && (uint64_t)actual < (uint64_t)threshold);
    }
    if (failed) {
        put_fail_start(line);
        put_text(str_expected);
        put_number(actual, style);
        put_comparison(cmp);
        put_number(threshold, style);
        put_message(msg);
        fail_and_bail();
    }
}

/* Unity's rule: equal infinities and two NaNs are "within"; otherwise a NaN
 * or infinite difference never is. */
static int doubles_within(double delta, double expected, double actual)
{
    double diff;

    if (isinf(expected) && isinf(actual) && ((expected < 0.0) == (actual < 0.0))) {
        return 1;
    }
    if (isnan(expected) && isnan(actual)) {
        return 1;
    }
    diff = actual - expected;
    if (diff < 0.0) {
        diff = -diff;
    }
    if (delta < 0.0) {
        delta = -delta;
    }
    return !(isnan(diff) || isinf(diff) || diff > delta);
}

void fxl_unity_assert_double_within(double delta, double expected, double actual,
                                    const char *msg, long line)
{
    stop_if_done();
    if (!doubles_within(delta, expected, actual)) {
        put_fail_start(line);
        put_text(str_expected);
        put_double(expected);
        put_text(str_was);
        put_double(actual);
        put_message(msg);
        fail_and_bail();
    }
}

/* Unity 2.6 tests for "not success" so that NaN fails every comparison, and
 * accepts equality within a relative 1e-12 (UNITY_DOUBLE_PRECISION). */
void fxl_unity_assert_double_compare(double threshold, double actual, int cmp,
                                     const char *msg, long line)
{
    int failed = 0;

    stop_if_done();
    if ((cmp & FXL_UNITY_CMP_LT) && !(actual < threshold)) {
        failed = 1;
    }
    if ((cmp & FXL_UNITY_CMP_GT) && !(actual > threshold)) {
        failed = 1;
    }
    if ((cmp & FXL_UNITY_CMP_EQ) && doubles_within(threshold * 1e-12, threshold, actual)) {
        failed = 0;
    }
    if (failed) {
        put_fail_start(line);
        put_text(str_expected);
        put_double(actual);
        put_comparison(cmp);
        put_double(threshold);
        put_message(msg);
        fail_and_bail();
    }
}

void fxl_unity_assert_memory(const void *expected, const void *actual,
                             uint32_t length, const char *msg, long line)
{
    const unsigned char *e = (const unsigned char *)expected;
    const unsigned char *a = (const unsigned char *)actual;
    uint32_t i;

    stop_if_done();
    if (length == 0) {
        put_fail_start(line);
        put_text(" You Asked Me To Compare Nothing, Which Was Pointless.");
        put_message(msg);
        fail_and_bail();
    }
    if (expected == actual) {
        return;
    }
    if (expected == NULL || actual == NULL) {
        put_fail_start(line);
        put_text(expected == NULL ? " Expected pointer to be NULL"
                                  : " Actual pointer was NULL");
        put_message(msg);
        fail_and_bail();
    }
    for (i = 0; i < length; i++) {
        if (e[i] != a[i]) {
            put_fail_start(line);
            put_text(" Memory Mismatch. Byte ");
            printf("%" PRIu32, i);
            put_text(str_expected);
            put_number(e[i], FXL_UNITY_STYLE_HEX8);
            put_text(str_was);
            put_number(a[i], FXL_UNITY_STYLE_HEX8);
            put_message(msg);
            fail_and_bail();
        }
    }
}

static void put_quoted(const char *s)
{
    if (s == NULL) {
        put_text("NULL");
    } else {
        put_char('\'');
        put_text(s);
        put_char('\'');
    }
}

void fxl_unity_assert_string(const char *expected, const char *actual,
                             const char *msg, long line)
{
    int differ = 0;

    stop_if_done();
    if (expected != NULL && actual != NULL) {
        size_t i;
        for (i = 0; expected[i] != '\0' || actual[i] != '\0'; i++) {
            if (expected[i] != actual[i]) {
                differ = 1;
                break;
            }
        }
    } else {
        differ = expected != actual;
    }
    if (differ) {
        put_fail_start(line);
        put_text(str_expected);
        put_quoted(expected);
        put_text(str_was);
        put_quoted(actual);
        put_message(msg);
        fail_and_bail();
    }
}

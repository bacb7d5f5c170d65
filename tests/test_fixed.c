/* test_fixed.c - q16 arithmetic, clz and 64-bit division at their edges.
 *
 * Expected values come from three places:
 *  - hand-derived edge cases, with the derivation next to the assertion;
 *  - an integer reference written differently from src/fixed.c (signed C
 *    division and remainder, then a half-away-from-zero fix-up);
 *  - a long double reference (C's roundl rounds half away from zero, the
 *    same rule as fixel), used where the value is exact in the type.
 * Every comparison is exact: the contract is round-to-nearest, so the allowed
 * error is 0 ulp. Random inputs come from a fixed LCG seed so runs repeat.
 */
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <string.h>

#include "unity.h"
#include "fixel/fixed.h"
/* the Cortex-M0+ products (four 16 x 16-bit halves), checked here on the
 * host, also inside the reciprocal division's high product */
#define FXL__MUL_HALVES 1
#define FXL__DIV_TABLE 1
#include "../src/div64.h"
#include "../src/persp.h"
#include "../src/clz.h"
#include "../src/isqrt.h"
#include "../src/recip_run.h"

#define RANDOM_ITERS 200000

void setUp(void) {}
void tearDown(void) {}

/* ---------------------------------------------------------------------- */
/* Helpers                                                                */

static uint32_t lcg_state;

static void lcg_seed(uint32_t s) { lcg_state = s; }

/* Numerical Recipes LCG; only the high bits are used where quality matters. */
static uint32_t lcg_next(void)
{
    lcg_state = lcg_state * 1664525u + 1013904223u;
    return lcg_state;
}

static uint32_t rand32(void)
{
    uint32_t hi = lcg_next() >> 16;
    uint32_t lo = lcg_next() >> 16;
    return (hi << 16) | lo;
}

static uint64_t rand64(void)
{
    return ((uint64_t)rand32() << 32) | rand32();
}

/* A q16 with a log-uniform magnitude (so tiny, medium and huge values all
 * show up), a random sign, and now and then an extreme value. */
static fxl_q16_t rand_q16(void)
{
    uint32_t pick = lcg_next() >> 24;
    uint32_t shift = (lcg_next() >> 27) + 1u; /* 1..32 */
    uint32_t mag;
    if (pick == 0) return FXL_Q16_MIN;
    if (pick == 1) return FXL_Q16_MAX;
    if (pick == 2) return 0;
    mag = shift >= 32u ? 0u : rand32() >> shift; /* <= 2^31 - 1 */
    return (lcg_next() & 0x80000000u) ? -(int32_t)mag : (int32_t)mag;
}

static int64_t rand_i64_wide(void)
{
    uint32_t pick = lcg_next() >> 26;
    uint32_t shift = lcg_next() >> 26; /* 0..63 */
    uint64_t mag;
    if (pick == 0) return INT64_MIN;
    if (pick == 1) return INT64_MAX;
    mag = (rand64() >> 1) >> shift; /* <= 2^63 - 1 */
    return (lcg_next() & 0x80000000u) ? -(int64_t)mag : (int64_t)mag;
}

/* round(n / d), ties away from zero, for |n| < 2^62 and d != 0: signed C
 * division truncates toward zero, so bump the quotient away from zero when
 * the remainder is at least half the divisor. */
static int64_t ref_round_div(int64_t n, int64_t d)
{
    int64_t q = n / d, r = n % d;
    int64_t ar = r < 0 ? -r : r, ad = d < 0 ? -d : d;
    if (2 * ar >= ad) {
        q += ((n < 0) != (d < 0)) ? -1 : 1;
    }
    return q;
}

static int64_t clamp_i32(int64_t v)
{
    return v > INT32_MAX ? INT32_MAX : (v < INT32_MIN ? INT32_MIN : v);
}

static char msg[160];

#define SENTINEL ((fxl_q16_t)0x5A5A5A5A)

/* int64 equality with a message (Unity's _INT_MESSAGE compares as int). */
#define ASSERT_EQUAL_I64_MSG(expected, actual, message) \
    assert_equal_i64((expected), (actual), (message), __LINE__)

static void assert_equal_i64(int64_t expected, int64_t actual, const char *what, int line)
{
    static char buf[240];
    if (expected != actual) {
        snprintf(buf, sizeof buf, "line %d: expected %lld, got %lld (off by %.0f) for %s", line,
                 (long long)expected, (long long)actual, (double)actual - (double)expected,
                 what);
        TEST_FAIL_MESSAGE(buf);
    }
}

#define ASSERT_STATUS(expected, actual) \
    TEST_ASSERT_EQUAL_INT_MESSAGE((int)(expected), (int)(actual), fxl_status_name(actual))

/* A _sat result, a _chk status and its output against the exact rounded
 * value ref of the same operation on (a, b), and the symmetry
 * sat(-a, b) = -sat(a, b) where both sides are in range: the _sat value is
 * ref clamped, the _chk value ref or FXL_ERR_RANGE with out untouched. */
static void assert_sat_chk(int64_t ref, fxl_q16_t a, fxl_q16_t sat, fxl_q16_t sat_neg_a, fxl_status_t st,
                           fxl_q16_t out, const char *msg)
{
    const int in_range = ref >= INT32_MIN && ref <= INT32_MAX;
    TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)clamp_i32(ref), sat, msg);
    if (in_range) {
        ASSERT_STATUS(FXL_OK, st);
        TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)ref, out, msg);
    } else {
        ASSERT_STATUS(FXL_ERR_RANGE, st);
        TEST_ASSERT_EQUAL_INT_MESSAGE(SENTINEL, out, msg);
    }
    if (a != FXL_Q16_MIN && in_range && ref != INT32_MIN) {
        TEST_ASSERT_EQUAL_INT_MESSAGE(-sat, sat_neg_a, msg);
    }
}

/* ---------------------------------------------------------------------- */
/* Conversions                                                            */

static void test_round_ties_go_away_from_zero(void)
{
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_round(0));
    TEST_ASSERT_EQUAL_INT32(1, fxl_q16_round(FXL_Q16_HALF));           /* +0.5 */
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_round(-FXL_Q16_HALF));         /* -0.5 */
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_round(FXL_Q16_HALF - 1));       /* 0.49998 */
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_round(-FXL_Q16_HALF + 1));
    TEST_ASSERT_EQUAL_INT32(2, fxl_q16_round(0x18000));                /* 1.5 */
    TEST_ASSERT_EQUAL_INT32(-2, fxl_q16_round(-0x18000));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_round(1));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_round(-1));
}

static void test_round_floor_ceil_at_int32_limits(void)
{
    /* MAX = 32767 + 65535/65536: rounds and ceils to 32768, floors to 32767.
     * MIN = -32768 exactly. */
    TEST_ASSERT_EQUAL_INT32(32768, fxl_q16_round(FXL_Q16_MAX));
    TEST_ASSERT_EQUAL_INT32(-32768, fxl_q16_round(FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(32767, fxl_q16_floor(FXL_Q16_MAX));
    TEST_ASSERT_EQUAL_INT32(-32768, fxl_q16_floor(FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(32768, fxl_q16_ceil(FXL_Q16_MAX));
    TEST_ASSERT_EQUAL_INT32(-32768, fxl_q16_ceil(FXL_Q16_MIN));
    /* MIN + 1 ulp = -32767.99998 */
    TEST_ASSERT_EQUAL_INT32(-32768, fxl_q16_round(FXL_Q16_MIN + 1));
    TEST_ASSERT_EQUAL_INT32(-32768, fxl_q16_floor(FXL_Q16_MIN + 1));
    TEST_ASSERT_EQUAL_INT32(-32767, fxl_q16_ceil(FXL_Q16_MIN + 1));
}

static void test_floor_ceil_small_values(void)
{
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_floor(0));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_ceil(0));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_floor(1));
    TEST_ASSERT_EQUAL_INT32(1, fxl_q16_ceil(1));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_floor(-1));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_ceil(-1));
    TEST_ASSERT_EQUAL_INT32(1, fxl_q16_floor(FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(1, fxl_q16_ceil(FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_floor(-FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_ceil(-FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_floor(-FXL_Q16_HALF));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_ceil(-FXL_Q16_HALF));
}

static void test_round_floor_ceil_match_libm_on_random_values(void)
{
    /* a / 65536 is exact in a double (31 significant bits), so floor, ceil
     * and round (half away from zero) of it are the exact references. */
    int i;
    lcg_seed(0x1234u);
    for (i = 0; i < RANDOM_ITERS; i++) {
        fxl_q16_t a = rand_q16();
        double x = (double)a / 65536.0;
        snprintf(msg, sizeof msg, "a=%ld", (long)a);
        TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)round(x), fxl_q16_round(a), msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)floor(x), fxl_q16_floor(a), msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)ceil(x), fxl_q16_ceil(a), msg);
        if (a != FXL_Q16_MIN) {
            TEST_ASSERT_EQUAL_INT_MESSAGE(-fxl_q16_round(a), fxl_q16_round(-a), msg);
        }
    }
}

static void test_from_int_sat_saturates_outside_q16_range(void)
{
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_from_int_sat(0));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, fxl_q16_from_int_sat(1));
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, fxl_q16_from_int_sat(-1));
    TEST_ASSERT_EQUAL_INT32(32767 * 65536, fxl_q16_from_int_sat(32767));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_from_int_sat(-32768)); /* exact */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_from_int_sat(32768));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_from_int_sat(-32769));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_from_int_sat(INT32_MAX));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_from_int_sat(INT32_MIN));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_INT(-5), fxl_q16_from_int_sat(-5));
}

/* ---------------------------------------------------------------------- */
/* Add, subtract                                                          */

static void test_add_sub_saturate_at_limits(void)
{
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_add_sat(FXL_Q16_MAX, 1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_add_sat(FXL_Q16_MAX, FXL_Q16_MAX));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_add_sat(FXL_Q16_MIN, -1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_add_sat(FXL_Q16_MIN, FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_add_sat(FXL_Q16_MIN, FXL_Q16_MAX));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_add_sat(FXL_Q16_MAX - 1, 1)); /* exact */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_add_sat(FXL_Q16_MIN + 1, -1)); /* exact */

    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_sub_sat(0, FXL_Q16_MIN)); /* +2^31 */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_sub_sat(FXL_Q16_MAX, FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_sub_sat(FXL_Q16_MIN, FXL_Q16_MAX));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_sub_sat(FXL_Q16_MIN, 1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_sub_sat(-1, FXL_Q16_MAX)); /* exact */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_sub_sat(-1, FXL_Q16_MIN)); /* exact */
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_sub_sat(FXL_Q16_MIN, FXL_Q16_MIN));
}

static void test_add_sub_match_wide_reference_on_random_values(void)
{
    int i;
    lcg_seed(0xADD5u);
    for (i = 0; i < RANDOM_ITERS; i++) {
        fxl_q16_t a = rand_q16(), b = rand_q16();
        snprintf(msg, sizeof msg, "a=%ld b=%ld", (long)a, (long)b);
        TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)clamp_i32((int64_t)a + b),
                                        fxl_q16_add_sat(a, b), msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)clamp_i32((int64_t)a - b),
                                        fxl_q16_sub_sat(a, b), msg);
    }
}

/* ---------------------------------------------------------------------- */
/* Multiply                                                               */

static void test_mul_identity_at_limits(void)
{
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_mul_sat(FXL_Q16_MAX, FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_mul_sat(FXL_Q16_MIN, FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_mul_sat(FXL_Q16_ONE, FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_MAX, fxl_q16_mul_sat(FXL_Q16_MAX, -FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_mul_sat(FXL_Q16_MIN, 0));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_mul_sat(0, FXL_Q16_MAX));
    /* MIN * 0.5 = -16384 exactly */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_INT(-16384), fxl_q16_mul_sat(FXL_Q16_MIN, FXL_Q16_HALF));
}

static void test_mul_rounds_half_ulp_away_from_zero(void)
{
    /* 1 ulp * 0.5 = 0.5 ulp -> 1 ulp; 1 ulp * (0.5 - 1 ulp) -> 0. */
    TEST_ASSERT_EQUAL_INT32(1, fxl_q16_mul_sat(1, FXL_Q16_HALF));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_mul_sat(-1, FXL_Q16_HALF));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_mul_sat(1, -FXL_Q16_HALF));
    TEST_ASSERT_EQUAL_INT32(1, fxl_q16_mul_sat(-1, -FXL_Q16_HALF));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_mul_sat(1, FXL_Q16_HALF - 1));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_mul_sat(-1, FXL_Q16_HALF - 1));
    /* 1 ulp * 1 ulp = 2^-32: rounds to 0 (never to -0 trouble). */
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_mul_sat(1, 1));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_mul_sat(-1, 1));
    /* 3 ulp * 0.5 = 1.5 ulp -> 2 ulp */
    TEST_ASSERT_EQUAL_INT32(2, fxl_q16_mul_sat(3, FXL_Q16_HALF));
    TEST_ASSERT_EQUAL_INT32(-2, fxl_q16_mul_sat(-3, FXL_Q16_HALF));
}

static void test_mul_saturates_and_chk_reports_range(void)
{
    fxl_q16_t out = SENTINEL;
    /* MIN * -1 = +2^31 ulp: one past MAX. */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_mul_sat(FXL_Q16_MIN, -FXL_Q16_ONE));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_mul_chk(FXL_Q16_MIN, -FXL_Q16_ONE, &out));
    TEST_ASSERT_EQUAL_INT32(SENTINEL, out);

    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_mul_sat(FXL_Q16_MAX, FXL_Q16_MAX));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_mul_sat(FXL_Q16_MIN, FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_mul_sat(FXL_Q16_MAX, FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_mul_sat(FXL_Q16_MIN, FXL_Q16_MAX));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_mul_chk(FXL_Q16_MAX, FXL_Q16_MIN, &out));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_mul_chk(FXL_Q16_MIN, FXL_Q16_MIN, &out));
    TEST_ASSERT_EQUAL_INT32(SENTINEL, out);

    /* 256 * 128 = 32768: one past the range, both signs of the operands. */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_mul_sat(FXL_Q16_INT(256), FXL_Q16_INT(128)));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_mul_sat(FXL_Q16_INT(-256), FXL_Q16_INT(-128)));
    /* -256 * 128 = -32768 = MIN exactly: representable. */
    ASSERT_STATUS(FXL_OK, fxl_q16_mul_chk(FXL_Q16_INT(-256), FXL_Q16_INT(128), &out));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, out);
}

static void test_mul_overflow_decided_after_rounding(void)
{
    /* a = 2^14 * 65537, b = 2 * 65535: a * b = 2^15 * (2^32 - 1), so
     * a * b / 2^16 = 2^31 - 0.5 exactly. Rounded away from zero that is 2^31:
     * one past MAX for a positive product, exactly MIN for a negative one. */
    const fxl_q16_t a = 1073758208, b = 131070;
    fxl_q16_t out = SENTINEL;
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_mul_sat(a, b));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_mul_chk(a, b, &out));
    TEST_ASSERT_EQUAL_INT32(SENTINEL, out);
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_mul_chk(-a, -b, &out));
    TEST_ASSERT_EQUAL_INT32(SENTINEL, out);
    ASSERT_STATUS(FXL_OK, fxl_q16_mul_chk(-a, b, &out));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, out);
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_mul_sat(a, -b));
}

static void test_mul_chk_null_out_is_arg_error(void)
{
    ASSERT_STATUS(FXL_ERR_ARG, fxl_q16_mul_chk(FXL_Q16_ONE, FXL_Q16_ONE, NULL));
}

static void test_mul_matches_references_on_random_values(void)
{
    int i;
    lcg_seed(0x6D756Cu);
    for (i = 0; i < RANDOM_ITERS; i++) {
        fxl_q16_t a = rand_q16(), b = rand_q16(), out = SENTINEL;
        int64_t p = (int64_t)a * b; /* |p| <= 2^62 */
        int64_t ref = ref_round_div(p, 65536);
        fxl_status_t st = fxl_q16_mul_chk(a, b, &out);
        snprintf(msg, sizeof msg, "a=%ld b=%ld ref=%lld", (long)a, (long)b, (long long)ref);
#if LDBL_MANT_DIG >= 64
        /* p fits the 64-bit significand, so p / 65536 is exact. */
        TEST_ASSERT_TRUE_MESSAGE((long double)ref == roundl((long double)p / 65536.0L), msg);
#endif
        assert_sat_chk(ref, a, fxl_q16_mul_sat(a, b), a != FXL_Q16_MIN ? fxl_q16_mul_sat(-a, b) : 0, st, out, msg);
    }
}

/* ---------------------------------------------------------------------- */
/* Divide                                                                 */

static void test_div_identity_at_limits(void)
{
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_div_sat(FXL_Q16_MAX, FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_div_sat(FXL_Q16_MIN, FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_MAX, fxl_q16_div_sat(FXL_Q16_MAX, -FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, fxl_q16_div_sat(FXL_Q16_MIN, FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, fxl_q16_div_sat(FXL_Q16_MAX, FXL_Q16_MAX));
    /* MIN / MAX = -2^31 / (2^31 - 1) = -1.00000000047: -1.0 at q16. */
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, fxl_q16_div_sat(FXL_Q16_MIN, FXL_Q16_MAX));
    /* MAX / MIN = -(2^31 - 1) / 2^31 = -0.99999999953: -1.0 at q16. */
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, fxl_q16_div_sat(FXL_Q16_MAX, FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_div_sat(0, FXL_Q16_MIN));
}

static void test_div_by_one_ulp(void)
{
    fxl_q16_t out = SENTINEL;
    /* x / 2^-16 = x * 65536: only |x| <= 32767 ulp (and -32768 ulp) fit. */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, fxl_q16_div_sat(1, 1));
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, fxl_q16_div_sat(-1, 1));
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, fxl_q16_div_sat(1, -1));
    TEST_ASSERT_EQUAL_INT32(32767 * 65536, fxl_q16_div_sat(32767, 1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_div_sat(32768, 1));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_div_chk(32768, 1, &out));
    TEST_ASSERT_EQUAL_INT32(SENTINEL, out);
    ASSERT_STATUS(FXL_OK, fxl_q16_div_chk(-32768, 1, &out));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, out);
    ASSERT_STATUS(FXL_OK, fxl_q16_div_chk(32768, -1, &out));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, out);
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_div_sat(FXL_Q16_MAX, 1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_div_sat(FXL_Q16_MAX, -1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_div_sat(FXL_Q16_MIN, 1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_div_sat(FXL_Q16_MIN, -1));
    out = SENTINEL;
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_div_chk(FXL_Q16_MIN, -1, &out));
    TEST_ASSERT_EQUAL_INT32(SENTINEL, out);
    /* MIN / -1.0 = +32768: one past MAX. */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_div_sat(FXL_Q16_MIN, -FXL_Q16_ONE));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_div_chk(FXL_Q16_MIN, -FXL_Q16_ONE, &out));
    TEST_ASSERT_EQUAL_INT32(SENTINEL, out);
}

static void test_div_by_zero_saturates_toward_sign(void)
{
    fxl_q16_t out = SENTINEL;
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_div_sat(1, 0));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_div_sat(FXL_Q16_MAX, 0));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_div_sat(-1, 0));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_div_sat(FXL_Q16_MIN, 0));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_div_sat(0, 0));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_div_chk(1, 0, &out));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_div_chk(-1, 0, &out));
    ASSERT_STATUS(FXL_ERR_RANGE, fxl_q16_div_chk(0, 0, &out));
    TEST_ASSERT_EQUAL_INT32(SENTINEL, out);
}

static void test_div_rounds_half_ulp_away_from_zero(void)
{
    /* 1 ulp / 2.0 = 0.5 ulp -> 1; 3 ulp / 2.0 = 1.5 ulp -> 2. */
    TEST_ASSERT_EQUAL_INT32(1, fxl_q16_div_sat(1, FXL_Q16_INT(2)));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_div_sat(-1, FXL_Q16_INT(2)));
    TEST_ASSERT_EQUAL_INT32(-1, fxl_q16_div_sat(1, FXL_Q16_INT(-2)));
    TEST_ASSERT_EQUAL_INT32(1, fxl_q16_div_sat(-1, FXL_Q16_INT(-2)));
    TEST_ASSERT_EQUAL_INT32(2, fxl_q16_div_sat(3, FXL_Q16_INT(2)));
    TEST_ASSERT_EQUAL_INT32(-2, fxl_q16_div_sat(-3, FXL_Q16_INT(2)));
    /* 1 ulp / (2.0 + 1 ulp) is just under 0.5 ulp -> 0. */
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_div_sat(1, FXL_Q16_INT(2) + 1));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_div_sat(-1, FXL_Q16_INT(2) + 1));
    /* 1.0 / 3.0 = 21845.33 ulp -> 21845; 2.0 / 3.0 = 43690.67 -> 43691. */
    TEST_ASSERT_EQUAL_INT32(21845, fxl_q16_div_sat(FXL_Q16_ONE, FXL_Q16_INT(3)));
    TEST_ASSERT_EQUAL_INT32(43691, fxl_q16_div_sat(FXL_Q16_INT(2), FXL_Q16_INT(3)));
    TEST_ASSERT_EQUAL_INT32(-43691, fxl_q16_div_sat(FXL_Q16_INT(-2), FXL_Q16_INT(3)));
}

static void test_div_chk_null_out_is_arg_error(void)
{
    ASSERT_STATUS(FXL_ERR_ARG, fxl_q16_div_chk(FXL_Q16_ONE, FXL_Q16_ONE, NULL));
}

static void test_div_matches_references_on_random_values(void)
{
    int i;
    lcg_seed(0xD1Du);
    for (i = 0; i < RANDOM_ITERS; i++) {
        fxl_q16_t a = rand_q16(), b = rand_q16(), out = SENTINEL;
        int64_t ref;
        int in_range;
        fxl_status_t st;
        if (b == 0) {
            continue; /* covered by test_div_by_zero_saturates_toward_sign */
        }
        ref = ref_round_div((int64_t)a * 65536, b); /* |a * 65536| <= 2^47 */
        in_range = ref >= INT32_MIN && ref <= INT32_MAX;
        st = fxl_q16_div_chk(a, b, &out);
        snprintf(msg, sizeof msg, "a=%ld b=%ld ref=%lld", (long)a, (long)b, (long long)ref);
#if LDBL_MANT_DIG >= 64
        /* For an in-range quotient (< 2^31) the long double division errs by at
         * most 2^-33 while a non-tie is at least 1 / (2|b|) >= 2^-32 from a
         * tie, and an exact tie is exactly representable: roundl is exact. */
        if (in_range) {
            TEST_ASSERT_TRUE_MESSAGE(
                (long double)ref == roundl((long double)a * 65536.0L / (long double)b), msg);
        }
#endif
        assert_sat_chk(ref, a, fxl_q16_div_sat(a, b), a != FXL_Q16_MIN ? fxl_q16_div_sat(-a, b) : 0, st, out, msg);
    }
}

/* ---------------------------------------------------------------------- */
/* Reciprocal                                                             */

static void test_recip_edges(void)
{
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, fxl_q16_recip_sat(FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(-FXL_Q16_ONE, fxl_q16_recip_sat(-FXL_Q16_ONE));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_HALF, fxl_q16_recip_sat(FXL_Q16_INT(2)));
    TEST_ASSERT_EQUAL_INT32(21845, fxl_q16_recip_sat(FXL_Q16_INT(3))); /* 21845.33 */
    /* 1 / 1 ulp = 65536.0 = 2^32 ulp: saturates; same for -1 ulp. */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_recip_sat(1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_recip_sat(-1));
    /* 1 / 2 ulp = 2^31 ulp: one past MAX, but exactly MIN when negative. */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_recip_sat(2));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MIN, fxl_q16_recip_sat(-2));
    /* 1 / 3 ulp = 1431655765.33 ulp: in range. */
    TEST_ASSERT_EQUAL_INT32(1431655765, fxl_q16_recip_sat(3));
    TEST_ASSERT_EQUAL_INT32(-1431655765, fxl_q16_recip_sat(-3));
    /* 1 / -32768 = -2^-15 = -2 ulp exactly; 1 / MAX = 2.0000000009 ulp -> 2. */
    TEST_ASSERT_EQUAL_INT32(-2, fxl_q16_recip_sat(FXL_Q16_MIN));
    TEST_ASSERT_EQUAL_INT32(2, fxl_q16_recip_sat(FXL_Q16_MAX));
    /* 1 / 0 saturates toward +. */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_MAX, fxl_q16_recip_sat(0));
}

static void test_recip_matches_reference_on_random_values(void)
{
    int i;
    lcg_seed(0x1EC1Fu);
    for (i = 0; i < RANDOM_ITERS; i++) {
        fxl_q16_t a = rand_q16();
        int64_t ref;
        if (a == 0) {
            continue;
        }
        ref = ref_round_div((int64_t)1 << 32, a);
        snprintf(msg, sizeof msg, "a=%ld ref=%lld", (long)a, (long long)ref);
        TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)clamp_i32(ref), fxl_q16_recip_sat(a), msg);
    }
}

/* ---------------------------------------------------------------------- */
/* Square root                                                            */

static void test_sqrt_edges_and_exact_squares(void)
{
    int32_t k;
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_sqrt(0));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_sqrt(-1));
    TEST_ASSERT_EQUAL_INT32(0, fxl_q16_sqrt(FXL_Q16_MIN));
    /* sqrt(2^-16) = 2^-8 = 256 ulp exactly. */
    TEST_ASSERT_EQUAL_INT32(256, fxl_q16_sqrt(1));
    /* sqrt(2 ulp) = sqrt(131072) ulp = 362.04 -> 362. */
    TEST_ASSERT_EQUAL_INT32(362, fxl_q16_sqrt(2));
    /* sqrt(0.25) = 0.5 */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_HALF, fxl_q16_sqrt(FXL_Q16_ONE / 4));
    /* sqrt(MAX) = sqrt((2^31 - 1) * 2^16) = 11863283.2003 ulp -> 11863283
     * (n - 11863283^2 = 4751703 <= 11863283, so below the .5 point). */
    TEST_ASSERT_EQUAL_INT32(11863283, fxl_q16_sqrt(FXL_Q16_MAX));
    /* k^2 for every integer k whose square is in range: exactly k. */
    for (k = 0; k <= 181; k++) {
        snprintf(msg, sizeof msg, "k=%ld", (long)k);
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_Q16_INT(k), fxl_q16_sqrt(FXL_Q16_INT(k * k)), msg);
    }
    /* Nearest misses of a tie: n = a * 2^16 = r (r + 1) puts sqrt(n) just
     * below r + 0.5 (by 1 / (8 r) roughly), so the result must be r, not
     * r + 1. r (r + 1) is a multiple of 2^16 when r = 65536 k or
     * r = 65536 k - 1; a = k (65536 k + 1) or k (65536 k - 1) <= MAX for
     * k <= 181. k = 1: sqrt(1.0 + 1 ulp) = 1.0, sqrt(1.0 - 1 ulp) = 1.0 - 1 ulp. */
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE, fxl_q16_sqrt(FXL_Q16_ONE + 1));
    TEST_ASSERT_EQUAL_INT32(FXL_Q16_ONE - 1, fxl_q16_sqrt(FXL_Q16_ONE - 1));
    for (k = 1; k <= 181; k++) {
        snprintf(msg, sizeof msg, "k=%ld", (long)k);
        TEST_ASSERT_EQUAL_INT_MESSAGE(65536 * k, fxl_q16_sqrt(k * (65536 * k + 1)), msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE(65536 * k - 1, fxl_q16_sqrt(k * (65536 * k - 1)), msg);
    }
    /* Every exact square at ulp scale: sqrt(j^2 ulp) = sqrt(j^2 * 2^16) ulp
     * = 256 j ulp, for all j with j^2 <= MAX (j <= 46340). */
    for (k = 0; k <= 46340; k++) {
        snprintf(msg, sizeof msg, "j=%ld", (long)k);
        TEST_ASSERT_EQUAL_INT_MESSAGE(256 * k, fxl_q16_sqrt(k * k), msg);
    }
}

/* The integer root the front end and texgen take (vector lengths): r =
 * floor(sqrt(x)) over all of uint64, i.e. r^2 <= x < (r + 1)^2, on both
 * sides of every word boundary of its two halves, around squares, and on
 * random values of every bit length. */
static int isqrt_holds(uint64_t x, uint64_t r)
{
    if (r > 0xFFFFFFFFu || r * r > x)
        return 0;
    return r == 0xFFFFFFFFu || (r + 1u) * (r + 1u) > x;   /* (2^32)^2 exceeds any x */
}

static void test_isqrt64_is_the_floor_root_everywhere(void)
{
    static const uint64_t edges[] = {0u, 1u, 2u, 3u, 4u, 0xFFFFFFFFu, (uint64_t)1 << 32, ((uint64_t)1 << 32) + 1u,
                                     ((uint64_t)1 << 34) - 1u, UINT64_MAX, UINT64_MAX - 1u,
                                     (uint64_t)0xFFFFFFFEu << 32, ((uint64_t)0xFFFFFFFEu << 32) + 1u};
    uint64_t r;
    size_t i;
    int k;
    for (i = 0; i < sizeof edges / sizeof edges[0]; i++) {
        snprintf(msg, sizeof msg, "x=%llu", (unsigned long long)edges[i]);
        TEST_ASSERT_TRUE_MESSAGE(isqrt_holds(edges[i], fxl__isqrt64(edges[i])), msg);
    }
    for (r = 1; r <= 0xFFFFFFFFu; r += (r >> 10) + 1u) {
        const uint64_t sq = r * r;
        int d;
        for (d = -2; d <= 2; d++) {
            const uint64_t x = sq + (uint64_t)(int64_t)d;
            snprintf(msg, sizeof msg, "x=%llu", (unsigned long long)x);
            TEST_ASSERT_TRUE_MESSAGE(isqrt_holds(x, fxl__isqrt64(x)), msg);
        }
    }
    lcg_seed(0x15C7u);
    for (k = 0; k < 64; k++) {
        for (i = 0; i < 4000; i++) {
            const uint64_t x = (((uint64_t)lcg_next() << 32) | lcg_next()) >> k;
            snprintf(msg, sizeof msg, "x=%llu", (unsigned long long)x);
            TEST_ASSERT_TRUE_MESSAGE(isqrt_holds(x, fxl__isqrt64(x)), msg);
        }
    }
}

static void test_sqrt_is_nearest_on_random_values(void)
{
    int i;
    lcg_seed(0x5C27u);
    for (i = 0; i < RANDOM_ITERS; i++) {
        fxl_q16_t a = rand_q16();
        fxl_q16_t r;
        uint64_t n, r2;
        if (a < 0) {
            a = a == FXL_Q16_MIN ? FXL_Q16_MAX : -a;
        }
        r = fxl_q16_sqrt(a);
        n = (uint64_t)a << 16;
        r2 = 2u * (uint64_t)r;
        snprintf(msg, sizeof msg, "a=%ld r=%ld", (long)a, (long)r);
        /* r is the nearest integer to sqrt(n) iff (2r - 1)^2 <= 4n < (2r + 1)^2
         * (no tie possible: 4n is even, (2r + 1)^2 odd). All < 2^50. */
        TEST_ASSERT_TRUE_MESSAGE(r == 0 || (r2 - 1u) * (r2 - 1u) <= 4u * n, msg);
        TEST_ASSERT_TRUE_MESSAGE(4u * n < (r2 + 1u) * (r2 + 1u), msg);
        /* double reference: n < 2^47 is exact; sqrt is correctly rounded to
         * 2^-29 near 2^23.5 while a root is at least 2^-26 from a .5. */
        TEST_ASSERT_EQUAL_INT_MESSAGE((int32_t)round(sqrt((double)n)), r, msg);
    }
}

/* ---------------------------------------------------------------------- */
/* Count leading zeros                                                    */

static void test_clz32_every_single_bit(void)
{
    int i;
    TEST_ASSERT_EQUAL_INT(32, fxl_clz32(0));
    TEST_ASSERT_EQUAL_INT(31, fxl_clz32(1));
    TEST_ASSERT_EQUAL_INT(0, fxl_clz32(0x80000000u));
    TEST_ASSERT_EQUAL_INT(0, fxl_clz32(0xFFFFFFFFu));
    for (i = 0; i < 32; i++) {
        uint32_t bit = (uint32_t)1 << i;
        snprintf(msg, sizeof msg, "bit %d", i);
        TEST_ASSERT_EQUAL_INT_MESSAGE(31 - i, fxl_clz32(bit), msg);
        /* The same top bit with every lower bit set. */
        TEST_ASSERT_EQUAL_INT_MESSAGE(31 - i, fxl_clz32(bit | (bit - 1u)), msg);
    }
}

static void test_clz64_every_single_bit(void)
{
    int i;
    TEST_ASSERT_EQUAL_INT(64, fxl_clz64(0));
    TEST_ASSERT_EQUAL_INT(63, fxl_clz64(1));
    TEST_ASSERT_EQUAL_INT(0, fxl_clz64((uint64_t)1 << 63));
    TEST_ASSERT_EQUAL_INT(0, fxl_clz64(UINT64_MAX));
    TEST_ASSERT_EQUAL_INT(31, fxl_clz64((uint64_t)1 << 32 | 1u));
    TEST_ASSERT_EQUAL_INT(32, fxl_clz64(0xFFFFFFFFu));
    for (i = 0; i < 64; i++) {
        uint64_t bit = (uint64_t)1 << i;
        snprintf(msg, sizeof msg, "bit %d", i);
        TEST_ASSERT_EQUAL_INT_MESSAGE(63 - i, fxl_clz64(bit), msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE(63 - i, fxl_clz64(bit | (bit - 1u)), msg);
    }
}

static void test_clz_matches_shift_count_on_random_values(void)
{
    int i;
    lcg_seed(0xC12u);
    for (i = 0; i < RANDOM_ITERS; i++) {
        uint64_t x = rand64() >> (lcg_next() >> 26);
        int n64 = 0, n32 = 0;
        uint32_t lo = (uint32_t)x;
        while (n64 < 64 && !(x & ((uint64_t)1 << (63 - n64)))) n64++;
        while (n32 < 32 && !(lo & ((uint32_t)1 << (31 - n32)))) n32++;
        snprintf(msg, sizeof msg, "x=0x%016llx", (unsigned long long)x);
        TEST_ASSERT_EQUAL_INT_MESSAGE(n64, fxl_clz64(x), msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE(n32, fxl_clz32(lo), msg);
        /* the binary search Cortex-M0+ builds run (clz.h) */
        if (lo != 0u)
            TEST_ASSERT_EQUAL_INT_MESSAGE(n32, fxl__clz32_soft(lo), msg);
    }
    for (i = 0; i < 32; i++) {
        const uint32_t bit = (uint32_t)1 << i;
        TEST_ASSERT_EQUAL_INT(31 - i, fxl__clz32_soft(bit));
        TEST_ASSERT_EQUAL_INT(31 - i, fxl__clz32_soft(bit | (bit - 1u)));
    }
}

/* ---------------------------------------------------------------------- */
/* 64-bit division                                                        */

static void test_div64_round_sign_combinations(void)
{
    /* 7 / 2 = 3.5 (tie), 5 / 3 = 1.67, 4 / 3 = 1.33, every sign pairing. */
    TEST_ASSERT_EQUAL_INT64(4, fxl_div64_round(7, 2));
    TEST_ASSERT_EQUAL_INT64(-4, fxl_div64_round(-7, 2));
    TEST_ASSERT_EQUAL_INT64(-4, fxl_div64_round(7, -2));
    TEST_ASSERT_EQUAL_INT64(4, fxl_div64_round(-7, -2));
    TEST_ASSERT_EQUAL_INT64(2, fxl_div64_round(5, 3));
    TEST_ASSERT_EQUAL_INT64(-2, fxl_div64_round(-5, 3));
    TEST_ASSERT_EQUAL_INT64(-2, fxl_div64_round(5, -3));
    TEST_ASSERT_EQUAL_INT64(2, fxl_div64_round(-5, -3));
    TEST_ASSERT_EQUAL_INT64(1, fxl_div64_round(4, 3));
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_round(-4, 3));
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_round(4, -3));
    TEST_ASSERT_EQUAL_INT64(1, fxl_div64_round(-4, -3));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_round(0, 5));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_round(0, -5));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_round(1, 3));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_round(-1, 3));
    TEST_ASSERT_EQUAL_INT64(1, fxl_div64_round(1, 2));
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_round(-1, 2));
}

static void test_div64_round_int64_limits(void)
{
    const int64_t q3 = 3074457345618258602; /* floor(2^63 / 3); 2^63 = 3 q3 + 2 */
    TEST_ASSERT_EQUAL_INT64(INT64_MAX, fxl_div64_round(INT64_MIN, -1)); /* saturates */
    TEST_ASSERT_EQUAL_INT64(INT64_MIN, fxl_div64_round(INT64_MIN, 1));
    TEST_ASSERT_EQUAL_INT64(INT64_MAX, fxl_div64_round(INT64_MAX, 1));
    TEST_ASSERT_EQUAL_INT64(-INT64_MAX, fxl_div64_round(INT64_MAX, -1));
    TEST_ASSERT_EQUAL_INT64(-((int64_t)1 << 62), fxl_div64_round(INT64_MIN, 2));
    TEST_ASSERT_EQUAL_INT64((int64_t)1 << 62, fxl_div64_round(INT64_MIN, -2));
    /* (2^63 - 1) / 2 = 2^62 - 0.5: a tie, away from zero. */
    TEST_ASSERT_EQUAL_INT64((int64_t)1 << 62, fxl_div64_round(INT64_MAX, 2));
    TEST_ASSERT_EQUAL_INT64(-((int64_t)1 << 62), fxl_div64_round(INT64_MAX, -2));
    TEST_ASSERT_EQUAL_INT64(-((int64_t)1 << 62), fxl_div64_round(-INT64_MAX, 2));
    /* 2^63 / 3 = q3 + 2/3 */
    TEST_ASSERT_EQUAL_INT64(-q3 - 1, fxl_div64_round(INT64_MIN, 3));
    TEST_ASSERT_EQUAL_INT64(q3 + 1, fxl_div64_round(INT64_MIN, -3));
    /* divisor extremes */
    TEST_ASSERT_EQUAL_INT64(1, fxl_div64_round(INT64_MIN, INT64_MIN));
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_round(INT64_MIN, INT64_MAX));  /* -1.0000000001 */
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_round(INT64_MAX, INT64_MIN));  /* -0.9999999999 */
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_round(1, INT64_MIN));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_round(-1, INT64_MAX));
    /* (2^62) / 2^63 = 0.5: tie against the largest divisor magnitude. */
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_round((int64_t)1 << 62, INT64_MIN));
    TEST_ASSERT_EQUAL_INT64(1, fxl_div64_round(-((int64_t)1 << 62), INT64_MIN));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_round(((int64_t)1 << 62) - 1, INT64_MIN));
}

static void test_div64_floor_sign_combinations(void)
{
    TEST_ASSERT_EQUAL_INT64(3, fxl_div64_floor(7, 2));
    TEST_ASSERT_EQUAL_INT64(-4, fxl_div64_floor(-7, 2));
    TEST_ASSERT_EQUAL_INT64(-4, fxl_div64_floor(-8, 2));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_floor(0, 2));
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_floor(-1, 2));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_floor(1, 2));
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_floor(-1, INT64_MAX));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_floor(INT64_MAX - 1, INT64_MAX));
    /* The contract is den > 0; a negative den gives the mathematical floor. */
    TEST_ASSERT_EQUAL_INT64(-4, fxl_div64_floor(7, -2));
    TEST_ASSERT_EQUAL_INT64(3, fxl_div64_floor(-7, -2));
    TEST_ASSERT_EQUAL_INT64(-4, fxl_div64_floor(8, -2));
}

static void test_div64_floor_int64_limits(void)
{
    const int64_t q3 = 3074457345618258602; /* floor(2^63 / 3) */
    TEST_ASSERT_EQUAL_INT64(INT64_MIN, fxl_div64_floor(INT64_MIN, 1));
    TEST_ASSERT_EQUAL_INT64(INT64_MAX, fxl_div64_floor(INT64_MAX, 1));
    TEST_ASSERT_EQUAL_INT64(-((int64_t)1 << 62), fxl_div64_floor(INT64_MIN, 2));
    TEST_ASSERT_EQUAL_INT64(((int64_t)1 << 62) - 1, fxl_div64_floor(INT64_MAX, 2));
    TEST_ASSERT_EQUAL_INT64(-q3 - 1, fxl_div64_floor(INT64_MIN, 3));
    TEST_ASSERT_EQUAL_INT64(q3, fxl_div64_floor(INT64_MAX, 3)); /* 2^63-1 = 3 q3 + 1 */
    TEST_ASSERT_EQUAL_INT64(-2, fxl_div64_floor(INT64_MIN, INT64_MAX)); /* -1.0000000001 */
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_floor(INT64_MIN + 1, INT64_MAX));
    TEST_ASSERT_EQUAL_INT64(1, fxl_div64_floor(INT64_MAX, INT64_MAX));
    TEST_ASSERT_EQUAL_INT64(INT64_MAX, fxl_div64_floor(INT64_MIN, -1)); /* saturates */
    TEST_ASSERT_EQUAL_INT64(1, fxl_div64_floor(INT64_MIN, INT64_MIN));
    TEST_ASSERT_EQUAL_INT64(-1, fxl_div64_floor(INT64_MAX, INT64_MIN));
}

#ifdef __SIZEOF_INT128__
/* 128-bit references (a GCC/Clang extension; skipped where absent). */
__extension__ typedef __int128 i128;

static int64_t clamp_i64(i128 v)
{
    return v > INT64_MAX ? INT64_MAX : (v < INT64_MIN ? INT64_MIN : (int64_t)v);
}

static void test_div64_match_int128_reference_on_random_values(void)
{
    int i;
    lcg_seed(0x64D1Du);
    for (i = 0; i < RANDOM_ITERS; i++) {
        int64_t num = rand_i64_wide(), den = rand_i64_wide();
        i128 n = num, d = den, q, r, ar, ad;
        if (den == 0) {
            continue;
        }
        q = n / d;
        r = n % d;
        ar = r < 0 ? -r : r;
        ad = d < 0 ? -d : d;
        snprintf(msg, sizeof msg, "num=%lld den=%lld", (long long)num, (long long)den);
        if (2 * ar >= ad) {
            ASSERT_EQUAL_I64_MSG(clamp_i64(q + (((n < 0) != (d < 0)) ? -1 : 1)),
                                            fxl_div64_round(num, den), msg);
        } else {
            ASSERT_EQUAL_I64_MSG(clamp_i64(q), fxl_div64_round(num, den), msg);
        }
        if (r != 0 && ((n < 0) != (d < 0))) {
            q -= 1; /* truncation went up; floor goes down */
        }
        ASSERT_EQUAL_I64_MSG(clamp_i64(q), fxl_div64_floor(num, den), msg);
    }
}
#endif

/* The core's own 64-bit division (div64.h: size-optimised builds use it in
 * place of the compiler's runtime helper) must be the exact truncated
 * quotient: checked against C's division at the edges and on random values
 * whose magnitudes spread over every bit length. */
static void check_udiv64_loop(uint64_t n, uint64_t d)
{
    snprintf(msg, sizeof msg, "n=%llu d=%llu", (unsigned long long)n, (unsigned long long)d);
    TEST_ASSERT_TRUE_MESSAGE(fxl__udiv64_loop(n, d) == n / d, msg);
}

static void test_udiv64_loop_matches_c_division(void)
{
    static const uint64_t edge[] = {1u, 2u, 3u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu, (uint64_t)1 << 32,
                                    ((uint64_t)1 << 32) + 1u, (uint64_t)1 << 62, (uint64_t)INT64_MAX,
                                    (uint64_t)1 << 63, UINT64_MAX - 1u, UINT64_MAX};
    const int ne = (int)(sizeof edge / sizeof edge[0]);
    int i, j;
    for (i = 0; i < ne; i++)
        for (j = 0; j < ne; j++)
            check_udiv64_loop(edge[i], edge[j]);
    TEST_ASSERT_TRUE(fxl__udiv64_loop(0u, 7u) == 0u);
    TEST_ASSERT_TRUE(fxl__udiv64_loop(6u, 7u) == 0u);
    TEST_ASSERT_TRUE(fxl__udiv64_loop(7u, 7u) == 1u);
    TEST_ASSERT_TRUE(fxl__udiv64_loop(UINT64_MAX, 1u) == UINT64_MAX);
    /* the one-word loop (n < 2^32, cores without a divide instruction): the
     * generic walk's step divisors (segment lengths), one below, at and one
     * above multiples up to the top of the word */
    for (j = 1; j <= 300; j++) {
        static const uint64_t ks[] = {1u, 2u, 0x7FFFu, 0x10000u, 0x3FFFFFFFu};
        const int nk = (int)(sizeof ks / sizeof ks[0]);
        const uint64_t d = (uint64_t)j, top = UINT64_C(0xFFFFFFFF) / d;
        for (i = 0; i < nk + 2; i++) {
            /* the listed multipliers, then the word's last two multiples */
            const uint64_t k = i < nk ? ks[i] : top - (uint64_t)(i - nk);
            if (k * d > UINT64_C(0xFFFFFFFF) || k == 0u)
                continue;
            check_udiv64_loop(k * d - 1u, d);
            check_udiv64_loop(k * d, d);
            if (k * d < UINT64_C(0xFFFFFFFF))
                check_udiv64_loop(k * d + 1u, d);
        }
    }
    lcg_seed(0xD1F64u);
    for (i = 0; i < RANDOM_ITERS; i++) {
        const uint64_t n = rand64() >> (lcg_next() >> 26), d = rand64() >> (lcg_next() >> 26);
        if (d != 0u)
            check_udiv64_loop(n, d);
    }
}

/* The 64 / 32 division Cortex-M builds with UDIV use: exact against C's
 * division at the edges of both words and of its digit corrections, and on
 * random values of every bit length. */
static void check_udiv64_by32(uint64_t n, uint32_t d)
{
    snprintf(msg, sizeof msg, "n=%llu d=%lu", (unsigned long long)n, (unsigned long)d);
    TEST_ASSERT_TRUE_MESSAGE(fxl__udiv64_by32(n, d) == n / d, msg);
}

static void test_udiv64_by32_matches_c_division(void)
{
    static const uint64_t en[] = {0u, 1u, 0xFFFFu, 0x10000u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu,
                                  (uint64_t)1 << 32, ((uint64_t)1 << 32) + 1u, 0xFFFF0000FFFF0000u,
                                  0x8000000000000000u, 0x7FFFFFFFFFFFFFFFu, UINT64_MAX - 1u, UINT64_MAX};
    static const uint32_t ed[] = {1u, 2u, 3u, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu,
                                  0x80000000u, 0x80000001u, 0xFFFF0001u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    const int nn = (int)(sizeof en / sizeof en[0]), nd = (int)(sizeof ed / sizeof ed[0]);
    int i, j;
    for (i = 0; i < nn; i++)
        for (j = 0; j < nd; j++) {
            check_udiv64_by32(en[i], ed[j]);
            /* a quotient digit one above and below each multiple */
            check_udiv64_by32(en[i] / ed[j] * ed[j] + ed[j] - 1u, ed[j]);
        }
    TEST_ASSERT_TRUE(fxl__udiv64_by32(5u, 0u) == 0u);
    lcg_seed(0xB32D1Fu);
    for (i = 0; i < RANDOM_ITERS; i++) {
        const uint64_t n = rand64() >> (lcg_next() >> 26);
        const uint32_t d = (uint32_t)(rand64() >> (32 + (lcg_next() >> 27)));
        if (d != 0u)
            check_udiv64_by32(n, d);
    }
}

/* Set-up's division by a reciprocal (div64.h, 32-bit cores): the high
 * product against a 128-bit one, and the quotient and remainder against
 * C's for every n < 2^63 it may see, at the edges of the estimate (exact
 * multiples, one below) and on random values of every bit length. */
#if defined(__SIZEOF_INT128__)
__extension__ typedef unsigned __int128 u128_t;   /* the reference high product */
#endif

static void check_udiv64_recip(uint64_t n, uint64_t d)
{
    uint64_t rem = 0, q = fxl__udiv64_recip(n, d, UINT64_MAX / d, &rem);
    snprintf(msg, sizeof msg, "n=%llu d=%llu", (unsigned long long)n, (unsigned long long)d);
    TEST_ASSERT_TRUE_MESSAGE(q == n / d && rem == n % d, msg);
}

static void test_udiv64_recip_matches_c_division(void)
{
    static const uint64_t en[] = {0u, 1u, 2u, 0xFFFFFFFFu, (uint64_t)1 << 32, ((uint64_t)1 << 62) - 1u,
                                  (uint64_t)1 << 62, (uint64_t)INT64_MAX - 1u, (uint64_t)INT64_MAX};
    static const uint64_t ed[] = {1u, 2u, 3u, 7u, 0xFFFFFFFFu, (uint64_t)1 << 32, ((uint64_t)1 << 32) + 1u,
                                  ((uint64_t)1 << 47) - 1u, (uint64_t)1 << 62, (uint64_t)INT64_MAX,
                                  (uint64_t)1 << 63, UINT64_MAX};
    const int nn = (int)(sizeof en / sizeof en[0]), nd = (int)(sizeof ed / sizeof ed[0]);
    int i, j;
    for (i = 0; i < nn; i++)
        for (j = 0; j < nd; j++) {
            const uint64_t m = en[i] / ed[j] * ed[j];
            check_udiv64_recip(en[i], ed[j]);
            check_udiv64_recip(m, ed[j]);
            if (m > 0u)
                check_udiv64_recip(m - 1u, ed[j]);
        }
    lcg_seed(0x2EC1Fu);
    for (i = 0; i < RANDOM_ITERS; i++) {
        const uint64_t a = rand64(), b = rand64();
#if defined(__SIZEOF_INT128__)
        TEST_ASSERT_TRUE(fxl__mulhi64(a, b) == (uint64_t)(((u128_t)a * b) >> 64));
#endif
        {
            const uint64_t n = (a >> 1) >> (lcg_next() >> 26), d = b >> (lcg_next() >> 26);
            if (d != 0u)
                check_udiv64_recip(n, d);
        }
    }
}

/* The 32 x 32 -> 64-bit products ARMv6-M builds make from 16-bit halves
 * (persp.h, FXL__MUL_HALVES, forced on for this file): exact against the
 * compiler's 64-bit products at the carries' edges and on random values. */
static void test_mul_halves_match_64bit_products(void)
{
    static const uint32_t e[] = {0u, 1u, 2u, 0xFFFFu, 0x10000u, 0x10001u, 0x7FFFFFFFu, 0x80000000u,
                                 0x80000001u, 0xFFFF0000u, 0xFFFF0001u, 0xFFFFFFFEu, 0xFFFFFFFFu};
    const int ne = (int)(sizeof e / sizeof e[0]);
    int i, j;
    TEST_ASSERT_EQUAL_INT(1, FXL__MUL_HALVES);
    for (i = 0; i < ne; i++)
        for (j = 0; j < ne; j++) {
            const int32_t a = (int32_t)e[i], b = (int32_t)e[j];
            TEST_ASSERT_TRUE(fxl__umul32(e[i], e[j]) == (uint64_t)e[i] * e[j]);
            TEST_ASSERT_TRUE(fxl__umul32_halves(e[i], e[j]) == (uint64_t)e[i] * e[j]);   /* -Os copy */
            TEST_ASSERT_TRUE(fxl__mul_s32(a, b) == (int64_t)a * b);
        }
    lcg_seed(0x3A1F5u);
    for (i = 0; i < RANDOM_ITERS; i++) {
        const uint32_t a = rand32(), b = rand32() >> (lcg_next() >> 27);
        TEST_ASSERT_TRUE(fxl__umul32(a, b) == (uint64_t)a * b);
        TEST_ASSERT_TRUE(fxl__umul32_halves(a, b) == (uint64_t)a * b);
        TEST_ASSERT_TRUE(fxl__mul_s32((int32_t)a, (int32_t)b) == (int64_t)(int32_t)a * (int32_t)b);
    }
}

/* The low word of fxl__persp_e's value from m * r in 32-bit words, as the
 * walk along rows of constant q computes it on 32-bit cores
 * (fxl__persp_lo32_words for every shift k, fxl__persp_lo32_hi for k >= 33):
 * equal to the 64-bit rounding fxl__persp_e uses, floor((floor(p /
 * 2^(k-1)) + 1) / 2), at the extremes of m and r and on random products,
 * for every k from 1 to 62. */
static void test_persp_lo32_word_forms_match_64bit(void)
{
    static const int32_t ms[] = {0, 1, -1, 2, -2, 0x3FFF, -0x4000, INT32_MAX, -INT32_MAX, 0x12345678, -0x7654321};
    static const int32_t rs[] = {0, 1, 2, 0x40000000, 0x55555555, 0x7FFFFFFE};
    const int nm = (int)(sizeof ms / sizeof ms[0]), nr = (int)(sizeof rs / sizeof rs[0]);
    int i, j, k;
    long checked = 0;
    lcg_seed(0x51EDu);
    for (k = 1; k <= 62; k++) {
        const uint64_t half = (uint64_t)1 << (k - 1);
        for (i = 0; i < nm * nr + 4000; i++) {
            const int32_t m = i < nm * nr ? ms[i % nm] : (int32_t)rand32() >> (lcg_next() >> 27);
            const int32_t r = i < nm * nr ? rs[i / nm] : (int32_t)(rand32() & 0x7FFFFFFFu) % 0x7FFFFFFF;
            const int64_t prod = (int64_t)m * r;
            const uint32_t want = (uint32_t)(uint64_t)fxl__asr64(fxl__asr64(prod, k - 1) + 1, 1);
            TEST_ASSERT_EQUAL_HEX32(want, fxl__persp_lo32_words(prod, k, half));
            TEST_ASSERT_EQUAL_HEX32(want, fxl__persp_lo32(prod, k, half));
            if (k >= 33)
                TEST_ASSERT_EQUAL_HEX32(want, fxl__persp_lo32_hi(prod, k));
            checked++;
        }
    }
    /* products whose low word plus 2^31 carries: k = 32 needs the
     * two-word sum (fxl__persp_lo32_hi is for k >= 33 only) */
    for (j = 0; j < 1000; j++) {
        const int64_t prod = (int64_t)((uint64_t)(rand32() & 0x3FFFFFFFu) << 32 | (0x80000000u | rand32()));
        TEST_ASSERT_EQUAL_HEX32((uint32_t)((uint64_t)prod >> 32) + 1u, fxl__persp_lo32_words(prod, 32, (uint64_t)1 << 31));
    }
    TEST_ASSERT_EQUAL_INT(62L * (nm * nr + 4000), checked);
}

/* fxl__recip's first quotient without a divide instruction (persp.h,
 * FXL__DIV_TABLE, forced on here): exact for every divisor it can get. */
static void test_div_ffffffff_table_is_exact(void)
{
    uint32_t d;
    for (d = 32769u; d <= 65536u; d++)
        if (fxl__div_ffffffff(d) != 0xFFFFFFFFu / d) {
            snprintf(msg, sizeof msg, "d=%lu", (unsigned long)d);
            TEST_FAIL_MESSAGE(msg);
        }
}

/* both of fxl__sdiv64's forms on 32-bit cores: the size builds' loop and
 * the magnitudes' division (Cortex-M3/M4/M7 speed builds) */
static void check_sdiv64_loop(int64_t n, int64_t d)
{
    snprintf(msg, sizeof msg, "n=%lld d=%lld", (long long)n, (long long)d);
    TEST_ASSERT_TRUE_MESSAGE(fxl__sdiv64_loop(n, d) == n / d, msg);
    TEST_ASSERT_TRUE_MESSAGE(fxl__sdiv64_mag(n, d) == n / d, msg);
}

/* The log2 table is round(256 log2(1 + i / 256)), and the size builds'
 * computed form (nine truncated squarings) gives the same 256 values. */
#if FXL_HAVE_MIPMAP || FXL_HAVE_AUTO
static void test_log2_frac_table_and_its_computed_form(void)
{
    int i;
    for (i = 0; i < 256; i++) {
        const long want = lround(256.0 * log2(1.0 + i / 256.0));
        snprintf(msg, sizeof msg, "i %d", i);
        TEST_ASSERT_EQUAL_INT_MESSAGE(want, fxl__log2_frac_q8[i], msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE((uint32_t)want, fxl__log2_frac_q8_calc((uint32_t)i), msg);
    }
}
#endif

/* recip_run.h's reciprocal, 2^62 / q for q in [2^31, 2^32): relative
 * error in (-2^-18, +2^-30.4), as the header states it, and below 2^31
 * (as an int32 it is positive), at every bucket's ends and on a stride
 * through all q (every q was checked once: (-2^-18.01, +2^-30.42), the
 * largest 0x7FFFE01E); the fast walks' seed table holds the division's
 * seeds. */
static void test_rr_recip_within_its_bound(void)
{
    double lo = 0, hi = 0;
    uint64_t q;
    int i;
    char msg[120];
    for (q = 0x80000000u; q <= 0xFFFFFFFFu; q++) {
        const uint32_t r = fxl__rr_recip((uint32_t)q);
        const double e = ((double)r - ldexp(1.0, 62) / (double)q) / (ldexp(1.0, 62) / (double)q);
        lo = e < lo ? e : lo;
        hi = e > hi ? e : hi;
        if (r >= 0x80000000u || e <= -ldexp(1.0, -18) || e >= exp2(-30.4)) {
            snprintf(msg, sizeof msg, "q %08x: r %08x, relative error %.3g", (unsigned)q, (unsigned)r, e);
            TEST_FAIL_MESSAGE(msg);
        }
        /* each 2^23 bucket of the seed: its first and last 4 q, and every 1021st */
        if ((q & 0x7FFFFFu) >= 3u && (q & 0x7FFFFFu) < 0x7FFFFBu)
            q += (q & 0x7FFFFFu) + 1021u < 0x7FFFFBu ? 1020u : 0x7FFFFAu - (q & 0x7FFFFFu);
    }
    snprintf(msg, sizeof msg, "relative error in [%.3g, %.3g]", lo, hi);
    TEST_MESSAGE(msg);
#if FXL_HAVE_RR && FXL__FAST_SPANS
    for (i = 0; i < 256; i++)
        TEST_ASSERT_EQUAL_HEX32((0xFFFFFFFFu / (uint32_t)(2 * (256 + i) + 1)) << 8, fxl__rr_seed[i]);
    for (q = 0x80000000u; q <= 0xFFFFFFFFu; q += 65521)
        TEST_ASSERT_EQUAL_HEX32(fxl__rr_recip((uint32_t)q), fxl__rr_recip_tab((uint32_t)q));
#else
    (void)i;
#endif
}

static void test_sdiv64_forms_truncate_like_c_division(void)
{
    static const int64_t edge[] = {1, -1, 2, -2, 7, -7, INT32_MAX, INT32_MIN, INT64_MAX, -INT64_MAX, INT64_MIN};
    const int ne = (int)(sizeof edge / sizeof edge[0]);
    int i, j;
    for (i = 0; i < ne; i++)
        for (j = 0; j < ne; j++)
            if (!(edge[i] == INT64_MIN && edge[j] == -1))
                check_sdiv64_loop(edge[i], edge[j]);
    /* the one quotient outside int64 saturates instead of overflowing */
    TEST_ASSERT_TRUE(fxl__sdiv64_loop(INT64_MIN, -1) == INT64_MAX);
    check_sdiv64_loop(-6, 7);   /* truncation toward zero, not floor */
    check_sdiv64_loop(6, -7);
    check_sdiv64_loop(INT64_MIN, 1);   /* a quotient of magnitude 2^63 */
    check_sdiv64_loop(INT64_MIN + 1, -1);
    check_sdiv64_loop(-((int64_t)1 << 40) - 5, 16);   /* a segment step: a long by a length */
    check_sdiv64_loop(((int64_t)1 << 40) + 5, 13);
    lcg_seed(0x5D1F64u);
    for (i = 0; i < RANDOM_ITERS; i++) {
        const int64_t n = rand_i64_wide(), d = rand_i64_wide();
        if (d != 0 && !(n == INT64_MIN && d == -1))
            check_sdiv64_loop(n, d);
    }
}

static void test_div64_by_zero_saturates_instead_of_trapping(void)
{
    /* Outside the contract (den != 0), but must not trap: saturate toward
     * the sign of num like fxl_q16_div_sat. */
    TEST_ASSERT_EQUAL_INT64(INT64_MAX, fxl_div64_round(5, 0));
    TEST_ASSERT_EQUAL_INT64(INT64_MIN, fxl_div64_round(-5, 0));
    TEST_ASSERT_EQUAL_INT64(0, fxl_div64_round(0, 0));
    TEST_ASSERT_EQUAL_INT64(INT64_MAX, fxl_div64_floor(5, 0));
    TEST_ASSERT_EQUAL_INT64(INT64_MIN, fxl_div64_floor(INT64_MIN, 0));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_round_ties_go_away_from_zero);
    RUN_TEST(test_round_floor_ceil_at_int32_limits);
    RUN_TEST(test_floor_ceil_small_values);
    RUN_TEST(test_round_floor_ceil_match_libm_on_random_values);
    RUN_TEST(test_from_int_sat_saturates_outside_q16_range);
    RUN_TEST(test_add_sub_saturate_at_limits);
    RUN_TEST(test_add_sub_match_wide_reference_on_random_values);
    RUN_TEST(test_mul_identity_at_limits);
    RUN_TEST(test_mul_rounds_half_ulp_away_from_zero);
    RUN_TEST(test_mul_saturates_and_chk_reports_range);
    RUN_TEST(test_mul_overflow_decided_after_rounding);
    RUN_TEST(test_mul_chk_null_out_is_arg_error);
    RUN_TEST(test_mul_matches_references_on_random_values);
    RUN_TEST(test_div_identity_at_limits);
    RUN_TEST(test_div_by_one_ulp);
    RUN_TEST(test_div_by_zero_saturates_toward_sign);
    RUN_TEST(test_div_rounds_half_ulp_away_from_zero);
    RUN_TEST(test_div_chk_null_out_is_arg_error);
    RUN_TEST(test_div_matches_references_on_random_values);
    RUN_TEST(test_recip_edges);
    RUN_TEST(test_recip_matches_reference_on_random_values);
    RUN_TEST(test_sqrt_edges_and_exact_squares);
    RUN_TEST(test_sqrt_is_nearest_on_random_values);
    RUN_TEST(test_isqrt64_is_the_floor_root_everywhere);
    RUN_TEST(test_clz32_every_single_bit);
    RUN_TEST(test_clz64_every_single_bit);
    RUN_TEST(test_clz_matches_shift_count_on_random_values);
    RUN_TEST(test_div64_round_sign_combinations);
    RUN_TEST(test_div64_round_int64_limits);
    RUN_TEST(test_div64_floor_sign_combinations);
    RUN_TEST(test_div64_floor_int64_limits);
#ifdef __SIZEOF_INT128__
    RUN_TEST(test_div64_match_int128_reference_on_random_values);
#endif
    RUN_TEST(test_div64_by_zero_saturates_instead_of_trapping);
    RUN_TEST(test_udiv64_loop_matches_c_division);
    RUN_TEST(test_udiv64_by32_matches_c_division);
    RUN_TEST(test_udiv64_recip_matches_c_division);
    RUN_TEST(test_mul_halves_match_64bit_products);
    RUN_TEST(test_persp_lo32_word_forms_match_64bit);
    RUN_TEST(test_div_ffffffff_table_is_exact);
#if FXL_HAVE_MIPMAP || FXL_HAVE_AUTO
    RUN_TEST(test_log2_frac_table_and_its_computed_form);
#endif
    RUN_TEST(test_rr_recip_within_its_bound);
    RUN_TEST(test_sdiv64_forms_truncate_like_c_division);
    return UNITY_END();
}

/* fixed.c - 16.16 fixed-point arithmetic (see include/fixel/fixed.h).
 *
 * Every rounding step here works on magnitudes held in unsigned types: the
 * sign is taken apart first, the magnitude is rounded half away from zero, and
 * the sign is put back only after a range check. That gives the symmetry the
 * header promises (f(-a, b) == -f(a, b)) for free, and it means no expression
 * below can overflow a signed type or shift a negative value, whatever the
 * arguments (INT32_MIN and INT64_MIN included: their magnitude 2^31 / 2^63 is
 * representable in the unsigned type of the same width).
 *
 * Division by a 64-bit value goes through div64.h: the compiler's runtime
 * helper, or in size-optimised builds a short loop of our own.
 */
#include <stddef.h>

#include "fixel/fixed.h"
#include "clz.h"
#include "div64.h"
#include "isqrt.h"

/* |v| as an unsigned number; exact for INT32_MIN (2^31) and INT64_MIN (2^63)
 * because the negation happens in unsigned arithmetic (modulo 2^N). */
static uint32_t abs_u32(int32_t v)
{
    return v < 0 ? 0u - (uint32_t)v : (uint32_t)v;
}

static uint64_t abs_u64(int64_t v)
{
    return v < 0 ? (uint64_t)0 - (uint64_t)v : (uint64_t)v;
}

/* Rebuild a q16 from its sign and magnitude. Returns 0 (and leaves *out alone)
 * when the value is outside [-2^31, 2^31 - 1]. */
static int q16_from_mag(int negative, uint64_t mag, fxl_q16_t *out)
{
    if (negative) {
        if (mag > (uint64_t)0x80000000u) {
            return 0;
        }
        /* mag <= 2^31, so -mag fits int64 and then int32 exactly. */
        *out = (fxl_q16_t)(-(int64_t)mag);
    } else {
        if (mag > (uint64_t)INT32_MAX) {
            return 0;
        }
        *out = (fxl_q16_t)mag;
    }
    return 1;
}

static fxl_q16_t q16_saturate(int negative)
{
    return negative ? FXL_Q16_MIN : FXL_Q16_MAX;
}

/* ------------------------------------------------------------------------ */
/* Conversions                                                              */

int32_t fxl_q16_round(fxl_q16_t a)
{
    /* m <= 2^31, so m + 2^15 cannot wrap a uint32_t; the result is at most
     * 2^15 = 32768 (round(32767.99998) and round(-32768)). */
    uint32_t m = abs_u32(a);
    uint32_t r = (m + 0x8000u) >> 16;
    return a < 0 ? -(int32_t)r : (int32_t)r;
}

int32_t fxl_q16_floor(fxl_q16_t a)
{
    /* Clearing the 16 fraction bits rounds toward -inf in two's complement;
     * the result is a multiple of 65536 in [INT32_MIN, INT32_MAX - 65535], so
     * the subtraction is in range and the division is exact (no dependence
     * on how >> treats negative numbers). */
    int32_t whole = a - (int32_t)(a & 0xFFFF);
    return whole / 65536;
}

int32_t fxl_q16_ceil(fxl_q16_t a)
{
    /* floor <= 32767, so the +1 stays in range (ceil(MAX) = 32768). */
    return fxl_q16_floor(a) + ((a & 0xFFFF) != 0 ? 1 : 0);
}

fxl_q16_t fxl_q16_from_int_sat(int32_t i)
{
    if (i > 32767) {
        return FXL_Q16_MAX;
    }
    if (i < -32768) {
        return FXL_Q16_MIN;
    }
    /* |i * 65536| <= 2^31 and -32768 * 65536 == INT32_MIN exactly. */
    return (fxl_q16_t)(i * 65536);
}

/* ------------------------------------------------------------------------ */
/* Add, subtract                                                            */

static fxl_q16_t clamp_q16(int64_t v)
{
    if (v > INT32_MAX) {
        return FXL_Q16_MAX;
    }
    if (v < INT32_MIN) {
        return FXL_Q16_MIN;
    }
    return (fxl_q16_t)v;
}

fxl_q16_t fxl_q16_add_sat(fxl_q16_t a, fxl_q16_t b)
{
    /* |a + b| <= 2^32: exact in int64. */
    return clamp_q16((int64_t)a + (int64_t)b);
}

fxl_q16_t fxl_q16_sub_sat(fxl_q16_t a, fxl_q16_t b)
{
    return clamp_q16((int64_t)a - (int64_t)b);
}

/* ------------------------------------------------------------------------ */
/* Multiply                                                                 */

/* a * b / 2^16 rounded half away from zero. Returns 0 on overflow. */
static int q16_mul(fxl_q16_t a, fxl_q16_t b, fxl_q16_t *out, int *negative)
{
    /* |a| * |b| <= 2^62; + 2^15 cannot wrap a uint64_t. */
    uint64_t p = (uint64_t)abs_u32(a) * (uint64_t)abs_u32(b);
    uint64_t r = (p + 0x8000u) >> 16;
    *negative = (a < 0) != (b < 0);
    return q16_from_mag(*negative, r, out);
}

fxl_q16_t fxl_q16_mul_sat(fxl_q16_t a, fxl_q16_t b)
{
    fxl_q16_t v;
    int negative;
    if (!q16_mul(a, b, &v, &negative)) {
        return q16_saturate(negative);
    }
    return v;
}

/* The status and store of the _chk variants: ok is the operation's
 * result, v its value. */
static fxl_status_t q16_chk_store(int ok, fxl_q16_t v, fxl_q16_t *out)
{
    if (out == NULL) { /* fixed.h: a NULL out is FXL_ERR_ARG */
        return FXL_ERR_ARG;
    }
    if (!ok) {
        return FXL_ERR_RANGE;
    }
    *out = v;
    return FXL_OK;
}

fxl_status_t fxl_q16_mul_chk(fxl_q16_t a, fxl_q16_t b, fxl_q16_t *out)
{
    fxl_q16_t v = 0;
    int negative;
    const int ok = q16_mul(a, b, &v, &negative);
    return q16_chk_store(ok, v, out);
}

/* ------------------------------------------------------------------------ */
/* Divide                                                                   */

/* (a * 2^16) / b rounded half away from zero. Returns 0 on overflow and for
 * b == 0; *negative is then the direction to saturate (for b == 0 the sign
 * of a; the caller turns 0 / 0 into 0). */
static int q16_div(fxl_q16_t a, fxl_q16_t b, fxl_q16_t *out, int *negative)
{
    uint64_t n, d, q;
    *negative = (a < 0) != (b < 0);
    if (b == 0) {
        *negative = a < 0;
        return 0;
    }
    /* n <= 2^47, d <= 2^31: n + d / 2 cannot wrap. Rounding: with
     * n = q*d + r, floor((n + floor(d/2)) / d) is q + 1 exactly when
     * r >= d - floor(d/2), i.e. r >= d/2 for even d and r > d/2 for odd d
     * (an odd divisor can never produce an exact .5). */
    n = (uint64_t)abs_u32(a) << 16;
    d = (uint64_t)abs_u32(b);
    q = fxl__udiv64(n + d / 2u, d);
    return q16_from_mag(*negative, q, out);
}

fxl_q16_t fxl_q16_div_sat(fxl_q16_t a, fxl_q16_t b)
{
    fxl_q16_t v;
    int negative;
    if (!q16_div(a, b, &v, &negative)) {
        if (a == 0) {
            return 0; /* 0 / 0 */
        }
        return q16_saturate(negative);
    }
    return v;
}

fxl_status_t fxl_q16_div_chk(fxl_q16_t a, fxl_q16_t b, fxl_q16_t *out)
{
    fxl_q16_t v = 0;
    int negative;
    const int ok = q16_div(a, b, &v, &negative);
    return q16_chk_store(ok, v, out);
}

fxl_q16_t fxl_q16_recip_sat(fxl_q16_t a)
{
    /* 1 / 0 saturates to MAX; 1 / (+-1 ulp) = +-2^32 ulp overflows to
     * MAX / MIN; 1 / INT32_MIN = -2 ulp exactly. */
    return fxl_q16_div_sat(FXL_Q16_ONE, a);
}

/* ------------------------------------------------------------------------ */
/* Square root                                                              */

/* floor(sqrt(x)) of a 32-bit x, and x - root^2 in *rem: the classic digit
 * by digit root (bit walks down the powers of four from x's leading pair,
 * r collects the root, x keeps the remainder), on 32-bit words. */
static uint32_t isqrt32(uint32_t x, uint32_t *rem)
{
    uint32_t r = 0, bit;
    if (x == 0) {
        *rem = 0;
        return 0;
    }
    bit = (uint32_t)1 << ((31 - fxl_clz32(x)) & ~1);
    while (bit != 0) {
        if (x >= r + bit) {
            x -= r + bit;
            r = (r >> 1) + bit;
        } else {
            r >>= 1;
        }
        bit >>= 2;
    }
    *rem = x;
    return r;
}

/* From the root of the high word, one 32-bit division and a correction.
 * x is first shifted left by an even 2k so that its leading pair is in the
 * top two bits (floor(sqrt(x)) is floor(sqrt(x 4^k)) >> k: floor commutes
 * with the root). Then xn = A^2 + N with A = h 2^16, h = the high word's
 * root in [2^15, 2^16), and the root is A + d with 2 A d + d^2 <= N, so
 * d <= N / 2A; as d^2 / 2A <= 2^32 / 2^32 = 1, d lies within two of that
 * quotient, which t / h (the remainder's 17 bits and the low word's top
 * 15, < 2^32) gives within one. One step above, and at most two steps
 * down with 64-bit squares, find it. On a Cortex-M4 ~190 instructions
 * where 32 digit steps on 64-bit words took ~480. */
uint64_t fxl__isqrt64(uint64_t x)
{
    uint32_t h, rem, lo, t, d;
    uint64_t xn, c;
    int k;
    if (x == 0)
        return 0;
    k = fxl_clz64(x) >> 1;
    xn = x << (2 * k);
    lo = (uint32_t)xn;
    h = isqrt32((uint32_t)(xn >> 32), &rem);   /* [2^15, 2^16); rem <= 2 h < 2^17 */
    t = (rem << 15) + (lo >> 17);              /* <= 131070 * 2^15 + 32767 < 2^32 */
    d = t / h + 1u;
    if (d > 0xFFFFu)
        d = 0xFFFFu;
    c = ((uint64_t)h << 16) + d;               /* >= the root, < 2^32 */
    while (c * c > xn)
        c--;
    return c >> k;
}

fxl_q16_t fxl_q16_sqrt(fxl_q16_t a)
{
    /* sqrt(a / 2^16) * 2^16 = sqrt(a * 2^16); n < 2^47, so the root is
     * below 2^23.5 and fits easily. */
    uint64_t n, root;
    if (a <= 0) {
        return 0;
    }
    n = (uint64_t)(uint32_t)a << 16;
    root = fxl__isqrt64(n);
    /* Round to nearest: n >= (root + 1/2)^2 = root^2 + root + 1/4 holds for an
     * integer n exactly when n - root^2 > root; never a tie. */
    if (n - root * root > root) {
        root++;
    }
    return (fxl_q16_t)root;
}

/* ------------------------------------------------------------------------ */
/* Count leading zeros                                                      */

/* __builtin_clz only where it becomes one instruction. Elsewhere GCC would
 * call the libgcc helper __clzsi2, so plain C is used instead. Building with
 * -DFXL_USE_BUILTIN_CLZ=0 forces the plain C path on any target: CI's 32-bit
 * arithmetic build (host_sim/scripts/ci_extra.sh) runs the whole suite so. */
#ifndef FXL_USE_BUILTIN_CLZ
#if defined(__GNUC__) && (defined(__ARM_FEATURE_CLZ) || defined(__x86_64__) || \
                          defined(__i386__) || defined(__aarch64__) ||           \
                          defined(__riscv_zbb))
#define FXL_USE_BUILTIN_CLZ 1
#else
#define FXL_USE_BUILTIN_CLZ 0
#endif
#endif

int fxl_clz32(uint32_t x)
{
    if (x == 0) {
        return 32; /* __builtin_clz(0) is undefined */
    }
#if FXL_USE_BUILTIN_CLZ
    /* unsigned int is 32 bits on every target selected above. */
    return __builtin_clz((unsigned int)x);
#else
    /* no libgcc helper (__clzsi2) on cores without a CLZ instruction such
     * as Cortex-M0+ */
    return fxl__clz32_soft(x);
#endif
}

int fxl_clz64(uint64_t x)
{
    uint32_t hi = (uint32_t)(x >> 32);
    if (hi != 0) {
        return fxl_clz32(hi);
    }
    return 32 + fxl_clz32((uint32_t)x);
}

uint64_t fxl__umul32_halves(uint32_t a, uint32_t b)
{
    return fxl__umul32_by_halves(a, b);
}

/* Restoring long division: d << s <= n < d << (s + 1) (d's leading one
 * aligned with n's), so the quotient has s + 1 bits, one per iteration.
 * The one loop of both widths below: the last statement of its function
 * (it returns q), on plain locals (it evaluates them more than once). */
#define FXL__SHIFT_SUBTRACT(q, n, d, s) \
    for (;;) {                          \
        if ((n) >= (d)) {               \
            (n) -= (d);                 \
            (q) |= 1u;                  \
        }                               \
        if ((s)-- == 0)                 \
            return (q);                 \
        (q) <<= 1;                      \
        (d) >>= 1;                      \
    }

#if !FXL__DIV32_HW
/* fxl__udiv64_loop in one word, for 0 < d <= n < 2^32: half the
 * instructions an iteration on a 32-bit core. Most of the generic walk's
 * step divisions are such; on cores without a divide instruction
 * (FXL__DIV32_HW, div64.h) they all take the loop: the Cortex-M0+ -Os
 * cube's ~270 instructions a step became ~120. Cores that divide 32 bits
 * in hardware divide those steps directly and keep 42 B of -Os core. */
static uint32_t udiv32_loop(uint32_t n, uint32_t d)
{
    uint32_t q = 0;
    int s = fxl_clz32(d) - fxl_clz32(n);

    d <<= s;
    FXL__SHIFT_SUBTRACT(q, n, d, s)
}
#endif

uint64_t fxl__udiv64_loop(uint64_t n, uint64_t d)
{
    uint64_t q = 0;
    int s;

    if (d == 0 || n < d)
        return 0;
#if !FXL__DIV32_HW
    if ((n >> 32) == 0u)
        return udiv32_loop((uint32_t)n, (uint32_t)d);
#endif
    s = fxl_clz64(d) - fxl_clz64(n);
    d <<= s;
    FXL__SHIFT_SUBTRACT(q, n, d, s)
}
#undef FXL__SHIFT_SUBTRACT

/* One base-2^16 digit of Knuth's algorithm D: the quotient digit of
 * (un << 16 | next) / d for un < d, d normalised (top bit set) with top
 * digit dn1 and low digit dn0; estimated from dn1, corrected at most twice.
 * q * dn0 is only formed once q < 2^16, and rhat < 2^16 there. */
static uint32_t udiv_digit(uint32_t un, uint32_t next, uint32_t dn1, uint32_t dn0)
{
    uint32_t q = un / dn1, rhat = un - q * dn1;
    while (q > 0xFFFFu || q * dn0 > ((rhat << 16) | next)) {
        q--;
        rhat += dn1;
        if (rhat > 0xFFFFu)
            break;
    }
    return q;
}

/* floor(n / d) for a 32-bit d != 0 from 32-bit divisions (div64.h uses it
 * on cores with a UDIV instruction, where the runtime's general 64-bit
 * division is ~50 instructions a call). The high word first; the rest,
 * whose quotient fits 32 bits, is long division in base 2^16 (two digits
 * of algorithm D) by d normalised so its top bit is set. */
uint64_t fxl__udiv64_by32(uint64_t n, uint32_t d)
{
    uint32_t nh = (uint32_t)(n >> 32), nl = (uint32_t)n, qh, q1, q0, un32, un21;
    int s;
    if (d == 0u)
        return 0u;
    qh = nh / d;
    nh -= qh * d;   /* now nh < d: the rest of the quotient fits 32 bits */
    if (nh == 0u)
        return ((uint64_t)qh << 32) | (nl / d);
    s = fxl_clz32(d);
    d <<= s;
    un32 = s ? (nh << s) | (nl >> (32 - s)) : nh;   /* < d */
    nl <<= s;
    q1 = udiv_digit(un32, nl >> 16, d >> 16, d & 0xFFFFu);
    un21 = (un32 << 16) + (nl >> 16) - q1 * d;   /* the remainder, < d: exact modulo 2^32 */
    q0 = udiv_digit(un21, nl & 0xFFFFu, d >> 16, d & 0xFFFFu);
    return ((uint64_t)qh << 32) | (q1 << 16) | q0;
}

/* ------------------------------------------------------------------------ */
/* 64-bit rounded and floored division                                      */

/* Both work on magnitudes: n = |num| <= 2^63, d = |den| <= 2^63, q = n / d,
 * r = n % d. A negative quotient has magnitude <= 2^63 and maps to INT64_MIN
 * at most; a positive one exceeds INT64_MAX only for INT64_MIN / -1.
 * den == 0 is outside the contract; it saturates like fxl_q16_div_sat
 * (toward the sign of num, 0 for 0 / 0) rather than trapping. */
static int64_t div64_from_mag(int negative, uint64_t q)
{
    if (negative) {
        if (q >= ((uint64_t)1 << 63)) {
            return INT64_MIN;
        }
        return -(int64_t)q;
    }
    if (q > (uint64_t)INT64_MAX) {
        return INT64_MAX;
    }
    return (int64_t)q;
}

static int64_t div64_by_zero(int64_t num)
{
    if (num > 0) {
        return INT64_MAX;
    }
    if (num < 0) {
        return INT64_MIN;
    }
    return 0;
}

int64_t fxl__sdiv64_loop(int64_t n, int64_t d)
{
    /* |q| is 2^63 for INT64_MIN / 1 (INT64_MIN) and INT64_MIN / -1 (which
     * saturates): div64_from_mag rebuilds both without a signed overflow */
    return div64_from_mag((n < 0) != (d < 0), fxl__udiv64_loop(abs_u64(n), abs_u64(d)));
}

int64_t fxl_div64_round(int64_t num, int64_t den)
{
    uint64_t n, d, q, r;
    if (den == 0) {
        return div64_by_zero(num);
    }
    n = abs_u64(num);
    d = abs_u64(den);
    q = fxl__udiv64(n, d);
    r = n - q * d; /* n % d without a second runtime division call */
    /* Round half away from zero: up when r >= d / 2, i.e. 2r >= d, written
     * as r >= d - r because 2r could wrap for d near 2^63 (r == 0 never passes:
     * d >= 1). If q is bumped then r != 0, so d >= 2 and q <= 2^62: q + 1
     * cannot wrap. */
    if (r >= d - r) {
        q++;
    }
    return div64_from_mag((num < 0) != (den < 0), q);
}

int64_t fxl_div64_floor(int64_t num, int64_t den)
{
    uint64_t n, d, q, r;
    int negative;
    if (den == 0) {
        return div64_by_zero(num);
    }
    n = abs_u64(num);
    d = abs_u64(den);
    q = fxl__udiv64(n, d);
    r = n - q * d; /* n % d without a second runtime division call */
    negative = (num < 0) != (den < 0);
    /* A negative inexact quotient floors one further away from zero. The
     * contract is den > 0; negative den gets the mathematical floor too. */
    if (negative && r != 0) {
        q++;
    }
    return div64_from_mag(negative, q);
}

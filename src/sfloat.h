/* sfloat.h - tiny integer "soft float" for setup-time and per-segment
 * estimates (LOD, error bounds): value = m * 2^e with |m| < 2^31.
 *
 * Why: derivative and error terms span more octaves than any one fixed
 * format (a sliver's gradients against a far q), but they are only needed to
 * a few significant bits. Products of two mantissas stay below 2^62, so every
 * operation is exact int64 arithmetic followed by one renormalising shift:
 * relative error < 2^-30 per operation, no floating point, no overflow.
 */
#ifndef FIXEL_SFLOAT_H
#define FIXEL_SFLOAT_H

#include "persp.h"

/* fxl__sf_t is declared in raster_int.h (the triangle keeps some). */

/* Inline on 32-bit cores outside -Os: out of line (GCC's choice once the
 * shift became 32-bit words) every per-segment LOD paid ~20 calls, M4
 * trilinear 109 -> 118 instructions a pixel. x86-64 keeps GCC's choice
 * (forced, its trilinear went 134 -> 137). */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__) && UINTPTR_MAX <= 0xFFFFFFFFu
#define FXL__SF_INLINE inline __attribute__((always_inline))
#else
#define FXL__SF_INLINE inline
#endif

static inline fxl__sf_t fxl__sf_make_body(int64_t m, int e)
{
    fxl__sf_t r;
    const uint64_t a = m < 0 ? (uint64_t)0 - (uint64_t)m : (uint64_t)m;
    int sh = 0;
    if (FXL__WORD32) {
        /* 32-bit cores: the bit length from 32-bit CLZs and the shift on
         * the two words (a 64-bit shift by a variable is ~10 instructions
         * and a branch there); the same values */
        const uint32_t ahi = (uint32_t)(a >> 32), alo = (uint32_t)a;
        if (ahi | (alo >> 31))
            sh = (ahi ? 64 - fxl__clz32_inline(ahi) : 32 - fxl__clz32_inline(alo)) - 31;
        r.m = fxl__asr64_to_i32(m, sh);
    } else {
        if (a >> 31)
            sh = 64 - fxl__clz64_inline(a) - 31;
        /* floor(m / 2^sh) has magnitude <= 2^31: INT32_MIN at worst */
        r.m = (int32_t)fxl__asr64(m, sh);
    }
    r.e = e + sh;
    return r;
}

/* m * 2^e normalised to |m| < 2^31 (floor). Size-optimised builds keep one
 * out-of-line copy (persp.c): GCC emitted one in each of auto.c and span.c,
 * 74 + 80 B of Cortex-M4 code. */
#if defined(__OPTIMIZE_SIZE__)
fxl__sf_t fxl__sf_make(int64_t m, int e);
#else
static FXL__SF_INLINE fxl__sf_t fxl__sf_make(int64_t m, int e)
{
    return fxl__sf_make_body(m, e);
}
#endif

/* a b + sign c d (sign = +1 or -1) with the two products exact (62 bits)
 * and the one of smaller exponent floored to the other's: an error below
 * one unit of the larger product's exponent (2^-60 of it for normalised
 * mantissas) plus the final rounding's 2^-30 of the result. The sum of two
 * products rounded to 31 bits each erred more and cost about twice the
 * Cortex-M4 instructions (the AUTO set-up's |N|, auto.c). */
static FXL__SF_INLINE fxl__sf_t fxl__sf_dot2(fxl__sf_t a, fxl__sf_t b, fxl__sf_t c, fxl__sf_t d, int sign)
{
    int64_t hi = (int64_t)a.m * b.m, lo = (int64_t)c.m * d.m, sum;   /* |.| <= 2^62 */
    int e = a.e + b.e, el = c.e + d.e;
    if (sign < 0)
        lo = -lo;
    /* hi: the product of larger exponent (a zero product has none) */
    if (hi == 0 || (lo != 0 && el > e)) {
        const int64_t t = hi;
        const int te = e;
        hi = lo;
        e = el;
        lo = t;
        el = te;
    }
    {
        /* e >= el unless lo is 0 (then a negative difference wraps to a
         * large unsigned one, and the shift of 0 by 63 is 0) */
        const unsigned sh = (unsigned)(e - el);
        lo = fxl__asr64(lo, sh > 63u ? 63 : (int)sh);
    }
    sum = (int64_t)((uint64_t)hi + (uint64_t)lo);
    if (hi > 0 && lo > 0 && sum < 0)   /* 2^62 + 2^62: both even */
        return fxl__sf_make((hi >> 1) + (lo >> 1), e + 1);
    return fxl__sf_make(sum, e);
}

static inline int fxl__sf_is_zero(fxl__sf_t a)
{
    return a.m == 0;
}

/* log2 |x| in q8 (x != 0); INT32_MIN / 4 for zero. |m| <= 2^31: the
 * 32-bit logarithm, inline (out of line, a 64-bit CLZ and a call were
 * ~0.2 Cortex-M4 instructions a pixel of the tunnel's AUTO set-up). */
static inline int32_t fxl__sf_log2_q8(fxl__sf_t x)
{
    const uint32_t a = x.m < 0 ? 0u - (uint32_t)x.m : (uint32_t)x.m;
    return a ? fxl__log2_q8_32(a) + x.e * 256 : INT32_MIN / 4;
}

#endif

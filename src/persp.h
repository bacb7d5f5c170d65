/* persp.h - the exact perspective division at a correction point (inline:
 * it runs every N pixels and is most of the per-segment cost).
 *
 * At a correction point the span loops need a = (attribute plane) / (q plane)
 * for two to five attributes sharing one q. One reciprocal of q is computed
 * and multiplied into each attribute:
 *   qv = qn * 2^(32 - n) + (dropped low bits),  qn in [2^31, 2^32)
 *   r  = 2^62 / qn  (one 32/32 division + one Newton step, see fxl__recip)
 *   a  = (av >> (PF - 1)) * r * 2^(n + PF - 95 + shift)
 * Error budget (relative): qn truncation < 2^-31, r < 2^-28, the 32-bit
 * attribute mantissa < 2^-30 of the largest vertex value of that attribute.
 * On a Cortex-M4 this is CLZ, UDIV, two UMULL for r and one SMULL per
 * attribute; on an M0+ the division and multiplies are library calls.
 */
#ifndef FIXEL_PERSP_H
#define FIXEL_PERSP_H

#include <stdint.h>
#include "raster_int.h"
#include "div64.h"
#include "clz.h"
#include "bits.h"

/* The perspective division runs at every correction point of every span
 * walk: on x86-64 a call plus spills is ~20% of a segment, so it is always
 * inlined there. On 32-bit targets the 64-bit arithmetic makes each copy
 * large: forced into the sixteen walks it added 23 KB of Cortex-M4 code
 * (-O2) for 1-2% fewer instructions, so there the compiler decides. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__) && UINTPTR_MAX > 0xFFFFFFFFu
#define FXL__ALWAYS_INLINE inline __attribute__((always_inline))
#else
#define FXL__ALWAYS_INLINE inline
#endif

/* 32-bit cores: where 64-bit shifts by a variable are long sequences (the
 * shortcut for them is left out of size-optimised builds). */
#ifndef FXL__WORD32   /* -DFXL__WORD32=1: the 32-bit cores' forms on a host (determinism.sh) */
#if defined(__OPTIMIZE_SIZE__)
#define FXL__WORD32 0
#else
#define FXL__WORD32 (UINTPTR_MAX <= 0xFFFFFFFFu)
#endif
#endif


/* Forced inline where it is a binary search (no CLZ instruction: the
 * Cortex-M0+, RISC-V without Zbb) outside -Os: GCC sometimes left it out of
 * line there, a call a correction point. Elsewhere it is one or two
 * instructions. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__) && !defined(__ARM_FEATURE_CLZ) && !defined(__x86_64__) &&   \
    !defined(__aarch64__) && !defined(__riscv_zbb)
#define FXL__CLZ_INLINE inline __attribute__((always_inline))
#else
#define FXL__CLZ_INLINE inline
#endif
static FXL__CLZ_INLINE int fxl__clz64_inline(uint64_t x)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__aarch64__) || (defined(__riscv_zbb) && __riscv_xlen == 64))
    return x ? __builtin_clzll(x) : 64;
#elif defined(__GNUC__) && (defined(__ARM_FEATURE_CLZ) || defined(__riscv_zbb))
    /* two CLZ on the halves, no call (RV32 Zbb: clz is 32 bits wide) */
    uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
    return hi ? __builtin_clz(hi) : (lo ? 32 + __builtin_clz(lo) : 64);
#elif !defined(__OPTIMIZE_SIZE__)
    /* no CLZ instruction (Cortex-M0+): the binary search inline, not two
     * calls (~1 M0+ instruction a pixel of the floor, ~4 of the tunnel) */
    const uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
    return hi ? fxl__clz32_soft(hi) : (lo ? 32 + fxl__clz32_soft(lo) : 64);
#else
    return fxl_clz64(x);
#endif
}

static inline int fxl__clz32_inline(uint32_t x)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__aarch64__) || defined(__ARM_FEATURE_CLZ) ||            \
                          defined(__riscv_zbb))
    return x ? __builtin_clz(x) : 32;
#elif !defined(__OPTIMIZE_SIZE__)
    return x ? fxl__clz32_soft(x) : 32;
#else
    return fxl_clz32(x);
#endif
}

/* log2 of x > 0 in q8: the position of the leading one, and the 8 bits
 * after it looked up in fxl__log2_frac_q8. Within (-1.94, +0.5) q8 steps of
 * the truth (the mantissa is truncated, the table rounded). */
static inline int32_t fxl__log2_q8_inline(uint64_t x)
{
    if (FXL__WORD32) {
        /* 32-bit cores: x normalised into one word (its leading one at bit
         * 31), the 8 bits after it taken from there; the same bits as the
         * 64-bit shift below in ~5 Cortex-M4 instructions less (the AUTO
         * set-up takes five of these a triangle) */
        const uint32_t hi = (uint32_t)(x >> 32), lo = (uint32_t)x;
        uint32_t top;
        int msb;
        if (hi) {
            const int c = fxl__clz32_inline(hi);
            msb = 63 - c;
            top = c ? (hi << c) | (lo >> (32 - c)) : hi;
        } else {
            const int c = fxl__clz32_inline(lo);
            msb = 31 - c;
            top = lo << (c & 31);   /* x = 0 (no caller's): 0, defined */
        }
        return (int32_t)msb * 256 + FXL__LOG2_FRAC_Q8((top >> 23) & 0xFFu);
    }
    {
        const int msb = 63 - fxl__clz64_inline(x);
        const uint32_t frac = (uint32_t)(msb >= 8 ? (x >> (msb - 8)) : (x << (8 - msb))) & 0xFFu;
        return (int32_t)msb * 256 + FXL__LOG2_FRAC_Q8(frac);
    }
}

/* fxl__log2_q8_inline's value for a 32-bit x >= 256, in 32-bit operations:
 * on a Cortex-M4 a 64-bit CLZ and shift are ~15 instructions more. */
static inline int32_t fxl__log2_q8_u32(uint32_t x)
{
    const int msb = 31 - fxl__clz32_inline(x);
    return (int32_t)msb * 256 + FXL__LOG2_FRAC_Q8((x >> (msb - 8)) & 0xFFu);
}

/* fxl__log2_q8_inline's value for any 32-bit x > 0, in 32-bit operations:
 * fxl__log2_q8_u32 without its x >= 256 condition (one select more), for
 * values that may be small (a budget, a width, a soft-float mantissa).
 * Size-optimised builds share the one out-of-line fxl__log2_q8. */
static inline int32_t fxl__log2_q8_32(uint32_t x)
{
#if defined(__OPTIMIZE_SIZE__)
    return fxl__log2_q8((uint64_t)x);
#else
    const int msb = 31 - fxl__clz32_inline(x);
    const uint32_t frac = (msb >= 8 ? x >> (msb - 8) : x << (8 - msb)) & 0xFFu;
    return (int32_t)msb * 256 + FXL__LOG2_FRAC_Q8(frac);
#endif
}

/* (int64)a * b, one SMULL on a Cortex-M3/M4. The empty asm (GCC, 32-bit
 * ARM) hides where a came from: GCC otherwise rebuilds fxl__persp_e's m
 * from the 64-bit plane value it was cut from and multiplies 64 x 32 bits
 * (MUL, MLA, UMULL). */
static inline int64_t fxl__mul_s32(int32_t a, int32_t b)
{
#if FXL__MUL_HALVES || FXL__MUL_HALVES_CALL
    /* the unsigned product of the bit patterns, less 2^32 b for a < 0 and
     * 2^32 a for b < 0 (modulo 2^64) */
    const uint64_t u = fxl__umul32((uint32_t)a, (uint32_t)b);
    const uint32_t fix = (a < 0 ? (uint32_t)b : 0u) + (b < 0 ? (uint32_t)a : 0u);
    const uint64_t p = u - ((uint64_t)fix << 32);
    return p <= (uint64_t)INT64_MAX ? (int64_t)p : -(int64_t)(~p) - 1;
#else
#if defined(__GNUC__) && defined(__arm__)
    __asm__("" : "+r"(a));
#endif
    return (int64_t)a * b;
#endif
}

/* (int32_t)fxl__asr64(x, k) for 0 <= k < 64 where the result fits int32
 * (the caller's guarantee), from the two 32-bit words: a 64-bit shift by a
 * variable is ~10 instructions and a branch on a 32-bit core. */
static inline int32_t fxl__asr64_to_i32(int64_t x, int k)
{
    const uint32_t lo = (uint32_t)(uint64_t)x;
    const uint32_t hi = (uint32_t)((uint64_t)x >> 32);
    if (k == 0)
        return fxl__i32_of_bits(lo);
    if (k < 32)
        return fxl__i32_of_bits((lo >> k) | (hi << (32 - k)));
    return fxl__asr32(fxl__i32_of_bits(hi), k - 32);
}

/* floor((2^32 - 1) / d) for d in (2^15, 2^16]: fxl__recip's first
 * estimate. Cores without a divide instruction (ARMv6-M) call
 * __aeabi_uidiv for it, ~130 instructions a correction point. With
 * FXL_DIV_TABLE (config.h; on in their -O2 builds) a table (d's top bits)
 * gives an estimate q0 at most ~510 below the quotient, one product with
 * q0 as 1/d refines it from below to within 2 (underestimates all the
 * way, so the remainder stays non-negative), and at most two steps
 * correct it: the exact quotient (test_fixed checks every d). */
#ifndef FXL__DIV_TABLE
#define FXL__DIV_TABLE FXL_DIV_TABLE
#endif
extern const uint16_t fxl__div_ffffffff_q0[256];   /* persp.c, where used */
static inline uint32_t fxl__div_ffffffff(uint32_t d)
{
#if FXL__DIV_TABLE
    /* d <= ((d - 1) >> 7) * 128 + 128: q0 <= the quotient; r0 < 2^25 */
    const uint32_t q0 = 65535u + fxl__div_ffffffff_q0[((d - 1u) >> 7) & 255u];
    const uint32_t r0 = 0xFFFFFFFFu - q0 * d;
    /* r0 / d from below: q0 / 2^32 <= 1 / d; the product < 2^31 */
    uint32_t q = q0 + (((r0 >> 10) * (q0 >> 1)) >> 21);
    uint32_t r = 0xFFFFFFFFu - q * d;
    while (r >= d) {
        q++;
        r -= d;
    }
    return q;
#else
    return 0xFFFFFFFFu / d;
#endif
}

/* Inline everywhere but in size-optimised builds: it is short, and where
 * GCC outlined it (span.c grew past its inlining budget) the M4 trilinear
 * walk paid ~2% in calls. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define FXL__RECIP_INLINE inline __attribute__((always_inline))
#else
#define FXL__RECIP_INLINE inline
#endif
/* r = 2^62 / qn in q30 for a normalised qn in [2^31, 2^32): fxl__recip's
 * value, for walks that keep q normalised themselves (exact_run, span.c). */
static FXL__RECIP_INLINE uint32_t fxl__recip_qn(uint32_t qn)
{
    const uint32_t d = (qn >> 16) + 1u;               /* (2^15, 2^16] */
    /* y0 = 2^48 / qn in q16, underestimated by < 2^-15 relative. */
    const uint32_t y0 = fxl__div_ffffffff(d);         /* <= 2^17 - 1 */
    /* Newton: y1 = y0 * (2 - x * y0) with x = qn / 2^32. e = x*y0 in q48 is
     * in [2^48 (1 - 2^-14), 2^48], so 2^49 - e in (2^48, 2^48 (1 + 2^-14)]
     * and t = (2^49 - e) >> 17 fits 32 bits (q31 of 2 - x*y0). */
    const uint64_t e = fxl__umul32(qn, y0);
    const uint32_t t = (uint32_t)(((UINT64_C(1) << 49) - e) >> 17);
    /* y0 (q16) * t (q31) = q47; >> 17 gives q30: r = 2^62 / qn, <= 2^31. */
    return (uint32_t)(fxl__umul32(y0, t) >> 17);
}

static FXL__RECIP_INLINE void fxl__recip(int64_t qv, fxl__recip_t *out)
{
    const uint64_t q = qv > 0 ? (uint64_t)qv : 1u;
    const int n = fxl__clz64_inline(q);
    out->r = fxl__recip_qn((uint32_t)((q << n) >> 32));   /* qn in [2^31, 2^32) */
    out->n = n;
}

/* The exponent of fxl__persp's result: a = m * r * 2^e with e = n + eb, where
 * eb = FXL__PF - 95 + shift is a per-triangle constant (fxl__persp_eb). */
static inline int fxl__persp_eb(int shift)
{
    return FXL__PF - 95 + shift;
}

/* fxl__persp_e's mantissa, av >> (PF - 1) as int32, and its range check
 * (bits 50..63 of av all equal, 0 or 0x3FFF, and not INT32_MIN: setup's
 * scaling makes that the rule). The walk along rows of constant q
 * (span_fast.h) checks a span once with it instead of each point. */
static inline int32_t fxl__persp_mant(int64_t av)
{
    return fxl__i32_of_bits((uint32_t)((uint64_t)av >> (FXL__PF - 1)));
}

static inline int fxl__persp_m_ok(int64_t av)
{
    const uint32_t top = (uint32_t)((uint64_t)av >> (FXL__PF + 30));
    return top == 0u || (top == 0x3FFFu && fxl__persp_mant(av) != INT32_MIN);
}

/* fxl__persp_e's product: the mantissa of av times 1/q's. */
static FXL__ALWAYS_INLINE int64_t fxl__persp_prod(int64_t av, const fxl__recip_t *rc)
{
    int32_t m = fxl__persp_mant(av);
    if (!fxl__persp_m_ok(av)) {
        /* Setup scales each attribute below 2^30 plane units, i.e. |m| <
         * 2^31; evaluation error can overshoot by a unit, so saturate. */
        m = fxl__asr64(av, FXL__PF - 1) > 0 ? INT32_MAX : -INT32_MAX;
    }
    /* r <= 2^31 - 2 (checked exhaustively over all 2^31 values of qn), so
     * both factors fit int32: one SMULL on a Cortex-M, |prod| < 2^62. */
    return fxl__mul_s32(m, (int32_t)rc->r);
}

/* fxl__persp_e's value for an exponent e in [-62, -33] (|a| < 2^29: u, v
 * within 2^13 texels of the rebased origin), on 32-bit words only:
 * floor(p / 2^(k-1)) = floor(hi / 2^(k-33)) with hi = floor(p / 2^32), and
 * floor((t + 1) / 2) = (t >> 1) + (t & 1). Bit for bit the value of the
 * general case, without its 64-bit shift by a variable (~16 Cortex-M4
 * instructions); on 64-bit cores the general case is as short. */
static FXL__ALWAYS_INLINE int32_t fxl__persp_w32(int64_t prod, int e)
{
    const int32_t hi = (int32_t)fxl__asr64(prod, 32);
    const int32_t t = fxl__asr32(hi, -e - 33);
    return fxl__asr32(t, 1) + (int32_t)((uint32_t)t & 1u);
}

static FXL__ALWAYS_INLINE int64_t fxl__persp_e(int64_t av, const fxl__recip_t *rc, int eb)
{
    const int e = rc->n + eb;
    const int64_t prod = fxl__persp_prod(av, rc);

    if (FXL__WORD32 && e <= -33 && e >= -62)
        return fxl__persp_w32(prod, e);   /* 32-bit cores */
    if (e < 0 && e >= -62) {
        /* The common case. Rounding half up, floor shift by k = -e:
         * floor((p + 2^(k-1)) / 2^k) equals floor((floor(p / 2^(k-1)) + 1) / 2),
         * which needs no 2^(k-1). */
        return fxl__asr64(fxl__asr64(prod, -e - 1) + 1, 1);
    }
    if (e == 0)
        return prod;
    if (e < 0)
        return 0;
    if (e > 62)
        return prod > 0 ? INT64_MAX : (prod < 0 ? INT64_MIN : 0);
    if (prod > (INT64_MAX >> e))
        return INT64_MAX;
    if (prod < -(INT64_MAX >> e))
        return INT64_MIN;
    return (int64_t)((uint64_t)prod << e);
}

/* Bits k..k+31 of p, 1 <= k <= 31: _words' case k < 32 (exact_run's
 * loops, span.c, choose the form once a stretch and call it directly) */
static inline uint32_t fxl__bits32_at(uint64_t p, int k)
{
    return ((uint32_t)p >> k) | ((uint32_t)(p >> 32) << (32 - k));
}

/* The low 32 bits of fxl__persp_e's value (the u, v of a repeat axis are
 * taken modulo 2^32) for an exponent e = -k, 1 <= k <= 62, from the product
 * prod = m * r and half = 2^(k-1): floor((prod + 2^(k-1)) / 2^k), which is
 * the rounding of both of fxl__persp_e's shifts (|prod| < 2^62: the sum
 * does not overflow). _words is the form in 32-bit words that 32-bit cores
 * use: bits k..k+31 of the sum. _hi is the one for k >= 33, where half's
 * low word is zero: the high word of prod plus 2^(k-33), shifted by
 * k - 32 (one add and one ASR). Both are tested on every host against the
 * 64-bit form (test_fixed). */
static inline uint32_t fxl__persp_lo32_words(int64_t prod, int k, uint64_t half)
{
    const uint64_t p = (uint64_t)prod + half;
    if (k >= 32)
        return (uint32_t)fxl__asr32(fxl__i32_of_bits((uint32_t)(p >> 32)), k - 32);
    return fxl__bits32_at(p, k);
}

static inline uint32_t fxl__persp_lo32_hi(int64_t prod, int k)
{
    const uint32_t hi = (uint32_t)((uint64_t)prod >> 32) + ((uint32_t)1 << (k - 33));
    return (uint32_t)fxl__asr32(fxl__i32_of_bits(hi), k - 32);
}

static inline uint32_t fxl__persp_lo32(int64_t prod, int k, uint64_t half)
{
    if (FXL__WORD32)
        return fxl__persp_lo32_words(prod, k, half);
    return (uint32_t)(uint64_t)fxl__asr64((int64_t)((uint64_t)prod + half), k);
}

static inline int64_t fxl__persp(int64_t av, const fxl__recip_t *rc, int shift)
{
    return fxl__persp_e(av, rc, fxl__persp_eb(shift));
}

/* Plane value at offset (dX, dY) from the reference vertex, inline for the
 * span walk (the arithmetic of fxl__plane_at: modular, see raster_int.h). */
static inline int64_t fxl__plane_eval(const fxl__plane_t *p, int32_t dX, int32_t dY)
{
    return (int64_t)((uint64_t)p->c + (uint64_t)p->gx * (uint64_t)(int64_t)dX +
                     (uint64_t)p->gy * (uint64_t)(int64_t)dY);
}

#endif

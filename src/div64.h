/* div64.h - every 64-bit division of the core goes through here.
 *
 * On 32-bit cores `n / d` with 64-bit operands is a call into the compiler's
 * runtime (__aeabi_uldivmod and __udivmoddi4: 0.7 KB of Cortex-M4 code; on a
 * Cortex-M0+ __divdi3 too, 1.2 KB), larger than fixel's whole span walk in a
 * small build. With FXL_SMALL_DIV64 (config.h; on by default in -Os builds)
 * the core uses fxl__udiv64_loop instead: a shift-subtract loop of ~60 bytes,
 * one iteration per quotient bit. Both give the exact truncated quotient, so
 * output is bit-identical either way; the loop is slower, and the core
 * divides 64-bit values only per triangle (set-up, edges) and once per span
 * (the generic walk's last segment). FXL_SMALL_DIV64_HW (config.h) keeps
 * the loop only for divisors beyond 32 bits on cores that divide 32 bits
 * in hardware: ~24% fewer Cortex-M4 -Os instructions on small triangles,
 * +366 B.
 */
#ifndef FIXEL_DIV64_H
#define FIXEL_DIV64_H

#include <stdint.h>
#include "fixel/config.h"

/* floor(n / d) for d != 0 by restoring long division (d == 0 gives 0: the
 * callers never pass it). Compiled in every build so tests check it against
 * the compiler's division on hosts. */
uint64_t fxl__udiv64_loop(uint64_t n, uint64_t d);
/* n / d truncated toward zero by the same loop, for d != 0; INT64_MIN / -1
 * saturates to INT64_MAX (one out-of-line call: smaller than the signs
 * inline) */
int64_t fxl__sdiv64_loop(int64_t n, int64_t d);

/* floor(n / d) for d != 0 from 32-bit divisions (0 for d == 0). Compiled
 * in every build so tests check it against the compiler's division. */
uint64_t fxl__udiv64_by32(uint64_t n, uint32_t d);

/* 32-bit cores with a hardware divide (Cortex-M3/M4/M7/M33): the divisors
 * of set-up (a triangle's doubled area in subpx^2, an edge's height) fit
 * 32 bits below ~2^8 px of height, and two UDIVs with their corrections
 * cost about half the runtime's general division. */
#if !FXL_SMALL_DIV64 && defined(__ARM_FEATURE_IDIV) && UINTPTR_MAX <= 0xFFFFFFFFu
#define FXL__DIV64_BY32 1
#else
#define FXL__DIV64_BY32 0
#endif

/* 32-bit cores whose 32-bit division is an instruction (Cortex-M3/M4/M7/
 * M33, RISC-V with M, i386): there a quotient that fits 32 bits is
 * cheaper as C's 32-bit `/` than as any 64-bit division. Not on ARMv6-M,
 * RV32I/E or cores this list does not know, where `/` may be a runtime
 * call (on the Cortex-M0+ it pulled libgcc's __aeabi_idiv, ~470 B, into
 * the smallest build). -DFXL__DIV32_HW=1 selects the forms on a 64-bit
 * host (determinism.sh's gcc -Os list). */
#ifndef FXL__DIV32_HW
#if UINTPTR_MAX == 0xFFFFFFFFu && (defined(__ARM_FEATURE_IDIV) || defined(__riscv_div) || defined(__i386__))
#define FXL__DIV32_HW 1
#else
#define FXL__DIV32_HW 0
#endif
#endif

/* Size builds that divide 32-bit divisors in hardware anyway
 * (FXL_SMALL_DIV64_HW, config.h): fxl__udiv64_by32 before the loop. */
#define FXL__SMALL_BY32 (FXL_SMALL_DIV64 && FXL_SMALL_DIV64_HW && FXL__DIV32_HW)

/* n / d, d != 0: a 32-bit divisor by fxl__udiv64_by32 where that is
 * chosen (speed builds on cores with UDIV, or FXL_SMALL_DIV64_HW), the rest
 * by the loop in size builds, by the compiler's division otherwise */
#if FXL_SMALL_DIV64
#define FXL__UDIV64_ANY(n, d) fxl__udiv64_loop(n, d)
#else
#define FXL__UDIV64_ANY(n, d) ((n) / (d))
#endif
static inline uint64_t fxl__udiv64(uint64_t n, uint64_t d)
{
#if FXL__DIV64_BY32 || FXL__SMALL_BY32
    return (d >> 32) == 0u ? fxl__udiv64_by32(n, (uint32_t)d) : FXL__UDIV64_ANY(n, d);
#else
    return FXL__UDIV64_ANY(n, d);
#endif
}

/* 32 x 32 -> 64-bit products. ARMv6-M (Cortex-M0/M0+) has no UMULL or
 * SMULL: GCC calls __aeabi_lmul, a 64 x 64 multiply (~45 instructions with
 * the call, four a correction point); four 16 x 16-bit MULS and their
 * carries take about half, inline. The same values (FXL__MUL_HALVES=1
 * selects them on any target: test_fixed checks them on the host). */
#ifndef FXL__MUL_HALVES
#if defined(__ARM_ARCH_6M__) && !defined(__OPTIMIZE_SIZE__)   /* -Os: the one libgcc copy */
#define FXL__MUL_HALVES 1
#else
#define FXL__MUL_HALVES 0
#endif
#endif

/* ARMv6-M size builds: the halves out of line (fxl__umul32_halves,
 * fixed.c), one copy for every product, ~25 instructions a call against
 * __aeabi_lmul's ~45. */
#ifndef FXL__MUL_HALVES_CALL
#if defined(__ARM_ARCH_6M__) && defined(__OPTIMIZE_SIZE__)
#define FXL__MUL_HALVES_CALL 1
#else
#define FXL__MUL_HALVES_CALL 0
#endif
#endif

static inline uint64_t fxl__umul32_by_halves(uint32_t a, uint32_t b)
{
    const uint32_t a0 = a & 0xFFFFu, a1 = a >> 16, b0 = b & 0xFFFFu, b1 = b >> 16;
    const uint32_t p00 = a0 * b0, p01 = a0 * b1, p10 = a1 * b0, p11 = a1 * b1;
    const uint32_t mid = p01 + p10;                  /* weight 2^16, may wrap */
    const uint32_t lo = p00 + (mid << 16);
    const uint32_t hi = p11 + (mid >> 16) + ((uint32_t)(mid < p01) << 16) + (uint32_t)(lo < p00);
    return ((uint64_t)hi << 32) | lo;
}

/* fxl__umul32_by_halves out of line (compiled in every build, so host
 * tests check it) */
uint64_t fxl__umul32_halves(uint32_t a, uint32_t b);

static inline uint64_t fxl__umul32(uint32_t a, uint32_t b)
{
#if FXL__MUL_HALVES
    return fxl__umul32_by_halves(a, b);
#elif FXL__MUL_HALVES_CALL
    return fxl__umul32_halves(a, b);
#else
    return (uint64_t)a * b;
#endif
}

/* Division by a divisor used several times (a triangle's doubled area, for
 * each of its gradients), on 32-bit cores outside -Os: there each 64-bit
 * division is a call of ~60 (Cortex-M4) to several hundred (M0+)
 * instructions, a high product ~15. r = floor((2^64 - 1) / d) once; then
 * for n < 2^63, with r d in (2^64 - 1 - d, 2^64), n r / 2^64 lies in
 * (n/d - 1/2, n/d), so its floor is the quotient or one below and one
 * correction against the remainder makes it exact: the same value as
 * n / d. */
#ifndef FXL__DIV64_RECIP   /* -DFXL__DIV64_RECIP=1: the same path on a 64-bit host (tests) */
#define FXL__DIV64_RECIP (!FXL_SMALL_DIV64 && UINTPTR_MAX <= 0xFFFFFFFFu)
#endif

typedef struct fxl__div64 {
    uint64_t d;   /* the divisor, != 0 */
    uint64_t r;   /* floor((2^64 - 1) / d) (FXL__DIV64_RECIP builds) */
} fxl__div64_t;

/* The high 64 bits of a * b from four 32 x 32 products (UMULL; halves on
 * ARMv6-M). */
static inline uint64_t fxl__mulhi64(uint64_t a, uint64_t b)
{
    const uint32_t a0 = (uint32_t)a, a1 = (uint32_t)(a >> 32), b0 = (uint32_t)b, b1 = (uint32_t)(b >> 32);
    const uint64_t p00 = fxl__umul32(a0, b0), p01 = fxl__umul32(a0, b1), p10 = fxl__umul32(a1, b0);
    const uint64_t mid = (p00 >> 32) + (uint32_t)p01 + (uint32_t)p10;
    return fxl__umul32(a1, b1) + (p01 >> 32) + (p10 >> 32) + (mid >> 32);
}

/* floor(n / d) for n < 2^63 from r = floor((2^64 - 1) / d), its remainder
 * in *rem (compiled everywhere, so host tests check it) */
static inline uint64_t fxl__udiv64_recip(uint64_t n, uint64_t d, uint64_t r, uint64_t *rem)
{
    uint64_t q = fxl__mulhi64(n, r), m = n - q * d;
    if (m >= d) {
        q++;
        m -= d;
    }
    *rem = m;
    return q;
}

static inline void fxl__div64_init(fxl__div64_t *dv, uint64_t d)
{
    dv->d = d;
    dv->r = FXL__DIV64_RECIP ? fxl__udiv64(UINT64_MAX, d) : 0u;
}

/* floor(n / dv->d) for n < 2^63, its remainder in *rem */
static inline uint64_t fxl__div64_by(uint64_t n, const fxl__div64_t *dv, uint64_t *rem)
{
    uint64_t q;
    if (FXL__DIV64_RECIP)
        return fxl__udiv64_recip(n, dv->d, dv->r, rem);
    q = fxl__udiv64(n, dv->d);
    *rem = n - q * dv->d;
    return q;
}

/* |x| as uint64, also for INT64_MIN. */
static inline uint64_t fxl__mag64(int64_t x)
{
    return x < 0 ? (uint64_t)0 - (uint64_t)x : (uint64_t)x;
}

/* C's n / d from q = |n| / |d|: q with the quotient's sign, its bit pattern
 * back to int64 without an out-of-range conversion (INT64_MIN / 1
 * included). */
static inline int64_t fxl__sdiv64_of_mag(int64_t n, int64_t d, uint64_t q)
{
    const uint64_t r = (n < 0) != (d < 0) ? (uint64_t)0 - q : q;
    return r <= (uint64_t)INT64_MAX ? (int64_t)r : -(int64_t)(~r) - 1;
}

/* fxl__sdiv64's value from the magnitudes' fxl__udiv64 (compiled
 * everywhere, so host tests check it against C's `/`). */
static inline int64_t fxl__sdiv64_mag(int64_t n, int64_t d)
{
    return fxl__sdiv64_of_mag(n, d, fxl__udiv64(fxl__mag64(n), fxl__mag64(d)));
}

/* n / d truncated toward zero, as C's `/`, for d != 0 and not INT64_MIN / -1 */
static inline int64_t fxl__sdiv64(int64_t n, int64_t d)
{
#if FXL__SMALL_BY32
    return fxl__sdiv64_mag(n, d);   /* fxl__udiv64: by32 for 32-bit divisors */
#elif FXL_SMALL_DIV64
    return fxl__sdiv64_loop(n, d);
#else
    return n / d;
#endif
}

/* fxl__sdiv64 for a divisor known to fit 32 bits, called often (the
 * generic walk's segment steps and AUTO's quadratic ones, divided by a
 * length): on cores with UDIV
 * two of them instead of the runtime's general 64-bit division (~100
 * Cortex-M4 instructions; 0.38 M of the firmware example's lit frame at
 * -O2). Elsewhere fxl__sdiv64 stays: inline in set-up's gradient, where
 * its rare general path takes it, this form cost the small triangles'
 * fast path ~11 Cortex-M4 instructions a triangle. */
static inline int64_t fxl__sdiv64_small(int64_t n, int32_t d)
{
#if FXL__DIV64_BY32
    return fxl__sdiv64_mag(n, d);
#else
    return fxl__sdiv64(n, d);
#endif
}

#endif

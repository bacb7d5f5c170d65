/* bits.h - two's-complement helpers shared by the rasterizer (persp.h) and
 * the front end (trig.c): floor shifts of signed values and the signed value
 * of a bit pattern, without C99's implementation-defined conversions and
 * shifts of negative values. Inline only; no state. */
#ifndef FIXEL_BITS_H
#define FIXEL_BITS_H

#include <stdint.h>

/* Does >> of a negative value shift in sign bits? C99 leaves it to the
 * implementation (GCC and Clang document that it does); the constant
 * expression is folded, and where it is false the portable form is used. */
#define FXL__SAR_IS_ARITHMETIC ((((int64_t)-5) >> 1) == -3 && (((int32_t)-5) >> 1) == -3)

/* Floor shift of a signed 64-bit value (0 <= k < 64). */
static inline int64_t fxl__asr64(int64_t x, int k)
{
    if (FXL__SAR_IS_ARITHMETIC)
        return x >> k;
    return x < 0 ? ~(int64_t)((uint64_t)~x >> k) : (int64_t)((uint64_t)x >> k);
}

/* Floor shift of a signed 32-bit value (0 <= k < 32). */
static inline int32_t fxl__asr32(int32_t x, int k)
{
    if (FXL__SAR_IS_ARITHMETIC)
        return x >> k;
    return x < 0 ? -(int32_t)(~(uint32_t)x >> k) - 1 : (int32_t)((uint32_t)x >> k);
}

/* The int32 whose two's-complement bit pattern is b (no conversion of an
 * out-of-range value: the compiler folds this to nothing). */
static inline int32_t fxl__i32_of_bits(uint32_t b)
{
    return b <= INT32_MAX ? (int32_t)b : -(int32_t)(~b) - 1;
}

/* The int64 whose two's-complement bit pattern is b, likewise. */
static inline int64_t fxl__i64_of_bits(uint64_t b)
{
    return b <= (uint64_t)INT64_MAX ? (int64_t)b : -(int64_t)(~b) - 1;
}

#endif

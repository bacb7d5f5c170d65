/* fixel/fixed.h - 16.16 fixed-point arithmetic (q16).
 *
 * A fxl_q16_t holds value * 65536 in an int32_t: range [-32768, 32768 - 2^-16],
 * resolution 2^-16. Products and quotients use 64-bit intermediates.
 *
 * Rounding: every function that drops bits rounds to nearest, ties away from
 * zero (so results are symmetric, f(-a, b) == -f(a, b), wherever neither
 * saturates: FXL_Q16_MIN is one unit further from zero than FXL_Q16_MAX).
 * Overflow: functions named _sat saturate to FXL_Q16_MAX / FXL_Q16_MIN; the
 * _chk variants return FXL_ERR_RANGE and leave *out untouched (a NULL out is
 * FXL_ERR_ARG). No function here ever performs a signed overflow, for any
 * argument.
 */
#ifndef FIXEL_FIXED_H
#define FIXEL_FIXED_H

#include <stdint.h>
#include "fixel/status.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef int32_t fxl_q16_t;

#define FXL_Q16_ONE  ((fxl_q16_t)0x10000)
#define FXL_Q16_HALF ((fxl_q16_t)0x8000)
#define FXL_Q16_MAX  ((fxl_q16_t)INT32_MAX)
#define FXL_Q16_MIN  ((fxl_q16_t)INT32_MIN)

/* Integer constant -> q16 (for compile-time constants with |i| < 32768). */
#define FXL_Q16_INT(i) ((fxl_q16_t)((int32_t)(i) * 65536))

/* Round-to-nearest q16 -> integer (ties away from zero). */
int32_t fxl_q16_round(fxl_q16_t a);
/* Floor and ceiling q16 -> integer. */
int32_t fxl_q16_floor(fxl_q16_t a);
int32_t fxl_q16_ceil(fxl_q16_t a);
/* Integer -> q16, saturating outside [-32768, 32767]. */
fxl_q16_t fxl_q16_from_int_sat(int32_t i);

fxl_q16_t fxl_q16_add_sat(fxl_q16_t a, fxl_q16_t b);
fxl_q16_t fxl_q16_sub_sat(fxl_q16_t a, fxl_q16_t b);
/* a * b, rounded to nearest. */
fxl_q16_t fxl_q16_mul_sat(fxl_q16_t a, fxl_q16_t b);
fxl_status_t fxl_q16_mul_chk(fxl_q16_t a, fxl_q16_t b, fxl_q16_t *out);
/* a / b, rounded to nearest. Division by zero saturates toward the sign of a
 * (0 / 0 gives 0) in _sat and is FXL_ERR_RANGE in _chk. */
fxl_q16_t fxl_q16_div_sat(fxl_q16_t a, fxl_q16_t b);
fxl_status_t fxl_q16_div_chk(fxl_q16_t a, fxl_q16_t b, fxl_q16_t *out);
/* 1 / a, rounded to nearest; same zero and overflow rules as division. */
fxl_q16_t fxl_q16_recip_sat(fxl_q16_t a);
/* Square root of a >= 0 (negative input gives 0), rounded to nearest. */
fxl_q16_t fxl_q16_sqrt(fxl_q16_t a);

/* Number of leading zero bits of x (32 for x == 0). Uses the CLZ instruction
 * where the target has one, a short branch tree elsewhere (Cortex-M0+). */
int fxl_clz32(uint32_t x);
int fxl_clz64(uint64_t x);

/* Rounded 64-bit quotient num / den (ties away from zero). INT64_MIN / -1
 * saturates to INT64_MAX; den == 0 saturates too: INT64_MAX for num > 0,
 * INT64_MIN for num < 0, 0 for num == 0 (no trap, no undefined behaviour). */
int64_t fxl_div64_round(int64_t num, int64_t den);
/* floor(num / den) for den > 0. */
int64_t fxl_div64_floor(int64_t num, int64_t den);

#ifdef __cplusplus
}
#endif
#endif

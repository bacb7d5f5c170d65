/* src/pipeline_int.h - helpers shared by the front-end files (pipeline.c,
 * clip.c, trig.c, texgen.c, light.c, mesh.c). Not part of the public API.
 * All of them are total: defined for every argument, no signed overflow.
 */
#ifndef FIXEL_PIPELINE_INT_H
#define FIXEL_PIPELINE_INT_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/pipeline.h"

/* round(x / 2^sh) with ties away from zero, 0 <= sh <= 62. */
int64_t fxl__shr_round(int64_t x, unsigned sh);
/* floor(x / 2^sh), 0 <= sh <= 63 (an arithmetic shift without relying on
 * implementation-defined >> of negative numbers). */
int64_t fxl__asr(int64_t x, unsigned sh);
/* round(a * b / 2^sh), ties away from zero, through a 96-bit product;
 * 0 <= sh <= 95. Saturates to +-INT64_MAX and sets *ovf (if not NULL). */
int64_t fxl__mul_shr(int64_t a, uint32_t b, unsigned sh, int *ovf);
int64_t fxl__mul_shr_s(int64_t a, int32_t b, unsigned sh, int *ovf);
/* a + b saturating; sets *ovf on saturation. */
int64_t fxl__add_sat(int64_t a, int64_t b, int *ovf);
/* Clamp to int32 and set *ovf when clamped. */
int32_t fxl__to_i32(int64_t x, int *ovf);
int fxl__clz64(uint64_t x);
/* floor(sqrt(x)). */
uint64_t fxl__isqrt64(uint64_t x);
/* sin and cos of a in q30 (|error| <= 2^-21 + 2^-29). */
void fxl__sincos_q30(fxl_angle_t a, int32_t *s, int32_t *c);
/* Angle of (x, y) in q32 turns (uint32, wraps), any int64 inputs with
 * |x|, |y| < 2^62. (0, 0) gives 0. */
uint32_t fxl__atan2_q32(int64_t y, int64_t x);

#endif

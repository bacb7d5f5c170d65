/* src/pipeline_int.h - helpers shared by the front-end files (pipeline.c,
 * clip.c, trig.c, texgen.c, light.c, mesh.c). Not part of the public API.
 * All of them are total: defined for every argument, no signed overflow.
 */
#ifndef FIXEL_PIPELINE_INT_H
#define FIXEL_PIPELINE_INT_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/pipeline.h"
#include "isqrt.h"
#include "div64.h"

/* The hot helpers below are defined here so that -O2 builds can inline
 * them where they run per vertex or per corner (FXL__HOT_*): there a
 * constant shift folds most of fxl__mul_shr's 64-bit shifts by a variable
 * away (~40 Cortex-M4 instructions a call out of line). Size-optimised
 * builds call the one out-of-line copy each (pipeline.c). */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define FXL__PIPE_INLINE inline __attribute__((always_inline))
#define FXL__HOT_ASR fxl__asr_i
#define FXL__HOT_MUL_SHR fxl__mul_shr_i
#define FXL__HOT_MUL_SHR_S fxl__mul_shr_s_i
#define FXL__HOT_TO_I32 fxl__to_i32_i
#else
#define FXL__PIPE_INLINE inline
#define FXL__HOT_ASR fxl__asr
#define FXL__HOT_MUL_SHR fxl__mul_shr
#define FXL__HOT_MUL_SHR_S fxl__mul_shr_s
#define FXL__HOT_TO_I32 fxl__to_i32
#endif

/* floor(n / d), d != 0, for the front end's divisions. Their divisors fit
 * 32 bits (a normal's length, a projection's normalised w, 255, a clip
 * distance), and where 32-bit division is an instruction (FXL__DIV32_HW:
 * Cortex-M3 and up, RISC-V with M) two of them with their corrections
 * (fxl__udiv64_by32) are ~5x faster than the shift-subtract loop that
 * FXL_SMALL_DIV64 gives size builds, whose core keeps that loop for its
 * 16 KiB unless FXL_SMALL_DIV64_HW: in the firmware example's -Os lit
 * frame the loop was 34% of the front end. Exact either way: the same
 * quotients. */
static inline uint64_t fxl__fe_udiv64(uint64_t n, uint64_t d)
{
#if FXL__DIV32_HW
    if ((d >> 32) == 0u)
        return fxl__udiv64_by32(n, (uint32_t)d);
#endif
    return fxl__udiv64(n, d);
}

/* n / d truncated toward zero (C's `/`) through fxl__fe_udiv64, d != 0,
 * not INT64_MIN / -1 */
static inline int64_t fxl__fe_sdiv64(int64_t n, int64_t d)
{
#if FXL__DIV32_HW
    return fxl__sdiv64_of_mag(n, d, fxl__fe_udiv64(fxl__mag64(n), fxl__mag64(d)));
#else
    return fxl__sdiv64(n, d);
#endif
}

/* m with the sign neg, saturated to INT64_MAX (setting *ovf if not NULL). */
static FXL__PIPE_INLINE int64_t fxl__apply_sign(uint64_t m, int neg, int *ovf)
{
    if (m > (uint64_t)INT64_MAX) {
        if (ovf) *ovf = 1;
        m = (uint64_t)INT64_MAX;
    }
    return neg ? -(int64_t)m : (int64_t)m;
}

/* fxl__asr */
static FXL__PIPE_INLINE int64_t fxl__asr_i(int64_t x, unsigned sh)
{
    if (x >= 0) return x >> sh;
    /* floor(x / 2^sh) = -ceil(-x / 2^sh) = -(((-x) - 1) >> sh) - 1 */
    return -(int64_t)(((uint64_t)0 - (uint64_t)x - 1u) >> sh) - 1;
}

/* fxl__mul_shr */
static FXL__PIPE_INLINE int64_t fxl__mul_shr_i(int64_t a, uint32_t b, unsigned sh, int *ovf)
{
    uint64_t m = fxl__mag64(a), hi, lo, r;
    /* 96-bit magnitude = hi * 2^32 + lo, lo < 2^32. ah <= 2^31 so
     * ah * b < 2^63 and hi cannot wrap. */
    uint64_t ph = (m >> 32) * b, pl = (m & 0xFFFFFFFFu) * b;
    hi = ph + (pl >> 32);
    lo = pl & 0xFFFFFFFFu;
    if (sh > 0) { /* add half an output unit: ties away from zero */
        if (sh <= 32) {
            lo += (uint64_t)1 << (sh - 1);
            hi += lo >> 32;
            lo &= 0xFFFFFFFFu;
        } else {
            hi += (uint64_t)1 << (sh - 33);
        }
    }
    if (sh <= 32) {
        if ((hi >> (31 + sh)) != 0) {
            r = (uint64_t)INT64_MAX + 1u; /* forces saturation */
        } else {
            r = (hi << (32 - sh)) | (lo >> sh);
        }
    } else {
        r = hi >> (sh - 32);
    }
    return fxl__apply_sign(r, a < 0, ovf);
}

/* fxl__to_i32 */
static FXL__PIPE_INLINE int32_t fxl__to_i32_i(int64_t x, int *ovf)
{
    if (x > INT32_MAX) { if (ovf) *ovf = 1; return INT32_MAX; }
    if (x < -INT32_MAX) { if (ovf) *ovf = 1; return -INT32_MAX; }
    return (int32_t)x;
}

/* fxl__mul_shr_s */
static FXL__PIPE_INLINE int64_t fxl__mul_shr_s_i(int64_t a, int32_t b, unsigned sh, int *ovf)
{
    uint32_t mb = b < 0 ? (uint32_t)0 - (uint32_t)b : (uint32_t)b;
    int64_t r = fxl__mul_shr_i(a, mb, sh, ovf);
    return b < 0 ? -r : r; /* r is never INT64_MIN */
}

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
/* Is xf within the ranges fxl_pipeline_prepare gives its fields (near in
 * [2^-16, 2^15) units, far 0 or beyond near, 1 <= G <= FXL_GUARD_MAX, G
 * times the larger half size at most FXL_GUARD_PX, viewport centre and
 * half sizes within the target limits)? fxl_xform_project and
 * fxl_clip_triangle refuse a hand-filled xf outside them: their shifts and
 * sums rely on them. */
int fxl__xform_ok(const fxl_xform_t *xf);
/* fxl_clip_triangle for an xf known good (the mesh path's, from
 * fxl_pipeline_prepare): no argument or xf checks, ~2% of a vertex's
 * Cortex-M4 instructions. */
fxl_status_t fxl__clip_triangle(const fxl_xform_t *xf, const fxl_clipvert_t in[3],
                                fxl_clipvert_t out[FXL_CLIP_MAX_VERTS], uint32_t *n);
/* The clip planes (clip.c) a clip-space position lies outside: bit set
 * for each plane whose signed distance is negative; 0 inside all of them,
 * where the clipper returns a triangle unchanged, and a triangle whose
 * three codes share a bit is outside whole. Positions within
 * FXL_CLIP_LIMIT_Q32, xf fxl_pipeline_prepare's. */
int fxl__clip_outcode(const fxl_xform_t *xf, int64_t x, int64_t y, int64_t w);
/* sin and cos of a in q30 (|error| <= 2^-21 + 2^-29). */
void fxl__sincos_q30(fxl_angle_t a, int32_t *s, int32_t *c);
/* The same for an angle in 2^-17 turns (any uint32, wraps): half of an
 * fxl_angle_t without losing its lowest bit (gluPerspective's fovy / 2). */
void fxl__sincos_fine_q30(uint32_t a17, int32_t *s, int32_t *c);
/* Angle of (x, y) in q32 turns (uint32, wraps), any int64 inputs with
 * |x|, |y| < 2^62. (0, 0) gives 0. */
uint32_t fxl__atan2_q32(int64_t y, int64_t x);

/* Texture-coordinate generation in two steps (fxl_texgen_triangle is the
 * three calls of the first and one of the second). The per-vertex data
 * out[3] is: planar (raw u, raw v, 0); cylindrical / spherical (raw u =
 * theta q16 in [0, 65536], raw v, pole flag); cube (the position x, y, z);
 * none (0, 0, 0). tg must be valid (fxl_texgen_triangle checks it). */
void fxl__texgen_vertex(const fxl_texgen_t *tg, const fxl_vec3_t *pos, int32_t out[3]);
/* Seams, poles, cube face, then scale and offset, for one triangle. */
void fxl__texgen_finish(const fxl_texgen_t *tg, const int32_t vt[3][3], fxl_texcoord_t out[3]);

#endif

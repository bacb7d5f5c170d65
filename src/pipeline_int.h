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
 * [2^-16, 2^31) units, far 0 or beyond near, 0 < G, G times the larger half
 * size at most FXL_GUARD_PX, viewport centre and half sizes within the
 * target limits)? fxl_xform_project and fxl_clip_triangle refuse a
 * hand-filled xf outside them: their shifts and sums rely on them. */
int fxl__xform_ok(const fxl_xform_t *xf);
/* fxl_clip_triangle for an xf known good (the mesh path's, from
 * fxl_pipeline_prepare): no argument or xf checks, ~2% of a vertex's
 * Cortex-M4 instructions. */
fxl_status_t fxl__clip_triangle(const fxl_xform_t *xf, const fxl_clipvert_t in[3],
                                fxl_clipvert_t out[FXL_CLIP_MAX_VERTS], uint32_t *n);
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

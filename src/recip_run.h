/* recip_run.h - FXL_PERSP_AUTO's reciprocal runs: u and v at every pixel
 * of a span from an approximate 1/q, for triangles whose segments would be
 * short (auto.c, fxl__auto_bound, sets tri->auto_rr).
 *
 * Along a span q, u q and v q are linear. Normalised to 32 bits (q in
 * [2^31, 2^32), u q as a, v q as b) they step by one add each; at each
 * pixel
 *   R = 2^62 / q      (fxl__rr_recip: a 32-bit division for a seed within
 *                      2^-9, one Newton step; relative error in
 *                      (-2^-18.0, +2^-30.4), and R < 2^31, checked over
 *                      every q)
 *   u = a R / 2^32,   v = b R / 2^32    (the high words of two products)
 * so a pixel costs a division and four multiplies wherever the segments'
 * error bound (auto.h) would ask for a correction every few pixels.
 *
 * The values are a function of the pixel alone, whatever the clip or band:
 * a run starts (fxl__rr_origin: exact plane values, one normalisation) at
 * xl + j 2^FXL__RR_BLOCK_LOG2 and wherever the stepped q leaves its octave,
 * and each pixel's values are the run start's stepped to it. The generic
 * walk (span.c, draw_span_rr) and the fast walks (span_fast.h, FXL_T_RR)
 * share these functions, so they agree bit for bit
 * (test_auto_reciprocal_runs_agree_and_stay_within_budget).
 *
 * Error (q16 texels of level 0), for |u| < 2^29 - 2^16 (auto.c keeps
 * |u| + |v| of the vertices below it; |a| < 4 |u| + 2^8 < 2^31):
 *   |u| 2^-18 from R, at most 1 unit of a's truncation and 1 a step
 *   (steps truncated, at most 2^8 a run) times R / 2^32 < 2^-1, and 1
 *   for the product's floor: under |u| 2^-18 + 130 units. q's stepped
 *   value drifts by under 2^8 units of 2^-31 relative, which is nothing
 *   beside the 2^-18.
 */
#ifndef FIXEL_RECIP_RUN_H
#define FIXEL_RECIP_RUN_H

#include <stdint.h>
#include "raster_int.h"
#include "persp.h"

/* runs restart at least every 2^8 pixels of a span: the truncated steps
 * drift by at most a unit each */
#define FXL__RR_BLOCK_LOG2 8

/* AUTO takes runs for a triangle whose every segment would be at most
 * 2^FXL__RR_SEG_LOG2 pixels long (auto.c): a run pixel (~30 Cortex-M4
 * instructions) against a segment pixel (~8) and its correction (~150 to
 * ~380 with the chooser and the quadratic steps) */
#define FXL__RR_SEG_LOG2 4

typedef struct fxl__rr {
    uint32_t q, dq;   /* q normalised to [2^31, 2^32), and its step a pixel */
    uint32_t a, da;   /* u's numerator (int32 bits) and step */
    uint32_t b, db;   /* v's */
    int32_t x;        /* the pixel these values are at */
    int32_t left;     /* pixels from x on (x included) whose q is in range:
                       * at 0, x's q has left it (fxl__rr_next) */
    int32_t xe;       /* the end of x's block, where runs restart */
} fxl__rr_t;

/* ARMv7E-M (Cortex-M4, M7): the high word of a product in one
 * instruction with one destination, SMMUL / SMMLA (truncating, as the C
 * forms). GCC uses them for neither, and SMULL's second destination
 * costs the run loop a register. */
#if defined(__GNUC__) && defined(__ARM_FEATURE_DSP) && !FXL__MUL_HALVES
#define FXL__RR_SMMUL 1
#else
#define FXL__RR_SMMUL 0
#endif

/* (int64)a * b: one SMULL on a Cortex-M3/M4 (fxl__mul_s32's empty asm,
 * there to keep GCC off a 64-bit source, cost a register copy a product
 * here: operands that live on through the loop) */
static inline int64_t fxl__rr_mul(int32_t a, int32_t b)
{
#if FXL__MUL_HALVES
    return fxl__mul_s32(a, b);
#else
    return (int64_t)a * b;
#endif
}

/* Newton's step from a seed r0 of 2^62 / q, from below: 2^32 (1 -
 * q r0 / 2^62), less 1, is small as an int32 d, and r0 + r0 d / 2^32 is
 * the refined reciprocal (relative error squared). */
static inline uint32_t fxl__rr_newton(uint32_t q, uint32_t r0)
{
    const uint32_t h = (uint32_t)(fxl__umul32(q, r0) >> 32);   /* q r0 / 2^32, ~2^30 */
    const int32_t d = fxl__i32_of_bits(~(h << 2));
#if FXL__RR_SMMUL
    int32_t r;
    __asm__("smmla %0, %1, %2, %1" : "=r"(r) : "r"((int32_t)r0), "r"(d));
    return (uint32_t)r;
#else
    return r0 + (uint32_t)(int32_t)fxl__asr64(fxl__rr_mul((int32_t)r0, d), 32);
#endif
}

/* 2^62 / q for q in [2^31, 2^32), in (2^30, 2^31). The seed is the
 * bucket's midpoint, (2^32 - 1) / (2j + 1) with j = q >> 23 (t = q >> 22
 * is 2j or 2j + 1), within 2^-9; Newton then squares its relative error,
 * from below (at q = 2^31 the seed is 2^-9 low: R stays under 2^31). */
static inline uint32_t fxl__rr_recip(uint32_t q)
{
    return fxl__rr_newton(q, (0xFFFFFFFFu / ((q >> 22) | 1u)) << 8);
}

#if FXL__FAST_SPANS
/* The same with the seed from a table (recip_run.c) */
extern const uint32_t fxl__rr_seed[256];
static inline uint32_t fxl__rr_recip_tab(uint32_t q)
{
    return fxl__rr_newton(q, fxl__rr_seed[(q >> 23) & 255u]);
}
#endif

/* The high word of a R as an int32's bits: u (or v) in q16 texels. */
static inline uint32_t fxl__rr_coord(uint32_t a, uint32_t r)
{
#if FXL__RR_SMMUL
    int32_t u;
    __asm__("smmul %0, %1, %2" : "=r"(u) : "r"(fxl__i32_of_bits(a)), "r"((int32_t)r));
    return (uint32_t)u;
#else
    return (uint32_t)(uint64_t)fxl__asr64(fxl__rr_mul(fxl__i32_of_bits(a), (int32_t)r), 32);
#endif
}

/* The low 32 bits of v * 2^t (t < 0: a floor shift), from v's two words:
 * a 64-bit shift by a variable is ~10 instructions on a 32-bit core */
static inline uint32_t fxl__rr_scale(int64_t v, int t)
{
    if (t >= 0)
        return t < 32 ? (uint32_t)(uint64_t)v << t : 0u;
    return (uint32_t)fxl__asr64_to_i32(v, -t < 63 ? -t : 63);
}

/* Pixels from this one on whose q stays in [2^31, 2^32) stepping by dq
 * (int32 bits, |dq| < 2^31), at most cap. One division (UDIV on a
 * Cortex-M3/M4) a run. */
static inline int32_t fxl__rr_len(uint32_t q, uint32_t dq, int32_t cap)
{
    const int32_t s = fxl__i32_of_bits(dq);
    uint32_t run;
    if (s == 0)
        return cap;
    run = (s < 0 ? (q - 0x80000000u) / (0u - dq) : (0xFFFFFFFFu - q) / dq) + 1u;
    return run < (uint32_t)cap ? (int32_t)run : cap;
}

/* Plane p at pixel x of the row dY below the reference vertex: the walks'
 * inline evaluation, or at -Os the one out-of-line copy (the same
 * modular arithmetic) */
static inline int64_t fxl__rr_plane(const fxl__tri_t *tri, const fxl__plane_t *p, int32_t x, int32_t dY)
{
#if defined(__OPTIMIZE_SIZE__)
    return fxl__plane_at(p, tri->X0, 0, x * FXL__ONE + FXL__HALF, dY);
#else
    return fxl__plane_eval(p, x * FXL__ONE + FXL__HALF - tri->X0, dY);
#endif
}

/* A run's start at pixel x of the row dY below the reference vertex, in
 * the span from xl: exact plane values, normalised. */
void fxl__rr_origin(const fxl__tri_t *tri, int32_t dY, int32_t xl, int32_t x, fxl__rr_t *rr);

/* rr stepped by j pixels, 0 <= j <= rr->left */
static inline void fxl__rr_skip(fxl__rr_t *rr, uint32_t j)
{
    rr->q += rr->dq * j;
    rr->a += rr->da * j;
    rr->b += rr->db * j;
    rr->x += (int32_t)j;
    rr->left -= (int32_t)j;
}

/* The next run, where the last one ended (rr->left == 0). Where q rose
 * past 2^32 (at most once: it was below, and |dq| < 2^31) every value and
 * step is halved, which keeps the error of each step within the same
 * share of a texel. Where q fell, at a block's end, and after a run of
 * constant q (dq == 0: it ends at the block's end) or of one pixel
 * (fxl__rr_origin), a fresh start: doubling the stepped values instead
 * would double the drift of their truncated steps with every octave (on
 * a span that recedes 64-fold, 0.04 texel). */
static inline void fxl__rr_next(const fxl__tri_t *tri, int32_t dY, int32_t xl, fxl__rr_t *rr)
{
    if (rr->x < rr->xe && fxl__i32_of_bits(rr->dq) > 0) {
        rr->q = (rr->q >> 1) | 0x80000000u;
        rr->dq >>= 1;
        rr->a = (uint32_t)fxl__asr32(fxl__i32_of_bits(rr->a), 1);
        rr->da = (uint32_t)fxl__asr32(fxl__i32_of_bits(rr->da), 1);
        rr->b = (uint32_t)fxl__asr32(fxl__i32_of_bits(rr->b), 1);
        rr->db = (uint32_t)fxl__asr32(fxl__i32_of_bits(rr->db), 1);
        rr->left = fxl__rr_len(rr->q, rr->dq, rr->xe - rr->x);
        return;
    }
    fxl__rr_origin(tri, dY, xl, rr->x, rr);
}

/* rr moved on to pixel x >= rr->x of the span from xl, over the runs
 * between */
static inline void fxl__rr_advance(const fxl__tri_t *tri, int32_t dY, int32_t xl, int32_t x, fxl__rr_t *rr)
{
    while (x - rr->x >= rr->left) {
        fxl__rr_skip(rr, (uint32_t)rr->left);
        fxl__rr_next(tri, dY, xl, rr);
    }
    fxl__rr_skip(rr, (uint32_t)(x - rr->x));
}

/* The run state at pixel x of the span from xl: from its block's start,
 * over the runs before x */
static inline void fxl__rr_seek(const fxl__tri_t *tri, int32_t dY, int32_t xl, int32_t x, fxl__rr_t *rr)
{
    fxl__rr_origin(tri, dY, xl, xl + (int32_t)(((uint32_t)(x - xl) >> FXL__RR_BLOCK_LOG2) << FXL__RR_BLOCK_LOG2),
                   rr);
    fxl__rr_advance(tri, dY, xl, x, rr);
}

#endif

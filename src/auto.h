/* auto.h - FXL_PERSP_AUTO per segment: each segment is the longest aligned
 * block whose affine error bound fits the budget (inline: the span walks
 * call it at every correction point).
 *
 * Along a row, N = (N_u, N_v) = S_x q - S q_x is constant (auto.c), so the
 * chord between exact points L pixels apart errs by at most
 *   err(L) <= L^2 / 4 * |q_x| * |N(row)| / q_min^3   (texels of level 0)
 * with q_min the smaller q at the segment's ends (q is linear). In q8 log2:
 *   2^k fits  <=>  k <= (t_row + 3 log2 q_min) / 2,
 * t_row holding the budget, |q_x| and |N(row)| with their rounding margins.
 * The allowed length grows as q^1.5: short segments where the surface
 * recedes, long ones where it is near, within one span.
 *
 * Segments are aligned blocks: one of 2^k pixels starts at xl + j 2^k. Pixel
 * p's segment is the longest such block containing p that satisfies the
 * bound over its part inside the span (capped at 2^auto_cap). A block inside
 * a satisfying block satisfies it too (shorter, larger q_min), so these
 * blocks partition the span, and the partition depends on the span and the
 * triangle only: the walk may start at the block containing the clip edge
 * (fxl__auto_first) and cuts exactly where a walk from xl would. Bands,
 * clip rectangles and full frames agree bit for bit, and a triangle a
 * million pixels wide costs nothing left of the clip.
 */
#ifndef FIXEL_AUTO_H
#define FIXEL_AUTO_H

#include "raster_int.h"
#include "persp.h"

#if FXL_HAVE_AUTO

/* fxl__log2_q8_inline (persp.h) of q >> FXL__PF >= 256, in 32 bits: a
 * 64-bit CLZ and shift cost the per-segment test ~15 Cortex-M4
 * instructions more. q is at most the largest vertex q, < 2^(31 + PF)
 * plane units (setup.c), so q >> PF fits 32 bits; below 256 it is too small
 * to matter (1-pixel segments long before: a depth ratio of 2^23). */
static inline int32_t fxl__auto_log2_q8(uint32_t q32)
{
    const int msb = 31 - fxl__clz32_inline(q32);
    return (int32_t)msb * 256 + fxl__log2_frac_q8[(q32 >> (msb - 8)) & 0xFFu];
}

/* t_row of the row dY subpx below the reference vertex. N is evaluated in
 * fixed point (auto.c: |n| < 2^29 units inside the triangle) and padded by
 * its worst rounding, so the result only ever errs towards shorter
 * segments. */
static inline int32_t fxl__auto_row(const fxl__tri_t *tri, int32_t dY)
{
    const uint64_t ady = dY < 0 ? (uint64_t)0 - (uint64_t)(int64_t)dY : (uint64_t)dY;
    const uint64_t pad = 512u + (ady >> 16);
    uint64_t a[2], s;
    int i;
    for (i = 0; i < 2; i++) {
        const int64_t n = fxl__asr64((int64_t)((uint64_t)tri->auto_ns[i] * (uint64_t)(int64_t)dY), 16) +
                          tri->auto_n[i];
        a[i] = (n < 0 ? (uint64_t)0 - (uint64_t)n : (uint64_t)n) + pad;
        if (a[i] >= ((uint64_t)1 << 31))
            return INT32_MIN / 2;   /* outside the triangle's rows: 1-pixel segments */
    }
    s = a[0] * a[0] + a[1] * a[1];   /* in [2^18, 2^63) */
    /* log2 |N| rounded up: (log2 s + 2) / 2, ceiling */
    return tri->auto_t0 - ((fxl__log2_q8_inline(s) + 3) >> 1);
}

/* Longest log2 length <= cap that the bound allows with q_min >= q32
 * (q32 = q >> PF, or a lower bound of it). */
static inline int fxl__auto_fit(int32_t t_row, int64_t q32, int cap)
{
    int32_t k;
    if (q32 < 256)
        return 0;
    k = t_row + 3 * fxl__auto_log2_q8((uint32_t)q32);
    if (k < 0)
        return 0;
    k >>= 9;
    return k > cap ? cap : (int)k;
}

static inline int fxl__ctz32(uint32_t x)   /* x != 0 */
{
#if defined(__GNUC__)
    return __builtin_ctz(x);
#else
    int n = 0;
    while (!(x & 1u)) {
        x >>= 1;
        n++;
    }
    return n;
#endif
}

/* q >> PF of a q plane value inside the triangle (> 0, < 2^(31 + PF));
 * anything else is 0 (1-pixel segments). */
static inline int64_t fxl__auto_q32(int64_t q)
{
    return q > 0 && q < ((int64_t)1 << (31 + FXL__PF)) ? (int64_t)((uint64_t)q >> FXL__PF) : 0;
}

/* Does the block [x, x + 2^k) of the span [xl, xr) fit? q32 is q >> PF at
 * x. Where q falls along x (q_x < 0) its smallest value is at the block's
 * end (x + 2^k, or the last pixel): bounded below by q32 - auto_gx32 * e,
 * auto_gx32 = ceil(|q_x| >> PF) per pixel. That bound of a sub-block is
 * never below its block's, so the partition property holds. */
static inline int fxl__auto_block_fits(const fxl__tri_t *tri, int32_t t_row, int32_t x, int32_t xr, int64_t q32, int k)
{
    const int32_t len = (int32_t)1 << k;
    const uint32_t e = (uint32_t)(xr - x > len ? len : xr - 1 - x);
    const int64_t qe = tri->q.gx < 0 ? q32 - (int64_t)((uint64_t)tri->auto_gx32 * e) : q32;
    return fxl__auto_fit(t_row, qe, k) >= k;
}

/* log2 length of the segment starting at x, a segment boundary of the walk
 * (see above), where q is q. */
static inline int fxl__auto_next(const fxl__tri_t *tri, int32_t t_row, int32_t x, int32_t xl, int32_t xr, int64_t q)
{
    const int64_t q32 = fxl__auto_q32(q);
    int k = tri->auto_cap;
    if (x != xl) {
        const int a = fxl__ctz32((uint32_t)(x - xl));
        k = a < k ? a : k;
    }
    /* the start's q bounds every length; where q falls, the end's decides */
    k = fxl__auto_fit(t_row, q32, k);
    if (tri->q.gx < 0)
        while (k > 0 && !fxl__auto_block_fits(tri, t_row, x, xr, q32, k))
            k--;
    return k;
}

/* Start of the segment that contains pixel cl (cl > xl: the walk begins
 * there instead of at xl). dY as for fxl__plane_eval. */
static inline int32_t fxl__auto_first(const fxl__tri_t *tri, int32_t t_row, int32_t xl, int32_t xr, int32_t cl,
                                      int32_t dY)
{
    /* q at cl bounds the q_min of every block containing cl from above,
     * so no block longer than fit(q(cl)) can fit: start there */
    int k = fxl__auto_fit(
        t_row, fxl__auto_q32(fxl__plane_eval(&tri->q, cl * FXL__ONE + FXL__HALF - tri->X0, dY)), tri->auto_cap);
    int32_t bs = cl;
    for (; k > 0; k--) {
        int64_t q;
        bs = xl + ((cl - xl) >> k << k);
        q = fxl__plane_eval(&tri->q, bs * FXL__ONE + FXL__HALF - tri->X0, dY);
        if (fxl__auto_block_fits(tri, t_row, bs, xr, fxl__auto_q32(q), k))
            break;
    }
    return k ? bs : cl;
}

#endif /* FXL_HAVE_AUTO */
#endif

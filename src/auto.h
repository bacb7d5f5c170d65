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
 *
 * Quadratic segments (tri->auto_quad). Between exact points L pixels apart
 * the true coordinate is the chord plus t (1 - t) du dq / q(t) (t in [0, 1],
 * du, dq the changes over the segment). A parabola through the same ends,
 * chord + t (1 - t) C with C = du dq (1/q0 + 1/q1) / 2, follows that
 * curvature; what is left is at most
 *   t (1 - t) |du| |dq| |1/q(t) - (1/q0 + 1/q1) / 2| <= |du| d^2 / (12 sqrt 3)
 * with d = |dq| / q_min (sup over t and over every d, checked numerically:
 * the ratio is largest as d -> 0), so with |du| <= L |N| / q_min^2
 *   err(L) <= 0.0482 L^3 |N| q_x^2 / q_min^4,
 * i.e. 2^k fits  <=>  k <= (t_row + tq + 4 log2 q_min) / 3. A segment is
 * quadratic where this allows a longer block (at most FXL__QUAD_CAP) than
 * the affine bound; "fits" is then either bound, still inherited by
 * sub-blocks, so the partition property above holds. fxl__auto_next_q
 * returns the length with FXL__AUTO_QUAD set for such a segment.
 */
#ifndef FIXEL_AUTO_H
#define FIXEL_AUTO_H

#include "raster_int.h"
#include "persp.h"
#include "div64.h"

#if FXL_HAVE_AUTO

/* fxl__log2_q8_inline (persp.h) of q >> FXL__PF >= 256, in 32 bits: a
 * 64-bit CLZ and shift cost the per-segment test ~15 Cortex-M4
 * instructions more. q is at most the largest vertex q, < 2^(31 + PF)
 * plane units (setup.c), so q >> PF fits 32 bits; below 256 it is too small
 * to matter (1-pixel segments long before: a depth ratio of 2^23).
 * The formula of fxl__log2_q8_u32 (persp.h), written out: calling that
 * from here made GCC 12 allocate fxl__auto_next_q's registers worse
 * (+2 Cortex-M4 instructions a call, rolled floor AUTO 66.63 -> 66.89). */
static inline int32_t fxl__auto_log2_q8(uint32_t q32)
{
    const int msb = 31 - fxl__clz32_inline(q32);
    return (int32_t)msb * 256 + FXL__LOG2_FRAC_Q8((q32 >> (msb - 8)) & 0xFFu);
}

/* Longest log2 L <= cap with L^2 / 4 * G <= budget, from lg and lb, the
 * log2 table's values (fxl__log2_q8) of G and budget: log2 L <=
 * (log2 budget + 2 - log2 G) / 2. The table is within (-1.94, +0.5) q8
 * steps of the truth; two steps of margin keep L an upper bound for the
 * true G and budget (without them 1,049 of the 1.78 million pairs of
 * test_lod's test_auto_fit_log2_bounds_the_true_values got a doubled L),
 * and the L it gives is within 1% of the longest: (2 L)^2 / 4 * G >
 * 0.99 budget. */
static inline int fxl__auto_fit_log2(int32_t lg, int32_t lb, int cap)
{
    int32_t k = (lb + 2 * 256 - lg - 2) / 2;
    if (k < 0)
        return 0;
    k >>= 8;
    return k > cap ? cap : (int)k;
}

/* The cases of the per-triangle choice that need no bound, inline in the
 * rasterizer: out of line, the 852 of the tunnel's 1,739 AUTO triangles
 * that end here paid the bound's 9-register prologue and stack frame
 * (inline, the tunnel's AUTO costs ~38k Cortex-M4 instructions a frame
 * less). The caller (raster.c) calls it for textured triangles only, with
 * auto_seg and auto_quad 0; fxl__auto_vertices has set auto_w and
 * auto_cap. */
/* The drift of an affine segment of 2^k pixels, q16 texels: its truncated
 * q16 steps err by under one unit a pixel on each axis, so under
 * 1.5 * 2^k units at its far end (both axes together, rounded up). The
 * chooser spends the budget less this on the chord (fxl__auto_bound), or
 * all of it where there is no chord (fxl__auto_setup). */
static inline int32_t fxl__auto_drift_q16(int k)
{
    return (int32_t)(((3u << k) + 1u) / 2);
}

static inline void fxl__auto_setup(fxl__tri_t *tri, const int32_t Y[3])
{
    tri->seg_log2 = 8;
    if ((uint64_t)tri->q.gx * FXL__ONE == 0) {
        /* Constant depth along every span: u, v are affine along a row,
         * and only the truncated q16 steps err. The longest length whose
         * drift fits the budget: 256 from 384 q16 (1/170 texel) up, exact
         * at every pixel below 3. A budget of 1 unit on 256-pixel
         * segments drew 44 units off (fuzz seed 51, case 4333147). */
        const int32_t budget = tri->draw->auto_budget;
        int k = 8;
        while (k > 0 && fxl__auto_drift_q16(k) > budget)
            k--;
        tri->seg_log2 = k;
        return;
    }
    /* Spans of at most 2 pixels have a correction point at every pixel
     * (the last segment ends on the span's last pixel) whatever the
     * length: no bound to compute (a tenth of the tunnel's triangles,
     * ~1,400 Cortex-M4 instructions each). */
    tri->seg_log2 = tri->auto_cap;
    if (tri->auto_cap > 1)
        fxl__auto_bound(tri, Y);
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

/* Per-segment LOD under AUTO: evaluated at the segments that start on a
 * grid of 2^FXL__AUTO_LOD_LOG2 pixels from the span's left end; a segment
 * between grid points takes the LOD of the grid point before it, which is
 * always a segment start (segments are aligned blocks, see above: a block
 * that contains a grid point and is no longer than the grid starts there).
 * The error bound places AUTO's correction points for the coordinates'
 * sake, often closer than the default 16 pixels on steep triangles; the
 * LOD (a log2, wanted within a quarter level) changes far more slowly, and
 * evaluating it at every such point was most of what AUTO's short
 * segments cost with mip levels (Cortex-M4 cube trilinear: lod_at 262k of
 * 1.70M instructions, against 137k under fixed subdiv16). On the grid it
 * is evaluated where subdiv16 evaluates it (or less often, on segments
 * longer than 16). A walk that would start off the grid (at the clip
 * edge, fxl__auto_first) starts at the grid point before it, computing
 * but not drawing the segments left of the clip: the LOD of a pixel does
 * not depend on the clip rectangle or band. */
#define FXL__AUTO_LOD_LOG2 4
#define FXL__AUTO_LOD_ON_GRID(x, xl) ((((x) - (xl)) & (((int32_t)1 << FXL__AUTO_LOD_LOG2) - 1)) == 0)
#define FXL__AUTO_LOD_GRID(x, xl) ((xl) + (((x) - (xl)) >> FXL__AUTO_LOD_LOG2 << FXL__AUTO_LOD_LOG2))

/* Is the per-segment LOD of triangle t (a pointer, drawn with draw d) on
 * the grid: AUTO with mip levels? Then its segments are capped at the grid too (raster.c). A
 * macro: as an inline function GCC -Os kept a copy in each of its two
 * users (46 bytes more of Cortex-M4 code). */
#define FXL__AUTO_LOD_GRIDDED(d, t) ((d)->persp == FXL_PERSP_AUTO && (t)->lod_per_segment && (t)->nlevels > 1)

/* Quadratic segments: at most 2^5 pixels (the fixed-point steps then err
 * by < 0.003 texel, fxl__quad_steps; beyond that, where chords would need
 * 32 pixels or more, a quadratic pixel's two extra adds cost more than
 * the divisions they save), and the flag fxl__auto_next_q adds to their
 * log2 length. */
#define FXL__QUAD_CAP 5
#define FXL__AUTO_QUAD 16
#define FXL__AUTO_LOG2(k) ((k) & (FXL__AUTO_QUAD - 1))

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

/* The quadratic bound's longest log2 length <= cap (t_row is the affine
 * one's; tri->auto_tq converts it). */
static inline int fxl__auto_fit_quad(const fxl__tri_t *tri, int32_t t_row, int64_t q32, int cap)
{
    int32_t k;
    if (q32 < 256)
        return 0;
    k = t_row + tri->auto_tq + 4 * fxl__auto_log2_q8((uint32_t)q32);
    if (k < 0)
        return 0;
    k /= 3 * 256;
    return k > cap ? cap : (int)k;
}

/* Trailing zeros of x != 0. GCC's builtin is one or two instructions
 * where the core counts leading zeros (x86-64, AArch64, ARMv7-M: RBIT and
 * CLZ; RISC-V with Zbb: CTZ); elsewhere (Cortex-M0+, RISC-V without Zbb)
 * it calls libgcc's __ctzsi2, outside what a freestanding core may
 * reference, so there the lowest set bit's leading zeros are counted in C
 * (clz.h). */
static inline int fxl__ctz32(uint32_t x)
{
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__aarch64__) || defined(__ARM_FEATURE_CLZ) ||            \
                          defined(__riscv_zbb))
    return __builtin_ctz(x);
#else
    return 31 - fxl__clz32_soft(x & (0u - x));
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
static inline int64_t fxl__auto_block_qmin(const fxl__tri_t *tri, int32_t x, int32_t xr, int64_t q32, int k)
{
    const int32_t len = (int32_t)1 << k;
    const uint32_t e = (uint32_t)(xr - x > len ? len : xr - 1 - x);
    return tri->q.gx < 0 ? q32 - (int64_t)((uint64_t)tri->auto_gx32 * e) : q32;
}

static inline int fxl__auto_block_fits(const fxl__tri_t *tri, int32_t t_row, int32_t x, int32_t xr, int64_t q32, int k)
{
    return fxl__auto_fit(t_row, fxl__auto_block_qmin(tri, x, xr, q32, k), k) >= k;
}

/* The same for a quadratic segment (k <= FXL__QUAD_CAP). */
static inline int fxl__auto_block_fits_quad(const fxl__tri_t *tri, int32_t t_row, int32_t x, int32_t xr, int64_t q32,
                                            int k)
{
    return fxl__auto_fit_quad(tri, t_row, fxl__auto_block_qmin(tri, x, xr, q32, k), k) >= k;
}

/* log2 length of the segment starting at x, a segment boundary of the walk
 * (see above), where q is q: affine segments only. */
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

/* Does every block of 2^auto_cap from x (such a block's start) to the
 * span's end xr fit, so that AUTO's segments there are exactly a fixed
 * walk's of that length? q is the q plane value at x. One test for the
 * span (the fast walks then take the fixed walk's cheaper segments) in
 * place of a bound per segment. It implies fxl__auto_next's answer at
 * every block start: q32 at x' >= q32(x) - auto_gx32 (x' - x) (a floor
 * of a sum is at least the floors' sum less the ceiling), so each block's
 * q_min bound is at least the one here, and auto_fit grows with q. */
static inline int fxl__auto_span_fits_cap(const fxl__tri_t *tri, int32_t t_row, int32_t x, int32_t xr, int64_t q)
{
    int64_t q32 = fxl__auto_q32(q);
    if (tri->q.gx < 0)
        q32 -= (int64_t)((uint64_t)tri->auto_gx32 * (uint32_t)(xr - 1 - x));
    return fxl__auto_fit(t_row, q32, tri->auto_cap) >= tri->auto_cap;
}

/* The same with quadratic segments (tri->auto_quad): the longest block
 * that either bound allows, FXL__AUTO_QUAD set where only the quadratic
 * one does. */
static inline int fxl__auto_next_q(const fxl__tri_t *tri, int32_t t_row, int32_t x, int32_t xl, int32_t xr, int64_t q)
{
    const int64_t q32 = fxl__auto_q32(q);
    int ka = tri->auto_cap, k, kq;
    if (x != xl) {
        const int a = fxl__ctz32((uint32_t)(x - xl));
        ka = a < ka ? a : ka;
    }
    k = fxl__auto_fit(t_row, q32, ka);
    kq = fxl__auto_fit_quad(tri, t_row, q32, ka < FXL__QUAD_CAP ? ka : FXL__QUAD_CAP);
    if (tri->q.gx < 0) {
        while (k > 0 && !fxl__auto_block_fits(tri, t_row, x, xr, q32, k))
            k--;
        while (kq > k && !fxl__auto_block_fits_quad(tri, t_row, x, xr, q32, kq))
            kq--;
    }
    return kq > k ? kq | FXL__AUTO_QUAD : k;
}

/* The chooser the triangle's segments take (walks where that is not a
 * compile-time constant). */
static inline int fxl__auto_next_tri(const fxl__tri_t *tri, int32_t t_row, int32_t x, int32_t xl, int32_t xr,
                                     int64_t q)
{
    return fxl__auto_quad(tri) ? fxl__auto_next_q(tri, t_row, x, xl, xr, q) : fxl__auto_next(tri, t_row, x, xl, xr, q);
}

/* Start of the segment that contains pixel cl (cl > xl: the walk begins
 * there instead of at xl). dY as for fxl__plane_eval. */
static inline int32_t fxl__auto_first(const fxl__tri_t *tri, int32_t t_row, int32_t xl, int32_t xr, int32_t cl,
                                      int32_t dY)
{
    /* q at cl bounds the q_min of every block containing cl from above,
     * so no block longer than fit(q(cl)) can fit: start there */
    const int64_t qc = fxl__auto_q32(fxl__plane_eval(&tri->q, cl * FXL__ONE + FXL__HALF - tri->X0, dY));
    int k = fxl__auto_fit(t_row, qc, tri->auto_cap);
    int32_t bs = cl;
    if (fxl__auto_quad(tri)) {
        const int kq = fxl__auto_fit_quad(tri, t_row, qc, tri->auto_cap < FXL__QUAD_CAP ? tri->auto_cap : FXL__QUAD_CAP);
        k = kq > k ? kq : k;
    }
    for (; k > 0; k--) {
        int64_t q32;
        bs = xl + ((cl - xl) >> k << k);
        q32 = fxl__auto_q32(fxl__plane_eval(&tri->q, bs * FXL__ONE + FXL__HALF - tri->X0, dY));
        if (fxl__auto_block_fits(tri, t_row, bs, xr, q32, k) ||
            (fxl__auto_quad(tri) && k <= FXL__QUAD_CAP && fxl__auto_block_fits_quad(tri, t_row, bs, xr, q32, k)))
            break;
    }
    return k ? bs : cl;
}

/* q_x / q at a correction point, q28 per pixel, from its reciprocal
 * (1/q = r 2^(n - 94), q_x = qx_m 2^qx_e): floor(qx_m r 2^-sh) with
 * sh = 66 - qx_e - n, saturated to int32 (a change of 8x a pixel; see
 * fxl__quad_steps for why that is safe). */
static inline int32_t fxl__quad_g(const fxl__tri_t *tri, const fxl__recip_t *rc)
{
    const int64_t prod = fxl__mul_s32(tri->qx_m, (int32_t)rc->r);   /* |prod| < 2^62 */
    const int sh = 66 - tri->qx_e - rc->n;
    int64_t g;
    if (sh >= 32) {
        /* the common case, on the high word: |hi| < 2^30 */
        const int32_t hi = (int32_t)fxl__asr64(prod, 32);
        return sh >= 63 ? (hi < 0 ? -1 : 0) : fxl__asr32(hi, sh - 32);
    }
    if (sh <= 0)
        return prod > 0 ? INT32_MAX : (prod < 0 ? -INT32_MAX : 0);
    g = fxl__asr64(prod, sh);
    return g > INT32_MAX ? INT32_MAX : (g < -INT32_MAX ? -INT32_MAX : (int32_t)g);
}

/* floor(d gbar / 2^28), clamped to +-(2^30 - 1): the curvature of a segment
 * per pixel of its length (q16 texels). Inside the bound |c1| stays
 * below 2^25 (|du| d_q^2 <= 5.2 texels at |du| <= 2^15 texels); the clamp
 * only keeps a saturated g's arithmetic in range. */
static inline int32_t fxl__quad_c1(int32_t d, int32_t gbar)
{
    const int64_t p = fxl__mul_s32(d, gbar);
    const int32_t hi = (int32_t)fxl__asr64(p, 32);
    const int32_t m = (1 << 30) - 1;
    /* |p| < 2^58: floor(p / 2^28) from the two words, |c1| <= 2^30 */
    if (hi >= -(1 << 26) && hi < (1 << 26)) {
        const int32_t c = fxl__i32_of_bits(((uint32_t)(uint64_t)p >> 28) | ((uint32_t)hi << 4));
        return c < -m ? -m : c;
    }
    return hi < 0 ? -m : m;
}

/* The steps of a quadratic segment whose exact ends are len pixels apart
 * (len = 2^k with k >= 1, or any len <= 2^FXL__QUAD_CAP with k < 0: the
 * span's last segment): d[0], d[1] are its changes of u and v (q16
 * texels, the short way round), g0, g1 fxl__quad_g at its ends; out
 * receives du, ddu, dv, ddv. The parabola chord + t (1 - t) C,
 * C = d len (g0 + g1) / 2 = c1 len, is stepped as u += du, du += dd with
 *   dd = -2 C / len^2,  du = d / len + C (len - 1) / len^2   (the first step).
 * For len = 2^k, c1 is first rounded down to a multiple of 2^(k-1) (then
 * dd = -(c1 >> (k - 1)) is exact) and du = (d >> k) + c1 - (c1 >> k); all
 * modulo 2^32, as the walk steps. The rounding of c1 moves C by < len^2/2
 * q16 units (the parabola by < len^2/8), the two floors the far end by
 * < 2 len: < 0.003 texel at len = 32, within the 1/64 texel auto.c
 * reserves. The last segment divides, truncating: dd = -2 c1 / len,
 * du = (d - dd len (len - 1) / 2) / len (< len + len^2/8 units).
 * A saturated g only shrinks |C|, its sign kept: the error then stays
 * below |d| d_q / (4 q_min), which the bound exceeds wherever g saturates. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define FXL__QUAD_INLINE inline __attribute__((always_inline))   /* a call was ~25 M4 instructions a segment */
#else
#define FXL__QUAD_INLINE inline
#endif
/* floor((g0 + g1) / 2) in 32 bits: the mean q_x / q of a segment */
static inline int32_t fxl__quad_gbar(int32_t g0, int32_t g1)
{
    return fxl__asr32(g0, 1) + fxl__asr32(g1, 1) + (int32_t)((uint32_t)g0 & (uint32_t)g1 & 1u);
}

/* One coordinate's steps: returns du, *ddu its change a pixel. Scalars
 * rather than arrays so the walk keeps them in registers (with arrays
 * GCC stored and reloaded them, ~10 Cortex-M4 instructions a segment). */
static FXL__QUAD_INLINE uint32_t fxl__quad_axis(int32_t d, int32_t gbar, int32_t len, int k, uint32_t *ddu)
{
    const int32_t c1 = fxl__quad_c1(d, gbar);
    if (k >= 1) {
        const int32_t h = fxl__asr32(c1, k - 1);
        *ddu = 0u - (uint32_t)h;
        return (uint32_t)fxl__asr32(d, k) + ((uint32_t)h << (k - 1)) - (uint32_t)fxl__asr32(h, 1);
    }
    if (len <= 1) {   /* no pixel between the ends */
        *ddu = 0u;
        return len ? (uint32_t)d : 0u;
    }
    {
        /* |2 c1| < 2^31, len <= 64: |ddv| < 2^30, |num| < 2^31 + 2^41;
         * a 32-bit division where num fits (the rule). "Fits" is tested
         * on the high word (one compare; the 64-bit range test was ~6 M4
         * instructions more an axis, on 62% of the tunnel's AUTO
         * segments); INT32_MIN / len is exact in 32 bits for len >= 2. */
        const int32_t ddv = -(2 * c1 / len);
        const int64_t num = (int64_t)d - fxl__mul_s32(ddv, len * (len - 1) / 2);
        const int32_t lo = fxl__i32_of_bits((uint32_t)(uint64_t)num);
        *ddu = (uint32_t)ddv;
        return (int32_t)fxl__asr64(num, 32) == fxl__asr32(lo, 31) ? (uint32_t)(lo / len)
                                                                  : (uint32_t)(uint64_t)fxl__sdiv64_small(num, len);
    }
}

/* Both coordinates: d[0], d[1] the changes of u and v; out receives du,
 * ddu, dv, ddv. */
static FXL__QUAD_INLINE void fxl__quad_steps(const int32_t d[2], int32_t g0, int32_t g1, int32_t len, int k,
                                             uint32_t out[4])
{
    const int32_t gbar = fxl__quad_gbar(g0, g1);
    out[0] = fxl__quad_axis(d[0], gbar, len, k, &out[1]);
    out[2] = fxl__quad_axis(d[1], gbar, len, k, &out[3]);
}

#endif /* FXL_HAVE_AUTO */
#endif

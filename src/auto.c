/* auto.c - FXL_PERSP_AUTO: per triangle, the terms of the affine error
 * bound that the span walks evaluate per segment (auto.h).
 *
 * Along a span (constant Y) u = S / q with S, q linear in x, so
 *   u'  = (S_x q - S q_x) / q^2 = N / q^2,   u'' = -2 u' q_x / q,
 * and linear interpolation between exact points L pixels apart errs by at
 * most L^2 / 8 * max|u''| = L^2 * |u'| * |q_x| / (4 q)  (the formula;
 * the worst point of the segment is where q is smallest, one of its ends).
 * N = S_x q - S q_x does not change along x (its x-derivative is
 * S_x q_x - S_x q_x = 0) and is linear in Y:
 *   N(Y) = (S_x q_0 - S_0 q_x) + (S_x q_y - S_y q_x) (Y - Y0),
 * so with the texel-space vector (N_u, N_v), per row and segment
 *   err(L) <= L^2 / 4 * |q_x| * |(N_u, N_v)(row)| / q_min^3   (texels),
 * the u and v errors combined as the Euclidean length the metric uses.
 * If the cheapest bound over the whole triangle (largest |N| at a vertex,
 * smallest vertex q) already allows the widest span, the triangle is drawn
 * with that one length; otherwise each segment gets its own (auto.h).
 * The bound is rigorous up to the exact-point error (< 0.003 texel measured)
 * and the q16 step truncation (L * 2^-16 texel).
 */
#include "raster_int.h"

#if FXL_HAVE_AUTO
#include "sfloat.h"
#include "auto.h"
#include "recip_run.h"

/* Helpers that GCC -Os copies into each of their call sites in
 * fxl__auto_bound: out of line in size builds (a few calls a triangle's
 * set-up) they are 76 bytes less Cortex-M4 code. Speed builds keep them
 * inline. */
#if defined(__GNUC__) && defined(__OPTIMIZE_SIZE__)
#define AUTO_SIZE_NOINLINE __attribute__((noinline))
#else
#define AUTO_SIZE_NOINLINE
#endif

/* Longest log2 L <= cap with 0.0482 L^3 2^lg <= budget (quadratic
 * segments, auto.h): 3 log2 L <= log2 budget + log2(12 sqrt 3) - lg, that
 * constant (4.377) rounded down to 1120/256, less margins for the log2
 * table (budget -1, |q_x|^2 +4, q_min^4 -4, |N| -1 steps). The budget
 * has already given up 1/16 of itself and 1/64 texel for the exact ends
 * and the fixed-point steps (fxl__quad_steps). */
static AUTO_SIZE_NOINLINE int fit_log2_quad(int32_t lg, int32_t lbq, int cap)
{
    int32_t k = lbq + 1120 - lg - 10;
    if (k < 0)
        return 0;
    k /= 3 * 256;
    return k > cap ? cap : (int)k;
}

/* Is a quadratic length 2^kq worth it over the affine 2^k? A quadratic
 * pixel costs ~4 Cortex-M4 instructions more (the steps of the steps), and
 * its segment ~60 more (fxl__quad_steps, q_x/q) than a division's ~150;
 * exact pixels (k = 0) run at ~80 each. Per pixel, ~(150 + 60) / 2^kq + 4
 * against 150 / 2^k (80 at k = 0): two doublings pay from k = 0 to 4, one
 * from k = 1 to 3, none beyond. */
static AUTO_SIZE_NOINLINE int quad_pays(int k, int kq)
{
    if (kq <= k)
        return 0;
    if (k == 0)
        return kq >= 2;
    if (k <= 3)
        return 1;
    return k == 4 && kq >= 6;
}

/* fxl__log2_q8 of x > 0, inline where speed counts: six calls a triangle
 * were ~1 Cortex-M4 instruction a pixel of the tunnel; -Os builds share
 * the one out-of-line copy. Values known to fit 32 bits take
 * fxl__log2_q8_32 (a 64-bit CLZ and shift are ~15 M4 instructions more). */
#if defined(__OPTIMIZE_SIZE__)
#define log2_q8(x) fxl__log2_q8(x)
#else
#define log2_q8(x) fxl__log2_q8_inline(x)
#endif

/* N = S_x q - S q_x of one coordinate where the planes q and S take the
 * values q (soft-float, shared by u and v) and sv (plane units,
 * texel-scaled by 2^es), or, with their y gradients, its change per unit
 * of Y: the terms of the bound (auto.h). */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
__attribute__((always_inline))   /* a call was ~80 M4 instructions a bound */
#endif
static inline fxl__sf_t n_of(fxl__sf_t sx, fxl__sf_t qx, fxl__sf_t q, int64_t sv, int es)
{
    return fxl__sf_dot2(sx, q, fxl__sf_make(sv, es), qx, -1);
}

/* log2 (a^2 + b^2) in q8 (INT32_MIN / 4 for zero): the smaller-exponent
 * mantissa floored to the other's exponent (2^-30 of the larger value at
 * most), the squares summed exactly in 64 bits (each <= 2^62), one
 * logarithm; as fxl__sf_log2_q8 of the soft-float sum of squares, within
 * the logarithm's (-1.94, +0.5) q8 steps, in ~30 fewer Cortex-M4
 * instructions a row (AUTO set-up, |N|^2). */
static int32_t log2_norm2_q8(fxl__sf_t a, fxl__sf_t b)
{
    const uint32_t ma = a.m < 0 ? 0u - (uint32_t)a.m : (uint32_t)a.m, mb = b.m < 0 ? 0u - (uint32_t)b.m : (uint32_t)b.m;
    /* a zero takes the other's exponent: it has none of its own */
    const int ea = ma ? a.e : b.e, eb = mb ? b.e : ea, e = ea > eb ? ea : eb;
    const uint32_t sa = e - ea > 31 ? 0u : ma >> (e - ea), sb = e - eb > 31 ? 0u : mb >> (e - eb);
    const uint64_t s2 = (uint64_t)sa * sa + (uint64_t)sb * sb;
    return s2 ? log2_q8(s2) + 2 * e * 256 : INT32_MIN / 4;
}

/* Quadratic segments for tri: one length (auto_seg 2, seg_log2) or per
 * segment (auto_seg 1); q_x as fxl__quad_g takes it. */
static void use_quad(fxl__tri_t *tri, fxl__sf_t qx, uint8_t auto_seg)
{
    tri->qx_m = qx.m;
    tri->qx_e = qx.e;
    tri->auto_quad = 1;
    tri->auto_seg = auto_seg;
}

/* floor(x / 256) for either sign (>> of a negative int is
 * implementation-defined). */
static int32_t floor_div256(int32_t x)
{
    return x >= 0 ? x / 256 : -((-x + 255) / 256);
}

/* round(a * 2^-E) as int64; INT64_MAX (or MIN) when it would not fit
 * 2^62, which auto_setup treats as "no per-segment bound". Out of line:
 * GCC -Os copied it into both its calls (230 bytes of M4 code), and at -O2
 * the per-segment set-up spilled more around it (M4 tunnel trilinear AUTO
 * 5,868 instructions a frame more inline). */
#if defined(__GNUC__)
__attribute__((noinline))
#endif
static int64_t sf_fixed(fxl__sf_t a, int E)
{
    const int sh = a.e - E;
    if (a.m == 0)
        return 0;
    if (sh >= 0)
        return sh > 30 ? (a.m > 0 ? INT64_MAX : INT64_MIN) : a.m * ((int64_t)1 << sh);
    if (sh < -62)
        return 0;
    return fxl__asr64(a.m + ((int64_t)1 << (-sh - 1)), -sh);
}

/* hi - lo of three int32 values, exact as uint32 */
static uint32_t range3(int32_t a, int32_t b, int32_t c)
{
    const int32_t lo = a < b ? (a < c ? a : c) : (b < c ? b : c);
    const int32_t hi = a > b ? (a > c ? a : c) : (b > c ? b : c);
    return (uint32_t)hi - (uint32_t)lo;
}

/* The budget (> 0, check_draw) capped at 256 texels (raster.h), q16. */
static inline int32_t budget_capped(const fxl_draw_t *d)
{
    return d->auto_budget > ((int32_t)1 << 24) ? (int32_t)1 << 24 : d->auto_budget;
}

/* The capped budget less 1/16 of itself and `texels` (q16) for the walk's
 * rounding; <= 0 when nothing is left. */
static int32_t budget_less_margins(const fxl_draw_t *d, int32_t texels)
{
    const int32_t b = budget_capped(d);
    return b - (b >> 4) - texels;
}

/* q8 log2 in texels of a budget of b q16; for b <= 0 a value that lets no
 * segment through. */
static AUTO_SIZE_NOINLINE int32_t log2_budget_q8(int32_t b)
{
    return b > 0 ? fxl__log2_q8_32((uint32_t)b) - 16 * 256 : INT32_MIN / 4;
}

/* The vertex test: perspective interpolation at a point with screen-space
 * barycentrics l_i gives u = sum m_i u_i with m_i = l_i q_i / q, q = sum
 * l_i q_i, and the affine map gives sum l_i u_i. Their difference is
 *   sum (m_i - l_i) (u_i - c)   for any c (both weight sets sum to 1),
 * at most (range u / 2) * sum l_i |q_i - q| / q, and the mean absolute
 * deviation of values within [q_min, q_max] is at most (q_max - q_min) / 2.
 * So the whole triangle drawn affine errs by at most
 *   (range u + range v) (q_max - q_min) / (4 q_min)   texels,
 * the Euclidean error included. The same figure bounds the chord between
 * any two exact points (t (1 - t) (u1 - u0) (q1 - q0) / q(t)). Where it is
 * within the budget, less 1/16 of it and 1/128 texel for the affine walk's
 * rounding (its re-anchoring points and q16 steps), the triangle needs no
 * division at all. q is 1/w up to a common factor, so the vertices' inv_w
 * serve exactly; the ranges are of the q16 vertex values, which rebasing
 * by whole periods does not change. */
void fxl__auto_vertices(fxl__tri_t *tri, const fxl_vertex_t v[3], uint32_t xrange)
{
    const fxl_texture_t *t = tri->tex;
    /* 32 x 32 multiplies, not 64-bit shifts (one UMULL, one UMLAL on a
     * Cortex-M) */
    const uint64_t r = (uint64_t)range3(v[0].u, v[1].u, v[2].u) * ((uint32_t)1 << t->log2_w) +
                       (uint64_t)range3(v[0].v, v[1].v, v[2].v) * ((uint32_t)1 << t->log2_h);
    const int32_t b = budget_less_margins(tri->draw, FXL_Q16_ONE / 128);
    const uint32_t w0 = v[0].inv_w, w1 = v[1].inv_w, w2 = v[2].inv_w;
    const uint32_t qmin = w0 < w1 ? (w0 < w2 ? w0 : w2) : (w1 < w2 ? w1 : w2);
    const uint32_t qmax = w0 > w1 ? (w0 > w2 ? w0 : w2) : (w1 > w2 ? w1 : w2);
    tri->auto_duv = r;
    /* Gouraud colours stay perspective-correct: the budget is in texels.
     * r < 2^31 and qmax - qmin < 2^32: the product < 2^63; the right side
     * < 2^2 * 2^32 * 2^24 */
    if (!tri->has_color && b > 0 && r <= INT32_MAX && r * (qmax - qmin) <= 4u * ((uint64_t)qmin * (uint32_t)b)) {
        tri->affine = 1;
        return;
    }
    {
        /* No span is longer than the bounding box: a longer L changes
         * nothing. cap: the least <= 8 with 2^cap >= w. */
        const int32_t w = (int32_t)(xrange >> FXL__S) + 1;   /* < 2^17 */
        int cap = 0;
        if (w > 1)
            cap = 32 - fxl__clz32_inline((uint32_t)w - 1u);
        tri->auto_w = w;
        tri->auto_cap = (int8_t)(cap < FXL__AUTO_CAP_MAX ? cap : FXL__AUTO_CAP_MAX);
    }
}

/* Reciprocal runs (recip_run.h) serve the triangle: any levels (one, the
 * nearest of several, or two blended), repeat or mirror axes, no colours,
 * not uv_wide (raster.c's clamp and needle cases, which divide at every
 * pixel, never get here), and their error, under (|u| + |v|) 2^-18 + 260
 * units (q16 texels), within the budget less its margins. |u| + |v| of
 * the rebased vertices is within the ranges plus a period a repeat axis
 * (two a mirror one); below 2^29 - 2^16 it keeps a and b within int32. */
#if FXL_HAVE_RR
static int rr_fits(const fxl__tri_t *tri)
{
    uint32_t uv;
    /* A side of 2^12 texels or more alone passes the limit below (its
     * period is 2^28 q16 units, twice that for mirror): refused first, so
     * the sum fits 32 bits (with FXL_TEX_MAX_LOG2 14, two periods of 2^14
     * wrapped it to 0 and such triangles took runs whose a, b overflowed). */
    if (fxl__signed_u(tri) || fxl__signed_v(tri) || tri->uv_wide || tri->has_color ||
        tri->auto_duv >= ((uint64_t)1 << 29) || tri->tex->log2_w >= 12 || tri->tex->log2_h >= 12)
        return 0;
    /* in 32 bits: the ranges below 2^29, the periods at most 2^29 */
    uv = (uint32_t)tri->auto_duv + ((((uint32_t)1 << tri->tex->log2_w) + ((uint32_t)1 << tri->tex->log2_h)) << 17);
    return uv <= ((uint32_t)1 << 29) - ((uint32_t)1 << 16) &&
           (int32_t)(uv >> 18) + 260 <= budget_less_margins(tri->draw, FXL_Q16_ONE / 64);
}
#else
#define rr_fits(tri) 0
#endif

void fxl__auto_bound(fxl__tri_t *tri, const int32_t Y[3])
{
    /* Plane value units cancel in N / q^3 (both carry 2^PF per factor);
     * u in texels = (S / q) * 2^(shift_u + log2_w - 16). */
    const int es[2] = {tri->a_shift[FXL__AU] + (int)tri->tex->log2_w - 16,
                       tri->a_shift[FXL__AV] + (int)tri->tex->log2_h - 16};
    const int64_t qx_g = (int64_t)((uint64_t)tri->q.gx * FXL__ONE);
    fxl__sf_t qx, q0, qy, sx[2], n[2][2];
    int32_t ys[2];   /* least and greatest vertex Y */
    int32_t lb, lqx, lnmax = INT32_MIN / 4, lmax = INT32_MIN / 4;
    int i, j, k, E, quad;
    int32_t lbq, lba;
    /* q_min > 0 (setup.c: every vertex q >= 2^PF) */
    const int32_t lqmin = log2_q8((uint64_t)tri->q_min);
    const int32_t w = tri->auto_w;
    const int cap = tri->auto_cap;
    qx = fxl__sf_make(qx_g, 0);
    /* The budget's q8 log2 less the margins of the vertex test (affine)
     * and of quadratic segments (the plain budget's, lb, once the vertex
     * test has not settled the triangle). */
    {
        const int32_t ba = budget_less_margins(tri->draw, FXL_Q16_ONE / 128);
        const int32_t bq = budget_less_margins(tri->draw, FXL_Q16_ONE / 64);
        /* Affine segments: the budget (above 256 texels it acts as 256,
         * raster.h) less the drift of their truncated q16 steps, under one
         * unit a pixel on each axis: under 1.5 2^cap units for the longest
         * (6 2^-16 texel at 4 pixels, 0.006 at 256: nothing against the
         * default 1/4, what keeps a budget of 1/256 on a 256-pixel span). */
        const int32_t bc = budget_capped(tri->draw) - fxl__auto_drift_q16(cap);
        lba = log2_budget_q8(ba);
        lb = log2_budget_q8(bc);
        /* quadratic steps take a segment's change as int32: not where it
         * may exceed 2^15 texels (uv_wide) */
        quad = FXL_HAVE_QUAD && !fxl__signed_u(tri) && !fxl__signed_v(tri) && tri->nlevels <= 1 && bq > 0 &&
               !tri->uv_wide;
        /* only quadratic segments use it (a logarithm less for the
         * others) */
        lbq = quad ? log2_budget_q8(bq) : 0;
    }
    {
        /* Whole spans from the vertex ranges, before the N bound: within a
         * span of at most w pixels u and v change by at most
         * R = range u + range v, and q by w |q_x|; a chord then errs by
         * at most R w |q_x| / (4 q_min), a quadratic segment (auto.h) by
         * 0.0482 R (w |q_x| / q_min)^2. Where the first fits, spans are
         * drawn whole and affine; where only the second does, small
         * triangles (spans <= 16 pixels, whose cost is this set-up's) take
         * whole quadratic spans. w itself rather than 2^cap makes the test
         * up to 2x (4x) tighter. Log2 margins: +2 for each upper and +1 for
         * each lower estimate. */
        const uint64_t R = tri->auto_duv;
        const uint64_t g = qx_g < 0 ? (uint64_t)0 - (uint64_t)qx_g : (uint64_t)qx_g;
        if (R == 0)
            return;   /* u, v constant: no error at any length */
        if (R <= INT32_MAX) {
            const int32_t lr = fxl__log2_q8_32((uint32_t)R) - 16 * 256;
            const int32_t lrho = log2_q8(g) + 2 - (lqmin - 1);
            const int32_t lw = fxl__log2_q8_32((uint32_t)w) + 2;
            if (lr + 2 + lw + lrho - 512 <= lba - 1)
                return;
            if (quad && cap <= 4 && cap <= FXL__QUAD_CAP && lr + 2 + 2 * (lw + lrho) <= lbq - 1 + 1120) {
                use_quad(tri, qx, 2);
                return;
            }
        }
    }
    for (j = 0; j < 2; j++)
        sx[j] = fxl__sf_make((int64_t)((uint64_t)tri->a[j].gx * FXL__ONE), es[j]);
    /* N is linear in Y alone, so over the triangle |N_u|, |N_v| and |N|
     * are largest on its top or bottom row: the vertices of least and
     * greatest Y (a third evaluation was ~0.8 Cortex-M4 instructions a
     * pixel of the tunnel). Found here rather than passed from the
     * rasterizer's sorted order: two more arguments cost its caller
     * registers (M4 tunnel +0.2 instructions a pixel, -Os +42 bytes). */
    ys[0] = ys[1] = Y[0];
    for (i = 1; i < 3; i++) {
        ys[0] = Y[i] < ys[0] ? Y[i] : ys[0];
        ys[1] = Y[i] > ys[1] ? Y[i] : ys[1];
    }
    for (i = 0; i < 2; i++) {
        /* N on that row, S_x q - S q_x with the planes' values where the
         * row meets X0 (exact in int64; N does not change along x): two
         * products a coordinate, where A + B (Y - Y0) took three and two
         * sums (M4 tunnel AUTO: 79 instructions a bound less) */
        const uint64_t dy = (uint64_t)((int64_t)ys[i] - tri->Y0);
        const fxl__sf_t qr = fxl__sf_make((int64_t)((uint64_t)tri->q.c + (uint64_t)tri->q.gy * dy), 0);
        int32_t l;
        for (j = 0; j < 2; j++) {
            const fxl__plane_t *p = &tri->a[j];
            n[i][j] = n_of(sx[j], qx, qr, (int64_t)((uint64_t)p->c + (uint64_t)p->gy * dy), es[j]);
        }
        /* |(nu, nv)|^2, compared as squares */
        l = log2_norm2_q8(n[i][0], n[i][1]);
        lnmax = l > lnmax ? l : lnmax;
    }
    if (lnmax == INT32_MIN / 4)
        return;
    /* Cheap bound first: max |N| with min q, each over the vertices. */
    lqx = fxl__sf_log2_q8(qx);
    k = fxl__auto_fit_log2(lqx + lnmax / 2 - 3 * lqmin, lb, cap);
    tri->seg_log2 = k;
    if (k >= cap)
        return;
    {
        /* Per segment pays ~40-70 Cortex-M4 instructions a segment for
         * the bound; it only wins where q varies enough that the longest
         * allowed length (at the largest vertex q) is 4x the one the whole
         * triangle allows. On several levels that length is not capped:
         * there the cap is the LOD grid's (raster.c), and spans that fit
         * the cap all along cost the batch walk one test and a fixed
         * walk's segments (fxl__auto_span_fits_cap). The near quad's
         * trilinear: ~1.19x fixed subdiv16's instructions with 8-pixel
         * segments for the whole triangle, ~1.01x per segment. */
        const int32_t lqmax = log2_q8((uint64_t)tri->q_max);
        int best_tri = k, best_seg = fxl__auto_fit_log2(lqx + lnmax / 2 - 3 * lqmax, lb, tri->nlevels > 1 ? 8 : cap);
        /* Quadratic segments (auto.h) on repeat and mirror axes (modular
         * coordinates: a parabola may overshoot its ends a little, which
         * a clamped int32 coordinate must not) of a texture with one level
         * (the walks that step several levels are affine only). */
        if (quad) {
            const int qcap = cap < FXL__QUAD_CAP ? cap : FXL__QUAD_CAP;
            const int kq = fit_log2_quad(2 * lqx + lnmax / 2 - 4 * lqmin, lbq, qcap);
            const int kq_max = fit_log2_quad(2 * lqx + lnmax / 2 - 4 * lqmax, lbq, qcap);
            const int seg_max = kq_max > best_seg ? kq_max : best_seg;
            if (quad_pays(k, kq) && seg_max < kq + 2) {
                /* one quadratic length for the whole triangle */
                tri->seg_log2 = kq;
                use_quad(tri, qx, 2);
                return;
            }
            /* per segment: quadratic where it pays at the nearest
             * point too (else the near part, affine and long, pays its
             * bound and loop) */
            quad = quad_pays(best_seg, kq_max);
            if (quad) {
                best_seg = seg_max;
                best_tri = kq > best_tri ? kq : best_tri;
            }
        }
        /* Reciprocal runs (recip_run.h) in place of short segments, where
         * they fit: a run pixel costs ~20 Cortex-M4 instructions beyond
         * its texels; a segment its division, and on several levels an
         * LOD and two levels' set-up too. */
        if (best_seg < best_tri + 2) {
            /* One length for the whole triangle, at most 4 pixels (k <= 2),
             * on several levels: tunnel AUTO trilinear, instructions a
             * frame, M4 24.92 -> 21.99 M, RV32IMAC 30.60 -> 27.81 M, M0+
             * -2.7%, x86-64 -4.9%; nearest level, point M4 -12%. On one
             * level the lean walks' short segments cost about what runs
             * do (x86-64 tunnel point +0.08% with runs of k = 0). */
            if (tri->nlevels > 1 && k <= 2 && rr_fits(tri))
                tri->auto_rr = 1;
            return;
        }
        /* Per segment: every segment at most 2^FXL__RR_SEG_LOG2 pixels
         * even at the largest q, and a pixel each at the smallest (k = 0).
         * The tunnel's steep mip triangles (shortest segment 4 pixels) do
         * not pay for a run's start a span on x86-64 or the M0+ (the M4
         * would draw them 2-4% cheaper as runs, the M0+ 1-2% dearer). */
        if (k == 0 && best_seg <= FXL__RR_SEG_LOG2 && rr_fits(tri)) {
            tri->auto_rr = 1;
            return;
        }
    }
    /* Per segment. N is linear in Y, so inside the triangle |N_u|, |N_v| <=
     * their value at the top or bottom vertex < 2^(lmax + 2 steps): units
     * of 2^E put them below 2^29. The slope keeps 16 more bits
     * (|dN/dY| * height <= 2 max). */
    for (i = 0; i < 2; i++)
        for (j = 0; j < 2; j++) {
            const int32_t l = fxl__sf_log2_q8(n[i][j]);
            lmax = l > lmax ? l : lmax;
        }
    E = floor_div256(lmax + 2 + 255) - 29;
    q0 = fxl__sf_make(tri->q.c, 0);
    qy = fxl__sf_make(tri->q.gy, 0);
    for (j = 0; j < 2; j++) {
        /* N(Y) = A + B (Y - Y0), texel-scaled */
        const fxl__plane_t *p = &tri->a[j];
        const fxl__sf_t A = n_of(sx[j], qx, q0, p->c, es[j]);
        const fxl__sf_t B = n_of(sx[j], qx, qy, p->gy, es[j]);
        tri->auto_n[j] = sf_fixed(A, E);
        tri->auto_ns[j] = sf_fixed(B, E - 16);
        if (tri->auto_n[j] > ((int64_t)1 << 40) || tri->auto_n[j] < -((int64_t)1 << 40) ||
            tri->auto_ns[j] > ((int64_t)1 << 47) || tri->auto_ns[j] < -((int64_t)1 << 47))
            return;   /* not representable (cannot happen for a drawable triangle): the cheap length */
    }
    /* Margins (q8 steps), all towards shorter segments: log2 budget is
     * within (-1.94, +0.5), so -1 makes it a lower bound; log2 |q_x| +2 an
     * upper one; 3 log2 q_min -3 a lower one (auto.h); the row's |N| is
     * rounded up in fxl__auto_row. */
    tri->auto_t0 = lb - 1 + 2 * 256 - (lqx + 2) - 256 * E - 3 + 3 * 256 * FXL__PF;
    {
        /* auto.h works on q >> PF: log2 q = log2 (q >> PF) + PF (floor: a
         * lower bound), and q_x per pixel rounded up */
        const uint64_t g = qx_g < 0 ? (uint64_t)0 - (uint64_t)qx_g : (uint64_t)qx_g;
        const uint64_t g32 = (g + ((uint64_t)1 << FXL__PF) - 1) >> FXL__PF;
        tri->auto_gx32 = g32 > ((uint64_t)1 << 31) ? (uint32_t)1 << 31 : (uint32_t)g32;
    }
    if (quad) {
        /* 3k <= lbq + log2(12 sqrt 3) - 2 log2 |q_x| - log2 |N| + 4 log2 q_min
         * in q8 (fit_log2_quad), with the margins of the affine terms
         * (4 log2 q_min: -4). */
        const int32_t t0q = lbq - 1 + 1120 - 2 * (lqx + 2) - 256 * E - 4 + 4 * 256 * FXL__PF;
        tri->auto_tq = t0q - tri->auto_t0;
    }
    tri->seg_log2 = cap;
    if (quad)
        use_quad(tri, qx, 1);
    else
        tri->auto_seg = 1;
}
#endif /* FXL_HAVE_AUTO */

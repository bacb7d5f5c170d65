/* src/clip.c - Sutherland-Hodgman clipping of a triangle in homogeneous clip
 * space (int64 q32), before the perspective divide.
 *
 * Planes, in this order, as signed distances d (inside: d >= 0):
 *   near  w - near          far  far - w (only when far != 0)
 *   +x    G w - x           -x   G w + x
 *   +y    G w - y           -y   G w + y
 * Ranges: |x|, |y|, |w| < 2^52 (FXL_CLIP_LIMIT_Q32) and G <= 256 (q16
 * <= 2^24), so G w < 2^60, |d| < 2^61 and d_in - d_out < 2^62: no overflow.
 * Interpolation is linear in clip space, which is the perspective-correct
 * choice for every attribute. A cut is interpolated from the end of the
 * edge nearer the plane, with t = |d_a| / (d_in - d_out) <= 1/2 (d_a that
 * end's distance) from the two distances each reduced to 32 significant bits: q31
 * where t >= 2^-8 (absolute error ~2^-31, relative below 2^-23), below
 * that a 32-bit mantissa with its own exponent (relative error below
 * 2^-30 however small t is); the new vertex is then put exactly on the
 * plane (w = near, x = G w, ...) so later stages can rely on it.
 */
#include "pipeline_int.h"
#include "div64.h"

enum { PL_NEAR, PL_FAR, PL_XP, PL_XN, PL_YP, PL_YN, PL_COUNT };

static int64_t guard_w(const fxl_xform_t *xf, int64_t w)
{
    return FXL__HOT_MUL_SHR(w, (uint32_t)xf->guard_q16, 16, NULL);
}

/* The clip planes are told apart by comparisons, not a switch: on Thumb-1
 * (Cortex-M0+) GCC compiles a switch of this size at -Os into a table and
 * a call of libgcc's __gnu_thumb1_case_uqi, outside what a freestanding
 * core may reference (scripts/check_freestanding.sh, strict). */
static int plane_is_x(int plane)
{
    return plane == PL_XP || plane == PL_XN;
}

static int plane_is_positive(int plane)   /* |x| <= G w or |y| <= G w from above */
{
    return plane == PL_XP || plane == PL_YP;
}

static int64_t plane_dist(const fxl_xform_t *xf, int plane, const fxl_clipvert_t *v)
{
    int64_t c;
    if (plane == PL_NEAR)
        return v->w - xf->near_q32;
    if (plane == PL_FAR)
        return xf->far_q32 - v->w;
    c = plane_is_x(plane) ? v->x : v->y;
    return plane_is_positive(plane) ? guard_w(xf, v->w) - c : guard_w(xf, v->w) + c;
}

/* t = m 2^-sh, sh in [31, 93] */
typedef struct lerp_t {
    uint32_t m;
    unsigned sh;
} lerp_t;

static int64_t lerp64(int64_t a, int64_t b, const lerp_t *t)
{
    /* the usual t >= 2^-8 as q31: a constant shift folds in speed builds */
    return a + (t->sh == 31u ? FXL__HOT_MUL_SHR(b - a, t->m, 31, NULL) : FXL__HOT_MUL_SHR(b - a, t->m, t->sh, NULL));
}

static int32_t lerp32(int32_t a, int32_t b, const lerp_t *t)
{
    /* the result lies between a and b, so it fits */
    return (int32_t)lerp64(a, b, t);
}

/* x (> 0) shifted to 32 significant bits, [2^31, 2^32); *top its top bit */
static uint64_t to_32_bits(uint64_t x, int *top)
{
    const int k = 63 - fxl_clz64(x);
    *top = k;
    return k > 31 ? x >> (k - 31) : x << (31 - k);
}

/* The near plane's cut of one coordinate, exactly: a_in + (a_out - a_in)
 * d_in / (d_in - d_out) rounded to nearest (ties up), as the mean of a_in
 * and a_out weighted by |d_out| and d_in. Offsets from the lower one are
 * below 2^53 (|a| < 2^52), weights below 2^62: the numerator is below
 * 2^116 and the quotient, which lies between the two offsets, below 2^53,
 * so 54 steps of long division give it with a 64-bit remainder. */
static int64_t near_cut(int64_t a_in, int64_t a_out, uint64_t d_in, uint64_t d_out_mag)
{
    const int64_t base = a_in < a_out ? a_in : a_out;
    const uint64_t den = d_in + d_out_mag, oo = (uint64_t)(a_out - base), oi = (uint64_t)(a_in - base);
    /* the two 128-bit products, high halves by div64.h's fxl__mulhi64 */
    const uint64_t l1 = oo * d_in;
    uint64_t lo = l1 + oi * d_out_mag, rem, q = 0;
    uint64_t hi = fxl__mulhi64(oo, d_in) + fxl__mulhi64(oi, d_out_mag) + (lo < l1 ? 1u : 0u);
    int i;
    rem = (hi << 10) | (lo >> 54);   /* < den: the quotient is below 2^54 */
    lo <<= 10;                       /* the 54 bits to bring down, from bit 63 */
    for (i = 0; i < 54; i++) {
        rem = (rem << 1) | (lo >> 63);   /* < 2 den < 2^63 */
        lo <<= 1;
        q <<= 1;
        if (rem >= den) {
            rem -= den;
            q |= 1u;
        }
    }
    if (rem >= den - rem)
        q++;
    return base + (int64_t)q;
}

/* Whether the near plane's cut of the edge in-out takes near_cut: its x, y
 * are divided by near when projected, and t's error (~2^-32 at t ~ 1/2)
 * times an edge 2^12 times longer than near is already 2^-20 of the
 * screen (small near planes, long edges through the eye's plane: up to
 * ~280 px off). */
static int near_exact(const fxl_xform_t *xf, const fxl_clipvert_t *in, const fxl_clipvert_t *out)
{
    const uint64_t lim = (uint64_t)xf->near_q32 << 12;
    return fxl__mag64(out->x - in->x) >= lim || fxl__mag64(out->y - in->y) >= lim;
}

/* The point where the edge from `in` (d_in >= 0) to `out` (d_out < 0)
 * crosses the plane. It is interpolated from the end nearer the plane (the
 * smaller |d|; `in` on a tie), so t <= 1/2 and its rounding scales the
 * shorter part of the edge. From `in` always, an edge from a far vertex
 * to one just across a guard plane had t = 1 - 10^-9, whose q31 rounding
 * is 2^-32 of the whole edge: the cut point's w a few percent off, its
 * corner tens to hundreds of pixels along the guard line (near 2^-16,
 * depths to 1,000; ~3 px at near 0.001, depths 2,000-32,000). The end depends
 * on the two distances only, so a shared edge is cut at one point. */
static void intersect(const fxl_xform_t *xf, int plane, const fxl_clipvert_t *in, int64_t d_in,
                      const fxl_clipvert_t *out, int64_t d_out, fxl_clipvert_t *res)
{
    /* 0 <= d_in < d_in - d_out < 2^62. Both to 32 significant bits and
     * t = (num / den) 2^(tn - td): the mantissa (num / den) 2^31 < 2^32
     * keeps its precision when the near end's |d| is tiny beside the
     * other's. One shared shift, as before, left a vertex just inside the
     * near plane 1-2 bits of t: corners ~150 px off on scaled geometry
     * with a small near. */
    const uint64_t d_out_mag = (uint64_t)0 - (uint64_t)d_out;
    const int from_out = (uint64_t)d_in > d_out_mag;
    const fxl_clipvert_t *a = from_out ? out : in, *b = from_out ? in : out;
    const uint64_t d_a = from_out ? d_out_mag : (uint64_t)d_in;
    lerp_t t = {0u, 31u};
    if (d_a > 0) {
        int tn, td;
        const uint64_t num = to_32_bits(d_a, &tn);
        const uint64_t den = to_32_bits((uint64_t)d_in + d_out_mag, &td);
        /* < 2^32: num < 2^32, den >= 2^31, so num 2^31 / den + 1/2 < 2^32 */
        const uint64_t m = fxl__fe_udiv64((num << 31) + den / 2u, den);
        /* >= 1: 2 d_a <= d_in - d_out, so d_a's top bit is below the sum's */
        const int e = td - tn;
        if (e < 8) {
            /* t >= 2^-8: q31 keeps 24 significant bits of it and takes
             * the constant shift (the -O2 floor's submit was 10% dearer
             * with every cut through the variable one) */
            t.m = (uint32_t)((m + ((uint64_t)1 << (e - 1))) >> e);
        } else {
            t.m = (uint32_t)m;
            t.sh = 31u + (unsigned)e;
        }
    }
    res->x = lerp64(a->x, b->x, &t);
    res->y = lerp64(a->y, b->y, &t);
    res->w = lerp64(a->w, b->w, &t);
    res->u = lerp32(a->u, b->u, &t);
    res->v = lerp32(a->v, b->v, &t);
    res->r = lerp32(a->r, b->r, &t);
    res->g = lerp32(a->g, b->g, &t);
    res->b = lerp32(a->b, b->b, &t);
    /* the intersection exactly on the plane */
    if (plane == PL_NEAR) {
        /* rare: the lerps above are then redone exactly (testing first,
         * to skip them, cost the -O2 clipped floor's submit 108 of its
         * 19,071 instructions) */
        if (near_exact(xf, in, out)) {
            res->x = near_cut(in->x, out->x, (uint64_t)d_in, (uint64_t)0 - (uint64_t)d_out);
            res->y = near_cut(in->y, out->y, (uint64_t)d_in, (uint64_t)0 - (uint64_t)d_out);
        }
        res->w = xf->near_q32;
    } else if (plane == PL_FAR) {
        res->w = xf->far_q32;
    } else {
        const int64_t g = plane_is_positive(plane) ? guard_w(xf, res->w) : -guard_w(xf, res->w);
        if (plane_is_x(plane))
            res->x = g;
        else
            res->y = g;
    }
    if (res->w < xf->near_q32) res->w = xf->near_q32; /* rounding never takes it behind near */
}

/* Makes room in a polygon that is full (m = FXL_CLIP_MAX_VERTS vertices,
 * so m >= 2): removes vertex i >= 1 nearest its predecessor (largest of
 * |dx|, |dy|, |dw|; the first on ties) and returns m - 1. A convex polygon
 * never fills up (3 + k vertices after k planes); one does only where the
 * cut points' rounding made it non-convex, near two planes at once, and
 * then its surplus vertices lie within that rounding of their neighbours.
 * Refusing such a triangle stopped fxl_mesh_draw at a valid mesh. Every
 * |coordinate| is below 2^61 (G w <= 2^60 on a guard plane), so the
 * differences fit int64. */
static uint32_t drop_closest(fxl_clipvert_t *poly, uint32_t m)
{
    uint32_t i, best = 1;
    uint64_t best_d = UINT64_MAX;
    for (i = 1; i < m; i++) {
        const uint64_t dx = fxl__mag64(poly[i].x - poly[i - 1].x), dy = fxl__mag64(poly[i].y - poly[i - 1].y);
        const uint64_t dw = fxl__mag64(poly[i].w - poly[i - 1].w);
        const uint64_t d = dx > dy ? (dx > dw ? dx : dw) : (dy > dw ? dy : dw);
        if (d < best_d) {
            best_d = d;
            best = i;
        }
    }
    for (i = best; i + 1 < m; i++) poly[i] = poly[i + 1];
    return m - 1;
}

/* Bit pl set where plane_dist(xf, pl, v) < 0. G w is formed once: through
 * plane_dist it was four 96-bit products a corner, twelve a triangle. */
int fxl__clip_outcode(const fxl_xform_t *xf, int64_t x, int64_t y, int64_t w)
{
    const int64_t gw = guard_w(xf, w);
    int code = 0;
    if (w - xf->near_q32 < 0) code |= 1 << PL_NEAR;
    if (xf->far_q32 != 0 && xf->far_q32 - w < 0) code |= 1 << PL_FAR;
    if (gw - x < 0) code |= 1 << PL_XP;
    if (gw + x < 0) code |= 1 << PL_XN;
    if (gw - y < 0) code |= 1 << PL_YP;
    if (gw + y < 0) code |= 1 << PL_YN;
    return code;
}

static int outcode(const fxl_xform_t *xf, const fxl_clipvert_t *v)
{
    return fxl__clip_outcode(xf, v->x, v->y, v->w);
}

static int in_range(const fxl_clipvert_t *v)
{
    return v->x < FXL_CLIP_LIMIT_Q32 && v->x > -FXL_CLIP_LIMIT_Q32 &&
           v->y < FXL_CLIP_LIMIT_Q32 && v->y > -FXL_CLIP_LIMIT_Q32 &&
           v->w < FXL_CLIP_LIMIT_Q32 && v->w > -FXL_CLIP_LIMIT_Q32;
}

fxl_status_t fxl_clip_triangle(const fxl_xform_t *xf, const fxl_clipvert_t in[3],
                               fxl_clipvert_t out[FXL_CLIP_MAX_VERTS], uint32_t *n)
{
    if (!xf || !in || !out || !n) return FXL_ERR_ARG;
    *n = 0;
    if (!fxl__xform_ok(xf)) return FXL_ERR_RANGE;
    return fxl__clip_triangle(xf, in, out, n);
}

fxl_status_t fxl__clip_triangle(const fxl_xform_t *xf, const fxl_clipvert_t in[3],
                                fxl_clipvert_t out[FXL_CLIP_MAX_VERTS], uint32_t *n)
{
    /* The polygon goes back and forth between scratch and out, one plane a
     * pass: one local buffer of FXL_CLIP_MAX_VERTS (432 B on 32-bit cores)
     * and the caller's, where two of 16 in this frame (1,536 B) made the
     * clipper the deepest frame of a firmware's front end
     * (docs/porting.md, section 10). */
    fxl_clipvert_t scratch[FXL_CLIP_MAX_VERTS];
    fxl_clipvert_t *cur = scratch, *next = out;
    int c0, c1, c2, pl;
    uint32_t count = 3, i;
    *n = 0;
    if (!in_range(&in[0]) || !in_range(&in[1]) || !in_range(&in[2])) return FXL_ERR_RANGE;
    c0 = outcode(xf, &in[0]);
    c1 = outcode(xf, &in[1]);
    c2 = outcode(xf, &in[2]);
    if ((c0 & c1 & c2) != 0) return FXL_OK; /* all outside one plane */
    /* copied first: in may overlap out (fxl_clip_triangle's caller) */
    for (i = 0; i < 3; i++) scratch[i] = in[i];
    if ((c0 | c1 | c2) != 0) {
        /* The planes some vertex of the polygon is outside: the inputs', and
         * each cut point's. A cut point carries t's rounding times its
         * edge's length, and with a long edge and a tiny near plane that put
         * it past a guard plane no input vertex was outside (depth ratios of
         * ~10^6): skipped, that plane left a corner the projection refuses
         * (FXL_ERR_RANGE from a valid pipeline and mesh). */
        int codes = c0 | c1 | c2;
        for (pl = 0; pl < PL_COUNT; pl++) {
            const fxl_clipvert_t *src = cur;
            fxl_clipvert_t *dst = next;
            uint32_t m = 0;
            if (!(codes & (1 << pl))) continue; /* no vertex is outside */
            for (i = 0; i < count; i++) {
                const fxl_clipvert_t *a = &src[i], *b = &src[(i + 1) % count];
                int64_t da = plane_dist(xf, pl, a), db = plane_dist(xf, pl, b);
                /* A convex polygon gains at most one vertex a plane, so
                 * after k planes it has at most 3 + k <= FXL_CLIP_MAX_VERTS;
                 * one that rounding made longer loses its nearest-neighbour
                 * vertices (drop_closest). */
                if (da >= 0) {
                    if (m >= FXL_CLIP_MAX_VERTS) m = drop_closest(dst, m);
                    dst[m++] = *a;
                }
                if ((da >= 0) != (db >= 0)) { /* the edge crosses the plane */
                    if (m >= FXL_CLIP_MAX_VERTS) m = drop_closest(dst, m);
                    if (da >= 0)
                        intersect(xf, pl, a, da, b, db, &dst[m]);
                    else
                        intersect(xf, pl, b, db, a, da, &dst[m]);
                    codes |= outcode(xf, &dst[m++]);
                }
            }
            count = m;
            next = cur;
            cur = dst;
            if (count < 3) return FXL_OK; /* nothing with area left */
        }
    }
    if (cur != out)
        for (i = 0; i < count; i++) out[i] = cur[i];
    *n = count;
    return FXL_OK;
}

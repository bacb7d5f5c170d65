/* setup.c - triangle setup: per-triangle scaling and attribute planes.
 *
 * Every interpolated quantity is a plane over the snapped vertices:
 *   a(X, Y) = a0 + gx (X - X0) + gy (Y - Y0)
 *   gx = ((a1 - a0)(Y2 - Y0) - (a2 - a0)(Y1 - Y0)) / det
 *   gy = ((a2 - a0)(X1 - X0) - (a1 - a0)(X2 - X0)) / det
 *   det = (X1 - X0)(Y2 - Y0) - (X2 - X0)(Y1 - Y0)
 * The numerators are exact in int64 (|a| < 2^32, |dX|, |dY| <= 2^22 give
 * < 2^55); the quotient is rounded to FXL__PF fraction bits by long division.
 *
 * Precision management (why the scaling): 1/w spans many octaves across a
 * receding triangle, so one fixed format cannot hold it. q is 1/w shifted so
 * the nearest vertex has q in [2^30, 2^31); u/w and v/w are shifted so the
 * largest vertex value is below 2^30; texture coordinates are first rebased
 * by whole periods (repeat) or pairs of periods (mirror), which the wrap
 * makes invisible, so large but narrow UV ranges keep their precision.
 */
#include "raster_int.h"
#include "persp.h"
#include "div64.h"

/* round(r * 2^bits / den) for |r| < den, 0 < den < 2^47, bits <= 31, by
 * long division in 16-bit chunks so no intermediate exceeds 2^63. The
 * quotient is below 2^bits, at most 2^bits rounded: 32 bits hold it (at
 * -Os one shift and one OR a step, not a 64-bit shift). */
static int64_t div_frac(int64_t r, int64_t den, int bits)
{
    uint64_t ur = r < 0 ? (uint64_t)0 - (uint64_t)r : (uint64_t)r;
    uint64_t d = (uint64_t)den;
    uint32_t q = 0;

#if FXL_SMALL_DIV64
    /* one quotient bit a step (ur < d < 2^47: the shift cannot wrap) */
    while (bits-- > 0) {
        ur <<= 1;
        q <<= 1;
        if (ur >= d) {
            ur -= d;
            q |= 1u;
        }
    }
#else
    while (bits > 0) {
        int c = bits > 16 ? 16 : bits;
        ur <<= c;
        {
            const uint64_t qc = fxl__udiv64(ur, d);   /* < 2^c */
            q = (q << c) + (uint32_t)qc;
            ur -= qc * d;
        }
        bits -= c;
    }
#endif
    if (2u * ur >= d)
        q++;
    return r < 0 ? -(int64_t)q : (int64_t)q;
}

/* The triangle's doubled area det as the gradients divide by it. */
typedef struct area {
    fxl__div64_t abs;   /* |det| */
    int neg;            /* det < 0 */
    uint8_t huge;       /* 4: some gradient's size is lost (uv_wide) */
} area_t;

/* N / den with FXL__PF fraction bits, den > 0, rounded, modulo 2^64. The
 * planes are evaluated modulo 2^64 and a value inside the triangle lies
 * within its vertex range, so values come out right whatever the size of
 * the gradients. What reads their size - segment bounds, the per-segment
 * LOD, from 16 gradients' worth a pixel - needs |N / den| < 2^38 (2^42
 * units a pixel, 2^11 times the range of a plane's vertex values: only
 * slivers thinner than ~2^-11 px across go beyond); beyond, det->huge. */
#if defined(__GNUC__) && !defined(__OPTIMIZE_SIZE__)
#define FXL__SETUP_INLINE inline __attribute__((always_inline))   /* two calls a plane were ~25 M4 instructions */
#else
#define FXL__SETUP_INLINE inline
#endif
/* log2 of the "huge" gradient, units a sub-pixel: 2^38 a sub-pixel is 2^42
 * units a pixel at S = 4, which is what the per-pixel readers (gx * ONE in
 * lod_setup, auto.c, auto.h) need to stay within int64; at S = 5, 6 the
 * same 2^42 a pixel is 2^37, 2^36 a sub-pixel. */
#define FXL__HUGE_LOG2 (FXL__S > 4 ? 42 - FXL__S : 38)

static FXL__SETUP_INLINE int64_t gradient(int64_t N, area_t *det)
{
    const fxl__div64_t *dv = &det->abs;
    const int64_t den = (int64_t)dv->d;
    int64_t qi, r;

    /* The value is sign(N) * round_half_up(|N| 2^PF / den). When |N| 2^PF
     * fits 63 bits (the usual case) one division with its remainder gives it
     * exactly - the same number the chunked path below computes with three,
     * which matters on Cortex-M where each is a library call. (Size-
     * optimised builds take the general path alone, less code, unless
     * their divisions are by32's: FXL_SMALL_DIV64_HW.) */
    if ((!FXL_SMALL_DIV64 || FXL__SMALL_BY32) && N > -((int64_t)1 << (62 - FXL__PF)) && N < ((int64_t)1 << (62 - FXL__PF))) {
        const uint64_t a = (uint64_t)(N < 0 ? -N : N) << FXL__PF;   /* < 2^62 */
        uint64_t rem, q = fxl__div64_by(a, dv, &rem);
        /* the general path's test below, on floor(|N| 2^PF / den) */
        if ((q >> (FXL__HUGE_LOG2 + FXL__PF)) &&
            q >= ((uint64_t)1 << (FXL__HUGE_LOG2 + FXL__PF)) + (N < 0 ? (uint64_t)1 << FXL__PF : 0u))
            det->huge = 4u;
        if (2u * rem >= (uint64_t)den)
            q++;
        return N < 0 ? -(int64_t)q : (int64_t)q;
    }
    qi = fxl__sdiv64(N, den);
    r = N - qi * den;
    if ((uint64_t)(qi + ((int64_t)1 << FXL__HUGE_LOG2)) >> (FXL__HUGE_LOG2 + 1))   /* |qi| beyond 2^HUGE */
        det->huge = 4u;
    return (int64_t)(((uint64_t)qi << FXL__PF) + (uint64_t)div_frac(r, den, FXL__PF));
}

static void make_plane(fxl__plane_t *p, const int64_t a[3], const int32_t X[3], const int32_t Y[3],
                       area_t *det)
{
    int64_t dX1 = (int64_t)X[1] - X[0], dY1 = (int64_t)Y[1] - Y[0];
    int64_t dX2 = (int64_t)X[2] - X[0], dY2 = (int64_t)Y[2] - Y[0];
    int64_t da1 = a[1] - a[0], da2 = a[2] - a[0];
    int64_t nx = da1 * dY2 - da2 * dY1;
    int64_t ny = da2 * dX1 - da1 * dX2;

    if (det->neg) {
        nx = -nx;
        ny = -ny;
    }
    p->c = a[0] * ((int64_t)1 << FXL__PF);
    p->gx = gradient(nx, det);
    p->gy = gradient(ny, det);
}

int64_t fxl__plane_at(const fxl__plane_t *p, int32_t X0, int32_t Y0, int32_t X, int32_t Y)
{
    /* Modular arithmetic: see raster_int.h. */
    uint64_t v = (uint64_t)p->c + (uint64_t)p->gx * (uint64_t)((int64_t)X - X0) +
                 (uint64_t)p->gy * (uint64_t)((int64_t)Y - Y0);
    return (int64_t)v;
}

/* Smallest k >= 0 with |a_i| >> k < 2^bits for all three. */
static inline int fit_shift(const int64_t a[3], int bits)
{
    uint64_t m = 0;
    int i, len;

    for (i = 0; i < 3; i++) {
        uint64_t v = a[i] < 0 ? (uint64_t)0 - (uint64_t)a[i] : (uint64_t)a[i];
        if (v > m)
            m = v;
    }
    /* m >> k < 2^bits <=> k >= bit length of m - bits (one CLZ; a loop of
     * 64-bit shifts here was ~700 Cortex-M4 instructions a triangle) */
    len = 64 - fxl__clz64_inline(m);
    return len > bits ? len - bits : 0;
}

/* Rebase three normalised q16 coordinates by whole periods (repeat) or
 * pairs of periods (mirror) so the smallest lies in [0, 1) or [0, 2).
 * Returns how the axis is wide (raster_int.h, uv_wide): 1 for repeat or
 * mirror with the largest rebased value at 2^30 q16 texels or more of a
 * level 0 2^lg texels across - normalised, 2^(30 - lg). Any two points of
 * the triangle lie less than 2^30 apart otherwise (u over it is between
 * its vertex values): half the 2^31 of the short way. 2 for clamp and
 * border with a vertex at 2^31 - 2^16 q16 texels or more from 0: its
 * correction points may saturate (span.c, sat_i32_bits), and a step
 * towards a saturated value crosses the texture at the wrong pixel. Also
 * gives the rebased values' range, lowest and highest. */
static int rebase(const int32_t c[3], fxl_wrap_t wrap, uint32_t lg, int64_t out[3], int64_t range[2])
{
    int32_t mn = c[0], mx = c[0], base = 0;
    uint32_t lim = 0x7FFF0000u;   /* clamp/border: 2^31 - 2^16 */
    int i;

    for (i = 1; i < 3; i++) {
        if (c[i] < mn)
            mn = c[i];
        if (c[i] > mx)
            mx = c[i];
    }
    if (wrap <= FXL_WRAP_MIRROR) {
        /* whole periods (repeat) or pairs of them (mirror), floored */
        const int sh = wrap == FXL_WRAP_REPEAT ? 16 : 17;
        base = fxl__i32_of_bits((uint32_t)fxl__asr32(mn, sh) << sh);
        lim = 1u << 30;
    }
    for (i = 0; i < 3; i++)
        out[i] = (int64_t)c[i] - base;
    /* the rebased range as q16 texels of level 0 (span.c, lod_bound_hi;
     * builds without mip levels have no use for it), exact: mn - base is
     * below 2^17 (repeat, mirror) or mn (clamp, border), |mx - base| below
     * 2^32, lg <= 15 */
    if (FXL_HAVE_MIPMAP) {
        range[0] = (int64_t)fxl__i32_of_bits((uint32_t)mn - (uint32_t)base) * (int32_t)(1 << lg);
        range[1] = (int64_t)((uint64_t)((int64_t)mx - base) * (1u << lg));
    }
    lim >>= lg;
    if ((int64_t)mx - base >= (int64_t)lim || (FXL_HAVE_GENERIC && mn - base <= -(int64_t)lim))
        return 1 + (wrap > FXL_WRAP_MIRROR);
    return 0;
}

/* Build the plane of attribute a_i * q_i, scaled below 2^30. */
static void persp_plane(fxl__tri_t *tri, int idx, const int64_t a[3], const int64_t q[3],
                        const int32_t X[3], const int32_t Y[3], area_t *det)
{
    int64_t s[3];
    int i, k;

    for (i = 0; i < 3; i++)
        s[i] = a[i] * q[i];   /* |a| < 2^32, q < 2^31: |s| < 2^63 */
    k = fit_shift(s, 30);
    for (i = 0; i < 3; i++)
        s[i] = fxl__asr64(s[i], k);
    tri->a_shift[idx] = k;
    make_plane(&tri->a[idx], s, X, Y, det);
}

/* Texture axis ax (0: u, 1: v): rebased, its bit length for the
 * per-segment LOD, its plane. A loop over the axes at -Os (one copy);
 * elsewhere two copies specialised for ax (the loop was ~80 instructions
 * a triangle slower on x86-64 at -O2). */
static FXL__SETUP_INLINE void uv_plane(fxl__tri_t *tri, const fxl_vertex_t v[3], int ax, const int64_t q[3],
                                       const int32_t X[3], const int32_t Y[3], area_t *det)
{
    int32_t c[3];
    int64_t a[3];
    int i;
    for (i = 0; i < 3; i++)
        c[i] = ax ? v[i].v : v[i].u;
    tri->uv_wide |= (uint8_t)rebase(c, (fxl_wrap_t)(ax ? tri->tex->wrap_v : tri->tex->wrap_u),
                                    ax ? tri->tex->log2_h : tri->tex->log2_w, a, tri->lod_a[ax]);
#if FXL_HAVE_MIPMAP
    if (tri->draw->lod == FXL_LOD_SEGMENT && tri->draw->mip != FXL_MIP_NONE)   /* span.c, lod_setup */
        tri->uv_len[ax] = (uint8_t)fit_shift(a, 0);
#endif
    persp_plane(tri, FXL__AU + ax, a, q, X, Y, det);
}

fxl_status_t fxl__setup(fxl__tri_t *tri, const fxl_vertex_t v[3], const int32_t X[3],
                        const int32_t Y[3], int64_t det)
{
    int64_t q[3], z[3], a[3];
    int i;
    area_t area;   /* divides up to 2 x 7 gradients */

    tri->uv_wide = 0;
    area.neg = det < 0;
    area.huge = 0;
    fxl__div64_init(&area.abs, area.neg ? (uint64_t)0 - (uint64_t)det : (uint64_t)det);
    tri->X0 = X[0];
    tri->Y0 = Y[0];

    /* q: 1/w normalised so the largest vertex value is in [2^30, 2^31).
     * Affine mode uses a constant q, which makes u = s / q linear. */
    if (tri->affine) {
        for (i = 0; i < 3; i++)
            q[i] = (int64_t)1 << 30;
    } else {
        uint32_t mx = v[0].inv_w;
        int sh;
        if (v[1].inv_w > mx)
            mx = v[1].inv_w;
        if (v[2].inv_w > mx)
            mx = v[2].inv_w;
        sh = fxl_clz32(mx) - 1;   /* mx >= 1 (validated): sh in [-1, 30] */
        for (i = 0; i < 3; i++) {
            q[i] = sh >= 0 ? (int64_t)v[i].inv_w << sh : (int64_t)(v[i].inv_w >> 1);
            if (q[i] < 1)
                q[i] = 1;
        }
    }
    make_plane(&tri->q, q, X, Y, &area);
    tri->q_min = tri->q_max = q[0];
    for (i = 1; i < 3; i++) {
        if (q[i] < tri->q_min)
            tri->q_min = q[i];
        if (q[i] > tri->q_max)
            tri->q_max = q[i];
    }
    tri->q_min *= (int64_t)1 << FXL__PF;
    tri->q_max *= (int64_t)1 << FXL__PF;

#if FXL_HAVE_DEPTH
    if (fxl__uses_depth(tri)) {
        for (i = 0; i < 3; i++)
            z[i] = (int64_t)v[i].inv_w;
        make_plane(&tri->z, z, X, Y, &area);
    } else
#endif
    {
        /* No depth buffer in use (the walks without depth never read z;
         * the generic walk steps it but tests and writes it only with
         * one): two gradients fewer, ~190 Cortex-M4 instructions a
         * triangle. */
        (void)z;
        tri->z.c = tri->z.gx = tri->z.gy = 0;
    }

    if (fxl__has_uv(tri)) {
#if defined(__OPTIMIZE_SIZE__)
        int ax;
        for (ax = 0; ax < 2; ax++)
            uv_plane(tri, v, ax, q, X, Y, &area);
#else
        uv_plane(tri, v, 0, q, X, Y, &area);
        uv_plane(tri, v, 1, q, X, Y, &area);
#endif
    }
    if (fxl__has_color(tri)) {
        /* Channels as q16 (r5, g6, b5), perspective-correct like u, v. */
        static const uint8_t sh[3] = {11, 5, 0}, mask[3] = {31, 63, 31};
        int ch;
        for (ch = 0; ch < 3; ch++) {
            uint32_t lo = mask[ch], hi = 0;
            for (i = 0; i < 3; i++) {
                const uint32_t c = (v[i].color >> sh[ch]) & mask[ch];
                lo = c < lo ? c : lo;
                hi = c > hi ? c : hi;
                a[i] = (int64_t)c << 16;
            }
            tri->color_lo[ch] = (int32_t)(lo << 16);
            tri->color_hi[ch] = (int32_t)(hi << 16);
            persp_plane(tri, FXL__AR + ch, a, q, X, Y, &area);
        }
    }
    tri->uv_wide |= area.huge;
    return FXL_OK;
}

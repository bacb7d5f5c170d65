/* raster_int.h - private state shared by setup.c, edge.c, span.c, raster.c.
 *
 * Units used throughout (S = FXL_SUBPIXEL_BITS):
 * - positions: integer sub-pixel grid units ("subpx"), 1 px = 2^S subpx;
 *   snapped vertices of an int32 q16 input lie within +-2^(31-16+S) subpx.
 *   Pixel (i, j) has its centre at subpx (i * 2^S + 2^(S-1), j * 2^S + 2^(S-1)).
 * - planes: an attribute a(X, Y) = c + gx * (X - X0) + gy * (Y - Y0), where
 *   c, gx, gy carry FXL__PF fraction bits ("plane units"), X, Y are subpx and
 *   (X0, Y0) is the reference vertex. Values are evaluated in uint64 modular
 *   arithmetic: the true value at any point inside the triangle is bounded by
 *   the vertex values (< 2^32 units), so an intermediate wrap-around cancels
 *   and no signed overflow can occur.
 */
#ifndef FIXEL_RASTER_INT_H
#define FIXEL_RASTER_INT_H

#include <stdint.h>
#include "fixel/raster.h"

#define FXL__S FXL_SUBPIXEL_BITS
#define FXL__ONE (1 << FXL__S)           /* one pixel in subpx */
#define FXL__HALF (1 << (FXL__S - 1))    /* half a pixel in subpx */

/* Fraction bits of plane constants and gradients. With distances below 2^21
 * subpx and gradients rounded to 2^-21 units, evaluation error stays below
 * one plane unit; the attributes are scaled per triangle so a unit is at most
 * 2^-30 of the largest vertex value. */
#define FXL__PF 20

/* Perspective-interpolated attributes: u, v and (Gouraud) r, g, b. */
enum { FXL__AU = 0, FXL__AV = 1, FXL__AR = 2, FXL__AG = 3, FXL__AB = 4, FXL__NATTR = 5 };

/* A soft float, value = m * 2^e with |m| <= 2^31 (operations in sfloat.h). */
typedef struct fxl__sf {
    int32_t m;   /* int32, so a product is one SMULL on a Cortex-M */
    int e;
} fxl__sf_t;

typedef struct fxl__plane {
    int64_t c;   /* value at the reference vertex, FXL__PF fraction bits */
    int64_t gx;  /* per subpx along x */
    int64_t gy;  /* per subpx along y */
} fxl__plane_t;

/* One edge walked row by row with an exact remainder (a DDA on the ceiling of
 * the intercept): at every row, x is the first pixel whose centre is at or
 * right of the edge. */
typedef struct fxl__edge {
    int32_t x;       /* ceil((X(yc) - HALF) / ONE): first pixel at/after the edge */
    int32_t err;     /* x * den - num, in [0, den) */
    int32_t den;     /* ONE * dy, dy > 0 */
    int32_t step;    /* floor(ONE * dx / den) */
    int32_t rem;     /* ONE * dx - step * den, in [0, den) */
} fxl__edge_t;

/* A texture level ready for the span loops. */
typedef struct fxl__level {
    const void *texels;
    uint32_t log2_w, log2_h;
    uint32_t mask_u, mask_v;     /* size - 1 */
} fxl__level_t;

/* Plane slots of a correction point: q, z, then the attributes. */
enum { FXL__PQ = 0, FXL__PZ = 1, FXL__PA = 2, FXL__NPLANES = FXL__PA + FXL__NATTR };

/* Exact perspective division at one point: attribute plane value `av` over
 * q plane value `qv` (> 0), scaled by 2^(shift) where shift = a_shift + the
 * caller's output scale; returns the 64-bit result (modular when it does not
 * fit). See span.c for the error bound. */
typedef struct fxl__recip {
    uint32_t r;    /* ~ 2^62 / qn */
    int n;         /* qv ~ qn * 2^(32 - n) */
} fxl__recip_t;
/* fxl__recip() and fxl__persp() are inline in persp.h. */

/* Everything the span loops need for one triangle. */
struct fxl__lean;   /* span.c: the lean walks' position */

/* AUTO's longest segment, log2 (256 pixels): auto_cap's ceiling */
#define FXL__AUTO_CAP_MAX 8

typedef struct fxl__tri {
    const fxl_draw_t *draw;
    const fxl_texture_t *tex;    /* NULL: untextured */
    fxl_target_t *target;

    int32_t X0, Y0;              /* reference vertex, subpx */
    fxl__plane_t q;              /* 1/w scaled so the largest vertex value is in [2^30, 2^31) */
    fxl__plane_t z;              /* inv_w as given (u0.32), for the depth buffer */
    fxl__plane_t a[FXL__NATTR];  /* attribute * q >> a_shift[i] */
    int a_shift[FXL__NATTR];     /* per-triangle scale of each attribute plane */
    uint8_t has_uv;              /* textured: planes u, v in use */
    uint8_t has_color;           /* Gouraud: planes r, g, b in use */
    /* Gouraud: each channel's (r5, g6, b5) least and greatest vertex value
     * in q16, to which the corrections clamp it: rounding left a constant
     * colour one step low at ~1-2% of its pixels. As int32, not bytes to
     * shift: the firmware example's lit bands +0.75% for the clamp instead
     * of +1.7% (Cortex-M4 -O2), for 18 bytes more of the triangle. */
    int32_t color_lo[3], color_hi[3];
    uint8_t signed_u, signed_v;  /* clamp/border axes hold saturated int32 coordinates */
    int64_t q_min;               /* smallest vertex q in plane units (clamp floor) */
    int64_t q_max;               /* largest vertex q in plane units */
    /* q the same everywhere (affine mode, a face parallel to the screen):
     * every correction point's 1/q is 1/q_min, computed once */
    uint8_t q_const;
    /* the lean walks' correction (span.c), chosen with the walk: a copy
     * that keeps the span start's 1/q where q is the same along every row
     * (gpx[PQ] == 0 exactly: two vertices on one row at one depth) */
    void (*lean_next)(const struct fxl__tri *tri, struct fxl__lean *s, uint32_t mult);
    fxl__recip_t rc_qmin;        /* fxl__recip(q_min), with q_const */

    int seg_log2;                /* log2 of the segment length, 0..8 */
    /* FXL_PERSP_AUTO (auto.c, auto.h): auto_seg 1, each segment's length
     * comes from the error bound at its correction point; 2, every segment
     * is quadratic, of length 2^seg_log2 (0: one fixed length, as other modes) */
    uint8_t auto_seg;
    uint64_t auto_duv;           /* range u + range v of the vertices, q16 texels of level 0 */
    int32_t auto_w;              /* the widest span (bounding box), px, < 2^17 */
    int8_t auto_cap;             /* longest log2 length: the least <= FXL__AUTO_CAP_MAX with 2^cap >= auto_w */
    uint32_t auto_gx32;          /* ceil(|q_x| per pixel >> PF), saturated at 2^31 */
    int32_t auto_t0;             /* q8 log2 terms of the bound common to all rows */
    int64_t auto_n[2];           /* N_u, N_v at Y0, units of 2^-29 of their largest value */
    int64_t auto_ns[2];          /* their change per subpx of Y, q16 of those units */
    /* Second-order (quadratic) segments (auto.h, fxl__quad_steps): a
     * segment the affine bound rejects may still fit the bound of a
     * parabola through its exact ends, which also follows the curvature. */
    uint8_t auto_quad;           /* read through fxl__auto_quad() */
    /* Reciprocal runs (recip_run.h): u, v from an approximate 1/q at every
     * pixel, where segments would be short */
    uint8_t auto_rr;
    int32_t auto_tq;             /* the quadratic bound's t_row minus the affine one's, q8 */
    int32_t qx_m;                /* q_x per pixel = qx_m * 2^qx_e, |qx_m| in [2^30, 2^31) */
    int qx_e;
    uint8_t affine;              /* q constant: no perspective */
    uint8_t depth_test, depth_write;
    uint8_t swap;                /* target stores byte-swapped RGB565 */

    /* mip state */
    int32_t lod_q8_tri;          /* per-triangle LOD incl. bias, clamped, q8 levels */
    uint8_t lod_per_segment;
    uint8_t lod_grid;            /* AUTO: per-segment LOD on the 16-pixel grid only (auto.h) */
    uint8_t nlevels;
    fxl__level_t level[FXL_TEX_MAX_LEVELS];
    uint8_t mip_linear;          /* blend two levels */
    int32_t lod_max_q8;          /* (levels - 1) * 256 */
    /* per-segment LOD's constant factors (span.c, lod_setup): for each
     * direction g (x, y) the numerators S_g - u q_g of du/dg, dv/dg are
     * lod_s[g][u or v] - u' * lod_mq[g] in units of 2^e, lod_e512[g] =
     * 512 e, with u' = u >> lod_ash (q16 texels of level 0, saturated) */
    int64_t lod_s[2][2];
    int32_t lod_mq[2];
    int32_t lod_e512[2];
    int32_t lod_dirc[2];         /* direction g's 2 log2 length when lod_mq[g] == 0 (then independent of u, v) */
    uint8_t lod_ash;
    /* the per-segment LOD (span.c, lod_setup chooses the copy: the ones
     * for lod_mq[g] == 0 read lod_dirc[g]) */
    int32_t (*lod_at)(const struct fxl__tri *tri, int64_t qv, int64_t u64, int64_t v64);
    /* where q is constant along rows (gpx[PQ] == 0, so lod_mq[0] == 0), the
     * same from lod_lq's log2 q term, which the constant-depth walk (64-bit
     * hosts, span_walk.h) then takes once a span; else NULL (always at -Os) */
    int32_t (*lod_at_lq)(const struct fxl__tri *tri, int32_t lq, int64_t u64, int64_t v64);
    uint8_t uv_len[2];           /* bit length of the largest rebased vertex u, v (normalised q16, setup.c) */
    /* A repeat or mirror axis whose rebased vertex coordinates reach 2^14
     * texels of level 0 (setup.c): two points of the triangle may then be
     * 2^15 texels or more apart, beyond what the q16 coordinates' 32 bits
     * tell apart (they hold u modulo 2^16 texels, and a segment's change
     * is taken the short way round). Such triangles take the generic walk,
     * which steps from the 64-bit values, with affine segments only (bit 0).
     * Bit 1: a clamp or border axis with a vertex near or past the 2^15
     * texels its saturated int32 coordinates hold; every pixel is then a
     * correction point (raster.c). Bit 2: some plane's gradient is kept
     * modulo 2^64 and is 2^38 units a sub-pixel or more (2^(42 - S) for
     * S > 4, so that 2^S sub-pixels of it fit int64; setup.c, gradient:
     * a needle, its attribute range within ~2^-11 px across); its values
     * are right, but segment bounds and the per-segment LOD, which read
     * the gradients' size, are not: every pixel is a correction point and
     * the LOD is the triangle's (raster.c). */
    uint8_t uv_wide;

    /* derived once per triangle for the span walk (fxl__span_setup) */
    int np;                             /* planes in use: 2, 4 or 7 */
    const fxl__plane_t *pl[FXL__NPLANES];
    int64_t gpx[FXL__NPLANES];          /* per pixel along x, modular */
    int64_t gpxN[FXL__NPLANES];         /* per full segment */
    int persp_eb[2];                    /* fxl__persp_eb of u, v (persp.h) */
    uint8_t fast_id;                    /* span.c: specialised span function, 0 none */

    fxl_stats_t *stats;

    /* The per-segment LOD's bound (last, so that the walks' fields above
     * keep their offsets): the rebased vertex range of u (0) and v (1)
     * [0: lowest, 1: highest], q16 texels of level 0 (setup.c, rebase),
     * where the coordinates of every point of the triangle lie; lod_hi,
     * the largest LOD lod_at gives there (span.c, lod_bound_hi; where that
     * is above level 0 with the bias, it may hold a smaller value, still
     * above it). A triangle whose lod_hi is at or below level 0 with its
     * bias takes lod_at_const, which gives lod_hi. */
    int64_t lod_a[2][2];
    int32_t lod_hi;
} fxl__tri_t;

/* What a triangle draws, as constants where the configuration allows only
 * one answer: without FXL_HAVE_GENERIC every draw is textured, RGB565,
 * repeat-wrapped and flat-shaded (check_draw refuses the rest), so the
 * compiler drops the Gouraud and the clamped-coordinate code paths. */
static inline int fxl__has_uv(const fxl__tri_t *tri)
{
    return !FXL_HAVE_GENERIC || tri->has_uv;
}
static inline int fxl__has_color(const fxl__tri_t *tri)
{
    return FXL_HAVE_GENERIC && tri->has_color;
}
/* a depth buffer that the draw tests or writes (else z is never read) */
static inline int fxl__uses_depth(const fxl__tri_t *tri)
{
    return tri->target->depth && (tri->depth_test || tri->depth_write);
}
/* Quadratic segments in this triangle (0 at compile time without them). */
static inline int fxl__auto_quad(const fxl__tri_t *tri)
{
    return FXL_HAVE_QUAD && tri->auto_quad;
}
static inline int fxl__signed_u(const fxl__tri_t *tri)
{
    return FXL_HAVE_GENERIC && tri->signed_u;
}
static inline int fxl__signed_v(const fxl__tri_t *tri)
{
    return FXL_HAVE_GENERIC && tri->signed_v;
}

/* A run of pixels between two correction points. */
typedef struct fxl__seg {
    uint16_t *dst;          /* first pixel of the run in the target */
    uint16_t *zb;           /* matching depth entry (NULL when no depth buffer) */
    int32_t n;              /* pixels in the run, >= 1 */
    uint32_t u, v;          /* texel coordinates at the first pixel, q16 of `level` */
    int32_t du, dv;         /* per pixel, q16 (the first step) */
    int32_t ddu, ddv;       /* change of du, dv per pixel: 0 but in quadratic segments */
    uint32_t z;             /* inv_w at the first pixel, u0.32 */
    int32_t dz;             /* per pixel, u0.32 modulo 2^32 (a one-pixel step can exceed an int32) */
    uint32_t c[3];          /* Gouraud r5, g6, b5 in q16 */
    int32_t dc[3];
    const fxl__level_t *lvl; /* nearest (or lower, for LINEAR) level */
    const fxl__level_t *lvl2;/* the next level for FXL_MIP_LINEAR, else NULL */
    uint32_t u2, v2;         /* coordinates on lvl2 */
    int32_t du2, dv2;
    uint32_t lod_frac_q8;    /* weight of lvl2, 0..255 */
    int32_t lod_q8;          /* LOD used for this segment (after bias, clamp), q8 */
} fxl__seg_t;

/* Coordinate at pixel i of a segment that starts at c with step d growing
 * by dd a pixel: c + i d + i (i - 1) / 2 dd, modulo 2^32 (the span loops
 * step c += d, d += dd). For probes and the clipped start of a segment. */
static inline uint32_t fxl__seg_coord(uint32_t c, int32_t d, int32_t dd, int32_t i)
{
    const uint32_t ui = (uint32_t)i;
    const uint32_t tri_i = ui & 1u ? ui * ((ui - 1u) >> 1) : (ui >> 1) * (ui - 1u);
    return c + (uint32_t)d * ui + (uint32_t)dd * tri_i;
}

/* Span loops (span.c). Each returns the number of pixels written. */
typedef uint32_t (*fxl__seg_fn)(const fxl__tri_t *tri, const fxl__seg_t *seg);
/* after fxl__span_setup */
fxl__seg_fn fxl__pick_seg_fn(const fxl__tri_t *tri);
/* The specialised walk (its variant's number, 1..16) that draws with d on
 * this target, or 0 where only the generic walk can: RGB565 texture,
 * repeat on both axes, no key, REPLACE, level 0 of at most 2^16 texels,
 * depth unused or tested and written, and the variant built (FXL_FAST_*).
 * From the settings alone, so check_build refuses from it before any
 * vertex is read (builds without the generic walk). mip_linear: two levels
 * blended (per triangle). */
int fxl__fast_id(const fxl_target_t *target, const fxl_draw_t *d, int mip_linear);

/* fxl_draw_triangle with the span loop replaced by `probe` when non-NULL:
 * the measuring hook of the tests and the benchmark (they read the exact
 * u, v every pixel receives). Not part of the public API. */
fxl_status_t fxl__draw_triangle_with(fxl_target_t *target, const fxl_draw_t *draw, const fxl_vertex_t v[3],
                                     fxl_stats_t *stats, fxl__seg_fn probe);
/* fxl__draw_triangle_with for settings that passed fxl_draw_check(target,
 * draw) and have not changed since (v non-NULL): the core's batch calls
 * (fxl_draw_indexed, fxl_mesh_draw) check them once. The band renderer
 * (port/) keeps to the public fxl_draw_triangle. */
fxl_status_t fxl__draw_valid(fxl_target_t *target, const fxl_draw_t *draw, const fxl_vertex_t v[3],
                             fxl_stats_t *stats, fxl__seg_fn probe);

/* Setup (setup.c): planes and per-triangle scaling of a triangle with
 * det != 0 (the caller culls zero area). Returns FXL_OK. */
fxl_status_t fxl__setup(fxl__tri_t *tri, const fxl_vertex_t v[3], const int32_t X[3],
                        const int32_t Y[3], int64_t det);
int64_t fxl__plane_at(const fxl__plane_t *p, int32_t X0, int32_t Y0, int32_t X, int32_t Y);


/* Edges (edge.c). */
void fxl__edge_init(fxl__edge_t *e, int32_t Xa, int32_t Ya, int32_t Xb, int32_t Yb, int32_t row);
/* One row down: num grows by ONE * dx = step * den + rem a row. Inline
 * (twice a row in fxl__draw_valid) where speed counts: as a call it was
 * ~12 x86-64 instructions a row and edge, half of them the call's. Size
 * builds keep one copy (edge.c): inline it cost the Cortex-M4 -Os core
 * 24 B. */
static inline void fxl__edge_next(fxl__edge_t *e)
{
    e->x += e->step;
    e->err -= e->rem;
    if (e->err < 0) {
        e->x += 1;
        e->err += e->den;
    }
}
#if defined(__OPTIMIZE_SIZE__)
void fxl__edge_step(fxl__edge_t *e);
#else
#define fxl__edge_step(e) fxl__edge_next(e)
#endif

/* FXL_PERSP_AUTO (auto.c). Before set-up, fxl__auto_vertices stores
 * tri->auto_duv and, unless the triangle has Gouraud colours, sets
 * tri->affine where the vertex bound proves it within the draw's
 * auto_budget drawn affine (tri has a texture, draw and tex set; xrange
 * the snapped vertices' X range, subpx); otherwise auto_w and auto_cap. Then
 * fxl__auto_setup (auto.h), after fxl__setup, sets seg_log2 (0..8) when
 * one length suits the whole triangle (with auto_quad and auto_seg 2 when
 * it is quadratic), else auto_seg 1 and the per-row terms of auto.h;
 * fxl__auto_bound is its part that computes the bound (auto_cap >= 2;
 * Y the snapped vertices' rows). */
void fxl__auto_vertices(fxl__tri_t *tri, const fxl_vertex_t v[3], uint32_t xrange);
void fxl__auto_bound(fxl__tri_t *tri, const int32_t Y[3]);

/* Per-triangle preparation of the span walk (span.c), after fxl__setup. */
void fxl__span_setup(fxl__tri_t *tri);

/* Rows (span.c): draw the span [xl, xr) of frame row `row` clipped to
 * [cl, cr), where xl <= cl < cr <= xr (anything else draws nothing), with
 * the generic walk and seg function fn; the specialised walks are reached
 * through fxl__pick_span_fn below. */
void fxl__draw_span(const fxl__tri_t *tri, fxl__seg_fn fn, int32_t row, int32_t xl, int32_t xr,
                    int32_t cl, int32_t cr);

/* The specialised span walks (one per variant, the pixel loop inlined) are
 * what makes the fast path fast, and most of the code at -O2 (with their
 * pixel loops ~180 KB of Cortex-M4 Thumb code for all sixteen; config.h's
 * FXL_FAST_* leave variants out).
 * Size-optimised builds (-Os) keep only the pixel loops, reached through
 * the generic walk and the seg functions, as small as before; the output is
 * the same bit for bit either way. Override with -DFXL__FAST_SPANS=0/1. */
#ifndef FXL__FAST_SPANS
#if defined(__OPTIMIZE_SIZE__)
#define FXL__FAST_SPANS 0
#else
#define FXL__FAST_SPANS 1
#endif
#endif

/* The specialised walk for every span of tri with seg function fn (after
 * fxl__span_setup), or NULL: then fxl__draw_span's generic walk serves.
 * Chosen once a triangle, so no span pays a dispatch; it requires
 * xl <= cl < cr <= xr, which the caller must guarantee. Sets the walk's
 * tri->lean_next. Built with FXL__FAST_SPANS only. */
typedef void (*fxl__span_fn)(const fxl__tri_t *tri, int32_t row, int32_t xl, int32_t xr, int32_t cl, int32_t cr);
fxl__span_fn fxl__pick_span_fn(fxl__tri_t *tri, fxl__seg_fn fn);

/* log2 of x > 0 in q8 (8 fraction bits), error < 2^-8 + table error. */
int32_t fxl__log2_q8(uint64_t x);
/* its table: round(256 log2(1 + i / 256)), i = 0..255 (persp.c) */
extern const uint8_t fxl__log2_frac_q8[256];
/* The same values computed (persp.c; test_fixed checks all 256): nine
 * squarings where the table is 256 bytes. Size-optimised builds use it,
 * the others the table (a load where this is ~50 Cortex-M4
 * instructions). */
uint32_t fxl__log2_frac_q8_calc(uint32_t i);
#if defined(__OPTIMIZE_SIZE__)
#define FXL__LOG2_FRAC_Q8(i) fxl__log2_frac_q8_calc(i)
#else
#define FXL__LOG2_FRAC_Q8(i) fxl__log2_frac_q8[i]
#endif

#endif

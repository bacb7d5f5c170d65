/* fixel/raster.h - drawing screen-space triangles into a target.
 *
 * Conventions (the reference renderer and the tests use the same ones):
 * - Positions are frame pixels in q16. Pixel (i, j) has its centre at
 *   (i + 0.5, j + 0.5). Each position is first snapped to the sub-pixel grid
 *   (1 / 2^FXL_SUBPIXEL_BITS px) by rounding to nearest, ties toward +inf:
 *   fxl_snap_subpx() gives the snapped value in grid units.
 * - Coverage is exactly the top-left rule on the snapped vertices: a pixel is
 *   drawn when its centre is strictly inside, or on a left or top edge. Either
 *   winding is accepted. A mesh whose triangles share snapped edges has every
 *   covered pixel drawn exactly once.
 * - inv_w is proportional to 1/w (u0.32: any positive uint32, larger is
 *   nearer). Interpolation only uses ratios of inv_w within a triangle; the
 *   depth buffer stores inv_w >> 16, so keep one scale per frame (the front
 *   end uses near/w * 2^32, clamped to [1, 2^32 - 1]). inv_w == 0 is
 *   FXL_ERR_RANGE. What a pixel stores is its interpolated inv_w >> 16,
 *   floored, from a plane that keeps 2^-20 of a unit and is stepped
 *   between correction points like u and v: it can be one step off the
 *   exact value's, even at a vertex: one whose inv_w is a multiple of 2^16
 *   can store one less (below every vertex's inv_w >> 16 when it is the
 *   farthest). Against a depth buffer cleared to 0 a pixel passes the test
 *   for certain when its inv_w is 2^17 or more.
 * - u, v are normalised texture coordinates in q16 (65536 = one texture
 *   side), any int32 value. They are interpolated perspective-correctly:
 *   1/w, u/w, v/w are planes in screen space; u = (u/w) / (1/w) is exact at
 *   every `persp`-th pixel of a span and stepped linearly between. "Exact"
 *   to the planes' precision: u/w and v/w keep 30-bit mantissas of their
 *   largest vertex value, so a point at depth q errs by up to
 *   3.2 * 2^-30 * max_i(|u_i| q_i) / q texels per axis (u_i rebased by whole
 *   periods, in texels), plus 2^-27 |u| and 2^-17: about 3.2 * 2^-30 U R for
 *   U texels of range across a triangle and a depth ratio R (measured 0.15
 *   to 0.55 of it). 1/64 texel needs U R below ~10^7: split triangles that
 *   span many periods far into the distance. The planes start from the
 *   vertex with the smallest inv_w (ties: smallest y, then x), so a
 *   triangle draws the same pixels in any vertex order; their gradients
 *   (2^-20 of a unit a sub-pixel) drift with the distance D = |x - x_f| +
 *   |y - y_f| in pixels from that vertex, which adds up to
 *   2^(FXL_SUBPIXEL_BITS - 51) D (max_i |u_i| q_max + 2 max_i(|u_i| q_i)) / q:
 *   nothing at the far vertex, where q is smallest (a far edge 60,000 px
 *   long across the target with R = 10^4 and U = 6.4 10^5 texels: 0.00075
 *   texel measured in all, where this term allows up to 1.97). When a
 *   vertex has inv_w of
 *   2^31 or more every vertex's inv_w is halved (truncated) to fit 31 bits,
 *   which adds up to 2 U / q texels at a point of interpolated inv_w q (U:
 *   the triangle's range of u in texels): within 1/64 texel where q is
 *   above 128 U. A triangle with a clamp or
 *   border vertex coordinate 32767 texels (of level 0) or more from 0 is
 *   divided at every pixel whatever `persp` says: such coordinates
 *   saturate, and cannot be stepped between. So is a needle: a sliver so
 *   thin that some attribute plane changes by 2^38 of its units a
 *   sub-pixel (2^(42 - FXL_SUBPIXEL_BITS) at 5 and 6 bits: 2^42 a pixel at
 *   most; its whole range within ~2^-11 px across), whose gradients
 *   are held modulo 2^64 - exact values, but no size for segment bounds
 *   or the per-segment LOD to read; it takes FXL_LOD_TRIANGLE's LOD.
 * - Accepted ranges: any int32 x, y (so |x|, |y| < 32768 px), inv_w >= 1,
 *   any u, v. Values outside never cause undefined behaviour: planes are
 *   evaluated in 64-bit modular arithmetic. A Gouraud channel is clamped to
 *   its three vertex values (one colour draws exactly that colour); other
 *   values are saturated to their format (depth to 0 .. 2^32 - 1, clamp and
 *   border coordinates to int32; repeat and mirror coordinates wrap), not
 *   to the vertex range, which rounding can leave by a step.
 */
#ifndef FIXEL_RASTER_H
#define FIXEL_RASTER_H

#include <stdint.h>
#include "fixel/config.h"
#include "fixel/status.h"
#include "fixel/fixed.h"
#include "fixel/target.h"
#include "fixel/texture.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct fxl_vertex {
    fxl_q16_t x, y;    /* frame position, pixels, q16 */
    uint32_t inv_w;    /* proportional to 1/w, u0.32, > 0 */
    fxl_q16_t u, v;    /* normalised texture coordinates, q16 */
    uint16_t color;    /* native RGB565, used by FXL_SHADE_GOURAUD */
} fxl_vertex_t;

/* persp: distance in pixels between exact divisions. */
#define FXL_PERSP_AFFINE 0    /* u, v linear in screen space (no correction) */
#define FXL_PERSP_EXACT 1     /* divide at every pixel */
#define FXL_PERSP_AUTO (-1)   /* longest power-of-two segment within auto_budget */
#define FXL_PERSP_MAX 256

typedef enum fxl_filter {
    FXL_FILTER_POINT = 0,     /* nearest texel */
    FXL_FILTER_BILINEAR = 1   /* 2x2 texels, 5-bit weights, texel centres at +0.5 */
} fxl_filter_t;

typedef enum fxl_mipmode {
    FXL_MIP_NONE = 0,         /* always level 0 (the only mode without FXL_HAVE_MIPMAP
                                 for a texture of more than one level) */
    FXL_MIP_NEAREST = 1,      /* nearest level (point or bilinear on it) */
    FXL_MIP_LINEAR = 2        /* blend two levels by the LOD fraction (trilinear
                                 with FXL_FILTER_BILINEAR, point-mip-linear with
                                 FXL_FILTER_POINT) */
} fxl_mipmode_t;

typedef enum fxl_lodmode {
    FXL_LOD_SEGMENT = 0,      /* at every correction point, from the derivatives
                               * (S_g - u q_g) / q of its u, v: their error e
                               * (exact mode's, above) moves them by up to
                               * e |q_g| / q, which at the far end of a depth
                               * ratio near 10^9 can reach any level */
    FXL_LOD_TRIANGLE = 1      /* once per triangle: log4(texel area / pixel area), the
                               * geometric mean of the two scales: too fine a level
                               * where the mapping is stretched one way, level 0 where
                               * u, v are collinear (no texel area: a 1 x N texture);
                               * take FXL_LOD_SEGMENT there */
} fxl_lodmode_t;

typedef enum fxl_texenv {
    FXL_TEXENV_REPLACE = 0,   /* texel */
    FXL_TEXENV_MODULATE = 1,  /* texel * colour, per channel: (t * (c + 1)) >> bits */
    FXL_TEXENV_DECAL = 2      /* colour where the texel is keyed, else texel */
} fxl_texenv_t;

typedef enum fxl_shade {
    FXL_SHADE_FLAT = 0,       /* colour = fxl_draw_t.color */
    FXL_SHADE_GOURAUD = 1     /* colour interpolated (perspective-correct) from vertices */
} fxl_shade_t;

#define FXL_DEPTH_TEST 0x01u  /* draw only where inv_w >> 16 > stored depth */
#define FXL_DEPTH_WRITE 0x02u /* store inv_w >> 16 where drawn */

/* Per-draw state. Start from fxl_draw_defaults(); all fields are plain data. */
typedef struct fxl_draw {
    const fxl_texture_t *texture; /* NULL: untextured, colour only */
    int16_t persp;                /* FXL_PERSP_* or a power of two 2..256 */
    uint8_t filter;               /* fxl_filter_t */
    uint8_t mip;                  /* fxl_mipmode_t */
    uint8_t lod;                  /* fxl_lodmode_t */
    uint8_t texenv;               /* fxl_texenv_t */
    uint8_t shade;                /* fxl_shade_t */
    uint8_t depth;                /* FXL_DEPTH_* bits; ignored without a depth buffer */
    uint16_t color;               /* flat colour, native RGB565 */
    int16_t lod_bias_q8;          /* added to the LOD, 1/256 level units (any int16; the
                                   * level is then clamped to the chain) */
    fxl_q16_t auto_budget;        /* FXL_PERSP_AUTO: max texel error, q16; > 0, else
                                   * FXL_ERR_RANGE; budgets above 256 texels act as 256.
                                   * Level-0 texels, on top of exact mode's own error;
                                   * on mip level n a segment's q16 steps of that level
                                   * may drift by up to L 2^(n-16) more (L 2^-16 of the
                                   * level's own texels). It bounds texture
                                   * coordinates only: Gouraud colours are stepped
                                   * on the segments it picks, an untextured draw
                                   * uses FXL_PERSP_SPAN segments, and a triangle
                                   * it draws affine (its vertex test) takes a
                                   * per-segment LOD from that affine map */
} fxl_draw_t;

/* Counters a draw adds to (pass NULL when not wanted). */
typedef struct fxl_stats {
    uint32_t triangles;           /* submitted */
    uint32_t drawn;               /* reached the span loops (a sliver between
                                   * pixel centres may write none) */
    uint32_t culled_degenerate;   /* zero area after snapping */
    uint32_t culled_outside;      /* its bounding box, taken half-open ([min,
                                   * max) on each axis, the pixels the top-left
                                   * rule can reach), holds no pixel centre of
                                   * the clip rectangle */
    uint32_t culled_backface;     /* by the front end */
    uint32_t pixels;              /* pixels written */
    uint32_t spans;               /* non-empty clipped spans */
    uint32_t divisions;           /* correction points: the span starts and
                                   * segment ends where u, v are computed exactly
                                   * (an affine draw counts its span ends too; a
                                   * correction that reuses the row's 1/q counts;
                                   * a one-pixel segment that ends the span, or
                                   * its clipped part, is one point: exact mode
                                   * counts one a pixel). The same count in every
                                   * build and walk; it counts points, not the
                                   * divisions made: the batch walk of mipmapped
                                   * draws in speed builds divides at a one-pixel
                                   * end twice and past a clipped one once more,
                                   * and counts one point for each) */
    uint32_t generic;             /* of drawn: by the generic span walk, the kinds of draw
                                   * with no specialised code (other texel formats and
                                   * wraps, key, modulate, Gouraud; those config.h's
                                   * FXL_FAST_* leave out; every draw of an -Os build) */
} fxl_stats_t;

/* Subdivided 16 (FXL_PERSP_SPAN), point filter, nearest mip, per-segment LOD,
 * replace, flat white, depth test + write, budget 1/4 texel. */
void fxl_draw_defaults(fxl_draw_t *d);

/* Snap a q16 position to the sub-pixel grid; result in grid units
 * (x * 2^FXL_SUBPIXEL_BITS, rounded to nearest, ties toward +inf). */
int32_t fxl_snap_subpx(fxl_q16_t x);

/* Draw one triangle. Errors: FXL_ERR_ARG (NULL target/draw/vertices/pixels,
 * unknown enum, a target whose fields were edited out of range or whose
 * pixel or depth pointer was edited to an odd address), FXL_ERR_RANGE
 * (inv_w == 0, persp not allowed, bad budget), FXL_ERR_UNSUPPORTED (a feature
 * compiled out by config.h), or whatever fxl_texture_validate() returns for
 * an invalid texture. Nothing is drawn on error. Degenerate and off-clip
 * triangles return FXL_OK and are counted; the errors that do not depend on
 * the vertices (fxl_draw_check) are returned for them too. */
fxl_status_t fxl_draw_triangle(fxl_target_t *target, const fxl_draw_t *draw,
                               const fxl_vertex_t v[3], fxl_stats_t *stats);

/* The status every fxl_draw_triangle with this target and these settings
 * gets before its vertices are read: FXL_OK, or the error (FXL_ERR_ARG,
 * FXL_ERR_UNSUPPORTED, ...) each such triangle returns. Call it once at
 * start-up to learn whether this build draws what a scene asks for:
 * FXL_ERR_UNSUPPORTED means a feature config.h left out (bilinear,
 * FXL_PERSP_AUTO, mip selection on a chain of levels, a depth buffer), or,
 * without FXL_HAVE_GENERIC, a draw no specialised walk serves (see there). */
fxl_status_t fxl_draw_check(const fxl_target_t *target, const fxl_draw_t *draw);

/* Draw an indexed list: `count` triangles from idx[3*i .. 3*i+2] into verts.
 * Stops at the first error (which is returned); out-of-range indices are
 * FXL_ERR_RANGE. The target and settings are checked first, as
 * fxl_draw_check does, also for an empty list (count 0, idx may be NULL). */
fxl_status_t fxl_draw_indexed(fxl_target_t *target, const fxl_draw_t *draw,
                              const fxl_vertex_t *verts, uint32_t vert_count,
                              const uint16_t *idx, uint32_t count, fxl_stats_t *stats);

/* Texture LOD of a whole triangle as in FXL_LOD_TRIANGLE, q8 levels (LOD =
 * log4(texel area / pixel area), texel area counted at level 0), clamped to
 * [-128 * 256, 255 * 256]; 0 without FXL_HAVE_MIPMAP. Within 2/256 level
 * of the exact log4 (its two q8 logarithms) while the vertices' u and v
 * differ by less than 2^31 q16 units (32768 periods); beyond, the
 * differences are halved (from v[0]), and a triangle that is a sliver in
 * texture space loses the precision of its area; there another vertex
 * order can differ by 1/256 level: a draw passes the order set-up uses
 * (the smallest inv_w first, see above). Exposed for tests and tools. */
int32_t fxl_lod_triangle_q8(const fxl_texture_t *t, const fxl_vertex_t v[3]);

#ifdef __cplusplus
}
#endif
#endif

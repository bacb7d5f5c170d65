/* raster.c - the public draw calls: validation, snapping, the row walk.
 *
 * Order of work per triangle: validate (every build: the target struct is
 * plain data the caller may have edited, so the clip rectangle is checked
 * against the buffer again; the batch calls, once a list), snap, cull, set
 * up planes (setup.c), walk rows with exact edges (edge.c), hand each
 * clipped span to span.c.
 */
#include <stddef.h>
#include "raster_int.h"
#include "persp.h"
#include "auto.h"
#include "align.h"
#include "texel.h"

void fxl_draw_defaults(fxl_draw_t *d)
{
    if (!d)
        return;
    d->texture = 0;
    d->persp = FXL_PERSP_SPAN;
    d->filter = FXL_FILTER_POINT;
    d->mip = FXL_MIP_NEAREST;
    d->lod = FXL_LOD_SEGMENT;
    d->texenv = FXL_TEXENV_REPLACE;
    d->shade = FXL_SHADE_FLAT;
    d->depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
    d->color = 0xFFFFu;
    d->lod_bias_q8 = 0;
    d->auto_budget = FXL_Q16_ONE / 4;
}

int32_t fxl_snap_subpx(fxl_q16_t x)
{
    /* floor((x + half grid step) / grid step); int64 so INT32_MAX cannot wrap. */
    return (int32_t)fxl__asr64((int64_t)x + ((int64_t)1 << (15 - FXL__S)), 16 - FXL__S);
}

static int is_pow2_persp(int32_t p)
{
    return p >= 2 && p <= FXL_PERSP_MAX && (p & (p - 1)) == 0;
}

static fxl_status_t check_draw(const fxl_draw_t *d)
{
    if (d->filter > FXL_FILTER_BILINEAR || d->mip > FXL_MIP_LINEAR || d->lod > FXL_LOD_TRIANGLE ||
        d->texenv > FXL_TEXENV_DECAL || d->shade > FXL_SHADE_GOURAUD)
        return FXL_ERR_ARG;
    if (d->persp != FXL_PERSP_AFFINE && d->persp != FXL_PERSP_EXACT && d->persp != FXL_PERSP_AUTO &&
        !is_pow2_persp(d->persp))
        return FXL_ERR_RANGE;
    if (d->persp == FXL_PERSP_AUTO && d->auto_budget <= 0)
        return FXL_ERR_RANGE;
#if !FXL_HAVE_AUTO
    if (d->persp == FXL_PERSP_AUTO)
        return FXL_ERR_UNSUPPORTED;
#endif
#if !FXL_HAVE_BILINEAR
    if (d->filter == FXL_FILTER_BILINEAR)
        return FXL_ERR_UNSUPPORTED;
#endif
#if !FXL_HAVE_GENERIC
    if (d->texenv != FXL_TEXENV_REPLACE || d->shade != FXL_SHADE_FLAT || !d->texture)
        return FXL_ERR_UNSUPPORTED;
#endif
    if (d->texture) {
        fxl_status_t st = fxl_texture_validate(d->texture);
        if (st != FXL_OK)
            return st;
#if !FXL_HAVE_MIPMAP
        /* Level selection is compiled out: a draw that asks for it on a
         * chain of levels is refused rather than drawn from level 0 alone
         * (silently aliased). A one-level texture needs none. */
        if (d->mip != FXL_MIP_NONE && d->texture->levels > 1u)
            return FXL_ERR_UNSUPPORTED;
#endif
    }
    return FXL_OK;
}

/* What this build can draw, from the target and the draw settings alone
 * (after check_target and check_draw): every triangle drawn with them gets
 * the same answer, culled ones included. */
static fxl_status_t check_build(const fxl_target_t *t, const fxl_draw_t *d)
{
#if !FXL_HAVE_DEPTH
    /* fxl_target_set_depth refuses a buffer; this one was put in the struct */
    if (t->depth && (d->depth & (FXL_DEPTH_TEST | FXL_DEPTH_WRITE)))
        return FXL_ERR_UNSUPPORTED;
#endif
#if !FXL_HAVE_GENERIC
    /* no generic walk: a draw needs its specialised one (RGB565, repeat, no
     * key, FXL_FAST_*, depth test and write together, level 0 of at most
     * 2^16 texels) */
    if (!fxl__fast_id(t, d, 0))   /* mip-linear draws need FXL_HAVE_MIPMAP */
        return FXL_ERR_UNSUPPORTED;
#endif
    (void)t;
    (void)d;
    return FXL_OK;
}

static fxl_status_t check_target(const fxl_target_t *t)
{
    const fxl_rect_t *c = &t->clip;
    if (!t->pixels || t->width < 1 || t->height < 1 || t->width > FXL_TARGET_MAX_DIM ||
        t->height > FXL_TARGET_MAX_DIM || t->stride < t->width || t->stride > FXL_TARGET_MAX_DIM * 4 ||
        t->origin_x < -FXL_TARGET_MAX_ORIGIN || t->origin_x > FXL_TARGET_MAX_ORIGIN ||
        t->origin_y < -FXL_TARGET_MAX_ORIGIN || t->origin_y > FXL_TARGET_MAX_ORIGIN ||
        (t->format != FXL_PIXFMT_RGB565 && t->format != FXL_PIXFMT_RGB565_SWAP))
        return FXL_ERR_ARG;
    /* fxl_target_init and _set_depth refuse odd buffers; one moved there by
     * hand would make every uint16_t store misaligned (a HardFault on a
     * Cortex-M0+, undefined behaviour in C): refused here too. */
    if (!fxl__aligned(t->pixels, 2u) || !fxl__aligned(t->depth, 2u))
        return FXL_ERR_ARG;
    /* The clip must lie inside the buffer: this is what makes stray writes
     * impossible whatever the caller did to the struct. */
    if (c->x0 < t->origin_x || c->y0 < t->origin_y || c->x1 > t->origin_x + t->width ||
        c->y1 > t->origin_y + t->height)
        return FXL_ERR_ARG;
    return FXL_OK;
}

/* ceil((Y - HALF) / ONE): the first row whose centre is at or below Y. */
static int32_t first_row_at(int32_t Y)
{
    /* floor division by ONE = 2^S: a floor shift (no 64-bit division) */
    return (int32_t)fxl__asr64((int64_t)Y - FXL__HALF + FXL__ONE - 1, FXL__S);
}

static int32_t seg_log2_for(int32_t p)
{
    /* Affine still re-anchors every FXL_PERSP_MAX pixels: q is constant so a
     * correction is just the linear value, but it stops the truncated q16
     * step (< 2^-16 texel per pixel) from accumulating across spans that run
     * thousands of pixels off-screen before reaching the clip rectangle. */
    if (p == FXL_PERSP_AFFINE)
        p = FXL_PERSP_MAX;
    if (p == FXL_PERSP_AUTO)
        p = FXL_PERSP_SPAN;   /* refined per triangle after setup (auto.c) */
    /* a power of two in 1..FXL_PERSP_MAX (check_draw): one CLZ */
    return 31 - fxl__clz32_inline((uint32_t)p);
}

int32_t fxl_lod_triangle_q8(const fxl_texture_t *t, const fxl_vertex_t v[3])
{
#if FXL_HAVE_MIPMAP
    int32_t X[3], Y[3], i, k = 0;
    int64_t d[4], uv, det;
    int32_t l;

    if (!t || !v)
        return 0;
    for (i = 0; i < 3; i++) {
        X[i] = fxl_snap_subpx(v[i].x);
        Y[i] = fxl_snap_subpx(v[i].y);
    }
    det = ((int64_t)X[1] - X[0]) * ((int64_t)Y[2] - Y[0]) - ((int64_t)X[2] - X[0]) * ((int64_t)Y[1] - Y[0]);
    /* u1 - u0, v1 - v0, u2 - u0, v2 - v0 in q16 (|d| < 2^32), halved (floor)
     * only when one reaches 2^31, so each product stays below 2^62: exact
     * otherwise. (Halving always, toward zero, lost up to half a unit a
     * difference: a one-unit v change read as no texel area at all, and
     * a sliver in texture space - large differences, a small cross
     * product - had its LOD off by 0.2 level.) */
    for (i = 0; i < 4; i++) {
        const fxl_vertex_t *p = &v[1 + (i >> 1)];
        d[i] = (i & 1) ? (int64_t)p->v - v[0].v : (int64_t)p->u - v[0].u;
        if (d[i] != fxl__i32_of_bits((uint32_t)(uint64_t)d[i]))   /* outside int32 */
            k = 1;
    }
    for (i = 0; k && i < 4; i++)
        d[i] = fxl__asr64(d[i], 1);
    uv = d[0] * d[3] - d[2] * d[1];
    if (uv < 0)
        uv = -uv;
    if (det < 0)
        det = -det;
    if (uv == 0)
        return -128 * 256;
    if (det == 0)
        return 255 * 256;
    /* texel area = uv * 4^k / 2^32 * 2^(lw + lh); pixel area = det / 2^(2S):
     * log4(ratio) = (log2 uv + 2k - 32 + lw + lh - log2 det + 2S) / 2. */
    l = (fxl__log2_q8((uint64_t)uv) - fxl__log2_q8((uint64_t)det) +
         (2 * k - 32 + (int32_t)t->log2_w + (int32_t)t->log2_h + 2 * FXL__S) * 256) / 2;
    if (l < -128 * 256)
        l = -128 * 256;
    if (l > 255 * 256)
        l = 255 * 256;
    return l;
#else
    (void)t;
    (void)v;
    return 0;
#endif
}

/* Level L of t, `off` bytes into its chain. */
static inline void set_level(fxl__level_t *lv, const fxl_texture_t *t, uint32_t L, uint32_t off)
{
    lv->texels = (const uint8_t *)t->texels + off;
    lv->log2_w = fxl__level_log2(t->log2_w, L);
    lv->log2_h = fxl__level_log2(t->log2_h, L);
    lv->mask_u = (1u << lv->log2_w) - 1u;
    lv->mask_v = (1u << lv->log2_h) - 1u;
}

static void setup_levels(fxl__tri_t *tri, const fxl_vertex_t v[3])
{
    const fxl_texture_t *t = tri->tex;
    const fxl_draw_t *d = tri->draw;
    /* a local count: the compiler folds the loop to level 0 without mips */
    const uint32_t nlevels = FXL_HAVE_MIPMAP && d->mip != FXL_MIP_NONE ? t->levels : 1u;

    tri->nlevels = (uint8_t)nlevels;
    set_level(&tri->level[0], t, 0u, 0u);
    if (nlevels > 1) {
        /* the chain's bytes before level L, fxl_texture_level_offset's sum
         * kept running (it sums the levels before L anew each call) */
        const uint32_t bytes = fxl_texfmt_bytes((fxl_texfmt_t)t->format);
        uint32_t L, off = 0;
        for (L = 1; L < nlevels; L++) {
            const fxl__level_t *prev = &tri->level[L - 1];
            off += (1u << (prev->log2_w + prev->log2_h)) * bytes;
            set_level(&tri->level[L], t, L, off);
        }
    }
    tri->mip_linear = 0;
    tri->lod_per_segment = 0;
    tri->lod_q8_tri = 0;
    tri->lod_max_q8 = ((int32_t)tri->nlevels - 1) * 256;
#if FXL_HAVE_MIPMAP
    if (tri->nlevels > 1) {
        tri->mip_linear = d->mip == FXL_MIP_LINEAR;
        /* (after fxl__setup) a gradient kept modulo 2^64 (raster_int.h,
         * uv_wide) has lost the size the per-segment LOD reads */
        tri->lod_per_segment = d->lod == FXL_LOD_SEGMENT && !(tri->uv_wide & 4u);
        if (!tri->lod_per_segment) {
            int32_t l = fxl_lod_triangle_q8(t, v) + d->lod_bias_q8;
            tri->lod_q8_tri = l < 0 ? 0 : (l > tri->lod_max_q8 ? tri->lod_max_q8 : l);
        }
    }
#else
    (void)v;
#endif
}

fxl_status_t fxl_draw_check(const fxl_target_t *target, const fxl_draw_t *draw)
{
    fxl_status_t st;
    if (!target || !draw)
        return FXL_ERR_ARG;
    st = check_target(target);
    if (st == FXL_OK)
        st = check_draw(draw);
    if (st == FXL_OK)
        st = check_build(target, draw);
    return st;
}

fxl_status_t fxl_draw_triangle(fxl_target_t *target, const fxl_draw_t *draw, const fxl_vertex_t v[3],
                               fxl_stats_t *stats)
{
    return fxl__draw_triangle_with(target, draw, v, stats, 0);
}

fxl_status_t fxl__draw_triangle_with(fxl_target_t *target, const fxl_draw_t *draw, const fxl_vertex_t v[3],
                                     fxl_stats_t *stats, fxl__seg_fn probe)
{
    fxl_status_t st;
    if (!v)
        return FXL_ERR_ARG;
    st = fxl_draw_check(target, draw);
    if (st != FXL_OK)
        return st;
    return fxl__draw_valid(target, draw, v, stats, probe);
}

/* The vertex set-up evaluates the planes from (setup.c, make_plane): the
 * one with the smallest inv_w, the farthest. A plane's gradients are
 * rounded (2^-20 of a unit a sub-pixel), so its value drifts with the
 * distance from that vertex; relative to q the drift is largest where q is
 * smallest, so the far vertex is where it should be nil. From a near vertex
 * 42,000 px off-screen (a floor's near corners after clipping) it cost
 * 0.45 texel at the horizon, against 0.0005 from the far one. Ties go to
 * the smallest y, then x, so a triangle draws the same pixels whichever
 * vertex is given first and in either winding (the rotation keeps the
 * winding; make_plane's gradients do not depend on it). Cost: 82 B of
 * Cortex-M4 -Os core (it left 4 B under 16 KiB then; a pointer walk, as index
 * arithmetic took 46 B more), 64 B of fxl__draw_valid's frame, ~50
 * Cortex-M4 instructions a triangle at -O2 (2,000 small triangles +1%). */
static const fxl_vertex_t *first_vertex(const fxl_vertex_t v[3])
{
    const fxl_vertex_t *best = v, *p;
    for (p = v + 1; p < v + 3; p++)
        if (p->inv_w < best->inv_w ||
            (p->inv_w == best->inv_w && (p->y < best->y || (p->y == best->y && p->x < best->x))))
            best = p;
    return best;
}

fxl_status_t fxl__draw_valid(fxl_target_t *target, const fxl_draw_t *draw, const fxl_vertex_t vin[3],
                             fxl_stats_t *stats, fxl__seg_fn probe)
{
    fxl_vertex_t rot[3];
    const fxl_vertex_t *f = first_vertex(vin), *v = vin;
    fxl__tri_t tri;
    fxl__edge_t el, es;
    fxl__seg_fn fn;
    fxl__span_fn span;   /* the specialised walk of every span, or NULL */
    fxl_status_t st;
    int32_t X[3], Y[3], ord[3], i, t;
    int32_t row_top, row_mid, row_bot, r0, r1, row, minx, maxx;
    int64_t det;
    int mid_left, odd = 0;

    /* set-up's planes start from v[0]: the canonical first vertex. A copy
     * only where it is not vin[0] (18 Cortex-M4 instructions a triangle
     * less on small triangles), except at -Os (the test cost 58 B). */
#if !defined(__OPTIMIZE_SIZE__)
    if (f != vin)
#endif
    {
        for (i = 0; i < 3; i++) {
            rot[i] = *f;
            f = f == vin + 2 ? vin : f + 1;
        }
        v = rot;
    }

    if (v[0].inv_w == 0)   /* the smallest */
        return FXL_ERR_RANGE;
    if (stats)
        stats->triangles++;

    for (i = 0; i < 3; i++) {
        X[i] = fxl_snap_subpx(v[i].x);
        Y[i] = fxl_snap_subpx(v[i].y);
    }
    det = ((int64_t)X[1] - X[0]) * ((int64_t)Y[2] - Y[0]) - ((int64_t)X[2] - X[0]) * ((int64_t)Y[1] - Y[0]);
    if (det == 0) {
        if (stats)
            stats->culled_degenerate++;
        return FXL_OK;
    }

    /* Sort by Y: ord[0] top, ord[1] middle, ord[2] bottom. */
    ord[0] = 0;
    ord[1] = 1;
    ord[2] = 2;
    if (Y[ord[1]] < Y[ord[0]]) { t = ord[0]; ord[0] = ord[1]; ord[1] = t; odd ^= 1; }
    if (Y[ord[2]] < Y[ord[1]]) { t = ord[1]; ord[1] = ord[2]; ord[2] = t; odd ^= 1; }
    if (Y[ord[1]] < Y[ord[0]]) { t = ord[0]; ord[0] = ord[1]; ord[1] = t; odd ^= 1; }

    row_top = first_row_at(Y[ord[0]]);
    row_mid = first_row_at(Y[ord[1]]);
    row_bot = first_row_at(Y[ord[2]]);
    r0 = row_top > target->clip.y0 ? row_top : target->clip.y0;
    r1 = row_bot < target->clip.y1 ? row_bot : target->clip.y1;
    minx = X[0] < X[1] ? (X[0] < X[2] ? X[0] : X[2]) : (X[1] < X[2] ? X[1] : X[2]);
    maxx = X[0] > X[1] ? (X[0] > X[2] ? X[0] : X[2]) : (X[1] > X[2] ? X[1] : X[2]);
    if (r0 >= r1 || target->clip.x0 >= target->clip.x1 ||
        first_row_at(maxx) <= target->clip.x0 || first_row_at(minx) >= target->clip.x1) {
        if (stats)
            stats->culled_outside++;
        return FXL_OK;
    }

    tri.draw = draw;
    tri.tex = draw->texture;
    tri.target = target;
    tri.stats = stats;
    tri.auto_seg = 0;
    tri.auto_quad = 0;
    tri.auto_rr = 0;
    /* set by fxl__auto_vertices unless it settles the triangle as affine;
     * read (clamped) below for every AUTO draw with a gridded LOD */
    tri.auto_cap = FXL__AUTO_CAP_MAX;
    tri.depth_test = (draw->depth & FXL_DEPTH_TEST) != 0;
    tri.depth_write = (draw->depth & FXL_DEPTH_WRITE) != 0;
    tri.swap = target->format == FXL_PIXFMT_RGB565_SWAP;
    tri.has_uv = tri.tex != 0;
    tri.has_color = draw->shade == FXL_SHADE_GOURAUD;
    tri.signed_u = tri.tex && tri.tex->wrap_u >= FXL_WRAP_CLAMP;
    tri.signed_v = tri.tex && tri.tex->wrap_v >= FXL_WRAP_CLAMP;
    tri.affine = draw->persp == FXL_PERSP_AFFINE;
#if FXL_HAVE_AUTO
    /* AUTO: where the vertex bound holds, no division is needed (auto.c).
     * The vertices' texel ranges serve the vertex test and the set-up. */
    if (draw->persp == FXL_PERSP_AUTO && tri.has_uv)
        fxl__auto_vertices(&tri, v, (uint32_t)maxx - (uint32_t)minx);
#endif
    tri.seg_log2 = seg_log2_for(tri.affine ? FXL_PERSP_AFFINE : draw->persp);
    tri.nlevels = 0;
    tri.mip_linear = 0;
    st = fxl__setup(&tri, v, X, Y, det);
    if (st != FXL_OK)
        return st;
    if (tri.tex)
        setup_levels(&tri, v);
#if FXL_HAVE_AUTO
#if FXL_HAVE_MIPMAP
    /* AUTO with a per-segment LOD: segments of at most the LOD grid
     * (auto.h), whatever the coordinates allow. Whole-span segments took
     * one LOD for up to 256 pixels: 0.84 level off the exact one at the
     * floor's span ends, where the bound is 0.25. */
    const int lod_cap = tri.has_uv && FXL__AUTO_LOD_GRIDDED(draw, &tri);
    if (lod_cap && tri.auto_cap > FXL__AUTO_LOD_LOG2)
        tri.auto_cap = FXL__AUTO_LOD_LOG2;
#endif
    if (draw->persp == FXL_PERSP_AUTO && tri.has_uv && !tri.affine)
        fxl__auto_setup(&tri, Y);
#if FXL_HAVE_MIPMAP
    if (lod_cap && tri.seg_log2 > FXL__AUTO_LOD_LOG2)
        tri.seg_log2 = FXL__AUTO_LOD_LOG2;   /* the affine and q_x = 0 cases */
#endif
#endif
    /* A clamp/border coordinate saturates far outside (span.c): stepped
     * towards a saturated end, it would cross the texture too late. Rare
     * (|u| of 2^15 texels at a vertex), so such a triangle divides at
     * every pixel, in every mode; so does one whose gradients' size is
     * lost (uv_wide bit 2), which the segment bounds read. */
    if (tri.uv_wide & (FXL_HAVE_GENERIC ? 6u : 4u)) {
        tri.seg_log2 = 0;
        tri.auto_seg = 0;
    }
    fxl__span_setup(&tri);
    fn = probe ? probe : fxl__pick_seg_fn(&tri);
    if (!fn)   /* check_build refused these already; kept against a NULL call */
        return FXL_ERR_UNSUPPORTED;
#if FXL__FAST_SPANS
    span = fxl__pick_span_fn(&tri, fn);
#else
    span = 0;   /* -Os: the generic walk only */
#endif
    if (stats) {
        stats->drawn++;
        stats->generic += span == 0;
    }

    /* Which side the middle vertex is on, from the long edge top -> bottom:
     * the sign of the sorted vertices' determinant, which is det's sign
     * flipped once per swap of the sort. */
    mid_left = (det < 0) != odd;

    fxl__edge_init(&el, X[ord[0]], Y[ord[0]], X[ord[2]], Y[ord[2]], r0);
    if (r0 < row_mid)
        fxl__edge_init(&es, X[ord[0]], Y[ord[0]], X[ord[1]], Y[ord[1]], r0);
    else
        fxl__edge_init(&es, X[ord[1]], Y[ord[1]], X[ord[2]], Y[ord[2]], r0);

    for (row = r0; row < r1; row++) {
        int32_t xl, xr, cl, cr;
        if (row == row_mid && row != r0)
            fxl__edge_init(&es, X[ord[1]], Y[ord[1]], X[ord[2]], Y[ord[2]], row);
        xl = mid_left ? es.x : el.x;
        xr = mid_left ? el.x : es.x;
        cl = xl > target->clip.x0 ? xl : target->clip.x0;
        cr = xr < target->clip.x1 ? xr : target->clip.x1;
        /* xl <= cl < cr <= xr by construction, as the walks require */
        if (cl < cr) {
            if (span)
                span(&tri, row, xl, xr, cl, cr);
            else
                fxl__draw_span(&tri, fn, row, xl, xr, cl, cr);
        }
        fxl__edge_step(&el);
        fxl__edge_step(&es);
    }
    return FXL_OK;
}

fxl_status_t fxl_draw_indexed(fxl_target_t *target, const fxl_draw_t *draw, const fxl_vertex_t *verts,
                              uint32_t vert_count, const uint16_t *idx, uint32_t count, fxl_stats_t *stats)
{
    uint32_t i;
    fxl_status_t st;
    if (!target || !draw || !verts || (!idx && count))
        return FXL_ERR_ARG;
    /* the settings once: every triangle of the list would get the same
     * answer (~120 Cortex-M4 instructions a triangle); checked for an empty
     * list too, as fxl_draw_triangle checks them for a culled triangle */
    st = fxl_draw_check(target, draw);
    if (st != FXL_OK || count == 0)
        return st;
    for (i = 0; i < count; i++) {
        fxl_vertex_t tv[3];
        int k;
        for (k = 0; k < 3; k++) {
            /* size_t: 3 i wraps 32 bits past 1.4 x 10^9 triangles */
            uint16_t ix = idx[(size_t)3 * i + (size_t)k];
            if (ix >= vert_count)
                return FXL_ERR_RANGE;
            tv[k] = verts[ix];
        }
        st = fxl__draw_valid(target, draw, tv, stats, 0);
        if (st != FXL_OK)
            return st;
    }
    return FXL_OK;
}

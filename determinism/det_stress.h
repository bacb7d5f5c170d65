/* det_stress.h - the determinism check's stress cases: random triangles with
 * inputs at and past every documented limit, drawn by every build.
 *
 * The gallery frames (det_entries.h) show that ordinary scenes come out bit
 * for bit the same on every compiler and core. The paths that differ most
 * between builds are the rare ones: 32-bit shortcuts for large shifts,
 * saturating coordinates, uv_wide and needle triangles, the generic walk of
 * size-optimised builds, error statuses. These cases reach them on purpose:
 * vertices at INT32 limits, far outside and a sub-pixel apart, 1/w from 1
 * to 2^32 - 1 (0 and past 2^31 - 1 refused), texture coordinates up to
 * 2^31, every persp mode (AUTO with
 * budgets from 1 q16 up), filter, mip and LOD mode, wrap, format, texture
 * environment, shading, depth mode, target format, origin, stride and clip.
 * Each build must produce the same status, counters, pixels and depth;
 * determinism.sh compares the lines det_main.c prints, and
 * tests/test_determinism.c also checks that no case wrote outside its clip
 * rectangle.
 *
 * Freestanding and integer only, like the core: a xorshift32 generator, and
 * a rotate-add hash instead of a CRC (a bitwise CRC of every case's buffers
 * was most of the run time on qemu's Cortex-M0+ and RV32I, which multiply
 * through libgcc). The caller owns every buffer.
 */
#ifndef FXL_DET_STRESS_H
#define FXL_DET_STRESS_H

#include <stdint.h>

#include "fixel/fixel.h"

#define DET_STRESS_CASES 16000   /* cases in the list */
#define DET_STRESS_LINE 1000     /* cases a printed line */
#define DET_STRESS_MAX_W 96      /* target width, height and stride at most */
#define DET_STRESS_MAX_H 64
#define DET_STRESS_MAX_STRIDE 112
#define DET_STRESS_BUF (DET_STRESS_MAX_STRIDE * DET_STRESS_MAX_H) /* uint16_t each buffer */
#define DET_STRESS_CANARY 0xA5C3u /* what the buffers hold before a draw */

/* Procedural textures with full mip chains: RGB565 64 x 32, L8 32 x 8,
 * I8 16 x 16 with its palette (levels: 7, 6, 5; texels 2,731, 343, 341). */
typedef struct det_stress_assets {
    uint16_t rgb[2731];
    uint8_t l8[343];
    uint8_t i8[341];
    uint16_t palette[256];
} det_stress_assets_t;

/* One case: the target over the caller's buffers, and what to draw. */
typedef struct det_stress_case {
    fxl_target_t tg;
    fxl_texture_t tex;
    fxl_draw_t d;
    fxl_vertex_t v[3];
    uint16_t *pixels, *depth; /* the caller's buffers (tg may refuse them in a reduced build) */
    fxl_rect_t clip;          /* where a draw may write, worked out here, not read off tg:
                               * the buffer's frame rectangle cut by the requested clip */
    int32_t buf_len;          /* elements of each the case uses: stride x height */
    int32_t stride;           /* and its geometry as made: elements a row, */
    int32_t origin_x, origin_y; /* frame position of element 0 */
    int with_depth;           /* the target took the depth buffer */
} det_stress_case_t;

static inline uint32_t det_stress_next(uint32_t *s)
{
    uint32_t x = *s;
    x ^= x << 13;
    x ^= x >> 17;
    x ^= x << 5;
    return *s = x;
}

/* uniform in [0, n), n > 0 (modulo bias does not matter here) */
static inline uint32_t det_stress_below(uint32_t *s, uint32_t n)
{
    return det_stress_next(s) % n;
}

/* log-uniform magnitude: a bit length in [1, bits], then any value of it */
static inline uint32_t det_stress_mag(uint32_t *s, uint32_t bits)
{
    const uint32_t len = 1u + det_stress_below(s, bits);
    const uint32_t top = (uint32_t)1 << (len - 1u);
    return top | (det_stress_next(s) & (top - 1u));
}

/* signed from a magnitude and a coin, without overflow */
static inline int32_t det_stress_signed(uint32_t *s, uint32_t mag)
{
    const uint32_t m = mag > 0x7FFFFFFFu ? 0x7FFFFFFFu : mag;
    return (det_stress_next(s) & 1u) ? -(int32_t)m : (int32_t)m;
}

/* a texel value from its position and level (any fixed function will do) */
static inline uint32_t det_stress_texel(uint32_t x, uint32_t y, uint32_t level)
{
    uint32_t h = x * 0x9E3779B1u ^ (y + 0x51u) * 0x85EBCA77u ^ level * 0xC2B2AE3Du;
    h ^= h >> 15;
    return h ^ ((x ^ y) & 8u ? 0xF81Fu : 0u);
}

static inline void det_stress_assets_init(det_stress_assets_t *a)
{
    uint32_t lv, x, y, n;
    for (lv = 0, n = 0; lv < 7u; lv++)
        for (y = 0; y < (32u >> lv ? 32u >> lv : 1u); y++)
            for (x = 0; x < (64u >> lv); x++)
                a->rgb[n++] = (uint16_t)det_stress_texel(x, y, lv);
    for (lv = 0, n = 0; lv < 6u; lv++)
        for (y = 0; y < (8u >> lv ? 8u >> lv : 1u); y++)
            for (x = 0; x < (32u >> lv); x++)
                a->l8[n++] = (uint8_t)det_stress_texel(x, y, lv);
    for (lv = 0, n = 0; lv < 5u; lv++)
        for (y = 0; y < (16u >> lv); y++)
            for (x = 0; x < (16u >> lv); x++)
                a->i8[n++] = (uint8_t)det_stress_texel(y, x, lv);
    for (n = 0; n < 256u; n++)
        a->palette[n] = (uint16_t)det_stress_texel(n, 7u, 9u);
}

/* A q16 frame coordinate on one axis of the target [o, o + len) */
static inline int32_t det_stress_coord(uint32_t *s, int wild, int32_t o, int32_t len, int32_t prev)
{
    static const int32_t special[] = {INT32_MIN, INT32_MAX, INT32_MIN + 1, 0x40000000, -0x40000000,
                                      0x7FFF0000, -0x7FFF0000, 0};
    switch (det_stress_below(s, wild ? 8u : 4u)) {
    case 4: /* a sliver: next to the previous vertex */
        return (int32_t)((uint32_t)prev + (uint32_t)det_stress_signed(s, det_stress_mag(s, 18u)));
    case 5: /* far, log-uniform up to the q16 limit */
        return det_stress_signed(s, det_stress_mag(s, 31u));
    case 6:
        return special[det_stress_below(s, 8u)];
    default: { /* around the target, 8 px of margin, any sub-pixel position */
        /* one draw a statement: the order of two calls in one expression
         * is unspecified, and would differ between compilers */
        const uint32_t px = (uint32_t)(o - 8) + det_stress_below(s, (uint32_t)len + 16u);
        return (int32_t)((px << 16) | (det_stress_next(s) & 0xFFFFu));
    }
    }
}

static inline uint32_t det_stress_inv_w(uint32_t *s, int wild, uint32_t prev)
{
    static const uint32_t special[] = {0u, 1u, 2u, 0x7FFFFFFFu, 0x80000000u, 0xFFFFFFFFu, 0x10000u, 0xFFFFu};
    switch (wild ? det_stress_below(s, 6u) : 2u + det_stress_below(s, 4u)) {
    case 0:
        return det_stress_mag(s, 31u);
    case 1:
        return special[det_stress_below(s, 8u)];
    case 2:
        return prev; /* the same depth: constant q along an edge or a whole triangle */
    default: { /* ratios up to ~2^8 around a random depth */
        const uint32_t hi = det_stress_mag(s, 16u) << 8;
        return hi | det_stress_below(s, 256u);
    }
    }
}

static inline int32_t det_stress_uv(uint32_t *s, int wild, int32_t prev)
{
    static const int32_t special[] = {INT32_MIN, INT32_MAX, 0, 0xFFFF, -0x10000, 0x7FFF0000, -0x7FFF0000,
                                      0x8000};
    switch (wild ? det_stress_below(s, 6u) : 2u + det_stress_below(s, 4u)) {
    case 0:
        return det_stress_signed(s, det_stress_mag(s, 31u));
    case 1:
        return special[det_stress_below(s, 8u)];
    case 2: /* a narrow range far from 0 */
    case 3:
        return (int32_t)((uint32_t)prev + (uint32_t)det_stress_signed(s, det_stress_mag(s, 22u)));
    default: /* up to 64 texels */
        return det_stress_signed(s, det_stress_below(s, 64u << 16));
    }
}

/* Case k of the list (its own generator state, so any case can be rerun
 * alone): the target over pixels and depth (DET_STRESS_BUF each, all of
 * it filled with DET_STRESS_CANARY, so a write past the case's own rows
 * shows too), and the draw. */
static inline void det_stress_make(uint32_t k, const det_stress_assets_t *a, uint16_t *pixels, uint16_t *depth,
                                   det_stress_case_t *c)
{
    static const int16_t persps[] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, FXL_PERSP_AUTO, FXL_PERSP_AUTO,
                                     2, 4, 8, 16, 16, 32, 64, 256, 3, -2};
    static const int32_t budgets[] = {0, -1, 1, 2, 384, 0x4000, 0x10000, INT32_MAX};
    uint32_t seed = 0x2545F491u ^ (k * 0x9E3779B9u), *s = &seed;
    const int32_t w = 1 + (int32_t)det_stress_below(s, DET_STRESS_MAX_W);
    const int32_t h = 1 + (int32_t)det_stress_below(s, DET_STRESS_MAX_H);
    const int32_t stride = w + (int32_t)det_stress_below(s, (uint32_t)(DET_STRESS_MAX_STRIDE - w) + 1u);
    /* half the cases wild (every class of value), half tame (vertices
     * around the target, moderate depth ratios and texel ranges: mostly
     * drawn, so the modes, filters and formats meet ordinary geometry) */
    const int wild = (int)det_stress_below(s, 2u);
    int32_t i, ox = 0, oy = 0;
    uint32_t t;

    c->pixels = pixels;
    c->depth = depth;
    c->buf_len = stride * h;
    c->stride = stride;
    for (i = 0; i < DET_STRESS_BUF; i++)
        pixels[i] = depth[i] = DET_STRESS_CANARY;
    (void)fxl_target_init(&c->tg, pixels,  w, h, stride,
                          det_stress_below(s, 2u) ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565);
    if (det_stress_below(s, 4u) != 0u) {
        ox = (int32_t)det_stress_below(s, 601u) - 300;
        oy = (int32_t)det_stress_below(s, 601u) - 300;
        (void)fxl_target_set_origin(&c->tg, ox, oy);
    }
    c->origin_x = ox;
    c->origin_y = oy;
    c->clip.x0 = ox;
    c->clip.y0 = oy;
    c->clip.x1 = ox + w;
    c->clip.y1 = oy + h;
    if (det_stress_below(s, 3u) == 0u) {
        fxl_rect_t r;
        r.x0 = ox - 4 + (int32_t)det_stress_below(s, (uint32_t)w + 8u);
        r.y0 = oy - 4 + (int32_t)det_stress_below(s, (uint32_t)h + 8u);
        r.x1 = r.x0 + (int32_t)det_stress_below(s, (uint32_t)w + 8u) - 2;
        r.y1 = r.y0 + (int32_t)det_stress_below(s, (uint32_t)h + 8u) - 2;
        (void)fxl_target_set_clip(&c->tg, &r);
        c->clip.x0 = r.x0 > c->clip.x0 ? r.x0 : c->clip.x0;
        c->clip.y0 = r.y0 > c->clip.y0 ? r.y0 : c->clip.y0;
        c->clip.x1 = r.x1 < c->clip.x1 ? r.x1 : c->clip.x1;
        c->clip.y1 = r.y1 < c->clip.y1 ? r.y1 : c->clip.y1;
    }
    c->with_depth = 0;
    if (det_stress_below(s, 2u) != 0u) {
        /* refused without FXL_HAVE_DEPTH: the case then draws without */
        c->with_depth = fxl_target_set_depth(&c->tg, depth) == FXL_OK;
        if (det_stress_below(s, 2u) && c->with_depth)
            (void)fxl_target_clear_depth(&c->tg);
    }

    fxl_draw_defaults(&c->d);
    c->d.persp = persps[det_stress_below(s, sizeof persps / sizeof persps[0])];
    c->d.filter = (uint8_t)det_stress_below(s, 2u);
    c->d.mip = (uint8_t)det_stress_below(s, 3u);
    c->d.lod = (uint8_t)det_stress_below(s, 2u);
    c->d.texenv = (uint8_t)det_stress_below(s, 3u);
    c->d.shade = (uint8_t)det_stress_below(s, 2u);
    c->d.depth = (uint8_t)det_stress_below(s, 4u);
    c->d.color = (uint16_t)det_stress_next(s);
    c->d.lod_bias_q8 = (int16_t)(det_stress_below(s, 4u) == 0u ? (int32_t)(int16_t)(det_stress_next(s) & 0xFFFFu)
                                                               : (int32_t)det_stress_below(s, 1025u) - 512);
    c->d.auto_budget = det_stress_below(s, 4u) == 0u ? budgets[det_stress_below(s, 8u)]
                                                     : (fxl_q16_t)det_stress_mag(s, 20u);

    t = det_stress_below(s, 8u);
    if (t == 0u) {
        c->d.texture = 0;
    } else {
        static const uint32_t levels_max[3] = {7u, 6u, 5u};
        const uint32_t which = t < 5u ? 0u : t - 5u; /* RGB565 mostly */
        const uint32_t levels = 1u + det_stress_below(s, levels_max[which]);
        if (which == 0u) {
            (void)fxl_texture_init(&c->tex, a->rgb, 64u, 32u, FXL_TEXFMT_RGB565, levels);
            c->tex.key = a->rgb[det_stress_below(s, 64u)];
        } else if (which == 1u) {
            (void)fxl_texture_init(&c->tex, a->l8, 32u, 8u, FXL_TEXFMT_L8, levels);
            c->tex.key = a->l8[det_stress_below(s, 32u)];
        } else {
            (void)fxl_texture_init(&c->tex, a->i8, 16u, 16u, FXL_TEXFMT_I8, levels);
            c->tex.palette = a->palette;
            c->tex.key = a->i8[det_stress_below(s, 16u)];
        }
        c->tex.wrap_u = (uint8_t)det_stress_below(s, 4u);
        c->tex.wrap_v = (uint8_t)det_stress_below(s, 4u);
        c->tex.flags = det_stress_below(s, 4u) == 0u ? FXL_TEXF_KEY : 0u;
        c->tex.border = (uint16_t)det_stress_next(s);
        c->d.texture = &c->tex;
    }

    for (i = 0; i < 3; i++) {
        const fxl_vertex_t *p = &c->v[i ? i - 1 : 0];
        fxl_vertex_t *q = &c->v[i];
        q->x = det_stress_coord(s, wild, ox, w, i ? p->x : 0);
        q->y = det_stress_coord(s, wild, oy, h, i ? p->y : 0);
        q->inv_w = det_stress_inv_w(s, wild, i ? p->inv_w : 0x10000u);
        q->u = det_stress_uv(s, wild, i ? p->u : det_stress_signed(s, det_stress_mag(s, 31u)));
        q->v = det_stress_uv(s, wild, i ? p->v : det_stress_signed(s, det_stress_mag(s, 31u)));
        q->color = (uint16_t)det_stress_next(s);
    }
}

/* Fold v into the running hash h (a rotate and an add: no multiply). */
static inline uint32_t det_stress_fold(uint32_t h, uint32_t v)
{
    return ((h << 7) | (h >> 25)) + (v ^ 0x9E3779B9u);
}

/* Draw case c and fold its status, counters, pixels and (when attached)
 * depth into h. Returns the status through *st. */
static inline uint32_t det_stress_draw(det_stress_case_t *c, uint32_t h, fxl_status_t *st)
{
    fxl_stats_t n = {0};
    int32_t i;
    *st = fxl_draw_triangle(&c->tg, &c->d, c->v, &n);
    h = det_stress_fold(h, (uint32_t)*st);
    h = det_stress_fold(h, n.triangles);
    h = det_stress_fold(h, n.drawn);
    h = det_stress_fold(h, n.culled_degenerate);
    h = det_stress_fold(h, n.culled_outside);
    h = det_stress_fold(h, n.pixels);
    h = det_stress_fold(h, n.spans);
    for (i = 0; i < c->buf_len; i++)
        h = det_stress_fold(h, c->pixels[i]);
    if (c->with_depth)
        for (i = 0; i < c->buf_len; i++)
            h = det_stress_fold(h, c->depth[i]);
    return h;
}

#endif

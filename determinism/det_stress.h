/* det_stress.h - the determinism check's stress cases: random triangles with
 * inputs at and past every documented limit, drawn by every build.
 *
 * The gallery frames (det_entries.h) show that ordinary scenes come out bit
 * for bit the same on every compiler and core. The paths that differ most
 * between builds are the rare ones: 32-bit shortcuts for large shifts,
 * saturating coordinates, uv_wide and needle triangles, the generic walk of
 * size-optimised builds, error statuses. These cases reach them on purpose:
 * vertices at INT32 limits, far outside and a sub-pixel apart, 1/w from 0
 * to 2^32 - 1 (0 and past 2^31 - 1 refused), texture coordinates up to
 * 2^31, every persp mode (AUTO with budgets from 0 up), filter, mip and LOD
 * mode, wrap, format, texture environment, shading, depth mode, target
 * format, origin, stride and clip;
 * then meshes through the front end (fxl_mesh_draw) with any projection,
 * model, viewport, culling, lighting, texgen and vertex cache.
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
    int32_t width, height;    /* and its geometry as made (not read off tg): the size, */
    int32_t stride;           /* elements a row, */
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

/* The target of a case over pixels and depth (DET_STRESS_BUF each, all of
 * it filled with DET_STRESS_CANARY, so a write past the case's own rows
 * shows too): random size, stride, format, origin, clip and depth. */
static inline void det_stress_target(uint32_t *s, uint16_t *pixels, uint16_t *depth, det_stress_case_t *c)
{
    const int32_t w = 1 + (int32_t)det_stress_below(s, DET_STRESS_MAX_W);
    const int32_t h = 1 + (int32_t)det_stress_below(s, DET_STRESS_MAX_H);
    const int32_t stride = w + (int32_t)det_stress_below(s, (uint32_t)(DET_STRESS_MAX_STRIDE - w) + 1u);
    int32_t i, ox = 0, oy = 0;

    c->pixels = pixels;
    c->depth = depth;
    c->buf_len = stride * h;
    c->width = w;
    c->height = h;
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
}

/* The draw settings of a case: every persp, filter, mip, LOD, texture
 * environment, shading and depth mode, and a texture (or none). */
static inline void det_stress_settings(uint32_t *s, const det_stress_assets_t *a, det_stress_case_t *c)
{
    static const int16_t persps[] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, FXL_PERSP_AUTO, FXL_PERSP_AUTO,
                                     2, 4, 8, 16, 16, 32, 64, 256, 3, -2};
    static const int32_t budgets[] = {0, -1, 1, 2, 384, 0x4000, 0x10000, INT32_MAX};
    uint32_t t;

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
}

/* Case k of the triangle list (its own generator state, so any case can
 * be rerun alone): a target, settings and three vertices. Half the cases
 * wild (every class of value), half tame (vertices around the target,
 * moderate depth ratios and texel ranges: mostly drawn, so the modes,
 * filters and formats meet ordinary geometry). */
static inline void det_stress_make(uint32_t k, const det_stress_assets_t *a, uint16_t *pixels, uint16_t *depth,
                                   det_stress_case_t *c)
{
    uint32_t seed = 0x2545F491u ^ (k * 0x9E3779B9u), *s = &seed;
    const int wild = (int)det_stress_below(s, 2u);
    int32_t i;

    det_stress_target(s, pixels, depth, c);
    det_stress_settings(s, a, c);
    for (i = 0; i < 3; i++) {
        const fxl_vertex_t *p = &c->v[i ? i - 1 : 0];
        fxl_vertex_t *q = &c->v[i];
        q->x = det_stress_coord(s, wild, c->origin_x, c->width, i ? p->x : 0);
        q->y = det_stress_coord(s, wild, c->origin_y, c->height, i ? p->y : 0);
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

/* Fold a draw's status, counters, pixels and (when attached) depth into
 * h. The counters are those every build counts alike (not `generic` or
 * `divisions`, which depend on the walk a build has). */
static inline uint32_t det_stress_result(const det_stress_case_t *c, uint32_t h, fxl_status_t st,
                                         const fxl_stats_t *n)
{
    int32_t i;
    h = det_stress_fold(h, (uint32_t)st);
    h = det_stress_fold(h, n->triangles);
    h = det_stress_fold(h, n->drawn);
    h = det_stress_fold(h, n->culled_degenerate);
    h = det_stress_fold(h, n->culled_outside);
    h = det_stress_fold(h, n->culled_backface);
    h = det_stress_fold(h, n->pixels);
    h = det_stress_fold(h, n->spans);
    for (i = 0; i < c->buf_len; i++)
        h = det_stress_fold(h, c->pixels[i]);
    if (c->with_depth)
        for (i = 0; i < c->buf_len; i++)
            h = det_stress_fold(h, c->depth[i]);
    return h;
}

/* Draw triangle case c and fold the result into h; the status in *st. */
static inline uint32_t det_stress_draw(det_stress_case_t *c, uint32_t h, fxl_status_t *st)
{
    fxl_stats_t n = {0};
    *st = fxl_draw_triangle(&c->tg, &c->d, c->v, &n);
    return det_stress_result(c, h, *st, &n);
}

/* ---- front-end cases: meshes through fxl_mesh_draw ------------------------ */

#define DET_STRESS_FE_CASES 4000
#define DET_STRESS_FE_VERTS 12
#define DET_STRESS_FE_TRIS 8

/* A mesh of up to 12 vertices and 8 triangles, the pipeline that draws it
 * (projection, model, viewport, culling, lighting, texgen, vertex cache)
 * and a target and settings as the triangle cases have them. */
typedef struct det_stress_fe_case {
    det_stress_case_t c;
    fxl_pipeline_t pipe;
    fxl_mesh_t mesh;
    fxl_vec3_t pos[DET_STRESS_FE_VERTS], normal[DET_STRESS_FE_VERTS];
    fxl_texcoord_t uv[DET_STRESS_FE_VERTS];
    uint16_t color[DET_STRESS_FE_VERTS];
    uint16_t idx[3 * DET_STRESS_FE_TRIS];
    fxl_vcache_entry_t vcache[DET_STRESS_FE_VERTS];
} det_stress_fe_case_t;

/* an object-space or q16 value: tame within +-range, wild any class */
static inline fxl_q16_t det_stress_q16(uint32_t *s, int wild, uint32_t range)
{
    static const int32_t special[] = {INT32_MIN, INT32_MAX, 0, 1, -1, 0x10000, 0x7FFF0000, -0x40000000};
    if (!wild || det_stress_below(s, 2u) == 0u)
        return det_stress_signed(s, det_stress_below(s, range + 1u));
    if (det_stress_below(s, 3u) == 0u)
        return special[det_stress_below(s, 8u)];
    return det_stress_signed(s, det_stress_mag(s, 31u));
}

/* Front-end case k: tame ones put a mesh 3 units across 2-6 units in
 * front of a 30-100 degree camera, its triangles on three distinct
 * vertices; wild ones take any fovy, aspect, near, far,
 * translation, scale, normals, texgen scale and index (past the mesh too). */
static inline void det_stress_fe_make(uint32_t k, const det_stress_assets_t *a, uint16_t *pixels, uint16_t *depth,
                                      det_stress_fe_case_t *f)
{
    uint32_t seed = 0x6A09E667u ^ (k * 0x9E3779B9u), *s = &seed;
    const int wild = (int)det_stress_below(s, 2u);
    det_stress_case_t *c = &f->c;
    fxl_pipeline_t *p = &f->pipe;
    fxl_mat4_t rx, ry, tr;
    uint32_t i, n, ntri;

    det_stress_target(s, pixels, depth, c);
    det_stress_settings(s, a, c);
    (void)fxl_pipeline_init(p, c->width, c->height);
    if (wild && det_stress_below(s, 4u) == 0u) {
        /* one draw a statement (the order of arguments is unspecified) */
        const int32_t vx = det_stress_q16(s, 1, 20000u), vy = det_stress_q16(s, 1, 20000u);
        const int32_t vw = det_stress_q16(s, 1, 5000u), vh = det_stress_q16(s, 1, 5000u);
        (void)fxl_pipeline_set_viewport(p, vx, vy, vw, vh);
    } else {
        (void)fxl_pipeline_set_viewport(p, c->origin_x, c->origin_y, c->width, c->height);
    }
    {
        const fxl_angle_t fovy = (fxl_angle_t)(wild ? det_stress_next(s) : 5461u + det_stress_below(s, 12743u));
        const fxl_q16_t aspect = wild ? det_stress_q16(s, 1, 0x40000u)
                                      : (fxl_q16_t)(((uint32_t)c->width << 16) / (uint32_t)c->height);
        const fxl_q16_t near_q16 = wild ? det_stress_q16(s, 1, 0x100000u)
                                        : (fxl_q16_t)(0x2000u + det_stress_below(s, 0x20000u));
        const fxl_q16_t far_q16 = det_stress_below(s, 2u) ? 0
                                  : wild                   ? det_stress_q16(s, 1, 0x400000u)
                                                           : near_q16 + (fxl_q16_t)(0x40000u + det_stress_below(s, 0x400000u));
        (void)fxl_pipeline_set_perspective(p, fovy, aspect, near_q16, far_q16);
    }
    fxl_mat4_rotate_x(&rx, (fxl_angle_t)det_stress_next(s));
    fxl_mat4_rotate_y(&ry, (fxl_angle_t)det_stress_next(s));
    if (wild) {
        const fxl_q16_t tx = det_stress_q16(s, 1, 0x40000u), ty = det_stress_q16(s, 1, 0x40000u);
        fxl_mat4_translate(&tr, tx, ty, det_stress_q16(s, 1, 0x140000u));
    } else {
        const fxl_q16_t tx = det_stress_q16(s, 0, 0x8000u), ty = det_stress_q16(s, 0, 0x8000u);
        fxl_mat4_translate(&tr, tx, ty, -(fxl_q16_t)(0x20000u + det_stress_below(s, 0x40000u)));
    }
    (void)fxl_mat4_mul(&p->model, &ry, &rx);
    (void)fxl_mat4_mul(&p->model, &tr, &p->model);
    if (wild && det_stress_below(s, 4u) == 0u) {
        fxl_mat4_t sc;
        const fxl_q16_t sx = det_stress_q16(s, 1, 0x40000u), sy = det_stress_q16(s, 1, 0x40000u);
        fxl_mat4_scale(&sc, sx, sy, det_stress_q16(s, 1, 0x40000u));
        (void)fxl_mat4_mul(&p->model, &p->model, &sc);
    }
    p->cull = (uint8_t)det_stress_below(s, 3u);
    p->lighting = (uint8_t)det_stress_below(s, 2u);
    p->material = (uint16_t)det_stress_next(s);
    p->light.dir.x = det_stress_q16(s, wild, 0x10000u);
    p->light.dir.y = det_stress_q16(s, wild, 0x10000u);
    p->light.dir.z = det_stress_q16(s, wild, 0x10000u);
    for (i = 0; i < 3u; i++) {
        p->light.ambient[i] = (uint8_t)det_stress_next(s);
        p->light.diffuse[i] = (uint8_t)det_stress_next(s);
    }
    fxl_texgen_defaults(&p->texgen);
    p->texgen.mode = (uint8_t)det_stress_below(s, 5u);
    p->texgen.space = (uint8_t)det_stress_below(s, 2u);
    p->texgen.plane = (uint8_t)det_stress_below(s, 3u);
    p->texgen.axis = (uint8_t)det_stress_below(s, 3u);
    if (wild) {
        p->texgen.scale_u = det_stress_q16(s, 1, 0x100000u);
        p->texgen.scale_v = det_stress_q16(s, 1, 0x100000u);
        p->texgen.offset_u = det_stress_q16(s, 1, 0x100000u);
        p->texgen.offset_v = det_stress_q16(s, 1, 0x100000u);
    }
    if (det_stress_below(s, 3u) == 0u)
        (void)fxl_pipeline_set_vertex_cache(p, f->vcache, 1u + det_stress_below(s, DET_STRESS_FE_VERTS));

    n = 3u + det_stress_below(s, DET_STRESS_FE_VERTS - 2u);
    ntri = 1u + det_stress_below(s, DET_STRESS_FE_TRIS);
    for (i = 0; i < n; i++) {
        f->pos[i].x = det_stress_q16(s, wild, 0x18000u);
        f->pos[i].y = det_stress_q16(s, wild, 0x18000u);
        f->pos[i].z = det_stress_q16(s, wild, 0x18000u);
        f->normal[i].x = det_stress_q16(s, wild, 0x10000u);
        f->normal[i].y = det_stress_q16(s, wild, 0x10000u);
        f->normal[i].z = det_stress_q16(s, wild, 0x10000u);
        f->uv[i].u = det_stress_q16(s, wild, 0x40000u);
        f->uv[i].v = det_stress_q16(s, wild, 0x40000u);
        f->color[i] = (uint16_t)det_stress_next(s);
    }
    for (i = 0; i < ntri; i++) {
        uint16_t *t = &f->idx[3u * i];
        if (wild) { /* any index, repeated or (1 in 64) past the mesh */
            uint32_t j;
            for (j = 0; j < 3u; j++)
                t[j] = (uint16_t)(det_stress_below(s, 64u) == 0u ? n : det_stress_below(s, n));
        } else { /* three distinct vertices */
            const uint32_t i0 = det_stress_below(s, n);
            const uint32_t i1 = (i0 + 1u + det_stress_below(s, n - 1u)) % n;
            uint32_t i2 = det_stress_below(s, n - 2u);
            i2 += i2 >= (i0 < i1 ? i0 : i1);
            i2 += i2 >= (i0 < i1 ? i1 : i0);
            t[0] = (uint16_t)i0;
            t[1] = (uint16_t)i1;
            t[2] = (uint16_t)i2;
        }
    }
    f->mesh.pos = f->pos;
    f->mesh.uv = det_stress_below(s, 4u) ? f->uv : 0;
    f->mesh.color = det_stress_below(s, 2u) ? f->color : 0;
    f->mesh.normal = det_stress_below(s, 4u) ? f->normal : 0;
    f->mesh.vert_count = n;
    f->mesh.idx = f->idx;
    f->mesh.tri_count = ntri;
}

/* Draw front-end case f and fold the result into h; the status in *st. */
static inline uint32_t det_stress_fe_draw(det_stress_fe_case_t *f, uint32_t h, fxl_status_t *st)
{
    fxl_stats_t n = {0};
    *st = fxl_mesh_draw(&f->pipe, &f->c.tg, &f->c.d, &f->mesh, &n);
    return det_stress_result(&f->c, h, *st, &n);
}

/* ---- the whole list: triangles 0 .. DET_STRESS_CASES - 1, then meshes ---- */

#define DET_STRESS_ALL (DET_STRESS_CASES + DET_STRESS_FE_CASES)

/* Case n of the whole list is a mesh (1) or a triangle (0); *index is its
 * number among its kind, which makes it (det_stress_make, _fe_make). */
static inline int det_stress_is_mesh(uint32_t n, uint32_t *index)
{
    const int mesh = n >= DET_STRESS_CASES;
    *index = mesh ? n - DET_STRESS_CASES : n;
    return mesh;
}

/* The name of a list line ("stress" or "stress_fe") for cases from n. */
static inline const char *det_stress_line_name(uint32_t n)
{
    return n >= DET_STRESS_CASES ? "stress_fe" : "stress";
}

/* Makes case n of the whole list in the caller's buffers, in *tri or *mesh
 * by its kind; returns its target and settings. Callers may look at the
 * buffers before det_stress_run draws it. */
static inline det_stress_case_t *det_stress_prepare(uint32_t n, const det_stress_assets_t *a, uint16_t *pixels,
                                                    uint16_t *depth, det_stress_case_t *tri, det_stress_fe_case_t *mesh)
{
    uint32_t k;
    if (det_stress_is_mesh(n, &k)) {
        det_stress_fe_make(k, a, pixels, depth, mesh);
        return &mesh->c;
    }
    det_stress_make(k, a, pixels, depth, tri);
    return tri;
}

/* Draws case n, as det_stress_prepare made it, and folds the result into h;
 * the status in *st. */
static inline uint32_t det_stress_run(uint32_t n, det_stress_case_t *tri, det_stress_fe_case_t *mesh, uint32_t h,
                                      fxl_status_t *st)
{
    return n >= DET_STRESS_CASES ? det_stress_fe_draw(mesh, h, st) : det_stress_draw(tri, h, st);
}

#endif

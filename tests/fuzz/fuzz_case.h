/* fuzz_case.h - one fuzz case of fxl_draw_triangle: decode, run, check.
 *
 * Shared by the randomized harness (host_sim/tools/fuzz.c -> fixel-fuzz),
 * the libFuzzer entry point (tests/fuzz/fuzz_raster.c) and the regression
 * test (tests/test_fuzz_regress.c), so a reproducer is just the input bytes.
 * Header-only (static functions) because each user is one translation unit;
 * host code: libc and POSIX (mmap for guard pages). The 3D front end's cases
 * (1 input in 8) are fuzz_pipe.h's, built on the reader, decoder parts,
 * guarded memory and checks here.
 *
 * A case is decoded from bytes (missing bytes read as 0, so any length is a
 * valid case): target size, stride, format, origin, clip, optional depth
 * buffer, optional texture (any format, size, levels, wrap, key, border,
 * sometimes an invalid descriptor), every draw field (sometimes an invalid
 * enum), and three vertices picked from pools of extreme values on purpose
 * (INT32 limits, +-32767 px, tiny steps, duplicates, collinear points,
 * level rows: two vertices on one row at one 1/w, sometimes one v too,
 * inv_w 0 / 1 / UINT32_MAX, huge u, v). fixel-fuzz and the libFuzzer
 * target then fit 7 of 8 cases to the build (fz_prepare): in a reduced
 * configuration a refused feature's fields are changed to ones it keeps.
 *
 * Checks (a finding is any violated one):
 *  1 status: FXL_OK exactly when the case is valid by the documented rules
 *    (raster.h, target.h, texture.h), else one of the applicable errors
 *    (FXL_ERR_UNSUPPORTED for a feature config.h left out: fz_left_out);
 *    on error no pixel and no depth value changes. fxl_draw_check on the
 *    same target and draw returns the draw's error, or FXL_OK where only
 *    the vertices fail (FXL_ERR_RANGE) or nothing does.
 *  2 memory: canary words before and after the pixel and depth buffers are
 *    intact; textures and palettes end (or start) at a PROT_NONE guard page,
 *    so a texel read outside the chain faults.
 *  3 clip: nothing written outside the clip rectangle (stride padding
 *    included), depth likewise.
 *  4 determinism: the case is rendered twice on two different backgrounds
 *    (0x0000 and 0xFFFF); every written pixel must hold the same value in
 *    both, and the status and depth buffer must be equal.
 *  5 coverage: the written pixels are a subset of the exact top-left
 *    coverage (reference.h) within the clip; equal to it when neither a
 *    depth test nor a colour key can reject pixels. A third run through the
 *    span-loop probe hook must visit each covered pixel exactly once and
 *    nothing else, with segments inside the clip rectangle.
 *  6 stats: pixels written == stats.pixels; a zero-area triangle is counted
 *    as culled_degenerate.
 *  7 texels: where a draw promises an error bound - FXL_PERSP_EXACT its
 *    plane precision (fz_exact_bound), FXL_PERSP_AUTO that plus its budget,
 *    a fixed segment length L that plus the chord bound (ref_chord_bound),
 *    FXL_PERSP_AFFINE the plane precision against the screen-linear map
 *    - on level 0, or on the levels the LOD can pick (within 4/256 level
 *    of the reference's: per triangle, or per segment at the segment's
 *    correction point - a fixed length L's segments start at the span's
 *    first pixel and every L-th (every pixel where a clamp coordinate
 *    saturates; a needle, fz_gradient_huge, at every pixel with the
 *    triangle's LOD), AUTO's LOD at any of its 16 grid candidates), flat
 *    shade, any texenv:
 *    every written pixel holds a texel (point) or lies channel by channel
 *    within the texels (bilinear), modulated or decalled by the flat colour
 *    or the Gouraud interval (fz_gouraud),
 *    of the texture footprint of the exact
 *    (u, v) widened by the bound. The texels are random, so a wrong texel
 *    is caught, and a bound a core path breaks is found. Untextured: the
 *    flat colour exactly, Gouraud channels within their interpolation's
 *    bound (fz_check_colors). Where the widened footprint spans more than
 *    FZ_TEXEL_SPAN texels an axis, the pixel is checked through the level's
 *    index (fz_texidx; counted apart): a point sample exactly against the
 *    texels of its colour, a blend against the channel range of the blocks
 *    covering the footprint. Where the level cannot be known (a
 *    per-triangle LOD from coordinate differences of 2^31 units or more)
 *    every level counts.
 *  8 depth: with FXL_DEPTH_WRITE every written pixel's depth value is
 *    within one of the exact inv_w plane's value >> 16 at its centre
 *    (raster.h: floored, one step off at most), whatever the walk.
 */
#ifndef FXL_FUZZ_CASE_H
#define FXL_FUZZ_CASE_H

#include <fcntl.h>
#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "fixel/fixel.h"
#include "left_out.h"
#include "reference.h"
#include "../../src/raster_int.h"

#define FZ_MAX_DIM 160          /* largest target side the decoder makes */
#define FZ_CANARY 16            /* canary words before and after each buffer */
#define FZ_TEX_MAX_TEXELS0 (1u << 16) /* level 0 texels (keeps cases fast) */
#define FZ_MSG 512

/* ---- byte reader ---------------------------------------------------------- */

typedef struct fz_reader {
    const uint8_t *p;
    size_t n, i;
} fz_reader;

static uint32_t fz_u8(fz_reader *r)
{
    return r->i < r->n ? r->p[r->i++] : 0u;
}

static uint32_t fz_u16(fz_reader *r)
{
    uint32_t a = fz_u8(r);
    return a | (fz_u8(r) << 8);
}

static uint32_t fz_u32(fz_reader *r)
{
    uint32_t a = fz_u16(r);
    return a | (fz_u16(r) << 16);
}

static int32_t fz_i32(fz_reader *r)
{
    uint32_t u = fz_u32(r);
    return u <= INT32_MAX ? (int32_t)u : -(int32_t)(~u) - 1;
}

/* ---- guarded memory ---------------------------------------------------------
 * A region of `bytes` with one inaccessible page before and after it. Data
 * placed flush against either end faults on the first byte read outside. */
typedef struct fz_guard {
    uint8_t *base;   /* first usable byte */
    size_t bytes;    /* usable bytes, a multiple of the page size */
} fz_guard;

static int fz_guard_alloc(fz_guard *g, size_t want)
{
    long pg = sysconf(_SC_PAGESIZE);
    size_t page = pg > 0 ? (size_t)pg : 4096u;
    size_t usable = (want + page - 1u) / page * page;
    int fd = open("/dev/zero", O_RDWR);
    uint8_t *m;

    if (fd < 0)
        return -1;
    m = (uint8_t *)mmap(NULL, usable + 2u * page, PROT_READ | PROT_WRITE, MAP_PRIVATE, fd, 0);
    close(fd);
    if (m == (uint8_t *)MAP_FAILED)
        return -1;
    if (mprotect(m, page, PROT_NONE) != 0 || mprotect(m + page + usable, page, PROT_NONE) != 0)
        return -1;
    g->base = m + page;
    g->bytes = usable;
    return 0;
}

/* ---- the decoded case ---------------------------------------------------- */

typedef struct fz_case {
    /* target */
    int32_t w, h, stride, origin_x, origin_y;
    fxl_rect_t clip;
    int32_t format;           /* fxl_pixfmt_t, possibly invalid */
    int bad_target;           /* 1: the struct violates target.h (expect ARG) */
    int has_depth;
    uint16_t depth_init;      /* constant, or seed of random contents when depth_rand */
    int depth_rand;
    /* texture */
    int has_tex;
    fxl_texture_t tex;        /* texels/palette filled in by fz_run */
    int tex_at_start;         /* texture placed after the lower guard page */
    int pal_null;
    uint32_t tex_seed;
    /* draw and vertices */
    fxl_draw_t draw;
    fxl_vertex_t v[3];
} fz_case;

static const int32_t fz_special_i32[] = {
    INT32_MIN, INT32_MIN + 1, INT32_MAX, INT32_MAX - 1, 0, 1, -1,
    32767 * 65536, -32767 * 65536, INT32_MAX, INT32_MIN,
    0x00008000, -0x00008000, 0x00000800, -0x00000800, 0x7FFF8000, (int32_t)0x80008000u,
    16384 * 65536, -16384 * 65536, 65536, -65536};
#define FZ_NSPECIAL ((uint32_t)(sizeof fz_special_i32 / sizeof fz_special_i32[0]))

/* A q16 frame coordinate: mostly near the target (so something is drawn),
 * otherwise extremes. `lo`, `len`: target range in pixels; prev: another
 * vertex's coordinate for tiny offsets. */
static int32_t fz_coord(fz_reader *r, int32_t lo, int32_t len, int32_t prev)
{
    uint32_t mode = fz_u8(r) % 16u;
    int64_t c;

    switch (mode) {
    case 0: case 1: case 2: case 3: case 4: case 5: {
        /* within the target +- 8 px, random fraction or exact grid/tie points */
        int64_t px = (int64_t)lo - 8 + (int64_t)(fz_u16(r) % (uint32_t)(len + 16));
        uint32_t fm = fz_u8(r);
        int64_t frac = fm < 64 ? 0 : (fm < 96 ? 0x8000 : (fm < 128 ? 0x0800 : (int64_t)(fz_u16(r))));
        c = px * 65536 + frac;
        break;
    }
    case 6: case 7:
        c = fz_special_i32[fz_u8(r) % FZ_NSPECIAL];
        break;
    case 8:
        c = fz_i32(r);
        break;
    case 9: case 10: {
        /* prev +- a few units: duplicates, half-grid ties, one grid step */
        static const int32_t d[] = {0, 1, -1, 0x7FF, 0x800, -0x800, 0x1000, -0x1000, 0x10000, -0x10000};
        c = (int64_t)prev + d[fz_u8(r) % 10u];
        break;
    }
    case 11: {
        /* far outside, up to +-2^k px */
        int k = (int)(fz_u8(r) % 16u);
        int64_t m = ((int64_t)1 << k) * 65536;
        c = (fz_u8(r) & 1u) ? m + (int64_t)(fz_u16(r)) : -m - (int64_t)(fz_u16(r));
        break;
    }
    case 12:
        c = (int64_t)lo * 65536 + (int64_t)(fz_u32(r) % 0x100000u) - 0x80000;
        break;
    default:
        c = ((int64_t)lo + (int64_t)(fz_u16(r) % (uint32_t)(len + 1))) * 65536;
        break;
    }
    if (c > INT32_MAX)
        c = INT32_MAX;
    if (c < INT32_MIN)
        c = INT32_MIN;
    return (int32_t)c;
}

static uint32_t fz_inv_w(fz_reader *r, uint32_t prev)
{
    uint32_t mode = fz_u8(r) % 12u;
    switch (mode) {
    case 0: return 1u;
    case 1: return UINT32_MAX;
    case 2: return fz_u8(r) < 16 ? 0u : 2u;           /* 0: FXL_ERR_RANGE */
    case 3: return (uint32_t)1 << (fz_u8(r) % 32u);
    case 4: return prev + 1u == 0u ? prev : prev + 1u;
    case 5: return prev;
    case 6: return 1u + fz_u8(r);
    case 7: return UINT32_MAX - fz_u8(r);
    default: {
        uint32_t x = fz_u32(r);
        return x ? x : 1u;
    }
    }
}

static int32_t fz_uv(fz_reader *r, int32_t prev)
{
    uint32_t mode = fz_u8(r) % 10u;
    switch (mode) {
    case 0: return 0;
    case 1: return fz_special_i32[fz_u8(r) % FZ_NSPECIAL];
    case 2: return fz_i32(r);
    case 3: {
        int64_t x = (int64_t)prev + ((fz_u8(r) & 1u) ? 1 : -1) * (int64_t)(fz_u8(r) % 4u);
        return x > INT32_MAX ? INT32_MAX : (x < INT32_MIN ? INT32_MIN : (int32_t)x);
    }
    case 4: return prev;
    default: return (int32_t)(fz_u32(r) % 0x80000u) - 0x40000;   /* +-4 periods */
    }
}

static const int16_t fz_persp_vals[] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, FXL_PERSP_AUTO, 2, 4, 8, 16, 32,
                                        64, 128, 256,
                                        /* invalid: */ 3, 512, -2, 24, INT16_MIN, INT16_MAX};
#define FZ_NPERSP_VALID 11

/* fz_decode in four parts, read in this order; the front-end case
 * (fuzz_pipe.h) reads the first three and its own geometry instead of the
 * fourth. c starts zeroed. */
static void fz_decode_target(fz_reader *r, fz_case *c)
{
    uint32_t m;

    m = fz_u8(r);
    if (m < 200) {
        c->w = 1 + (int32_t)(fz_u8(r) % 40u);
        c->h = 1 + (int32_t)(fz_u8(r) % 40u);
    } else if (m < 240) {
        c->w = 1 + (int32_t)(fz_u8(r) % 4u);
        c->h = 1 + (int32_t)(fz_u8(r) % 4u);
    } else {
        c->w = 1 + (int32_t)(fz_u8(r) % FZ_MAX_DIM);
        c->h = 1 + (int32_t)(fz_u8(r) % FZ_MAX_DIM);
    }
    c->stride = c->w + (int32_t)(fz_u8(r) % 8u < 5 ? 0 : fz_u8(r) % 7u);
    m = fz_u8(r);
    c->format = m < 120 ? FXL_PIXFMT_RGB565 : (m < 250 ? FXL_PIXFMT_RGB565_SWAP : 2 + (int32_t)(m % 3u));
    m = fz_u8(r) % 8u;
    if (m < 4) {
        c->origin_x = c->origin_y = 0;
    } else if (m < 6) {
        c->origin_x = (int32_t)(fz_u16(r) % 801u) - 400;
        c->origin_y = (int32_t)(fz_u16(r) % 801u) - 400;
    } else {
        static const int32_t ext[] = {FXL_TARGET_MAX_ORIGIN, -FXL_TARGET_MAX_ORIGIN, 32767 - FZ_MAX_DIM,
                                      -32768, FXL_TARGET_MAX_ORIGIN - 1, 0};
        c->origin_x = ext[fz_u8(r) % 6u];
        c->origin_y = ext[fz_u8(r) % 6u];
        /* Clamp to the documented limit except on purpose (bad_target). */
        if (fz_u8(r) >= 16) {
            if (c->origin_x < -FXL_TARGET_MAX_ORIGIN) c->origin_x = -FXL_TARGET_MAX_ORIGIN;
            if (c->origin_y < -FXL_TARGET_MAX_ORIGIN) c->origin_y = -FXL_TARGET_MAX_ORIGIN;
            if (c->origin_x > FXL_TARGET_MAX_ORIGIN) c->origin_x = FXL_TARGET_MAX_ORIGIN;
            if (c->origin_y > FXL_TARGET_MAX_ORIGIN) c->origin_y = FXL_TARGET_MAX_ORIGIN;
        }
    }
    /* clip, frame coordinates */
    m = fz_u8(r) % 8u;
    c->clip.x0 = c->origin_x;
    c->clip.y0 = c->origin_y;
    c->clip.x1 = c->origin_x + c->w;
    c->clip.y1 = c->origin_y + c->h;
    if (m >= 3 && m < 6) {
        int32_t a = (int32_t)(fz_u8(r) % (uint32_t)(c->w + 1)), b = (int32_t)(fz_u8(r) % (uint32_t)(c->w + 1));
        int32_t e = (int32_t)(fz_u8(r) % (uint32_t)(c->h + 1)), f = (int32_t)(fz_u8(r) % (uint32_t)(c->h + 1));
        c->clip.x0 = c->origin_x + (a < b ? a : b);
        c->clip.x1 = c->origin_x + (a < b ? b : a);
        c->clip.y0 = c->origin_y + (e < f ? e : f);
        c->clip.y1 = c->origin_y + (e < f ? f : e);
    } else if (m == 6) {
        /* empty or inverted */
        c->clip.x1 = c->clip.x0 - (int32_t)(fz_u8(r) % 3u);
    } else if (m == 7 && fz_u8(r) < 32) {
        /* outside the buffer: the struct is invalid */
        c->clip.x1 += 1 + (int32_t)(fz_u8(r) % 4u);
    }
    c->has_depth = fz_u8(r) % 3u != 0u;
    c->depth_rand = fz_u8(r) % 4u == 0u;
    {
        static const uint16_t dv[] = {0, 0, 1, 0x7FFF, 0xFFFF, 0x8000};
        c->depth_init = c->depth_rand ? (uint16_t)fz_u16(r) : dv[fz_u8(r) % 6u];
    }
}

static void fz_decode_texture(fz_reader *r, fz_case *c)
{
    uint32_t m;

    m = fz_u8(r);
    c->has_tex = m >= 48;
    if (c->has_tex) {
        fxl_texture_t *t = &c->tex;
        uint32_t lw, lh, maxl;
        m = fz_u8(r);
        t->format = (uint8_t)(m < 150 ? FXL_TEXFMT_RGB565 : (m < 200 ? FXL_TEXFMT_L8 : (m < 252 ? FXL_TEXFMT_I8 : 3 + m % 2u)));
        m = fz_u8(r);
        if (m < 200) {
            lw = fz_u8(r) % 8u;
            lh = fz_u8(r) % 8u;
        } else {
            lw = fz_u8(r) % (FXL_TEX_MAX_LOG2 + 1u);
            lh = fz_u8(r) % (FXL_TEX_MAX_LOG2 + 1u);
            while (lw + lh > 16u) {
                if (lw > lh) lw--; else lh--;
            }
            if (m >= 254)
                lw = FXL_TEX_MAX_LOG2 + 1u + (m & 1u);   /* too large: invalid */
        }
        t->log2_w = (uint8_t)lw;
        t->log2_h = (uint8_t)lh;
        maxl = 1u + (lw > lh ? lw : lh);
        m = fz_u8(r);
        t->levels = (uint8_t)(m < 100 ? 1u : (m < 200 ? maxl : (m < 250 ? 1u + fz_u8(r) % maxl : (m & 1u ? 0u : maxl + 1u))));
        m = fz_u8(r);
        t->wrap_u = (uint8_t)(m % 4u);
        t->wrap_v = (uint8_t)((m >> 2) % 4u);
        if (m >= 250)
            t->wrap_u = 4;   /* invalid */
        m = fz_u8(r);
        t->flags = (uint8_t)(m < 80 ? FXL_TEXF_KEY : (m < 252 ? 0u : 0x80u));
        t->key = (uint16_t)fz_u16(r);
        if (t->format != FXL_TEXFMT_RGB565 && fz_u8(r) >= 8)
            t->key &= 0xFFu;
        t->border = (uint16_t)fz_u16(r);
        t->reserved = (uint8_t)(fz_u8(r) >= 252 ? 1u : 0u);
        c->tex_at_start = (int)(fz_u8(r) & 1u);
        c->pal_null = fz_u8(r) < 8;
        c->tex_seed = fz_u32(r);
    }
}

static void fz_decode_draw(fz_reader *r, fz_case *c)
{
    uint32_t m;

    fxl_draw_defaults(&c->draw);
    m = fz_u8(r);
    c->draw.persp = m < 240 ? fz_persp_vals[m % FZ_NPERSP_VALID]
                            : fz_persp_vals[FZ_NPERSP_VALID + m % (sizeof fz_persp_vals / sizeof fz_persp_vals[0] - FZ_NPERSP_VALID)];
    m = fz_u8(r);
    c->draw.filter = (uint8_t)(m < 250 ? m % 2u : 2u + m % 3u);
    m = fz_u8(r);
    c->draw.mip = (uint8_t)(m < 250 ? m % 3u : 3u);
    m = fz_u8(r);
    c->draw.lod = (uint8_t)(m < 250 ? m % 2u : 2u);
    m = fz_u8(r);
    c->draw.texenv = (uint8_t)(m < 250 ? m % 3u : 3u);
    m = fz_u8(r);
    c->draw.shade = (uint8_t)(m < 250 ? m % 2u : 2u);
    c->draw.depth = (uint8_t)(fz_u8(r) % 4u);
    c->draw.color = (uint16_t)fz_u16(r);
    m = fz_u8(r);
    c->draw.lod_bias_q8 = (int16_t)(m < 128 ? 0 : (m < 192 ? (int32_t)(fz_u16(r) % 8193u) - 4096
                                                            : (m & 1u ? INT16_MAX : INT16_MIN)));
    m = fz_u8(r);
    c->draw.auto_budget = m < 200 ? (int32_t)(1u + fz_u32(r) % 0x40000u)
                                  : (m < 230 ? fz_special_i32[fz_u8(r) % FZ_NSPECIAL] : FXL_Q16_ONE / 4);
    if (c->has_tex && fz_u8(r) >= 8)
        c->draw.texture = &c->tex;   /* else untextured with a texture prepared */
}

static void fz_decode_vertices(fz_reader *r, fz_case *c)
{
    uint32_t m, mb, i;
    int32_t prev_x, prev_y;

    /* 0..5 free (of those, a byte of 41..87: v1 on v0's row at its depth,
     * 152..175: a receding floor; so that no input of test_fuzz_regress.c
     * changes meaning: their bytes here are 0, 1, 40, 50, 88, 91, 127,
     * 128, 144, 183, 216, 240 and 255), 6: two vertices equal, 7:
     * collinear */
    mb = fz_u8(r);
    m = mb % 8u;
    prev_x = c->origin_x * 65536;
    prev_y = c->origin_y * 65536;
    for (i = 0; i < 3; i++) {
        fxl_vertex_t *v = &c->v[i];
        v->x = fz_coord(r, c->origin_x, c->w, prev_x);
        v->y = fz_coord(r, c->origin_y, c->h, prev_y);
        v->inv_w = fz_inv_w(r, i ? c->v[i - 1].inv_w : 0x40000000u);
        v->u = fz_uv(r, i ? c->v[i - 1].u : 0);
        v->v = fz_uv(r, i ? c->v[i - 1].v : 0);
        v->color = (uint16_t)fz_u16(r);
        prev_x = v->x;
        prev_y = v->y;
    }
    if (m <= 5u && mb >= 41u && mb < 88u) {
        /* a level row: q and z constant along every row (a level floor),
         * the specialised walks' constant-depth copies; from 64, v too
         * (v runs with depth: every span on one texel row, FXL_T_LROW) */
        c->v[1].y = c->v[0].y;
        c->v[1].inv_w = c->v[0].inv_w;
        if (mb >= 64u)
            c->v[1].v = c->v[0].v;
    } else if (m <= 5u && mb >= 152u && mb < 176u) {
        /* a floor receding to the horizon, rolled (AUTO's reciprocal runs):
         * two near vertices 8 to 39 target widths either side of a point
         * below the target, one far vertex (1/w 24 to 87 times less) in
         * its upper half, u and v across 16 to 79 repeats */
        const int64_t dx = 16 + fz_u8(r) % 48u, dy = (int64_t)(fz_u8(r) % 65u) - 32;
        const int64_t k = (int64_t)(8 + fz_u8(r) % 32u) * c->w / 16 + 1;
        const int64_t cx = c->origin_x + (int64_t)(fz_u16(r) % (uint32_t)(c->w + 1));
        const int64_t cy = c->origin_y + c->h + c->h / 16;
        const uint32_t q = 0x01000000u + fz_u32(r) % 0x40000000u;
        const int32_t su = (int32_t)(16 + fz_u8(r) % 64u) * 65536, sv = (int32_t)(16 + fz_u8(r) % 64u) * 65536;
        const int64_t xs[3] = {cx - k * dx, cx + k * dx,
                               c->origin_x + c->w / 4 + (int64_t)(fz_u16(r) % (uint32_t)(c->w / 2 + 1))};
        const int64_t ys[3] = {cy - k * dy, cy + k * dy,
                               c->origin_y + c->h / 4 + (int64_t)(fz_u16(r) % (uint32_t)(c->h / 4 + 1))};
        for (i = 0; i < 3; i++) {
            const int64_t x = xs[i] * 65536, y = ys[i] * 65536;
            c->v[i].x = x > INT32_MAX ? INT32_MAX : (x < INT32_MIN ? INT32_MIN : (int32_t)x);
            c->v[i].y = y > INT32_MAX ? INT32_MAX : (y < INT32_MIN ? INT32_MIN : (int32_t)y);
        }
        c->v[0].inv_w = c->v[1].inv_w = q;
        c->v[2].inv_w = q / (24u + fz_u8(r) % 64u);
        /* the decoded u, v scaled below 2^23: the sums stay in int32 */
        c->v[0].u /= 256;
        c->v[0].v /= 256;
        c->v[1].u = c->v[0].u + su;
        c->v[1].v = c->v[0].v;
        c->v[2].u = c->v[0].u + su / 2;
        c->v[2].v = c->v[0].v + sv;
    } else if (m == 6) {
        c->v[2].x = c->v[0].x;
        c->v[2].y = c->v[0].y;
    } else if (m == 7) {
        /* v2 = v0 + k (v1 - v0) on the q16 grid, k in {-2, -1, 2, 3} (may saturate) */
        static const int k[] = {-2, -1, 2, 3};
        int kk = k[fz_u8(r) % 4u];
        int64_t x = (int64_t)c->v[0].x + kk * ((int64_t)c->v[1].x - c->v[0].x);
        int64_t y = (int64_t)c->v[0].y + kk * ((int64_t)c->v[1].y - c->v[0].y);
        if (x >= INT32_MIN && x <= INT32_MAX && y >= INT32_MIN && y <= INT32_MAX) {
            c->v[2].x = (int32_t)x;
            c->v[2].y = (int32_t)y;
        }
    }
}

static void fz_decode(const uint8_t *data, size_t n, fz_case *c)
{
    fz_reader rd = {data, n, 0};

    memset(c, 0, sizeof *c);
    fz_decode_target(&rd, c);
    fz_decode_texture(&rd, c);
    fz_decode_draw(&rd, c);
    fz_decode_vertices(&rd, c);
}

/* ---- the oracle ------------------------------------------------------------- */

#define FZ_E_ARG 1u
#define FZ_E_RANGE 2u
#define FZ_E_UNSUP 4u

static int fz_target_valid(const fz_case *c)
{
    if (c->w < 1 || c->h < 1 || c->w > FXL_TARGET_MAX_DIM || c->h > FXL_TARGET_MAX_DIM || c->stride < c->w)
        return 0;
    if (c->origin_x < -FXL_TARGET_MAX_ORIGIN || c->origin_x > FXL_TARGET_MAX_ORIGIN ||
        c->origin_y < -FXL_TARGET_MAX_ORIGIN || c->origin_y > FXL_TARGET_MAX_ORIGIN)
        return 0;
    if (c->format != FXL_PIXFMT_RGB565 && c->format != FXL_PIXFMT_RGB565_SWAP)
        return 0;
    /* target.h: the clip is always inside the buffer (an empty one is fine
     * as long as it does not reach outside). */
    if (c->clip.x0 < c->clip.x1 && c->clip.y0 < c->clip.y1 &&
        (c->clip.x0 < c->origin_x || c->clip.y0 < c->origin_y || c->clip.x1 > c->origin_x + c->w ||
         c->clip.y1 > c->origin_y + c->h))
        return 0;
    return 1;
}

/* The first optional feature (fixel/config.h) the case needs that this
 * build left out, or NULL (left_out.h): such a draw is FXL_ERR_UNSUPPORTED
 * for every triangle, culled or not. */
static const char *fz_left_out(const fz_case *c)
{
    return left_out_feature(&c->draw, c->draw.texture, c->format, c->has_depth);
}

/* a == b for two feature names; a loop rather than strcmp, which GCC
 * flags (-Wstring-compare) where it can prove left_out_feature never
 * returns that name in this configuration. */
static int fz_names(const char *a, const char *b)
{
    while (*a != '\0' && *a == *b) {
        a++;
        b++;
    }
    return *a == *b;
}

/* Change the case, a field at a time, until this build draws it (until
 * fz_left_out is NULL): the fields a left-out feature's name points at
 * take a value the build keeps. In a build without the generic walk most
 * decoded cases are refused (an untextured, keyed, L8 or clamped draw, a
 * Gouraud or MODULATE one...), so few would reach a walk: 12 of 20,000
 * before this. A no-op in the default build, where nothing is left out. */
static void fz_fit_build(fz_case *c)
{
    int k;
    const char *need;
    for (k = 0; k < 8 && (need = fz_left_out(c)) != NULL; k++) {
        fxl_draw_t *d = &c->draw;
        fxl_texture_t *t = &c->tex;
        if (fz_names(need, "FXL_HAVE_BILINEAR") || fz_names(need, "FXL_FAST_BILINEAR")) {
            d->filter = FXL_FILTER_POINT;
        } else if (fz_names(need, "FXL_FAST_POINT")) {
            d->filter = FXL_FILTER_BILINEAR;
        } else if (fz_names(need, "FXL_HAVE_AUTO")) {
            d->persp = FXL_PERSP_SPAN;
        } else if (fz_names(need, "FXL_HAVE_MIPMAP")) {
            d->mip = FXL_MIP_NONE;
        } else if (fz_names(need, "FXL_HAVE_DEPTH") || fz_names(need, "FXL_FAST_DEPTH")) {
            d->depth = 0;
        } else if (fz_names(need, "FXL_FAST_NO_DEPTH")) {
            c->has_depth = 1;
            d->depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
        } else if (fz_names(need, "FXL_FAST_NATIVE") || fz_names(need, "FXL_FAST_SWAPPED")) {
            c->format = fz_names(need, "FXL_FAST_NATIVE") ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        } else if (fz_names(need, "FXL_HAVE_GENERIC")) {
            /* the specialised walks' draw: an RGB565 repeat texture (kept
             * if the case has one), REPLACE, flat, both depth flags or none */
            if (!c->has_tex) {
                memset(t, 0, sizeof *t);
                t->log2_w = (uint8_t)(c->v[0].color % 8u);
                t->log2_h = (uint8_t)(c->v[1].color % 8u);
                t->levels = 1;
                c->tex_seed = (uint32_t)c->v[2].color + 1u;
                c->has_tex = 1;
            }
            d->texture = t;
            t->format = FXL_TEXFMT_RGB565;
            t->wrap_u = t->wrap_v = FXL_WRAP_REPEAT;
            t->flags &= (uint8_t)~FXL_TEXF_KEY;
            while ((uint32_t)t->log2_w + t->log2_h > 16u) {
                if (t->log2_w > t->log2_h) t->log2_w--; else t->log2_h--;
            }
            d->texenv = FXL_TEXENV_REPLACE;
            d->shade = FXL_SHADE_FLAT;
            if ((d->depth & (FXL_DEPTH_TEST | FXL_DEPTH_WRITE)) != 0)
                d->depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
        } else {
            break;   /* a name this function does not know: leave the case refused */
        }
    }
}

/* Decode a case as fixel-fuzz and the libFuzzer target do: fz_decode,
 * then in 7 of 8 inputs (the last byte's low three bits not all zero)
 * fz_fit_build, so a build without the generic walk still runs its walks
 * and the rest still checks its refusals. The regression replays use
 * fz_decode alone (they were recorded in the default build, where the
 * two agree). */
static inline void fz_prepare(const uint8_t *data, size_t n, fz_case *c)
{
    fz_decode(data, n, c);
    if (n > 0 && (data[n - 1] & 7u) != 0u)
        fz_fit_build(c);
}

/* Which errors the documented rules allow for the target and draw alone,
 * before any vertex is read (fxl_draw_check; 0: must be OK). */
static uint32_t fz_setting_errors(const fz_case *c)
{
    uint32_t e = 0;
    const fxl_draw_t *d = &c->draw;

    if (!fz_target_valid(c))
        e |= FZ_E_ARG;
    if (d->filter > 1 || d->mip > 2 || d->lod > 1 || d->texenv > 2 || d->shade > 1)
        e |= FZ_E_ARG;
    {
        int p = d->persp, ok = p == FXL_PERSP_AFFINE || p == FXL_PERSP_EXACT || p == FXL_PERSP_AUTO ||
                               (p >= 2 && p <= FXL_PERSP_MAX && (p & (p - 1)) == 0);
        if (!ok || (p == FXL_PERSP_AUTO && d->auto_budget <= 0))
            e |= FZ_E_RANGE;
    }
    if (d->texture) {
        const fxl_texture_t *t = d->texture;
        uint32_t maxl = 1u + (t->log2_w > t->log2_h ? t->log2_w : t->log2_h);
        int bad = t->log2_w > FXL_TEX_MAX_LOG2 || t->log2_h > FXL_TEX_MAX_LOG2 || t->format > FXL_TEXFMT_I8 ||
                  t->wrap_u > FXL_WRAP_BORDER || t->wrap_v > FXL_WRAP_BORDER ||
                  (t->format == FXL_TEXFMT_I8 && !t->palette) || t->reserved != 0 ||
                  (t->flags & ~FXL_TEXF_KEY) != 0 || t->levels == 0 || t->levels > maxl ||
                  ((t->flags & FXL_TEXF_KEY) && t->format != FXL_TEXFMT_RGB565 && t->key > 255);
        if (bad)
            e |= FZ_E_ARG | FZ_E_RANGE | FZ_E_UNSUP;   /* texture.h does not fix which */
    }
    if (fz_left_out(c))
        e |= FZ_E_UNSUP;
    return e;
}

/* Which errors the documented rules allow for this case (0: must be OK). */
static uint32_t fz_expected_errors(const fz_case *c)
{
    uint32_t e = fz_setting_errors(c);
    int i;

    for (i = 0; i < 3; i++)
        if (c->v[i].inv_w == 0)
            e |= FZ_E_RANGE;
    return e;
}

static uint32_t fz_status_bit(fxl_status_t st)
{
    switch (st) {
    case FXL_OK: return 0;
    case FXL_ERR_ARG: return FZ_E_ARG;
    case FXL_ERR_RANGE: return FZ_E_RANGE;
    case FXL_ERR_UNSUPPORTED: return FZ_E_UNSUP;
    default: return 0x100u;
    }
}

/* ---- running a case ----------------------------------------------------------- */

/* ---- check 7's level indexes -------------------------------------------------
 * A footprint wider than FZ_TEXEL_SPAN texels an axis (minified draws, large
 * bounds) is too many texels to read one by one at every pixel. For those
 * pixels each texture level gets, once per case and when first needed:
 * - its texels sorted by colour (keyed ones left out), so that a point
 *   sample (replace, decal) is held exactly to "some texel of this colour
 *   lies in the footprint";
 * - a min/max pyramid of its channels over aligned blocks, so that a blend
 *   (or a modulated point sample) is held to the channel range of the blocks
 *   that cover the footprint: a superset of its texels, never more than 8
 *   blocks an axis, so a little looser than the texels themselves.
 * Wrapped, a footprint is up to three intervals of the level an axis
 * (fz_axis), plus the border colour where it leaves a border axis. */
#define FZ_IDX_LEVELS (FXL_TEX_MAX_LOG2 + 1)
#define FZ_IDX_TEXELS (2u * FZ_TEX_MAX_TEXELS0 + 64u)   /* any chain of <= 2^16 level-0 texels */

typedef struct fz_block {
    uint8_t lo[3], hi[3];   /* channel range of its unkeyed texels (lo > hi: none) */
    uint8_t keyed;          /* it holds a keyed texel */
} fz_block;

typedef struct fz_level_idx {
    int built, sorted;
    uint32_t lw, lh, count;      /* log2 size; unkeyed texels */
    uint64_t *by_colour;         /* colour << 32 | (y << lw | x), sorted */
    fz_block *blocks;            /* pyramid: step k has blocks of 2^min(k,lw) x 2^min(k,lh) */
    size_t step_at[FXL_TEX_MAX_LOG2 + 2];
} fz_level_idx;

typedef struct fz_texidx {
    fz_level_idx lv[FZ_IDX_LEVELS];
    uint64_t *colour_mem, *sort_tmp;
    fz_block *block_mem;
    size_t colour_used, block_used;
} fz_texidx;

static struct fz_texidx *fz_texidx_new(void)
{
    fz_texidx *x = (fz_texidx *)calloc(1, sizeof *x);
    if (!x)
        return NULL;
    x->colour_mem = (uint64_t *)malloc(FZ_IDX_TEXELS * sizeof *x->colour_mem);
    x->sort_tmp = (uint64_t *)malloc((FZ_TEX_MAX_TEXELS0 + 64u) * sizeof *x->sort_tmp);
    /* a pyramid holds at most twice its level's texels (a 1-texel-high level) */
    x->block_mem = (fz_block *)malloc(2u * FZ_IDX_TEXELS * sizeof *x->block_mem);
    if (!x->colour_mem || !x->sort_tmp || !x->block_mem)
        return NULL;
    return x;
}

/* Forget the previous case's texture. */
static void fz_texidx_reset(fz_texidx *x)
{
    int n;
    for (n = 0; n < FZ_IDX_LEVELS; n++)
        x->lv[n].built = 0;
    x->colour_used = x->block_used = 0;
}

/* Sort a level's entries by colour: two stable counting passes over the
 * colour's bytes (entries are made in index order, so ties stay sorted). */
static void fz_sort_by_colour(uint64_t *e, uint64_t *tmp, uint32_t n)
{
    int pass;
    for (pass = 0; pass < 2; pass++) {
        uint32_t at[257] = {0}, i;
        const int sh = 32 + 8 * pass;
        for (i = 0; i < n; i++)
            at[((e[i] >> sh) & 255u) + 1]++;
        for (i = 1; i < 257; i++)
            at[i] += at[i - 1];
        for (i = 0; i < n; i++)
            tmp[at[(e[i] >> sh) & 255u]++] = e[i];
        memcpy(e, tmp, (size_t)n * sizeof *e);
    }
}

static void fz_block_add(fz_block *b, const fz_block *o)
{
    int ch;
    for (ch = 0; ch < 3; ch++) {
        b->lo[ch] = o->lo[ch] < b->lo[ch] ? o->lo[ch] : b->lo[ch];
        b->hi[ch] = o->hi[ch] > b->hi[ch] ? o->hi[ch] : b->hi[ch];
    }
    b->keyed |= o->keyed;
}

static const fz_block fz_block_empty = {{255, 255, 255}, {0, 0, 0}, 0};

static fz_level_idx *fz_level(fz_texidx *x, const fxl_texture_t *t, uint32_t n)
{
    fz_level_idx *L = &x->lv[n];
    uint32_t xx, yy, k, kmax;
    if (L->built)
        return L;
    L->lw = t->log2_w > n ? t->log2_w - n : 0;
    L->lh = t->log2_h > n ? t->log2_h - n : 0;
    L->by_colour = x->colour_mem + x->colour_used;
    L->blocks = x->block_mem + x->block_used;
    L->count = 0;
    for (yy = 0; yy < 1u << L->lh; yy++)
        for (xx = 0; xx < 1u << L->lw; xx++) {
            int key = 0;
            const uint16_t c = fxl_texture_fetch(t, n, (int32_t)xx, (int32_t)yy, &key);
            fz_block *b = &L->blocks[(yy << L->lw) + xx];
            *b = fz_block_empty;
            if (key) {
                b->keyed = 1;
                continue;
            }
            b->lo[0] = b->hi[0] = (uint8_t)(c >> 11);
            b->lo[1] = b->hi[1] = (uint8_t)((c >> 5) & 63u);
            b->lo[2] = b->hi[2] = (uint8_t)(c & 31u);
            L->by_colour[L->count++] = (uint64_t)c << 32 | ((uint64_t)yy << L->lw | xx);
        }
    L->sorted = 0;   /* sorted when first asked for a colour */
    x->colour_used += L->count;
    /* step k from step k - 1: an axis stops halving at one block */
    kmax = L->lw > L->lh ? L->lw : L->lh;
    L->step_at[0] = 0;
    L->step_at[1] = (size_t)1 << (L->lw + L->lh);
    for (k = 1; k <= kmax; k++) {
        const uint32_t pw = L->lw - (k - 1 < L->lw ? k - 1 : L->lw), ph = L->lh - (k - 1 < L->lh ? k - 1 : L->lh);
        const uint32_t w = L->lw - (k < L->lw ? k : L->lw), h = L->lh - (k < L->lh ? k : L->lh);
        const fz_block *prev = L->blocks + L->step_at[k - 1];
        fz_block *cur = L->blocks + L->step_at[k];
        for (yy = 0; yy < 1u << h; yy++)
            for (xx = 0; xx < 1u << w; xx++) {
                /* the previous step's blocks this one covers: 1 or 2 an axis */
                const uint32_t fx = w < pw ? 2u : 1u, fy = h < ph ? 2u : 1u;
                uint32_t i, j;
                fz_block *b = &cur[(yy << w) + xx];
                *b = fz_block_empty;
                for (j = 0; j < fy; j++)
                    for (i = 0; i < fx; i++)
                        fz_block_add(b, &prev[((yy * fy + j) << pw) + xx * fx + i]);
            }
        L->step_at[k + 1] = L->step_at[k] + ((size_t)1 << (w + h));
    }
    x->block_used += L->step_at[kmax + 1];
    L->built = 1;
    return L;
}

/* An axis of a level: the in-range texel intervals a footprint reaches. */
typedef struct fz_axis {
    int32_t lo[3], hi[3];
    int n;
    int border;   /* it reads the border colour too */
} fz_axis;

static void fz_axis_add(fz_axis *a, int64_t lo, int64_t hi)
{
    a->lo[a->n] = (int32_t)lo;
    a->hi[a->n] = (int32_t)hi;
    a->n++;
}

/* The texels an axis of 2^lg texels reads under wrap for level coordinates
 * [lo, hi] (whole, unwrapped); whole = 0 when they are too far out to hold
 * (all of the axis, and its border). */
static void fz_axis_make(double lo, double hi, uint32_t lg, uint8_t wrap, fz_axis *a)
{
    const int64_t n = (int64_t)1 << lg, period = wrap == FXL_WRAP_MIRROR ? 2 * n : n;
    int64_t l, h, s, e;
    a->n = 0;
    a->border = 0;
    if (!(lo > -1e15 && hi < 1e15 && hi - lo < 1e15)) {   /* NaN-safe */
        fz_axis_add(a, 0, n - 1);
        a->border = wrap == FXL_WRAP_BORDER;
        return;
    }
    l = (int64_t)lo;
    h = (int64_t)hi;
    if (wrap == FXL_WRAP_CLAMP || wrap == FXL_WRAP_BORDER) {
        a->border = wrap == FXL_WRAP_BORDER && (l < 0 || h >= n);
        if (wrap == FXL_WRAP_CLAMP) {
            l = l < 0 ? 0 : (l > n - 1 ? n - 1 : l);
            h = h < 0 ? 0 : (h > n - 1 ? n - 1 : h);
        } else {
            l = l < 0 ? 0 : l;
            h = h > n - 1 ? n - 1 : h;
        }
        if (l <= h)
            fz_axis_add(a, l, h);
        return;
    }
    if (h - l + 1 >= period) {
        fz_axis_add(a, 0, n - 1);
        return;
    }
    /* [s, e] within [0, 2 period): cut at multiples of n; a mirror's odd
     * cells read backwards */
    s = ((l % period) + period) % period;
    e = s + (h - l);
    while (s <= e) {
        const int64_t cell = s / n, end = (cell + 1) * n - 1 < e ? (cell + 1) * n - 1 : e;
        const int64_t a0 = s - cell * n, a1 = end - cell * n;
        if (wrap == FXL_WRAP_MIRROR && (cell & 1))
            fz_axis_add(a, n - 1 - a1, n - 1 - a0);
        else
            fz_axis_add(a, a0, a1);
        s = end + 1;
    }
}

static int fz_axis_has(const fz_axis *a, int64_t t)
{
    int i;
    for (i = 0; i < a->n; i++)
        if (t >= a->lo[i] && t <= a->hi[i])
            return 1;
    return 0;
}

/* Is some unkeyed texel of colour px inside the footprint au x av? */
static int fz_level_has_colour(fz_texidx *x, fz_level_idx *L, const fz_axis *au, const fz_axis *av, uint16_t px)
{
    const uint64_t key = (uint64_t)px << 32;
    size_t lo = 0, hi = L->count;
    if (!L->sorted) {
        fz_sort_by_colour(L->by_colour, x->sort_tmp, L->count);
        L->sorted = 1;
    }
    while (lo < hi) {   /* the first entry >= key */
        const size_t mid = lo + (hi - lo) / 2;
        if (L->by_colour[mid] < key)
            lo = mid + 1;
        else
            hi = mid;
    }
    for (; lo < L->count && (L->by_colour[lo] >> 32) == px; lo++) {
        const uint32_t i = (uint32_t)L->by_colour[lo];
        if (fz_axis_has(au, i & ((1u << L->lw) - 1u)) && fz_axis_has(av, i >> L->lw))
            return 1;
    }
    return 0;
}

/* The channel range (and keyed flag) of blocks covering [x0, x1] x [y0, y1]. */
static void fz_level_range(const fz_level_idx *L, int32_t x0, int32_t x1, int32_t y0, int32_t y1, fz_block *r)
{
    uint32_t k = 0, ku, kv;
    int32_t bx, by;
    for (;; k++) {
        ku = k < L->lw ? k : L->lw;
        kv = k < L->lh ? k : L->lh;
        if ((x1 >> ku) - (x0 >> ku) < 8 && (y1 >> kv) - (y0 >> kv) < 8)
            break;
    }
    for (by = y0 >> kv; by <= y1 >> kv; by++)
        for (bx = x0 >> ku; bx <= x1 >> ku; bx++)
            fz_block_add(r, &L->blocks[L->step_at[k] + ((size_t)by << (L->lw - ku)) + (size_t)bx]);
}

typedef struct fz_state {
    fz_guard texmem, palmem;
    uint16_t *pix_a, *pix_b, *dep_a, *dep_b, *dep_init;  /* FZ_CANARY + stride*h + FZ_CANARY */
    uint8_t *cover;                                       /* w*h */
    uint8_t *probe_cnt;
    struct fz_texidx *texidx;                             /* check 7's level indexes */
    size_t cap;
    int ready;
} fz_state;

typedef struct fz_outcome {
    fxl_status_t status;
    uint32_t written;       /* pixels written */
    uint32_t covered;       /* exact coverage within the clip */
    int checked_equal;      /* coverage equality was required */
    int pipe;               /* a front-end case (fuzz_pipe.h) */
    uint32_t emitted;       /* front end: screen triangles emitted */
    uint32_t placed;        /* front end: mesh triangles found where the double projection puts them */
    uint32_t texel_checked; /* check 7: pixels held to their texel footprint or colour */
    uint32_t texel_wide;    /* check 7: of those, pixels checked through the level indexes (fz_texidx) */
    uint32_t alone_tris;    /* front end, P7: emitted triangles run as raster cases */
    uint32_t alone_written; /* P7: pixels they wrote, drawn alone */
    uint32_t alone_checked; /* P7: of those, held to check 7 */
    uint32_t depth_checked; /* check 8: depth values held to the exact plane */
} fz_outcome;

/* The probe (check 5) has no user pointer: file-scope state, set per run. */
static struct {
    const uint16_t *base;
    int32_t stride, w, h, ox, oy;
    fxl_rect_t clip;
    uint8_t *cnt;
    int bad;                /* a segment outside the buffer or clip */
    long bad_idx;
} fz_probe_ctx;

static uint32_t fz_probe_seg(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    long k = (long)(s->dst - fz_probe_ctx.base);
    int32_t row, col, i;
    (void)tri;
    if (s->n < 1 || k < 0) {
        fz_probe_ctx.bad = 1;
        fz_probe_ctx.bad_idx = k;
        return 0;
    }
    row = (int32_t)(k / fz_probe_ctx.stride);
    col = (int32_t)(k % fz_probe_ctx.stride);
    if (row >= fz_probe_ctx.h || col + s->n > fz_probe_ctx.w ||
        row + fz_probe_ctx.oy < fz_probe_ctx.clip.y0 || row + fz_probe_ctx.oy >= fz_probe_ctx.clip.y1 ||
        col + fz_probe_ctx.ox < fz_probe_ctx.clip.x0 || col + s->n + fz_probe_ctx.ox > fz_probe_ctx.clip.x1) {
        fz_probe_ctx.bad = 1;
        fz_probe_ctx.bad_idx = k;
        return 0;
    }
    for (i = 0; i < s->n; i++) {
        uint8_t *p = &fz_probe_ctx.cnt[(size_t)row * (size_t)fz_probe_ctx.w + (size_t)(col + i)];
        if (*p < 255)
            (*p)++;
    }
    return (uint32_t)s->n;
}

static int fz_state_init(fz_state *s)
{
    size_t words = (size_t)FZ_CANARY * 2u + (size_t)(FZ_MAX_DIM + 8) * FZ_MAX_DIM;
    /* a chain of at most 2^16 level-0 texels: every level at least halves
     * the one before, so below 2^17 texels (4/3 of level 0 held only for
     * square-ish chains: 16384 x 4 with FXL_TEX_MAX_LOG2 14 needs 1.37) */
    size_t tex_bytes = (size_t)FZ_TEX_MAX_TEXELS0 * 2u * 2u + 64u;
    memset(s, 0, sizeof *s);
    if (fz_guard_alloc(&s->texmem, tex_bytes) || fz_guard_alloc(&s->palmem, 512))
        return -1;
    s->cap = words;
    s->pix_a = (uint16_t *)malloc(words * 2u);
    s->pix_b = (uint16_t *)malloc(words * 2u);
    s->dep_a = (uint16_t *)malloc(words * 2u);
    s->dep_b = (uint16_t *)malloc(words * 2u);
    s->dep_init = (uint16_t *)malloc(words * 2u);
    s->cover = (uint8_t *)malloc((size_t)FZ_MAX_DIM * FZ_MAX_DIM);
    s->probe_cnt = (uint8_t *)malloc((size_t)FZ_MAX_DIM * FZ_MAX_DIM);
    s->texidx = fz_texidx_new();
    if (!s->pix_a || !s->pix_b || !s->dep_a || !s->dep_b || !s->dep_init || !s->cover || !s->probe_cnt ||
        !s->texidx)
        return -1;
    s->ready = 1;
    return 0;
}

static uint32_t fz_xs(uint32_t *x)
{
    uint32_t v = *x;
    v ^= v << 13;
    v ^= v >> 17;
    v ^= v << 5;
    *x = v ? v : 0x9E3779B9u;
    return *x;
}

static uint16_t fz_canary_word(size_t i)
{
    return (uint16_t)(0xA55Au ^ (uint16_t)(i * 0x9E37u));
}

/* Fill texels and palette into guarded memory; point c->tex at them. */
static void fz_place_texture(fz_state *s, fz_case *c)
{
    fxl_texture_t *t = &c->tex;
    uint32_t bpp = t->format == FXL_TEXFMT_RGB565 ? 2u : 1u, L, texels = 0, lw, lh, nl;
    size_t bytes, i;
    uint32_t x = c->tex_seed | 1u;
    uint8_t *dst;

    /* Bytes of the chain the descriptor describes (levels as given, at
     * most a full chain; invalid descriptors get a full chain of memory). */
    lw = t->log2_w > FXL_TEX_MAX_LOG2 ? 0u : t->log2_w;
    lh = t->log2_h > FXL_TEX_MAX_LOG2 ? 0u : t->log2_h;
    nl = t->levels;
    if (nl == 0 || nl > 1u + (lw > lh ? lw : lh))
        nl = 1u + (lw > lh ? lw : lh);
    for (L = 0; L < nl; L++)
        texels += 1u << ((lw > L ? lw - L : 0u) + (lh > L ? lh - L : 0u));
    bytes = (size_t)texels * bpp;
    if (bytes > s->texmem.bytes) {
        /* the harness's own invariant (fz_state_init): a chain cut short
         * here would let the core read past it as if it were the core's fault */
        fprintf(stderr, "fuzz harness: texture chain of %zu bytes exceeds its %zu-byte buffer\n", bytes,
                s->texmem.bytes);
        abort();
    }
    dst = c->tex_at_start ? s->texmem.base : s->texmem.base + s->texmem.bytes - bytes;
    for (i = 0; i < bytes; i++)
        dst[i] = (uint8_t)(fz_xs(&x) >> 24);
    /* Make the key occur so keyed paths run. */
    if ((t->flags & FXL_TEXF_KEY) && bytes >= bpp) {
        for (i = 0; i + bpp <= bytes; i += bpp * (1u + (fz_xs(&x) & 7u))) {
            if (bpp == 2u) {
                uint16_t k = t->key;
                memcpy(dst + i, &k, 2);
            } else {
                dst[i] = (uint8_t)t->key;
            }
        }
    }
    t->texels = dst;
    if (t->format == FXL_TEXFMT_I8 && !c->pal_null) {
        uint16_t *pal = (uint16_t *)(s->palmem.base + s->palmem.bytes - 512u);
        for (i = 0; i < 256; i++)
            pal[i] = (uint16_t)(fz_xs(&x) >> 16);
        t->palette = pal;
    } else {
        t->palette = NULL;
    }
}

/* Set up a target over buf (FZ_CANARY words in) the way a caller would,
 * then apply the raw fields so invalid structs reach the core too. */
static void fz_make_target(const fz_case *c, fxl_target_t *t, uint16_t *buf, uint16_t *depth)
{
    memset(t, 0, sizeof *t);
    t->pixels = buf + FZ_CANARY;
    t->depth = depth ? depth + FZ_CANARY : NULL;
    t->width = c->w;
    t->height = c->h;
    t->stride = c->stride;
    t->origin_x = c->origin_x;
    t->origin_y = c->origin_y;
    t->clip = c->clip;
    t->format = (fxl_pixfmt_t)c->format;
}

static void fz_fill(const fz_case *c, const fz_state *s, uint16_t *pix, uint16_t bg, uint16_t *dep)
{
    size_t n = (size_t)c->stride * (size_t)c->h, i;
    for (i = 0; i < FZ_CANARY; i++) {
        pix[i] = fz_canary_word(i);
        pix[FZ_CANARY + n + i] = fz_canary_word(i + 77u);
    }
    for (i = 0; i < n; i++)
        pix[FZ_CANARY + i] = bg;
    if (dep)
        memcpy(dep, s->dep_init, (n + 2u * FZ_CANARY) * 2u);
}

static int fz_in_clip(const fz_case *c, int32_t col, int32_t row)
{
    int32_t fx = col + c->origin_x, fy = row + c->origin_y;
    return col < c->w && fx >= c->clip.x0 && fx < c->clip.x1 && fy >= c->clip.y0 && fy < c->clip.y1;
}

#define FZ_FAIL(...) do { snprintf(msg, FZ_MSG, __VA_ARGS__); return 1; } while (0)

/* The depth buffer's initial contents (s->dep_init), canaries included. */
static void fz_init_depth(fz_state *s, const fz_case *c)
{
    size_t n = (size_t)c->stride * (size_t)c->h, i;
    uint32_t x = c->depth_init | 0x10000u;

    for (i = 0; i < n + 2u * FZ_CANARY; i++)
        s->dep_init[i] = c->depth_rand ? (uint16_t)(fz_xs(&x) >> 16) : c->depth_init;
    for (i = 0; i < FZ_CANARY; i++) {
        s->dep_init[i] = fz_canary_word(i + 5u);
        s->dep_init[FZ_CANARY + n + i] = fz_canary_word(i + 99u);
    }
}

/* Check 2: the canary words around the pixels (fz_fill) and the depth
 * buffer (dep NULL: none) of one render. */
static int fz_check_canaries(const fz_case *c, const fz_state *s, const uint16_t *pix, const uint16_t *dep,
                             char *msg)
{
    size_t n = (size_t)c->stride * (size_t)c->h, i;

    for (i = 0; i < FZ_CANARY; i++) {
        if (pix[i] != fz_canary_word(i))
            FZ_FAIL("canary before pixels overwritten (word %d)", (int)i - FZ_CANARY);
        if (pix[FZ_CANARY + n + i] != fz_canary_word(i + 77u))
            FZ_FAIL("canary after pixels overwritten (word %d past the end)", (int)i);
        if (dep && (dep[i] != s->dep_init[i] || dep[FZ_CANARY + n + i] != s->dep_init[FZ_CANARY + n + i]))
            FZ_FAIL("depth canary overwritten (word %d)", (int)i);
    }
    return 0;
}

/* Checks 3 and 4 on two renders of one case, pix_a on background 0x0000
 * and pix_b on 0xFFFF (depth dep_a, dep_b, or NULL): every written pixel
 * inside the clip and equal in both, none when !may_write (status st, for
 * the message), depth likewise and only with FXL_DEPTH_WRITE. *written:
 * the pixels either render wrote. */
static int fz_check_writes(const fz_case *c, const fz_state *s, const uint16_t *pix_a, const uint16_t *pix_b,
                           const uint16_t *dep_a, const uint16_t *dep_b, fxl_status_t st, int may_write,
                           uint32_t *written, char *msg)
{
    size_t n = (size_t)c->stride * (size_t)c->h, i;
    int32_t row, col;

    *written = 0;
    for (row = 0; row < c->h; row++)
        for (col = 0; col < c->stride; col++) {
            size_t k = FZ_CANARY + (size_t)row * (size_t)c->stride + (size_t)col;
            uint16_t a = pix_a[k], b = pix_b[k];
            int wa = a != 0x0000u, wb = b != 0xFFFFu;
            if (!wa && !wb)
                continue;
            if (!may_write)
                FZ_FAIL("pixel (%d,%d) written although the draw failed with %s", col, row, fxl_status_name(st));
            if (!fz_in_clip(c, col, row))
                FZ_FAIL("pixel (%d,%d) (frame %d,%d) written outside the clip [%d,%d)x[%d,%d)", col, row,
                        col + c->origin_x, row + c->origin_y, c->clip.x0, c->clip.x1, c->clip.y0, c->clip.y1);
            /* One render kept its background: the drawn value equals it. */
            if ((wa && wb && a != b) || (!wa && b != 0x0000u) || (!wb && a != 0xFFFFu))
                FZ_FAIL("pixel (%d,%d) nondeterministic: %04X vs %04X", col, row, a, b);
            (*written)++;
        }
    if (dep_a)
        for (i = 0; i < n; i++) {
            size_t k = FZ_CANARY + i;
            int32_t rr = (int32_t)(i / (size_t)c->stride), cc = (int32_t)(i % (size_t)c->stride);
            if (dep_a[k] != dep_b[k])
                FZ_FAIL("depth (%d,%d) nondeterministic: %04X vs %04X", cc, rr, dep_a[k], dep_b[k]);
            if (dep_a[k] != s->dep_init[k]) {
                if (!may_write || !fz_in_clip(c, cc, rr))
                    FZ_FAIL("depth (%d,%d) written %s", cc, rr, !may_write ? "on error" : "outside the clip");
                if (!(c->draw.depth & FXL_DEPTH_WRITE))
                    FZ_FAIL("depth (%d,%d) written without FXL_DEPTH_WRITE", cc, rr);
            }
        }
    return 0;
}

/* ---- check 7: texel values --------------------------------------------------- */

#define FZ_ONE ((int64_t)1 << FXL_SUBPIXEL_BITS)   /* sub-pixels a pixel */
#define FZ_TEXEL_SPAN 16   /* widest footprint (texels an axis) check 7 examines */

/* The whole periods (repeat) or pairs of them (mirror) setup.c rebases an
 * axis's vertex coordinates by, in periods; 0 for clamp and border. */
static double fz_rebase_periods(const fz_case *c, int axis)
{
    const uint8_t wrap = axis ? c->tex.wrap_v : c->tex.wrap_u;
    double mn = 1e300;
    int i;
    for (i = 0; i < 3; i++) {
        const double u = (axis ? c->v[i].v : c->v[i].u) / 65536.0;
        mn = u < mn ? u : mn;
    }
    return wrap == FXL_WRAP_REPEAT ? floor(mn) : (wrap == FXL_WRAP_MIRROR ? 2 * floor(mn / 2) : 0);
}

/* The vertex a draw passes set-up first (raster.c, first_vertex): the
 * smallest inv_w, ties to the smallest y, then x. Its planes are anchored
 * there, and fxl_lod_triangle_q8 takes its differences from it. */
static const fxl_vertex_t *fz_first_vertex(const fz_case *c)
{
    const fxl_vertex_t *best = &c->v[0];
    int i;
    for (i = 1; i < 3; i++) {
        const fxl_vertex_t *p = &c->v[i];
        if (p->inv_w < best->inv_w ||
            (p->inv_w == best->inv_w && (p->y < best->y || (p->y == best->y && p->x < best->x))))
            best = p;
    }
    return best;
}

/* Exact mode's error bound, per axis in level-0 texels, at the pixel centre
 * (X, Y) (sub-pixel units, slack more from the anchor: a segment's ends)
 * of the case's triangle: test_raster's
 * exact_plane_bound - the planes of s = u q kept below 2^30 (< 1.51 units of
 * 2^-29 max |s_i| at a vertex: 3.2 2^-30 max |u_i| q_i / q_min texels), the
 * reciprocal's 2^-28 of |u|, the q16 rounding, setup's q = inv_w >> 1 when
 * some inv_w >= 2^31 - plus what that test's targets do not reach: the
 * 2^-21-unit rounding of each plane's gradients (FXL__PF = 20), times the
 * distance D (sub-pixels) from the vertex where the planes are anchored
 * (fz_first_vertex). It
 * moves s by D 2^-21 units and q by D 2^-21 of q's units (q_max scaled to
 * >= 2^30), i.e. D 2^-51 q_max / q_min relative. u is rebased as setup does
 * (whole periods for repeat, pairs for mirror). */
static void fz_exact_bound(const fz_case *c, int64_t X, int64_t Y, int64_t slack, int affine, double b[2])
{
    const fxl_vertex_t *f = fz_first_vertex(c);
    double qmin = 4294967296.0, qmax = 0, qtrunc = 0, D;
    int axis, i;
    for (i = 0; i < 3; i++) {
        const double q = affine ? 1.0 : (double)c->v[i].inv_w;   /* affine: one constant q */
        if (q < qmin)
            qmin = q;
        if (q > qmax)
            qmax = q;
        if (!affine && c->v[i].inv_w >= 0x80000000u)
            qtrunc = 1;
    }
    if (qtrunc)
        qtrunc = 1.0 / floor(qmin / 2);
    /* the distance from the planes' anchor, the vertex set-up takes first
     * (from c->v[0], a pixel 2 px from v[0] and 49,000 px from the anchor
     * had a bound of 0.044 texel against 0.047 drawn: seed 58 case
     * 77738644) */
    D = fabs((double)(X - ref_snap(f->x))) + fabs((double)(Y - ref_snap(f->y))) + (double)slack;
    for (axis = 0; axis < 2; axis++) {
        const double side = ldexp(1.0, axis ? c->tex.log2_h : c->tex.log2_w);
        const double base = fz_rebase_periods(c, axis);
        double mn = 1e300, mx = -1e300, m = 0, umax = 0;
        for (i = 0; i < 3; i++) {
            const double u = (axis ? c->v[i].v : c->v[i].u) / 65536.0;
            mn = u < mn ? u : mn;
            mx = u > mx ? u : mx;
        }
        for (i = 0; i < 3; i++) {
            const double a = fabs((axis ? c->v[i].v : c->v[i].u) / 65536.0 - base) * side;
            const double aq = a * (affine ? 1.0 : (double)c->v[i].inv_w);
            m = aq > m ? aq : m;
            umax = a > umax ? a : umax;
        }
        b[axis] = (3.2 * ldexp(1, -30) + D * ldexp(1, -50)) * m / qmin + ldexp(umax, -27) + ldexp(1, -17) +
                  (mx - mn) * side * qtrunc + umax * D * ldexp(1, -51) * qmax / qmin;
    }
}

/* The level-0 texels [lo, hi] an axis whose values (point) or blend
 * (bilinear: the taps at floor(t - 1/2) and one more) a coordinate within
 * t +- e can read. Returns 0 when that is more than FZ_TEXEL_SPAN. */
static int fz_footprint(double t, double e, int bilinear, int64_t *lo, int64_t *hi)
{
    const double c = bilinear ? t - 0.5 : t;
    if (!(e < FZ_TEXEL_SPAN) || fabs(t) > 1e15)
        return 0;
    *lo = (int64_t)floor(c - e);
    *hi = (int64_t)floor(c + e) + (bilinear ? 1 : 0);
    return *hi - *lo < FZ_TEXEL_SPAN;
}

/* The native RGB565 value render a (background 0x0000) and b (0xFFFF)
 * wrote at buffer pixel (col, row); 0 when neither wrote it. */
static int fz_written_pixel(const fz_case *c, const fz_state *s, int32_t row, int32_t col, uint16_t *px)
{
    const size_t k = FZ_CANARY + (size_t)row * (size_t)c->stride + (size_t)col;
    const uint16_t a = s->pix_a[k], b = s->pix_b[k];
    if (a == 0x0000u && b == 0xFFFFu)
        return 0;
    *px = b != 0xFFFFu ? b : a;   /* one render kept its background: the value is the other's */
    if (c->format == FXL_PIXFMT_RGB565_SWAP)
        *px = (uint16_t)((*px >> 8) | (*px << 8));
    return 1;
}

/* Gouraud channels (r5, g6, b5) are interpolated like u on a one-texel
 * clamp axis (q16 channel values, perspective-correct, clamped, floored),
 * so they have the same bounds: exact mode's plane precision, plus a
 * chord over L pixels (L 0: none; affine: against the screen-linear map). */
typedef struct fz_gouraud {
    fz_case cs[2];   /* channels (r, g) and (b, -) as the u, v of a 1 x 1 clamp texture */
    double chord[2];
    int L, affine;
} fz_gouraud;

static const int fz_ch_shift[3] = {11, 5, 0}, fz_ch_top[3] = {31, 63, 31};

static void fz_gouraud_init(fz_gouraud *g, const fz_case *c, int L, int affine)
{
    int i, k;
    g->L = L;
    g->affine = affine;
    for (k = 0; k < 2; k++) {
        g->cs[k] = *c;
        g->cs[k].tex.log2_w = g->cs[k].tex.log2_h = 0;
        g->cs[k].tex.wrap_u = g->cs[k].tex.wrap_v = FXL_WRAP_CLAMP;
        for (i = 0; i < 3; i++) {
            const uint32_t col565 = c->v[i].color;
            g->cs[k].v[i].u = (fxl_q16_t)(((col565 >> fz_ch_shift[2 * k]) & (uint32_t)fz_ch_top[2 * k]) << 16);
            g->cs[k].v[i].v = k ? 0 : (fxl_q16_t)(((col565 >> 5) & 63u) << 16);
        }
        g->chord[k] = !L ? 0 : (affine ? L / 65536.0 : ref_chord_bound(g->cs[k].v, 0, 0, L));
    }
}

/* The channel values [lo, hi] the draw may show at frame pixel (fx, fy). */
static void fz_gouraud_range(const fz_gouraud *g, int64_t fx, int64_t fy, int lo[3], int hi[3])
{
    int ch;
    for (ch = 0; ch < 3; ch++) {
        const fz_case *cs = &g->cs[ch >> 1];
        double val[2] = {0, 0}, e[2], l, h;
        (void)ref_uv_at(cs->v, (double)fx + 0.5, (double)fy + 0.5, g->affine, &val[0], &val[1], NULL, NULL);
        fz_exact_bound(cs, fx * FZ_ONE + FZ_ONE / 2, fy * FZ_ONE + FZ_ONE / 2, FZ_ONE * (int64_t)g->L, g->affine, e);
        l = floor(val[ch == 1] - e[ch == 1] - g->chord[ch >> 1]);
        h = floor(val[ch == 1] + e[ch == 1] + g->chord[ch >> 1]);
        /* (a bound that is not finite allows the whole channel) */
        lo[ch] = !(l > 0) ? 0 : (l > fz_ch_top[ch] ? fz_ch_top[ch] : (int)l);
        hi[ch] = !(h < fz_ch_top[ch]) ? fz_ch_top[ch] : (h < 0 ? 0 : (int)h);
    }
}

/* Does a clamp or border axis have a vertex 2^31 - 2^16 q16 texels or more
 * from 0 (setup.c, rebase)? The triangle is then divided at every pixel
 * whatever persp says (raster.h). */
static int fz_clamp_saturates(const fz_case *c)
{
    int axis, i;
    for (axis = 0; FXL_HAVE_GENERIC && axis < 2; axis++) {
        const uint8_t wrap = axis ? c->tex.wrap_v : c->tex.wrap_u;
        const int64_t lim = (int64_t)(0x7FFF0000u >> (axis ? c->tex.log2_h : c->tex.log2_w));
        for (i = 0; i < 3 && wrap >= FXL_WRAP_CLAMP; i++) {
            const int64_t t = axis ? c->v[i].v : c->v[i].u;
            if (t >= lim || t <= -lim)
                return 1;
        }
    }
    return 0;
}

/* Does some plane of the draw have a gradient of 2^38 of its units a
 * sub-pixel or more (setup.c, gradient: a needle-like sliver)? The core
 * then divides at every pixel and takes the triangle's LOD (raster.h).
 * A double estimate of setup's scaled planes: 2 surely, 1 near the
 * boundary (either may happen), 0 surely not. */
static int fz_gradient_huge(const fz_case *c)
{
    const fxl_draw_t *d = &c->draw;
    const int affine = d->persp == FXL_PERSP_AFFINE;
    const int hl = FXL_SUBPIXEL_BITS > 4 ? 42 - FXL_SUBPIXEL_BITS : 38;
    double X[3], Y[3], q[3], det, worst = 0;
    uint32_t mx = 0;
    int i, p, sh;
    for (i = 0; i < 3; i++) {
        X[i] = (double)ref_snap(c->v[i].x);
        Y[i] = (double)ref_snap(c->v[i].y);
        mx = c->v[i].inv_w > mx ? c->v[i].inv_w : mx;
    }
    det = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    if (det == 0 || mx == 0)
        return 0;
    sh = 0;
    while (sh < 31 && !(mx & (0x80000000u >> sh)))
        sh++;
    sh--;   /* clz - 1: q_max in [2^30, 2^31) */
    for (i = 0; i < 3; i++) {
        q[i] = affine ? 1073741824.0 : (sh >= 0 ? ldexp(c->v[i].inv_w, sh) : floor(c->v[i].inv_w / 2.0));
        q[i] = q[i] < 1 ? 1 : q[i];
    }
    /* the planes: q; z (inv_w) where a depth buffer is tested or written;
     * u, v (rebased) and the channels times q, scaled below 2^30 */
    for (p = -2; p < 5; p++) {
        double m = 0, v3[3], base = 0, da1, da2, nx, ny, g;
        int k;
        if (p == -1 && !(c->has_depth && (d->depth & (FXL_DEPTH_TEST | FXL_DEPTH_WRITE))))
            continue;
        if (p >= 0 && (p < 2 ? !d->texture : d->shade != FXL_SHADE_GOURAUD))
            continue;
        if (p == 0 || p == 1)
            base = fz_rebase_periods(c, p) * 65536;
        for (i = 0; i < 3; i++) {
            static const int csh[3] = {11, 5, 0}, ctop[3] = {31, 63, 31};
            if (p == -2)
                v3[i] = q[i];
            else if (p == -1)
                v3[i] = c->v[i].inv_w;
            else if (p < 2)
                v3[i] = ((p ? c->v[i].v : c->v[i].u) - base) * q[i];
            else
                v3[i] = (double)(((uint32_t)c->v[i].color >> csh[p - 2]) & (uint32_t)ctop[p - 2]) * 65536 * q[i];
            m = fabs(v3[i]) > m ? fabs(v3[i]) : m;
        }
        /* fit_shift(s, 30): the smallest k with m >> k < 2^30 */
        for (k = 0; p >= 0 && m >= 1073741824.0; k++)
            m /= 2;
        da1 = ldexp(v3[1] - v3[0], -k);
        da2 = ldexp(v3[2] - v3[0], -k);
        nx = fabs(da1 * (Y[2] - Y[0]) - da2 * (Y[1] - Y[0]));
        ny = fabs(da2 * (X[1] - X[0]) - da1 * (X[2] - X[0]));
        g = (nx > ny ? nx : ny) / fabs(det);
        worst = g > worst ? g : worst;
    }
    /* setup.c's FXL__HUGE_LOG2: 2^42 units a pixel, 2^38 a sub-pixel at S <= 4 */
    return worst >= ldexp(1.001, hl) ? 2 : (worst >= ldexp(0.999, hl) ? 1 : 0);
}

/* The frame column of the first pixel of the triangle's span on frame row
 * fy, whose pixel fx is covered: spans are convex, and no pixel left of
 * -2^17 is (|x| < 32768 px). */
static int64_t fz_span_first(const fz_case *c, int64_t fx, int64_t fy)
{
    int64_t lo = -((int64_t)1 << 17), hi = fx;   /* lo not covered, hi covered */
    while (hi - lo > 1) {
        const int64_t mid = lo + (hi - lo) / 2;
        if (ref_pixel_covered(c->v, (int32_t)mid, (int32_t)fy))
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

/* q (the vertices' inv_w, linear in screen space) as a plane in pixels:
 * its value at vertex 0, its gradient, and the least vertex q, which the
 * core clamps to; plane 0 for a zero-area triangle (no plane), ok 0 for
 * that or an affine draw (q constant there: no LOD term; the depth plane,
 * check 8, is the same in every mode). Set up once per case by each check
 * that reads it (three vertices: cheap beside the renders). */
typedef struct fz_qplane {
    double x0, y0, q0, qx, qy, qmin;
    int plane, ok;
} fz_qplane;

static void fz_qplane_init(const fz_case *c, fz_qplane *p)
{
    const double grid = ldexp(1.0, FXL_SUBPIXEL_BITS);   /* sub-pixels a pixel */
    double X[3], Y[3], q[3], det;
    int i;
    for (i = 0; i < 3; i++) {
        X[i] = (double)ref_snap(c->v[i].x) / grid;
        Y[i] = (double)ref_snap(c->v[i].y) / grid;
        q[i] = (double)c->v[i].inv_w;
    }
    det = (X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0]);
    p->plane = det != 0;
    p->ok = p->plane && c->draw.persp != FXL_PERSP_AFFINE;
    if (!p->plane)
        return;
    p->x0 = X[0];
    p->y0 = Y[0];
    p->q0 = q[0];
    p->qx = ((q[1] - q[0]) * (Y[2] - Y[0]) - (q[2] - q[0]) * (Y[1] - Y[0])) / det;
    p->qy = ((q[2] - q[0]) * (X[1] - X[0]) - (q[1] - q[0]) * (X[2] - X[0])) / det;
    p->qmin = fmin(q[0], fmin(q[1], q[2]));
}

/* A per-segment LOD is measured from the core's u, v at the correction
 * point: du/dg = (S_g - u q_g) / q (span.c, lod_at), so an error e of u, v
 * there moves each derivative by up to e |q_g| / q. Where exact mode's
 * coordinates lose their precision (a large depth ratio times the rebased
 * range: stability.md, "range") that term can exceed the derivative
 * itself, as at the far edge of a triangle of depth ratio 10^9, whose v
 * was a period (16 texels) off and its LOD 15 levels high (seed 61, case
 * 6260750). Widens the reference's [lo, hi] (LOD, bias added) at frame
 * point (px, py) by it: log2 of the sum of the magnitudes above, log2 of
 * their difference (or -inf) below. */
static void fz_lod_widen(const fz_case *c, const fz_qplane *p, double px, double py, double *lo, double *hi)
{
    const double grid = ldexp(1.0, FXL_SUBPIXEL_BITS);
    double q, e[2], n, ln;
    if (!p->ok)
        return;
    q = fmax(p->q0 + p->qx * (px - p->x0) + p->qy * (py - p->y0), p->qmin);
    fz_exact_bound(c, (int64_t)floor(px * grid), (int64_t)floor(py * grid), 0, 0, e);
    /* texels a pixel of level 0; the LOD's derivatives are in those */
    n = hypot(e[0], e[1]) * fmax(fabs(p->qx), fabs(p->qy)) / q;
    if (!(n > 0))
        return;
    ln = log2(n) + c->draw.lod_bias_q8 / 256.0;
    *hi = log2(exp2(*hi) + exp2(ln));
    *lo = ln >= *lo ? -1e300 : log2(exp2(*lo) - exp2(ln));
}

/* Check 7 (see the top) on render a (background 0x0000) and b (0xFFFF). */
static int fz_check_texels(const fz_case *c, const fz_state *s, fz_outcome *out, char *msg)
{
    const fxl_draw_t *d = &c->draw;
    const int bil = d->filter == FXL_FILTER_BILINEAR;
    int32_t row, col;

    /* segment length of a fixed mode (affine re-anchors every 256 pixels) */
    const int L = d->persp == FXL_PERSP_AFFINE ? FXL_PERSP_MAX : (d->persp > 1 ? d->persp : 0);
    const int affine = d->persp == FXL_PERSP_AFFINE;
    /* the colour's channels, for modulate (raster.h: t (c + 1) >> bits) and
     * decal: the flat one, or per pixel a Gouraud interval (AUTO picks its
     * lengths for u, v: up to 256 pixels for the colours) */
    const int modulate = d->texenv == FXL_TEXENV_MODULATE, decal = d->texenv == FXL_TEXENV_DECAL;
    const int gouraud = d->shade == FXL_SHADE_GOURAUD && d->texenv != FXL_TEXENV_REPLACE;
    int clo[3] = {d->color >> 11, (d->color >> 5) & 63, d->color & 31};
    int chi[3] = {d->color >> 11, (d->color >> 5) & 63, d->color & 31};
    fz_gouraud g;
    /* Mip levels: with one LOD for the triangle, the levels its LOD can
     * round to (the reference's, within 4/256 level: test_lod holds the
     * core to 2/256), clamped to the chain; a pixel on level n reads it
     * with its coordinates shifted (floored) by min(n, log2 side) an axis,
     * and steps of that level drift by up to 2^-16 of its texels a pixel
     * over a segment (raster.h, auto_budget). A blend of levels (LINEAR)
     * lies within the union of their texels. */
    const int mips = c->tex.levels > 1 && d->mip != FXL_MIP_NONE;
    const int linear = mips && d->mip == FXL_MIP_LINEAR;
    const int blend = bil || linear;
    /* A per-segment LOD is taken at the segment's first pixel. A fixed
     * length L starts its segments at the span's first pixel and every L-th
     * (raster.h; exact mode: every pixel): one candidate. AUTO takes it at
     * its 16-pixel grid points: one of the W = 16 pixels up to this one. */
    const int per_seg = mips && d->lod == FXL_LOD_SEGMENT;
    const int auto_lod = d->persp == FXL_PERSP_AUTO, W = 16;
    /* a needle's gradients (fz_gradient_huge): every pixel a correction
     * point, the triangle's LOD (1: that or the usual) */
    const int huge = d->texture ? fz_gradient_huge(c) : 0;
    const int seg_lod_on = per_seg && huge != 2;
    const int64_t seg_len = d->persp == FXL_PERSP_EXACT || fz_clamp_saturates(c) || huge == 2 ? 1 : L;
    int tri_lo = 0, tri_hi = 0;
    int64_t span_first = 0, seg_first = INT64_MIN;
    double seg_lod = 0, seg_lod_hi = 0;
    double chord = 0, drift = 0;
    int n_lo = 0, n_hi = 0;
    /* the exact LOD (bias added; AUTO: perspective and affine) at columns
     * col - 15 .. of the current row */
    double lod_lo[FZ_MAX_DIM + 16], lod_hi[FZ_MAX_DIM + 16];
    uint8_t lod_known[FZ_MAX_DIM + 16];
    int32_t lod_row = -1;
    fz_qplane qpl;               /* q's plane, for fz_lod_widen */
    double lod_noise = -1e300;   /* per segment: the LOD of rounding-noise derivatives, bias added */
    /* Levels not known (every level may be read): a per-triangle LOD from
     * coordinate differences of 2^31 units or more, which raster.h halves
     * (a texture-space sliver's area then loses its precision). The
     * differences are taken from the vertex the draw passes first
     * (fz_first_vertex): from c->v[0], u = 0, -3 and 2^31 - 1 with v2 first
     * (every inv_w equal, v2 the topmost) read level 3 where v[0]'s order
     * gives 3.59, level 4 (fixel-fuzz seed 1 case 123457080563, a review's
     * run). */
    int all_levels = 0;

    if (!d->texture)
        return 0;
    fz_texidx_reset(s->texidx);
    fz_qplane_init(c, &qpl);
    if (gouraud)
        fz_gouraud_init(&g, c, d->persp == FXL_PERSP_AUTO ? FXL_PERSP_MAX : L, affine);
    /* affine: against the screen-linear map, to which it is exact but for
     * its steps' truncation */
    if (L)
        chord = affine ? L / 65536.0 : ref_chord_bound(c->v, c->tex.log2_w, c->tex.log2_h, L);
    if (mips && (!per_seg || huge)) {
        const double top = (double)c->tex.levels - 1, tol = 4.0 / 256;
        double lod = ref_lod_triangle(&c->tex, c->v) + d->lod_bias_q8 / 256.0, lo, hi;
        const fxl_vertex_t *f = fz_first_vertex(c);
        int i;
        for (i = 0; i < 3; i++)
            if (fabs((double)c->v[i].u - f->u) >= 2147483648.0 || fabs((double)c->v[i].v - f->v) >= 2147483648.0)
                all_levels = 1;
        lod = lod < 0 ? 0 : (lod > top ? top : lod);   /* also -HUGE_VAL (no texel area) */
        lo = lod - tol < 0 ? 0 : lod - tol;
        hi = lod + tol > top ? top : lod + tol;
        n_lo = (int)floor(linear ? lo : lo + 0.5);
        n_hi = (int)floor(linear ? hi : hi + 0.5) + linear;
        n_hi = n_hi > (int)top ? (int)top : n_hi;
        tri_lo = n_lo;
        tri_hi = n_hi;
    }
    if (mips)
        drift = (d->persp == FXL_PERSP_AUTO || affine ? FXL_PERSP_MAX : (L ? L : 1)) / 65536.0;
    if (all_levels) {
        n_lo = 0;
        n_hi = (int)c->tex.levels - 1;
    }
    if (seg_lod_on && !all_levels) {
        double qmin = 4294967296.0, qmax = 0, umax = 0;
        int i, ax;
        for (i = 0; i < 3; i++) {
            qmin = c->v[i].inv_w < qmin ? c->v[i].inv_w : qmin;
            qmax = c->v[i].inv_w > qmax ? c->v[i].inv_w : qmax;
            for (ax = 0; ax < 2; ax++) {
                const double t = fabs((ax ? c->v[i].v : c->v[i].u) / 65536.0) *
                                 ldexp(1.0, ax ? c->tex.log2_h : c->tex.log2_w);
                umax = t > umax ? t : umax;
            }
        }
        lod_noise = log2(ldexp(umax + 1, -20) * (affine ? 1 : qmax / qmin)) + d->lod_bias_q8 / 256.0;
    }
    for (row = 0; row < c->h; row++)
        for (col = 0; col < c->w; col++) {
            const int64_t fx = (int64_t)col + c->origin_x, fy = (int64_t)row + c->origin_y;
            uint16_t px;
            double u, v, e[2];
            int64_t box[4] = {0, 0, 0, 0}, x, y;
            int lo[3] = {255, 255, 255}, hi[3] = {0, 0, 0}, hit = 0, keyed = 0, ch, n, wide = 0, ranged = 0;
            if (!fz_written_pixel(c, s, row, col, &px))
                continue;
            if (gouraud)
                fz_gouraud_range(&g, fx, fy, clo, chi);
            if (ref_uv_at(c->v, (double)fx + 0.5, (double)fy + 0.5, affine, &u, &v, NULL, NULL) != 0)
                FZ_FAIL("pixel (%d,%d) written on a zero-area triangle", col, row);
            /* a segment's ends are up to L pixels from the pixel: the
             * planes' rounding grows with the distance from their anchor */
            fz_exact_bound(c, fx * FZ_ONE + FZ_ONE / 2, fy * FZ_ONE + FZ_ONE / 2, FZ_ONE * (int64_t)L, affine, e);
            e[0] += chord;
            e[1] += chord;
            if (d->persp == FXL_PERSP_AUTO) {
                const double budget = (d->auto_budget > (1 << 24) ? (1 << 24) : d->auto_budget) / 65536.0;
                e[0] += budget;
                e[1] += budget;
            }
            if (seg_lod_on && !all_levels) {
                /* the levels the exact LOD (within 4/256: test_lod) at the
                 * segment's correction point (AUTO: any of W candidates) rounds to */
                const double top = (double)c->tex.levels - 1, tol = 4.0 / 256;
                double lmin = 1e300, lmax = -1e300, du[2], dv[2];
                int j;
                if (lod_row != row) {
                    lod_row = row;
                    for (j = 0; j < FZ_MAX_DIM + 16; j++)
                        lod_known[j] = 0;
                    seg_first = INT64_MIN;
                    if (!auto_lod)
                        span_first = fz_span_first(c, fx, fy);
                }
                if (!auto_lod) {
                    /* the one correction point of this pixel's segment */
                    const int64_t x0 = span_first + (fx - span_first) / seg_len * seg_len;
                    if (x0 != seg_first) {
                        seg_first = x0;
                        (void)ref_uv_at(c->v, (double)x0 + 0.5, (double)fy + 0.5, affine, NULL, NULL, du, dv);
                        seg_lod = seg_lod_hi = ref_lod_pixel(&c->tex, du, dv) + d->lod_bias_q8 / 256.0;
                        fz_lod_widen(c, &qpl, (double)x0 + 0.5, (double)fy + 0.5, &seg_lod, &seg_lod_hi);
                    }
                    lmin = seg_lod;
                    lmax = seg_lod_hi;
                    if (huge) {   /* or divided at this pixel */
                        double here, here_hi;
                        (void)ref_uv_at(c->v, (double)fx + 0.5, (double)fy + 0.5, affine, NULL, NULL, du, dv);
                        here = here_hi = ref_lod_pixel(&c->tex, du, dv) + d->lod_bias_q8 / 256.0;
                        fz_lod_widen(c, &qpl, (double)fx + 0.5, (double)fy + 0.5, &here, &here_hi);
                        lmin = here < lmin ? here : lmin;
                        lmax = here_hi > lmax ? here_hi : lmax;
                    }
                }
                for (j = 0; auto_lod && j < W; j++) {
                    /* cached by column: pixels of a row share candidates */
                    const int ci = col - j + 15;
                    if (!lod_known[ci]) {
                        (void)ref_uv_at(c->v, (double)(fx - j) + 0.5, (double)fy + 0.5, affine, NULL, NULL, du, dv);
                        lod_lo[ci] = lod_hi[ci] = ref_lod_pixel(&c->tex, du, dv) + d->lod_bias_q8 / 256.0;
                        fz_lod_widen(c, &qpl, (double)(fx - j) + 0.5, (double)fy + 0.5, &lod_lo[ci], &lod_hi[ci]);
                        if (d->persp == FXL_PERSP_AUTO) {
                            /* a triangle AUTO draws affine (its vertex test)
                             * takes the LOD of the affine map it draws */
                            double la;
                            (void)ref_uv_at(c->v, (double)(fx - j) + 0.5, (double)fy + 0.5, 1, NULL, NULL, du, dv);
                            la = ref_lod_pixel(&c->tex, du, dv) + d->lod_bias_q8 / 256.0;
                            lod_lo[ci] = la < lod_lo[ci] ? la : lod_lo[ci];
                            lod_hi[ci] = la > lod_hi[ci] ? la : lod_hi[ci];
                        }
                        lod_known[ci] = 1;
                    }
                    lmin = lod_lo[ci] < lmin ? lod_lo[ci] : lmin;
                    lmax = lod_hi[ci] > lmax ? lod_hi[ci] : lmax;
                }
                /* Derivatives near zero (u, v nearly constant) are rounding
                 * noise of the planes, ~2^-30 of their values: the core's
                 * LOD is then anything up to log2 of that (generously
                 * 2^-20 (U + 1) R texels a pixel), which a bias can lift
                 * into the chain while the exact LOD is -inf; and where the
                 * reference's LOD is below that, its own long-double rounding
                 * (~2^-44 texels a pixel) may stand for a -inf the core sees. */
                lmax = lmax > lod_noise ? lmax : lod_noise;
                if (lmin < lod_noise)
                    lmin = -1e300;   /* below the noise the reference's own rounding is no better */
                lmin = lmin - tol < 0 ? 0 : (lmin - tol > top ? top : lmin - tol);   /* NaN-free: -inf clamps */
                lmax = lmax + tol < 0 ? 0 : (lmax + tol > top ? top : lmax + tol);
                n_lo = (int)floor(linear ? lmin : lmin + 0.5);
                n_hi = (int)floor(linear ? lmax : lmax + 0.5) + linear;
                n_hi = n_hi > (int)top ? (int)top : n_hi;
                if (huge) {   /* or the triangle's LOD */
                    n_lo = tri_lo < n_lo ? tri_lo : n_lo;
                    n_hi = tri_hi > n_hi ? tri_hi : n_hi;
                }
            }
            for (n = n_lo; n <= n_hi; n++) {
                /* level n: an axis stops halving at one texel */
                const int su = n < (int)c->tex.log2_w ? n : (int)c->tex.log2_w;
                const int sv = n < (int)c->tex.log2_h ? n : (int)c->tex.log2_h;
                const double tu = u * ldexp(1.0, (int)c->tex.log2_w - su);
                const double tv = v * ldexp(1.0, (int)c->tex.log2_h - sv);
                const double extra = n > 0 ? drift + 1.0 / 65536 : 0;   /* + the shift's floor */
                if (!fz_footprint(tu, ldexp(e[0], -su) + extra, bil, &box[0], &box[1]) ||
                    !fz_footprint(tv, ldexp(e[1], -sv) + extra, bil, &box[2], &box[3])) {
                    /* too many texels to read: the level's index */
                    fz_level_idx *lv = fz_level(s->texidx, &c->tex, (uint32_t)n);
                    const double cu = bil ? tu - 0.5 : tu, cv = bil ? tv - 0.5 : tv;
                    const double eu = ldexp(e[0], -su) + extra, ev = ldexp(e[1], -sv) + extra;
                    fz_axis au, av;
                    fz_block r = fz_block_empty;
                    int i, j;
                    wide = 1;
                    fz_axis_make(floor(cu - eu), floor(cu + eu) + bil, lv->lw, c->tex.wrap_u, &au);
                    fz_axis_make(floor(cv - ev), floor(cv + ev) + bil, lv->lh, c->tex.wrap_v, &av);
                    if (blend || modulate || decal) {   /* (replace needs no key) */
                        for (j = 0; j < av.n; j++)
                            for (i = 0; i < au.n; i++)
                                fz_level_range(lv, au.lo[i], au.hi[i], av.lo[j], av.hi[j], &r);
                        keyed |= r.keyed;
                    }
                    if (!blend && !modulate) {
                        /* a point sample is one texel: exactly */
                        hit |= fz_level_has_colour(s->texidx, lv, &au, &av, px) ||
                               ((au.border || av.border) && px == c->tex.border);
                        continue;
                    }
                    if (au.border || av.border) {
                        const uint16_t b = c->tex.border;
                        const fz_block bb = {{(uint8_t)(b >> 11), (uint8_t)((b >> 5) & 63u), (uint8_t)(b & 31u)},
                                             {(uint8_t)(b >> 11), (uint8_t)((b >> 5) & 63u), (uint8_t)(b & 31u)},
                                             0};
                        fz_block_add(&r, &bb);
                    }
                    for (ch = 0; ch < 3; ch++) {
                        lo[ch] = r.lo[ch] < lo[ch] ? r.lo[ch] : lo[ch];
                        hi[ch] = r.hi[ch] > hi[ch] ? r.hi[ch] : hi[ch];
                    }
                    ranged = 1;
                    continue;
                }
                for (y = box[2]; y <= box[3] && !hit; y++)
                    for (x = box[0]; x <= box[1] && !hit; x++) {
                        int key = 0;
                        const uint16_t t = fxl_texture_fetch(&c->tex, (uint32_t)n, (int32_t)x, (int32_t)y, &key);
                        const int tc[3] = {t >> 11, (t >> 5) & 63, t & 31};
                        if (key) {
                            /* never drawn but with decal, which draws the colour;
                             * a keyed bilinear tap takes the nearest's colour */
                            keyed = 1;
                            continue;
                        }
                        if (!blend) {
                            /* modulate is monotonic in the colour */
                            hit = 1;
                            for (ch = 0; ch < 3; ch++) {
                                const int sh = ch == 1 ? 6 : 5, p = (px >> fz_ch_shift[ch]) & fz_ch_top[ch];
                                hit &= modulate ? p >= (tc[ch] * (clo[ch] + 1)) >> sh &&
                                                      p <= (tc[ch] * (chi[ch] + 1)) >> sh
                                                : p == tc[ch];
                            }
                            continue;
                        }
                        for (ch = 0; ch < 3; ch++) {
                            lo[ch] = tc[ch] < lo[ch] ? tc[ch] : lo[ch];
                            hi[ch] = tc[ch] > hi[ch] ? tc[ch] : hi[ch];
                        }
                    }
            }
            if (wide)
                out->texel_wide++;
            /* a blend, or a modulated point sample of a level read through
             * its index, within the channel range (lo > hi: no texel) */
            if (blend || (ranged && !hit)) {
                /* modulate scales the blend, per channel and monotonically */
                const int pc[3] = {px >> 11, (px >> 5) & 63, px & 31};
                hit = 1;
                for (ch = 0; ch < 3; ch++) {
                    const int sh = ch == 1 ? 6 : 5;
                    const int l = modulate ? (lo[ch] * (clo[ch] + 1)) >> sh : lo[ch];
                    const int h = modulate ? (hi[ch] * (chi[ch] + 1)) >> sh : hi[ch];
                    hit &= pc[ch] >= l && pc[ch] <= h;
                }
            }
            if (decal && keyed && !hit) {
                /* the colour where the texel is keyed */
                hit = 1;
                for (ch = 0; ch < 3; ch++) {
                    const int p = (px >> fz_ch_shift[ch]) & fz_ch_top[ch];
                    hit &= p >= clo[ch] && p <= chi[ch];
                }
            }
            if (!hit)
                FZ_FAIL("pixel (%d,%d) (frame %lld,%lld) is %04X, no %s of texels [%lld,%lld]x[%lld,%lld] (levels "
                        "%d..%d) around the exact level-0 (%.6f, %.6f) +- (%.3g, %.3g)",
                        col, row, (long long)fx, (long long)fy, px, blend ? "blend" : "one", (long long)box[0],
                        (long long)box[1], (long long)box[2], (long long)box[3], n_lo, n_hi,
                        u * ldexp(1.0, c->tex.log2_w), v * ldexp(1.0, c->tex.log2_h), e[0], e[1]);
            out->texel_checked++;
        }
    return 0;
}

/* Check 8 (see the top): the depth values written, against the inv_w
 * plane through the snapped vertices (fz_qplane; |inv_w| < 2^32 and pixel
 * distances < 2^17: far inside double precision). */
static int fz_check_depth(const fz_case *c, const fz_state *s, fz_outcome *out, char *msg)
{
    fz_qplane z;
    int32_t row, col;
    if (!c->has_depth || !(c->draw.depth & FXL_DEPTH_WRITE))
        return 0;
    fz_qplane_init(c, &z);
    if (!z.plane)
        return 0;
    for (row = 0; row < c->h; row++)
        for (col = 0; col < c->w; col++) {
            const double fx = (double)col + c->origin_x + 0.5, fy = (double)row + c->origin_y + 0.5;
            const double q = z.q0 + z.qx * (fx - z.x0) + z.qy * (fy - z.y0), want = floor(q / 65536.0);
            uint16_t px, got;
            if (!fz_written_pixel(c, s, row, col, &px))
                continue;
            got = s->dep_a[FZ_CANARY + (size_t)row * (size_t)c->stride + (size_t)col];
            if (fabs((double)got - want) > 1.0)
                FZ_FAIL("pixel (%d,%d) (frame %.0f,%.0f) stores depth %04X, the exact inv_w %.1f (>> 16: %04X)", col,
                        row, fx - 0.5, fy - 0.5, got, q, (unsigned)want);
            out->depth_checked++;
        }
    return 0;
}

/* Check 7 for untextured draws: a flat one writes its colour exactly; a
 * Gouraud one each channel within its interpolation's bound (fz_gouraud). */
static int fz_check_colors(const fz_case *c, const fz_state *s, fz_outcome *out, char *msg)
{
    const fxl_draw_t *d = &c->draw;
    /* AUTO chooses lengths for texture coordinates: untextured, it draws
     * FXL_PERSP_SPAN segments (raster.h, auto_budget) */
    const int L = d->persp == FXL_PERSP_AFFINE ? FXL_PERSP_MAX
                  : d->persp == FXL_PERSP_AUTO ? FXL_PERSP_SPAN : (d->persp > 1 ? d->persp : 0);
    fz_gouraud g;
    int32_t row, col;

    if (d->texture)
        return 0;
    fz_gouraud_init(&g, c, L, d->persp == FXL_PERSP_AFFINE);
    for (row = 0; row < c->h; row++)
        for (col = 0; col < c->w; col++) {
            const int64_t fx = (int64_t)col + c->origin_x, fy = (int64_t)row + c->origin_y;
            uint16_t px;
            int ch, lo[3], hi[3];
            if (!fz_written_pixel(c, s, row, col, &px))
                continue;
            if (d->shade == FXL_SHADE_FLAT) {
                if (px != d->color)
                    FZ_FAIL("pixel (%d,%d) is %04X, the flat colour %04X", col, row, px, d->color);
                out->texel_checked++;
                continue;
            }
            fz_gouraud_range(&g, fx, fy, lo, hi);
            for (ch = 0; ch < 3; ch++) {
                const int p = (px >> fz_ch_shift[ch]) & fz_ch_top[ch];
                if (p < lo[ch] || p > hi[ch])
                    FZ_FAIL("pixel (%d,%d) (frame %lld,%lld) is %04X: channel %d is %d, the interpolation allows "
                            "%d..%d",
                            col, row, (long long)fx, (long long)fy, px, ch, p, lo[ch], hi[ch]);
            }
            out->texel_checked++;
        }
    return 0;
}

/* Run one decoded case. Returns 0 when every check holds, 1 with a message
 * in msg (FZ_MSG bytes) otherwise. */
static int fz_run_case(fz_state *s, fz_case *c, fz_outcome *out, char *msg)
{
    fxl_target_t ta, tb;
    fxl_stats_t sa, sb, sp;
    fxl_status_t st_a, st_b, st_p, st_chk;
    uint32_t allowed, written = 0, covered = 0;
    int32_t row, col;
    int need_equal;
    long det;

    msg[0] = 0;
    memset(out, 0, sizeof *out);
    if (c->has_tex)
        fz_place_texture(s, c);
    if (c->has_depth)
        fz_init_depth(s, c);
    fz_fill(c, s, s->pix_a, 0x0000u, c->has_depth ? s->dep_a : NULL);
    fz_fill(c, s, s->pix_b, 0xFFFFu, c->has_depth ? s->dep_b : NULL);
    fz_make_target(c, &ta, s->pix_a, c->has_depth ? s->dep_a : NULL);
    fz_make_target(c, &tb, s->pix_b, c->has_depth ? s->dep_b : NULL);

    memset(&sa, 0, sizeof sa);
    memset(&sb, 0, sizeof sb);
    st_a = fxl_draw_triangle(&ta, &c->draw, c->v, &sa);
    st_b = fxl_draw_triangle(&tb, &c->draw, c->v, &sb);
    out->status = st_a;

    /* 2: canaries */
    if (fz_check_canaries(c, s, s->pix_a, c->has_depth ? s->dep_a : NULL, msg) ||
        fz_check_canaries(c, s, s->pix_b, c->has_depth ? s->dep_b : NULL, msg))
        return 1;
    /* 1: status */
    if (st_a != st_b)
        FZ_FAIL("nondeterministic status: %s then %s", fxl_status_name(st_a), fxl_status_name(st_b));
    allowed = fz_expected_errors(c);
    /* fxl_draw_check answers for every triangle: its error is the draw's,
     * and after its FXL_OK only the vertices can fail (FXL_ERR_RANGE) */
    st_chk = fxl_draw_check(&ta, &c->draw);
    if (st_chk != FXL_OK ? st_a != st_chk : (st_a != FXL_OK && st_a != FXL_ERR_RANGE))
        FZ_FAIL("status %s, but fxl_draw_check says %s", fxl_status_name(st_a), fxl_status_name(st_chk));
    if (allowed == 0 && st_a != FXL_OK)
        FZ_FAIL("status %s for a valid case", fxl_status_name(st_a));
    if (allowed != 0 && (st_a == FXL_OK || (fz_status_bit(st_a) & allowed) == 0))
        FZ_FAIL("status %s, expected one of%s%s%s", fxl_status_name(st_a), (allowed & FZ_E_ARG) ? " ARG" : "",
                (allowed & FZ_E_RANGE) ? " RANGE" : "", (allowed & FZ_E_UNSUP) ? " UNSUPPORTED" : "");

    /* 3, 4: written pixels, clip, determinism */
    if (fz_check_writes(c, s, s->pix_a, s->pix_b, c->has_depth ? s->dep_a : NULL, c->has_depth ? s->dep_b : NULL,
                        st_a, st_a == FXL_OK, &written, msg))
        return 1;
    out->written = written;
    if (st_a != FXL_OK)
        return 0;

    /* 6: stats */
    if (sa.pixels != written || sb.pixels != written)
        FZ_FAIL("stats.pixels %u/%u but %u pixels written", (unsigned)sa.pixels, (unsigned)sb.pixels, (unsigned)written);
    if (sa.triangles != 1)
        FZ_FAIL("stats.triangles %u", (unsigned)sa.triangles);
    {
        int64_t X[3], Y[3];
        int k;
        for (k = 0; k < 3; k++) {
            X[k] = ref_snap(c->v[k].x);
            Y[k] = ref_snap(c->v[k].y);
        }
        det = ((X[1] - X[0]) * (Y[2] - Y[0]) - (X[2] - X[0]) * (Y[1] - Y[0])) != 0;
        if (!det && sa.culled_degenerate != 1)
            FZ_FAIL("zero-area triangle not counted as culled_degenerate");
        if (!det && written)
            FZ_FAIL("zero-area triangle wrote %u pixels", (unsigned)written);
    }

    /* 5: coverage */
    {
        int32_t cx0 = c->clip.x0, cy0 = c->clip.y0, cw = c->clip.x1 - c->clip.x0, ch = c->clip.y1 - c->clip.y0;
        memset(s->cover, 0, (size_t)c->w * (size_t)c->h);
        if (cw > 0 && ch > 0) {
            /* the mask over the clip, scattered to buffer positions */
            uint8_t *m = s->probe_cnt;
            if (ref_coverage_mask(c->v, cx0, cy0, cw, ch, m) < 0)
                FZ_FAIL("reference coverage failed");
            for (row = 0; row < ch; row++)
                for (col = 0; col < cw; col++)
                    if (m[(size_t)row * (size_t)cw + (size_t)col]) {
                        s->cover[(size_t)(row + cy0 - c->origin_y) * (size_t)c->w + (size_t)(col + cx0 - c->origin_x)] = 1;
                        covered++;
                    }
        }
    }
    out->covered = covered;
    need_equal = !(c->has_depth && (c->draw.depth & FXL_DEPTH_TEST)) &&
                 !(c->draw.texture && (c->tex.flags & FXL_TEXF_KEY) && c->draw.texenv != FXL_TEXENV_DECAL);
    out->checked_equal = need_equal;
    for (row = 0; row < c->h; row++)
        for (col = 0; col < c->w; col++) {
            size_t k = FZ_CANARY + (size_t)row * (size_t)c->stride + (size_t)col;
            int w = s->pix_a[k] != 0x0000u || s->pix_b[k] != 0xFFFFu;
            int cv = s->cover[(size_t)row * (size_t)c->w + (size_t)col];
            if (w && !cv)
                FZ_FAIL("pixel (%d,%d) (frame %d,%d) drawn but not covered by the exact rule", col, row,
                        col + c->origin_x, row + c->origin_y);
            if (need_equal && cv && !w)
                FZ_FAIL("pixel (%d,%d) (frame %d,%d) covered by the exact rule but not drawn", col, row,
                        col + c->origin_x, row + c->origin_y);
        }

    /* 7: texel values (before 5b redraws pix_a) */
    if (fz_check_texels(c, s, out, msg) || fz_check_colors(c, s, out, msg) || fz_check_depth(c, s, out, msg))
        return 1;

    /* 5b: the probe sees every covered pixel once */
    fz_fill(c, s, s->pix_a, 0x0000u, c->has_depth ? s->dep_a : NULL);
    fz_make_target(c, &ta, s->pix_a, c->has_depth ? s->dep_a : NULL);
    memset(s->probe_cnt, 0, (size_t)c->w * (size_t)c->h);
    fz_probe_ctx.base = ta.pixels;
    fz_probe_ctx.stride = c->stride;
    fz_probe_ctx.w = c->w;
    fz_probe_ctx.h = c->h;
    fz_probe_ctx.ox = c->origin_x;
    fz_probe_ctx.oy = c->origin_y;
    fz_probe_ctx.clip = c->clip;
    fz_probe_ctx.cnt = s->probe_cnt;
    fz_probe_ctx.bad = 0;
    memset(&sp, 0, sizeof sp);
    st_p = fxl__draw_triangle_with(&ta, &c->draw, c->v, &sp, fz_probe_seg);
    if (st_p != FXL_OK)
        FZ_FAIL("probe run status %s", fxl_status_name(st_p));
    if (fz_probe_ctx.bad)
        FZ_FAIL("segment outside the buffer or clip (offset %ld)", fz_probe_ctx.bad_idx);
    for (row = 0; row < c->h; row++)
        for (col = 0; col < c->w; col++) {
            int pc = s->probe_cnt[(size_t)row * (size_t)c->w + (size_t)col];
            int cv = s->cover[(size_t)row * (size_t)c->w + (size_t)col];
            if (pc != cv)
                FZ_FAIL("span loops visit pixel (%d,%d) (frame %d,%d) %d times, exact coverage %d", col, row,
                        col + c->origin_x, row + c->origin_y, pc, cv);
        }
    return 0;
}

/* Print the target, texture and draw of a case. */
static void fz_print_settings(FILE *f, const fz_case *c)
{
    fprintf(f, "  target %dx%d stride %d format %d origin (%d,%d) clip [%d,%d)x[%d,%d) depth %s init %04X%s\n", c->w,
            c->h, c->stride, c->format, c->origin_x, c->origin_y, c->clip.x0, c->clip.x1, c->clip.y0, c->clip.y1,
            c->has_depth ? "yes" : "no", c->depth_init, c->depth_rand ? " (random)" : "");
    if (c->draw.texture)
        fprintf(f, "  texture fmt %d %dx%d (log2) levels %d wrap %d/%d flags %02X key %04X border %04X%s%s\n",
                c->tex.format, c->tex.log2_w, c->tex.log2_h, c->tex.levels, c->tex.wrap_u, c->tex.wrap_v, c->tex.flags,
                c->tex.key, c->tex.border, c->tex.palette ? "" : " no-palette", c->tex_at_start ? " at-start" : "");
    fprintf(f, "  draw persp %d filter %d mip %d lod %d texenv %d shade %d depth %d color %04X bias %d budget %d\n",
            c->draw.persp, c->draw.filter, c->draw.mip, c->draw.lod, c->draw.texenv, c->draw.shade, c->draw.depth,
            c->draw.color, c->draw.lod_bias_q8, (int)c->draw.auto_budget);
}

/* Print the case as C initialisers (for a regression test). */
static void fz_print_case(FILE *f, const fz_case *c)
{
    int i;
    fz_print_settings(f, c);
    for (i = 0; i < 3; i++)
        fprintf(f, "  v%d = {%ld, %ld, %luu, %ld, %ld, 0x%04X}  /* x %.4f y %.4f px */\n", i, (long)c->v[i].x,
                (long)c->v[i].y, (unsigned long)c->v[i].inv_w, (long)c->v[i].u, (long)c->v[i].v, c->v[i].color,
                c->v[i].x / 65536.0, c->v[i].y / 65536.0);
}

#endif

/* test_span_modes.c - every texel format, wrap mode, colour key, filter,
 * texture environment and shading mode of the span loops, drawn by the core
 * and compared pixel by pixel with the double-precision reference. */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "test_features.h"
#include "left_out.h"
#include "test_vertex.h"
#include "fixel/fixel.h"
#include "reference.h"

void setUp(void) {}
void tearDown(void) {}

#define W 48
#define H 40
#define SENTINEL 0xF81Fu   /* never produced by the textures below */

static uint32_t seed = 1u;
static uint32_t rnd(void)
{
    seed = seed * 1664525u + 1013904223u;
    return seed >> 8;
}


static uint16_t rgb_to_565(const double *rgb)
{
    return (uint16_t)(((uint32_t)lround(rgb[0] * 31 / 255) << 11) | ((uint32_t)lround(rgb[1] * 63 / 255) << 5) |
                      (uint32_t)lround(rgb[2] * 31 / 255));
}

/* Distance of x to the nearest multiple of 1 (texel boundary). */
static double frac_dist(double x)
{
    double f = x - floor(x);
    return f < 0.5 ? f : 1 - f;
}

static uint16_t tex565[8 * 8];
static uint8_t tex8[8 * 8];
static uint16_t palette[256];

static void make_textures(void)
{
    int i;
    for (i = 0; i < 64; i++) {
        tex565[i] = (uint16_t)(rnd() & 0xFFFF);
        if (tex565[i] == SENTINEL)
            tex565[i] ^= 1;
        tex8[i] = (uint8_t)(rnd() & 0xFF);
    }
    for (i = 0; i < 256; i++) {
        palette[i] = (uint16_t)(rnd() & 0xFFFF);
        if (palette[i] == SENTINEL)
            palette[i] ^= 1;
    }
    /* a few key texels at known places */
    tex565[9] = 0x1234;
    tex565[30] = 0x1234;
    tex8[9] = 77;
    tex8[30] = 77;
}

static void random_tri(fxl_vertex_t v[3])
{
    int i;
    for (i = 0; i < 3; i++)
        v[i] = test_vertex((rnd() % 7000) / 100.0 - 11, (rnd() % 6000) / 100.0 - 10, 0.05 + (rnd() % 950) / 1000.0,
                   ((int)(rnd() % 6001) - 2000) / 1000.0, ((int)(rnd() % 6001) - 2000) / 1000.0,
                   (uint16_t)(rnd() & 0xFFFF));
}

/* Renders one triangle with the core and the reference and compares. Pixels
 * whose exact coordinate lies within `eps` texel of a decision boundary (a
 * texel edge for point sampling; also the half-texel nearest-texel choice for
 * bilinear keys) are skipped: there the two renderers may legitimately pick
 * different texels with u within ~1e-5 texel of each other. */
static int compare(const fxl_texture_t *tex, const fxl_draw_t *d, const fxl_vertex_t v[3], int tol,
                   char *msg, size_t msglen)
{
    static uint16_t pix[W * H];
    fxl_target_t t;
    ref_params p;
    ref_image img;
    int x, y, bad = 0, checked = 0;
    const double eps = 1e-3;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, pix, W, H, W, drawable_rgb565()));
    fxl_target_clear(&t, SENTINEL);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, d, v, NULL));
    pixels_to_native(pix, W * H, t.format);
    ref_params_init(&p, W, H);
    p.draw = *d;
    p.clear_color = SENTINEL;
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, v, 1, &img));
    for (y = 0; y < H; y++)
        for (x = 0; x < W; x++) {
            int k = y * W + x, diff;
            uint16_t want, got = pix[k];
            if (tex && img.covered[k]) {
                double uu = img.u[k], vv = img.v[k];
                if (frac_dist(uu) < eps || frac_dist(vv) < eps)
                    continue;
                if (d->filter == FXL_FILTER_BILINEAR &&
                    (frac_dist(uu - 0.5) < eps || frac_dist(vv - 0.5) < eps || fabs(frac_dist(uu - 0.5) - 0.5) < eps ||
                     fabs(frac_dist(vv - 0.5) - 0.5) < eps))
                    continue;
            }
            want = img.drawn[k] ? rgb_to_565(&img.rgb[3 * k]) : SENTINEL;
            checked++;
            if ((got == SENTINEL) != (want == SENTINEL)) {
                diff = 1000;
            } else {
                int dr = abs((int)(got >> 11) - (int)(want >> 11));
                int dg = abs((int)((got >> 5) & 63) - (int)((want >> 5) & 63));
                int db = abs((int)(got & 31) - (int)(want & 31));
                /* tol is for 5-bit channels; green has twice the steps */
                dg = (dg + 1) / 2;
                diff = dr > dg ? (dr > db ? dr : db) : (dg > db ? dg : db);
            }
            if (diff > tol) {
                if (!bad)
                    snprintf(msg, msglen, "pixel (%d,%d): core %04x, reference %04x (u %.5f v %.5f)", x, y, got,
                             want, img.u[k], img.v[k]);
                bad++;
            }
        }
    ref_free(&img);
    (void)checked;
    return bad;
}

/* A draw this build cannot serve: FXL_ERR_UNSUPPORTED and not a pixel drawn. */
static void check_refused(const fxl_draw_t *d, const fxl_vertex_t v[3], const char *ctx)
{
    static uint16_t pix[W * H];
    fxl_target_t t;
    int k, drawn = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, pix, W, H, W, drawable_rgb565()));
    fxl_target_clear(&t, SENTINEL);
    TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_UNSUPPORTED, fxl_draw_triangle(&t, d, v, NULL), ctx);
    pixels_to_native(pix, W * H, t.format);
    for (k = 0; k < W * H; k++)
        drawn += pix[k] != SENTINEL;
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, drawn, ctx);
}

/* Exact perspective, no depth test, the given mip mode and filter. */
static void exact_draw(fxl_draw_t *d, const fxl_texture_t *tex, int mip, int filter)
{
    fxl_draw_defaults(d);
    d->texture = tex;
    d->depth = 0;
    d->persp = FXL_PERSP_EXACT;
    d->mip = (uint8_t)mip;
    d->filter = (uint8_t)filter;
}

void test_every_format_wrap_key_and_filter_matches_reference(void)
{
    static const fxl_texfmt_t fmts[3] = {FXL_TEXFMT_RGB565, FXL_TEXFMT_L8, FXL_TEXFMT_I8};
    int f, wu, wv, key, filt, k, checked = 0, refused = 0;
    char msg[200] = "", ctx[300];
    seed = 5u;
    make_textures();
    for (f = 0; f < 3; f++)
        for (wu = 0; wu < 4; wu++)
            for (wv = 0; wv < 4; wv++)
                for (key = 0; key < 2; key++)
                    for (filt = 0; filt < 2; filt++) {
                        fxl_texture_t tex;
                        fxl_draw_t d;
                        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, f == 0 ? (const void *)tex565 : (const void *)tex8,
                                                                        8, 8, fmts[f], 1));
                        tex.palette = palette;
                        tex.wrap_u = (uint8_t)wu;
                        tex.wrap_v = (uint8_t)wv;
                        tex.border = 0x07FF;
                        if (key) {
                            tex.flags = FXL_TEXF_KEY;
                            tex.key = f == 0 ? 0x1234 : 77;
                        }
                        exact_draw(&d, &tex, FXL_MIP_NONE, filt);
                        /* Left out of this build: other formats, wraps and the
                         * key without FXL_HAVE_GENERIC, bilinear without
                         * FXL_HAVE_BILINEAR. Refused; its random triangles are
                         * still drawn from the sequence, so every other
                         * combination gets the triangles it gets by default. */
                        if ((!FXL_HAVE_GENERIC && (f != 0 || wu != FXL_WRAP_REPEAT || wv != FXL_WRAP_REPEAT || key)) ||
                            (!FXL_HAVE_BILINEAR && filt == FXL_FILTER_BILINEAR)) {
                            for (k = 0; k < 6; k++) {
                                fxl_vertex_t v[3];
                                random_tri(v);
                                snprintf(ctx, sizeof ctx, "fmt %d wrap %d/%d key %d filter %d tri %d", f, wu, wv,
                                         key, filt, k);
                                check_refused(&d, v, ctx);
                            }
                            refused++;
                            continue;
                        }
                        checked++;
                        for (k = 0; k < 6; k++) {
                            fxl_vertex_t v[3];
                            /* Point sampling picks the same texel: exact colour.
                             * Bilinear: the core truncates each axis weight to
                             * 5 bits (error < 1/32 of the channel range per axis)
                             * and rounds three lerps (0.5 step each): bound
                             * 2/32 * 31 + 1.5 = 3.4 steps for 5-bit channels
                             * (6.4 of green's 63, compared halved above). */
                            int tol = filt ? 3 : 0;
                            random_tri(v);
                            snprintf(ctx, sizeof ctx, "fmt %d wrap %d/%d key %d filter %d tri %d: ", f, wu, wv, key, filt, k);
                            if (compare(&tex, &d, v, tol, msg, sizeof msg)) {
                                strncat(ctx, msg, sizeof ctx - strlen(ctx) - 1);
                                TEST_FAIL_MESSAGE(ctx);
                            }
                        }
                    }
    snprintf(msg, sizeof msg, "%d of %d combinations checked, %d need features this build lacks (refused)",
             checked, checked + refused, refused);
    TEST_MESSAGE(msg);
}

/* Draw a triangle that covers all of an 8 x 8 RGB565 target (cleared to
 * SENTINEL first) with the vertex texture coordinates u[k], v[k] (q16). */
static void draw_over_8x8(const fxl_draw_t *d, const int32_t u[3], const int32_t v[3], uint16_t px[64])
{
    fxl_target_t t;
    fxl_vertex_t vx[3];
    int k;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, 8, 8, 8, FXL_PIXFMT_RGB565));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear(&t, SENTINEL));
    memset(vx, 0, sizeof vx);
    vx[0].x = FXL_Q16_INT(-1); vx[0].y = FXL_Q16_INT(-1);
    vx[1].x = FXL_Q16_INT(20); vx[1].y = FXL_Q16_INT(-1);
    vx[2].x = FXL_Q16_INT(-1); vx[2].y = FXL_Q16_INT(20);
    for (k = 0; k < 3; k++) {
        vx[k].inv_w = 0x40000000u;
        vx[k].color = 0xFFFF;
        vx[k].u = u[k];
        vx[k].v = v[k];
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, d, vx, NULL));
}

/* Clamp and border axes hold texel coordinates as a saturated int32 in
 * 16.16 texels: +-32768 texels. Coordinates far beyond it on the negative
 * side must still read the near (left or top) edge, and bilinear's half
 * texel to the left must not wrap a saturated -32768 round to +32767.5 (the
 * far edge). A 4096-texel axis saturates at -8 periods, a 64-texel one at
 * -512. Each u is drawn constant, and as a ramp that crosses the saturation
 * point inside the triangle; v likewise on a texture standing up. */
static uint16_t edge_tex[4096];

void test_clamp_and_border_far_outside_read_the_near_edge_with_every_filter(void)
{
    /* -8 and -512 periods are the window's end itself on the 4096- and
     * 64-texel axes, -32768 texels, INT32_MIN in q16 texels: it must
     * saturate to -32767.5, as the values beyond it do earlier in the walk
     * (a saturation to INT32_MIN went unnoticed further out) */
    static const int32_t periods_q16[] = {-20 * 65536, -(8 * 65536 + 32768), -1000 * 65536, -8 * 65536,
                                          -512 * 65536, 20 * 65536, 8 * 65536 + 32768, 1000 * 65536,
                                          8 * 65536, 512 * 65536};
    static const uint32_t sides[] = {4096, 64};
    const uint16_t lo = 0x001Fu, hi = 0xF800u, mid = 0x07E0u, border = 0xFFFFu;
    size_t si, pi;
    int axis, wrap, filt, ramp, checked = 0;
    char ctx[200];
    for (si = 0; si < sizeof sides / sizeof sides[0]; si++) {
        const uint32_t n = sides[si];
        uint32_t i;
        for (i = 0; i < n; i++)
            edge_tex[i] = i == 0 ? lo : (i == n - 1 ? hi : mid);
        for (axis = 0; axis < 2; axis++)
            for (wrap = FXL_WRAP_CLAMP; wrap <= FXL_WRAP_BORDER; wrap++)
                for (filt = 0; filt < 2; filt++)
                    for (pi = 0; pi < sizeof periods_q16 / sizeof periods_q16[0]; pi++)
                        for (ramp = 0; ramp < 2; ramp++) {
                            static uint16_t px[8 * 8];
                            fxl_texture_t tex;
                            fxl_draw_t d;
                            int32_t cu[3], cv[3];
                            const int32_t c = periods_q16[pi];
                            const int neg = c < 0;
                            /* the ramp runs from 0.75 of c to 1.25 of c */
                            const int32_t c0 = ramp ? c - c / 4 : c, c1 = ramp ? c + c / 4 : c;
                            const uint16_t want = wrap == FXL_WRAP_BORDER ? border : (neg ? lo : hi);
                            int k;
                            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, edge_tex, axis ? 1 : n, axis ? n : 1,
                                                                            FXL_TEXFMT_RGB565, 1));
                            tex.wrap_u = tex.wrap_v = (uint8_t)wrap;
                            tex.border = border;
                            exact_draw(&d, &tex, FXL_MIP_NONE, filt);
                            if (left_out_feature(&d, &tex, FXL_PIXFMT_RGB565, 0) != NULL)
                                continue;
                            for (k = 0; k < 3; k++) {
                                cu[k] = axis ? 32768 : (k == 1 ? c1 : c0);
                                cv[k] = axis ? (k == 1 ? c1 : c0) : 32768;
                            }
                            draw_over_8x8(&d, cu, cv, px);
                            for (k = 0; k < 64; k++)
                                if (px[k] != want) {
                                    snprintf(ctx, sizeof ctx,
                                             "side %u axis %c wrap %d filter %d coordinate %.1f periods%s: pixel %d "
                                             "is %04X, want %04X",
                                             (unsigned)n, axis ? 'v' : 'u', wrap, filt, c / 65536.0,
                                             ramp ? " (ramp)" : "", k, px[k], want);
                                    TEST_FAIL_MESSAGE(ctx);
                                }
                            checked++;
                        }
    }
    test_needs_draw(checked ? NULL : "FXL_HAVE_GENERIC (clamp and border wraps)");
}

/* A clamp axis's coordinate that runs from inside the +-32768-texel window
 * of its int32 values to far outside it within one segment must still
 * cross the texture where the map does. Stepped from the saturated end
 * value, the chord crossed it too late: with v falling 2000 texels a pixel
 * through 0 at x = 16, an affine (or AUTO) span from +31000 to a saturated
 * -32768 crossed 0 at x = 31, and pixels 16..30 read the far edge. A 32 x 32
 * texture of distinct texels, 64 x 4 target, u constant (texel 16), v
 * linear in x (q constant, so every mode's map is the affine one); both
 * axes, both clamp-type wraps, every persp mode, point and bilinear; each
 * pixel must be the edge texel (or border) on its side of the crossing. */
static uint16_t cross_tex[32 * 32];

static void draw_cross_quad(const fxl_draw_t *d, int axis, double c0, double c64, uint16_t px[64 * 4])
{
    fxl_target_t t;
    fxl_vertex_t q[4];
    int k;
    const double xs[4] = {0, 64, 64, 0}, ys[4] = {0, 0, 4, 4};
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, 64, 4, 64, FXL_PIXFMT_RGB565));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear(&t, SENTINEL));
    for (k = 0; k < 4; k++) {
        const double c = xs[k] > 0 ? c64 : c0;   /* periods */
        q[k] = test_vertex(xs[k], ys[k], 0.5, axis ? 16.5 / 32 : c, axis ? c : 16.5 / 32, 0xFFFF);
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, d, q, NULL));
    {
        const fxl_vertex_t q2[3] = {q[0], q[2], q[3]};
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, d, q2, NULL));
    }
}

void test_clamp_ramps_out_of_the_int32_window_cross_the_texture_where_the_map_does(void)
{
    /* texels a pixel (falling) and the x where the coordinate is 0 */
    static const double slopes[] = {2000, 16000, 300};
    static const double zeros[] = {16, 5, 40};
    static const int16_t modes[] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, FXL_PERSP_AUTO, 4, 8, 16, 32, 256};
    const uint16_t border = 0xFFFFu;
    size_t si, mi;
    int axis, wrap, filt, k, checked = 0;
    char ctx[220];
    for (k = 0; k < 32 * 32; k++)
        cross_tex[k] = (uint16_t)(0x0400u + (uint32_t)k);   /* distinct, never SENTINEL or white */
    for (si = 0; si < sizeof slopes / sizeof slopes[0]; si++)
        for (axis = 0; axis < 2; axis++)
            for (wrap = FXL_WRAP_CLAMP; wrap <= FXL_WRAP_BORDER; wrap++)
                for (filt = 0; filt < 2; filt++)
                    for (mi = 0; mi < sizeof modes / sizeof modes[0]; mi++) {
                        static uint16_t px[64 * 4];
                        fxl_texture_t tex;
                        fxl_draw_t d;
                        /* in periods of 32 texels: v(x) = (zero - x) slope */
                        const double c0 = zeros[si] * slopes[si] / 32, c64 = (zeros[si] - 64) * slopes[si] / 32;
                        int x, y;
                        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, cross_tex, 32, 32, FXL_TEXFMT_RGB565, 1));
                        tex.wrap_u = tex.wrap_v = (uint8_t)wrap;
                        tex.border = border;
                        exact_draw(&d, &tex, FXL_MIP_NONE, filt);
                        d.persp = modes[mi];
                        if (left_out_feature(&d, &tex, FXL_PIXFMT_RGB565, 0) != NULL)
                            continue;
                        draw_cross_quad(&d, axis, c0, c64, px);
                        for (y = 0; y < 4; y++)
                            for (x = 0; x < 64; x++) {
                                /* the far side is texel 31 (before the zero), the near one 0 */
                                const int edge = x + 0.5 < zeros[si] ? 31 : 0;
                                const uint16_t want = wrap == FXL_WRAP_BORDER
                                                          ? border
                                                          : cross_tex[axis ? edge * 32 + 16 : 16 * 32 + edge];
                                if (px[y * 64 + x] != want) {
                                    snprintf(ctx, sizeof ctx,
                                             "axis %c wrap %d filter %d persp %d, %.0f texels a pixel through 0 at "
                                             "x = %.0f: pixel (%d,%d) is %04X, want %04X",
                                             axis ? 'v' : 'u', wrap, filt, modes[mi], slopes[si], zeros[si], x, y,
                                             px[y * 64 + x], want);
                                    TEST_FAIL_MESSAGE(ctx);
                                }
                            }
                        checked++;
                    }
    test_needs_draw(checked ? NULL : "FXL_HAVE_GENERIC (clamp and border wraps)");
}

/* Level n of a w x h chain is max(1, w >> n) x max(1, h >> n): once an axis
 * is one texel it stops halving, and so must its coordinates. A border
 * axis shows it: v from 1.55 to 1.9 heights is outside the texture on every
 * level, bilinear's left tap too (half a texel back: still past the edge on
 * a 1-texel level), so every pixel is the border colour, on the 1x1 level
 * too (it was white there: v was halved past the short side, to 0.78 ..
 * 0.95). Both
 * axes (4x2 and 2x4), point and bilinear, nearest and linear mips, LOD per
 * segment and per triangle, biased to the top and to the bottom level. */
void test_border_axis_stays_outside_on_levels_past_the_short_side(void)
{
    static uint16_t texels[16];
    const uint16_t white = 0xFFFFu, red = 0xF800u;
    int shape, axis, filt, mip, lodm, bias, checked = 0, narrow;
    char ctx[200];
    int i;
    for (i = 0; i < 16; i++)
        texels[i] = white;
    /* the border axis u or v, 2 texels wide, then 1 (level 0 already its
     * last level along that axis: a second level must not step past it) */
    for (shape = 0; shape < 4; shape++)
        for (filt = 0, axis = shape & 1, narrow = shape >> 1; filt < 2; filt++)
            for (mip = FXL_MIP_NEAREST; mip <= FXL_MIP_LINEAR; mip++)
                for (lodm = 0; lodm < 2; lodm++)
                    for (bias = 0; bias < 3; bias++) {
                        static uint16_t px[8 * 8];
                        fxl_texture_t tex;
                        fxl_draw_t d;
                        int32_t cu[3], cv[3];
                        int k;
                        const int32_t side = narrow ? 1 : 2;
                        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, axis ? 4 : side, axis ? side : 4,
                                                                        FXL_TEXFMT_RGB565, 3));
                        tex.border = red;
                        if (axis) { /* the border axis is the short one: v on 4x2 */
                            tex.wrap_u = FXL_WRAP_REPEAT;
                            tex.wrap_v = FXL_WRAP_BORDER;
                        } else {    /* u on 2x4 */
                            tex.wrap_u = FXL_WRAP_BORDER;
                            tex.wrap_v = FXL_WRAP_REPEAT;
                        }
                        exact_draw(&d, &tex, mip, filt);
                        d.lod = (uint8_t)lodm;
                        /* bias 2: none, with the other axis minified
                         * (below) so two levels blend */
                        d.lod_bias_q8 = (int16_t)(bias == 2 ? 0 : bias ? 10 * 256 : -10 * 256);
                        if (left_out_feature(&d, &tex, FXL_PIXFMT_RGB565, 0) != NULL)
                            continue;
                        for (k = 0; k < 3; k++) {
                            /* the border axis from 1.55 to 1.9, the other from
                             * 0 to 0.8 (bias 2: to 6, ~1.1 texels a pixel) */
                            const int32_t b = k == 0 ? 101581 : 124518,
                                          o = k == 0 ? 0 : bias == 2 ? FXL_Q16_INT(6) : 52429;
                            cu[k] = axis ? o : b;
                            cv[k] = axis ? b : o;
                        }
                        draw_over_8x8(&d, cu, cv, px);
                        for (k = 0; k < 64; k++)
                            if (px[k] != red) {
                                snprintf(ctx, sizeof ctx,
                                         "%s texture, border on %c, filter %d, mip %d, lod %d, bias %s: pixel %d is "
                                         "%04X, want the border %04X",
                                         axis ? (narrow ? "4x1" : "4x2") : (narrow ? "1x4" : "2x4"), axis ? 'v' : 'u',
                                         filt, mip, lodm,
                                         bias == 2 ? "0 (levels 0 and 1 blend)" : bias ? "+10 (the 1x1 level)" : "-10 (level 0)",
                                         k, px[k], red);
                                TEST_FAIL_MESSAGE(ctx);
                            }
                        checked++;
                    }
    test_needs_draw(checked ? NULL : "FXL_HAVE_GENERIC and FXL_HAVE_MIPMAP (border wrap on mip levels)");
}

/* MODULATE is t * (c + 1) >> bits per channel (white keeps the texel);
 * DECAL shows the colour where the texel is keyed. Checked on the point
 * sampled texel the reference picks. */
void test_modulate_and_decal_follow_their_formulas(void)
{
    TEST_NEEDS(FXL_HAVE_GENERIC);
    static uint16_t pix[W * H];
    fxl_texture_t tex;
    fxl_draw_t d;
    fxl_target_t t;
    fxl_vertex_t v[3];
    ref_params p;
    ref_image img;
    int mode, x, y, checked = 0;
    seed = 9u;
    make_textures();
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, tex565, 8, 8, FXL_TEXFMT_RGB565, 1));
    tex.flags = FXL_TEXF_KEY;
    tex.key = 0x1234;
    v[0] = test_vertex(2, 2, 0.5, -1, -1, 0);
    v[1] = test_vertex(46, 5, 0.9, 2, -1, 0);
    v[2] = test_vertex(8, 38, 0.2, -1, 2.5, 0);
    for (mode = 0; mode < 2; mode++) {
        fxl_draw_defaults(&d);
        d.texture = &tex;
        d.depth = 0;
        d.persp = FXL_PERSP_EXACT;
        d.mip = FXL_MIP_NONE;
        d.color = 0x8410 | 0x0821;   /* r 17, g 33, b 17 */
        d.texenv = (uint8_t)(mode ? FXL_TEXENV_DECAL : FXL_TEXENV_MODULATE);
        fxl_target_init(&t, pix, W, H, W, FXL_PIXFMT_RGB565);
        fxl_target_clear(&t, SENTINEL);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
        ref_params_init(&p, W, H);
        p.draw = d;
        p.draw.texenv = FXL_TEXENV_REPLACE;
        TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, v, 1, &img));
        for (y = 0; y < H; y++)
            for (x = 0; x < W; x++) {
                int k = y * W + x;
                uint32_t texel, want, c = d.color;
                if (!img.covered[k] || frac_dist(img.u[k]) < 1e-3 || frac_dist(img.v[k]) < 1e-3)
                    continue;
                texel = tex565[(img.tex_y[k] & 7) * 8 + (img.tex_x[k] & 7)];
                if (texel == 0x1234)
                    want = mode ? c : SENTINEL;
                else if (mode)
                    want = texel;
                else
                    want = (((((texel >> 11) & 31) * (((c >> 11) & 31) + 1)) >> 5) << 11) |
                           (((((texel >> 5) & 63) * (((c >> 5) & 63) + 1)) >> 6) << 5) |
                           (((texel & 31) * ((c & 31) + 1)) >> 5);
                TEST_ASSERT_EQUAL_HEX16(want, pix[k]);
                checked++;
            }
        ref_free(&img);
    }
    TEST_ASSERT_GREATER_THAN(500, checked);
}

/* Gouraud colour is interpolated perspective-correctly like u, v; the
 * reference does the same in double and rounds. In exact mode the core's
 * q16 channels truncate to 5/6 bits: within 1 step. (Subdivided modes add
 * the affine-segment error of the colour, measured up to 2 steps on thin
 * triangles with a 2.4:1 depth ratio across 6 pixels.) */
void test_gouraud_matches_reference_within_one_step(void)
{
    TEST_NEEDS(FXL_HAVE_GENERIC);
    fxl_draw_t d;
    int k;
    char msg[200] = "";
    seed = 11u;
    fxl_draw_defaults(&d);
    d.depth = 0;
    d.shade = FXL_SHADE_GOURAUD;
    d.persp = FXL_PERSP_EXACT;
    for (k = 0; k < 40; k++) {
        fxl_vertex_t v[3];
        random_tri(v);
        if (compare(NULL, &d, v, 1, msg, sizeof msg))
            TEST_FAIL_MESSAGE(msg);
    }
}

/* Gouraud channels stay within their vertex values: a triangle of one
 * colour draws exactly that colour, and two colours give channels between
 * theirs, in every perspective mode, with depth ratios up to 2^32 - 1;
 * untextured, and every other triangle lit (MODULATE) on a white texture,
 * which gives the colour back exactly (31 (c + 1) >> 5 = c): the speed
 * builds' own walk for lit textures (draw_span_mod) and its pixel loop.
 * Before the corrections clamped to the vertex range (they clamped to
 * 0 .. 31 or 63), rounding left ~1-2% of a one-colour triangle's pixels a
 * step low (white drawn as 0xF7DE). */
void test_gouraud_stays_within_its_vertex_colours(void)
{
    TEST_NEEDS(FXL_HAVE_GENERIC);
    static const int16_t modes[] = {FXL_PERSP_AFFINE, FXL_PERSP_EXACT, 2, 16, FXL_PERSP_MAX, FXL_PERSP_AUTO};
    static const int sh[3] = {11, 5, 0};
    static const uint32_t mask[3] = {31, 63, 31};
    static uint16_t img[W * H];
    static uint16_t white[8 * 8];
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    char msg[200];
    long drawn = 0, lit = 0;
    int k;
    seed = 54u;
    for (k = 0; k < 8 * 8; k++)
        white[k] = 0xFFFF;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, img, W, H, W, FXL_PIXFMT_RGB565));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, white, 8, 8, FXL_TEXFMT_RGB565, 1));
    for (k = 0; k < 1200; k++) {
        fxl_vertex_t v[3];
        uint32_t lo[3], hi[3];
        const uint16_t c0 = (uint16_t)(rnd() | 1u), c1 = k & 1 ? (uint16_t)(rnd() | 1u) : c0;
        int i, ch, p;
        for (i = 0; i < 3; i++) {
            v[i].x = (fxl_q16_t)((int32_t)(rnd() % (uint32_t)((W + 20) << 8)) - (10 << 8)) * 256;
            v[i].y = (fxl_q16_t)((int32_t)(rnd() % (uint32_t)((H + 20) << 8)) - (10 << 8)) * 256;
            /* far (1 .. 2^20) or anywhere up to 2^32 - 1 */
            v[i].inv_w = rnd() & 1u ? 1u + rnd() % (1u << 20) : (rnd() << 8) | (rnd() & 255u) | 1u;
            v[i].u = (fxl_q16_t)(rnd() % (4u << 16));
            v[i].v = (fxl_q16_t)(rnd() % (4u << 16));
            v[i].color = i == 2 ? c1 : c0;
        }
        for (ch = 0; ch < 3; ch++) {
            const uint32_t a = (c0 >> sh[ch]) & mask[ch], b = (c1 >> sh[ch]) & mask[ch];
            lo[ch] = a < b ? a : b;
            hi[ch] = a < b ? b : a;
        }
        fxl_draw_defaults(&d);
        d.depth = 0;
        d.shade = FXL_SHADE_GOURAUD;
        d.persp = modes[k % (int)(sizeof modes / sizeof modes[0])];
        d.mip = FXL_MIP_NONE;
        if ((k / 2) & 1) {   /* lit texture: both colour cases, every mode */
            d.texture = &tex;
            d.texenv = FXL_TEXENV_MODULATE;
        }
        if (left_out_feature(&d, d.texture, FXL_PIXFMT_RGB565, 0) != NULL)
            continue;   /* AUTO in a build without it */
        memset(img, 0, sizeof img);   /* colours are odd: never 0 */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, v, NULL));
        for (p = 0; p < W * H; p++) {
            if (!img[p])
                continue;
            drawn++;
            lit += d.texture != NULL;
            for (ch = 0; ch < 3; ch++) {
                const uint32_t c = (img[p] >> sh[ch]) & mask[ch];
                if (c < lo[ch] || c > hi[ch]) {
                    snprintf(msg, sizeof msg,
                             "triangle %d (persp %d, colours %04x %04x, inv_w %u %u %u): pixel %d is %04x",
                             k, d.persp, c0, c1, v[0].inv_w, v[1].inv_w, v[2].inv_w, p, img[p]);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
        }
    }
    TEST_ASSERT_GREATER_THAN(100000, drawn);
    TEST_ASSERT_GREATER_THAN(drawn / 4, lit);
}

/* A 2x2 texture (red, green / blue, white) magnified onto a 10x10 square,
 * u, v from 0 to 1: pixel (i, j) samples u = (i + 0.5) / 5 texels. Point
 * sampling by hand, and one bilinear pixel computed by hand from the
 * documented blend: texel centres at +0.5, 5-bit weights, three lerps
 * (a * (32 - f) + b * f + 16) >> 5. */
void test_point_and_bilinear_against_hand_computed_texels(void)
{
    static const uint16_t t2[4] = {0xF800, 0x07E0, 0x001F, 0xFFFF};
    static uint16_t pix[16 * 16];
    fxl_texture_t tex;
    fxl_target_t t;
    fxl_draw_t d;
    fxl_vertex_t a[3], b[3];
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, t2, 2, 2, FXL_TEXFMT_RGB565, 1));
    a[0] = test_vertex(0, 0, 0.5, 0, 0, 0);
    a[1] = test_vertex(10, 0, 0.5, 1, 0, 0);
    a[2] = test_vertex(10, 10, 0.5, 1, 1, 0);
    b[0] = a[0];
    b[1] = a[2];
    b[2] = test_vertex(0, 10, 0.5, 0, 1, 0);
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.depth = 0;
    /* drawn in the byte order this build draws, read native */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, pix, 16, 16, 16, drawable_rgb565()));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, a, NULL));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, b, NULL));
    pixels_to_native(pix, 16 * 16, t.format);
    TEST_ASSERT_EQUAL_HEX16(0xF800, pix[1 * 16 + 1]);   /* u 0.3, v 0.3: texel (0,0) */
    TEST_ASSERT_EQUAL_HEX16(0x07E0, pix[2 * 16 + 7]);   /* u 1.5, v 0.5: texel (1,0) */
    TEST_ASSERT_EQUAL_HEX16(0x001F, pix[8 * 16 + 3]);   /* u 0.7, v 1.7: texel (0,1) */
    TEST_ASSERT_EQUAL_HEX16(0xFFFF, pix[9 * 16 + 9]);   /* u 1.9, v 1.9: texel (1,1) */
    d.filter = FXL_FILTER_BILINEAR;
#if !FXL_HAVE_BILINEAR
    /* Left out: refused, the point-sampled square stays; the hand-computed
     * bilinear pixel below cannot be checked. */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_draw_triangle(&t, &d, a, NULL));
    TEST_ASSERT_EQUAL_HEX16(0xF800, pix[1 * 16 + 1]);
    TEST_NEEDS(FXL_HAVE_BILINEAR);
#endif
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, a, NULL));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, b, NULL));
    pixels_to_native(pix, 16 * 16, t.format);   /* the square is redrawn whole */
    /* Pixel (1,1): u = v = 0.3; minus 0.5 gives -0.2: x0 = y0 = -1 (repeat:
     * texel 1), f = 0.8 -> 25/32. Upper row (y = 1): white (x 1) to blue
     * (x 0) -> r (31*7+16)>>5 = 7, g (63*7+16)>>5 = 14, b (31*32+16)>>5 = 31.
     * Lower row (y = 0): green to red -> r (31*25+16)>>5 = 24, g 14, b 0.
     * Rows at 25/32: r (7*7+24*25+16)>>5 = 20, g 14, b (31*7+16)>>5 = 7. */
    TEST_ASSERT_EQUAL_HEX16((20 << 11) | (14 << 5) | 7, pix[1 * 16 + 1]);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_format_wrap_key_and_filter_matches_reference);
    RUN_TEST(test_clamp_and_border_far_outside_read_the_near_edge_with_every_filter);
    RUN_TEST(test_clamp_ramps_out_of_the_int32_window_cross_the_texture_where_the_map_does);
    RUN_TEST(test_border_axis_stays_outside_on_levels_past_the_short_side);
    RUN_TEST(test_modulate_and_decal_follow_their_formulas);
    RUN_TEST(test_gouraud_matches_reference_within_one_step);
    RUN_TEST(test_gouraud_stays_within_its_vertex_colours);
    RUN_TEST(test_point_and_bilinear_against_hand_computed_texels);
    return UNITY_END();
}

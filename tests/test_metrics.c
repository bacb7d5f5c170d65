/* tests/test_metrics.c - the metric code (host_sim/lib/metrics.c) on cases
 * with known answers, and the probe-texture round trip through the core. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "left_out.h"
#include "metrics.h"

void setUp(void) {}
void tearDown(void) {}

#define PX(v) ((fxl_q16_t)((v) * 65536.0))
#define K20 (1u << 20)

static fxl_vertex_t vtx(double x, double y, double u, double v)
{
    fxl_vertex_t r;
    memset(&r, 0, sizeof(r));
    r.x = PX(x);
    r.y = PX(y);
    r.inv_w = K20;
    r.u = (fxl_q16_t)(u * 65536.0);
    r.v = (fxl_q16_t)(v * 65536.0);
    r.color = 0xFFFFu;
    return r;
}

/* Two triangles covering [x0, x1) x [y0, y1) with u, v 0..1 across it. */
static void quad(fxl_vertex_t q[6], double x0, double y0, double x1, double y1)
{
    q[0] = vtx(x0, y0, 0, 0);
    q[1] = vtx(x1, y0, 1, 0);
    q[2] = vtx(x1, y1, 1, 1);
    q[3] = q[0];
    q[4] = q[2];
    q[5] = vtx(x0, y1, 0, 1);
}

/* ---- statistics --------------------------------------------------------------- */

void test_percentile_nearest_rank_on_known_lists(void)
{
    double x[200];
    int i;
    /* 1..100 in reverse order: rank ceil(0.99 * 100) = 99 -> 99 */
    for (i = 0; i < 100; ++i) x[i] = 100 - i;
    TEST_ASSERT_DOUBLE_WITHIN(0, 99.0, metrics_percentile(x, 100, 99));
    TEST_ASSERT_DOUBLE_WITHIN(0, 50.0, metrics_percentile(x, 100, 50));
    TEST_ASSERT_DOUBLE_WITHIN(0, 100.0, metrics_percentile(x, 100, 100));
    /* 1..200: rank ceil(198) = 198 */
    for (i = 0; i < 200; ++i) x[i] = (i * 37) % 200 + 1; /* a permutation: gcd(37, 200) = 1 */
    TEST_ASSERT_DOUBLE_WITHIN(0, 198.0, metrics_percentile(x, 200, 99));
    /* 10 values: rank ceil(9.9) = 10 -> the maximum */
    for (i = 0; i < 10; ++i) x[i] = i * 0.5;
    TEST_ASSERT_DOUBLE_WITHIN(0, 4.5, metrics_percentile(x, 10, 99));
    /* one value */
    x[0] = 7;
    TEST_ASSERT_DOUBLE_WITHIN(0, 7.0, metrics_percentile(x, 1, 99));
}

void test_summarize_max_mean_p99(void)
{
    /* 256 values: 254 zeros, 0.5 and 1.0. p99 rank ceil(253.44) = 254 -> the
     * 254th smallest is still 0; mean 1.5 / 256; max 1. */
    double x[256];
    metrics_summary s;
    int i;
    for (i = 0; i < 256; ++i) x[i] = 0;
    x[17] = 1.0;
    x[200] = 0.5;
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_summarize(x, 256, &s));
    TEST_ASSERT_EQUAL_UINT32(256, (uint32_t)s.n);
    TEST_ASSERT_DOUBLE_WITHIN(0, 1.0, s.max);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.5 / 256, s.mean);
    TEST_ASSERT_DOUBLE_WITHIN(0, 0.0, s.p99);
    TEST_ASSERT_DOUBLE_WITHIN(0, 1.0, x[17]); /* input untouched */
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_summarize(NULL, 0, &s));
    TEST_ASSERT_DOUBLE_WITHIN(0, 0.0, s.max);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, metrics_summarize(x, 4, NULL));
}

/* ---- coverage ----------------------------------------------------------------- */

void test_coverage_compare_counts_each_kind(void)
{
    static const uint8_t ref[6] = {0, 1, 1, 2, 1, 0};
    static const uint8_t fxl[6] = {0, 1, 0, 2, 2, 1};
    metrics_coverage c;
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_coverage_compare(ref, fxl, 6, &c));
    TEST_ASSERT_EQUAL_UINT32(4, c.ref_pixels);       /* 1 2 3 4 */
    TEST_ASSERT_EQUAL_UINT32(4, c.drawn_pixels);     /* 1 3 4 5 */
    TEST_ASSERT_EQUAL_UINT32(2, c.mismatches);       /* 2 and 5 */
    TEST_ASSERT_EQUAL_UINT32(1, c.holes);            /* 2 */
    TEST_ASSERT_EQUAL_UINT32(1, c.extra);            /* 5 */
    TEST_ASSERT_EQUAL_UINT32(2, c.twice);            /* 3 and 4 */
    TEST_ASSERT_EQUAL_UINT32(1, c.ref_twice);        /* 3 */
    TEST_ASSERT_EQUAL_UINT32(3, c.count_mismatches); /* 2, 4, 5 */
}

void test_mask_from_target_reads_swapped_pixels(void)
{
    uint16_t px[4] = {0x3412u, 0x0000u, 0x3412u, 0xFFFFu}; /* sentinel 0x1234 swapped */
    uint8_t mask[4];
    fxl_target_t t;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, 2, 2, 2, FXL_PIXFMT_RGB565_SWAP));
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_mask_from_target(&t, 0x1234u, mask));
    TEST_ASSERT_EQUAL_INT(0, mask[0]);
    TEST_ASSERT_EQUAL_INT(1, mask[1]);
    TEST_ASSERT_EQUAL_INT(0, mask[2]);
    TEST_ASSERT_EQUAL_INT(1, mask[3]);
}

/* ---- image -------------------------------------------------------------------- */

static void black_ref(ref_image *img, int32_t w, int32_t h)
{
    ref_params p;
    ref_params_init(&p, w, h);
    p.clear_color = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, NULL, 0, img));
}

void test_psnr_identical_images_is_capped(void)
{
    static uint16_t px[10 * 10];
    fxl_target_t t;
    ref_image img;
    metrics_image m;
    memset(px, 0, sizeof px);
    black_ref(&img, 10, 10);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, 10, 10, 10, FXL_PIXFMT_RGB565));
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_image_compare(&t, &img, NULL, &m));
    TEST_ASSERT_EQUAL_UINT32(100, (uint32_t)m.pixels);
    TEST_ASSERT_DOUBLE_WITHIN(0, METRICS_PSNR_CAP, m.psnr);
    TEST_ASSERT_DOUBLE_WITHIN(0, 0.0, m.mse);
    TEST_ASSERT_DOUBLE_WITHIN(0, 0.0, m.max_diff);
    TEST_ASSERT_EQUAL_INT(-1, m.max_x);
    ref_free(&img);
}

void test_psnr_single_pixel_difference_hand_computed(void)
{
    /* 10x10, one pixel's red off by one 5-bit step = 255/31 on the 0..255
     * scale: mse = (255/31)^2 / 300, so 255^2 / mse = 300 * 31^2 = 288300
     * and PSNR = 10 log10(288300) = 54.5984 dB. Masked to that pixel alone:
     * 3 * 961 = 2883, 34.5984 dB. */
    static uint16_t px[10 * 10];
    fxl_target_t t;
    ref_image img;
    metrics_image m;
    uint8_t mask[100];
    int swapped;
    black_ref(&img, 10, 10);
    for (swapped = 0; swapped < 2; ++swapped) {
        memset(px, 0, sizeof px);
        px[7 * 10 + 3] = swapped ? 0x0008u : 0x0800u; /* red = 1 */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, 10, 10, 10,
                                                      swapped ? FXL_PIXFMT_RGB565_SWAP
                                                              : FXL_PIXFMT_RGB565));
        TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_image_compare(&t, &img, NULL, &m));
        TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10 * log10(288300.0), m.psnr);
        TEST_ASSERT_DOUBLE_WITHIN(0.0001, 54.5984, m.psnr);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 255.0 / 31, m.max_diff);
        TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, m.max_diff_lsb);
        TEST_ASSERT_EQUAL_INT(3, m.max_x);
        TEST_ASSERT_EQUAL_INT(7, m.max_y);
    }
    memset(mask, 0, sizeof mask);
    mask[73] = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_image_compare(&t, &img, mask, &m));
    TEST_ASSERT_EQUAL_UINT32(1, (uint32_t)m.pixels);
    TEST_ASSERT_DOUBLE_WITHIN(1e-9, 10 * log10(2883.0), m.psnr);
    /* one green step is 255/63 and also 1 LSB */
    px[73] = 0x0020u;
    t.format = FXL_PIXFMT_RGB565;
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_image_compare(&t, &img, NULL, &m));
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 255.0 / 63, m.max_diff);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, m.max_diff_lsb);
    /* a size mismatch is an argument error */
    t.width = 9;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, metrics_image_compare(&t, &img, NULL, &m));
    ref_free(&img);
}

/* ---- probe texture ------------------------------------------------------------ */

static uint16_t g_probe0[512 * 256], g_probe1[512 * 256];

void test_probe_fill_and_decode_round_trip(void)
{
    /* texels (0,0), (0x1A3, 0xB7), (511, 255) of a 512x256 probe:
     * pass 0 words (y & 255) << 8 | (x & 255): 0x0000, 0xB7A3, 0xFFFF;
     * pass 1 words (y >> 8) << 8 | (x >> 8):    0x0000, 0x0001, 0x0001 */
    static const int32_t xs[3] = {0, 0x1A3, 511}, ys[3] = {0, 0xB7, 255};
    static const uint16_t w0[3] = {0x0000u, 0xB7A3u, 0xFFFFu}, w1[3] = {0, 1, 1};
    uint16_t px[3];
    int32_t tx[3], ty[3];
    fxl_target_t t;
    int k, swapped;
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_probe_fill(g_probe0, 512, 256, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_probe_fill(g_probe1, 512, 256, 1));
    for (k = 0; k < 3; ++k) {
        TEST_ASSERT_EQUAL_HEX16(w0[k], g_probe0[ys[k] * 512 + xs[k]]);
        TEST_ASSERT_EQUAL_HEX16(w1[k], g_probe1[ys[k] * 512 + xs[k]]);
    }
    for (swapped = 0; swapped < 2; ++swapped) {
        fxl_pixfmt_t f = swapped ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, 3, 1, 3, f));
        /* what a point-sampled replace render stores for those texels */
        for (k = 0; k < 3; ++k) {
            uint16_t w = g_probe0[ys[k] * 512 + xs[k]];
            px[k] = swapped ? (uint16_t)((w >> 8) | (w << 8)) : w;
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_probe_decode(&t, 0, tx, ty));
        for (k = 0; k < 3; ++k) {
            uint16_t w = g_probe1[ys[k] * 512 + xs[k]];
            px[k] = swapped ? (uint16_t)((w >> 8) | (w << 8)) : w;
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_probe_decode(&t, 1, tx, ty));
        for (k = 0; k < 3; ++k) {
            TEST_ASSERT_EQUAL_INT32(xs[k], tx[k]);
            TEST_ASSERT_EQUAL_INT32(ys[k], ty[k]);
        }
    }
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, metrics_probe_fill(g_probe0, 3, 4, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, metrics_probe_fill(g_probe0, 4, 4, 2));
}

void test_axis_error_hand_values(void)
{
    double lo, ce;
    /* repeat, n = 8 */
    metrics_axis_error(3.25, 3, 8, FXL_WRAP_REPEAT, &lo, &ce); /* inside texel 3 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, lo);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.25, ce);
    metrics_axis_error(3.25, 4, 8, FXL_WRAP_REPEAT, &lo, &ce); /* [4,5): 0.75 away */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.75, lo);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.25, ce);
    metrics_axis_error(-0.25, 7, 8, FXL_WRAP_REPEAT, &lo, &ce); /* [-1,0) is texel 7 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, lo);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.25, ce);
    metrics_axis_error(1000.5, 0, 8, FXL_WRAP_REPEAT, &lo, &ce); /* 1000 = 125 * 8 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, lo);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, ce);
    /* mirror, n = 4: texel 0 also covers [-1, 0) and [7, 8) */
    metrics_axis_error(-0.5, 0, 4, FXL_WRAP_MIRROR, &lo, &ce);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, ce);
    metrics_axis_error(4.5, 3, 4, FXL_WRAP_MIRROR, &lo, &ce); /* [4,5) is texel 3 */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, ce);
    metrics_axis_error(4.5, 0, 4, FXL_WRAP_MIRROR, &lo, &ce); /* [7,8): 2.5 away */
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 2.5, lo);
    /* clamp, n = 4: texel 0 holds everything below 1 */
    metrics_axis_error(-5.0, 0, 4, FXL_WRAP_CLAMP, &lo, &ce);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 0.0, lo);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 5.5, ce);
    metrics_axis_error(-5.0, 1, 4, FXL_WRAP_CLAMP, &lo, &ce);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 6.0, lo);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 6.5, ce);
}

static uint16_t g_probe16[16 * 16];

static fxl_texture_t probe16(void)
{
    fxl_texture_t t;
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_probe_fill(g_probe16, 16, 16, 0));
    memset(&t, 0, sizeof t);
    t.texels = g_probe16;
    t.log2_w = t.log2_h = 4;
    t.levels = 1;
    return t;
}

void test_texcoord_compare_one_wrong_texel(void)
{
    /* A 16x16 quad mapped 1:1 onto a 16x16 texture: exact u at pixel i is
     * i + 0.5. Fetched = reference everywhere except pixel (5, 9), which
     * claims texel 6 in x (lower bound 0.5, centre distance 1.0), and pixel
     * (0, 0), whose index is out of range (skipped): 255 pixels compared.
     * lower: max 0.5, mean 0.5 / 255, p99 rank ceil(252.45) = 253 -> 0. */
    fxl_texture_t tex = probe16();
    fxl_vertex_t q[6];
    ref_params p;
    ref_image img;
    int32_t tx[256], ty[256];
    metrics_texcoord m;
    int k;
    quad(q, 0, 0, 16, 16);
    ref_params_init(&p, 16, 16);
    p.draw.texture = &tex;
    p.draw.mip = FXL_MIP_NONE;
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, q, 2, &img));
    for (k = 0; k < 256; ++k) {
        tx[k] = k % 16;
        ty[k] = k / 16;
    }
    tx[9 * 16 + 5] = 6;
    ty[0] = 16;
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_texcoord_compare(&img, tx, ty, NULL, 16, 16,
                                                           FXL_WRAP_REPEAT, FXL_WRAP_REPEAT, &m));
    TEST_ASSERT_EQUAL_UINT32(255, (uint32_t)m.pixels);
    TEST_ASSERT_EQUAL_UINT32(1, (uint32_t)m.wrong_texel);
    TEST_ASSERT_DOUBLE_WITHIN(1e-15, 1.0 / 255, m.wrong_share);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.5, m.lower.max);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.5 / 255, m.lower.mean);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, m.lower.p99);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 1.0, m.centre.max);
    TEST_ASSERT_DOUBLE_WITHIN(1e-12, 0.0, m.centre.p99);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG,
                          metrics_texcoord_compare(&img, tx, ty, NULL, 16, 16, FXL_WRAP_BORDER,
                                                   FXL_WRAP_REPEAT, &m));
    ref_free(&img);
}

/* ---- through the core ------------------------------------------------------------ */

void test_coverage_count_of_core_matches_reference(void)
{
    /* Two triangles sharing the diagonal of the pixel square 0..3 (vertices on
     * pixel centres, see test_reference.c): the exact rule draws each pixel
     * once; listing the first triangle twice must show up as 10 pixels drawn
     * twice (its 10 pixels, hand-counted in test_reference.c). */
    fxl_vertex_t tris[9];
    uint8_t counts[8 * 8];
    ref_params p;
    ref_image img;
    metrics_coverage c;
    tris[0] = vtx(0.5, 0.5, 0, 0);
    tris[1] = vtx(4.5, 0.5, 0, 0);
    tris[2] = vtx(0.5, 4.5, 0, 0);
    tris[3] = vtx(4.5, 4.5, 0, 0);
    tris[4] = vtx(0.5, 4.5, 0, 0);
    tris[5] = vtx(4.5, 0.5, 0, 0);
    memcpy(tris + 6, tris, 3 * sizeof(fxl_vertex_t));
    ref_params_init(&p, 8, 8);
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, tris, 2, &img));
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_coverage_count(tris, 2, 8, 8, counts));
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_coverage_compare(img.covered, counts, 64, &c));
    TEST_ASSERT_EQUAL_UINT32(16, c.ref_pixels);
    TEST_ASSERT_EQUAL_UINT32(0, c.mismatches);
    TEST_ASSERT_EQUAL_UINT32(0, c.twice);
    TEST_ASSERT_EQUAL_UINT32(0, c.count_mismatches);
    ref_free(&img);
    TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, tris, 3, &img));
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_coverage_count(tris, 3, 8, 8, counts));
    TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_coverage_compare(img.covered, counts, 64, &c));
    TEST_ASSERT_EQUAL_UINT32(10, c.twice);
    TEST_ASSERT_EQUAL_UINT32(10, c.ref_twice);
    TEST_ASSERT_EQUAL_UINT32(0, c.count_mismatches);
    ref_free(&img);
}

void test_probe_render_through_core_fetches_reference_texels(void)
{
    /* The same 1:1 quad drawn by the core with the probe texture, point,
     * no mips, exact perspective: exact u = i + 0.5 is half a texel from
     * either boundary, so any core error below 0.5 texel fetches the
     * reference texel. Expect 0 wrong texels and a lower bound of 0. On
     * both target formats (the probe decodes either), each one this build
     * draws (left_out.h). */
    fxl_texture_t tex = probe16();
    fxl_vertex_t q[6];
    static uint16_t px[16 * 16];
    fxl_target_t t;
    fxl_draw_t d;
    ref_params p;
    ref_image img;
    int32_t tx[256], ty[256];
    metrics_texcoord m;
    int f, drawn = 0;
    quad(q, 0, 0, 16, 16);
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.persp = FXL_PERSP_EXACT;
    d.filter = FXL_FILTER_POINT;
    d.mip = FXL_MIP_NONE;
    d.texenv = FXL_TEXENV_REPLACE;
    d.depth = 0;
    for (f = 0; f < 2; f++) {
        const fxl_pixfmt_t fmt = f ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, 16, 16, 16, fmt));
        if (left_out_feature(&d, &tex, fmt, 0) != NULL) {
            TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_draw_triangle(&t, &d, q, NULL));
            continue;
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, q, NULL));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, &d, q + 3, NULL));
        ref_params_init(&p, 16, 16);
        p.draw = d;
        TEST_ASSERT_EQUAL_INT(FXL_OK, ref_render(&p, q, 2, &img));
        TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_probe_decode(&t, 0, tx, ty));
        TEST_ASSERT_EQUAL_INT(FXL_OK, metrics_texcoord_compare(&img, tx, ty, NULL, 16, 16,
                                                               FXL_WRAP_REPEAT, FXL_WRAP_REPEAT, &m));
        TEST_ASSERT_EQUAL_UINT32(256, (uint32_t)m.pixels);
        TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)m.wrong_texel);
        TEST_ASSERT_DOUBLE_WITHIN(0, 0.0, m.lower.max);
        ref_free(&img);
        drawn++;
    }
    /* at least one: the build draws one of the two formats (config.h) */
    TEST_ASSERT_TRUE(drawn > 0);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_percentile_nearest_rank_on_known_lists);
    RUN_TEST(test_summarize_max_mean_p99);
    RUN_TEST(test_coverage_compare_counts_each_kind);
    RUN_TEST(test_mask_from_target_reads_swapped_pixels);
    RUN_TEST(test_psnr_identical_images_is_capped);
    RUN_TEST(test_psnr_single_pixel_difference_hand_computed);
    RUN_TEST(test_probe_fill_and_decode_round_trip);
    RUN_TEST(test_axis_error_hand_values);
    RUN_TEST(test_texcoord_compare_one_wrong_texel);
    RUN_TEST(test_coverage_count_of_core_matches_reference);
    RUN_TEST(test_probe_render_through_core_fetches_reference_texels);
    return UNITY_END();
}

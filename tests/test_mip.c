/* tests/test_mip.c - mip chain construction (src/mip.c): box-average
 * exactness and rounding, chain layout, linear-light averaging, I8 and the
 * colour key. */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "unity.h"
#include "fixel/texture.h"
#include "../src/texel.h"
#include "../src/mip_tables.h"

void setUp(void) {}
void tearDown(void) {}

static uint16_t g_rgb[128 * 32 * 2];
static uint8_t g_l8[128 * 32 * 2];
static uint16_t g_pal[256];

static uint16_t rgb(uint32_t r5, uint32_t g6, uint32_t b5)
{
    return (uint16_t)((r5 << 11) | (g6 << 5) | b5);
}

/* ---- box average, stored space ------------------------------------------- */

void test_box_2x2_rgb565_channels_round_half_up(void)
{
    /* r: 1+2+3+4 = 10 -> (10+2)>>2 = 3 (2.5 rounds up)
     * g: 63+63+62+62 = 250 -> 63 (62.5 up); a 16-bit average of the packed
     *    words would carry into red instead.
     * b: 0+0+0+1 = 1 -> (1+2)>>2 = 0 (0.25 down); 31+31+31+30 would be 31. */
    uint16_t *t = g_rgb;
    t[0] = rgb(1, 63, 0); t[1] = rgb(2, 63, 0);
    t[2] = rgb(3, 62, 0); t[3] = rgb(4, 62, 1);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(t, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL,
                                                FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_HEX16(rgb(3, 63, 0), t[4]);
    /* 0.75 rounds up: 1+1+1+0 = 3 -> (3+2)>>2 = 1 per channel */
    t[0] = rgb(1, 1, 1); t[1] = rgb(1, 1, 1); t[2] = rgb(1, 1, 1); t[3] = rgb(0, 0, 0);
    fxl_mip_build(t, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL, FXL_MIP_SPACE_STORED);
    TEST_ASSERT_EQUAL_HEX16(rgb(1, 1, 1), t[4]);
    /* white + black checkerboard in stored space: 5-bit (62+2)>>2 = 16,
     * 6-bit (126+2)>>2 = 32 -> the darkened 0x8410 that linear light avoids */
    t[0] = 0xFFFF; t[1] = 0; t[2] = 0; t[3] = 0xFFFF;
    fxl_mip_build(t, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL, FXL_MIP_SPACE_STORED);
    TEST_ASSERT_EQUAL_HEX16(0x8410, t[4]);
}

void test_box_1d_cases_round_half_up(void)
{
    uint8_t *l = g_l8;
    /* 4x1 L8: (10, 11, 200, 203) -> (10+11+1)>>1 = 11, (403+1)>>1 = 202;
     * then (11+202+1)>>1 = 107. */
    l[0] = 10; l[1] = 11; l[2] = 200; l[3] = 203;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(l, 7, 4, 1, FXL_TEXFMT_L8, 3, NULL,
                                                FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_UINT8(11, l[4]);
    TEST_ASSERT_EQUAL_UINT8(202, l[5]);
    TEST_ASSERT_EQUAL_UINT8(107, l[6]);
    /* 1x2 RGB565 column: r (30+31+1)>>1 = 31, g (0+1+1)>>1 = 1, b (4+7+1)>>1 = 6 */
    g_rgb[0] = rgb(30, 0, 4); g_rgb[1] = rgb(31, 1, 7);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(g_rgb, 6, 1, 2, FXL_TEXFMT_RGB565, 2, NULL,
                                                FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_HEX16(rgb(31, 1, 6), g_rgb[2]);
}

/* Reference for one level from the previous one, written independently of
 * mip.c: the exact mean in double, rounded half up with floor(m + 0.5). */
static void ref_level_l8(const uint8_t *src, uint32_t sw, uint32_t sh, uint8_t *dst)
{
    uint32_t dw = sw > 1 ? sw / 2 : 1, dh = sh > 1 ? sh / 2 : 1, x, y, i, j;
    for (y = 0; y < dh; y++)
        for (x = 0; x < dw; x++) {
            double s = 0;
            uint32_t n = 0;
            for (j = 0; j < (sh > 1 ? 2u : 1u); j++)
                for (i = 0; i < (sw > 1 ? 2u : 1u); i++) {
                    s += src[(y * (sh > 1 ? 2 : 1) + j) * sw + x * (sw > 1 ? 2 : 1) + i];
                    n++;
                }
            dst[y * dw + x] = (uint8_t)floor(s / n + 0.5);
        }
}

void test_chain_128x32_l8_matches_reference_every_level(void)
{
    static uint8_t ref[5463];
    uint32_t i, lv, w = 128, h = 32, off = 0;
    uint32_t seed = 12345;
    char msg[96];
    TEST_ASSERT_EQUAL_UINT32(5463, fxl_mip_size(128, 32, FXL_TEXFMT_L8, 8));
    for (i = 0; i < 4096; i++) {
        seed = seed * 1103515245u + 12345u;
        g_l8[i] = ref[i] = (uint8_t)(seed >> 23);
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(g_l8, 5463, 128, 32, FXL_TEXFMT_L8, 8, NULL,
                                                FXL_MIP_SPACE_STORED));
    for (lv = 1; lv < 8; lv++) {
        uint32_t next = off + w * h;
        ref_level_l8(ref + off, w, h, ref + next);
        off = next;
        w = w > 1 ? w / 2 : 1;
        h = h > 1 ? h / 2 : 1;
        for (i = 0; i < w * h; i++) {
            snprintf(msg, sizeof msg, "level %u (%ux%u) texel %u", (unsigned)lv, (unsigned)w,
                     (unsigned)h, (unsigned)i);
            TEST_ASSERT_EQUAL_INT_MESSAGE(ref[off + i], g_l8[off + i], msg);
        }
    }
    /* level 7 is the single texel at offset 5462 */
    TEST_ASSERT_EQUAL_UINT32(5462, off);
}

void test_chain_128x32_rgb565_uniform_stays_uniform_and_tail_untouched(void)
{
    /* A uniform level 0 averages to itself on all 8 levels (exact mean);
     * the canary after the chain must survive. */
    uint32_t i;
    for (i = 0; i < 4096; i++)
        g_rgb[i] = 0x5AA5;
    g_rgb[5463] = 0xBEEF;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(g_rgb, 5463 * 2, 128, 32, FXL_TEXFMT_RGB565, 8,
                                                NULL, FXL_MIP_SPACE_STORED));
    for (i = 4096; i < 5463; i++)
        TEST_ASSERT_EQUAL_HEX16(0x5AA5, g_rgb[i]);
    TEST_ASSERT_EQUAL_HEX16(0xBEEF, g_rgb[5463]);
}

/* ---- linear light ---------------------------------------------------------- */

/* Nearest code (0..top) to linear value 0.5 under a decoding function, in
 * double: the value an ideal linear-light average of black and white gives. */
static double g22(double x) { return pow(x, 2.2); }
static double srgb(double x) { return x <= 0.04045 ? x / 12.92 : pow((x + 0.055) / 1.055, 2.4); }
static uint32_t ideal_mid(double (*dec)(double), uint32_t top)
{
    uint32_t c, best = 0;
    for (c = 1; c <= top; c++)
        if (fabs(dec((double)c / top) - 0.5) < fabs(dec((double)best / top) - 0.5))
            best = c;
    return best;
}

void test_checkerboard_averages_to_linear_mid_grey(void)
{
    /* 0.5 linear encodes to 255 * 0.5^(1/2.2) = 186.0 (gamma 2.2) and to
     * 255 * (1.055 * 0.5^(1/2.4) - 0.055) = 187.5 (sRGB; the nearest code in
     * linear light is 188), against 128 for a stored-value average. */
    uint8_t *l = g_l8;
    l[0] = 0; l[1] = 255; l[2] = 255; l[3] = 0;
    fxl_mip_build(l, 5, 2, 2, FXL_TEXFMT_L8, 2, NULL, FXL_MIP_SPACE_GAMMA22);
    TEST_ASSERT_EQUAL_UINT8(186, l[4]);
    TEST_ASSERT_EQUAL_UINT32(ideal_mid(g22, 255), l[4]);
    fxl_mip_build(l, 5, 2, 2, FXL_TEXFMT_L8, 2, NULL, FXL_MIP_SPACE_SRGB);
    TEST_ASSERT_EQUAL_UINT8(188, l[4]);
    TEST_ASSERT_EQUAL_UINT32(ideal_mid(srgb, 255), l[4]);
    fxl_mip_build(l, 5, 2, 2, FXL_TEXFMT_L8, 2, NULL, FXL_MIP_SPACE_STORED);
    TEST_ASSERT_EQUAL_UINT8(128, l[4]);

    /* RGB565: per channel, 5 and 6 bits. Hand values: gamma 2.2 r/b 23
     * ((23/31)^2.2 = 0.519 vs (22/31)^2.2 = 0.470), g 46 ((46/63)^2.2 = 0.5005);
     * sRGB r/b 23 (0.510 vs 0.462), g 46 (0.492 vs 0.516). */
    g_rgb[0] = 0xFFFF; g_rgb[1] = 0; g_rgb[2] = 0; g_rgb[3] = 0xFFFF;
    fxl_mip_build(g_rgb, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL, FXL_MIP_SPACE_GAMMA22);
    TEST_ASSERT_EQUAL_HEX16(rgb(23, 46, 23), g_rgb[4]);
    TEST_ASSERT_EQUAL_HEX16(rgb(ideal_mid(g22, 31), ideal_mid(g22, 63), ideal_mid(g22, 31)),
                            g_rgb[4]);
    fxl_mip_build(g_rgb, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL, FXL_MIP_SPACE_SRGB);
    TEST_ASSERT_EQUAL_HEX16(rgb(23, 46, 23), g_rgb[4]);
    TEST_ASSERT_EQUAL_HEX16(rgb(ideal_mid(srgb, 31), ideal_mid(srgb, 63), ideal_mid(srgb, 31)),
                            g_rgb[4]);
}

void test_linear_spaces_keep_uniform_codes_exact(void)
{
    /* Decode -> average of equal values -> encode must return the code:
     * every L8 code and every 5/6-bit channel value, both transfer curves.
     * Three equal texels plus one keyed texel force the averaging path (four
     * equal texels take the uniform shortcut). Code 0 is the L8 key here. */
    uint32_t c, sp;
    uint16_t key = 0;
    char msg[64];
    for (sp = FXL_MIP_SPACE_GAMMA22; sp <= FXL_MIP_SPACE_SRGB; sp++) {
        for (c = 1; c < 256; c++) {
            g_l8[0] = (uint8_t)c; g_l8[1] = (uint8_t)c; g_l8[2] = (uint8_t)c; g_l8[3] = 0;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build_keyed(g_l8, 5, 2, 2, FXL_TEXFMT_L8, 2,
                                                               NULL, (fxl_mip_space_t)sp, &key));
            snprintf(msg, sizeof msg, "space %u L8 code %u", (unsigned)sp, (unsigned)c);
            TEST_ASSERT_EQUAL_INT_MESSAGE(c, g_l8[4], msg);
        }
        for (c = 0; c < 64; c++) {
            /* key 0xFFFF never matches these: r5/b5 <= 31 with g6 = c */
            uint16_t k = 0xFFFF, v = rgb(c & 31, c, 31 - (c & 31));
            g_rgb[0] = v; g_rgb[1] = v; g_rgb[2] = v; g_rgb[3] = k;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build_keyed(g_rgb, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL,
                                                               (fxl_mip_space_t)sp, &k));
            snprintf(msg, sizeof msg, "space %u RGB565 %04x", (unsigned)sp, (unsigned)v);
            TEST_ASSERT_EQUAL_INT_MESSAGE(v, g_rgb[4], msg);
        }
    }
}

/* The code nearest to n sources' mean linear value sum / n in table t of
 * `count` codes, ties to the higher code: |sum - n t[c]| compared exactly. */
static uint32_t nearest_code(const uint16_t *t, uint32_t count, uint32_t sum, uint32_t n)
{
    uint32_t c, best = 0, best_d = UINT32_MAX;
    for (c = 0; c < count; c++) {
        const uint32_t d = sum > n * t[c] ? sum - n * t[c] : n * t[c] - sum;
        if (d <= best_d) {
            best_d = d;
            best = c;
        }
    }
    return best;
}

/* Each level's channel is the code nearest to the exact mean of its
 * sources' linear values. The mean used to be rounded to an integer first,
 * which picked the farther code within half a unit of a midpoint: L8
 * {140, 28} in gamma 2.2 gave 104 where 103 is nearer (a review's sweep
 * found 71 of 268,920 texels). Every L8 pair (2x1, both curves) and
 * 20,000 random 2x2 RGB565 blocks (four sources a channel). */
void test_linear_spaces_pick_the_code_nearest_the_exact_mean(void)
{
    const uint16_t *t8[2] = {fxl__lin8_g22, fxl__lin8_srgb}, *t5[2] = {fxl__lin5_g22, fxl__lin5_srgb};
    const uint16_t *t6[2] = {fxl__lin6_g22, fxl__lin6_srgb};
    uint32_t a, b, sp, i, k;
    char msg[96];
    uint64_t rs = 12345;
    for (sp = 0; sp < 2; sp++) {
        const fxl_mip_space_t space = sp ? FXL_MIP_SPACE_SRGB : FXL_MIP_SPACE_GAMMA22;
        for (a = 0; a < 256; a++)
            for (b = 0; b < 256; b++) {
                uint32_t want;
                g_l8[0] = (uint8_t)a;
                g_l8[1] = (uint8_t)b;
                TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(g_l8, 3, 2, 1, FXL_TEXFMT_L8, 2, NULL, space));
                want = a == b ? a : nearest_code(t8[sp], 256, (uint32_t)t8[sp][a] + t8[sp][b], 2);
                if (g_l8[2] != want) {
                    snprintf(msg, sizeof msg, "space %u L8 {%u, %u}: %u, nearest %u", (unsigned)sp, (unsigned)a,
                             (unsigned)b, (unsigned)g_l8[2], (unsigned)want);
                    TEST_FAIL_MESSAGE(msg);
                }
            }
        for (i = 0; i < 20000; i++) {
            uint32_t sum[3] = {0, 0, 0}, got;
            for (k = 0; k < 4; k++) {
                rs = rs * 6364136223846793005u + 1442695040888963407u;
                g_rgb[k] = (uint16_t)(rs >> 40);
                sum[0] += t5[sp][g_rgb[k] >> 11];
                sum[1] += t6[sp][(g_rgb[k] >> 5) & 63];
                sum[2] += t5[sp][g_rgb[k] & 31];
            }
            if (g_rgb[1] == g_rgb[0] && g_rgb[2] == g_rgb[0] && g_rgb[3] == g_rgb[0])
                continue;   /* uniform: the shortcut, checked above */
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(g_rgb, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL, space));
            got = g_rgb[4];
            if ((got >> 11) != nearest_code(t5[sp], 32, sum[0], 4) ||
                ((got >> 5) & 63) != nearest_code(t6[sp], 64, sum[1], 4) ||
                (got & 31) != nearest_code(t5[sp], 32, sum[2], 4)) {
                snprintf(msg, sizeof msg, "space %u RGB565 block %u: 0x%04X", (unsigned)sp, (unsigned)i,
                         (unsigned)got);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
}

/* ---- I8 --------------------------------------------------------------------- */

static void grey_palette(void)
{
    uint32_t i;
    /* entries 0..3 as below; the rest a colour far from all test averages */
    for (i = 0; i < 256; i++)
        g_pal[i] = rgb(31, 0, 31);
    g_pal[0] = 0x0000; /* black */
    g_pal[1] = 0xFFFF; /* white */
    g_pal[2] = 0x8410; /* grey: 8-bit (132, 130, 132) */
    g_pal[3] = 0xF800; /* red */
    g_pal[4] = rgb(23, 46, 23); /* light grey: 8-bit (189, 186, 189) */
}

void test_i8_averages_palette_colours_and_picks_nearest(void)
{
    grey_palette();
    /* black/white checker: stored mean (128, 128, 128) -> grey, index 2
     * (distance 4+4+16 = 24; light grey is 61^2 * 2 + 58^2 away). */
    g_l8[0] = 0; g_l8[1] = 1; g_l8[2] = 1; g_l8[3] = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_I8, 2, g_pal,
                                                FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_UINT8(2, g_l8[4]);
    /* the same in linear light: (186..188)-ish grey -> index 4 */
    fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_I8, 2, g_pal, FXL_MIP_SPACE_GAMMA22);
    TEST_ASSERT_EQUAL_UINT8(4, g_l8[4]);
    fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_I8, 2, g_pal, FXL_MIP_SPACE_SRGB);
    TEST_ASSERT_EQUAL_UINT8(4, g_l8[4]);
    /* red + black in 1-D: (128, 0, 0) -> distances: black 128^2, red 127^2,
     * grey 4^2+130^2+132^2 -> red (index 3) */
    g_l8[0] = 3; g_l8[1] = 0;
    fxl_mip_build(g_l8, 3, 2, 1, FXL_TEXFMT_I8, 2, g_pal, FXL_MIP_SPACE_STORED);
    TEST_ASSERT_EQUAL_UINT8(3, g_l8[2]);
}

void test_i8_ties_go_to_lowest_index(void)
{
    grey_palette();
    /* duplicate of grey at 9 and 200: the average of 200 and a colour next
     * to it must pick index 2, the lowest of the equal entries */
    g_pal[9] = 0x8410;
    g_pal[200] = 0x8410;
    g_l8[0] = 200; g_l8[1] = 9; g_l8[2] = 200; g_l8[3] = 9;
    fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_I8, 2, g_pal, FXL_MIP_SPACE_STORED);
    TEST_ASSERT_EQUAL_UINT8(2, g_l8[4]);
    /* all four sources the same index: kept as is (documented shortcut) */
    g_l8[0] = g_l8[1] = g_l8[2] = g_l8[3] = 200;
    fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_I8, 2, g_pal, FXL_MIP_SPACE_STORED);
    TEST_ASSERT_EQUAL_UINT8(200, g_l8[4]);
}

void test_i8_chain_4x4_down_to_1x1(void)
{
    /* Left half black (0), right half white (1): level 1 (2x2) keeps black
     * and white columns (uniform 2x2 blocks), level 2 averages to grey (2). */
    uint32_t x, y;
    grey_palette();
    for (y = 0; y < 4; y++)
        for (x = 0; x < 4; x++)
            g_l8[y * 4 + x] = x < 2 ? 0 : 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(g_l8, 21, 4, 4, FXL_TEXFMT_I8, 3, g_pal,
                                                FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_UINT8(0, g_l8[16]);
    TEST_ASSERT_EQUAL_UINT8(1, g_l8[17]);
    TEST_ASSERT_EQUAL_UINT8(0, g_l8[18]);
    TEST_ASSERT_EQUAL_UINT8(1, g_l8[19]);
    TEST_ASSERT_EQUAL_UINT8(2, g_l8[20]);
}

/* ---- colour key --------------------------------------------------------------- */

void test_key_two_of_four_transparent_else_mean_of_opaque(void)
{
    uint16_t key = 0xF81F; /* magenta */
    uint16_t *t = g_rgb;
    /* 4x2 -> 2x1: left block has 2 keyed sources (-> key); right block has
     * one keyed source, so the mean of the 3 others, rounded half up with
     * (sum + 1) / 3: r (15+1)/3 = 5, g (9+1)/3 = 3, b (6+1)/3 = 2 */
    t[0] = key; t[1] = rgb(1, 1, 1); t[2] = rgb(3, 0, 2); t[3] = rgb(4, 0, 2);
    t[4] = rgb(1, 1, 1); t[5] = key; t[6] = key; t[7] = rgb(8, 9, 2);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build_keyed(t, 20, 4, 2, FXL_TEXFMT_RGB565, 2, NULL,
                                                       FXL_MIP_SPACE_STORED, &key));
    TEST_ASSERT_EQUAL_HEX16(key, t[8]);
    TEST_ASSERT_EQUAL_HEX16(rgb(5, 3, 2), t[9]);
    /* 1-D: one keyed of two -> keyed; level 2 of this chain: (key, opaque) */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build_keyed(t, 22, 4, 2, FXL_TEXFMT_RGB565, 3, NULL,
                                                       FXL_MIP_SPACE_STORED, &key));
    TEST_ASSERT_EQUAL_HEX16(key, t[10]);
    /* without the key the magenta texels are averaged like any colour */
    t[0] = key; t[1] = key; t[2] = 0; t[3] = 0;
    fxl_mip_build(t, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL, FXL_MIP_SPACE_STORED);
    TEST_ASSERT_EQUAL_HEX16(rgb(16, 0, 16), t[4]);
}

void test_key_opaque_average_never_becomes_the_key(void)
{
    /* RGB565: an opaque average equal to the key flips the blue LSB. */
    uint16_t key = rgb(2, 2, 2), l8key = 100, ikey = 2;
    g_rgb[0] = rgb(1, 1, 1); g_rgb[1] = rgb(3, 3, 3); g_rgb[2] = rgb(1, 1, 1);
    g_rgb[3] = rgb(3, 3, 3);
    fxl_mip_build_keyed(g_rgb, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL, FXL_MIP_SPACE_STORED, &key);
    TEST_ASSERT_EQUAL_HEX16(rgb(2, 2, 3), g_rgb[4]);
    /* L8: 99 and 101 average to the key 100 -> 101 */
    g_l8[0] = 99; g_l8[1] = 101;
    fxl_mip_build_keyed(g_l8, 3, 2, 1, FXL_TEXFMT_L8, 2, NULL, FXL_MIP_SPACE_STORED, &l8key);
    TEST_ASSERT_EQUAL_UINT8(101, g_l8[2]);
    /* I8: black/white would pick grey (2), the key index -> next nearest.
     * Mean (128,128,128): black 3*128^2 = 49152, white 3*127^2 = 48387,
     * light grey (189,186,189) 61^2*2 + 58^2 = 10806 -> index 4 */
    grey_palette();
    g_l8[0] = 0; g_l8[1] = 1; g_l8[2] = 1; g_l8[3] = 0;
    fxl_mip_build_keyed(g_l8, 5, 2, 2, FXL_TEXFMT_I8, 2, g_pal, FXL_MIP_SPACE_STORED, &ikey);
    TEST_ASSERT_EQUAL_UINT8(4, g_l8[4]);
}

/* ---- errors ----------------------------------------------------------------- */

void test_mip_build_error_paths(void)
{
    uint16_t key = 300;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mip_build(NULL, 10, 2, 2, FXL_TEXFMT_RGB565, 2, NULL,
                                                     FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_I8, 2, NULL,
                                                     FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mip_build(g_l8, 5, 2, 2, (fxl_texfmt_t)5, 2, NULL,
                                                     FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_L8, 2, NULL,
                                                     (fxl_mip_space_t)3));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mip_build((uint8_t *)g_rgb + 1, 10, 2, 2,
                                                     FXL_TEXFMT_RGB565, 2, NULL,
                                                     FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mip_build(g_l8, 5, 0, 2, FXL_TEXFMT_L8, 2, NULL,
                                                     FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_mip_build(g_l8, 100, 6, 2, FXL_TEXFMT_L8, 2,
                                                             NULL, FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_L8, 3, NULL,
                                                       FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_L8, 0, NULL,
                                                       FXL_MIP_SPACE_STORED));
    /* 2x2 RGB565 with 2 levels needs (4 + 1) * 2 = 10 bytes */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_NOMEM, fxl_mip_build(g_rgb, 9, 2, 2, FXL_TEXFMT_RGB565, 2,
                                                       NULL, FXL_MIP_SPACE_STORED));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_mip_build_keyed(g_l8, 5, 2, 2, FXL_TEXFMT_L8, 2,
                                                              NULL, FXL_MIP_SPACE_STORED, &key));
    {
        /* a palette or key at an odd address (read as uint16_t): refused,
         * never read */
        static uint16_t words[258];
        const uint16_t *odd = (const uint16_t *)(const void *)((const uint8_t *)words + 1);
        TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mip_build(g_l8, 5, 2, 2, FXL_TEXFMT_I8, 2, odd,
                                                         FXL_MIP_SPACE_STORED));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_mip_build_keyed(g_l8, 5, 2, 2, FXL_TEXFMT_L8, 2, NULL,
                                                               FXL_MIP_SPACE_STORED, odd));
    }
    /* one level: nothing to build, success */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(g_l8, 4, 2, 2, FXL_TEXFMT_L8, 1, NULL,
                                                FXL_MIP_SPACE_STORED));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_box_2x2_rgb565_channels_round_half_up);
    RUN_TEST(test_box_1d_cases_round_half_up);
    RUN_TEST(test_chain_128x32_l8_matches_reference_every_level);
    RUN_TEST(test_chain_128x32_rgb565_uniform_stays_uniform_and_tail_untouched);
    RUN_TEST(test_checkerboard_averages_to_linear_mid_grey);
    RUN_TEST(test_linear_spaces_keep_uniform_codes_exact);
    RUN_TEST(test_linear_spaces_pick_the_code_nearest_the_exact_mean);
    RUN_TEST(test_i8_averages_palette_colours_and_picks_nearest);
    RUN_TEST(test_i8_ties_go_to_lowest_index);
    RUN_TEST(test_i8_chain_4x4_down_to_1x1);
    RUN_TEST(test_key_two_of_four_transparent_else_mean_of_opaque);
    RUN_TEST(test_key_opaque_average_never_becomes_the_key);
    RUN_TEST(test_mip_build_error_paths);
    return UNITY_END();
}

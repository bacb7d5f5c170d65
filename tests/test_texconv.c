/* tests/test_texconv.c - the PNG converter (host_sim/lib/texconv_lib.c, the
 * fixel-texconv tool): PNG -> chain -> fxl_texture_fetch equals the PNG's
 * pixels, emitted C compiles and holds the same chain, blob layout, errors. */
#define _POSIX_C_SOURCE 200809L
#include <dirent.h>
#include <fcntl.h>
#include <png.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "unity.h"
#include "fixel/texture.h"
#include "texconv_lib.h"

static char g_dir[64];

void setUp(void)
{
    snprintf(g_dir, sizeof g_dir, "/tmp/fxl_texconv_XXXXXX");
    if (mkdtemp(g_dir) == NULL)
        g_dir[0] = '\0';
}

void tearDown(void)
{
    DIR *d;
    struct dirent *e;
    char p[sizeof g_dir + 260];
    if (g_dir[0] == '\0')
        return;
    d = opendir(g_dir);
    if (d != NULL) {
        while ((e = readdir(d)) != NULL) {
            if (strcmp(e->d_name, ".") == 0 || strcmp(e->d_name, "..") == 0)
                continue;
            snprintf(p, sizeof p, "%s/%s", g_dir, e->d_name);
            unlink(p);
        }
        closedir(d);
    }
    rmdir(g_dir);
}

/* A ring of buffers: a test's argument arrays keep the pointers while it
 * calls path_in again. With 4 slots, the later calls of a test overwrote its
 * earlier arguments (the truncated-PNG test ran "-o t.png", its own input),
 * so every test now stays well under 64 calls. */
static const char *path_in(const char *name)
{
    static char buf[64][256];
    static int k;
    k = (k + 1) & 63;
    snprintf(buf[k], sizeof buf[k], "%s/%s", g_dir, name);
    return buf[k];
}

static int exists(const char *p)
{
    struct stat st;
    return stat(p, &st) == 0;
}

static int dir_entries(void)
{
    DIR *d = opendir(g_dir);
    struct dirent *e;
    int n = 0;
    if (d == NULL)
        return -1;
    while ((e = readdir(d)) != NULL)
        if (strcmp(e->d_name, ".") != 0 && strcmp(e->d_name, "..") != 0)
            n++;
    closedir(d);
    return n;
}

/* Write an 8-bit RGBA image as a PNG of the given libpng colour type and
 * depth (RGB drops alpha, GRAY takes the red channel, PALETTE indexes a
 * palette built from the distinct colours, with tRNS for alpha). */
static void write_png(const char *path, uint32_t w, uint32_t h, const uint8_t *rgba, int color,
                      int depth)
{
    FILE *f = fopen(path, "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    png_color pal[256];
    png_byte trns[256];
    int npal = 0, ch = color == PNG_COLOR_TYPE_RGBA ? 4 : color == PNG_COLOR_TYPE_RGB ? 3 : 1;
    int bpc = depth / 8;
    uint8_t *row = (uint8_t *)malloc((size_t)w * 4 * 2);
    uint32_t x, y;
    TEST_ASSERT_NOT_NULL(f);
    TEST_ASSERT_NOT_NULL(row);
    if (setjmp(png_jmpbuf(png)))
        TEST_FAIL_MESSAGE("libpng write failed");
    png_init_io(png, f);
    png_set_IHDR(png, info, w, h, depth, color, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (color == PNG_COLOR_TYPE_PALETTE) {
        for (y = 0; y < w * h; y++) {
            const uint8_t *p = rgba + 4 * y;
            int k;
            for (k = 0; k < npal; k++)
                if (pal[k].red == p[0] && pal[k].green == p[1] && pal[k].blue == p[2] &&
                    trns[k] == p[3])
                    break;
            if (k == npal) {
                TEST_ASSERT_LESS_THAN(256, npal);
                pal[npal].red = p[0]; pal[npal].green = p[1]; pal[npal].blue = p[2];
                trns[npal] = p[3];
                npal++;
            }
        }
        png_set_PLTE(png, info, pal, npal);
        png_set_tRNS(png, info, trns, npal, NULL);
    }
    png_write_info(png, info);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            const uint8_t *p = rgba + 4 * (y * w + x);
            int c;
            if (color == PNG_COLOR_TYPE_PALETTE) {
                int k = 0;
                while (!(pal[k].red == p[0] && pal[k].green == p[1] && pal[k].blue == p[2] &&
                         trns[k] == p[3]))
                    k++;
                row[x] = (uint8_t)k;
                continue;
            }
            for (c = 0; c < ch; c++) {
                /* 16-bit samples: v * 257 (so the high byte is v) */
                if (bpc == 2) {
                    row[(x * ch + c) * 2] = p[c];
                    row[(x * ch + c) * 2 + 1] = p[c];
                } else {
                    row[x * ch + c] = p[c];
                }
            }
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
    free(row);
}

static uint32_t g_seed = 1;
static uint32_t rnd(void)
{
    g_seed = g_seed * 1664525u + 1013904223u;
    return g_seed >> 8;
}

/* w x h random opaque pixels drawn from `colours` distinct colours (0 = any). */
static uint8_t *random_image(uint32_t w, uint32_t h, uint32_t colours)
{
    uint8_t *p = (uint8_t *)malloc((size_t)w * h * 4);
    uint32_t i;
    TEST_ASSERT_NOT_NULL(p);
    for (i = 0; i < w * h; i++) {
        uint32_t r = colours ? (rnd() % colours) * 2654435761u : rnd();
        p[4 * i] = (uint8_t)(r >> 24);
        p[4 * i + 1] = (uint8_t)(r >> 16);
        p[4 * i + 2] = (uint8_t)(r >> 8);
        p[4 * i + 3] = 255;
    }
    return p;
}

static int run_tool(const char *const *args, int n)
{
    char *argv[24];
    int i;
    argv[0] = (char *)"fixel-texconv";
    for (i = 0; i < n; i++)
        argv[i + 1] = (char *)args[i];
    argv[n + 1] = NULL;
    return texconv_main(n + 1, argv);
}

/* ---- conversions and PNG reading ---------------------------------------------- */

void test_colour_conversions_round_to_nearest(void)
{
    /* r5 = (255*31+127)/255 = 31; g6 for 128: (8064+127)/255 = 32.1 -> 32 */
    TEST_ASSERT_EQUAL_HEX16(0xFFFF, texconv_rgb565(255, 255, 255));
    TEST_ASSERT_EQUAL_HEX16(0xFC00, texconv_rgb565(255, 128, 0));
    /* 4 -> (124+127)/255 = 0.98 -> 0; 5 -> (155+127)/255 = 1.1 -> 1 (5/255*31 = 0.61) */
    TEST_ASSERT_EQUAL_HEX16(0x0000, texconv_rgb565(4, 0, 4));
    TEST_ASSERT_EQUAL_HEX16(0x0801, texconv_rgb565(5, 0, 5));
    /* grey is exact in L8; pure colours get the BT.601 weights */
    TEST_ASSERT_EQUAL_UINT8(200, texconv_luma(200, 200, 200));
    TEST_ASSERT_EQUAL_UINT8(77, texconv_luma(255, 0, 0));  /* (77*255+128)>>8 = 77 */
    TEST_ASSERT_EQUAL_UINT8(149, texconv_luma(0, 255, 0)); /* (150*255+128)>>8 = 149 */
}

void test_read_png_any_colour_type_gives_rgba8(void)
{
    static const int types[][2] = {{PNG_COLOR_TYPE_RGBA, 8}, {PNG_COLOR_TYPE_RGB, 8},
                                   {PNG_COLOR_TYPE_GRAY, 8}, {PNG_COLOR_TYPE_PALETTE, 8},
                                   {PNG_COLOR_TYPE_RGBA, 16}, {PNG_COLOR_TYPE_GRAY, 16}};
    uint8_t *src = random_image(8, 4, 20);
    uint32_t t, i;
    char err[256], msg[96];
    src[4 * 5 + 3] = 77; /* one translucent pixel */
    for (t = 0; t < sizeof types / sizeof types[0]; t++) {
        texconv_image_t img;
        int color = types[t][0];
        write_png(path_in("in.png"), 8, 4, src, color, types[t][1]);
        TEST_ASSERT_EQUAL_INT(0, texconv_read_png(path_in("in.png"), &img, err, sizeof err));
        TEST_ASSERT_EQUAL_UINT32(8, img.width);
        TEST_ASSERT_EQUAL_UINT32(4, img.height);
        for (i = 0; i < 32; i++) {
            const uint8_t *p = src + 4 * i, *q = img.rgba + 4 * i;
            int grey = color == PNG_COLOR_TYPE_GRAY;
            int alpha = color == PNG_COLOR_TYPE_RGBA || color == PNG_COLOR_TYPE_PALETTE;
            snprintf(msg, sizeof msg, "colour type %d depth %d pixel %u", color, types[t][1],
                     (unsigned)i);
            TEST_ASSERT_EQUAL_INT_MESSAGE(p[0], q[0], msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(grey ? p[0] : p[1], q[1], msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(grey ? p[0] : p[2], q[2], msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(alpha ? p[3] : 255, q[3], msg);
        }
        texconv_image_free(&img);
    }
    free(src);
}

/* A 4x2 PNG written from packed rows as given: colour type, bit depth,
 * interlace, and a tRNS chunk (trns_n > 0: a grey or RGB key colour). */
static void write_raw_png(const char *path, int color, int depth, int interlace, const png_byte *rows,
                          size_t row_bytes, const png_color_16 *trns)
{
    FILE *f = fopen(path, "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    png_bytep rp[2];
    TEST_ASSERT_NOT_NULL(f);
    if (setjmp(png_jmpbuf(png)))
        TEST_FAIL_MESSAGE("libpng write failed");
    png_init_io(png, f);
    png_set_IHDR(png, info, 4, 2, depth, color, interlace, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    if (trns)
        png_set_tRNS(png, info, NULL, 0, (png_color_16p)trns);
    png_write_info(png, info);
    rp[0] = (png_bytep)rows;
    rp[1] = (png_bytep)rows + row_bytes;
    png_write_image(png, rp);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
}

/* The colour types and depths the first reading test does not write: grey
 * with alpha, grey at 1, 2 and 4 bits (expanded by 255, 85, 17), a tRNS
 * key on grey and on RGB (that colour transparent, the rest opaque), and
 * an interlaced (Adam7) RGBA image. Each 4x2 image must read as the RGBA8
 * pixels it holds. */
void test_read_png_grey_alpha_low_depths_trns_and_interlace(void)
{
    static const png_byte ga[] = {0, 255, 40, 128, 90, 0, 255, 7, 1, 2, 3, 4, 5, 6, 200, 201};
    static const png_byte g1[] = {0xA0, 0x50};                 /* 1 0 1 0 / 0 1 0 1 */
    static const png_byte g2[] = {0x1B, 0xE4};                 /* 0 1 2 3 / 3 2 1 0 */
    static const png_byte g4[] = {0x01, 0x8F, 0xF7, 0x3C};     /* 0 1 8 15 / 15 7 3 12 */
    static const png_byte gk[] = {10, 20, 30, 20, 20, 40, 50, 20};
    static const png_byte rgbk[] = {1, 2, 3, 9, 9, 9, 1, 2, 3, 4, 5, 6, 9, 9, 9, 7, 8, 9, 1, 2, 3, 0, 0, 0};
    png_byte rgba[32];
    png_color_16 kg, kc;
    uint8_t want[8][32];
    const char *what[8] = {"grey+alpha", "grey 1 bit", "grey 2 bit", "grey 4 bit", "grey tRNS", "RGB tRNS",
                           "interlaced RGBA", ""};
    texconv_image_t img;
    char err[256], msg[96];
    int t, i;
    memset(&kg, 0, sizeof kg);
    memset(&kc, 0, sizeof kc);
    kg.gray = 20;
    kc.red = 9;
    kc.green = 9;
    kc.blue = 9;
    for (i = 0; i < 32; i++)
        rgba[i] = (png_byte)(i * 37 + 11);
    for (i = 0; i < 8; i++) {
        const int v1 = (g1[i / 4] >> (7 - i % 4)) & 1, v2 = (g2[i / 4] >> (6 - 2 * (i % 4))) & 3;
        const int v4 = (g4[i / 2] >> (i % 2 ? 0 : 4)) & 15;
        const int grey[5] = {ga[2 * i], v1 * 255, v2 * 85, v4 * 17, gk[i]};
        const int alpha[5] = {ga[2 * i + 1], 255, 255, 255, gk[i] == 20 ? 0 : 255};
        int k;
        for (k = 0; k < 5; k++) {
            want[k][4 * i] = want[k][4 * i + 1] = want[k][4 * i + 2] = (uint8_t)grey[k];
            want[k][4 * i + 3] = (uint8_t)alpha[k];
        }
        for (k = 0; k < 3; k++)
            want[5][4 * i + k] = rgbk[3 * i + k];
        want[5][4 * i + 3] = (rgbk[3 * i] == 9 && rgbk[3 * i + 1] == 9 && rgbk[3 * i + 2] == 9) ? 0 : 255;
        memcpy(&want[6][4 * i], &rgba[4 * i], 4);
    }
    write_raw_png(path_in("t0.png"), PNG_COLOR_TYPE_GRAY_ALPHA, 8, PNG_INTERLACE_NONE, ga, 8, NULL);
    write_raw_png(path_in("t1.png"), PNG_COLOR_TYPE_GRAY, 1, PNG_INTERLACE_NONE, g1, 1, NULL);
    write_raw_png(path_in("t2.png"), PNG_COLOR_TYPE_GRAY, 2, PNG_INTERLACE_NONE, g2, 1, NULL);
    write_raw_png(path_in("t3.png"), PNG_COLOR_TYPE_GRAY, 4, PNG_INTERLACE_NONE, g4, 2, NULL);
    write_raw_png(path_in("t4.png"), PNG_COLOR_TYPE_GRAY, 8, PNG_INTERLACE_NONE, gk, 4, &kg);
    write_raw_png(path_in("t5.png"), PNG_COLOR_TYPE_RGB, 8, PNG_INTERLACE_NONE, rgbk, 12, &kc);
    write_raw_png(path_in("t6.png"), PNG_COLOR_TYPE_RGBA, 8, PNG_INTERLACE_ADAM7, rgba, 16, NULL);
    for (t = 0; t < 7; t++) {
        char name[16];
        snprintf(name, sizeof name, "t%d.png", t);
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, texconv_read_png(path_in(name), &img, err, sizeof err), what[t]);
        TEST_ASSERT_EQUAL_UINT32(4, img.width);
        TEST_ASSERT_EQUAL_UINT32(2, img.height);
        for (i = 0; i < 32; i++) {
            snprintf(msg, sizeof msg, "%s: byte %d (pixel %d)", what[t], i, i / 4);
            TEST_ASSERT_EQUAL_INT_MESSAGE(want[t][i], img.rgba[i], msg);
        }
        texconv_image_free(&img);
    }
}

/* ---- round trips through fxl_texture_fetch --------------------------------------- */

static void convert_file(const uint8_t *rgba, uint32_t w, uint32_t h, const texconv_opts_t *o,
                         texconv_chain_t *c)
{
    texconv_image_t img;
    char err[256];
    write_png(path_in("rt.png"), w, h, rgba, PNG_COLOR_TYPE_RGBA, 8);
    TEST_ASSERT_EQUAL_INT(0, texconv_read_png(path_in("rt.png"), &img, err, sizeof err));
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, texconv_convert(&img, o, c, err, sizeof err), err);
    texconv_image_free(&img);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_validate(&c->tex));
}

void test_roundtrip_rgb565_level0_equals_png_pixels(void)
{
    uint8_t *src = random_image(32, 16, 0);
    texconv_opts_t o;
    texconv_chain_t c;
    uint32_t x, y;
    int tr;
    char msg[96];
    texconv_opts_default(&o);
    convert_file(src, 32, 16, &o, &c);
    /* 32x16: 6 levels, 512 + 128 + 32 + 8 + 2 + 1 = 683 texels */
    TEST_ASSERT_EQUAL_UINT8(6, c.tex.levels);
    TEST_ASSERT_EQUAL_UINT32(683, c.texel_count);
    for (y = 0; y < 16; y++)
        for (x = 0; x < 32; x++) {
            const uint8_t *p = src + 4 * (y * 32 + x);
            uint16_t got = fxl_texture_fetch(&c.tex, 0, (int32_t)x, (int32_t)y, &tr);
            snprintf(msg, sizeof msg, "pixel (%u,%u) got %04x", (unsigned)x, (unsigned)y, got);
            TEST_ASSERT_EQUAL_HEX32_MESSAGE(texconv_rgb565(p[0], p[1], p[2]), got, msg);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, tr, msg);
        }
    /* the chain's level 1 is the core's box average of level 0 */
    {
        uint16_t *copy = (uint16_t *)malloc(c.bytes);
        TEST_ASSERT_NOT_NULL(copy);
        memcpy(copy, c.texels, 512 * 2);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mip_build(copy, c.bytes, 32, 16, FXL_TEXFMT_RGB565, 6,
                                                    NULL, FXL_MIP_SPACE_STORED));
        TEST_ASSERT_EQUAL_MEMORY(copy, c.texels, c.bytes);
        free(copy);
    }
    texconv_chain_free(&c);
    free(src);
}

void test_roundtrip_l8_and_exact_i8_with_key(void)
{
    /* 16x16 from 40 colours, a transparent column (alpha 0) and a pixel of
     * exactly the key colour: those are keyed, everything else equals the
     * PNG's pixel (L8: grey of its luminance; I8: exact palette, since 40
     * colours fit). */
    uint8_t *src = random_image(16, 16, 40);
    texconv_opts_t o;
    texconv_chain_t c;
    uint32_t x, y, f;
    int tr;
    char msg[96];
    for (y = 0; y < 16; y++)
        src[4 * (y * 16 + 5) + 3] = 0;
    src[4 * 37] = 0xFF; src[4 * 37 + 1] = 0x00; src[4 * 37 + 2] = 0xFF;
    for (f = FXL_TEXFMT_L8; f <= FXL_TEXFMT_I8; f++) {
        texconv_opts_default(&o);
        o.format = (fxl_texfmt_t)f;
        o.has_key = 1;
        o.key_rgb = 0xFF00FF;
        o.mips = TEXCONV_MIPS_SRGB;
        convert_file(src, 16, 16, &o, &c);
        TEST_ASSERT_EQUAL_UINT8(5, c.tex.levels);
        for (y = 0; y < 16; y++)
            for (x = 0; x < 16; x++) {
                uint32_t i = y * 16 + x;
                const uint8_t *p = src + 4 * i;
                int keyed = x == 5 || i == 37;
                uint16_t got = fxl_texture_fetch(&c.tex, 0, (int32_t)x, (int32_t)y, &tr);
                snprintf(msg, sizeof msg, "format %u pixel (%u,%u) got %04x", (unsigned)f,
                         (unsigned)x, (unsigned)y, got);
                TEST_ASSERT_EQUAL_INT_MESSAGE(keyed, tr, msg);
                if (keyed)
                    continue;
                if (f == FXL_TEXFMT_L8) {
                    uint32_t l = texconv_luma(p[0], p[1], p[2]);
                    /* an opaque pixel whose luminance equals the key's is moved one step */
                    if (l == c.tex.key)
                        l = l == 255 ? 254 : l + 1;
                    TEST_ASSERT_EQUAL_HEX32_MESSAGE(((l >> 3) << 11) | ((l >> 2) << 5) | (l >> 3),
                                                    got, msg);
                } else {
                    TEST_ASSERT_EQUAL_HEX32_MESSAGE(texconv_rgb565(p[0], p[1], p[2]), got, msg);
                }
            }
        if (f == FXL_TEXFMT_I8) /* key + at most 40 colours */
            TEST_ASSERT_LESS_OR_EQUAL(41, c.palette_used);
        texconv_chain_free(&c);
    }
    free(src);
}

void test_i8_quantiser_maps_every_pixel_to_its_nearest_entry(void)
{
    /* 64x64 random colours: far more than 256 distinct, so median cut fills
     * all 256 entries; each pixel must use the nearest entry (8-bit expanded
     * squared distance, ties to the lowest index). */
    uint8_t *src = random_image(64, 64, 0);
    texconv_opts_t o;
    texconv_chain_t c;
    uint32_t i, k;
    char msg[96];
    texconv_opts_default(&o);
    o.format = FXL_TEXFMT_I8;
    o.mips = TEXCONV_MIPS_NONE;
    convert_file(src, 64, 64, &o, &c);
    TEST_ASSERT_EQUAL_UINT32(256, c.palette_used);
    TEST_ASSERT_EQUAL_UINT8(1, c.tex.levels);
    for (i = 0; i < 64 * 64; i++) {
        uint32_t px = texconv_rgb565(src[4 * i], src[4 * i + 1], src[4 * i + 2]);
        uint32_t best = 0, best_d = UINT32_MAX, got = ((const uint8_t *)c.texels)[i];
        for (k = 0; k < 256; k++) {
            uint32_t q = c.palette[k];
            int32_t d0 = (int32_t)(((px >> 11) << 3) | (px >> 13)) -
                         (int32_t)(((q >> 11) << 3) | (q >> 13));
            int32_t d1 = (int32_t)((((px >> 5) & 63) << 2) | ((px >> 9) & 3)) -
                         (int32_t)((((q >> 5) & 63) << 2) | ((q >> 9) & 3));
            int32_t d2 = (int32_t)(((px & 31) << 3) | ((px >> 2) & 7)) -
                         (int32_t)(((q & 31) << 3) | ((q >> 2) & 7));
            uint32_t d = (uint32_t)(d0 * d0 + d1 * d1 + d2 * d2);
            if (d < best_d) {
                best_d = d;
                best = k;
            }
        }
        snprintf(msg, sizeof msg, "pixel %u: index %u, nearest %u", (unsigned)i, (unsigned)got,
                 (unsigned)best);
        TEST_ASSERT_EQUAL_INT_MESSAGE(best, got, msg);
    }
    texconv_chain_free(&c);
    free(src);
}

/* Median cut with one colour holding most of the pixels (a white
 * background): a box whose last colour in the sort order held over half its
 * pixels was split into itself and an empty box, whose mean divided by zero
 * (the tool died on SIGFPE). 30% white among random colours: every entry
 * must be a colour some pixel maps to, and white pixels must stay white. */
void test_i8_quantiser_survives_a_dominant_colour(void)
{
    uint8_t *src = random_image(64, 64, 0);
    texconv_opts_t o;
    texconv_chain_t c;
    uint32_t i, used[256] = {0}, white = 0;
    char msg[96];
    for (i = 0; i < 64 * 64; i++)
        if (rnd() % 10 < 3) {
            src[4 * i] = src[4 * i + 1] = src[4 * i + 2] = 255;
            white++;
        }
    TEST_ASSERT_TRUE(white > 1000);
    texconv_opts_default(&o);
    o.format = FXL_TEXFMT_I8;
    o.mips = TEXCONV_MIPS_NONE;
    convert_file(src, 64, 64, &o, &c);
    TEST_ASSERT_EQUAL_UINT32(256, c.palette_used);
    for (i = 0; i < 64 * 64; i++) {
        const uint32_t k = ((const uint8_t *)c.texels)[i];
        used[k]++;
        if (src[4 * i] == 255 && src[4 * i + 1] == 255 && src[4 * i + 2] == 255) {
            snprintf(msg, sizeof msg, "white pixel %u: entry %u = 0x%04X", (unsigned)i, (unsigned)k,
                     (unsigned)c.palette[k]);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0xFFFF, c.palette[k], msg);
        }
    }
    for (i = 0; i < 256; i++) {
        snprintf(msg, sizeof msg, "entry %u (0x%04X) is used by no pixel", (unsigned)i, (unsigned)c.palette[i]);
        TEST_ASSERT_TRUE_MESSAGE(used[i] > 0, msg);
    }
    texconv_chain_free(&c);
    free(src);
}

/* The command line the outputs record names the tool "fixel-texconv"
 * whatever argv[0] is; a shorter argv[0] (a symlink, exec -a) once sized
 * that string too small (a heap overflow: ASan in make sanitize). */
void test_short_program_name_is_not_an_overflow(void)
{
    uint8_t *src = random_image(4, 4, 3);
    char *argv[] = {(char *)"t", (char *)path_in("s.png"), (char *)"-o", (char *)path_in("s.c"), NULL};
    FILE *f;
    char line[512];
    int found = 0;
    write_png(path_in("s.png"), 4, 4, src, PNG_COLOR_TYPE_RGBA, 8);
    TEST_ASSERT_EQUAL_INT(0, texconv_main(4, argv));
    f = fopen(path_in("s.c"), "r");
    TEST_ASSERT_NOT_NULL(f);
    while (fgets(line, sizeof line, f))
        found |= strstr(line, "command: fixel-texconv ") != NULL;
    fclose(f);
    TEST_ASSERT_TRUE_MESSAGE(found, "the generated file names the command");
    free(src);
}

/* ---- emitted C and blob ------------------------------------------------------------ */

/* FNV-1a over the chain, palette and descriptor. The same function is
 * compiled into the generated program (k_main below); keep them in step. */
#define CHECKSUM_BODY                                                                        \
    uint32_t n = 0, lv, hsh = 2166136261u, i;                                                \
    for (lv = 0; lv < t->levels; lv++) {                                                     \
        uint32_t lw = t->log2_w > lv ? t->log2_w - lv : 0, lh = t->log2_h > lv ? t->log2_h - lv : 0; \
        n += 1u << (lw + lh);                                                                \
    }                                                                                        \
    for (i = 0; i < n; i++)                                                                  \
        hsh = (hsh ^ (t->format == 0 ? ((const uint16_t *)t->texels)[i]                      \
                                     : ((const uint8_t *)t->texels)[i])) * 16777619u;        \
    if (t->palette)                                                                          \
        for (i = 0; i < 256; i++)                                                            \
            hsh = (hsh ^ t->palette[i]) * 16777619u;                                         \
    hsh = (hsh ^ (uint32_t)(t->log2_w | t->log2_h << 4 | t->levels << 8 | t->format << 16)) * 16777619u; \
    hsh = (hsh ^ (uint32_t)(t->wrap_u | t->wrap_v << 4 | t->flags << 8)) * 16777619u;        \
    hsh = (hsh ^ (uint32_t)(t->key | (uint32_t)t->border << 16)) * 16777619u;
#define STR2(...) #__VA_ARGS__
#define STR(...) STR2(__VA_ARGS__)

static void checksum(const fxl_texture_t *t, uint32_t *count, uint32_t *hash)
{
    CHECKSUM_BODY
    *count = n;
    *hash = hsh;
}

static const char k_main[] =
    "#include <stdio.h>\n#include <stdint.h>\n#include \"fixel/texture.h\"\n"
    "extern const fxl_texture_t brick;\n"
    "int main(void) { const fxl_texture_t *t = &brick;\n" STR(CHECKSUM_BODY)
    "\n printf(\"%lu %08lx\\n\", (unsigned long)n, (unsigned long)hsh); return 0; }\n";

/* The fixel include directory: from the build's FXL_TEST_SOURCE_DIR, else
 * next to this source file (__FILE__), else relative to the tests/ working
 * directory. */
static const char *include_dir(void)
{
    static char buf[512];
    const char *tail = strstr(__FILE__, "tests/test_texconv.c");
    char probe[600];
#ifdef FXL_TEST_SOURCE_DIR
    snprintf(buf, sizeof buf, "%s/../include", FXL_TEST_SOURCE_DIR);
    snprintf(probe, sizeof probe, "%s/fixel/texture.h", buf);
    if (exists(probe))
        return buf;
#endif
    if (tail != NULL) {
        snprintf(buf, sizeof buf, "%.*sinclude", (int)(tail - __FILE__), __FILE__);
        snprintf(probe, sizeof probe, "%s/fixel/texture.h", buf);
        if (exists(probe))
            return buf;
    }
    if (exists("../include/fixel/texture.h"))
        return "../include";
    if (exists("include/fixel/texture.h"))
        return "include";
    return NULL;
}

void test_emitted_c_compiles_and_holds_the_same_chain(void)
{
    static const char *formats[] = {"rgb565", "l8", "i8"};
    uint8_t *src = random_image(16, 8, 300);
    uint32_t f;
    const char *inc = include_dir();
    char cmd[2048], line[128];
    FILE *p;
    if (system("cc --version >/dev/null 2>&1") != 0) {
        free(src);
        TEST_IGNORE_MESSAGE("no system cc: cannot compile the emitted C");
    }
    TEST_ASSERT_MESSAGE(inc != NULL, "fixel include directory not found");
    src[4 * 3 + 3] = 0;
    write_png(path_in("brick.png"), 16, 8, src, PNG_COLOR_TYPE_RGBA, 8);
    p = fopen(path_in("main.c"), "w");
    TEST_ASSERT_NOT_NULL(p);
    fputs(k_main, p);
    fclose(p);
    for (f = 0; f < 3; f++) {
        const char *args[] = {path_in("brick.png"), "-o", path_in("brick.c"), "--name", "brick",
                              "--format", formats[f], "--mips", "gamma22", "--key", "FF00FF",
                              "--wrap", "mirror,border", "--border", "123456"};
        texconv_image_t img;
        texconv_chain_t c;
        texconv_opts_t o;
        char err[256];
        uint32_t n, h;
        unsigned long got_n = 0, got_h = 0;
        TEST_ASSERT_EQUAL_INT(0, run_tool(args, 15));
        /* the same conversion in memory */
        texconv_opts_default(&o);
        o.format = (fxl_texfmt_t)f;
        o.mips = TEXCONV_MIPS_GAMMA22;
        o.has_key = 1;
        o.key_rgb = 0xFF00FF;
        o.wrap_u = FXL_WRAP_MIRROR;
        o.wrap_v = FXL_WRAP_BORDER;
        o.border_rgb = 0x123456;
        TEST_ASSERT_EQUAL_INT(0, texconv_read_png(path_in("brick.png"), &img, err, sizeof err));
        TEST_ASSERT_EQUAL_INT(0, texconv_convert(&img, &o, &c, err, sizeof err));
        texconv_image_free(&img);
        checksum(&c.tex, &n, &h);
        texconv_chain_free(&c);

        snprintf(cmd, sizeof cmd,
                 "cc -std=c99 -Wall -Wextra -Wpedantic -Werror -I '%s' '%s' '%s' -o '%s' 2>&1",
                 inc, path_in("brick.c"), path_in("main.c"), path_in("prog"));
        p = popen(cmd, "r");
        TEST_ASSERT_NOT_NULL(p);
        while (fgets(line, sizeof line, p) != NULL)
            fputs(line, stderr); /* compiler diagnostics, if any */
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, pclose(p), formats[f]);
        snprintf(cmd, sizeof cmd, "'%s'", path_in("prog"));
        p = popen(cmd, "r");
        TEST_ASSERT_NOT_NULL(p);
        TEST_ASSERT_EQUAL_INT(2, fscanf(p, "%lu %lx", &got_n, &got_h));
        TEST_ASSERT_EQUAL_INT(0, pclose(p));
        /* 16x8: 128 + 32 + 8 + 2 + 1 = 171 texels */
        TEST_ASSERT_EQUAL_UINT32(171, n);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(n, (uint32_t)got_n, formats[f]);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(h, (uint32_t)got_h, formats[f]);
    }
    free(src);
}

void test_blob_layout(void)
{
    uint8_t *src = random_image(8, 2, 5);
    const char *args[] = {path_in("b.png"), "--bin", path_in("b.bin"), "--format", "i8",
                          "--key", "#000000", "--wrap", "clamp"};
    uint8_t blob[24 + 512 + 64];
    texconv_image_t img;
    texconv_chain_t c;
    texconv_opts_t o;
    char err[256];
    FILE *f;
    size_t got;
    write_png(path_in("b.png"), 8, 2, src, PNG_COLOR_TYPE_RGBA, 8);
    TEST_ASSERT_EQUAL_INT(0, run_tool(args, 9));
    f = fopen(path_in("b.bin"), "rb");
    TEST_ASSERT_NOT_NULL(f);
    got = fread(blob, 1, sizeof blob, f);
    fclose(f);
    /* 8x2 I8, box mips: 16 + 4 + 2 + 1 = 23 texels; 24 + 512 + 23 bytes */
    TEST_ASSERT_EQUAL_UINT32(24 + 512 + 23, (uint32_t)got);
    TEST_ASSERT_EQUAL_MEMORY("FXLT", blob, 4);
    TEST_ASSERT_EQUAL_UINT8(1, blob[4]);
    TEST_ASSERT_EQUAL_UINT8(0, blob[5]);
    TEST_ASSERT_EQUAL_UINT8(3, blob[6]);   /* log2_w */
    TEST_ASSERT_EQUAL_UINT8(1, blob[7]);   /* log2_h */
    TEST_ASSERT_EQUAL_UINT8(4, blob[8]);   /* levels */
    TEST_ASSERT_EQUAL_UINT8(FXL_TEXFMT_I8, blob[9]);
    TEST_ASSERT_EQUAL_UINT8(FXL_WRAP_CLAMP, blob[10]);
    TEST_ASSERT_EQUAL_UINT8(FXL_WRAP_CLAMP, blob[11]);
    TEST_ASSERT_EQUAL_UINT8(FXL_TEXF_KEY, blob[12]);
    TEST_ASSERT_EQUAL_UINT8(0, blob[13]);   /* reserved */
    TEST_ASSERT_EQUAL_UINT8(23, blob[20]);
    TEST_ASSERT_EQUAL_UINT8(0, blob[21]);
    TEST_ASSERT_EQUAL_UINT8(0, blob[22]);   /* texel count, high half */
    TEST_ASSERT_EQUAL_UINT8(0, blob[23]);
    TEST_ASSERT_EQUAL_UINT8(0, blob[18]);   /* reserved */
    TEST_ASSERT_EQUAL_UINT8(0, blob[19]);
    texconv_opts_default(&o);
    o.format = FXL_TEXFMT_I8;
    o.has_key = 1;
    o.key_rgb = 0;
    o.wrap_u = o.wrap_v = FXL_WRAP_CLAMP;
    TEST_ASSERT_EQUAL_INT(0, texconv_read_png(path_in("b.png"), &img, err, sizeof err));
    TEST_ASSERT_EQUAL_INT(0, texconv_convert(&img, &o, &c, err, sizeof err));
    texconv_image_free(&img);
    /* key and border, little-endian, as the converted descriptor has them */
    TEST_ASSERT_EQUAL_UINT8(c.tex.key & 0xFF, blob[14]);
    TEST_ASSERT_EQUAL_UINT8(c.tex.key >> 8, blob[15]);
    TEST_ASSERT_EQUAL_UINT8(c.tex.border & 0xFF, blob[16]);
    TEST_ASSERT_EQUAL_UINT8(c.tex.border >> 8, blob[17]);
    {
        uint32_t i;
        for (i = 0; i < 256; i++) {
            TEST_ASSERT_EQUAL_UINT8(c.palette[i] & 0xFF, blob[24 + 2 * i]);
            TEST_ASSERT_EQUAL_UINT8(c.palette[i] >> 8, blob[24 + 2 * i + 1]);
        }
    }
    TEST_ASSERT_EQUAL_MEMORY(c.texels, blob + 24 + 512, 23);
    texconv_chain_free(&c);
    free(src);
}

/* ---- errors ------------------------------------------------------------------------- */

void test_missing_file_fails_and_writes_nothing(void)
{
    const char *args[] = {path_in("nope.png"), "-o", path_in("out.c"), "--bin",
                          path_in("out.bin")};
    TEST_ASSERT_EQUAL_INT(1, run_tool(args, 5));
    TEST_ASSERT_FALSE(exists(path_in("out.c")));
    TEST_ASSERT_FALSE(exists(path_in("out.bin")));
    TEST_ASSERT_EQUAL_INT(0, dir_entries());
}

void test_truncated_png_fails_and_leaves_no_output_or_temp(void)
{
    uint8_t *src = random_image(32, 32, 0);
    const char *args[] = {path_in("t.png"), "-o", path_in("out.c"), "--bin", path_in("out.bin")};
    FILE *f;
    long size;
    write_png(path_in("t.png"), 32, 32, src, PNG_COLOR_TYPE_RGBA, 8);
    f = fopen(path_in("t.png"), "rb+");
    TEST_ASSERT_NOT_NULL(f);
    fseek(f, 0, SEEK_END);
    size = ftell(f);
    fclose(f);
    TEST_ASSERT_EQUAL_INT(0, truncate(path_in("t.png"), size / 2));
    TEST_ASSERT_NOT_EQUAL(0, run_tool(args, 5));
    TEST_ASSERT_FALSE(exists(path_in("out.c")));
    TEST_ASSERT_FALSE(exists(path_in("out.bin")));
    TEST_ASSERT_EQUAL_INT(1, dir_entries()); /* only t.png */
    free(src);
}

void test_unsupported_inputs_fail_cleanly(void)
{
    uint8_t *src = random_image(12, 8, 0);
    const char *npot[] = {path_in("n.png"), "-o", path_in("out.c")};
    const char *text[] = {path_in("x.txt"), "-o", path_in("out.c")};
    const char *badname[] = {path_in("n.png"), "-o", path_in("out.c"), "--name", "9lives"};
    const char *badopt[] = {path_in("n.png"), "-o", path_in("out.c"), "--format", "rgb888"};
    const char *noout[] = {path_in("n.png")};
    FILE *f;
    write_png(path_in("n.png"), 12, 8, src, PNG_COLOR_TYPE_RGBA, 8);
    f = fopen(path_in("x.txt"), "w");
    TEST_ASSERT_NOT_NULL(f);
    fputs("this is not a PNG file\n", f);
    fclose(f);
    /* the input's faults exit 1, the command line's 2 (docs/textures.md) */
    TEST_ASSERT_EQUAL_INT(1, run_tool(npot, 3));   /* 12x8: not a power of two */
    TEST_ASSERT_EQUAL_INT(1, run_tool(text, 3));
    TEST_ASSERT_EQUAL_INT(2, run_tool(badname, 5));
    TEST_ASSERT_EQUAL_INT(2, run_tool(badopt, 5));
    TEST_ASSERT_EQUAL_INT(2, run_tool(noout, 1));
    TEST_ASSERT_FALSE(exists(path_in("out.c")));
    TEST_ASSERT_EQUAL_INT(2, dir_entries());
    free(src);
}

/* "-o x --bin x" left only the blob in x and "-o in.png" replaced the image
 * with C source, both with exit status 0: the tool now refuses (status 2). */
void test_outputs_that_meet_each_other_or_the_input_are_refused(void)
{
    uint8_t *src = random_image(4, 4, 0);
    texconv_image_t img;
    char err[256], same_dot[300];
    const char *pair[] = {path_in("in.png"), "-o", path_in("x.out"), "--bin", path_in("x.out")};
    const char *pair_dot[] = {path_in("in.png"), "-o", path_in("x.out"), "--bin", same_dot};
    const char *onto_in[] = {path_in("in.png"), "-o", path_in("in.png")};
    const char *bin_onto_in[] = {path_in("in.png"), "--bin", path_in("in.png")};
    snprintf(same_dot, sizeof same_dot, "%s/./x.out", g_dir);
    write_png(path_in("in.png"), 4, 4, src, PNG_COLOR_TYPE_RGBA, 8);
    TEST_ASSERT_EQUAL_INT(2, run_tool(pair, 5));
    TEST_ASSERT_EQUAL_INT(2, run_tool(pair_dot, 5));
    TEST_ASSERT_EQUAL_INT(2, run_tool(onto_in, 3));
    TEST_ASSERT_EQUAL_INT(2, run_tool(bin_onto_in, 3));
    TEST_ASSERT_EQUAL_INT(1, dir_entries()); /* only in.png, and still a PNG */
    TEST_ASSERT_EQUAL_INT(0, texconv_read_png(path_in("in.png"), &img, err, sizeof err));
    texconv_image_free(&img);
    free(src);
}

/* The output may be a device or a FIFO ("-o /dev/null" to check an image): it
 * is written in place. A temp file renamed over it replaced the node itself
 * (run as root, /dev/null became a regular file). A FIFO shows it unprivileged. */
void test_non_regular_output_is_written_in_place(void)
{
    uint8_t *src = random_image(2, 2, 0);
    const char *args[] = {path_in("in.png"), "-o", path_in("fifo")};
    struct stat st;
    char head[32];
    ssize_t n;
    int fd;
    write_png(path_in("in.png"), 2, 2, src, PNG_COLOR_TYPE_RGBA, 8);
    TEST_ASSERT_EQUAL_INT(0, mkfifo(path_in("fifo"), 0600));
    /* The reader end first, so opening for writing does not block; the C
     * source of a 2x2 chain (about 1.3 KB) fits the pipe's buffer. */
    fd = open(path_in("fifo"), O_RDONLY | O_NONBLOCK);
    TEST_ASSERT_TRUE(fd >= 0);
    TEST_ASSERT_EQUAL_INT(0, run_tool(args, 3));
    TEST_ASSERT_EQUAL_INT(0, lstat(path_in("fifo"), &st));
    TEST_ASSERT_TRUE_MESSAGE(S_ISFIFO(st.st_mode), "the FIFO was replaced by a file");
    n = read(fd, head, sizeof head - 1);
    close(fd);
    TEST_ASSERT_TRUE(n > 0);
    head[n] = '\0';
    TEST_ASSERT_TRUE_MESSAGE(strncmp(head, "/* Generated by fixel-texconv", 29) == 0, head);
    TEST_ASSERT_EQUAL_INT(2, dir_entries()); /* in.png and the FIFO: no temp file left */
    free(src);
}

/* --key and --border take exactly six hex digits: strtoul also took "0x1234",
 * " +1234" and "-00001" (which wrapped to 0xFFFFFFFF: key "#FFFFFFFF"). */
void test_colour_options_want_exactly_six_hex_digits(void)
{
    static const char *const bad[] = {"-00001", "0x1234", " +1234", "12345", "1234567", "12345g",
                                      "#12345", ""};
    uint8_t *src = random_image(2, 2, 0);
    size_t i;
    write_png(path_in("in.png"), 2, 2, src, PNG_COLOR_TYPE_RGBA, 8);
    for (i = 0; i < sizeof bad / sizeof bad[0]; i++) {
        const char *key[] = {path_in("in.png"), "-o", path_in("o.c"), "--key", bad[i]};
        const char *border[] = {path_in("in.png"), "-o", path_in("o.c"), "--border", bad[i]};
        TEST_ASSERT_EQUAL_INT_MESSAGE(2, run_tool(key, 5), bad[i]);
        TEST_ASSERT_EQUAL_INT_MESSAGE(2, run_tool(border, 5), bad[i]);
    }
    TEST_ASSERT_FALSE(exists(path_in("o.c")));
    {
        const char *ok[] = {path_in("in.png"), "-o", path_in("o.c"), "--key", "#a0B0c0"};
        TEST_ASSERT_EQUAL_INT(0, run_tool(ok, 5));
    }
    free(src);
}

/* `const fxl_texture_t int = {` does not compile: keywords are refused, also
 * when the name comes from the file ("int.png"). */
void test_c_keyword_names_are_refused(void)
{
    uint8_t *src = random_image(2, 2, 0);
    const char *named[] = {path_in("in.png"), "-o", path_in("o.c"), "--name", "int"};
    const char *from_file[] = {path_in("int.png"), "-o", path_in("o.c")};
    write_png(path_in("in.png"), 2, 2, src, PNG_COLOR_TYPE_RGBA, 8);
    write_png(path_in("int.png"), 2, 2, src, PNG_COLOR_TYPE_RGBA, 8);
    /* names the generated file's headers use gave C that did not compile */
    static const char *const clash[] = {"uint16_t", "fxl_texture_t", "fxl_brick", "FXL_OK", "FIXEL_TEXTURE_H",
                                        "_Brick",   "__brick",       "UINT16_MAX", "INT8_MIN", "INTMAX_C",
                                        "INT8_WIDTH", "main"};   /* -Wmain, and the program's own */
    size_t k;
    TEST_ASSERT_EQUAL_INT(2, run_tool(named, 5));
    TEST_ASSERT_EQUAL_INT(2, run_tool(from_file, 3));
    for (k = 0; k < sizeof clash / sizeof clash[0]; k++) {
        named[4] = clash[k];
        TEST_ASSERT_EQUAL_INT_MESSAGE(2, run_tool(named, 5), clash[k]);
    }
    TEST_ASSERT_FALSE(exists(path_in("o.c")));
    /* and ordinary ones are taken (mixed case is not a limit macro) */
    named[4] = "brick_2";
    TEST_ASSERT_EQUAL_INT(0, run_tool(named, 5));
    named[4] = "Max_C";
    TEST_ASSERT_EQUAL_INT(0, run_tool(named, 5));
    free(src);
}

/* 16-bit samples round to the nearest 8-bit value, as png_io.c reads them:
 * v8 = (v16 * 255 + 32767) / 65535, so 0xFF00 -> 254 and 0x00FF -> 1 (taking
 * the high byte gave 255 and 0). */
void test_16bit_samples_round_to_nearest(void)
{
    static const uint16_t v16[4] = {0xFF00u, 0x00FFu, 0x8080u, 0xFFFFu};
    static const uint8_t want[4] = {254, 1, 128, 255};
    png_byte row[8];
    texconv_image_t img;
    char err[256];
    FILE *f = fopen(path_in("g16.png"), "wb");
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, NULL, NULL, NULL);
    png_infop info = png_create_info_struct(png);
    int i;
    TEST_ASSERT_NOT_NULL(f);
    if (setjmp(png_jmpbuf(png)))
        TEST_FAIL_MESSAGE("libpng write failed");
    png_init_io(png, f);
    png_set_IHDR(png, info, 4, 1, 16, PNG_COLOR_TYPE_GRAY, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (i = 0; i < 4; i++) {
        row[2 * i] = (png_byte)(v16[i] >> 8); /* PNG samples are big-endian */
        row[2 * i + 1] = (png_byte)v16[i];
    }
    png_write_row(png, row);
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    fclose(f);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, texconv_read_png(path_in("g16.png"), &img, err, sizeof err), err);
    for (i = 0; i < 4; i++) {
        TEST_ASSERT_EQUAL_UINT8(want[i], img.rgba[4 * i]);
        TEST_ASSERT_EQUAL_UINT8(want[i], img.rgba[4 * i + 2]);
        TEST_ASSERT_EQUAL_UINT8(255, img.rgba[4 * i + 3]);
    }
    texconv_image_free(&img);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_colour_conversions_round_to_nearest);
    RUN_TEST(test_read_png_any_colour_type_gives_rgba8);
    RUN_TEST(test_read_png_grey_alpha_low_depths_trns_and_interlace);
    RUN_TEST(test_roundtrip_rgb565_level0_equals_png_pixels);
    RUN_TEST(test_roundtrip_l8_and_exact_i8_with_key);
    RUN_TEST(test_i8_quantiser_maps_every_pixel_to_its_nearest_entry);
    RUN_TEST(test_i8_quantiser_survives_a_dominant_colour);
    RUN_TEST(test_short_program_name_is_not_an_overflow);
    RUN_TEST(test_emitted_c_compiles_and_holds_the_same_chain);
    RUN_TEST(test_blob_layout);
    RUN_TEST(test_missing_file_fails_and_writes_nothing);
    RUN_TEST(test_truncated_png_fails_and_leaves_no_output_or_temp);
    RUN_TEST(test_unsupported_inputs_fail_cleanly);
    RUN_TEST(test_outputs_that_meet_each_other_or_the_input_are_refused);
    RUN_TEST(test_non_regular_output_is_written_in_place);
    RUN_TEST(test_colour_options_want_exactly_six_hex_digits);
    RUN_TEST(test_c_keyword_names_are_refused);
    RUN_TEST(test_16bit_samples_round_to_nearest);
    return UNITY_END();
}

/* test_scene.c - the simulator's host library: scene builder, CRC-32, PNG
 * round trip, procedural textures. Needs no rasterizer output. */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include "crc32.h"
#include "png_io.h"
#include "scene.h"
#include "test_features.h"
#include "textures.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

static char msg[512];

static int build(const char *name, scene_t *s)
{
    return scene_build(name, SCENE_DEFAULT_WIDTH, SCENE_DEFAULT_HEIGHT, s);
}

/* Point-in-triangle for a pixel centre in double on the (unsnapped) q16
 * vertices; boundary counts as inside (only used away from edges). */
static int inside_tri(const fxl_vertex_t *v, double px, double py)
{
    double e[3];
    int k, pos = 0, neg = 0;
    for (k = 0; k < 3; k++) {
        const fxl_vertex_t *a = &v[k], *b = &v[(k + 1) % 3];
        double ax = a->x / 65536.0, ay = a->y / 65536.0, bx = b->x / 65536.0, by = b->y / 65536.0;
        e[k] = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
        pos |= e[k] > 0;
        neg |= e[k] < 0;
    }
    return !(pos && neg);
}

static void test_scene_triangle_counts(void)
{
    /* Counts follow from the definitions in scene.h: floor 1 quad; floor_tess
     * 16 x 32 quads; cube 3 visible faces x 2; fan 24 + 16 * 16 * 2; tunnel
     * 24 x 40 quads (the 24 of the first ring clipped to quads again);
     * small_tris 50 x 40. */
    static const struct {
        const char *name;
        uint32_t tris;
    } expect[] = {{"floor", 2},   {"floor_tess", 1024}, {"floor_rolled", 2}, {"cube", 6},
                  {"fan", 536},   {"tunnel", 1920},     {"quad_near", 2},    {"small_tris", 2000}};
    size_t i;
    TEST_ASSERT_EQUAL_UINT32(sizeof(expect) / sizeof(expect[0]), scene_count());
    for (i = 0; i < sizeof(expect) / sizeof(expect[0]); i++) {
        scene_t s;
        TEST_ASSERT_EQUAL_STRING(expect[i].name, scene_name(i));
        TEST_ASSERT_EQUAL_INT(SCENE_OK, build(expect[i].name, &s));
        snprintf(msg, sizeof(msg), "scene %s: %lu triangles, expected %lu", expect[i].name,
                 (unsigned long)s.tri_count, (unsigned long)expect[i].tris);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(expect[i].tris, s.tri_count, msg);
        scene_free(&s);
    }
    TEST_ASSERT_NULL(scene_name(scene_count()));
}

static void test_scene_every_inv_w_positive(void)
{
    size_t i;
    uint32_t k;
    for (i = 0; i < scene_count(); i++) {
        scene_t s;
        TEST_ASSERT_EQUAL_INT(SCENE_OK, build(scene_name(i), &s));
        for (k = 0; k < 3u * s.tri_count; k++) {
            snprintf(msg, sizeof(msg), "scene %s vertex %lu has inv_w 0", s.name,
                     (unsigned long)k);
            TEST_ASSERT_TRUE_MESSAGE(s.verts[k].inv_w > 0u, msg);
        }
        scene_free(&s);
    }
}

static void test_scene_tunnel_near_clip_reaches_scale_one(void)
{
    /* The tunnel starts at z = 0, behind the near plane (0.1): clipping puts
     * vertices exactly on w = near, where inv_w = near / w * (2^32 - 1) is
     * exactly UINT32_MAX; no vertex can exceed it (nothing behind the eye). */
    scene_t s;
    uint32_t k, at_near = 0;
    TEST_ASSERT_EQUAL_INT(SCENE_OK, build("tunnel", &s));
    TEST_ASSERT_EQUAL_UINT32(24, s.clipped);
    for (k = 0; k < 3u * s.tri_count; k++) {
        at_near += s.verts[k].inv_w == UINT32_MAX;
    }
    TEST_ASSERT_GREATER_THAN(0, at_near);
    scene_free(&s);
}

static void test_scene_floor_covers_lower_half_not_top(void)
{
    /* Derivation (scene.h conventions, f = 1 / tan 30 = 1.7320508):
     * far edge z = -50: ndc_y = -0.577 f / 50 = -0.019988, screen y = 122.40;
     * near edge z = -1: screen y = (0.5 + 0.99939 / 2) * 240 = 239.93; the far
     * edge spans x = +-40 -> screen x = 160 +- 166 (beyond both sides). So
     * every pixel centre of rows 123..239 (centres 123.5..239.5) is on the
     * floor and none of rows 0..121 (centres up to 121.5) is. */
    scene_t s;
    int x, y;
    TEST_ASSERT_EQUAL_INT(SCENE_OK, build("floor", &s));
    for (y = 0; y < SCENE_DEFAULT_HEIGHT; y++) {
        for (x = 0; x < SCENE_DEFAULT_WIDTH; x++) {
            int in = inside_tri(&s.verts[0], x + 0.5, y + 0.5) ||
                     inside_tri(&s.verts[3], x + 0.5, y + 0.5);
            if (y <= 121 || y >= 123) {
                snprintf(msg, sizeof(msg), "floor pixel (%d, %d): covered %d, expected %d", x, y,
                         in, y >= 123);
                TEST_ASSERT_TRUE_MESSAGE(in == (y >= 123), msg);
            }
        }
    }
    scene_free(&s);
}

static void test_scene_cube_shows_three_faces_half_screen_high(void)
{
    /* A cube seen from a generic direction shows 3 faces; the other 3 are
     * back faces. Height: measured 61.06..187.88 px = 126.8 px = 0.53 of 240
     * ("about half"); the bound [0.4, 0.65] H rejects a wrong distance or fov. */
    scene_t s;
    uint32_t k;
    double y0 = 1e9, y1 = -1e9;
    TEST_ASSERT_EQUAL_INT(SCENE_OK, build("cube", &s));
    TEST_ASSERT_EQUAL_UINT32(3, s.culled_backface);
    for (k = 0; k < 3u * s.tri_count; k++) {
        double y = s.verts[k].y / 65536.0;
        y0 = y < y0 ? y : y0;
        y1 = y > y1 ? y : y1;
    }
    snprintf(msg, sizeof(msg), "cube height %.2f px", y1 - y0);
    TEST_ASSERT_TRUE_MESSAGE(y1 - y0 >= 0.4 * 240 && y1 - y0 <= 0.65 * 240, msg);
    scene_free(&s);
}

static void test_scene_fan_closed_and_on_screen(void)
{
    /* The watertightness tests need the whole mesh on screen, and the fan
     * must close on the very same vertex it started from. */
    scene_t s;
    uint32_t k;
    TEST_ASSERT_EQUAL_INT(SCENE_OK, build("fan", &s));
    TEST_ASSERT_EQUAL_MEMORY(&s.verts[1], &s.verts[3 * 23 + 2], sizeof(fxl_vertex_t));
    for (k = 0; k < 3u * s.tri_count; k++) {
        snprintf(msg, sizeof(msg), "fan vertex %lu at (%.3f, %.3f) off screen", (unsigned long)k,
                 s.verts[k].x / 65536.0, s.verts[k].y / 65536.0);
        TEST_ASSERT_TRUE_MESSAGE(s.verts[k].x >= 0 && s.verts[k].x <= 320 * 65536 &&
                                     s.verts[k].y >= 0 && s.verts[k].y <= 240 * 65536,
                                 msg);
    }
    scene_free(&s);
}

static void test_scene_build_errors(void)
{
    scene_t s;
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_NAME, scene_build("nosuch", 320, 240, &s));
    TEST_ASSERT_NULL(s.verts);
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_NAME, scene_build(NULL, 320, 240, &s));
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_SIZE, scene_build("floor", 0, 240, &s));
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_SIZE, scene_build("floor", 320, FXL_TARGET_MAX_DIM + 1, &s));
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_NAME, scene_build("floor", 320, 240, NULL));
}

static void test_scene_builds_at_other_sizes(void)
{
    /* Scenes are defined in view space, so any size works. Up to 640 x 480
     * the guard band (g = 60000 / 640 - 1 = 92.75) is beyond every scene
     * (largest |ndc| at any size: floor 52.0, floor_rolled 40.3), so the
     * triangle counts must not change. At 4096 x 4096 (g = 13.6) the floor
     * and tunnel are cut by the guard band: every vertex must then lie within
     * the +-30000 px it promises. */
    static const int32_t sizes[][2] = {{1, 1}, {64, 48}, {240, 320}, {640, 480}, {4096, 4096}};
    size_t i, k;
    uint32_t j;
    for (i = 0; i < scene_count(); i++) {
        scene_t ref;
        TEST_ASSERT_EQUAL_INT(SCENE_OK, build(scene_name(i), &ref));
        TEST_ASSERT_EQUAL_UINT32(0, ref.guard_clipped);
        for (k = 0; k < sizeof(sizes) / sizeof(sizes[0]); k++) {
            scene_t s;
            int rc = scene_build(scene_name(i), sizes[k][0], sizes[k][1], &s);
            snprintf(msg, sizeof(msg), "scene %s at %ldx%ld: %s", scene_name(i),
                     (long)sizes[k][0], (long)sizes[k][1], scene_strerror(rc));
            TEST_ASSERT_EQUAL_INT_MESSAGE(SCENE_OK, rc, msg);
            if (sizes[k][0] <= 640) {
                TEST_ASSERT_EQUAL_UINT32_MESSAGE(ref.tri_count, s.tri_count, msg);
            }
            TEST_ASSERT_TRUE_MESSAGE(s.tri_count > 0, msg);
            for (j = 0; j < 3u * s.tri_count; j++) {
                TEST_ASSERT_TRUE_MESSAGE(s.verts[j].x >= -30000 * 65536 - 1 &&
                                             s.verts[j].x <= 30000 * 65536 + 1 &&
                                             s.verts[j].y >= -30000 * 65536 - 1 &&
                                             s.verts[j].y <= 30000 * 65536 + 1,
                                         msg);
            }
            scene_free(&s);
        }
        scene_free(&ref);
    }
}

static void test_crc32_check_value(void)
{
    /* The standard check value of CRC-32/ISO-HDLC. */
    const char *s = "123456789";
    TEST_ASSERT_EQUAL_HEX32(0xCBF43926u, crc32_update(0, s, 9));
    /* Streaming in pieces gives the same value. */
    TEST_ASSERT_EQUAL_HEX32(0xCBF43926u, crc32_update(crc32_update(0, s, 4), s + 4, 5));
    TEST_ASSERT_EQUAL_HEX32(0u, crc32_update(0, s, 0));
}

static void test_crc_target_hashes_clip_rows_only(void)
{
    /* 5x4 buffer, stride 7; clip [1, 4) x [1, 3): the CRC equals that of the
     * six clipped pixels' bytes in row order, whatever lies outside. */
    uint16_t px[7 * 4], expect[6];
    fxl_target_t t;
    fxl_rect_t r = {1, 1, 4, 3};
    int i;
    for (i = 0; i < 7 * 4; i++) {
        px[i] = (uint16_t)(i * 2654435761u >> 16);
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, px, 5, 4, 7, FXL_PIXFMT_RGB565));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_clip(&t, &r));
    for (i = 0; i < 3; i++) {
        expect[i] = px[7 + 1 + i];
        expect[3 + i] = px[14 + 1 + i];
    }
    TEST_ASSERT_EQUAL_HEX32(crc32_update(0, expect, sizeof(expect)), fxl_host_crc_target(&t));
    px[0] ^= 0xFFFFu; /* outside the clip */
    px[6] ^= 0xFFFFu; /* stride padding */
    TEST_ASSERT_EQUAL_HEX32(crc32_update(0, expect, sizeof(expect)), fxl_host_crc_target(&t));
}

static void tmp_path(char *buf, size_t n, const char *leaf)
{
    const char *dir = getenv("FXL_TEST_OUTPUT_DIR");
#ifdef FXL_TEST_OUTPUT_DIR
    if (dir == NULL || dir[0] == '\0') {
        dir = FXL_TEST_OUTPUT_DIR;
    }
#endif
    if (dir == NULL || dir[0] == '\0') {
        dir = "/tmp";
    }
    snprintf(buf, n, "%s/%s_%ld.png", dir, leaf, (long)getpid());
}

static void test_png_round_trip_expands_565_exactly(void)
{
    /* 37 x 13 image with stride 41 holding every 5- and 6-bit channel value;
     * written once native and once byte-swapped, both must read back as the
     * bit-replicated 8-bit values with alpha 255. */
    enum { W = 37, H = 13, STRIDE = 41 };
    static uint16_t px[STRIDE * H], swapped[STRIDE * H];
    char path[1024], err[256];
    int pass, x, y;
    for (y = 0; y < H; y++) {
        for (x = 0; x < STRIDE; x++) {
            unsigned i = (unsigned)(y * W + x);
            uint16_t c = (uint16_t)(((i % 32u) << 11) | (((i * 7u) % 64u) << 5) | ((i * 3u) % 32u));
            px[y * STRIDE + x] = c;
            swapped[y * STRIDE + x] = (uint16_t)((c >> 8) | (c << 8));
        }
    }
    tmp_path(path, sizeof(path), "test_scene_roundtrip");
    for (pass = 0; pass < 2; pass++) {
        uint8_t *rgba = NULL;
        uint32_t w = 0, h = 0;
        int rc = pngio_write_rgb565(path, pass ? swapped : px, W, H, STRIDE,
                                    pass ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565, err,
                                    sizeof(err));
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, rc, err);
        rc = pngio_read_rgba8(path, &rgba, &w, &h, err, sizeof(err));
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, rc, err);
        TEST_ASSERT_EQUAL_UINT32(W, w);
        TEST_ASSERT_EQUAL_UINT32(H, h);
        for (y = 0; y < H; y++) {
            for (x = 0; x < W; x++) {
                uint16_t c = px[y * STRIDE + x];
                unsigned r5 = c >> 11, g6 = (c >> 5) & 63u, b5 = c & 31u;
                const uint8_t *p = rgba + ((size_t)y * W + (size_t)x) * 4u;
                unsigned er = (r5 << 3) | (r5 >> 2), eg = (g6 << 2) | (g6 >> 4),
                         eb = (b5 << 3) | (b5 >> 2);
                snprintf(msg, sizeof(msg),
                         "pass %d pixel (%d, %d) 0x%04X: got %u %u %u %u, expected %u %u %u 255",
                         pass, x, y, c, p[0], p[1], p[2], p[3], er, eg, eb);
                TEST_ASSERT_TRUE_MESSAGE(p[0] == er && p[1] == eg && p[2] == eb && p[3] == 255,
                                         msg);
            }
        }
        free(rgba);
    }
    remove(path);
}

static void test_png_errors_are_reported_without_partial_files(void)
{
    char path[1024], err[256];
    uint8_t *rgba = (uint8_t *)&rgba; /* must be reset to NULL */
    uint32_t w = 1, h = 1;
    uint16_t px[4] = {0, 0, 0, 0};
    FILE *f;
    tmp_path(path, sizeof(path), "test_scene_missing");
    err[0] = '\0';
    TEST_ASSERT_EQUAL_INT(-1, pngio_read_rgba8(path, &rgba, &w, &h, err, sizeof(err)));
    TEST_ASSERT_NULL(rgba);
    TEST_ASSERT_EQUAL_UINT32(0, w);
    TEST_ASSERT_TRUE(strstr(err, "cannot open") != NULL);
    /* A text file is not a PNG. */
    f = fopen(path, "wb");
    TEST_ASSERT_NOT_NULL(f);
    fputs("definitely not a png\n", f);
    fclose(f);
    TEST_ASSERT_EQUAL_INT(-1, pngio_read_rgba8(path, &rgba, &w, &h, err, sizeof(err)));
    TEST_ASSERT_TRUE_MESSAGE(strstr(err, "not a PNG") != NULL, err);
    remove(path);
    /* Writing into a directory that does not exist fails cleanly. */
    TEST_ASSERT_EQUAL_INT(-1, pngio_write_rgb565("/nonexistent-dir-fixel/x.png", px, 2, 2, 2,
                                                 FXL_PIXFMT_RGB565, err, sizeof(err)));
    TEST_ASSERT_TRUE_MESSAGE(strstr(err, "cannot create") != NULL, err);
    /* Bad arguments are errors, not crashes. */
    TEST_ASSERT_EQUAL_INT(-1, pngio_write_rgb565(path, px, 2, 2, 1, FXL_PIXFMT_RGB565, err,
                                                 sizeof(err)));
    TEST_ASSERT_EQUAL_INT(-1, pngio_write_rgb565(path, NULL, 2, 2, 2, FXL_PIXFMT_RGB565, err,
                                                 sizeof(err)));
    f = fopen(path, "rb");
    TEST_ASSERT_NULL(f); /* nothing was left behind */
}

/* A device or FIFO target ("fixel-sim -o /dev/null") is written in place: a
 * temp file renamed over it replaced the node itself (as root, /dev/null
 * became a regular file). A FIFO shows it without privileges. */
static void test_png_write_to_a_fifo_keeps_the_fifo(void)
{
    char path[1024], err[256];
    uint16_t px[4] = {0xF800u, 0x07E0u, 0x001Fu, 0xFFFFu};
    unsigned char sig[8];
    struct stat st;
    ssize_t n;
    int fd;
    tmp_path(path, sizeof(path), "test_scene_fifo");
    (void)remove(path);
    TEST_ASSERT_EQUAL_INT(0, mkfifo(path, 0600));
    /* Reader first, so the write end opens at once; a 2x2 PNG fits the pipe. */
    fd = open(path, O_RDONLY | O_NONBLOCK);
    TEST_ASSERT_TRUE(fd >= 0);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, pngio_write_rgb565(path, px, 2, 2, 2, FXL_PIXFMT_RGB565, err,
                                                        sizeof(err)), err);
    TEST_ASSERT_EQUAL_INT(0, lstat(path, &st));
    TEST_ASSERT_TRUE_MESSAGE(S_ISFIFO(st.st_mode), "the FIFO was replaced by a file");
    n = read(fd, sig, sizeof(sig));
    close(fd);
    remove(path);
    TEST_ASSERT_EQUAL_INT(8, (int)n);
    TEST_ASSERT_EQUAL_UINT8(0x89, sig[0]);
    TEST_ASSERT_EQUAL_UINT8('P', sig[1]);
}

static void test_texture_checker_mips_are_box_averages(void)
{
    /* 64x64 checker with 8-texel cells: level 3 (8x8) averages one whole
     * cell per texel, so it is the checker of the two colours exactly;
     * level 4 (4x4) averages two c0 and two c1 cells per texel: per channel
     * (2 a + 2 b + 2) >> 2. Levels: 64 -> 1 is 7 levels, 4/3-ish storage. */
    host_texture_t t;
    const uint16_t c0 = FXL_RGB565(235, 235, 235), c1 = FXL_RGB565(40, 40, 48);
    const uint16_t *l3, *l4;
    unsigned r, g, b;
    uint32_t x, y;
    TEST_ASSERT_EQUAL_INT(0, texture_make(&t, TEXTURE_CHECKER));
    TEST_ASSERT_EQUAL_UINT8(7, t.tex.levels);
    TEST_ASSERT_EQUAL_UINT32(4096 + 1024 + 256 + 64 + 16 + 4 + 1, t.texel_count);
    l3 = t.texels + 4096 + 1024 + 256;
    l4 = l3 + 64;
    for (y = 0; y < 8; y++) {
        for (x = 0; x < 8; x++) {
            TEST_ASSERT_EQUAL_HEX16(((x + y) & 1u) ? c1 : c0, l3[y * 8 + x]);
        }
    }
    r = (2u * (c0 >> 11) + 2u * (c1 >> 11) + 2u) >> 2;
    g = (2u * ((c0 >> 5) & 63u) + 2u * ((c1 >> 5) & 63u) + 2u) >> 2;
    b = (2u * (c0 & 31u) + 2u * (c1 & 31u) + 2u) >> 2;
    TEST_ASSERT_EQUAL_HEX16((r << 11) | (g << 5) | b, l4[0]);
    texture_free(&t);
}

static void test_texture_crate_marks_corners(void)
{
    /* The orientation marks documented in textures.h. */
    host_texture_t t;
    TEST_ASSERT_EQUAL_INT(0, texture_make(&t, TEXTURE_CRATE));
    TEST_ASSERT_EQUAL_HEX16(FXL_RGB565(255, 0, 0), texture_texel(&t, 0, 0));
    TEST_ASSERT_EQUAL_HEX16(FXL_RGB565(0, 255, 0), texture_texel(&t, 63, 0));
    TEST_ASSERT_EQUAL_HEX16(FXL_RGB565(0, 0, 255), texture_texel(&t, 0, 63));
    TEST_ASSERT_NOT_EQUAL(FXL_RGB565(255, 0, 0), texture_texel(&t, 63, 63));
    texture_free(&t);
    TEST_ASSERT_EQUAL_INT(-1, texture_make_crate(&t, 48)); /* not a power of two */
    TEST_ASSERT_NULL(t.texels);
}

static void test_texture_grid_lines_every_8_texels(void)
{
    host_texture_t t;
    uint32_t i;
    TEST_ASSERT_EQUAL_INT(0, texture_make(&t, TEXTURE_GRID));
    TEST_ASSERT_EQUAL_UINT32(128, t.width);
    for (i = 0; i < 128; i++) {
        uint16_t expect = (i % 32u == 0) ? FXL_RGB565(255, 255, 255) : FXL_RGB565(170, 170, 170);
        /* row 8 is a line everywhere except where a 32-block line crosses */
        TEST_ASSERT_EQUAL_HEX16(expect, texture_texel(&t, i, 8));
        TEST_ASSERT_EQUAL_HEX16(expect, texture_texel(&t, 8, i));
    }
    texture_free(&t);
}

static void test_texture_checker_hc_mips_average_in_linear_light(void)
{
    /* TEXTURE_CHECKER_HC: 256x256, 16-texel cells of white and black, levels
     * by fxl_mip_build in sRGB linear light. Level 4 (16x16) is one texel
     * per cell: still pure black and white. Level 5 and up average equal
     * numbers of black and white: linear 0.5, sRGB-encoded 0.7354, i.e.
     * 0.7354 * 31 = 22.8 -> 23 (red, blue) and 0.7354 * 63 = 46.3 -> 46
     * (green), far above the stored-value mean 15 / 31 that darkens. */
    host_texture_t t;
    const uint16_t grey = (uint16_t)((23u << 11) | (46u << 5) | 23u);
    uint32_t l, i;
    TEST_ASSERT_EQUAL_INT(0, texture_make(&t, TEXTURE_CHECKER_HC));
    TEST_ASSERT_EQUAL_UINT8(9, t.tex.levels);
    TEST_ASSERT_EQUAL_HEX16(0xFFFF, t.texels[fxl_texture_level_offset(&t.tex, 4)]);
    TEST_ASSERT_EQUAL_HEX16(0x0000, t.texels[fxl_texture_level_offset(&t.tex, 4) + 1]);
    for (l = 5; l < 9; l++) {
        uint32_t off = fxl_texture_level_offset(&t.tex, l), n = (256u >> l) * (256u >> l);
        for (i = 0; i < n; i++) {
            snprintf(msg, sizeof(msg), "level %lu texel %lu: 0x%04X, expected 0x%04X",
                     (unsigned long)l, (unsigned long)i, (unsigned)t.texels[off + i],
                     (unsigned)grey);
            TEST_ASSERT_EQUAL_INT_MESSAGE(grey, t.texels[off + i], msg);
        }
    }
    texture_free(&t);
}

static void test_texture_cubemap_tiles_framed_and_coloured(void)
{
    /* 256x128 atlas, tiles 85.33 x 64 texels (textures.h). The texel whose
     * centre is within 2 texels of a tile edge is the dark frame; a texel a
     * quarter into each tile (clear of lines, which sit at eighths, and of
     * the label) has that face's own colour, so all six differ. */
    host_texture_t t;
    const uint16_t dark = FXL_RGB565(24, 24, 28);
    uint16_t body[6];
    int f, g;
    TEST_ASSERT_EQUAL_INT(0, texture_make(&t, TEXTURE_CUBEMAP));
    TEST_ASSERT_EQUAL_UINT32(256, t.width);
    TEST_ASSERT_EQUAL_UINT32(128, t.height);
    for (f = 0; f < 6; f++) {
        uint32_t x0 = (uint32_t)((f % 3) * 256 / 3), y0 = (uint32_t)(f / 3) * 64u;
        uint32_t x1 = (uint32_t)((f % 3 + 1) * 256 / 3) - 1u, y1 = y0 + 63u;
        TEST_ASSERT_EQUAL_HEX16(dark, texture_texel(&t, x0 + 1u, y0 + 30u));
        TEST_ASSERT_EQUAL_HEX16(dark, texture_texel(&t, x1, y0 + 30u));
        TEST_ASSERT_EQUAL_HEX16(dark, texture_texel(&t, x0 + 30u, y0));
        TEST_ASSERT_EQUAL_HEX16(dark, texture_texel(&t, x0 + 30u, y1));
        body[f] = texture_texel(&t, x0 + 13u, y0 + 52u);
        for (g = 0; g < f; g++) {
            snprintf(msg, sizeof(msg), "tiles %d and %d have the same colour 0x%04X", g, f,
                     (unsigned)body[f]);
            TEST_ASSERT_TRUE_MESSAGE(body[g] != body[f], msg);
        }
    }
    texture_free(&t);
}

static void test_font_covers_labels(void)
{
    /* Letters of either case share a glyph; unknown characters are blank. */
    const uint8_t blank[5] = {0, 0, 0, 0, 0};
    TEST_ASSERT_EQUAL_MEMORY(texture_font_glyph('a'), texture_font_glyph('A'), 5);
    TEST_ASSERT_EQUAL_MEMORY(blank, texture_font_glyph(' '), 5);
    TEST_ASSERT_EQUAL_MEMORY(blank, texture_font_glyph('#'), 5);
    TEST_ASSERT_EQUAL_UINT8(7, texture_font_glyph('T')[0]);
    TEST_ASSERT_EQUAL_UINT8(2, texture_font_glyph('T')[4]);
    TEST_ASSERT_EQUAL_UINT8(4, texture_font_glyph(',')[4]);
}

static fxl_status_t draw_collected(const fxl_band_tri_t *tris, size_t n, fxl_target_t *t)
{
    size_t i;
    for (i = 0; i < n; i++) {
        fxl_status_t st = fxl_draw_triangle(t, tris[i].draw, tris[i].v, NULL);
        if (st != FXL_OK) {
            return st;
        }
    }
    return FXL_OK;
}

static void test_pscene_collected_triangles_draw_the_same_image(void)
{
    /* The panel path hands pscene_collect's triangles to the band renderer;
     * the gallery draws meshes with fxl_mesh_draw. Both must give the same
     * pixels for every pipeline scene (same front end, same order). */
    size_t i, refused = 0;
    TEST_ASSERT_EQUAL_UINT32(6, pscene_count());
    for (i = 0; i < pscene_count(); i++) {
        pscene_t s;
        frame_t a, b;
        fxl_draw_t d, draws[PSCENE_MAX_PARTS];
        fxl_band_tri_t *tris = NULL;
        fxl_stats_t st;
        size_t n = 0;
        const char *missing;
        memset(&st, 0, sizeof(st));
        fxl_draw_defaults(&d);
        /* What the build has: point without bilinear, level 0 without mip
         * selection, no depth buffer without depth (both images are drawn
         * in the same order, so they must still be equal). */
        d.filter = FXL_HAVE_BILINEAR ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
        d.mip = (uint8_t)(FXL_HAVE_MIPMAP ? d.mip : FXL_MIP_NONE);
        TEST_ASSERT_EQUAL_INT(SCENE_OK, pscene_build(pscene_name(i), 320, 240, 0, &s));
        TEST_ASSERT_EQUAL_INT(0, frame_alloc(&a, 320, 240, FXL_PIXFMT_RGB565, FXL_HAVE_DEPTH));
        TEST_ASSERT_EQUAL_INT(0, frame_alloc(&b, 320, 240, FXL_PIXFMT_RGB565, FXL_HAVE_DEPTH));
        scene_clear_flat(&a.target, 0);
        scene_clear_flat(&b.target, 0);
        missing = pscene_missing_feature(&s, &d, FXL_PIXFMT_RGB565, FXL_HAVE_DEPTH);
        if (missing != NULL) { /* p_lit without FXL_HAVE_GENERIC: both ways refused */
            snprintf(msg, sizeof(msg), "%s needs %s", pscene_name(i), missing);
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_UNSUPPORTED, pscene_draw(&s, &d, &a.target, &st),
                                          msg);
            TEST_ASSERT_EQUAL_INT(FXL_OK, pscene_collect(&s, &d, draws, &tris, &n));
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_UNSUPPORTED, draw_collected(tris, n, &b.target),
                                          msg);
            refused++;
            free(tris);
            frame_free(&a);
            frame_free(&b);
            pscene_free(&s);
            continue;
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, pscene_draw(&s, &d, &a.target, &st));
        TEST_ASSERT_EQUAL_INT(FXL_OK, pscene_collect(&s, &d, draws, &tris, &n));
        TEST_ASSERT_EQUAL_INT(FXL_OK, draw_collected(tris, n, &b.target));
        snprintf(msg, sizeof(msg), "%s: %lu pixels drawn", pscene_name(i),
                 (unsigned long)st.pixels);
        /* Every pipeline scene covers thousands of pixels (the table of
         * `make run`: 11868 for p_cube, the fewest). */
        TEST_ASSERT_TRUE_MESSAGE(st.pixels > 10000u, msg);
        {
            uint32_t k;
            for (k = 0; k < 320u * 240u && a.pixels[k] == b.pixels[k]; k++) {
            }
            snprintf(msg, sizeof(msg), "%s: collected triangles differ at x %lu, y %lu",
                     pscene_name(i), (unsigned long)(k % 320u), (unsigned long)(k / 320u));
            TEST_ASSERT_TRUE_MESSAGE(k == 320u * 240u, msg);
        }
        free(tris);
        frame_free(&a);
        frame_free(&b);
        pscene_free(&s);
    }
    snprintf(msg, sizeof(msg), "%lu of %lu pipeline scenes compared, %lu need features this "
             "build lacks", (unsigned long)(pscene_count() - refused),
             (unsigned long)pscene_count(), (unsigned long)refused);
    TEST_MESSAGE(msg);
}

static void test_pscene_build_errors(void)
{
    pscene_t s;
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_NAME, pscene_build("nope", 320, 240, 0, &s));
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_NAME, pscene_build(NULL, 320, 240, 0, &s));
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_SIZE, pscene_build("p_cube", 0, 240, 0, &s));
    TEST_ASSERT_EQUAL_INT(SCENE_ERR_SIZE, pscene_build("p_cube", 320, 4097, 0, &s));
    TEST_ASSERT_EQUAL_INT(0, s.parts);
    TEST_ASSERT_TRUE(anyscene_exists("p_lit"));
    TEST_ASSERT_TRUE(anyscene_exists("floor"));
    TEST_ASSERT_FALSE(anyscene_exists("p_nope"));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_scene_triangle_counts);
    RUN_TEST(test_scene_every_inv_w_positive);
    RUN_TEST(test_scene_tunnel_near_clip_reaches_scale_one);
    RUN_TEST(test_scene_floor_covers_lower_half_not_top);
    RUN_TEST(test_scene_cube_shows_three_faces_half_screen_high);
    RUN_TEST(test_scene_fan_closed_and_on_screen);
    RUN_TEST(test_scene_build_errors);
    RUN_TEST(test_scene_builds_at_other_sizes);
    RUN_TEST(test_crc32_check_value);
    RUN_TEST(test_crc_target_hashes_clip_rows_only);
    RUN_TEST(test_png_round_trip_expands_565_exactly);
    RUN_TEST(test_png_errors_are_reported_without_partial_files);
    RUN_TEST(test_png_write_to_a_fifo_keeps_the_fifo);
    RUN_TEST(test_texture_checker_mips_are_box_averages);
    RUN_TEST(test_texture_crate_marks_corners);
    RUN_TEST(test_texture_grid_lines_every_8_texels);
    RUN_TEST(test_texture_checker_hc_mips_average_in_linear_light);
    RUN_TEST(test_texture_cubemap_tiles_framed_and_coloured);
    RUN_TEST(test_font_covers_labels);
    RUN_TEST(test_pscene_collected_triangles_draw_the_same_image);
    RUN_TEST(test_pscene_build_errors);
    return UNITY_END();
}

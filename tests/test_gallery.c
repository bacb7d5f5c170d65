/* test_gallery.c - golden CRC-32s of the simulator gallery, and the checks
 * behind its pictures.
 *
 * Every gallery image (scene.h lists them: the double-precision scenes x
 * {subdiv16, affine} x {point, bilinear}; the floor_mips comparison; the
 * pipeline scenes x {point, trilinear}; p_cube on the emulated ST7789) is
 * rendered and its pixel CRC compared with tests/golden/gallery_crc.txt.
 * Fixed point makes the output deterministic, so the comparison is exact. On
 * a mismatch the test names the image, prints expected and actual CRC and
 * writes the PNG to the test output directory for a human to look at.
 *
 * A build that leaves features out (fixel/config.h) checks every image it
 * can draw against the same goldens, bit for bit; the others must be
 * refused with FXL_ERR_UNSUPPORTED (scene.h: gallery_missing_feature).
 *
 * A missing golden file is a failure, never a silent pass. Regenerate it
 * (only after checking the new images by eye) with
 *     fixel-sim --gallery-crc > tests/golden/gallery_crc.txt
 */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "crc32.h"
#include "png_io.h"
#include "scene.h"
#include "test_features.h"
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define GOLDEN_LEAF "golden/gallery_crc.txt"
#define MAX_GOLDEN 256

typedef struct golden {
    char id[64], persp[32], filter[32];
    uint32_t crc;
    int used;
} golden_t;

static golden_t golden[MAX_GOLDEN];
static size_t golden_n;
static char golden_path[512];
static char msg[4096];

static const char *output_dir(void)
{
    const char *dir = getenv("FXL_TEST_OUTPUT_DIR");
#ifdef FXL_TEST_OUTPUT_DIR
    if (dir == NULL || dir[0] == '\0') {
        dir = FXL_TEST_OUTPUT_DIR;
    }
#endif
    return (dir == NULL || dir[0] == '\0') ? "." : dir;
}

/* Loads the golden list; returns -1 (with msg set) if it is missing or
 * malformed. */
static int load_golden(void)
{
    FILE *f;
    char line[512];
    int lineno = 0;
#ifdef FXL_TEST_SOURCE_DIR
    snprintf(golden_path, sizeof(golden_path), "%s/%s", FXL_TEST_SOURCE_DIR, GOLDEN_LEAF);
#else
    snprintf(golden_path, sizeof(golden_path), "%s", GOLDEN_LEAF); /* cwd is tests/ */
#endif
    golden_n = 0;
    f = fopen(golden_path, "r");
    if (f == NULL) {
        snprintf(msg, sizeof(msg),
                 "golden file %s is missing; after checking the images, create it with "
                 "`fixel-sim --gallery-crc > tests/golden/gallery_crc.txt`",
                 golden_path);
        return -1;
    }
    while (fgets(line, sizeof(line), f) != NULL) {
        golden_t g;
        unsigned long crc;
        char *p = line;
        lineno++;
        while (*p == ' ' || *p == '\t') {
            p++;
        }
        if (*p == '#' || *p == '\n' || *p == '\r' || *p == '\0') {
            continue;
        }
        memset(&g, 0, sizeof(g));
        if (sscanf(p, "%63s %31s %31s %lx", g.id, g.persp, g.filter, &crc) != 4 ||
            golden_n >= MAX_GOLDEN) {
            snprintf(msg, sizeof(msg), "%s:%d: malformed line (want: image persp filter 0xCRC)",
                     golden_path, lineno);
            fclose(f);
            return -1;
        }
        g.crc = (uint32_t)crc;
        golden[golden_n++] = g;
    }
    fclose(f);
    return 0;
}

static golden_t *find_golden(const gallery_entry_t *e)
{
    size_t i;
    for (i = 0; i < golden_n; i++) {
        if (strcmp(golden[i].id, e->id) == 0 && strcmp(golden[i].persp, e->persp_name) == 0
            && strcmp(golden[i].filter, e->filter_name) == 0) {
            return &golden[i];
        }
    }
    return NULL;
}

static void test_gallery_golden_file_lists_every_image_once(void)
{
    size_t i;
    if (load_golden() != 0) {
        TEST_FAIL_MESSAGE(msg);
    }
    for (i = 0; i < gallery_count(); i++) {
        gallery_entry_t e;
        golden_t *g;
        TEST_ASSERT_EQUAL_INT(0, gallery_entry(i, &e));
        g = find_golden(&e);
        snprintf(msg, sizeof(msg), "%s has no line for %s %s %s", golden_path, e.id,
                 e.persp_name, e.filter_name);
        TEST_ASSERT_TRUE_MESSAGE(g != NULL, msg);
        g->used++;
    }
    for (i = 0; i < golden_n; i++) {
        snprintf(msg, sizeof(msg), "%s: line %.63s %.31s %.31s is %s", golden_path, golden[i].id,
                 golden[i].persp, golden[i].filter,
                 golden[i].used ? "duplicated" : "not a gallery image (stale?)");
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, golden[i].used, msg);
    }
}

static void test_gallery_crcs_match_golden(void)
{
    size_t i, mismatches = 0, refused = 0;
    TEST_NEEDS_DEFAULT_GRID();
    if (load_golden() != 0) {
        TEST_FAIL_MESSAGE(msg);
    }
    for (i = 0; i < gallery_count(); i++) {
        gallery_entry_t e;
        frame_t f;
        fxl_status_t st;
        golden_t *g;
        uint32_t crc;
        const char *missing;
        TEST_ASSERT_EQUAL_INT(0, gallery_entry(i, &e));
        missing = gallery_missing_feature(&e);
        st = gallery_render(&e, &f, NULL, NULL);
        if (missing != NULL) { /* never in the default configuration */
            snprintf(msg, sizeof(msg), "gallery %s %s %s needs %s: status %s", e.id,
                     e.persp_name, e.filter_name, missing, fxl_status_name(st));
            frame_free(&f);
            TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_UNSUPPORTED, st, msg);
            refused++;
            continue;
        }
        snprintf(msg, sizeof(msg), "gallery %s %s %s: render failed: %s", e.id, e.persp_name,
                 e.filter_name, fxl_status_name(st));
        if (st != FXL_OK) {
            frame_free(&f);
            TEST_FAIL_MESSAGE(msg);
        }
        crc = fxl_host_crc_target(&f.target);
        g = find_golden(&e);
        if (g == NULL || g->crc != crc) {
            char path[1200], err[256], name[256];
            gallery_file_name(&e, name, sizeof(name));
            snprintf(path, sizeof(path), "%s/gallery_%s", output_dir(), name);
            if (pngio_write_target(path, &f.target, err, sizeof(err)) != 0) {
                snprintf(path, sizeof(path), "(PNG not written: %s)", err);
            }
            if (g == NULL) {
                snprintf(msg, sizeof(msg), "gallery %s %s %s: no golden CRC, actual 0x%08lX; image: %s",
                         e.id, e.persp_name, e.filter_name, (unsigned long)crc, path);
            } else {
                snprintf(msg, sizeof(msg),
                         "gallery %s %s %s: CRC expected 0x%08lX, actual 0x%08lX; image: %s",
                         e.id, e.persp_name, e.filter_name, (unsigned long)g->crc,
                         (unsigned long)crc, path);
            }
            TEST_MESSAGE(msg);
            mismatches++;
        }
        frame_free(&f);
    }
    snprintf(msg, sizeof(msg), "%lu of %lu gallery images checked, %lu need features this build "
             "lacks", (unsigned long)(gallery_count() - refused), (unsigned long)gallery_count(),
             (unsigned long)refused);
    TEST_MESSAGE(msg);
    snprintf(msg, sizeof(msg), "%lu of %lu gallery images differ from %s (listed above)",
             (unsigned long)mismatches, (unsigned long)(gallery_count() - refused), golden_path);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(0, (uint32_t)mismatches, msg);
}

static void test_gallery_render_is_repeatable(void)
{
    /* No hidden state: the same image rendered twice has the same CRC. */
    gallery_entry_t e;
    frame_t f;
    uint32_t a, b;
    /* floor subdiv16 bilinear (point without FXL_HAVE_BILINEAR) */
    TEST_ASSERT_EQUAL_INT(0, gallery_entry(FXL_HAVE_BILINEAR ? 1 : 0, &e));
    TEST_ASSERT_EQUAL_INT(FXL_OK, gallery_render(&e, &f, NULL, NULL));
    a = fxl_host_crc_target(&f.target);
    frame_free(&f);
    TEST_ASSERT_EQUAL_INT(FXL_OK, gallery_render(&e, &f, NULL, NULL));
    b = fxl_host_crc_target(&f.target);
    frame_free(&f);
    TEST_ASSERT_EQUAL_HEX32(a, b);
}

static uint32_t pixels_without_depth(const char *scene)
{
    scene_t s;
    host_texture_t tex;
    frame_t f;
    fxl_draw_t d;
    fxl_stats_t st;
    memset(&st, 0, sizeof(st));
    TEST_ASSERT_EQUAL_INT(SCENE_OK, scene_build(scene, 320, 240, &s));
    TEST_ASSERT_EQUAL_INT(0, texture_make(&tex, s.texture));
    TEST_ASSERT_EQUAL_INT(0, frame_alloc(&f, 320, 240, drawable_rgb565(), 0));
    fxl_draw_defaults(&d);
    d.mip = FXL_MIP_NONE;
    d.depth = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, scene_render(&s, &tex.tex, &d, &f.target, &st));
    frame_free(&f);
    texture_free(&tex);
    scene_free(&s);
    return st.pixels;
}

static void test_gallery_floor_and_quad_pixel_counts(void)
{
    /* Without depth test a pixel drawn twice counts twice, so these exact
     * counts also check the shared diagonal of each quad.
     * floor: the far edge is horizontal at y = 122.40 (snapped 122.375), the
     * near edge at 239.93 (snapped 239.9375), sides far outside the screen:
     * rows 122..239 are covered, 118 x 320 = 37760 pixels.
     * quad_near covers the whole 320 x 240 screen (scene.h): 76800. */
    TEST_ASSERT_EQUAL_UINT32(37760, pixels_without_depth("floor"));
    TEST_ASSERT_EQUAL_UINT32(37760, pixels_without_depth("floor_tess"));
    TEST_ASSERT_EQUAL_UINT32(76800, pixels_without_depth("quad_near"));
}

static void test_gallery_panel_image_equals_direct_render(void)
{
    /* Issue 6: what the emulated panel shows after the real driver, band
     * renderer (24-row bands, DMA completing late) and wire decoding must be
     * bit-identical to one full-frame render of the same triangles; for
     * every module preset and rotation (offsets, MADCTL, odd 135-px width),
     * for a pipeline scene and a double-precision one. */
    static const char *const panels[] = {"st7789", "st7789-240x240", "st7789-135x240", "ili9341"};
    static const char *const scenes[] = {"p_cube", "floor"};
    size_t p, r, k, refused = 0;
    for (k = 0; k < 2; k++) {
        for (p = 0; p < 4; p++) {
            for (r = 0; r < 4; r++) {
                frame_t img;
                panel_check_t c;
                fxl_draw_t d;
                fxl_status_t st;
                const char *missing;
                fxl_draw_defaults(&d);
                /* What the build has: point without bilinear, level 0 without
                 * mip selection. */
                d.filter = (uint8_t)(k == 0 && FXL_HAVE_BILINEAR ? FXL_FILTER_BILINEAR
                                                                 : FXL_FILTER_POINT);
                d.mip = (uint8_t)(FXL_HAVE_MIPMAP ? d.mip : FXL_MIP_NONE);
                missing = panel_scene_missing_feature(scenes[k], &d);
                st = panel_scene_render(panels[p], (int)r, 24, scenes[k], &d, &img, &c);
                if (missing != NULL) {
                    snprintf(msg, sizeof(msg), "%s on %s rotation %lu needs %s: status %s",
                             scenes[k], panels[p], (unsigned long)r, missing,
                             fxl_status_name(st));
                    frame_free(&img);
                    TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_UNSUPPORTED, st, msg);
                    refused++;
                    continue;
                }
                snprintf(msg, sizeof(msg),
                         "%s on %s rotation %lu: status %s, %ld pixels differ (first at "
                         "index %ld), protocol errors %d",
                         scenes[k], panels[p], (unsigned long)r, fxl_status_name(st),
                         c.diff_pixels, c.first_diff, c.res.protocol_errors);
                TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, st, msg);
                TEST_ASSERT_EQUAL_INT_MESSAGE(0, c.res.protocol_errors, msg);
                TEST_ASSERT_TRUE_MESSAGE(c.diff_pixels == 0, msg);
                TEST_ASSERT_EQUAL_HEX32(c.direct_crc, c.panel_crc);
                /* Something was drawn: the cube and floor cover thousands of
                 * pixels at every one of these sizes. */
                TEST_ASSERT_GREATER_THAN(1000, (int)c.res.stats.pixels);
                frame_free(&img);
            }
        }
    }
    if (refused == 2 * 4 * 4) {
        TEST_IGNORE_MESSAGE("all 32 panel renders need features this build lacks (refused "
                            "with FXL_ERR_UNSUPPORTED), none compared");
    }
}

static void render_320(const char *scene, int texture, uint8_t filter, uint8_t mip, frame_t *f)
{
    anyscene_t a;
    fxl_draw_t d;
    fxl_draw_defaults(&d);
    d.filter = filter;
    d.mip = mip;
    d.lod = FXL_LOD_SEGMENT;
    TEST_ASSERT_EQUAL_INT(SCENE_OK, anyscene_build(&a, scene, 320, 240, texture, 0));
    /* Without FXL_HAVE_DEPTH, no depth buffer: these scenes draw the same
     * pixels without (scene.h), any other would be refused here. */
    TEST_ASSERT_EQUAL_INT(0, frame_alloc(f, 320, 240, drawable_rgb565(),
                                         FXL_HAVE_DEPTH || anyscene_needs_depth(scene)));
    TEST_ASSERT_EQUAL_INT(FXL_OK, anyscene_render(&a, &d, &f->target, NULL));
    frame_to_native(f);
    anyscene_free(&a);
}

static void test_gallery_pipeline_cube_matches_double_cube(void)
{
    /* p_cube is the cube scene through the fixed-point front end (same
     * rotation order, face layout and texture coordinates). The only
     * differences are the q16 inputs (rotation entries within 2^-17,
     * positions) that move vertices by ~1e-3 px, which flips the odd pixel
     * along an edge or a texel boundary: measured 149 of 11864 pixels with
     * point sampling. A wrong rotation sign, order, winding or uv layout
     * changes thousands. Bound: twice the measurement. */
    frame_t a, b;
    int i, n = 0, first = -1;
    render_320("cube", -1, FXL_FILTER_POINT, FXL_MIP_NONE, &a);
    render_320("p_cube", -1, FXL_FILTER_POINT, FXL_MIP_NONE, &b);
    for (i = 0; i < 320 * 240; i++) {
        if (a.pixels[i] != b.pixels[i]) {
            first = first < 0 ? i : first;
            n++;
        }
    }
    snprintf(msg, sizeof(msg), "p_cube differs from cube in %d pixels (first at x %d, y %d)", n,
             first % 320, first / 320);
    TEST_ASSERT_TRUE_MESSAGE(n <= 300, msg);
    frame_free(&a);
    frame_free(&b);
}

static void test_gallery_mips_trilinear_greys_the_horizon_point_aliases(void)
{
    /* floor_mips derivation: 256-texel checker, 16-texel cells, one texture
     * per 2 world units; at d rows below the horizon (d = y + 0.5 - 120) one
     * pixel spans 15360 / d^2 texels along v, so rows 122..133 (d <= 13.5)
     * have LOD >= log2(15360 / 13.5^2) = 6.4. Every level >= 5 averages whole
     * black-and-white cell pairs: uniform grey. So trilinear must draw those
     * 12 x 320 pixels all alike, while point sampling without mips shows
     * both black and white there (the shimmer; measured about half each,
     * green channel standard deviation 31.5 of 63). */
    frame_t pt, tri;
    int x, y, black = 0, white = 0, other = 0;
    uint16_t ref;
    TEST_NEEDS(FXL_HAVE_MIPMAP && FXL_HAVE_BILINEAR);
    render_320("floor", TEXTURE_CHECKER_HC, FXL_FILTER_POINT, FXL_MIP_NONE, &pt);
    render_320("floor", TEXTURE_CHECKER_HC, FXL_FILTER_BILINEAR, FXL_MIP_LINEAR, &tri);
    ref = tri.pixels[122 * 320];
    for (y = 122; y < 134; y++) {
        for (x = 0; x < 320; x++) {
            uint16_t c = pt.pixels[y * 320 + x];
            black += c == 0x0000u;
            white += c == 0xFFFFu;
            other += tri.pixels[y * 320 + x] != ref;
        }
    }
    snprintf(msg, sizeof(msg), "trilinear horizon rows: %d pixels differ from 0x%04X", other,
             (unsigned)ref);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, other, msg);
    TEST_ASSERT_TRUE_MESSAGE(ref != 0x0000u && ref != 0xFFFFu, "horizon grey is not grey");
    snprintf(msg, sizeof(msg), "point horizon rows: %d black, %d white", black, white);
    TEST_ASSERT_TRUE_MESSAGE(black > 100 && white > 100, msg);
    frame_free(&pt);
    frame_free(&tri);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_gallery_golden_file_lists_every_image_once);
    RUN_TEST(test_gallery_crcs_match_golden);
    RUN_TEST(test_gallery_render_is_repeatable);
    RUN_TEST(test_gallery_floor_and_quad_pixel_counts);
    RUN_TEST(test_gallery_panel_image_equals_direct_render);
    RUN_TEST(test_gallery_pipeline_cube_matches_double_cube);
    RUN_TEST(test_gallery_mips_trilinear_greys_the_horizon_point_aliases);
    return UNITY_END();
}

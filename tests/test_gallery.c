/* test_gallery.c - golden CRC-32s of the simulator gallery.
 *
 * Every gallery image (scene.h: every scene x {subdiv16, affine} x {point,
 * bilinear}, 320x240 native RGB565, depth on, mip none) is rendered and its
 * pixel CRC compared with tests/golden/gallery_crc.txt. Fixed point makes
 * the output deterministic, so the comparison is exact. On a mismatch the
 * test names the image, prints expected and actual CRC and writes the PNG to
 * the test output directory for a human to look at.
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
#include "unity.h"

void setUp(void) {}
void tearDown(void) {}

#define GOLDEN_LEAF "golden/gallery_crc.txt"
#define MAX_GOLDEN 256

typedef struct golden {
    char scene[64], persp[32], filter[32];
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
        if (sscanf(p, "%63s %31s %31s %lx", g.scene, g.persp, g.filter, &crc) != 4 ||
            golden_n >= MAX_GOLDEN) {
            snprintf(msg, sizeof(msg), "%s:%d: malformed line (want: scene persp filter 0xCRC)",
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
        if (strcmp(golden[i].scene, e->scene) == 0 && strcmp(golden[i].persp, e->persp_name) == 0
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
        snprintf(msg, sizeof(msg), "%s has no line for %s %s %s", golden_path, e.scene,
                 e.persp_name, e.filter_name);
        TEST_ASSERT_TRUE_MESSAGE(g != NULL, msg);
        g->used++;
    }
    for (i = 0; i < golden_n; i++) {
        snprintf(msg, sizeof(msg), "%s: line %.63s %.31s %.31s is %s", golden_path, golden[i].scene,
                 golden[i].persp, golden[i].filter,
                 golden[i].used ? "duplicated" : "not a gallery image (stale?)");
        TEST_ASSERT_EQUAL_INT_MESSAGE(1, golden[i].used, msg);
    }
}

static void test_gallery_crcs_match_golden(void)
{
    size_t i, mismatches = 0;
    if (load_golden() != 0) {
        TEST_FAIL_MESSAGE(msg);
    }
    for (i = 0; i < gallery_count(); i++) {
        gallery_entry_t e;
        frame_t f;
        fxl_status_t st;
        golden_t *g;
        uint32_t crc;
        TEST_ASSERT_EQUAL_INT(0, gallery_entry(i, &e));
        st = gallery_render(&e, &f, NULL);
        snprintf(msg, sizeof(msg), "gallery %s %s %s: render failed: %s", e.scene, e.persp_name,
                 e.filter_name, fxl_status_name(st));
        if (st != FXL_OK) {
            frame_free(&f);
            TEST_FAIL_MESSAGE(msg);
        }
        crc = fxl_host_crc_target(&f.target);
        g = find_golden(&e);
        if (g == NULL || g->crc != crc) {
            char path[1200], err[256];
            snprintf(path, sizeof(path), "%s/gallery_%s_%s_%s.png", output_dir(), e.scene,
                     e.persp_name, e.filter_name);
            if (pngio_write_target(path, &f.target, err, sizeof(err)) != 0) {
                snprintf(path, sizeof(path), "(PNG not written: %s)", err);
            }
            if (g == NULL) {
                snprintf(msg, sizeof(msg), "gallery %s %s %s: no golden CRC, actual 0x%08lX; image: %s",
                         e.scene, e.persp_name, e.filter_name, (unsigned long)crc, path);
            } else {
                snprintf(msg, sizeof(msg),
                         "gallery %s %s %s: CRC expected 0x%08lX, actual 0x%08lX; image: %s",
                         e.scene, e.persp_name, e.filter_name, (unsigned long)g->crc,
                         (unsigned long)crc, path);
            }
            TEST_MESSAGE(msg);
            mismatches++;
        }
        frame_free(&f);
    }
    snprintf(msg, sizeof(msg), "%lu of %lu gallery images differ from %s (listed above)",
             (unsigned long)mismatches, (unsigned long)gallery_count(), golden_path);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE(0, (uint32_t)mismatches, msg);
}

static void test_gallery_render_is_repeatable(void)
{
    /* No hidden state: the same image rendered twice has the same CRC. */
    gallery_entry_t e;
    frame_t f;
    uint32_t a, b;
    TEST_ASSERT_EQUAL_INT(0, gallery_entry(1, &e)); /* floor subdiv16 bilinear */
    TEST_ASSERT_EQUAL_INT(FXL_OK, gallery_render(&e, &f, NULL));
    a = fxl_host_crc_target(&f.target);
    frame_free(&f);
    TEST_ASSERT_EQUAL_INT(FXL_OK, gallery_render(&e, &f, NULL));
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
    TEST_ASSERT_EQUAL_INT(0, frame_alloc(&f, 320, 240, FXL_PIXFMT_RGB565, 0));
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

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_gallery_golden_file_lists_every_image_once);
    RUN_TEST(test_gallery_crcs_match_golden);
    RUN_TEST(test_gallery_render_is_repeatable);
    RUN_TEST(test_gallery_floor_and_quad_pixel_counts);
    return UNITY_END();
}

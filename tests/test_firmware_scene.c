/* test_firmware_scene.c - the firmware example's scenes and frame runner
 * (examples/common), compiled for the host from the very sources the
 * Cortex-M4 firmware uses. The CRCs of the bytes each frame sends to the
 * panel must equal examples/expected_crc.txt, which
 * host_sim/scripts/firmware.sh also compares the qemu run against: so host
 * and firmware agree through one committed file. The banded frame must
 * also be the image a full-frame fxl_mesh_draw render gives.
 *
 * In a build that leaves features out (fixel/config.h) a frame whose draw
 * state needs one must be refused with FXL_ERR_UNSUPPORTED; the others are
 * checked in full, against the same expected CRCs.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "test_features.h"
#include "crc32.h"

/* The shared sources, as one unit: the test build globs only tests/. */
#include "../examples/common/fw_scenes.c"
#include "../examples/common/fw_app.c"

#include "scene.h"

#define FRAME_BYTES (FW_WIDTH * FW_HEIGHT * 2)

static fw_app_t app;
static uint8_t captured[FRAME_BYTES];
static uint16_t full[FW_WIDTH * FW_HEIGHT], full_depth[FW_WIDTH * FW_HEIGHT];
static char msg[256];

typedef struct expected {
    char name[32];
    unsigned frame;
    uint32_t crc;
} expected_t;

#define MAX_EXPECTED 64
static expected_t expected[MAX_EXPECTED];
static int expected_count;

void setUp(void)
{
}

void tearDown(void)
{
}

static FILE *open_expected(void)
{
    static const char *const paths[] = {
#ifdef FXL_TEST_SOURCE_DIR
        FXL_TEST_SOURCE_DIR "/../examples/expected_crc.txt",
#endif
        "../examples/expected_crc.txt", "examples/expected_crc.txt"};
    size_t i;
    for (i = 0; i < sizeof(paths) / sizeof(paths[0]); i++) {
        FILE *f = fopen(paths[i], "r");
        if (f) return f;
    }
    return NULL;
}

/* Lines "<scene> <frame> 0x<crc>"; '#' starts a comment line. */
static void load_expected(void)
{
    char line[256];
    FILE *f = open_expected();
    expected_count = 0;
    if (!f) TEST_FAIL_MESSAGE("examples/expected_crc.txt not found");
    while (fgets(line, sizeof line, f)) {
        expected_t e;
        char *end;
        if (line[0] == '#' || line[0] == '\n') continue;
        if (sscanf(line, "%31s %u", e.name, &e.frame) != 2 || !strstr(line, "0x")) {
            snprintf(msg, sizeof msg, "malformed line in expected_crc.txt: %.120s", line);
            fclose(f);
            TEST_FAIL_MESSAGE(msg);
        }
        e.crc = (uint32_t)strtoul(strstr(line, "0x"), &end, 16);
        if (expected_count == MAX_EXPECTED) break;
        expected[expected_count++] = e;
    }
    fclose(f);
}

static void init_app(void)
{
    TEST_ASSERT_EQUAL_INT(FXL_OK, fw_app_init(&app));
    app.spi.capture = captured;
    app.spi.capture_cap = sizeof captured;
}

/* The feature that frame i's draw needs and this build left out (scene.h:
 * left_out_feature; the bands are in the wire's format, with a depth band where
 * the build has depth), or NULL. After init_app. */
static const char *frame_missing(uint32_t i)
{
    fw_view_t v;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fw_scene_setup(&app.scenes, fw_frames[i].scene, fw_frames[i].frame,
                                                 FW_WIDTH, FW_HEIGHT, &v));
    return left_out_feature(&v.draw, v.draw.texture, fxl_port_wire_format(), FXL_HAVE_DEPTH);
}

/* A frame that frame_missing says this build cannot draw: asserts that it
 * is refused and returns 1 (skip the rest); 0 for a frame to check. */
static int refused_frame(uint32_t i, fxl_status_t st)
{
    const char *missing = frame_missing(i);
    if (missing == NULL) {
        return 0; /* every frame in the default configuration */
    }
    snprintf(msg, sizeof msg, "%s %u needs %s: status %d", fw_scene_name(fw_frames[i].scene),
             (unsigned)fw_frames[i].frame, missing, (int)st);
    TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_UNSUPPORTED, st, msg);
    return 1;
}

static void frames_message(uint32_t refused)
{
    snprintf(msg, sizeof msg, "%u of %u frames checked, %u need features this build lacks",
             (unsigned)(fw_frame_count - refused), (unsigned)fw_frame_count, (unsigned)refused);
    TEST_MESSAGE(msg);
}

static void test_expected_file_lists_init_and_every_frame_in_order(void)
{
    uint32_t i;
    load_expected();
    TEST_ASSERT_EQUAL_INT_MESSAGE((int)fw_frame_count + 1, expected_count,
                                  "expected_crc.txt: one line for init plus one per fw_frames entry");
    TEST_ASSERT_EQUAL_STRING("init", expected[0].name);
    for (i = 0; i < fw_frame_count; i++) {
        snprintf(msg, sizeof msg, "line %u: '%s %u', the firmware renders '%s %u'", (unsigned)i + 1,
                 expected[i + 1].name, expected[i + 1].frame, fw_scene_name(fw_frames[i].scene),
                 (unsigned)fw_frames[i].frame);
        TEST_ASSERT_TRUE_MESSAGE(strcmp(fw_scene_name(fw_frames[i].scene), expected[i + 1].name) == 0, msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE(fw_frames[i].frame, expected[i + 1].frame, msg);
    }
}

/* The host computes the CRCs the firmware prints on qemu. */
static void test_wire_crc_of_every_frame_equals_expected_file(void)
{
    uint32_t i, refused = 0;
    TEST_NEEDS_DEFAULT_GRID();
    load_expected();
    init_app();
    TEST_ASSERT_GREATER_THAN(fw_frame_count, expected_count);
    snprintf(msg, sizeof msg, "init: crc 0x%08x, expected 0x%08x", (unsigned)app.init_crc,
             (unsigned)expected[0].crc);
    TEST_ASSERT_EQUAL_HEX32_MESSAGE(expected[0].crc, app.init_crc, msg);
    for (i = 0; i < fw_frame_count; i++) {
        fw_result_t r;
        fxl_status_t st = fw_app_frame(&app, fw_frames[i].scene, fw_frames[i].frame, &r);
        printf("%s %u 0x%08x  (%u screen triangles, %u pixels, pixel crc 0x%08x)\n",
               fw_scene_name(fw_frames[i].scene), (unsigned)fw_frames[i].frame, (unsigned)r.wire_crc,
               (unsigned)r.screen_tris, (unsigned)r.stats.pixels, (unsigned)r.pixel_crc);
        if (refused_frame(i, st)) {
            refused++;
            continue;
        }
        snprintf(msg, sizeof msg, "%s %u: status %d", fw_scene_name(fw_frames[i].scene),
                 (unsigned)fw_frames[i].frame, (int)st);
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, st, msg);
        snprintf(msg, sizeof msg, "%s %u: wire crc 0x%08x, expected_crc.txt says 0x%08x",
                 fw_scene_name(fw_frames[i].scene), (unsigned)fw_frames[i].frame,
                 (unsigned)r.wire_crc, (unsigned)expected[i + 1].crc);
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(expected[i + 1].crc, r.wire_crc, msg);
    }
    frames_message(refused);
}

/* Per frame on the wire: CASET (1 + 4 bytes), RASET (1 + 4), RAMWR (1) for
 * the one full-frame window, then 320 * 240 * 2 pixel bytes in one transfer
 * per band (240 / 24 = 10), and the bin memory sufficed (no fallback). */
static void test_each_frame_sends_one_window_and_ten_band_transfers(void)
{
    uint32_t i, refused = 0;
    init_app();
    for (i = 0; i < fw_frame_count; i++) {
        fw_result_t r;
        fxl_status_t st = fw_app_frame(&app, fw_frames[i].scene, fw_frames[i].frame, &r);
        if (refused_frame(i, st)) {
            refused++;
            continue;
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, st);
        snprintf(msg, sizeof msg, "%s %u: %u wire bytes, %u pixel bytes, %u transfers",
                 fw_scene_name(fw_frames[i].scene), (unsigned)fw_frames[i].frame,
                 (unsigned)r.wire_bytes, (unsigned)r.pixel_bytes, (unsigned)r.transfers);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(11u + FRAME_BYTES, r.wire_bytes, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(FRAME_BYTES, r.pixel_bytes, msg);
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(FW_BANDS, r.transfers, msg);
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, r.bins_overflowed, msg);
        TEST_ASSERT_TRUE_MESSAGE(r.screen_tris <= FW_TRI_CAP, msg);
    }
    frames_message(refused);
}

/* The bytes on the wire are the full-frame image: the same view drawn with
 * fxl_mesh_draw into one 320 x 240 byte-swapped target with a full depth
 * buffer. Checked pixel by pixel and by CRC (the mock's own CRC against the
 * host library's). */
static void test_banded_frame_equals_full_frame_mesh_draw(void)
{
    uint32_t i, refused = 0;
    init_app();
    for (i = 0; i < fw_frame_count; i++) {
        fw_result_t r;
        fw_view_t v;
        fxl_target_t t;
        fxl_stats_t st;
        const char *name = fw_scene_name(fw_frames[i].scene);
        int p;
        fxl_status_t fst;
        memset(captured, 0xA5, sizeof captured);
        fst = fw_app_frame(&app, fw_frames[i].scene, fw_frames[i].frame, &r);
        if (refused_frame(i, fst)) {
            refused++;
            continue;
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, fst);

        memset(&st, 0, sizeof st);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fw_scene_setup(&app.scenes, fw_frames[i].scene, fw_frames[i].frame,
                                                     FW_WIDTH, FW_HEIGHT, &v));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, full, FW_WIDTH, FW_HEIGHT, FW_WIDTH,
                                                      FXL_PIXFMT_RGB565_SWAP));
        if (FXL_HAVE_DEPTH) { /* else no depth band either (fw_app_init) */
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, full_depth));
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear(&t, v.clear_rgb565));
        if (FXL_HAVE_DEPTH) {
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear_depth(&t));
        }
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_mesh_draw(&v.pipe, &t, &v.draw, &v.mesh, &st));
        TEST_ASSERT_GREATER_THAN(0, st.pixels);

        for (p = 0; p < FW_WIDTH * FW_HEIGHT; p++) {
            const uint8_t *f = (const uint8_t *)&full[p];
            if (f[0] != captured[2 * p] || f[1] != captured[2 * p + 1]) {
                snprintf(msg, sizeof msg, "%s %u: pixel (%d, %d) on the wire %02x%02x, full frame %02x%02x",
                         name, (unsigned)fw_frames[i].frame, p % FW_WIDTH, p / FW_WIDTH,
                         captured[2 * p], captured[2 * p + 1], f[0], f[1]);
                TEST_FAIL_MESSAGE(msg);
            }
        }
        snprintf(msg, sizeof msg, "%s %u: pixel crc 0x%08x, crc32 of the full frame 0x%08x", name,
                 (unsigned)fw_frames[i].frame, (unsigned)r.pixel_crc,
                 (unsigned)crc32_update(0, full, sizeof full));
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(crc32_update(0, full, sizeof full), r.pixel_crc, msg);
    }
    frames_message(refused);
}

/* The mock's table CRC is the standard CRC-32 (check value of "123456789"). */
static void test_mock_crc_is_standard_crc32(void)
{
    static const uint8_t check[9] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
    init_app();
    TEST_ASSERT_EQUAL_HEX32(0xCBF43926u, ~spi_mock_crc(&app.spi, 0xFFFFFFFFu, check, 9));
}

/* Rotation moves the cube: its three frames differ from each other, and the
 * sphere's two frames differ (the texgen u follows the object). */
static void test_rotating_frames_differ(void)
{
    uint32_t i, j, crc[16], refused = 0, moved = 0;
    int drawn[16];
    init_app();
    TEST_ASSERT_LESS_OR_EQUAL(16, fw_frame_count);
    for (i = 0; i < fw_frame_count; i++) {
        fw_result_t r;
        fxl_status_t st = fw_app_frame(&app, fw_frames[i].scene, fw_frames[i].frame, &r);
        drawn[i] = !refused_frame(i, st);
        refused += (uint32_t)!drawn[i];
        if (drawn[i]) {
            TEST_ASSERT_EQUAL_INT(FXL_OK, st);
        }
        crc[i] = r.pixel_crc;
    }
    frames_message(refused);
    for (i = 0; i < fw_frame_count; i++)
        for (j = i + 1; j < fw_frame_count; j++) {
            if (!drawn[i] || !drawn[j]) continue;
            moved += fw_frames[i].scene == fw_frames[j].scene;
            snprintf(msg, sizeof msg, "frames %s %u and %s %u have the same image",
                     fw_scene_name(fw_frames[i].scene), (unsigned)fw_frames[i].frame,
                     fw_scene_name(fw_frames[j].scene), (unsigned)fw_frames[j].frame);
            TEST_ASSERT_TRUE_MESSAGE(crc[i] != crc[j], msg);
        }
    if (moved == 0) { /* never in the default configuration */
        TEST_IGNORE_MESSAGE("no scene has two frames this build can draw (the rotating ones need "
                            "features it lacks): the frames drawn differ, rotation not checked");
    }
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_mock_crc_is_standard_crc32);
    RUN_TEST(test_expected_file_lists_init_and_every_frame_in_order);
    RUN_TEST(test_wire_crc_of_every_frame_equals_expected_file);
    RUN_TEST(test_each_frame_sends_one_window_and_ten_band_transfers);
    RUN_TEST(test_banded_frame_equals_full_frame_mesh_draw);
    RUN_TEST(test_rotating_frames_differ);
    return UNITY_END();
}

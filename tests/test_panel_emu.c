/* test_panel_emu.c - the emulated panel: address decoding (window, RAMWR
 * continuation, MADCTL), the glass model (offsets, mirroring, colour order,
 * inversion), protocol checks, the DMA mock and the wire CRC. The image
 * tests drive it through the real drivers, so they also check every preset's
 * rotation and offset table against the module geometry. */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "unity.h"
#include "fixel/port.h"
#include "panel_emu.h"
#include "crc32.h"

static panel_emu_t emu;
static int emu_live;
static fxl_port_hal_t hal;
static fxl_panel_t panel;
static char msg[256];

static void start_emu(const char *name)
{
    TEST_ASSERT_EQUAL_INT(0, panel_emu_init(&emu, panel_emu_module_find(name), 0x1234));
    emu_live = 1;
    emu.panel = &panel;
    panel_emu_hal(&emu, &hal);
}

void setUp(void)
{
    emu_live = 0;
    memset(&panel, 0, sizeof(panel));
}

void tearDown(void)
{
    if (emu_live) panel_emu_free(&emu);
    emu_live = 0;
}

static uint16_t to_wire(uint16_t rgb565)
{
    return fxl_port_wire_format() == FXL_PIXFMT_RGB565_SWAP
               ? (uint16_t)((rgb565 >> 8) | (rgb565 << 8))
               : rgb565;
}

/* A pattern with distinct neighbours in both directions and all bits used. */
static uint16_t pattern(int x, int y)
{
    return (uint16_t)((unsigned)x * 0x9E37u + (unsigned)y * 0x79B9u + 0x1357u);
}

/* Send a w x h frame of pattern() through the driver in transfers of
 * `rows` rows, as the band renderer would (one window, RAMWR continuing). */
static void send_pattern(int rows)
{
    const int w = panel.width, h = panel.height;
    uint16_t *buf = (uint16_t *)malloc((size_t)w * (size_t)rows * 2u * 2u);
    int y0, x, y, k = 0;
    TEST_ASSERT_NOT_NULL(buf);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, w, h));
    for (y0 = 0; y0 < h; y0 += rows, k ^= 1) {
        const int n = h - y0 < rows ? h - y0 : rows;
        uint16_t *b = buf + (size_t)k * (size_t)w * (size_t)rows;
        /* Alternate halves: the previous transfer may still be reading the other. */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_done(&panel, panel.started > 0 ? panel.started - 1 : 0));
        for (y = 0; y < n; y++)
            for (x = 0; x < w; x++) b[(size_t)y * (size_t)w + (size_t)x] = to_wire(pattern(x, y0 + y));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, b, (size_t)w * (size_t)n * 2u));
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&panel));
    free(buf);
}

static void check_view_is_pattern(int rotation)
{
    int w, h, x, y;
    uint16_t *view;
    TEST_ASSERT_EQUAL_INT(0, panel_emu_view(&emu, rotation, NULL, &w, &h));
    TEST_ASSERT_EQUAL_INT(panel.width, w);
    TEST_ASSERT_EQUAL_INT(panel.height, h);
    view = (uint16_t *)malloc((size_t)w * (size_t)h * 2u);
    TEST_ASSERT_NOT_NULL(view);
    TEST_ASSERT_EQUAL_INT(0, panel_emu_view(&emu, rotation, view, NULL, NULL));
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint16_t got = view[(size_t)y * (size_t)w + (size_t)x];
            if (got != pattern(x, y)) {
                snprintf(msg, sizeof(msg), "%s rotation %d: frame pixel (%d, %d) shows 0x%04X, sent 0x%04X",
                         emu.mod.name, rotation, x, y, got, pattern(x, y));
                free(view);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
    free(view);
}

/* ---- every preset and rotation through the real driver -------------------- */

void test_every_preset_and_rotation_shows_the_frame_upright(void)
{
    /* The driver's MADCTL and offset tables against the module geometry in
     * the emulator: every frame pixel must appear exactly where a viewer of
     * the rotated module expects it, with no write outside the glass. */
    static const char *const names[] = { "st7789-240x320", "st7789-240x240", "st7789-135x240",
                                         "ili9341-240x320" };
    size_t i;
    int r;
    for (i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
        for (r = 0; r < 4; r++) {
            start_emu(names[i]);
            emu.dma_delay = 2;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, panel_emu_preset_find(names[i]),
                                                         (unsigned)r));
            send_pattern(24);
            TEST_ASSERT_EQUAL_INT_MESSAGE(0, emu.errors, emu.first_error);
            snprintf(msg, sizeof(msg), "%s rotation %d: pixels written outside the glass", names[i], r);
            TEST_ASSERT_EQUAL_UINT32_MESSAGE(0, (uint32_t)emu.writes_outside_glass, msg);
            TEST_ASSERT_EQUAL_UINT32((uint32_t)(panel.width * panel.height), (uint32_t)emu.pixels_written);
            check_view_is_pattern(r);
            tearDown();
        }
    }
}

void test_wrong_offset_table_is_caught(void)
{
    /* The check above can fail: the 135x240 preset with the rotation-2
     * offset of rotation 0 (52 instead of 53) misplaces the image. */
    fxl_panel_preset_t bad = fxl_st7789_135x240;
    int w, h;
    uint16_t *view;
    bad.offset[2] = bad.offset[0];
    start_emu("st7789-135x240");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &bad, 2));
    send_pattern(24);
    TEST_ASSERT_EQUAL_INT(0, panel_emu_view(&emu, 2, NULL, &w, &h));
    view = (uint16_t *)malloc((size_t)w * (size_t)h * 2u);
    TEST_ASSERT_NOT_NULL(view);
    TEST_ASSERT_EQUAL_INT(0, panel_emu_view(&emu, 2, view, NULL, NULL));
    /* One column off: frame pixel (0, 0) shows what was sent for (1, 0). */
    TEST_ASSERT_EQUAL_HEX16(pattern(1, 0), view[0]);
    TEST_ASSERT_GREATER_THAN(0, (int)emu.writes_outside_glass);
    free(view);
}

/* One pixel (rgb565) sent to (0, 0) of `module` driven with `preset`: what
 * the glass shows there. glass_w x glass_h is the module's glass. */
static uint16_t glass_of_one_pixel(const char *module, const fxl_panel_preset_t *preset, uint16_t rgb565,
                                   uint32_t glass_w, uint32_t glass_h)
{
    uint16_t px = to_wire(rgb565), glass_px;
    uint16_t *glass = (uint16_t *)malloc((size_t)glass_w * glass_h * 2u);
    TEST_ASSERT_NOT_NULL(glass);
    start_emu(module);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, preset, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 1, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, &px, 2));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&panel));
    panel_emu_glass(&emu, glass);
    glass_px = glass[0];
    free(glass);
    return glass_px;
}

void test_missing_bgr_flag_swaps_red_and_blue(void)
{
    fxl_panel_preset_t rgb = fxl_ili9341_240x320;
    rgb.flags = 0;
    TEST_ASSERT_EQUAL_HEX16(0x001Fu, glass_of_one_pixel("ili9341", &rgb, 0xF800u, 240, 320)); /* red sent, blue shown */
}

void test_missing_inversion_on_ips_glass_inverts_colours(void)
{
    fxl_panel_preset_t plain = fxl_st7789_240x240;
    plain.flags = 0;
    TEST_ASSERT_EQUAL_HEX16(0x07FFu, glass_of_one_pixel("st7789-240x240", &plain, 0xF800u, 240, 240)); /* ~0xF800 */
}

/* ---- address decoding ------------------------------------------------------ */

static void raw_cmd(uint8_t c, const uint8_t *p, size_t n)
{
    TEST_ASSERT_EQUAL_INT(FXL_OK, hal.cmd(hal.user, c, p, n));
}

static void raw_pixels(const uint16_t *native, size_t count)
{
    uint8_t bytes[64];
    size_t i;
    TEST_ASSERT_TRUE(count * 2 <= sizeof(bytes));
    for (i = 0; i < count; i++) {
        bytes[2 * i] = (uint8_t)(native[i] >> 8);
        bytes[2 * i + 1] = (uint8_t)(native[i] & 0xFFu);
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, hal.pixels(hal.user, bytes, count * 2));
}

static uint16_t ram_at(int col, int row)
{
    return emu.ram[(size_t)row * (size_t)emu.mod.ram_w + (size_t)col];
}

/* A started, awake emulator without going through the driver. */
static void start_awake(void)
{
    start_emu("st7789");
    emu.panel = NULL;
    hal.delay_ms(hal.user, 200);
    raw_cmd(FXL_DCS_SLPOUT, NULL, 0);
    hal.delay_ms(hal.user, 10);
    {
        const uint8_t colmod = 0x55;
        raw_cmd(FXL_DCS_COLMOD, &colmod, 1);
    }
}

void test_ramwr_continues_across_transfers_and_wraps_at_window_end(void)
{
    /* Window 4x2 at (10, 20): 3 + 5 pixels fill it, 2 more wrap to the start. */
    static const uint8_t caset[4] = { 0, 10, 0, 13 }, raset[4] = { 0, 20, 0, 21 };
    static const uint16_t a[3] = { 1, 2, 3 }, b[5] = { 4, 5, 6, 7, 8 }, c[2] = { 9, 10 };
    start_awake();
    raw_cmd(FXL_DCS_CASET, caset, 4);
    raw_cmd(FXL_DCS_RASET, raset, 4);
    raw_cmd(FXL_DCS_RAMWR, NULL, 0);
    raw_pixels(a, 3);
    raw_pixels(b, 5);
    TEST_ASSERT_EQUAL_HEX16(3, ram_at(12, 20));
    TEST_ASSERT_EQUAL_HEX16(4, ram_at(13, 20));
    TEST_ASSERT_EQUAL_HEX16(5, ram_at(10, 21));
    TEST_ASSERT_EQUAL_HEX16(8, ram_at(13, 21));
    raw_pixels(c, 2);
    TEST_ASSERT_EQUAL_HEX16(9, ram_at(10, 20));
    TEST_ASSERT_EQUAL_HEX16(10, ram_at(11, 20));
    TEST_ASSERT_EQUAL_HEX16(0x1234, ram_at(14, 20)); /* never outside the window */
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, emu.errors, emu.first_error);
}

void test_ramwrc_continues_after_a_command_ramwr_restarts(void)
{
    static const uint8_t caset[4] = { 0, 0, 0, 9 }, raset[4] = { 0, 0, 0, 0 };
    static const uint16_t a[3] = { 1, 2, 3 }, b[2] = { 4, 5 }, c[1] = { 6 };
    start_awake();
    raw_cmd(FXL_DCS_CASET, caset, 4);
    raw_cmd(FXL_DCS_RASET, raset, 4);
    raw_cmd(FXL_DCS_RAMWR, NULL, 0);
    raw_pixels(a, 3);
    raw_cmd(FXL_DCS_NOP, NULL, 0);
    raw_cmd(FXL_DCS_RAMWRC, NULL, 0);
    raw_pixels(b, 2);
    TEST_ASSERT_EQUAL_HEX16(4, ram_at(3, 0));
    TEST_ASSERT_EQUAL_HEX16(5, ram_at(4, 0));
    raw_cmd(FXL_DCS_RAMWR, NULL, 0);
    raw_pixels(c, 1);
    TEST_ASSERT_EQUAL_HEX16(6, ram_at(0, 0));
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, emu.errors, emu.first_error);
}

void test_madctl_maps_logical_addresses_to_memory(void)
{
    int col, row;
    start_awake();
    emu.madctl = 0;
    TEST_ASSERT_EQUAL_INT(0, panel_emu_map(&emu, 5, 7, &col, &row));
    TEST_ASSERT_EQUAL_INT(5, col);
    TEST_ASSERT_EQUAL_INT(7, row);
    emu.madctl = FXL_MADCTL_MV;
    TEST_ASSERT_EQUAL_INT(0, panel_emu_map(&emu, 5, 7, &col, &row));
    TEST_ASSERT_EQUAL_INT(7, col);
    TEST_ASSERT_EQUAL_INT(5, row);
    TEST_ASSERT_EQUAL_INT(0, panel_emu_map(&emu, 319, 239, &col, &row)); /* MV: x spans 320 */
    TEST_ASSERT_EQUAL_INT(-1, panel_emu_map(&emu, 0, 240, &col, &row));
    emu.madctl = FXL_MADCTL_MV | FXL_MADCTL_MX;
    TEST_ASSERT_EQUAL_INT(0, panel_emu_map(&emu, 0, 0, &col, &row));
    TEST_ASSERT_EQUAL_INT(239, col);
    TEST_ASSERT_EQUAL_INT(0, row);
    emu.madctl = FXL_MADCTL_MY;
    TEST_ASSERT_EQUAL_INT(0, panel_emu_map(&emu, 0, 0, &col, &row));
    TEST_ASSERT_EQUAL_INT(0, col);
    TEST_ASSERT_EQUAL_INT(319, row);
    emu.madctl = FXL_MADCTL_MY | FXL_MADCTL_MV;
    TEST_ASSERT_EQUAL_INT(0, panel_emu_map(&emu, 0, 0, &col, &row));
    TEST_ASSERT_EQUAL_INT(0, col);
    TEST_ASSERT_EQUAL_INT(319, row);
}

/* ---- protocol checks (each must fire) ------------------------------------- */

void test_command_too_soon_after_swreset_is_flagged(void)
{
    start_awake();
    raw_cmd(FXL_DCS_SWRESET, NULL, 0);
    hal.delay_ms(hal.user, 4); /* needs 5 */
    raw_cmd(FXL_DCS_NOP, NULL, 0);
    TEST_ASSERT_EQUAL_INT(1, emu.errors);
}

void test_slpout_too_soon_after_reset_is_flagged(void)
{
    start_emu("st7789");
    hal.reset(hal.user, 0);
    hal.delay_ms(hal.user, 1);
    hal.reset(hal.user, 1);
    hal.delay_ms(hal.user, 119); /* needs 120 */
    raw_cmd(FXL_DCS_SLPOUT, NULL, 0);
    TEST_ASSERT_EQUAL_INT(1, emu.errors);
}

void test_pixels_without_ramwr_or_in_wrong_colmod_are_flagged(void)
{
    static const uint16_t a[1] = { 1 };
    static const uint8_t colmod666 = 0x66;
    start_awake();
    raw_pixels(a, 1);
    TEST_ASSERT_EQUAL_INT(1, emu.errors);
    raw_cmd(FXL_DCS_COLMOD, &colmod666, 1);
    raw_cmd(FXL_DCS_RAMWR, NULL, 0);
    raw_pixels(a, 1);
    TEST_ASSERT_EQUAL_INT(2, emu.errors);
}

void test_window_outside_address_space_is_flagged(void)
{
    static const uint8_t caset[4] = { 0x00, 0x00, 0x00, 0xF0 }; /* 0..240, max 239 */
    start_awake();
    raw_cmd(FXL_DCS_CASET, caset, 4);
    TEST_ASSERT_EQUAL_INT(1, emu.errors);
}

void test_buffer_modified_before_completion_is_flagged(void)
{
    /* The DMA mock compares the buffer at completion with its content at
     * pixels(): reusing a buffer early is caught. */
    static const uint8_t caset[4] = { 0, 0, 0, 1 }, raset[4] = { 0, 0, 0, 0 };
    uint8_t buf[4] = { 0xAA, 0xBB, 0xCC, 0xDD };
    start_awake();
    emu.dma_delay = 2;
    raw_cmd(FXL_DCS_CASET, caset, 4);
    raw_cmd(FXL_DCS_RASET, raset, 4);
    raw_cmd(FXL_DCS_RAMWR, NULL, 0);
    TEST_ASSERT_EQUAL_INT(FXL_OK, hal.pixels(hal.user, buf, 4));
    buf[2] = 0x00;
    hal.wait(hal.user);
    TEST_ASSERT_EQUAL_INT(0, emu.errors);
    hal.wait(hal.user);
    TEST_ASSERT_EQUAL_UINT32(1, (uint32_t)emu.completions);
    TEST_ASSERT_EQUAL_INT(1, emu.errors);
}

void test_command_during_transfer_is_flagged(void)
{
    static const uint8_t caset[4] = { 0, 0, 0, 1 }, raset[4] = { 0, 0, 0, 0 };
    uint8_t buf[4] = { 1, 2, 3, 4 };
    start_awake();
    emu.dma_delay = 3;
    raw_cmd(FXL_DCS_CASET, caset, 4);
    raw_cmd(FXL_DCS_RASET, raset, 4);
    raw_cmd(FXL_DCS_RAMWR, NULL, 0);
    TEST_ASSERT_EQUAL_INT(FXL_OK, hal.pixels(hal.user, buf, 4));
    raw_cmd(FXL_DCS_NOP, NULL, 0);
    TEST_ASSERT_EQUAL_INT(1, emu.errors);
    panel_emu_flush(&emu);
}

void test_asleep_or_display_off_shows_black(void)
{
    uint16_t *glass = (uint16_t *)malloc(240u * 320u * 2u);
    TEST_ASSERT_NOT_NULL(glass);
    start_emu("st7789");
    emu.inverted = 1; /* so a black pixel would not come from RAM 0x1234 */
    panel_emu_glass(&emu, glass);
    TEST_ASSERT_EQUAL_HEX16(0, glass[0]); /* after power-on: asleep, off */
    emu.sleeping = 0;
    emu.display_on = 1;
    panel_emu_glass(&emu, glass);
    TEST_ASSERT_EQUAL_HEX16(0x1234, glass[0]);
    free(glass);
}

/* ---- wire CRC ------------------------------------------------------------- */

void test_crc32_check_value_and_agreement_with_host_crc(void)
{
    uint8_t data[1000];
    size_t i;
    TEST_ASSERT_EQUAL_HEX32(0xCBF43926u, panel_emu_crc32(0, "123456789", 9));
    for (i = 0; i < sizeof(data); i++) data[i] = (uint8_t)(i * 37u + 11u);
    TEST_ASSERT_EQUAL_HEX32(crc32_update(0, data, sizeof(data)), panel_emu_crc32(0, data, sizeof(data)));
    /* Streaming equals one pass. */
    TEST_ASSERT_EQUAL_HEX32(panel_emu_crc32(0, data, sizeof(data)),
                            panel_emu_crc32(panel_emu_crc32(0, data, 333), data + 333, sizeof(data) - 333));
}

void test_wire_crc_covers_commands_parameters_and_pixels_in_order(void)
{
    static const uint8_t caset[4] = { 0, 0, 0, 0 };
    static const uint16_t px[1] = { 0xABCD };
    const uint8_t expect_bytes[] = { 0x2A, 0, 0, 0, 0, 0x2C, 0xAB, 0xCD };
    start_awake();
    panel_emu_clear_log(&emu);
    raw_cmd(FXL_DCS_CASET, caset, 4);
    raw_cmd(FXL_DCS_RAMWR, NULL, 0);
    raw_pixels(px, 1);
    TEST_ASSERT_EQUAL_UINT32(sizeof(expect_bytes), (uint32_t)emu.wire_bytes);
    TEST_ASSERT_EQUAL_HEX32(panel_emu_crc32(0, expect_bytes, sizeof(expect_bytes)), emu.crc);
}

/* 16-bit SPI frames: pixels() data are native uint16 words, each sent high
 * byte first, whatever the host's byte order; commands stay bytes. An odd
 * byte count cannot be 16-bit frames. */
void test_spi16_sends_each_word_high_byte_first(void)
{
    static const uint8_t caset[4] = { 0, 0, 0, 1 };
    static const uint16_t px[2] = { 0xABCD, 0xF800 };
    const uint8_t expect_bytes[] = { 0x2A, 0, 0, 0, 1, 0x2C, 0xAB, 0xCD, 0xF8, 0x00 };
    start_awake();
    emu.spi16 = 1;
    panel_emu_hal(&emu, &hal);
    TEST_ASSERT_EQUAL_UINT32(FXL_PORT_PIXELS_16BIT, hal.flags);
    /* before RAMWR: one protocol error per transfer, as with bytes */
    TEST_ASSERT_EQUAL_INT(FXL_OK, hal.pixels(hal.user, px, sizeof(px)));
    TEST_ASSERT_EQUAL_INT(1, emu.errors);
    panel_emu_clear_log(&emu);
    raw_cmd(FXL_DCS_CASET, caset, 4);
    raw_cmd(FXL_DCS_RAMWR, NULL, 0);
    TEST_ASSERT_EQUAL_INT(FXL_OK, hal.pixels(hal.user, px, sizeof(px)));
    TEST_ASSERT_EQUAL_INT(1, emu.errors);
    TEST_ASSERT_EQUAL_UINT32(sizeof(expect_bytes), (uint32_t)emu.wire_bytes);
    TEST_ASSERT_EQUAL_HEX32(panel_emu_crc32(0, expect_bytes, sizeof(expect_bytes)), emu.crc);
    TEST_ASSERT_EQUAL_HEX16(0xABCD, ram_at(0, 0));
    TEST_ASSERT_EQUAL_HEX16(0xF800, ram_at(1, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, hal.pixels(hal.user, px, 3));
    TEST_ASSERT_EQUAL_INT(2, emu.errors);
}

void test_lookup_by_name_and_alias(void)
{
    int w, h;
    TEST_ASSERT_NOT_NULL(panel_emu_module_find("st7789"));
    TEST_ASSERT_EQUAL_STRING("ili9341-240x320", panel_emu_module_find("ili9341")->name);
    TEST_ASSERT_TRUE(panel_emu_preset_find("st7789-135x240") == &fxl_st7789_135x240);
    TEST_ASSERT_NULL(panel_emu_module_find("ssd1306"));
    TEST_ASSERT_NULL(panel_emu_preset_find(NULL));
    TEST_ASSERT_EQUAL_INT(0, panel_emu_frame_size("st7789-135x240", 1, &w, &h));
    TEST_ASSERT_EQUAL_INT(240, w);
    TEST_ASSERT_EQUAL_INT(135, h);
    TEST_ASSERT_EQUAL_INT(-1, panel_emu_frame_size("st7789", 4, &w, &h));
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_every_preset_and_rotation_shows_the_frame_upright);
    RUN_TEST(test_wrong_offset_table_is_caught);
    RUN_TEST(test_missing_bgr_flag_swaps_red_and_blue);
    RUN_TEST(test_missing_inversion_on_ips_glass_inverts_colours);
    RUN_TEST(test_ramwr_continues_across_transfers_and_wraps_at_window_end);
    RUN_TEST(test_ramwrc_continues_after_a_command_ramwr_restarts);
    RUN_TEST(test_madctl_maps_logical_addresses_to_memory);
    RUN_TEST(test_command_too_soon_after_swreset_is_flagged);
    RUN_TEST(test_slpout_too_soon_after_reset_is_flagged);
    RUN_TEST(test_pixels_without_ramwr_or_in_wrong_colmod_are_flagged);
    RUN_TEST(test_window_outside_address_space_is_flagged);
    RUN_TEST(test_buffer_modified_before_completion_is_flagged);
    RUN_TEST(test_command_during_transfer_is_flagged);
    RUN_TEST(test_asleep_or_display_off_shows_black);
    RUN_TEST(test_crc32_check_value_and_agreement_with_host_crc);
    RUN_TEST(test_wire_crc_covers_commands_parameters_and_pixels_in_order);
    RUN_TEST(test_spi16_sends_each_word_high_byte_first);
    RUN_TEST(test_lookup_by_name_and_alias);
    return UNITY_END();
}

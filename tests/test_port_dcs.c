/* test_port_dcs.c - the MIPI DCS driver layer: exact bytes on the wire for
 * init, windows and pixels, every preset and rotation, the HAL contract and
 * its error paths. The wire is recorded by the panel emulator (panel_emu.h). */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <string.h>
#include <sys/time.h>

#include "unity.h"
#include "fixel/port.h"
#include "panel_emu.h"

static panel_emu_t emu;
static int emu_live;
static fxl_port_hal_t hal;
static fxl_panel_t panel;
static char msg[256];

#define C(x) PANEL_EMU_EV(PANEL_EMU_EV_CMD, x)
#define D(x) PANEL_EMU_EV(PANEL_EMU_EV_DATA, x)
#define W(x) PANEL_EMU_EV(PANEL_EMU_EV_DELAY, x)
#define R(x) PANEL_EMU_EV(PANEL_EMU_EV_RESET, x)
#define COUNT(a) (sizeof(a) / sizeof((a)[0]))

static void start_emu(const char *name)
{
    TEST_ASSERT_EQUAL_INT(0, panel_emu_init(&emu, panel_emu_module_find(name), 0));
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

static const char *ev_name(uint32_t ev)
{
    switch (ev >> 16) {
    case PANEL_EMU_EV_CMD: return "cmd";
    case PANEL_EMU_EV_DATA: return "data";
    case PANEL_EMU_EV_DELAY: return "delay";
    case PANEL_EMU_EV_RESET: return "reset";
    default: return "?";
    }
}

/* The recorded events from `from` on must be exactly `exp`. */
static void assert_wire(size_t from, const uint32_t *exp, size_t n)
{
    size_t i;
    for (i = 0; i < n && from + i < emu.log_len; i++) {
        uint32_t got = emu.log[from + i];
        snprintf(msg, sizeof(msg), "wire event %zu: expected %s 0x%02X, got %s 0x%02X", i,
                 ev_name(exp[i]), (unsigned)(exp[i] & 0xFFFFu), ev_name(got),
                 (unsigned)(got & 0xFFFFu));
        TEST_ASSERT_EQUAL_HEX32_MESSAGE(exp[i], got, msg);
    }
    snprintf(msg, sizeof(msg), "wire has %zu events, expected %zu", emu.log_len - from, n);
    TEST_ASSERT_EQUAL_UINT32_MESSAGE((uint32_t)n, (uint32_t)(emu.log_len - from), msg);
}

static void assert_no_protocol_errors(void)
{
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, emu.errors, emu.first_error);
}

/* ---- init sequences ------------------------------------------------------ */

void test_st7789_init_with_reset_pin_exact_bytes(void)
{
    /* RESX pulse (>= 10 us low; 1 ms granularity), 120 ms before SLPOUT,
     * 120 ms after it, COLMOD 16 bit, MADCTL 0 for rotation 0, INVON for
     * the IPS glass, NORON, DISPON. */
    static const uint32_t exp[] = {
        R(1), W(1), R(0), W(1), R(1), W(120),
        C(0x11), W(120),
        C(0x3A), D(0x55),
        C(0x36), D(0x00),
        C(0x21), C(0x13), C(0x29),
    };
    start_emu("st7789-240x240");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x240, 0));
    assert_wire(0, exp, COUNT(exp));
    assert_no_protocol_errors();
    TEST_ASSERT_EQUAL_INT(1, emu.display_on);
    TEST_ASSERT_EQUAL_INT(0, emu.sleeping);
}

void test_st7789_init_without_reset_pin_uses_swreset(void)
{
    /* 5 ms before SWRESET: the gap a previous SWRESET or SLPOUT needs. */
    static const uint32_t exp[] = {
        W(5), C(0x01), W(120),
        C(0x11), W(120),
        C(0x3A), D(0x55),
        C(0x36), D(0x60), /* rotation 1: MX | MV */
        C(0x21), C(0x13), C(0x29),
    };
    start_emu("st7789-240x320");
    hal.reset = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 1));
    assert_wire(0, exp, COUNT(exp));
    assert_no_protocol_errors();
    TEST_ASSERT_EQUAL_INT(320, panel.width);
    TEST_ASSERT_EQUAL_INT(240, panel.height);
}

void test_ili9341_init_exact_bytes(void)
{
    static const uint32_t exp[] = {
        R(1), W(1), R(0), W(1), R(1), W(120),
        C(0x11), W(120),
        C(0xC0), D(0x23),
        C(0xC1), D(0x10),
        C(0xC5), D(0x3E), D(0x28),
        C(0xC7), D(0x86),
        C(0xB1), D(0x00), D(0x18),
        C(0xB6), D(0x08), D(0x82), D(0x27),
        C(0x26), D(0x01),
        C(0x3A), D(0x55),
        C(0x36), D(0xE8), /* rotation 3: MY | MX | MV | BGR */
        C(0x20), C(0x13), C(0x29),
    };
    start_emu("ili9341");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_ili9341_240x320, 3));
    assert_wire(0, exp, COUNT(exp));
    assert_no_protocol_errors();
}

void test_madctl_per_rotation_for_every_preset(void)
{
    /* ST7789: 0, MX|MV, MX|MY, MY|MV; ILI9341: MX, MV, MY, MX|MY|MV, + BGR. */
    static const struct { const fxl_panel_preset_t *p; uint8_t m[4]; } cases[] = {
        { &fxl_st7789_240x320, { 0x00, 0x60, 0xC0, 0xA0 } },
        { &fxl_st7789_240x240, { 0x00, 0x60, 0xC0, 0xA0 } },
        { &fxl_st7789_135x240, { 0x00, 0x60, 0xC0, 0xA0 } },
        { &fxl_ili9341_240x320, { 0x48, 0x28, 0x88, 0xE8 } },
    };
    size_t i;
    unsigned r;
    for (i = 0; i < COUNT(cases); i++) {
        start_emu(cases[i].p->name);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, cases[i].p, 0));
        for (r = 0; r < 4; r++) {
            static uint32_t exp[2];
            size_t from = emu.log_len;
            exp[0] = C(0x36);
            exp[1] = D(cases[i].m[r]);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_rotation(&panel, r));
            assert_wire(from, exp, 2);
        }
        assert_no_protocol_errors();
        tearDown();
    }
}

/* The colour order comes from the preset's flags alone (port.h: madctl[]
 * holds "MY/MX/MV per rotation (BGR is added from flags)"): a BGR bit left
 * in a madctl entry of a preset without FXL_PANEL_BGR is not sent, so the
 * ST7789 table with 0x08 added still sends 0x00 / 0x60 / 0xC0 / 0xA0, and
 * the ILI9341 preset with its BGR flag cleared sends its entries without
 * 0x08 (0x40, 0x20, 0x80, 0xE0). */
void test_madctl_bgr_bit_comes_from_the_flags_only(void)
{
    static const uint8_t st[4] = { 0x00, 0x60, 0xC0, 0xA0 }, ili[4] = { 0x40, 0x20, 0x80, 0xE0 };
    static fxl_panel_preset_t pr[2];
    int i;
    unsigned r;
    pr[0] = fxl_st7789_240x320;
    for (r = 0; r < 4; r++)
        pr[0].madctl[r] = (uint8_t)(pr[0].madctl[r] | FXL_MADCTL_BGR);
    pr[1] = fxl_ili9341_240x320;
    pr[1].flags = (uint8_t)(pr[1].flags & ~FXL_PANEL_BGR);
    for (i = 0; i < 2; i++) {
        start_emu(i ? "ili9341" : "st7789");
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &pr[i], 0));
        for (r = 0; r < 4; r++) {
            uint32_t exp[2];
            size_t from = emu.log_len;
            exp[0] = C(0x36);
            exp[1] = D(i ? ili[r] : st[r]);
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_rotation(&panel, r));
            assert_wire(from, exp, 2);
        }
        assert_no_protocol_errors();
        tearDown();
    }
}

/* ---- windows ------------------------------------------------------------- */

/* RAM offsets per rotation (derivation in port/st7789.c): the glass at
 * columns c0..c0+w-1 / rows r0..r0+h-1 of the 240x320 memory appears at
 * 240-c0-w / 320-r0-h when MX / MY mirror that axis. */
static const struct {
    const fxl_panel_preset_t *p;
    int w, h;
    int off[4][2];
} window_cases[] = {
    { &fxl_st7789_240x320, 240, 320, { { 0, 0 }, { 0, 0 }, { 0, 0 }, { 0, 0 } } },
    { &fxl_st7789_240x240, 240, 240, { { 0, 0 }, { 0, 0 }, { 0, 80 }, { 80, 0 } } },
    { &fxl_st7789_135x240, 135, 240, { { 52, 40 }, { 40, 53 }, { 53, 40 }, { 40, 52 } } },
    { &fxl_ili9341_240x320, 240, 320, { { 0, 0 }, { 0, 0 }, { 0, 0 }, { 0, 0 } } },
};

static void expect_window(size_t from, int x0, int y0, int x1, int y1)
{
    uint32_t exp[11];
    exp[0] = C(0x2A);
    exp[1] = D((unsigned)x0 >> 8);
    exp[2] = D((unsigned)x0 & 0xFFu);
    exp[3] = D((unsigned)x1 >> 8);
    exp[4] = D((unsigned)x1 & 0xFFu);
    exp[5] = C(0x2B);
    exp[6] = D((unsigned)y0 >> 8);
    exp[7] = D((unsigned)y0 & 0xFFu);
    exp[8] = D((unsigned)y1 >> 8);
    exp[9] = D((unsigned)y1 & 0xFFu);
    exp[10] = C(0x2C);
    assert_wire(from, exp, 11);
}

void test_full_window_bytes_every_preset_and_rotation(void)
{
    size_t i;
    int r;
    for (i = 0; i < COUNT(window_cases); i++) {
        start_emu(window_cases[i].p->name);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, window_cases[i].p, 0));
        for (r = 0; r < 4; r++) {
            const int w = (r & 1) ? window_cases[i].h : window_cases[i].w;
            const int h = (r & 1) ? window_cases[i].w : window_cases[i].h;
            const int ox = window_cases[i].off[r][0], oy = window_cases[i].off[r][1];
            size_t from;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_rotation(&panel, (unsigned)r));
            TEST_ASSERT_EQUAL_INT(w, panel.width);
            TEST_ASSERT_EQUAL_INT(h, panel.height);
            from = emu.log_len;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, w, h));
            expect_window(from, ox, oy, ox + w - 1, oy + h - 1);
        }
        assert_no_protocol_errors();
        tearDown();
    }
}

void test_partial_window_bytes_every_preset_and_rotation(void)
{
    size_t i;
    int r;
    for (i = 0; i < COUNT(window_cases); i++) {
        start_emu(window_cases[i].p->name);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, window_cases[i].p, 0));
        for (r = 0; r < 4; r++) {
            const int ox = window_cases[i].off[r][0], oy = window_cases[i].off[r][1];
            size_t from;
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_rotation(&panel, (unsigned)r));
            from = emu.log_len;
            /* Bottom-right corner pixel block 7x2 ending at the last column/row. */
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, panel.width - 7,
                                                               panel.height - 2, 7, 2));
            expect_window(from, ox + panel.width - 7, oy + panel.height - 2,
                          ox + panel.width - 1, oy + panel.height - 1);
        }
        assert_no_protocol_errors();
        tearDown();
    }
}

void test_window_addresses_above_255_are_big_endian(void)
{
    static const uint32_t exp[] = {
        C(0x2A), D(0x01), D(0x00), D(0x01), D(0x3F),
        C(0x2B), D(0x00), D(0x10), D(0x00), D(0xEF),
        C(0x2C),
    };
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_dcs_window(&hal, 256, 16, 319, 239));
    assert_wire(0, exp, COUNT(exp));
}

void test_window_outside_visible_area_is_range_error(void)
{
    start_emu("st7789-135x240");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_135x240, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_panel_set_window(&panel, 0, 0, 136, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_panel_set_window(&panel, 0, 239, 1, 2));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_panel_set_window(&panel, -1, 0, 1, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_panel_set_window(&panel, 0, 0, 0, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_panel_set_window(&panel, 134, 0, INT32_MAX, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_dcs_window(&hal, 5, 0, 4, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_dcs_window(&hal, 0, 10, 5, 9));   /* rows reversed */
}

/* ---- pixels -------------------------------------------------------------- */

static uint16_t to_wire(uint16_t rgb565)
{
    return fxl_port_wire_format() == FXL_PIXFMT_RGB565_SWAP
               ? (uint16_t)((rgb565 >> 8) | (rgb565 << 8))
               : rgb565;
}

void test_wire_format_matches_cpu_byte_order(void)
{
    const uint16_t probe = 0x1234u;
    unsigned char b[2];
    memcpy(b, &probe, 2);
    TEST_ASSERT_EQUAL_INT(b[0] == 0x34 ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565,
                          fxl_port_wire_format());
}

void test_pixels_go_out_high_byte_first_without_copy(void)
{
    /* Red 0xF800, magenta 0xF81F, green 0x07E0 must appear as F8 00, F8 1F,
     * 07 E0, and the controller must store exactly those RGB565 words. */
    static const uint32_t exp[] = { D(0xF8), D(0x00), D(0xF8), D(0x1F), D(0x07), D(0xE0) };
    uint16_t buf[3];
    size_t from;
    int col, row;
    buf[0] = to_wire(0xF800u);
    buf[1] = to_wire(0xF81Fu);
    buf[2] = to_wire(0x07E0u);
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 10, 20, 3, 1));
    from = emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&panel));
    assert_wire(from, exp, COUNT(exp));
    TEST_ASSERT_EQUAL_INT(0, panel_emu_map(&emu, 11, 20, &col, &row));
    TEST_ASSERT_EQUAL_HEX16(0xF81Fu, emu.ram[row * 240 + col]);
    assert_no_protocol_errors();
}

void test_late_completion_is_waited_for_through_the_wait_hook(void)
{
    /* dma_delay 3: the transfer completes on the third HAL call after
     * pixels(); only wait() calls follow, so exactly 3 waits. */
    uint16_t buf[4] = { 1, 2, 3, 4 };
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 4, 1));
    emu.dma_delay = 3;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
    TEST_ASSERT_EQUAL_UINT32(1, panel.started);
    TEST_ASSERT_EQUAL_UINT32(0, panel.done);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&panel));
    TEST_ASSERT_EQUAL_UINT32(1, panel.done);
    TEST_ASSERT_EQUAL_UINT32(3, (uint32_t)emu.waits);
    assert_no_protocol_errors();
}

void test_second_write_waits_for_the_first_transfer(void)
{
    /* A second write while the first is on the wire would be a protocol
     * error in the emulator ("pixels() while transfer in flight"). */
    uint16_t a[2] = { 1, 2 }, b[2] = { 3, 4 };
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 4, 1));
    emu.dma_delay = 5;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, a, sizeof(a)));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, b, sizeof(b)));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 1, 1, 1));
    assert_no_protocol_errors();
    TEST_ASSERT_EQUAL_UINT32(2, panel.done);
}

void test_sync_hal_counts_its_own_completion(void)
{
    uint16_t buf[2] = { 1, 2 };
    start_emu("st7789");
    emu.panel = NULL; /* a blocking HAL never reports */
    hal.flags = FXL_PORT_PIXELS_SYNC;
    hal.wait = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 2, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
    TEST_ASSERT_EQUAL_UINT32(1, panel.done);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&panel));
    assert_no_protocol_errors();
}

void test_transfer_done_is_a_counter_and_ignores_null(void)
{
    fxl_port_transfer_done(NULL);
    panel.done = 0xFFFFFFFFu;
    fxl_port_transfer_done(&panel);
    TEST_ASSERT_EQUAL_UINT32(0, panel.done);
}

/* ---- fxl_panel_busy and hooks that sleep ---------------------------------- */

void test_panel_busy_follows_the_transfer_without_waiting(void)
{
    uint16_t buf[2] = { 1, 2 };
    int i;
    TEST_ASSERT_EQUAL_INT(0, fxl_panel_busy(NULL));
    TEST_ASSERT_EQUAL_INT(0, fxl_panel_busy(&panel)); /* zeroed, not initialised */
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(0, fxl_panel_busy(&panel));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 2, 1));
    /* one HAL call more would complete it: asking must call none */
    emu.dma_delay = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
    for (i = 0; i < 5; i++)
        TEST_ASSERT_EQUAL_INT(1, fxl_panel_busy(&panel));
    TEST_ASSERT_EQUAL_UINT32(0, panel.done);
    panel_emu_flush(&emu);
    TEST_ASSERT_EQUAL_INT(0, fxl_panel_busy(&panel));
    /* a completion reported twice (done ahead of started) is not a transfer */
    fxl_port_transfer_done(&panel);
    TEST_ASSERT_EQUAL_INT(0, fxl_panel_busy(&panel));
    assert_no_protocol_errors();
}

void test_panel_busy_is_zero_after_a_blocking_write(void)
{
    uint16_t buf[2] = { 1, 2 };
    start_emu("st7789");
    emu.panel = NULL; /* a blocking HAL never reports */
    hal.flags = FXL_PORT_PIXELS_SYNC;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 2, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
    TEST_ASSERT_EQUAL_INT(0, fxl_panel_busy(&panel));
}

/* The masked-WFI hook of docs/porting.md ("Sleeping in the wait hook"):
 * __disable_irq(); if (fxl_panel_busy(panel)) __WFI(); __enable_irq();
 * with the DMA interrupt landing at the worst moment, after the driver's
 * last look and before the hook masks interrupts (its wfi_land_at-th call).
 * Until then the hook must find the transfer running and may sleep (the
 * interrupt would wake it); from then on it must find it over and not
 * sleep, where a bare WFI would sleep through the completion. */
static int wfi_calls, wfi_land_at, wfi_sleeps, wfi_lost;

static fxl_status_t masked_wfi_hook(void *user)
{
    const fxl_panel_t *p = ((panel_emu_t *)user)->panel;
    wfi_calls++;
    if (wfi_calls == wfi_land_at) panel_emu_flush((panel_emu_t *)user); /* the interrupt */
    /* __disable_irq() */
    if (fxl_panel_busy(p)) {
        wfi_sleeps++; /* __WFI() */
        if (wfi_calls >= wfi_land_at) wfi_lost++;
    }
    /* __enable_irq() */
    return FXL_OK;
}

void test_masked_wfi_hook_never_sleeps_through_a_completion(void)
{
    uint16_t buf[4] = { 1, 2, 3, 4 };
    int land;
    for (land = 1; land <= 4; land++) {
        start_emu("st7789");
        hal.wait = masked_wfi_hook;
        emu.dma_delay = 1 << 30; /* only the modelled interrupt completes */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 4, 1));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
        wfi_calls = wfi_sleeps = wfi_lost = 0;
        wfi_land_at = land;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&panel));
        TEST_ASSERT_EQUAL_INT(0, wfi_lost);
        TEST_ASSERT_EQUAL_INT(land, wfi_calls); /* the driver stops calling once it is over */
        TEST_ASSERT_EQUAL_INT(land - 1, wfi_sleeps);
        TEST_ASSERT_EQUAL_UINT32(1, panel.done);
        assert_no_protocol_errors();
        tearDown();
        setUp();
    }
}

/* ---- HAL contract and error paths ---------------------------------------- */

static fxl_status_t failing_cmd(void *user, uint8_t c, const uint8_t *p, size_t n)
{
    (void)user; (void)c; (void)p; (void)n;
    return FXL_ERR_IO;
}
static fxl_status_t failing_pixels(void *user, const void *d, size_t n)
{
    (void)user; (void)d; (void)n;
    return FXL_ERR_BUSY;
}
static fxl_status_t failing_wait(void *user)
{
    (void)user;
    return FXL_ERR_BUSY;
}

void test_null_and_missing_required_callbacks_are_arg_errors(void)
{
    fxl_port_hal_t h;
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(NULL, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(&panel, NULL, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(&panel, &hal, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 4));
    h = hal;
    h.cmd = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(&panel, &h, &fxl_st7789_240x320, 0));
    h = hal;
    h.pixels = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(&panel, &h, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_dcs_cmd(NULL, 0x29, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_dcs_cmd(&hal, 0x29, NULL, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_dcs_window(NULL, 0, 0, 0, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_dcs_run(&hal, NULL, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_write(NULL, "ab", 2));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_wait_idle(NULL));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_set_window(NULL, 0, 0, 1, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_set_rotation(NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_display(NULL, 1));
    /* Nothing reached the wire. */
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)emu.log_len);
}

void test_optional_wrappers_report_unsupported_when_null(void)
{
    fxl_port_hal_t h;
    memset(&h, 0, sizeof(h));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_port_reset(&h, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_port_delay_ms(&h, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_port_wait_hook(&h));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_port_reset(NULL, 1));
}

void test_init_without_delay_refuses_before_sending_anything(void)
{
    start_emu("st7789");
    hal.delay_ms = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)emu.log_len);
}

/* The ST7789 preset 200 x 50 (clauses 0, 1) or 50 x 200 (2, 3) with
 * rotation 1's offset x (even clauses) or y (odd) at `offset`, the others 0:
 * the longer side meets the offset in x + width, y + width, x + height or
 * y + height, one sum a clause. */
static fxl_panel_preset_t preset_with_offset(int clause, uint16_t offset)
{
    fxl_panel_preset_t pr = fxl_st7789_240x320;
    pr.width = clause < 2 ? 200 : 50;
    pr.height = clause < 2 ? 50 : 200;
    memset(pr.offset, 0, sizeof pr.offset);
    if (clause & 1)
        pr.offset[1].y = offset;
    else
        pr.offset[1].x = offset;
    return pr;
}

/* A preset whose window addresses would pass 16 bits in any rotation is
 * refused, each of the four offset + side sums on its own (65400 + 200);
 * a sum of exactly 65535 is inside the contract ("above 65535" is refused:
 * the last address on the wire is 65534, which CASET/RASET's 16 bits
 * hold). */
void test_preset_addresses_beyond_16_bits_are_refused(void)
{
    int clause;
    start_emu("st7789");
    for (clause = 0; clause < 4; clause++) {
        fxl_panel_preset_t pr = preset_with_offset(clause, 65400);
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_ERR_ARG, fxl_panel_init(&panel, &hal, &pr, 0), "offset clause");
    }
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)emu.log_len);
    for (clause = 0; clause < 4; clause++) {
        fxl_panel_preset_t pr = preset_with_offset(clause, 65335);   /* + 200 = 65535 */
        TEST_ASSERT_EQUAL_INT_MESSAGE(FXL_OK, fxl_panel_init(&panel, &hal, &pr, 0), "offset clause at 65535");
    }
}

/* A preset of zero width or zero height is a bad preset (port.h: "a zero
 * size"): FXL_ERR_ARG with nothing sent, not an init of an empty panel. */
void test_preset_of_zero_width_or_height_is_refused(void)
{
    fxl_panel_preset_t pr = fxl_st7789_240x320;
    start_emu("st7789");
    pr.width = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(&panel, &hal, &pr, 0));
    pr.width = 240;
    pr.height = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(&panel, &hal, &pr, 0));
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)emu.log_len);
}

/* A preset step with more parameters than a step holds is refused before
 * anything is sent (not after the reset and the steps before it). */
void test_preset_step_longer_than_its_parameters_is_refused(void)
{
    static fxl_dcs_step_t steps[256];
    fxl_panel_preset_t pr = fxl_ili9341_240x320;
    TEST_ASSERT_TRUE(pr.init_count >= 2);
    memcpy(steps, pr.init, pr.init_count * sizeof steps[0]);
    pr.init = steps;
    steps[pr.init_count - 1].n = (uint8_t)(sizeof steps[0].params + 1);
    start_emu("ili9341");
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_init(&panel, &hal, &pr, 0));
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)emu.log_len);
    steps[pr.init_count - 1].n = (uint8_t)sizeof steps[0].params;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &pr, 0));
}

/* The drivers send RGB565 only: a preset whose COLMOD selects another MCU
 * interface format (bits 2..0; 0x66 is 18 bits a pixel) is refused before
 * anything is sent; 0x05 (16 bits, RGB interface bits clear) is accepted. */
void test_init_refuses_a_pixel_format_other_than_rgb565(void)
{
    fxl_panel_preset_t pr = fxl_st7789_240x320;
    start_emu("st7789");
    pr.colmod = 0x66u;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_panel_init(&panel, &hal, &pr, 0));
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)emu.log_len);
    pr.colmod = 0x05u;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &pr, 0));
}

void test_missing_reset_and_wait_hooks_still_work(void)
{
    /* reset NULL: SWRESET path; wait NULL: the driver spins on the counter,
     * which the mock raises inside pixels() (dma_delay 0, an ISR firing at
     * once). */
    uint16_t buf[8] = { 0 };
    start_emu("st7789");
    hal.reset = NULL;
    hal.wait = NULL;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 2));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 8, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&panel));
    TEST_ASSERT_EQUAL_UINT32(1, panel.done);
    assert_no_protocol_errors();
}

void test_hal_failures_become_io_errors(void)
{
    uint16_t buf[2] = { 0, 0 };
    start_emu("st7789");
    hal.cmd = failing_cmd;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    /* the panel is in no known state: refused until an init succeeds */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_set_window(&panel, 0, 0, 2, 1));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_write(&panel, buf, sizeof(buf)));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_display(&panel, 1));
    tearDown();

    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 2, 1));
    panel.hal.pixels = failing_pixels;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, fxl_panel_write(&panel, buf, sizeof(buf)));
    /* A refused start is not in flight: waiting returns at once. */
    TEST_ASSERT_EQUAL_UINT32(0, panel.started);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&panel));
}

/* delay_ms that refuses its `refuse_delay_at`-th 120 ms delay (1-based),
 * else the emulator's. */
static fxl_status_t (*emu_delay)(void *user, uint32_t ms);
static int delay_calls, refuse_delay_at;
static fxl_status_t refusing_delay(void *user, uint32_t ms)
{
    if (ms == 120u && ++delay_calls == refuse_delay_at) return FXL_ERR_IO;
    return emu_delay(user, ms);
}

void test_init_retried_after_a_refused_delay_keeps_the_swreset_gap(void)
{
    /* Without a reset pin: the 120 ms after SWRESET, then the 120 ms after
     * SLPOUT, refused; the init fails right after a command
     * that needs 5 ms before the next, and the firmware retries at once.
     * The retry's SWRESET must not come inside those 5 ms (the emulator
     * flags a command 0 ms after SWRESET or SLPOUT). */
    static const int refuse[] = { 1, 2 };
    size_t i;
    for (i = 0; i < COUNT(refuse); i++) {
        start_emu("st7789");
        hal.reset = NULL;
        emu_delay = hal.delay_ms;
        hal.delay_ms = refusing_delay;
        delay_calls = 0;
        refuse_delay_at = refuse[i];
        TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
        assert_no_protocol_errors();
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
        assert_no_protocol_errors();
        TEST_ASSERT_EQUAL_INT(1, emu.display_on);
        tearDown();
    }
}

/* An ST7789 with a two-pixel transfer that never completes within the
 * test in flight, and a wait hook that gives up. */
static void start_stuck_transfer(void)
{
    static uint16_t buf[2];
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 2, 1));
    emu.dma_delay = 1000000;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
    panel.hal.wait = failing_wait;
}

void test_wait_hook_can_abort_a_stuck_transfer(void)
{
    start_stuck_transfer();
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, fxl_panel_wait_idle(&panel));
    panel_emu_flush(&emu);
}

/* fxl_panel_set_rotation "waits for transfers" (port.h) and the driver
 * never calls cmd() with a pixel transfer in flight: with the transfer
 * ending on the third HAL call after pixels(), MADCTL goes out after
 * exactly three wait() calls, behind the pixel bytes, with no protocol
 * error. */
void test_set_rotation_waits_for_the_transfer_in_flight(void)
{
    static const uint32_t exp[] = { D(0x12), D(0x34), D(0x56), D(0x78), C(0x36), D(0x60) };
    uint16_t buf[2];
    size_t from;
    buf[0] = to_wire(0x1234u);
    buf[1] = to_wire(0x5678u);
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 2, 1));
    emu.dma_delay = 3;
    from = emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&panel, buf, sizeof(buf)));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_rotation(&panel, 1));
    TEST_ASSERT_EQUAL_UINT32(3, (uint32_t)emu.waits);
    TEST_ASSERT_EQUAL_UINT32(1, panel.done);
    assert_wire(from, exp, COUNT(exp));
    assert_no_protocol_errors();
}

/* A wait hook that gives up makes set_rotation return FXL_ERR_IO with no
 * MADCTL sent (port.h: "every call that waits gives up again"), and the
 * panel keeps its rotation and size. */
void test_set_rotation_gives_up_with_the_wait_hook_and_sends_nothing(void)
{
    size_t from;
    start_stuck_transfer();
    from = emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, fxl_panel_set_rotation(&panel, 1));
    TEST_ASSERT_EQUAL_UINT32((uint32_t)from, (uint32_t)emu.log_len);
    TEST_ASSERT_EQUAL_INT(0, panel.rotation);
    TEST_ASSERT_EQUAL_INT(240, panel.width);
    TEST_ASSERT_EQUAL_INT(320, panel.height);
    assert_no_protocol_errors();
    panel_emu_flush(&emu);
}

/* A MADCTL the HAL failed to send leaves the controller in the old
 * rotation, so the panel keeps the old rotation and size too ("width/height
 * follow" the MADCTL): FXL_ERR_IO, still 240 x 320, and the full 240 x 320
 * window is still the one set afterwards. */
void test_set_rotation_refused_by_the_hal_keeps_the_old_rotation(void)
{
    size_t from;
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    panel.hal.cmd = failing_cmd;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, fxl_panel_set_rotation(&panel, 1));
    TEST_ASSERT_EQUAL_INT(0, panel.rotation);
    TEST_ASSERT_EQUAL_INT(240, panel.width);
    TEST_ASSERT_EQUAL_INT(320, panel.height);
    panel.hal.cmd = hal.cmd;
    from = emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&panel, 0, 0, 240, 320));
    expect_window(from, 0, 0, 239, 319);
    assert_no_protocol_errors();
}

void test_bad_write_sizes_are_arg_errors(void)
{
    uint16_t buf[2] = { 0, 0 };
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_write(&panel, buf, 3));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_write(&panel, buf, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_write(&panel, NULL, 2));
    /* a HAL sending 16-bit frames reads uint16s: an odd address is refused */
    panel.hal.flags |= FXL_PORT_PIXELS_16BIT;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_write(&panel, (const unsigned char *)buf + 1, 2));
    TEST_ASSERT_EQUAL_UINT32(0, panel.started);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_panel_set_rotation(&panel, 4));
}

void test_display_off_and_on(void)
{
    static const uint32_t exp[] = { C(0x28), C(0x29) };
    size_t from;
    start_emu("st7789");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, &fxl_st7789_240x320, 0));
    from = emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_display(&panel, 0));
    TEST_ASSERT_EQUAL_INT(0, emu.display_on);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_display(&panel, 1));
    assert_wire(from, exp, COUNT(exp));
}

/* fxl_dcs_run's own contract (the presets' steps never had a delay in the
 * ILI9341 steps, nor did any test run it directly): a step's delay follows
 * its bytes; without delay_ms the step is sent and the run stops with
 * FXL_ERR_UNSUPPORTED; a step of more than 15 parameters is FXL_ERR_ARG
 * with the steps before it sent and nothing of it. */
void test_dcs_run_steps_delays_and_refusals(void)
{
    static const fxl_dcs_step_t steps[] = {
        {0xB1, 2, 10, {0x01, 0x02}},
        {0xB2, 0, 0, {0}},
        {0xB3, 1, 120, {0x7F}},
    };
    static const uint32_t all[] = {C(0xB1), D(0x01), D(0x02), W(10), C(0xB2), C(0xB3), D(0x7F), W(120)};
    static const uint32_t first[] = {C(0xB1), D(0x01), D(0x02)};
    fxl_dcs_step_t big[2] = {{0xB4, 1, 0, {0x11}}, {0xB5, 16, 0, {0}}};
    size_t from;
    start_emu("ili9341");
    from = emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_dcs_run(&hal, steps, COUNT(steps)));
    assert_wire(from, all, COUNT(all));
    /* no delay callback: the first step goes out, then the refusal */
    hal.delay_ms = NULL;
    from = emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_UNSUPPORTED, fxl_dcs_run(&hal, steps, COUNT(steps)));
    assert_wire(from, first, COUNT(first));
    /* an oversized step: the one before it sent, nothing of it */
    from = emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_dcs_run(&hal, big, 2));
    {
        static const uint32_t before[] = {C(0xB4), D(0x11)};
        assert_wire(from, before, COUNT(before));
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_dcs_run(&hal, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_dcs_run(&hal, NULL, 1));
    assert_no_protocol_errors();
}

/* The shortest delay a step can ask for, 1 ms, is a delay too: a step's
 * delay_ms > 0 is followed by delay_ms(delay_ms) (fxl_dcs_run, port.h). */
void test_dcs_run_keeps_a_one_millisecond_delay(void)
{
    static const fxl_dcs_step_t steps[] = {{0xB1, 1, 1, {0x05}}, {0xB2, 0, 1, {0}}};
    static const uint32_t exp[] = {C(0xB1), D(0x05), W(1), C(0xB2), W(1)};
    start_emu("ili9341");
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_dcs_run(&hal, steps, COUNT(steps)));
    assert_wire(0, exp, COUNT(exp));
    assert_no_protocol_errors();
}

/* A HAL without a wait hook whose DMA completes later, asynchronously: a
 * timer signal plays the DMA-complete interrupt 1 ms after each pixels().
 * The driver must spin on the completion counter before any further cmd()
 * or pixels() (the other no-hook tests complete inside pixels(), so a driver
 * that did not wait at all passed them). */
static fxl_panel_t async_panel;
static volatile sig_atomic_t async_busy;
static int async_violations, async_started;

static void async_complete(int sig)
{
    (void)sig;
    async_busy = 0;
    fxl_port_transfer_done(&async_panel);
}

static fxl_status_t async_cmd(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    (void)user;
    (void)cmd;
    (void)params;
    (void)n;
    if (async_busy)
        async_violations++;
    return FXL_OK;
}

static fxl_status_t async_pixels(void *user, const void *data, size_t bytes)
{
    struct itimerval it;
    (void)user;
    (void)data;
    (void)bytes;
    if (async_busy)
        async_violations++;
    async_busy = 1;
    async_started++;
    memset(&it, 0, sizeof it);
    it.it_value.tv_usec = 1000;
    TEST_ASSERT_EQUAL_INT(0, setitimer(ITIMER_REAL, &it, NULL));
    return FXL_OK;
}

static fxl_status_t async_delay(void *user, uint32_t ms)
{
    (void)user;
    (void)ms;
    return FXL_OK;
}

void test_without_wait_hook_the_driver_waits_for_a_late_completion(void)
{
    static uint16_t line[240];
    struct sigaction sa, old;
    fxl_port_hal_t h;
    int i;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = async_complete;
    sigemptyset(&sa.sa_mask);
    TEST_ASSERT_EQUAL_INT(0, sigaction(SIGALRM, &sa, &old));
    memset(&h, 0, sizeof h);
    h.cmd = async_cmd;
    h.pixels = async_pixels;
    h.delay_ms = async_delay;
    async_busy = 0;
    async_violations = async_started = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&async_panel, &h, &fxl_ili9341_240x320, 0));
    for (i = 0; i < 8; i++) {
        /* a window (commands) after each line, a wait for a numbered one */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_window(&async_panel, 0, i, 240, 1));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_write(&async_panel, line, sizeof line));
        if (i == 3)
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_done(&async_panel, async_panel.started));
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_display(&async_panel, 1));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_idle(&async_panel));
    {
        /* disarmed before the default action (exit) is back */
        struct itimerval off;
        memset(&off, 0, sizeof off);
        TEST_ASSERT_EQUAL_INT(0, setitimer(ITIMER_REAL, &off, NULL));
    }
    TEST_ASSERT_EQUAL_INT(0, sigaction(SIGALRM, &old, NULL));
    TEST_ASSERT_EQUAL_INT(8, async_started);
    TEST_ASSERT_EQUAL_UINT32(8, async_panel.done);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, async_violations, "HAL called while a transfer was in flight");
    TEST_ASSERT_EQUAL_INT(0, async_busy);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_st7789_init_with_reset_pin_exact_bytes);
    RUN_TEST(test_st7789_init_without_reset_pin_uses_swreset);
    RUN_TEST(test_ili9341_init_exact_bytes);
    RUN_TEST(test_madctl_per_rotation_for_every_preset);
    RUN_TEST(test_madctl_bgr_bit_comes_from_the_flags_only);
    RUN_TEST(test_full_window_bytes_every_preset_and_rotation);
    RUN_TEST(test_partial_window_bytes_every_preset_and_rotation);
    RUN_TEST(test_window_addresses_above_255_are_big_endian);
    RUN_TEST(test_window_outside_visible_area_is_range_error);
    RUN_TEST(test_wire_format_matches_cpu_byte_order);
    RUN_TEST(test_pixels_go_out_high_byte_first_without_copy);
    RUN_TEST(test_late_completion_is_waited_for_through_the_wait_hook);
    RUN_TEST(test_second_write_waits_for_the_first_transfer);
    RUN_TEST(test_sync_hal_counts_its_own_completion);
    RUN_TEST(test_transfer_done_is_a_counter_and_ignores_null);
    RUN_TEST(test_panel_busy_follows_the_transfer_without_waiting);
    RUN_TEST(test_panel_busy_is_zero_after_a_blocking_write);
    RUN_TEST(test_masked_wfi_hook_never_sleeps_through_a_completion);
    RUN_TEST(test_null_and_missing_required_callbacks_are_arg_errors);
    RUN_TEST(test_optional_wrappers_report_unsupported_when_null);
    RUN_TEST(test_init_without_delay_refuses_before_sending_anything);
    RUN_TEST(test_init_refuses_a_pixel_format_other_than_rgb565);
    RUN_TEST(test_preset_addresses_beyond_16_bits_are_refused);
    RUN_TEST(test_preset_of_zero_width_or_height_is_refused);
    RUN_TEST(test_preset_step_longer_than_its_parameters_is_refused);
    RUN_TEST(test_missing_reset_and_wait_hooks_still_work);
    RUN_TEST(test_hal_failures_become_io_errors);
    RUN_TEST(test_init_retried_after_a_refused_delay_keeps_the_swreset_gap);
    RUN_TEST(test_wait_hook_can_abort_a_stuck_transfer);
    RUN_TEST(test_set_rotation_waits_for_the_transfer_in_flight);
    RUN_TEST(test_set_rotation_gives_up_with_the_wait_hook_and_sends_nothing);
    RUN_TEST(test_set_rotation_refused_by_the_hal_keeps_the_old_rotation);
    RUN_TEST(test_bad_write_sizes_are_arg_errors);
    RUN_TEST(test_display_off_and_on);
    RUN_TEST(test_dcs_run_steps_delays_and_refusals);
    RUN_TEST(test_dcs_run_keeps_a_one_millisecond_delay);
    RUN_TEST(test_without_wait_hook_the_driver_waits_for_a_late_completion);
    return UNITY_END();
}

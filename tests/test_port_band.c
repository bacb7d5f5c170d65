/* test_port_band.c - band rendering with DMA double buffering and binning:
 * the image on the emulated panel is bit-identical to a full-frame render of
 * the same triangles, for every band height, preset, rotation, DMA latency
 * and bin budget (fallback included); buffers are never reused before their
 * transfer completed (the emulator's DMA mock checks every transfer); the
 * two buffers alternate, band k + 1 is drawn while band k is on the wire,
 * and the transfer counters survive a panel re-init, wrapping, a refused
 * transfer and a wait hook that gives up. */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/time.h>

#include "unity.h"
#include "test_features.h"
#include "left_out.h"
#include "fixel/fixel.h"
#include "fixel/port.h"
#include "panel_emu.h"
#include "crc32.h"

#define MAX_TRIS 32
#define CLEAR_COLOR 0x2104u

static char msg[256];
static uint16_t texels[16 * 16];
static fxl_texture_t tex;
static fxl_draw_t d_tex, d_flat_red, d_flat_green, d_flat_blue, d_bad;
#if !FXL_HAVE_GENERIC
static uint16_t solid_texel[4];
static fxl_texture_t solid_tex[4];
#endif

/* Each frame is compared with the same triangles drawn another way by the
 * same build, so any configuration can run the comparisons with the draws
 * it has: without FXL_HAVE_DEPTH no depth buffer (painter's order), without
 * FXL_HAVE_BILINEAR point sampling, without FXL_HAVE_GENERIC flat() below. */
#define DEPTH_BUF(p) (FXL_HAVE_DEPTH ? (p) : NULL)

/* A flat-colour draw. Untextured draws need FXL_HAVE_GENERIC; without it a
 * 1x1 RGB565 texture of the colour (slot i) draws the same pixels. */
static void flat(fxl_draw_t *d, int i)
{
#if FXL_HAVE_GENERIC
    (void)d;
    (void)i;
#else
    solid_texel[i] = d->color;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&solid_tex[i], &solid_texel[i], 1, 1, FXL_TEXFMT_RGB565, 1));
    d->texture = &solid_tex[i];
#endif
}

typedef struct scene {
    fxl_vertex_t v[MAX_TRIS][3];
    const fxl_draw_t *draw[MAX_TRIS];
    int count;
} scene_t;

typedef struct run_cfg {
    const char *panel;
    int rotation;
    int band_rows;
    int dma_delay;
    int bins;          /* 0: room for everything, 1: a few entries (fallback), 2: no bin memory */
    int no_wait_hook;
    int spi16;         /* 1: the HAL sends pixels in 16-bit SPI frames (FXL_PORT_PIXELS_16BIT) */
    int late;          /* 1: transfers complete from a 2 ms SIGALRM tick (late_pixels) */
} run_cfg_t;

typedef struct run_out {
    uint16_t *image;   /* w x h native RGB565 as the viewer sees it */
    int w, h;
    fxl_stats_t stats;
    fxl_status_t status;
    int overflowed;
    int protocol_errors;
    unsigned long transfers, waits;
    uint32_t bin_used;
    uint32_t wire_crc; /* every byte the panel received, commands included */
    char first_error[160];
} run_out_t;

void setUp(void)
{
    int x, y;
    for (y = 0; y < 16; y++)
        for (x = 0; x < 16; x++)
            texels[y * 16 + x] = ((x ^ y) & 2) ? FXL_RGB565(250, 200, 40) : FXL_RGB565(30, 60, 200);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_texture_init(&tex, texels, 16, 16, FXL_TEXFMT_RGB565, 1));
    fxl_draw_defaults(&d_tex);
    d_tex.texture = &tex;
    d_tex.filter = FXL_HAVE_BILINEAR ? FXL_FILTER_BILINEAR : FXL_FILTER_POINT;
    fxl_draw_defaults(&d_flat_red);
    d_flat_red.color = FXL_RGB565(255, 0, 0);
    flat(&d_flat_red, 0);
    fxl_draw_defaults(&d_flat_green);
    d_flat_green.color = FXL_RGB565(0, 255, 0);
    flat(&d_flat_green, 1);
    fxl_draw_defaults(&d_flat_blue);
    d_flat_blue.color = FXL_RGB565(0, 0, 255);
    flat(&d_flat_blue, 2);
    d_flat_blue.depth = 0; /* no depth test: pure painter's order */
    fxl_draw_defaults(&d_bad);
    d_bad.persp = 3; /* not a power of two: the core refuses it */
}

/* the late-completion tick (render_banded, cfg->late): its emulator, and
 * the stop that tearDown calls after a failed assertion */
static panel_emu_t *late_emu;
static void late_stop(void);

void tearDown(void)
{
    if (late_emu != NULL)
        late_stop();
}

/* Fraction of the frame size in q16, so one scene fits every panel. */
static fxl_q16_t fx(int w, int num, int den)
{
    return (fxl_q16_t)(((int64_t)w * num * 65536) / den);
}

static void tri(scene_t *s, const fxl_draw_t *d, fxl_q16_t x0, fxl_q16_t y0, uint32_t w0,
                fxl_q16_t x1, fxl_q16_t y1, uint32_t w1, fxl_q16_t x2, fxl_q16_t y2, uint32_t w2)
{
    fxl_vertex_t *v = s->v[s->count];
    TEST_ASSERT_TRUE(s->count < MAX_TRIS);
    memset(v, 0, sizeof(fxl_vertex_t) * 3);
    v[0].x = x0; v[0].y = y0; v[0].inv_w = w0; v[0].u = 0;          v[0].v = 0;
    v[1].x = x1; v[1].y = y1; v[1].inv_w = w1; v[1].u = 3 * 65536;  v[1].v = 0;
    v[2].x = x2; v[2].y = y2; v[2].inv_w = w2; v[2].u = 0;          v[2].v = 3 * 65536;
    v[0].color = v[1].color = v[2].color = 0xFFFF;
    s->draw[s->count] = d;
    s->count++;
}

/* A few overlapping triangles crossing band boundaries: a perspective
 * textured quad, depth-tested flat triangles in front of and behind it, an
 * exact depth tie (two identical triangles, the first must win), painter's
 * order without depth, triangles sticking out of the frame on every side,
 * one entirely above the frame and a thin sliver. */
static void build_scene(scene_t *s, int w, int h)
{
    const uint32_t far = 0x20000000u, mid = 0x40000000u, near = 0x80000000u;
    memset(s, 0, sizeof(*s));
    /* Receding textured quad: near at the bottom, far at the top. */
    tri(s, &d_tex, fx(w, 1, 10), fx(h, 9, 10), near, fx(w, 9, 10), fx(h, 9, 10), near,
        fx(w, 3, 10), fx(h, 2, 10), far);
    tri(s, &d_tex, fx(w, 9, 10), fx(h, 9, 10), near, fx(w, 7, 10), fx(h, 2, 10), far,
        fx(w, 3, 10), fx(h, 2, 10), far);
    /* Red in front of part of the quad, green behind it. */
    tri(s, &d_flat_red, fx(w, 1, 20), fx(h, 1, 3), near + 0x1000000u, fx(w, 1, 2), fx(h, 1, 2),
        near + 0x1000000u, fx(w, 1, 5), fx(h, 7, 8), near + 0x1000000u);
    tri(s, &d_flat_green, fx(w, 1, 2), fx(h, 1, 10), far / 2, fx(w, 19, 20), fx(h, 3, 10), far / 2,
        fx(w, 3, 5), fx(h, 19, 20), far / 2);
    /* Depth tie: identical vertices and depth, red first then green; the
     * depth test is strict (greater), so red must stay. */
    tri(s, &d_flat_red, fx(w, 3, 4), fx(h, 1, 20), mid, fx(w, 19, 20), fx(h, 1, 20), mid,
        fx(w, 17, 20), fx(h, 2, 5), mid);
    tri(s, &d_flat_green, fx(w, 3, 4), fx(h, 1, 20), mid, fx(w, 19, 20), fx(h, 1, 20), mid,
        fx(w, 17, 20), fx(h, 2, 5), mid);
    /* Painter's order without depth test, over everything. */
    tri(s, &d_flat_blue, fx(w, 2, 5), fx(h, 2, 5), far, fx(w, 3, 5), fx(h, 9, 20), far,
        fx(w, 9, 20), fx(h, 3, 5), far);
    /* Out of the frame: above/left, below/right, entirely above, off right. */
    tri(s, &d_flat_green, -fx(w, 1, 5), -fx(h, 1, 5), near, fx(w, 1, 4), -fx(h, 1, 10), near,
        fx(w, 1, 10), fx(h, 1, 6), near);
    tri(s, &d_tex, fx(w, 4, 5), fx(h, 4, 5), mid, fx(w, 6, 5), fx(h, 9, 10), mid, fx(w, 9, 10),
        fx(h, 6, 5), mid);
    tri(s, &d_flat_red, 0, -fx(h, 1, 2), near, fx(w, 1, 2), -fx(h, 1, 2), near, 0, -fx(h, 1, 4), near);
    tri(s, &d_flat_red, fx(w, 6, 5), 0, near, fx(w, 7, 5), 0, near, fx(w, 6, 5), fx(h, 1, 1), near);
    /* A sliver from top to bottom, 1/4 pixel wide at the base. */
    tri(s, &d_flat_red, fx(w, 1, 3), 0, near, fx(w, 1, 3) + 16384, fx(h, 1, 1), near, fx(w, 1, 3),
        fx(h, 1, 1), near);
}

static void render_full(const scene_t *s, int w, int h, uint16_t *out, fxl_stats_t *stats)
{
    uint16_t *depth = (uint16_t *)malloc((size_t)w * (size_t)h * 2u);
    fxl_target_t t;
    int i;
    TEST_ASSERT_NOT_NULL(depth);
    memset(stats, 0, sizeof(*stats));
    /* native pixels, drawn in the byte order this build draws */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_init(&t, out, w, h, w, drawable_rgb565()));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_set_depth(&t, DEPTH_BUF(depth)));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear(&t, CLEAR_COLOR));
    if (FXL_HAVE_DEPTH)
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_target_clear_depth(&t));
    for (i = 0; i < s->count; i++) TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_draw_triangle(&t, s->draw[i], s->v[i], stats));
    pixels_to_native(out, (size_t)w * (size_t)h, t.format);
    free(depth);
}

/* The format the band renderer draws in for a HAL sending bytes (spi16 0)
 * or 16-bit frames (fxl_panel_pixel_format). */
static fxl_pixfmt_t band_format(int spi16)
{
    return spi16 ? FXL_PIXFMT_RGB565 : fxl_port_wire_format();
}

/* The feature the scenes' draw states need and this build left out, into
 * bands of format band_fmt or into the full frame (in drawable_rgb565's
 * order), each with depth where the build has it; NULL when none. */
static const char *band_draws_missing(fxl_pixfmt_t band_fmt)
{
    const fxl_draw_t *const draws[4] = {&d_tex, &d_flat_red, &d_flat_green, &d_flat_blue};
    const char *m = NULL;
    int i;
    for (i = 0; i < 4 && m == NULL; i++) {
        m = left_out_feature(draws[i], draws[i]->texture, band_fmt, FXL_HAVE_DEPTH);
        if (m == NULL)
            m = left_out_feature(draws[i], draws[i]->texture, drawable_rgb565(), FXL_HAVE_DEPTH);
    }
    return m;
}

/* The band tests need both (left_out.h), else they report IGNORE. */
static void need_band_draws_in(fxl_pixfmt_t band_fmt)
{
    test_needs_draw(band_draws_missing(band_fmt));
}

/* The emulated HAL sends bytes, unless this build cannot draw the bands
 * for it (native walks only, FXL_FAST_SWAPPED 0): then the tests run as
 * such a firmware would, with FXL_PORT_PIXELS_16BIT (panel_spi16 in
 * left_out.h, the rule panel_emu_render_scene follows too). */
static void need_band_draws(void)
{
    need_band_draws_in(band_format(panel_spi16()));
}

/* Late completions (cfg->late), as a DMA interrupt gives them: the
 * emulator's clock never completes a transfer (dma_delay huge); a periodic
 * 2 ms timer, started by the first pixels(), completes the one in flight
 * from SIGALRM while the thread side draws (~25-60 us a band here) or
 * waits. A tick never gets lost, so a driver that waits cannot hang here.
 * SIGALRM is blocked inside cmd() and pixels(), so it never lands in the
 * emulator's own bookkeeping: a driver that called them with a transfer in
 * flight shows as a protocol error. (With 16-bit SPI frames complete()
 * allocates: the thread side allocates nothing while the timer runs.) */
static fxl_port_hal_t late_inner;
static volatile sig_atomic_t late_fired, late_armed;
static int late_timer_errors;

static void late_complete(int sig)
{
    (void)sig;
    if (late_emu != NULL && late_emu->in_flight) {
        late_fired++;
        panel_emu_flush(late_emu);
    }
}

/* Stops the tick and puts SIGALRM's default back (tearDown too: a failed
 * assertion skips the test's own cleanup). */
static void late_stop(void)
{
    struct itimerval off;
    memset(&off, 0, sizeof(off));
    if (setitimer(ITIMER_REAL, &off, NULL) != 0) late_timer_errors++;
    late_armed = 0;
    late_emu = NULL;
    signal(SIGALRM, SIG_DFL);
}

static void late_block(int how)
{
    sigset_t set;
    sigemptyset(&set);
    sigaddset(&set, SIGALRM);
    if (sigprocmask(how, &set, NULL) != 0) late_timer_errors++;
}

static fxl_status_t late_cmd(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    fxl_status_t st;
    late_block(SIG_BLOCK);
    st = late_inner.cmd(user, cmd, params, n);
    late_block(SIG_UNBLOCK);
    return st;
}

static fxl_status_t late_pixels(void *user, const void *data, size_t bytes)
{
    fxl_status_t st;
    late_block(SIG_BLOCK);
    st = late_inner.pixels(user, data, bytes);
    if (!late_armed) {
        struct itimerval it;
        memset(&it, 0, sizeof(it));
        it.it_value.tv_usec = 2000;
        it.it_interval.tv_usec = 2000;
        if (setitimer(ITIMER_REAL, &it, NULL) != 0) late_timer_errors++;
        late_armed = 1;
    }
    late_block(SIG_UNBLOCK);
    return st;
}

/* Render through init -> band renderer -> emulated panel. Only asserts on
 * setup; the caller checks status and the image. */
static void render_banded(const scene_t *s, const run_cfg_t *cfg, run_out_t *o)
{
    panel_emu_t emu;
    fxl_port_hal_t hal;
    fxl_panel_t panel;
    fxl_band_t band;
    fxl_band_tri_t store[MAX_TRIS];
    fxl_band_bin_t *bins = NULL;
    uint32_t bin_cap = 0;
    uint16_t *buf0, *buf1, *depth;
    int i, bands;

    memset(o, 0, sizeof(*o));
    TEST_ASSERT_EQUAL_INT(0, panel_emu_init(&emu, panel_emu_module_find(cfg->panel), 0));
    emu.panel = &panel;
    emu.dma_delay = cfg->dma_delay;
    emu.spi16 = cfg->spi16 || panel_spi16();
    panel_emu_hal(&emu, &hal);
    if (cfg->no_wait_hook) hal.wait = NULL;
    if (cfg->late) {
        late_emu = &emu;
        late_inner = hal;
        late_fired = 0;
        late_armed = 0;
        late_timer_errors = 0;
        hal.cmd = late_cmd;
        hal.pixels = late_pixels;
        emu.dma_delay = 1 << 30;
    }
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&panel, &hal, panel_emu_preset_find(cfg->panel),
                                                 (unsigned)cfg->rotation));
    o->w = panel.width;
    o->h = panel.height;
    bands = (o->h + cfg->band_rows - 1) / cfg->band_rows;
    if (cfg->bins == 0) bin_cap = (uint32_t)bands * (1u + MAX_TRIS);
    if (cfg->bins == 1) bin_cap = (uint32_t)bands + 5u;
    if (bin_cap > 0) {
        bins = (fxl_band_bin_t *)malloc(bin_cap * sizeof(*bins));
        TEST_ASSERT_NOT_NULL(bins);
    }
    buf0 = (uint16_t *)malloc((size_t)o->w * (size_t)cfg->band_rows * 2u);
    buf1 = (uint16_t *)malloc((size_t)o->w * (size_t)cfg->band_rows * 2u);
    depth = (uint16_t *)malloc((size_t)o->w * (size_t)cfg->band_rows * 2u);
    o->image = (uint16_t *)malloc((size_t)o->w * (size_t)o->h * 2u);
    TEST_ASSERT_TRUE(buf0 && buf1 && depth && o->image);

    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&band, &panel, buf0, buf1, DEPTH_BUF(depth), cfg->band_rows,
                                                store, MAX_TRIS, bins, bin_cap));
    for (i = 0; i < s->count; i++)
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&band, s->v[i], s->draw[i]));
    o->status = fxl_band_render(&band, CLEAR_COLOR, &o->stats);
    if (cfg->late)
        late_stop();   /* no tick may reach the emulator once it is freed below */
    o->overflowed = fxl_band_overflowed(&band);
    o->bin_used = band.bin_used;
    TEST_ASSERT_EQUAL_INT(0, panel_emu_view(&emu, cfg->rotation, o->image, NULL, NULL));
    o->protocol_errors = emu.errors;
    memcpy(o->first_error, emu.first_error, sizeof(o->first_error));
    o->transfers = emu.transfers;
    o->waits = emu.waits;
    o->wire_crc = emu.crc;
    panel_emu_free(&emu);
    free(bins);
    free(buf0);
    free(buf1);
    free(depth);
}

/* Banded == full frame, pixel by pixel and by CRC; returns the banded run. */
static void check_identical(const run_cfg_t *cfg, run_out_t *o)
{
    scene_t s;
    fxl_stats_t full_stats;
    uint16_t *full;
    int w, h, x, y;
    need_band_draws_in(band_format(cfg->spi16 || panel_spi16()));
    TEST_ASSERT_EQUAL_INT(0, panel_emu_frame_size(cfg->panel, cfg->rotation, &w, &h));
    build_scene(&s, w, h);
    full = (uint16_t *)malloc((size_t)w * (size_t)h * 2u);
    TEST_ASSERT_NOT_NULL(full);
    render_full(&s, w, h, full, &full_stats);
    render_banded(&s, cfg, o);
    TEST_ASSERT_EQUAL_INT(FXL_OK, o->status);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, o->protocol_errors, o->first_error);
    TEST_ASSERT_EQUAL_INT(w, o->w);
    TEST_ASSERT_EQUAL_INT(h, o->h);
    for (y = 0; y < h; y++) {
        for (x = 0; x < w; x++) {
            uint16_t a = full[(size_t)y * (size_t)w + (size_t)x], b = o->image[(size_t)y * (size_t)w + (size_t)x];
            if (a != b) {
                snprintf(msg, sizeof(msg), "%s rot %d rows %d: pixel (%d, %d) banded 0x%04X, full frame 0x%04X",
                         cfg->panel, cfg->rotation, cfg->band_rows, x, y, b, a);
                free(full);
                free(o->image);
                TEST_FAIL_MESSAGE(msg);
            }
        }
    }
    TEST_ASSERT_EQUAL_HEX32(crc32_update(0, full, (size_t)w * (size_t)h * 2u),
                            crc32_update(0, o->image, (size_t)w * (size_t)h * 2u));
    /* Every covered pixel is written exactly once per frame either way. */
    TEST_ASSERT_EQUAL_UINT32(full_stats.pixels, o->stats.pixels);
    free(full);
    free(o->image);
    o->image = NULL;
}

/* ---- identical images ------------------------------------------------------ */

void test_banded_frame_equals_full_frame_render(void)
{
    run_cfg_t cfg = { "st7789", 1, 24, 2, 0, 0, 0, 0 };
    run_out_t o;
    check_identical(&cfg, &o);
    /* 320x240 in 24-row bands: 10 transfers, no fallback. */
    TEST_ASSERT_EQUAL_UINT32(10, (uint32_t)o.transfers);
    TEST_ASSERT_FALSE(o.overflowed);
    /* The scene really draws: several thousand pixels (the quad alone
     * covers about 0.6 * 0.7 / 2 * 2 of 76800 px minus overlaps). */
    TEST_ASSERT_GREATER_THAN(10000, (int)o.stats.pixels);
}

void test_banded_frame_equals_full_frame_for_any_band_height(void)
{
    /* 1 row (240 bands), 7 (a short last band: 240 = 34 * 7 + 2), 24, 240. */
    static const int rows[] = { 1, 7, 24, 240 };
    size_t i;
    for (i = 0; i < sizeof(rows) / sizeof(rows[0]); i++) {
        run_cfg_t cfg = { "st7789", 1, 24, 1, 0, 0, 0, 0 };
        run_out_t o;
        cfg.band_rows = rows[i];
        check_identical(&cfg, &o);
        TEST_ASSERT_EQUAL_UINT32((uint32_t)((240 + rows[i] - 1) / rows[i]), (uint32_t)o.transfers);
    }
}

void test_banded_frame_equals_full_frame_every_preset_and_rotation(void)
{
    static const char *const names[] = { "st7789-240x320", "st7789-240x240", "st7789-135x240",
                                         "ili9341-240x320" };
    size_t i;
    int r;
    for (i = 0; i < sizeof(names) / sizeof(names[0]); i++) {
        for (r = 0; r < 4; r++) {
            run_cfg_t cfg = { NULL, 0, 16, 2, 0, 0, 0, 0 };
            run_out_t o;
            cfg.panel = names[i];
            cfg.rotation = r;
            check_identical(&cfg, &o);
        }
    }
}

/* A HAL that sends pixels in 16-bit SPI frames (FXL_PORT_PIXELS_16BIT): the
 * band renderer draws native RGB565 bands, and the panel receives the same
 * bytes as from a byte-stream HAL with byte-swapped bands. Each mode needs
 * its walks: a build with native walks only (an SPI peripheral in 16-bit
 * mode) checks the 16-bit mode alone, a build with swapped walks only the
 * byte mode; the wire bytes are compared where both draw. */
void test_spi16_frames_draw_native_bands_and_send_the_same_bytes(void)
{
    static const run_cfg_t cfgs[] = { { "st7789", 1, 24, 2, 0, 0, 0, 0 }, { "ili9341", 2, 7, 0, 1, 1, 0, 0 } };
    size_t i;
    int checked = 0;
    for (i = 0; i < sizeof(cfgs) / sizeof(cfgs[0]); i++) {
        const int have_bytes = band_draws_missing(band_format(0)) == NULL;
        const int have_16 = band_draws_missing(band_format(1)) == NULL;
        run_cfg_t cfg = cfgs[i];
        run_out_t bytes, words;
        if (have_16) {
            cfg.spi16 = 1;
            check_identical(&cfg, &words);
            checked++;
        }
        if (have_bytes) {
            cfg.spi16 = 0;
            check_identical(&cfg, &bytes);
            checked++;
        }
        if (have_16 && have_bytes) {
            TEST_ASSERT_EQUAL_HEX32(bytes.wire_crc, words.wire_crc);
            TEST_ASSERT_EQUAL_UINT32((uint32_t)bytes.transfers, (uint32_t)words.transfers);
        }
    }
    if (checked == 0)
        need_band_draws_in(band_format(1));
    if (band_draws_missing(band_format(1)) != NULL)
        TEST_MESSAGE("16-bit frames not checked: this build cannot draw native bands");
    if (band_draws_missing(band_format(0)) != NULL)
        TEST_MESSAGE("byte stream not checked: this build cannot draw byte-swapped bands");
}

void test_panel_pixel_format_follows_the_hal_flags(void)
{
    fxl_panel_t panel;
    memset(&panel, 0, sizeof(panel));
    TEST_ASSERT_EQUAL_INT(fxl_port_wire_format(), fxl_panel_pixel_format(NULL));
    TEST_ASSERT_EQUAL_INT(fxl_port_wire_format(), fxl_panel_pixel_format(&panel));
    panel.hal.flags = FXL_PORT_PIXELS_SYNC;
    TEST_ASSERT_EQUAL_INT(fxl_port_wire_format(), fxl_panel_pixel_format(&panel));
    panel.hal.flags = FXL_PORT_PIXELS_16BIT | FXL_PORT_PIXELS_SYNC;
    TEST_ASSERT_EQUAL_INT(FXL_PIXFMT_RGB565, fxl_panel_pixel_format(&panel));
}

void test_late_dma_completion_never_lets_a_buffer_be_reused_early(void)
{
    /* Completions arrive 0 (inside pixels()), 1, 5 and 50 HAL calls late.
     * The mock compares each buffer at completion with its content when
     * sent, so drawing into it early would be a protocol error, and the
     * image would differ. With a delay d, every transfer needs d ticks, all
     * spent in the wait hook: waits == d * transfers exactly. */
    static const int delays[] = { 0, 1, 5, 50 };
    size_t i;
    for (i = 0; i < sizeof(delays) / sizeof(delays[0]); i++) {
        run_cfg_t cfg = { "st7789", 1, 24, 0, 0, 0, 0, 0 };
        run_out_t o;
        cfg.dma_delay = delays[i];
        check_identical(&cfg, &o);
        TEST_ASSERT_EQUAL_UINT32((uint32_t)(delays[i] * 10), (uint32_t)o.waits);
    }
}

void test_without_wait_hook_the_driver_spins_on_the_completion_counter(void)
{
    /* Every transfer completes up to 2 ms late, from a signal, and there is
     * no hook: the driver must spin on panel->done before it touches the
     * bus or a buffer again. A band path that did not wait would call cmd()
     * or pixels() under a running transfer (a protocol error) or redraw a
     * buffer still being sent (a different image). */
    run_cfg_t cfg = { "ili9341", 0, 32, 0, 0, 1, 0, 1 };
    run_out_t o;
    struct sigaction sa;
    memset(&sa, 0, sizeof(sa));
    sa.sa_handler = late_complete;
    sigemptyset(&sa.sa_mask);
    TEST_ASSERT_EQUAL_INT(0, sigaction(SIGALRM, &sa, NULL));
    check_identical(&cfg, &o);   /* render_banded stopped the tick (late_stop) */
    TEST_ASSERT_EQUAL_INT(0, late_timer_errors);
    /* 320 rows in bands of 32: ten transfers, each completed by the tick */
    TEST_ASSERT_EQUAL_UINT32(10, (uint32_t)o.transfers);
    TEST_ASSERT_EQUAL_INT(10, (int)late_fired);
}

void test_bin_budget_exceeded_falls_back_with_identical_image(void)
{
    run_cfg_t cfg = { "st7789", 1, 24, 2, 1, 0, 0, 0 };
    run_out_t o;
    check_identical(&cfg, &o);
    TEST_ASSERT_TRUE(o.overflowed);
}

void test_no_bin_memory_scans_every_triangle_with_identical_image(void)
{
    run_cfg_t cfg = { "st7789", 3, 24, 2, 2, 0, 0, 0 };
    run_out_t o;
    check_identical(&cfg, &o);
    TEST_ASSERT_TRUE(o.overflowed);
}

/* ---- binning --------------------------------------------------------------- */

typedef struct band_fixture {
    panel_emu_t emu;
    fxl_port_hal_t hal;
    fxl_panel_t panel;
    fxl_band_t band;
    fxl_band_tri_t store[4];
    fxl_band_bin_t bins[64];
    uint16_t buf0[320 * 24], buf1[320 * 24], depth[320 * 24];
} band_fixture_t;

static band_fixture_t *fixture(void)
{
    band_fixture_t *f = (band_fixture_t *)calloc(1, sizeof(band_fixture_t));
    TEST_ASSERT_NOT_NULL(f);
    TEST_ASSERT_EQUAL_INT(0, panel_emu_init(&f->emu, panel_emu_module_find("st7789"), 0));
    f->emu.panel = &f->panel;
    f->emu.spi16 = panel_spi16();
    panel_emu_hal(&f->emu, &f->hal);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&f->panel, &f->hal, &fxl_st7789_240x320, 1));
    return f;
}

static void fixture_free(band_fixture_t *f)
{
    panel_emu_free(&f->emu);
    free(f);
}

static void flat_tri(fxl_vertex_t v[3], int y0, int y1)
{
    memset(v, 0, sizeof(fxl_vertex_t) * 3);
    v[0].x = FXL_Q16_INT(10); v[0].y = FXL_Q16_INT(y0);
    v[1].x = FXL_Q16_INT(50); v[1].y = FXL_Q16_INT(y0);
    v[2].x = FXL_Q16_INT(30); v[2].y = FXL_Q16_INT(y1);
    v[0].inv_w = v[1].inv_w = v[2].inv_w = 0x40000000u;
}

void test_triangle_is_listed_once_in_each_band_it_touches(void)
{
    band_fixture_t *f = fixture();
    fxl_vertex_t v[3];
    fxl_draw_t d;
    fxl_draw_defaults(&d);
    flat(&d, 3);
    need_band_draws();   /* fxl_band_add checks the draw in the panel's format */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, DEPTH_BUF(f->depth), 24,
                                                f->store, 4, f->bins, 64));
    /* 10 bands of 24 rows use 10 list headers. */
    TEST_ASSERT_EQUAL_UINT32(10, f->band.bin_used);
    /* y 10..50: rows 9..50 with the half-step margin -> bands 0..2. */
    flat_tri(v, 10, 50);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_UINT32(13, f->band.bin_used);
    TEST_ASSERT_EQUAL_UINT32(0, f->store[0].band0);
    TEST_ASSERT_EQUAL_UINT32(2, f->store[0].band1);
    /* y 100..119.5 stays inside band 4 (rows 96..119). */
    flat_tri(v, 100, 119);
    v[2].y += FXL_Q16_HALF;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_UINT32(14, f->band.bin_used);
    TEST_ASSERT_EQUAL_UINT32(4, f->store[1].band0);
    TEST_ASSERT_EQUAL_UINT32(4, f->store[1].band1);
    /* Entirely above or below the frame: dropped, nothing stored. */
    flat_tri(v, -40, -2);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    flat_tri(v, 241, 300);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_UINT32(2, f->band.tri_count);
    TEST_ASSERT_FALSE(fxl_band_overflowed(&f->band));
    /* A new frame forgets the scene. */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_begin(&f->band));
    TEST_ASSERT_EQUAL_UINT32(0, f->band.tri_count);
    TEST_ASSERT_EQUAL_UINT32(10, f->band.bin_used);
    fixture_free(f);
}

/* A fixture with 24-row bands (10 on the rotated 240x320 panel), a
 * store of 4 triangles and bin_cap bin entries, and a flat draw in d. */
static band_fixture_t *binning_fixture(fxl_draw_t *d, uint32_t bin_cap)
{
    band_fixture_t *f;
    need_band_draws();   /* fxl_band_add checks the draw in the panel's format */
    f = fixture();
    fxl_draw_defaults(d);
    flat(d, 3);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, DEPTH_BUF(f->depth), 24,
                                                f->store, 4, f->bins, bin_cap));
    return f;
}

void test_triangle_that_does_not_fit_the_bins_starts_the_fallback(void)
{
    fxl_vertex_t v[3];
    fxl_draw_t d;
    /* 10 headers + 4 entries: a 3-band triangle fits, the next 3-band one
     * does not, and a later 1-band one must not be binned either (order). */
    band_fixture_t *f = binning_fixture(&d, 14);
    flat_tri(v, 10, 50);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_FALSE(fxl_band_overflowed(&f->band));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_TRUE(fxl_band_overflowed(&f->band));
    flat_tri(v, 100, 110);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_UINT32(13, f->band.bin_used);
    TEST_ASSERT_EQUAL_UINT32(1, f->band.first_unbinned);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_render(&f->band, 0, NULL));
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, f->emu.errors, f->emu.first_error);
    fixture_free(f);
}

/* The edges of binning: a triangle whose only covered row is row 0 is
 * kept (band 0), and bins exactly large enough for a scene do not
 * overflow. */
void test_binning_edges_row_zero_and_bins_exactly_full(void)
{
    fxl_vertex_t v[3];
    fxl_draw_t d;
    /* 10 headers + 3 entries: one 3-band triangle fills them exactly */
    band_fixture_t *f = binning_fixture(&d, 13);
    flat_tri(v, 10, 50);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_UINT32(13, f->band.bin_used);
    TEST_ASSERT_FALSE(fxl_band_overflowed(&f->band));
    /* y from -10 to 0.6: row 0's centre (0.5) is inside */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_begin(&f->band));
    flat_tri(v, -10, 0);
    v[1].y = v[2].y = FXL_Q16_INT(0) + (fxl_q16_t)(0.6 * 65536);
    v[0].y = FXL_Q16_INT(-10);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_UINT32(1, f->band.tri_count);
    TEST_ASSERT_EQUAL_UINT32(0, f->store[0].band0);
    TEST_ASSERT_EQUAL_UINT32(0, f->store[0].band1);
    fixture_free(f);
}

/* Without bin memory each triangle is "tested against each band by its
 * stored band range" (port.h), so the core sees it once per band it
 * touches, exactly as with bins: y 10..50 touches bands 0..2 (rows 0..71)
 * and y 100..110 band 4 (rows 96..119), 3 + 1 = 4 submitted triangles,
 * none culled as outside (each band holds rows of the triangle). Drawing
 * one into a band outside its range would count it again, culled. */
void test_fallback_draws_a_triangle_only_in_the_bands_it_touches(void)
{
    int mode;
    for (mode = 0; mode < 2; mode++) {
        fxl_vertex_t v[3];
        fxl_draw_t d;
        fxl_stats_t st;
        /* mode 0: no bin memory (fallback from the start); 1: room for all */
        band_fixture_t *f = binning_fixture(&d, mode ? 64u : 0u);
        flat_tri(v, 10, 50);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
        flat_tri(v, 100, 110);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
        TEST_ASSERT_EQUAL_INT(!mode, fxl_band_overflowed(&f->band));
        memset(&st, 0, sizeof st);
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_render(&f->band, 0, &st));
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(4, st.triangles, mode ? "binned" : "fallback");
        TEST_ASSERT_EQUAL_UINT32_MESSAGE(0, st.culled_outside, mode ? "binned" : "fallback");
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, f->emu.errors, f->emu.first_error);
        fixture_free(f);
    }
}

/* A triangle ending less than a pixel above the frame covers no row (row
 * 0's centre is at 0.5) and must be dropped like one far above it: its
 * rows floor(ymax + h) = floor(-0.47) = -1 (band.c floor_px). Division
 * that truncates toward zero gives 0 there and lists it in band 0, taking
 * a store slot for nothing. */
void test_triangle_ending_just_above_the_frame_is_dropped(void)
{
    fxl_vertex_t v[3];
    fxl_draw_t d;
    band_fixture_t *f = binning_fixture(&d, 14);
    flat_tri(v, -10, 0);
    v[0].y = FXL_Q16_INT(-10);
    v[1].y = v[2].y = -FXL_Q16_HALF;   /* y = -0.5 */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_UINT32(0, f->band.tri_count);
    TEST_ASSERT_EQUAL_UINT32(10, f->band.bin_used);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_render(&f->band, 0, NULL));
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, f->emu.errors, f->emu.first_error);
    fixture_free(f);
}

/* ---- error paths ----------------------------------------------------------- */

void test_band_api_errors(void)
{
    band_fixture_t *f = fixture();
    fxl_vertex_t v[3];
    fxl_draw_t d;
    fxl_draw_defaults(&d);
    flat(&d, 3);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(NULL, &f->panel, f->buf0, f->buf1, NULL, 24, f->store, 4, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, NULL, f->buf0, f->buf1, NULL, 24, f->store, 4, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, NULL, f->buf1, NULL, 24, f->store, 4, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf0, NULL, 24, f->store, 4, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 0, f->store, 4, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 24, NULL, 4, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 24, f->store, 0, NULL, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 24, f->store, 4, NULL, 5));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 241, f->store, 4, NULL, 0));
    /* Fewer entries than the 10 band headers. */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_NOMEM, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 24, f->store, 4, f->bins, 9));
    /* Buffers carved from one array must not share a byte: 12-row bands
     * (320 x 12 pixels) fit twice in buf0; one pixel less apart, or a depth
     * band on a colour band, or bins on the triangle store, is refused
     * (FXL_ERR_ARG before the depth band's FXL_HAVE_DEPTH check). */
    {
        uint16_t *const half = f->buf0 + 320 * 12;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, half, NULL, 12, f->store, 4, f->bins, 64));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, half - 1, f->depth, 12, f->store, 4, f->bins, 64));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, half - 1, f->buf0, f->depth, 12, f->store, 4, f->bins, 64));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, f->buf1, 24, f->store, 4, NULL, 0));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, half - 2, 12, f->store, 4, NULL, 0));
        TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, f->depth, 24, f->store, 4,
                                                         (fxl_band_bin_t *)(void *)&f->store[3], 64));
        /* the store's four entries end where bins begin: apart */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 24, f->store, 3,
                                                    (fxl_band_bin_t *)(void *)&f->store[3], 10));
    }
    /* A frame taller than a target's origin reaches is refused at init,
     * not mid-frame with part of it sent, and a failed init leaves the
     * binding it replaces as it was (panel fields set by hand: no preset
     * is that tall). */
    {
        fxl_band_t before;
        const int32_t w = f->panel.width, h = f->panel.height;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 24, f->store, 4, NULL, 0));
        memcpy(&before, &f->band, sizeof before);
        TEST_ASSERT_EQUAL_INT(FXL_ERR_NOMEM, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 24, f->store, 4, f->bins, 9));
        TEST_ASSERT_EQUAL_MEMORY(&before, &f->band, sizeof before);
        f->panel.width = 16;
        f->panel.height = FXL_TARGET_MAX_ORIGIN + 17;   /* last 16-row band at y0 = 16400 */
        TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 16, f->store, 4, NULL, 0));
        TEST_ASSERT_EQUAL_MEMORY(&before, &f->band, sizeof before);
        f->panel.height = FXL_TARGET_MAX_ORIGIN + 16;   /* last band at y0 = 16384 */
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 16, f->store, 4, NULL, 0));
        TEST_ASSERT_EQUAL_INT(1025, f->band.band_count);
        f->panel.width = w;
        f->panel.height = h;
    }

    need_band_draws();   /* the rest adds draws in the panel's format */
    /* a depth band in a build without depth: refused at init, not mid-frame */
    TEST_ASSERT_EQUAL_INT(FXL_HAVE_DEPTH ? FXL_OK : FXL_ERR_UNSUPPORTED,
                          fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, f->depth, 24, f->store, 2, f->bins, 64));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, DEPTH_BUF(f->depth), 24,
                                                f->store, 2, f->bins, 64));
    flat_tri(v, 10, 50);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_add(&f->band, NULL, &d));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_add(&f->band, v, NULL));
    v[1].inv_w = 0;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_band_add(&f->band, v, &d));
    v[1].inv_w = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_NOMEM, fxl_band_add(&f->band, v, &d)); /* store of 2 is full */
    TEST_ASSERT_EQUAL_UINT32(2, f->band.tri_count);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_render(NULL, 0, NULL));
    /* Rotating the panel after init changes the frame: re-init needed. */
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_set_rotation(&f->panel, 0));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_render(&f->band, 0, NULL));
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, f->emu.errors, f->emu.first_error);
    fixture_free(f);
}

void test_bad_draw_is_refused_when_added_before_anything_is_sent(void)
{
    /* Settings the core refuses for every band (persp 3) are refused by
     * fxl_band_add with the core's status, the triangle not stored, also
     * one entirely off the frame (the core refuses before culling too). */
    band_fixture_t *f = fixture();
    fxl_vertex_t v[3];
    fxl_draw_t d;
    fxl_draw_defaults(&d);
    flat(&d, 3);
    need_band_draws();
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, DEPTH_BUF(f->depth), 24,
                                                f->store, 4, f->bins, 64));
    flat_tri(v, 10, 50);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_band_add(&f->band, v, &d_bad));
    TEST_ASSERT_EQUAL_UINT32(0, f->band.tri_count);
    flat_tri(v, -900, -800);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_band_add(&f->band, v, &d_bad));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));   /* off the frame: dropped */
    TEST_ASSERT_EQUAL_UINT32(0, f->band.tri_count);
    flat_tri(v, 10, 50);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));      /* found valid once */
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_band_add(&f->band, v, &d_bad));
    TEST_ASSERT_EQUAL_UINT32(2, f->band.tri_count);
    TEST_ASSERT_EQUAL_UINT32(0, (uint32_t)f->emu.transfers);
    fixture_free(f);
}

void test_draw_error_is_returned_after_the_whole_frame_was_sent(void)
{
    /* A draw changed after it was added into one the core refuses (persp
     * 3) must not leave the panel mid-RAMWR: every band is still sent,
     * then the error is returned. */
    band_fixture_t *f = fixture();
    fxl_vertex_t v[3];
    fxl_draw_t d, later;
    fxl_draw_defaults(&d);
    flat(&d, 3);
    need_band_draws();
    later = d;
    f->emu.dma_delay = 2;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, DEPTH_BUF(f->depth), 24,
                                                f->store, 4, f->bins, 64));
    flat_tri(v, 10, 50);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &later));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &d));
    later.persp = d_bad.persp;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_band_render(&f->band, 0, NULL));
    TEST_ASSERT_EQUAL_UINT32(10, (uint32_t)f->emu.transfers);
    TEST_ASSERT_EQUAL_UINT32(f->panel.started, f->panel.done);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, f->emu.errors, f->emu.first_error);
    fixture_free(f);
}

/* "The first draw error is returned" (port.h): two draws changed after
 * they were added, the first (persp 3) to one the core refuses with
 * FXL_ERR_RANGE, the second (an unknown shade) with FXL_ERR_ARG, both in
 * bands 0..2. Band 0 draws them in submission order, so the frame's first
 * error is the first draw's FXL_ERR_RANGE, not the ARG that comes after it
 * in every band; all 10 bands are still sent. */
void test_first_of_several_draw_errors_is_returned(void)
{
    band_fixture_t *f = fixture();
    fxl_vertex_t v[3];
    fxl_draw_t d, first, second;
    fxl_draw_defaults(&d);
    flat(&d, 3);
    need_band_draws();
    first = d;
    second = d;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, DEPTH_BUF(f->depth), 24,
                                                f->store, 4, f->bins, 64));
    flat_tri(v, 10, 50);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &first));
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&f->band, v, &second));
    first.persp = d_bad.persp;
    second.shade = 99;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_RANGE, fxl_band_render(&f->band, 0, NULL));
    TEST_ASSERT_EQUAL_UINT32(10, (uint32_t)f->emu.transfers);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, f->emu.errors, f->emu.first_error);
    fixture_free(f);
}

void test_band_buffers_at_odd_addresses_are_refused_before_anything_is_sent(void)
{
    /* A band or depth buffer at an odd address (a uint8_t array cast to
     * uint16_t *): every uint16 store of the core would be misaligned (a
     * HardFault on a Cortex-M0+), and with a 16-bit HAL fxl_panel_write
     * refused band 0 only after the frame's CASET/RASET/RAMWR went out.
     * fxl_band_init refuses it, leaves the binding as it was and sends
     * nothing. (The odd pointers are only passed, never dereferenced.) */
    band_fixture_t *f = fixture();
    uint16_t *odd0 = (uint16_t *)(void *)((unsigned char *)f->buf0 + 1);
    uint16_t *odd1 = (uint16_t *)(void *)((unsigned char *)f->buf1 + 1);
    uint16_t *odd_depth = (uint16_t *)(void *)((unsigned char *)f->depth + 1);
    fxl_band_t before;
    const size_t wire = f->emu.log_len;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, NULL, 24, f->store, 4,
                                                f->bins, 64));
    memcpy(&before, &f->band, sizeof before);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, odd0, f->buf1, NULL, 24, f->store, 4,
                                                     f->bins, 64));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, odd1, NULL, 24, f->store, 4,
                                                     f->bins, 64));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, f->buf0, f->buf1, odd_depth, 24,
                                                     f->store, 4, f->bins, 64));
    TEST_ASSERT_EQUAL_MEMORY(&before, &f->band, sizeof before);
    TEST_ASSERT_EQUAL_UINT32((uint32_t)wire, (uint32_t)f->emu.log_len);
    /* the same with a HAL sending 16-bit frames */
    f->hal.flags |= FXL_PORT_PIXELS_16BIT;
    f->emu.spi16 = 1;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&f->panel, &f->hal, &fxl_st7789_240x320, 1));
    memcpy(&before, &f->band, sizeof before);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, fxl_band_init(&f->band, &f->panel, odd0, odd1, NULL, 24, f->store, 4,
                                                     f->bins, 64));
    TEST_ASSERT_EQUAL_MEMORY(&before, &f->band, sizeof before);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, f->emu.errors, f->emu.first_error);
    fixture_free(f);
}

/* ---- the double-buffer protocol and the transfer counters ------------------ */

/* A HAL in front of the emulator's: it checks which buffer each transfer
 * sends and what the other one holds while the driver waits, can fail
 * pixels() on one transfer, and gives up waiting after `wait_limit` calls
 * in a row (so a driver that would wait forever fails the test instead). */
typedef struct probe {
    panel_emu_t *emu;
    fxl_port_hal_t inner;
    const uint16_t *buf[2];
    const uint16_t *full;      /* the frame drawn at once, native RGB565 */
    fxl_pixfmt_t fmt;
    int w, h, rows, bands;
    unsigned long frame_first; /* emu->transfers when the frame started */
    unsigned long fail_transfer; /* 1-based transfer of the frame that pixels() refuses, 0 none */
    unsigned long waits_in_a_row, wait_limit;
    unsigned long last_checked;  /* emu->transfers at the last check */
    int order_wrong, ahead_checked, ahead_wrong; /* ahead_checked: bands, not wait calls */
} probe_t;

static probe_t probe;

static fxl_status_t probe_pixels(void *user, const void *data, size_t bytes)
{
    const int k = (int)(probe.emu->transfers - probe.frame_first); /* this band */
    const int i = data == probe.buf[0] ? 0 : (data == probe.buf[1] ? 1 : -1);
    probe.waits_in_a_row = 0;
    if (probe.fail_transfer != 0 && (unsigned long)k + 1u == probe.fail_transfer)
        return FXL_ERR_IO;
    /* band k from buffer k % 2: both buffers, in turn */
    if (i != (k & 1))
        probe.order_wrong++;
    return probe.inner.pixels(user, data, bytes);
}

static fxl_status_t probe_cmd(void *user, uint8_t c, const uint8_t *p, size_t n)
{
    probe.waits_in_a_row = 0;
    return probe.inner.cmd(user, c, p, n);
}

/* While band k is on the wire the driver may only be waiting to send band
 * k + 1, which must then be complete in the other buffer: proof that it was
 * drawn during band k's transfer, into the buffer not being read. */
static fxl_status_t probe_wait(void *user)
{
    if (probe.wait_limit != 0 && ++probe.waits_in_a_row > probe.wait_limit)
        return FXL_ERR_IO;
    if (probe.emu->in_flight && probe.full != NULL) {
        const int k = (int)(probe.emu->transfers - probe.frame_first) - 1;
        const int rows = probe.h - (k + 1) * probe.rows < probe.rows ? probe.h - (k + 1) * probe.rows : probe.rows;
        if (k >= 0 && k + 1 < probe.bands) {
            const uint16_t *other = (const uint8_t *)probe.buf[0] == probe.emu->xfer.data ? probe.buf[1] : probe.buf[0];
            uint16_t *row = (uint16_t *)malloc((size_t)probe.w * 2u);
            int y;
            TEST_ASSERT_NOT_NULL(row);
            if (probe.last_checked != probe.emu->transfers)
                probe.ahead_checked++;
            probe.last_checked = probe.emu->transfers;
            for (y = 0; y < rows; y++) {
                memcpy(row, other + (size_t)y * (size_t)probe.w, (size_t)probe.w * 2u);
                pixels_to_native(row, (size_t)probe.w, probe.fmt);
                if (memcmp(row, probe.full + ((size_t)(k + 1) * (size_t)probe.rows + (size_t)y) * (size_t)probe.w,
                           (size_t)probe.w * 2u) != 0) {
                    probe.ahead_wrong++;
                    break;
                }
            }
            free(row);
        }
    }
    return probe.inner.wait(user);
}

typedef struct probed_run {
    panel_emu_t emu;
    fxl_port_hal_t hal;
    fxl_panel_t panel;
    fxl_band_t band;
    fxl_band_tri_t store[MAX_TRIS];
    fxl_band_bin_t bins[16 * (1 + MAX_TRIS)];
    uint16_t *buf0, *buf1, *depth, *full, *view;
    scene_t scene;
    int rows;
} probed_run_t;

/* st7789 at rotation 1 (320 x 240) in `rows`-row bands, the scene of the
 * image tests added, the probe in front of the emulator's HAL. */
static probed_run_t *probed_setup(int rows, int dma_delay)
{
    probed_run_t *r = (probed_run_t *)calloc(1, sizeof(probed_run_t));
    fxl_stats_t st;
    int i, w = 320, h = 240;
    need_band_draws();
    TEST_ASSERT_NOT_NULL(r);
    TEST_ASSERT_EQUAL_INT(0, panel_emu_init(&r->emu, panel_emu_module_find("st7789"), 0));
    r->emu.panel = &r->panel;
    r->emu.dma_delay = dma_delay;
    r->emu.spi16 = panel_spi16();
    memset(&probe, 0, sizeof(probe));
    probe.emu = &r->emu;
    panel_emu_hal(&r->emu, &probe.inner);
    r->hal = probe.inner;
    r->hal.pixels = probe_pixels;
    r->hal.cmd = probe_cmd;
    r->hal.wait = probe_wait;
    probe.wait_limit = 100000;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&r->panel, &r->hal, &fxl_st7789_240x320, 1));
    TEST_ASSERT_EQUAL_INT(w, r->panel.width);
    r->rows = rows;
    r->buf0 = (uint16_t *)malloc((size_t)w * (size_t)rows * 2u);
    r->buf1 = (uint16_t *)malloc((size_t)w * (size_t)rows * 2u);
    r->depth = (uint16_t *)malloc((size_t)w * (size_t)rows * 2u);
    r->full = (uint16_t *)malloc((size_t)w * (size_t)h * 2u);
    r->view = (uint16_t *)malloc((size_t)w * (size_t)h * 2u);
    TEST_ASSERT_TRUE(r->buf0 && r->buf1 && r->depth && r->full && r->view);
    build_scene(&r->scene, w, h);
    render_full(&r->scene, w, h, r->full, &st);
    probe.buf[0] = r->buf0;
    probe.buf[1] = r->buf1;
    probe.full = r->full;
    probe.fmt = fxl_panel_pixel_format(&r->panel);
    probe.w = w;
    probe.h = h;
    probe.rows = rows;
    probe.bands = (h + rows - 1) / rows;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&r->band, &r->panel, r->buf0, r->buf1, DEPTH_BUF(r->depth), rows,
                                                r->store, MAX_TRIS, r->bins, (uint32_t)(sizeof(r->bins) / sizeof(r->bins[0]))));
    for (i = 0; i < r->scene.count; i++)
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&r->band, r->scene.v[i], r->scene.draw[i]));
    return r;
}

/* One frame through the probe: its status, and when it is FXL_OK, the
 * panel must show the full-frame image with no protocol error. */
static fxl_status_t probed_frame(probed_run_t *r)
{
    fxl_status_t st;
    probe.frame_first = r->emu.transfers;
    st = fxl_band_render(&r->band, CLEAR_COLOR, NULL);
    if (st == FXL_OK) {
        TEST_ASSERT_EQUAL_INT_MESSAGE(0, r->emu.errors, r->emu.first_error);
        TEST_ASSERT_EQUAL_INT(0, panel_emu_view(&r->emu, 1, r->view, NULL, NULL));
        TEST_ASSERT_EQUAL_MEMORY(r->full, r->view, (size_t)probe.w * (size_t)probe.h * 2u);
        TEST_ASSERT_EQUAL_UINT32(r->panel.started, r->panel.done);
    }
    return st;
}

static void probed_free(probed_run_t *r)
{
    panel_emu_free(&r->emu);
    free(r->buf0);
    free(r->buf1);
    free(r->depth);
    free(r->full);
    free(r->view);
    free(r);
    memset(&probe, 0, sizeof(probe));
}

void test_bands_alternate_buffers_and_the_next_is_drawn_while_one_is_sent(void)
{
    /* 24-row bands (10), completions 3 HAL calls late: the driver waits in
     * the hook before every send but the first, each time with the next
     * band already complete in the buffer that is not on the wire. A
     * renderer using one buffer, or drawing band k + 1 only after band k
     * completed, fails here even though its image would be right. */
    probed_run_t *r = probed_setup(24, 3);
    int f;
    for (f = 0; f < 2; f++)
        TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
    TEST_ASSERT_EQUAL_INT(0, probe.order_wrong);
    TEST_ASSERT_EQUAL_INT(0, probe.ahead_wrong);
    TEST_ASSERT_EQUAL_INT(2 * 9, probe.ahead_checked);
    probed_free(r);
}

void test_panel_reinit_after_frames_does_not_stall_the_band_renderer(void)
{
    /* fxl_panel_init zeroes the transfer counters while the band renderer
     * holds the numbers of the transfers it last sent (here 30 and 29): the
     * next frame must not wait for them. */
    probed_run_t *r = probed_setup(24, 2);
    int f;
    for (f = 0; f < 3; f++)
        TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
    TEST_ASSERT_EQUAL_UINT32(30, r->panel.started);
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&r->panel, &r->hal, &fxl_st7789_240x320, 1));
    TEST_ASSERT_EQUAL_UINT32(0, r->panel.started);
    for (f = 0; f < 2; f++)
        TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
    TEST_ASSERT_EQUAL_UINT32(20, r->panel.started);
    TEST_ASSERT_EQUAL_INT(0, probe.order_wrong);
    TEST_ASSERT_EQUAL_INT(0, probe.ahead_wrong);
    probed_free(r);
}

void test_transfer_counters_wrap_and_old_numbers_are_never_pending(void)
{
    /* Counters as after 2^31 - 8 and 2^32 - 8 transfers (~3 days of one-row
     * bands at 30 fps): frames across both boundaries, and a band re-init
     * (its buffers start at transfer 0) once 0 is 2^31 behind `done`. */
    static const uint32_t starts[] = { 0x7FFFFFF8u, 0xFFFFFFF8u };
    size_t i;
    for (i = 0; i < sizeof(starts) / sizeof(starts[0]); i++) {
        probed_run_t *r = probed_setup(24, 2);
        unsigned long waits;
        int f;
        r->panel.started = r->panel.done = starts[i];
        for (f = 0; f < 2; f++)
            TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
        TEST_ASSERT_EQUAL_UINT32(starts[i] + 20u, r->panel.started);
        /* 0 and a number 2^31 old are not in flight: no wait at all */
        waits = r->emu.waits;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_done(&r->panel, 0));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_done(&r->panel, r->panel.done - 0x80000000u));
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_wait_done(&r->panel, r->panel.started + 5u));
        TEST_ASSERT_EQUAL_UINT32((uint32_t)waits, (uint32_t)r->emu.waits);
        r->panel.started = r->panel.done = 0x80000010u;
        TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_init(&r->band, &r->panel, r->buf0, r->buf1, DEPTH_BUF(r->depth), 24,
                                                    r->store, MAX_TRIS, r->bins,
                                                    (uint32_t)(sizeof(r->bins) / sizeof(r->bins[0]))));
        for (f = 0; f < r->scene.count; f++)
            TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_band_add(&r->band, r->scene.v[f], r->scene.draw[f]));
        TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
        TEST_ASSERT_EQUAL_INT(0, probe.order_wrong);
        TEST_ASSERT_EQUAL_INT(0, probe.ahead_wrong);
        probed_free(r);
    }
}

void test_pixels_failure_mid_frame_leaves_the_panel_idle_for_the_next(void)
{
    /* pixels() refuses band 4's transfer: the render returns FXL_ERR_IO
     * with nothing in flight (band 3's transfer waited for), and the next
     * frame is whole. */
    probed_run_t *r = probed_setup(24, 3);
    probe.fail_transfer = 4;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, probed_frame(r));
    TEST_ASSERT_EQUAL_UINT32(3, (uint32_t)r->emu.transfers);
    TEST_ASSERT_EQUAL_UINT32(r->panel.started, r->panel.done);
    TEST_ASSERT_EQUAL_INT(0, r->emu.in_flight);
    TEST_ASSERT_EQUAL_INT_MESSAGE(0, r->emu.errors, r->emu.first_error);
    probe.fail_transfer = 0;
    TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
    TEST_ASSERT_EQUAL_INT(0, probe.ahead_wrong);
    probed_free(r);
}

void test_after_the_wait_hook_gives_up_the_documented_recoveries_work(void)
{
    /* A DMA that never completes: the hook gives up (a timeout), the render
     * returns FXL_ERR_IO and so does every call that waits. */
    probed_run_t *r = probed_setup(24, 1000000000);
    probe.wait_limit = 50;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, probed_frame(r));
    TEST_ASSERT_EQUAL_INT(1, r->emu.in_flight);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, fxl_panel_display(&r->panel, 1));
    /* 1: stop the DMA (here it ends), report the transfer over */
    r->emu.dma_delay = 2;
    r->emu.in_flight = 0;
    fxl_port_transfer_done(&r->panel);
    TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
    /* 2: stall again; the DMA is stopped, fxl_panel_init runs, and then the
     * stalled transfer's interrupt still arrives: `done` is one ahead of
     * `started`. The next transfers must still wait for each other (the
     * emulator fails a pixels() or command while one is in flight). */
    r->emu.dma_delay = 1000000000;
    TEST_ASSERT_EQUAL_INT(FXL_ERR_IO, probed_frame(r));
    r->emu.in_flight = 0;
    r->emu.dma_delay = 2;
    TEST_ASSERT_EQUAL_INT(FXL_OK, fxl_panel_init(&r->panel, &r->hal, &fxl_st7789_240x320, 1));
    fxl_port_transfer_done(&r->panel);
    TEST_ASSERT_EQUAL_UINT32(1, r->panel.done - r->panel.started);
    TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
    TEST_ASSERT_EQUAL_INT(FXL_OK, probed_frame(r));
    TEST_ASSERT_EQUAL_INT(0, probe.order_wrong);
    TEST_ASSERT_EQUAL_INT(0, probe.ahead_wrong);
    probed_free(r);
}

void test_render_scene_helper_matches_full_frame(void)
{
    /* The one-call helper fixel-sim uses: same image as a full-frame render. */
    scene_t s;
    fxl_band_tri_t tris[MAX_TRIS];
    panel_emu_result_t res;
    fxl_stats_t full_stats;
    uint16_t *full, *out;
    int i, w, h;
    need_band_draws();
    TEST_ASSERT_EQUAL_INT(0, panel_emu_frame_size("st7789-135x240", 1, &w, &h));
    build_scene(&s, w, h);
    for (i = 0; i < s.count; i++) {
        memcpy(tris[i].v, s.v[i], sizeof(tris[i].v));
        tris[i].draw = s.draw[i];
    }
    full = (uint16_t *)malloc((size_t)w * (size_t)h * 2u);
    out = (uint16_t *)malloc((size_t)w * (size_t)h * 2u);
    TEST_ASSERT_TRUE(full && out);
    render_full(&s, w, h, full, &full_stats);
    TEST_ASSERT_EQUAL_INT(FXL_OK, panel_emu_render_scene("st7789-135x240", 1, 0, tris, (size_t)s.count,
                                                         CLEAR_COLOR, out, (size_t)w * (size_t)h, &res));
    TEST_ASSERT_EQUAL_INT(0, res.protocol_errors);
    TEST_ASSERT_EQUAL_INT(w, res.width);
    TEST_ASSERT_EQUAL_INT(h, res.height);
    TEST_ASSERT_EQUAL_HEX32(crc32_update(0, full, (size_t)w * (size_t)h * 2u),
                            crc32_update(0, out, (size_t)w * (size_t)h * 2u));
    /* Frame bytes: 11 window bytes + 2 per pixel. */
    TEST_ASSERT_EQUAL_UINT32(full_stats.pixels, res.stats.pixels);
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, panel_emu_render_scene("nope", 0, 0, tris, 1, 0, out,
                                                              (size_t)w * (size_t)h, NULL));
    TEST_ASSERT_EQUAL_INT(FXL_ERR_ARG, panel_emu_render_scene("st7789", 0, 0, tris, 1, 0, out, 10, NULL));
    free(full);
    free(out);
}

int main(void)
{
    UNITY_BEGIN();
    RUN_TEST(test_banded_frame_equals_full_frame_render);
    RUN_TEST(test_banded_frame_equals_full_frame_for_any_band_height);
    RUN_TEST(test_banded_frame_equals_full_frame_every_preset_and_rotation);
    RUN_TEST(test_spi16_frames_draw_native_bands_and_send_the_same_bytes);
    RUN_TEST(test_panel_pixel_format_follows_the_hal_flags);
    RUN_TEST(test_late_dma_completion_never_lets_a_buffer_be_reused_early);
    RUN_TEST(test_without_wait_hook_the_driver_spins_on_the_completion_counter);
    RUN_TEST(test_bin_budget_exceeded_falls_back_with_identical_image);
    RUN_TEST(test_no_bin_memory_scans_every_triangle_with_identical_image);
    RUN_TEST(test_triangle_is_listed_once_in_each_band_it_touches);
    RUN_TEST(test_triangle_that_does_not_fit_the_bins_starts_the_fallback);
    RUN_TEST(test_binning_edges_row_zero_and_bins_exactly_full);
    RUN_TEST(test_fallback_draws_a_triangle_only_in_the_bands_it_touches);
    RUN_TEST(test_triangle_ending_just_above_the_frame_is_dropped);
    RUN_TEST(test_band_api_errors);
    RUN_TEST(test_bad_draw_is_refused_when_added_before_anything_is_sent);
    RUN_TEST(test_draw_error_is_returned_after_the_whole_frame_was_sent);
    RUN_TEST(test_first_of_several_draw_errors_is_returned);
    RUN_TEST(test_band_buffers_at_odd_addresses_are_refused_before_anything_is_sent);
    RUN_TEST(test_render_scene_helper_matches_full_frame);
    RUN_TEST(test_bands_alternate_buffers_and_the_next_is_drawn_while_one_is_sent);
    RUN_TEST(test_panel_reinit_after_frames_does_not_stall_the_band_renderer);
    RUN_TEST(test_transfer_counters_wrap_and_old_numbers_are_never_pending);
    RUN_TEST(test_pixels_failure_mid_frame_leaves_the_panel_idle_for_the_next);
    RUN_TEST(test_after_the_wait_hook_gives_up_the_documented_recoveries_work);
    return UNITY_END();
}

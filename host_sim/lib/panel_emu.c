/* panel_emu.c - emulated MIPI DCS panel (contract in panel_emu.h). */
#define _POSIX_C_SOURCE 200809L
#include "panel_emu.h"
#include "left_out.h"

#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

/* Datasheet minimums the emulator enforces (ST7789V and ILI9341 agree):
 * 5 ms from reset (RESX rising edge or SWRESET) to the next command,
 * 120 ms from reset to SLPOUT, 5 ms from SLPOUT to the next command. */
#define T_RESET_CMD_MS 5u
#define T_RESET_SLPOUT_MS 120u
#define T_SLPOUT_CMD_MS 5u

/* Glass placement of the modules (facts about the modules, independent of
 * the driver's offset tables, which the tests check against these). */
static const panel_emu_module_t modules[] = {
    { "st7789-240x320", 240, 320, 0, 0, 240, 320, 0, 0, 1 },
    { "st7789-240x240", 240, 320, 0, 0, 240, 240, 0, 0, 1 },
    { "st7789-135x240", 240, 320, 52, 40, 135, 240, 0, 0, 1 },
    { "ili9341-240x320", 240, 320, 0, 0, 240, 320, 1, 1, 0 },
};

static const char *canonical(const char *name)
{
    if (name == NULL) return NULL;
    if (strcmp(name, "st7789") == 0) return "st7789-240x320";
    if (strcmp(name, "ili9341") == 0) return "ili9341-240x320";
    return name;
}

const panel_emu_module_t *panel_emu_module_find(const char *name)
{
    size_t i;
    name = canonical(name);
    if (name == NULL) return NULL;
    for (i = 0; i < sizeof(modules) / sizeof(modules[0]); i++)
        if (strcmp(modules[i].name, name) == 0) return &modules[i];
    return NULL;
}

const fxl_panel_preset_t *panel_emu_preset_find(const char *name)
{
    static const fxl_panel_preset_t *const presets[] = {
        &fxl_st7789_240x320, &fxl_st7789_240x240, &fxl_st7789_135x240, &fxl_ili9341_240x320
    };
    size_t i;
    name = canonical(name);
    if (name == NULL) return NULL;
    for (i = 0; i < sizeof(presets) / sizeof(presets[0]); i++)
        if (strcmp(presets[i]->name, name) == 0) return presets[i];
    return NULL;
}

uint32_t panel_emu_crc32(uint32_t crc, const void *data, size_t n)
{
    const uint8_t *p = (const uint8_t *)data;
    size_t i;
    int k;
    crc = ~crc;
    for (i = 0; i < n; i++) {
        crc ^= p[i];
        for (k = 0; k < 8; k++) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
    }
    return ~crc;
}

static void fail(panel_emu_t *e, const char *fmt, ...)
{
    e->errors++;
    if (e->errors == 1) {
        va_list ap;
        va_start(ap, fmt);
        vsnprintf(e->first_error, sizeof(e->first_error), fmt, ap);
        va_end(ap);
    }
}

static void record(panel_emu_t *e, uint32_t type, uint32_t value)
{
    if (!e->log_enabled) return;
    if (e->log_len == e->log_cap) {
        size_t cap = e->log_cap ? e->log_cap * 2 : 4096;
        uint32_t *p = (uint32_t *)realloc(e->log, cap * sizeof(*p));
        if (p == NULL) {
            fail(e, "wire log: out of memory");
            e->log_enabled = 0;
            return;
        }
        e->log = p;
        e->log_cap = cap;
    }
    e->log[e->log_len++] = PANEL_EMU_EV(type, value);
}

static void wire_byte(panel_emu_t *e, uint32_t type, uint8_t b)
{
    e->crc = panel_emu_crc32(e->crc, &b, 1);
    e->wire_bytes++;
    record(e, type, b);
}

static void power_on_state(panel_emu_t *e)
{
    /* Register values after reset (both datasheets): sleep in, display off,
     * MADCTL 0, COLMOD 18 bit, inversion off, full window. */
    e->madctl = 0;
    e->colmod = 0x66;
    e->sleeping = 1;
    e->display_on = 0;
    e->inverted = 0;
    e->xs = 0;
    e->xe = e->mod.ram_w - 1;
    e->ys = 0;
    e->ye = e->mod.ram_h - 1;
    e->cx = 0;
    e->cy = 0;
    e->writing = 0;
    e->have_half = 0;
    e->reset_ms = e->now_ms;
    e->slpout_seen = 0;
}

int panel_emu_init(panel_emu_t *e, const panel_emu_module_t *mod, uint16_t ram_fill)
{
    size_t i, n;
    if (e == NULL || mod == NULL || mod->ram_w <= 0 || mod->ram_h <= 0) return -1;
    memset(e, 0, sizeof(*e));
    e->mod = *mod;
    n = (size_t)mod->ram_w * (size_t)mod->ram_h;
    e->ram = (uint16_t *)malloc(n * sizeof(uint16_t));
    if (e->ram == NULL) return -1;
    for (i = 0; i < n; i++) e->ram[i] = ram_fill;
    e->log_enabled = 1;
    e->resx = 1;
    /* Powered up long ago: the first reset is what the driver must wait for. */
    e->now_ms = 1000;
    power_on_state(e);
    e->reset_ms = 0;
    e->dma_delay = 0;
    return 0;
}

void panel_emu_free(panel_emu_t *e)
{
    if (e == NULL) return;
    free(e->ram);
    free(e->log);
    free(e->xfer.snapshot);
    e->ram = NULL;
    e->log = NULL;
    e->xfer.snapshot = NULL;
}

void panel_emu_clear_log(panel_emu_t *e)
{
    e->log_len = 0;
    e->crc = 0;
    e->wire_bytes = 0;
}

int panel_emu_map(const panel_emu_t *e, int x, int y, int *col, int *row)
{
    /* MV exchanges first, then MX mirrors the physical column and MY the
     * physical row: the combination that puts the known module offsets
     * (240x240: y 80 at MX|MY, x 80 at MY|MV) where they are. */
    int a = x, b = y;
    if (e->madctl & FXL_MADCTL_MV) {
        a = y;
        b = x;
    }
    if (a < 0 || b < 0 || a >= e->mod.ram_w || b >= e->mod.ram_h) return -1;
    if (e->madctl & FXL_MADCTL_MX) a = e->mod.ram_w - 1 - a;
    if (e->madctl & FXL_MADCTL_MY) b = e->mod.ram_h - 1 - b;
    *col = a;
    *row = b;
    return 0;
}

static void put_pixel(panel_emu_t *e, uint16_t value)
{
    int col, row;
    if (panel_emu_map(e, e->cx, e->cy, &col, &row) != 0) {
        fail(e, "pixel at logical (%d, %d) outside the address space (MADCTL 0x%02X)", e->cx,
             e->cy, e->madctl);
    } else {
        e->ram[(size_t)row * (size_t)e->mod.ram_w + (size_t)col] = value;
        e->pixels_written++;
        if (col < e->mod.glass_x0 || col >= e->mod.glass_x0 + e->mod.glass_w ||
            row < e->mod.glass_y0 || row >= e->mod.glass_y0 + e->mod.glass_h)
            e->writes_outside_glass++;
    }
    /* Address counter: along x within the window, then the next row; past
     * the end of the window it wraps to the start. */
    if (++e->cx > e->xe) {
        e->cx = e->xs;
        if (++e->cy > e->ye) e->cy = e->ys;
    }
}

static void pixel_bytes(panel_emu_t *e, const uint8_t *p, size_t n)
{
    size_t i;
    if (!e->writing) {
        fail(e, "%zu pixel bytes without RAMWR", n);
        for (i = 0; i < n; i++) wire_byte(e, PANEL_EMU_EV_DATA, p[i]);
        return;
    }
    if (e->colmod != FXL_COLMOD_RGB565) fail(e, "pixel data with COLMOD 0x%02X (not 16 bit)", e->colmod);
    for (i = 0; i < n; i++) {
        wire_byte(e, PANEL_EMU_EV_DATA, p[i]);
        if (e->have_half) {
            /* 16-bit pixels arrive high byte first. */
            put_pixel(e, (uint16_t)(((unsigned)e->half << 8) | p[i]));
            e->have_half = 0;
        } else {
            e->half = p[i];
            e->have_half = 1;
        }
    }
}

static void complete(panel_emu_t *e)
{
    panel_emu_xfer_t *x = &e->xfer;
    if (!e->in_flight) return;
    if (memcmp(x->data, x->snapshot, x->bytes) != 0) {
        size_t i = 0;
        while (x->data[i] == x->snapshot[i]) i++;
        fail(e, "transfer %lu: buffer modified before completion (byte %zu: 0x%02X -> 0x%02X)",
             e->transfers, i, x->snapshot[i], x->data[i]);
    }
    /* The controller gets what the buffer holds when the DMA reads it; we
     * read it at the last moment, so any early reuse also shows in the image. */
    if (e->spi16) {
        /* 16-bit frames: each word's high byte goes out first (decoded in
         * one piece, so a protocol error counts once per transfer, as with
         * bytes) */
        const size_t n = x->bytes & ~(size_t)1;
        uint8_t *wire = (uint8_t *)malloc(n ? n : 1);
        size_t i;
        if (x->bytes & 1u) fail(e, "transfer %lu: %zu bytes in 16-bit frames", e->transfers, x->bytes);
        if (wire == NULL) {
            fail(e, "16-bit frames: out of memory");
        } else {
            for (i = 0; i < n; i += 2) {
                uint16_t w;
                memcpy(&w, x->data + i, 2);
                wire[i] = (uint8_t)(w >> 8);
                wire[i + 1] = (uint8_t)w;
            }
            pixel_bytes(e, wire, n);
            free(wire);
        }
    } else {
        pixel_bytes(e, x->data, x->bytes);
    }
    e->in_flight = 0;
    e->completions++;
    if (e->panel != NULL) fxl_port_transfer_done(e->panel);
}

void panel_emu_flush(panel_emu_t *e)
{
    complete(e);
}

/* Every HAL call is one tick of the DMA mock's clock. */
static void tick(panel_emu_t *e)
{
    if (e->in_flight && --e->xfer.ticks_left <= 0) complete(e);
}

static uint16_t be16(const uint8_t *p)
{
    return (uint16_t)(((unsigned)p[0] << 8) | p[1]);
}

static void command(panel_emu_t *e, uint8_t c, const uint8_t *p, size_t n)
{
    if (e->have_half) {
        fail(e, "command 0x%02X after an odd number of pixel bytes", c);
        e->have_half = 0;
    }
    e->writing = 0;
    if (e->resx == 0) fail(e, "command 0x%02X while RESX is low", c);
    if (e->now_ms - e->reset_ms < T_RESET_CMD_MS)
        fail(e, "command 0x%02X %llu ms after reset (needs %u)", c,
             (unsigned long long)(e->now_ms - e->reset_ms), T_RESET_CMD_MS);
    if (e->slpout_seen && e->now_ms - e->slpout_ms < T_SLPOUT_CMD_MS)
        fail(e, "command 0x%02X %llu ms after SLPOUT (needs %u)", c,
             (unsigned long long)(e->now_ms - e->slpout_ms), T_SLPOUT_CMD_MS);
    switch (c) {
    case FXL_DCS_SWRESET:
        power_on_state(e);
        break;
    case FXL_DCS_SLPOUT:
        if (e->now_ms - e->reset_ms < T_RESET_SLPOUT_MS)
            fail(e, "SLPOUT %llu ms after reset (needs %u)",
                 (unsigned long long)(e->now_ms - e->reset_ms), T_RESET_SLPOUT_MS);
        e->sleeping = 0;
        e->slpout_ms = e->now_ms;
        e->slpout_seen = 1;
        break;
    case FXL_DCS_SLPIN: e->sleeping = 1; break;
    case FXL_DCS_DISPON: e->display_on = 1; break;
    case FXL_DCS_DISPOFF: e->display_on = 0; break;
    case FXL_DCS_INVON: e->inverted = 1; break;
    case FXL_DCS_INVOFF: e->inverted = 0; break;
    case FXL_DCS_CASET:
    case FXL_DCS_RASET: {
        int s, t, limit;
        int is_x = (c == FXL_DCS_CASET);
        if (n != 4) {
            fail(e, "%s with %zu parameter bytes", is_x ? "CASET" : "RASET", n);
            break;
        }
        s = be16(p);
        t = be16(p + 2);
        /* With MV, columns address the long side. */
        limit = ((e->madctl & FXL_MADCTL_MV) != 0) == is_x ? e->mod.ram_h : e->mod.ram_w;
        if (s > t || t >= limit) fail(e, "%s %d..%d outside 0..%d", is_x ? "CASET" : "RASET", s, t, limit - 1);
        if (is_x) {
            e->xs = s;
            e->xe = t;
        } else {
            e->ys = s;
            e->ye = t;
        }
        break;
    }
    case FXL_DCS_RAMWR:
        e->cx = e->xs;
        e->cy = e->ys;
        e->writing = 1;
        break;
    case FXL_DCS_RAMWRC:
        e->writing = 1;
        break;
    case FXL_DCS_MADCTL:
        if (n != 1) fail(e, "MADCTL with %zu parameter bytes", n);
        else e->madctl = p[0];
        break;
    case FXL_DCS_COLMOD:
        if (n != 1) fail(e, "COLMOD with %zu parameter bytes", n);
        else e->colmod = p[0];
        break;
    default:
        break; /* vendor registers: recorded, no visible effect */
    }
}

static fxl_status_t cb_cmd(void *user, uint8_t c, const uint8_t *p, size_t n)
{
    panel_emu_t *e = (panel_emu_t *)user;
    size_t i;
    if (e->in_flight) fail(e, "command 0x%02X while a pixel transfer is in flight", c);
    tick(e);
    e->cmds++;
    wire_byte(e, PANEL_EMU_EV_CMD, c);
    for (i = 0; i < n; i++) wire_byte(e, PANEL_EMU_EV_DATA, p[i]);
    command(e, c, p, n);
    return FXL_OK;
}

static fxl_status_t cb_pixels(void *user, const void *data, size_t bytes)
{
    panel_emu_t *e = (panel_emu_t *)user;
    uint8_t *snap;
    if (e->in_flight) {
        fail(e, "pixels() while transfer %lu is in flight", e->transfers);
        complete(e);
    }
    tick(e);
    snap = (uint8_t *)realloc(e->xfer.snapshot, bytes ? bytes : 1);
    if (snap == NULL) {
        fail(e, "snapshot: out of memory");
        return FXL_ERR_IO;
    }
    memcpy(snap, data, bytes);
    e->xfer.snapshot = snap;
    e->xfer.data = (const uint8_t *)data;
    e->xfer.bytes = bytes;
    e->xfer.ticks_left = e->dma_delay;
    e->in_flight = 1;
    e->transfers++;
    if (e->dma_delay <= 0) complete(e);
    return FXL_OK;
}

static fxl_status_t cb_reset(void *user, int level)
{
    panel_emu_t *e = (panel_emu_t *)user;
    tick(e);
    record(e, PANEL_EMU_EV_RESET, (uint32_t)(level != 0));
    if (e->resx == 0 && level != 0) power_on_state(e); /* reset ends on the rising edge */
    e->resx = level != 0;
    return FXL_OK;
}

static fxl_status_t cb_delay(void *user, uint32_t ms)
{
    panel_emu_t *e = (panel_emu_t *)user;
    tick(e);
    record(e, PANEL_EMU_EV_DELAY, ms > 0xFFFFu ? 0xFFFFu : ms);
    e->now_ms += ms;
    return FXL_OK;
}

static fxl_status_t cb_wait(void *user)
{
    panel_emu_t *e = (panel_emu_t *)user;
    e->waits++;
    tick(e);
    return FXL_OK;
}

void panel_emu_hal(panel_emu_t *e, fxl_port_hal_t *hal)
{
    memset(hal, 0, sizeof(*hal));
    hal->cmd = cb_cmd;
    hal->pixels = cb_pixels;
    hal->reset = cb_reset;
    hal->delay_ms = cb_delay;
    hal->wait = cb_wait;
    hal->user = e;
    hal->flags = e->spi16 ? FXL_PORT_PIXELS_16BIT : 0u;
}

void panel_emu_glass(const panel_emu_t *e, uint16_t *out)
{
    const panel_emu_module_t *m = &e->mod;
    const int swap_rb = ((e->madctl & FXL_MADCTL_BGR) != 0) != (m->glass_bgr != 0);
    const int invert = (e->inverted != 0) != (m->glass_inverted != 0);
    int gx, gy;
    for (gy = 0; gy < m->glass_h; gy++) {
        for (gx = 0; gx < m->glass_w; gx++) {
            int col = m->glass_x0 + (m->glass_mirror_x ? m->glass_w - 1 - gx : gx);
            int row = m->glass_y0 + gy;
            uint16_t v = e->ram[(size_t)row * (size_t)m->ram_w + (size_t)col];
            if (swap_rb) v = (uint16_t)(((v & 0x1Fu) << 11) | (v & 0x07E0u) | (v >> 11));
            if (invert) v = (uint16_t)~v;
            if (e->sleeping || !e->display_on) v = 0;
            out[(size_t)gy * (size_t)m->glass_w + (size_t)gx] = v;
        }
    }
}

int panel_emu_view(const panel_emu_t *e, int rotation, uint16_t *out, int *w, int *h)
{
    const int gw = e->mod.glass_w, gh = e->mod.glass_h;
    const int fw = (rotation & 1) ? gh : gw, fh = (rotation & 1) ? gw : gh;
    uint16_t *glass;
    int x, y;
    if (rotation < 0 || rotation > 3) return -1;
    if (w) *w = fw;
    if (h) *h = fh;
    if (out == NULL) return 0;
    glass = (uint16_t *)malloc((size_t)gw * (size_t)gh * sizeof(uint16_t));
    if (glass == NULL) return -1;
    panel_emu_glass(e, glass);
    for (y = 0; y < fh; y++) {
        for (x = 0; x < fw; x++) {
            /* Frame (x, y) -> glass: rotation 1 puts the frame's top row on
             * the glass's right column, 2 turns it upside down, 3 is 1 reversed. */
            int gx, gy;
            switch (rotation) {
            case 0: gx = x; gy = y; break;
            case 1: gx = gw - 1 - y; gy = x; break;
            case 2: gx = gw - 1 - x; gy = gh - 1 - y; break;
            default: gx = y; gy = gh - 1 - x; break;
            }
            out[(size_t)y * (size_t)fw + (size_t)x] = glass[(size_t)gy * (size_t)gw + (size_t)gx];
        }
    }
    free(glass);
    return 0;
}

/* ---- one-call rendering ---------------------------------------------------- */

int panel_emu_frame_size(const char *panel, int rotation, int *w, int *h)
{
    const panel_emu_module_t *m = panel_emu_module_find(panel);
    if (m == NULL || rotation < 0 || rotation > 3) return -1;
    if (w) *w = (rotation & 1) ? m->glass_h : m->glass_w;
    if (h) *h = (rotation & 1) ? m->glass_w : m->glass_h;
    return 0;
}

fxl_status_t panel_emu_render_scene(const char *panel, int rotation, int band_rows,
                                    const fxl_band_tri_t *tris, size_t count,
                                    uint16_t clear_rgb565, uint16_t *out, size_t out_pixels,
                                    panel_emu_result_t *res)
{
    const panel_emu_module_t *mod = panel_emu_module_find(panel);
    const fxl_panel_preset_t *preset = panel_emu_preset_find(panel);
    panel_emu_t emu;
    fxl_port_hal_t hal;
    fxl_panel_t p;
    fxl_band_t band;
    fxl_band_tri_t *store = NULL;
    fxl_band_bin_t *bins = NULL;
    uint16_t *buf0 = NULL, *buf1 = NULL, *depth = NULL;
    fxl_stats_t stats;
    fxl_status_t st;
    int w, h, bands;
    size_t i, bin_cap;

    if (res != NULL) memset(res, 0, sizeof(*res));
    if (mod == NULL || preset == NULL || out == NULL || (tris == NULL && count > 0) ||
        count > FXL_BAND_MAX_TRIS || panel_emu_frame_size(panel, rotation, &w, &h) != 0)
        return FXL_ERR_ARG;
    if (out_pixels < (size_t)w * (size_t)h) return FXL_ERR_ARG;
    if (band_rows <= 0) band_rows = 24;
    if (band_rows > h) band_rows = h;
    bands = (h + band_rows - 1) / band_rows;
    if (panel_emu_init(&emu, mod, 0) != 0) return FXL_ERR_NOMEM;
    emu.dma_delay = 2;
    emu.panel = &p;
    emu.spi16 = panel_spi16();
    panel_emu_hal(&emu, &hal);
    memset(&stats, 0, sizeof(stats));

    /* Enough bin entries for every triangle in every band: no fallback. */
    bin_cap = (size_t)bands + (count > 0 ? count : 1) * (size_t)bands;
    if (bin_cap > 0xFFFFu) bin_cap = 0xFFFFu;
    store = (fxl_band_tri_t *)malloc((count > 0 ? count : 1) * sizeof(*store));
    bins = (fxl_band_bin_t *)malloc(bin_cap * sizeof(*bins));
    buf0 = (uint16_t *)malloc((size_t)w * (size_t)band_rows * 2u);
    buf1 = (uint16_t *)malloc((size_t)w * (size_t)band_rows * 2u);
    /* A depth band where the build has depth; without it the scene must
     * not need one (painter's order), as in a direct render. */
    depth = FXL_HAVE_DEPTH ? (uint16_t *)malloc((size_t)w * (size_t)band_rows * 2u) : NULL;
    st = (store && bins && buf0 && buf1 && (depth || !FXL_HAVE_DEPTH)) ? FXL_OK : FXL_ERR_NOMEM;

    if (st == FXL_OK) st = fxl_panel_init(&p, &hal, preset, (unsigned)rotation);
    if (st == FXL_OK)
        st = fxl_band_init(&band, &p, buf0, buf1, depth, band_rows, store,
                           (uint32_t)(count > 0 ? count : 1), bins, (uint32_t)bin_cap);
    for (i = 0; st == FXL_OK && i < count; i++) st = fxl_band_add(&band, tris[i].v, tris[i].draw);
    if (st == FXL_OK) {
        uint32_t frame_crc = 0;
        size_t first = emu.log_len;
        st = fxl_band_render(&band, clear_rgb565, &stats);
        /* The frame's own CRC: re-run the CRC over the recorded frame bytes. */
        for (i = first; i < emu.log_len; i++) {
            uint32_t ev = emu.log[i];
            if ((ev >> 16) == PANEL_EMU_EV_CMD || (ev >> 16) == PANEL_EMU_EV_DATA) {
                uint8_t byte = (uint8_t)(ev & 0xFFu);
                frame_crc = panel_emu_crc32(frame_crc, &byte, 1);
            }
        }
        if (res != NULL) {
            res->frame_crc = frame_crc;
            res->overflowed = fxl_band_overflowed(&band);
        }
    }
    if (st == FXL_OK && panel_emu_view(&emu, rotation, out, NULL, NULL) != 0) st = FXL_ERR_NOMEM;
    if (st == FXL_OK && emu.errors > 0) st = FXL_ERR_IO;
    if (res != NULL) {
        res->width = w;
        res->height = h;
        res->wire_crc = emu.crc;
        res->wire_bytes = emu.wire_bytes;
        res->transfers = emu.transfers;
        res->bands = bands;
        res->protocol_errors = emu.errors;
        res->stats = stats;
    }
    panel_emu_free(&emu);
    free(store);
    free(bins);
    free(buf0);
    free(buf1);
    free(depth);
    return st;
}

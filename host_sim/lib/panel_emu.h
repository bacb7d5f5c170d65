/* panel_emu.h - an emulated MIPI DCS panel behind the fixel port HAL.
 *
 * The emulator implements the HAL callbacks of include/fixel/port.h and
 * decodes what a real controller would see on its SPI lines: commands and
 * parameters (CASET/RASET/RAMWR/RAMWRC, MADCTL MY/MX/MV/BGR, COLMOD,
 * SWRESET/SLPOUT/DISPON/DISPOFF/INVON/INVOFF) into a controller memory of
 * ram_w x ram_h RGB565 words. A module description says which part of that
 * memory the glass shows and how (mirrored columns, BGR colour filter,
 * normally-inverted IPS glass), so a wrong preset shows a wrong image.
 *
 * It also checks the protocol: datasheet delays after reset / SLPOUT,
 * windows inside the address space, pixel data only after RAMWR, COLMOD
 * 16 bit, no command or second transfer while a transfer is in flight, and
 * that a buffer handed to pixels() is unchanged until its completion
 * (snapshot compared at completion). Every violation counts in `errors`,
 * the first one is described in `first_error`.
 *
 * SPI frame size: with `spi16` set (before panel_emu_hal, which then sets
 * FXL_PORT_PIXELS_16BIT in the HAL's flags) pixels() data is read as native
 * uint16 words, each sent high byte first, as an SPI peripheral in 16-bit
 * frame mode does; commands stay bytes.
 *
 * DMA mock: a transfer completes (its bytes are decoded, then
 * fxl_port_transfer_done is called) after `dma_delay` later HAL calls
 * (wait/delay hooks included); 0 completes inside pixels(), as an interrupt
 * firing at once would.
 *
 * Wire record: every byte in order with its D/C state, resets and delays as
 * events (for exact-bytes tests), and a CRC-32 (IEEE 802.3, the zlib one)
 * of all command, parameter and pixel bytes on the wire.
 *
 * Host only (uses malloc). PNG output is not here: convert the image
 * from panel_emu_view() with png_io.
 */
#ifndef PANEL_EMU_H
#define PANEL_EMU_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/port.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef struct panel_emu_module {
    const char *name;             /* matches the driver preset's name */
    int ram_w, ram_h;             /* controller memory: columns x rows */
    int glass_x0, glass_y0;       /* visible area in memory (physical, no MADCTL) */
    int glass_w, glass_h;
    int glass_mirror_x;           /* module wires columns right to left */
    int glass_bgr;                /* colour filter is BGR: needs MADCTL.BGR */
    int glass_inverted;           /* IPS normally-black: needs INVON */
} panel_emu_module_t;

/* Known modules: "st7789-240x320" (alias "st7789"), "st7789-240x240",
 * "st7789-135x240", "ili9341-240x320" (alias "ili9341"). NULL if unknown. */
const panel_emu_module_t *panel_emu_module_find(const char *name);
/* The driver preset for the same name (or alias). NULL if unknown. */
const fxl_panel_preset_t *panel_emu_preset_find(const char *name);

/* Wire events: type in bits 16..23, value in bits 0..15. */
#define PANEL_EMU_EV_CMD 1u
#define PANEL_EMU_EV_DATA 2u
#define PANEL_EMU_EV_DELAY 3u         /* value = ms (saturated at 65535) */
#define PANEL_EMU_EV_RESET 4u         /* value = RESX level */
#define PANEL_EMU_EV(type, value) (((uint32_t)(type) << 16) | ((uint32_t)(value) & 0xFFFFu))

typedef struct panel_emu_xfer {
    const uint8_t *data;
    size_t bytes;
    uint8_t *snapshot;
    int ticks_left;
} panel_emu_xfer_t;

typedef struct panel_emu {
    panel_emu_module_t mod;
    uint16_t *ram;                /* ram_w * ram_h words, value = (first byte << 8) | second */
    fxl_panel_t *panel;           /* completions are reported here (may be NULL) */

    /* controller state */
    uint8_t madctl, colmod;
    int sleeping, display_on, inverted, resx;
    int xs, xe, ys, ye;           /* window, logical addresses, inclusive */
    int cx, cy;                   /* address counter */
    int writing;                  /* inside a RAMWR/RAMWRC data phase */
    int have_half;                /* odd byte pending */
    uint8_t half;

    /* time (advanced only by delay_ms) */
    uint64_t now_ms, reset_ms, slpout_ms;
    int slpout_seen;

    /* SPI: 0 = pixels() sends bytes in memory order, 1 = 16-bit frames */
    int spi16;

    /* DMA mock */
    int dma_delay;
    panel_emu_xfer_t xfer;        /* the driver keeps at most one in flight */
    int in_flight;

    /* wire record */
    uint32_t *log;
    size_t log_len, log_cap;
    int log_enabled;              /* 1 by default */
    uint32_t crc;                 /* CRC-32 of the wire bytes so far */
    uint64_t wire_bytes;

    /* counters */
    unsigned long cmds, transfers, completions, waits, pixels_written, writes_outside_glass;
    int errors;
    char first_error[160];
} panel_emu_t;

/* Create for a module; RAM is filled with `ram_fill`. Returns 0, or -1 on
 * bad arguments / no memory. */
int panel_emu_init(panel_emu_t *e, const panel_emu_module_t *mod, uint16_t ram_fill);
void panel_emu_free(panel_emu_t *e);
/* HAL whose callbacks drive this emulator (cmd, pixels, reset, delay_ms,
 * wait all set; clear the ones a test wants missing; flags
 * FXL_PORT_PIXELS_16BIT when spi16 is set). */
void panel_emu_hal(panel_emu_t *e, fxl_port_hal_t *hal);
/* Forget the wire record and CRC (state and RAM stay). */
void panel_emu_clear_log(panel_emu_t *e);
/* Complete every pending transfer now (as if time passed). */
void panel_emu_flush(panel_emu_t *e);

/* What the glass shows, native RGB565, glass_w x glass_h in the module's
 * own orientation: memory through the glass mapping, colour order and
 * inversion applied; black while asleep or off. */
void panel_emu_glass(const panel_emu_t *e, uint16_t *out);
/* The glass as seen by a viewer who turned the module by rotation * 90
 * degrees, i.e. in the orientation of a frame rendered for that rotation:
 * *w x *h = glass_w x glass_h, exchanged for odd rotations. out may be NULL
 * to query the size. Returns 0, -1 for a bad rotation. */
int panel_emu_view(const panel_emu_t *e, int rotation, uint16_t *out, int *w, int *h);

/* Map a logical address (as CASET/RASET address it under the current
 * MADCTL) to memory; returns 0, or -1 when outside the address space. */
int panel_emu_map(const panel_emu_t *e, int x, int y, int *col, int *row);

/* CRC-32 (IEEE, reflected, init/xorout 0xFFFFFFFF) update; start with 0. */
uint32_t panel_emu_crc32(uint32_t crc, const void *data, size_t n);

/* ---- one-call rendering for fixel-sim --panel ---------------------------- */

typedef struct panel_emu_result {
    int width, height;            /* frame size for the rotation */
    uint32_t wire_crc;            /* CRC-32 of every byte of init + frame */
    uint32_t frame_crc;           /* CRC-32 of the frame's bytes only (window + pixels) */
    uint64_t wire_bytes;
    unsigned long transfers;
    int bands;
    int protocol_errors;          /* emulator findings; 0 expected */
    int overflowed;               /* bin memory was too small (fallback used) */
    fxl_stats_t stats;            /* core counters summed over bands */
} panel_emu_result_t;

/* Frame size of a panel in a rotation. Returns 0, -1 for an unknown panel or
 * bad rotation. */
int panel_emu_frame_size(const char *panel, int rotation, int *w, int *h);

/* Initialise the named panel through the real driver, render `count`
 * triangles (vertices in frame coordinates of the rotated panel, each with
 * its draw state; band0/band1 are ignored) through the band renderer
 * (`band_rows` rows per band, 0 = 24; a HAL sending bytes, or 16-bit
 * frames where the build cannot draw byte-swapped bands: panel_spi16,
 * left_out.h; a depth band where the build has depth; dma_delay 2) into
 * the emulated panel, and write the view (panel_emu_view) into out, which
 * holds out_pixels >= width * height native RGB565 pixels. res may be NULL.
 * Returns the first fxl_status_t error, FXL_ERR_IO when the emulator found
 * protocol errors, FXL_ERR_ARG for an unknown panel or a small `out`. */
fxl_status_t panel_emu_render_scene(const char *panel, int rotation, int band_rows,
                                    const fxl_band_tri_t *tris, size_t count,
                                    uint16_t clear_rgb565, uint16_t *out, size_t out_pixels,
                                    panel_emu_result_t *res);

#ifdef __cplusplus
}
#endif
#endif

/* fixel/port.h - SPI (MIPI DCS) panels and band rendering with DMA double buffering.
 *
 * HAL. The caller fills a fxl_port_hal_t with callbacks and a `void *user`
 * context (no weak symbols, no vendor SDK; two panels = two HAL structs):
 *   cmd      blocking: D/C low, the command byte, D/C high, the n parameter
 *            bytes, in this order. Required.
 *   pixels   send `bytes` bytes of pixel data exactly as they are in memory
 *            (D/C high); with FXL_PORT_PIXELS_16BIT in `flags` instead
 *            bytes / 2 16-bit frames, one per uint16 of the (2-byte aligned)
 *            data, most significant bit first. May start a DMA and return
 *            at once; the transfer's end is then reported by calling
 *            fxl_port_transfer_done() once its last bit has left the SPI
 *            (a DMA-complete interrupt usually fires earlier, while the
 *            SPI still shifts: wait for it to be idle first, as
 *            docs/porting.md section 11 says; the driver may drive D/C
 *            low for the next command as soon as the count moves). With
 *            FXL_PORT_PIXELS_SYNC in `flags` the callback returns only when
 *            the bytes are out and the driver counts the completion itself.
 *            Required.
 *   reset    optional: drive the RESX pin to `level` (0 = in reset).
 *   delay_ms optional for drawing, required by fxl_panel_init (an init
 *            sequence without its datasheet delays leaves the panel in an
 *            undefined state, so init refuses with FXL_ERR_UNSUPPORTED).
 *   wait     optional idle hook called repeatedly while the driver waits for
 *            a transfer. Return FXL_OK to keep waiting, anything else to give
 *            up (the driver returns FXL_ERR_IO). NULL: the driver spins on
 *            the completion counter. A hook that sleeps must not sleep
 *            through a completion that came after the driver's last look:
 *            on Cortex-M use __WFE() (an exception return sets the event
 *            register, so WFE then returns at once), not a bare __WFI(),
 *            which would sleep until some other interrupt; for WFI, mask
 *            interrupts and test fxl_panel_busy() first (WFI still wakes on
 *            an interrupt that becomes pending while masked). An RTOS
 *            semaphore given by the interrupt is latched too. After a give-up
 *            the transfer still counts as in flight, so every call that waits
 *            gives up again. To recover, stop the DMA in the HAL, then either
 *            report the transfer over with fxl_port_transfer_done() or call
 *            fxl_panel_init() again. A completion that arrives after
 *            fxl_panel_init() but before the next fxl_panel_write() is
 *            absorbed (that write counts from it); one that arrives later
 *            is taken for that write's, so clear it in the HAL first.
 *            The band renderer needs nothing: it waits only for numbers
 *            in flight.
 * Callbacks return FXL_OK or a negative status; the driver turns a failure
 * into FXL_ERR_IO. The driver never calls cmd() or pixels() while a pixel
 * transfer of the same panel is in flight, so the HAL needs no queue (two
 * panels on one bus: wait_idle the other first, or make the HAL wait for the
 * bus; fxl_dcs_cmd, _window
 * and _run take a HAL, not a panel, and do not wait: call them only after
 * fxl_panel_wait_idle() returned FXL_OK).
 *
 * DMA / ISR contract. fxl_port_transfer_done(panel) must be called exactly
 * once per pixels() call that returned FXL_OK (not with FXL_PORT_PIXELS_SYNC).
 * It only increments a volatile 32-bit counter that the thread side reads
 * and only fxl_panel_init() writes (to 0), so it is safe from an interrupt
 * on any CPU with atomic aligned 32-bit stores (every Cortex-M). One bus:
 * transfers complete in the order they were started, so a count identifies
 * which buffers are free. The counters wrap after 2^32 transfers.
 *
 * Byte order. MIPI DCS panels take RGB565 big-endian (high byte first) with
 * COLMOD 0x55. A HAL that sends bytes (8-bit SPI frames) gets them from
 * FXL_PIXFMT_RGB565_SWAP targets on little-endian CPUs
 * (fxl_port_wire_format() picks it), so memory is already in wire order and
 * pixels() sends the buffer with no copy. A HAL that sends pixel data as
 * 16-bit SPI frames (each uint16 most significant bit first) sets
 * FXL_PORT_PIXELS_16BIT: then native RGB565 is wire order on any CPU.
 * fxl_panel_pixel_format() says which format a panel's HAL wants; the band
 * renderer draws in it. Colour order (RGB/BGR) is the MADCTL BGR bit, never
 * a pixel conversion.
 *
 * Rotation and RAM offsets are data (fxl_panel_preset_t): a MADCTL value and
 * an (x, y) offset per rotation 0/90/180/270. See docs/porting.md.
 *
 * Memory: the caller owns fxl_panel_t, fxl_band_t, band buffers, depth band,
 * triangle store and bin memory. Nothing here allocates or uses libc.
 */
#ifndef FIXEL_PORT_H
#define FIXEL_PORT_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/status.h"
#include "fixel/target.h"
#include "fixel/raster.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- HAL ---------------------------------------------------------------- */

#define FXL_PORT_PIXELS_SYNC 0x01u  /* pixels() is blocking: no completion call */
#define FXL_PORT_PIXELS_16BIT 0x02u /* pixels() sends 16-bit frames, MSB first: data
                                     * holds native uint16 pixels (cmd() still
                                     * sends bytes) */

typedef struct fxl_port_hal {
    fxl_status_t (*cmd)(void *user, uint8_t cmd, const uint8_t *params, size_t n);
    fxl_status_t (*pixels)(void *user, const void *data, size_t bytes);
    fxl_status_t (*reset)(void *user, int level);     /* optional */
    fxl_status_t (*delay_ms)(void *user, uint32_t ms); /* optional (see above) */
    fxl_status_t (*wait)(void *user);                  /* optional idle hook */
    void *user;
    uint32_t flags;                                    /* FXL_PORT_* */
} fxl_port_hal_t;

/* Zephyr-style wrappers: a NULL optional callback is FXL_ERR_UNSUPPORTED,
 * a failing one FXL_ERR_IO. */
static inline fxl_status_t fxl_port_reset(const fxl_port_hal_t *h, int level)
{
    if (h == NULL || h->reset == NULL) return FXL_ERR_UNSUPPORTED;
    return h->reset(h->user, level) == FXL_OK ? FXL_OK : FXL_ERR_IO;
}
static inline fxl_status_t fxl_port_delay_ms(const fxl_port_hal_t *h, uint32_t ms)
{
    if (h == NULL || h->delay_ms == NULL) return FXL_ERR_UNSUPPORTED;
    return h->delay_ms(h->user, ms) == FXL_OK ? FXL_OK : FXL_ERR_IO;
}
static inline fxl_status_t fxl_port_wait_hook(const fxl_port_hal_t *h)
{
    if (h == NULL || h->wait == NULL) return FXL_ERR_UNSUPPORTED;
    return h->wait(h->user) == FXL_OK ? FXL_OK : FXL_ERR_IO;
}

/* ---- MIPI DCS (port/mipi_dcs.c) ------------------------------------------ */

#define FXL_DCS_NOP     0x00u
#define FXL_DCS_SWRESET 0x01u /* then 5 ms before any command, 120 ms before SLPOUT */
#define FXL_DCS_SLPIN   0x10u
#define FXL_DCS_SLPOUT  0x11u /* then 5 ms before any command, 120 ms before SLPIN */
#define FXL_DCS_NORON   0x13u
#define FXL_DCS_INVOFF  0x20u
#define FXL_DCS_INVON   0x21u
#define FXL_DCS_DISPOFF 0x28u
#define FXL_DCS_DISPON  0x29u
#define FXL_DCS_CASET   0x2Au /* XS, XE: 16-bit big-endian, inclusive */
#define FXL_DCS_RASET   0x2Bu /* YS, YE: likewise */
#define FXL_DCS_RAMWR   0x2Cu /* pixel data from (XS, YS) */
#define FXL_DCS_MADCTL  0x36u
#define FXL_DCS_COLMOD  0x3Au
#define FXL_DCS_RAMWRC  0x3Cu /* pixel data continuing where the last write stopped */

#define FXL_MADCTL_MY  0x80u  /* mirror rows (page address) */
#define FXL_MADCTL_MX  0x40u  /* mirror columns */
#define FXL_MADCTL_MV  0x20u  /* exchange rows and columns (applied before the mirrors) */
#define FXL_MADCTL_ML  0x10u
#define FXL_MADCTL_BGR 0x08u  /* panel colour filter order B, G, R */
#define FXL_MADCTL_MH  0x04u

#define FXL_COLMOD_RGB565 0x55u /* 65K colours on both RGB and MCU interfaces, 16 bit/pixel */

/* One command of an init sequence: `n` parameter bytes, then `delay_ms`. */
typedef struct fxl_dcs_step {
    uint8_t cmd;
    uint8_t n;          /* <= 15 */
    uint8_t delay_ms;
    uint8_t params[15];
} fxl_dcs_step_t;

/* Send one command (FXL_ERR_ARG: NULL hal or cmd callback, params NULL with
 * n > 0). */
fxl_status_t fxl_dcs_cmd(const fxl_port_hal_t *hal, uint8_t cmd, const uint8_t *params, size_t n);
/* CASET/RASET with inclusive ends, then RAMWR. Coordinates are controller
 * addresses (offsets already added), 0..65535. FXL_ERR_ARG: NULL hal or
 * cmd callback; FXL_ERR_RANGE: x1 < x0 or y1 < y0 (nothing is sent). */
fxl_status_t fxl_dcs_window(const fxl_port_hal_t *hal, uint16_t x0, uint16_t y0, uint16_t x1,
                            uint16_t y1);
/* Run `count` steps, delaying after each one that asks for it. FXL_ERR_ARG
 * for NULL hal, cmd callback or steps with count > 0, and for a step of
 * more than 15 parameters (the steps before it are sent); a delay with
 * hal->delay_ms NULL is FXL_ERR_UNSUPPORTED (the step itself was sent). */
fxl_status_t fxl_dcs_run(const fxl_port_hal_t *hal, const fxl_dcs_step_t *steps, size_t count);

/* ---- panels -------------------------------------------------------------- */

typedef struct fxl_port_offset {
    uint16_t x, y;      /* added to window coordinates in this rotation */
} fxl_port_offset_t;

#define FXL_PANEL_BGR    0x01u /* set MADCTL.BGR (the glass is BGR) */
#define FXL_PANEL_INVERT 0x02u /* send INVON (IPS glass that is normally inverted) */

/* Everything that differs between panel modules, as data. To configure a
 * module without editing the library, copy a preset and change fields. */
typedef struct fxl_panel_preset {
    const char *name;
    uint16_t width, height;          /* visible pixels at rotation 0 */
    uint8_t madctl[4];               /* MY/MX/MV per rotation (BGR is added from flags) */
    fxl_port_offset_t offset[4];     /* RAM offset per rotation */
    uint8_t flags;                   /* FXL_PANEL_* */
    uint8_t colmod;                  /* FXL_COLMOD_RGB565; bits 2..0 (the MCU interface's
                                      * format) must be 0x5, 16 bits a pixel: fixel sends
                                      * RGB565 only (fxl_panel_init: FXL_ERR_UNSUPPORTED) */
    const fxl_dcs_step_t *init;      /* controller-specific steps after SLPOUT */
    uint8_t init_count;
} fxl_panel_preset_t;

/* port/st7789.c */
extern const fxl_panel_preset_t fxl_st7789_240x320;
extern const fxl_panel_preset_t fxl_st7789_240x240; /* 240x240 glass in 240x320 RAM */
extern const fxl_panel_preset_t fxl_st7789_135x240; /* 135x240 glass at RAM (52, 40) */
/* port/ili9341.c */
extern const fxl_panel_preset_t fxl_ili9341_240x320;

typedef struct fxl_panel {
    fxl_port_hal_t hal;                /* copied at init */
    const fxl_panel_preset_t *preset;
    uint8_t rotation;                  /* 0..3 = 0, 90, 180, 270 degrees */
    int32_t width, height;             /* visible pixels in this rotation */
    uint32_t started;                  /* pixel transfers started */
    volatile uint32_t done;            /* completed: incremented only by fxl_port_transfer_done,
                                        * zeroed by fxl_panel_init */
} fxl_panel_t;

/* Called by the HAL (DMA interrupt) when a pixels() transfer has ended. */
void fxl_port_transfer_done(fxl_panel_t *panel);

/* Pixel format whose memory layout is wire order on this CPU when pixels()
 * sends bytes: FXL_PIXFMT_RGB565_SWAP on little-endian CPUs,
 * FXL_PIXFMT_RGB565 otherwise. */
fxl_pixfmt_t fxl_port_wire_format(void);

/* Pixel format whose memory layout is what this panel's HAL puts on the
 * wire: FXL_PIXFMT_RGB565 with FXL_PORT_PIXELS_16BIT in hal.flags, else
 * fxl_port_wire_format(). NULL: fxl_port_wire_format(). */
fxl_pixfmt_t fxl_panel_pixel_format(const fxl_panel_t *panel);

/* Reset (RESX pulse when hal->reset exists, else 5 ms then SWRESET: a retry
 * after a failed init keeps the gap its SWRESET or SLPOUT needs), SLPOUT, the
 * preset's steps, COLMOD, MADCTL for `rotation`, INVON/INVOFF, NORON,
 * DISPON, with the datasheet delays. The HAL is copied; the preset is
 * referenced and must outlive the panel (a modified copy of a preset needs
 * static storage too). Forgets every transfer (started = done = 0): stop
 * any DMA of this panel first. Errors: FXL_ERR_ARG (NULL panel, hal,
 * preset, hal->cmd or hal->pixels, rotation > 3, bad preset: a zero size,
 * an offset plus a side (either side, with either offset of any rotation)
 * above 65535, a step of more than 15 parameters; nothing is
 * sent), FXL_ERR_UNSUPPORTED (hal->delay_ms NULL; nothing is sent),
 * FXL_ERR_IO. After FXL_ERR_IO the panel is refused (FXL_ERR_ARG) by every
 * call but fxl_panel_init until an init succeeds. */
fxl_status_t fxl_panel_init(fxl_panel_t *panel, const fxl_port_hal_t *hal,
                            const fxl_panel_preset_t *preset, unsigned rotation);
/* Change rotation (MADCTL); width/height follow. Waits for transfers. */
fxl_status_t fxl_panel_set_rotation(fxl_panel_t *panel, unsigned rotation);
/* Partial update: set the window [x, x+w) x [y, y+h) of the visible area
 * (offsets of the rotation added) and start RAMWR. Waits for transfers.
 * FXL_ERR_RANGE when the rectangle is empty or leaves the visible area. */
fxl_status_t fxl_panel_set_window(fxl_panel_t *panel, int32_t x, int32_t y, int32_t w, int32_t h);
/* Send pixel bytes after fxl_panel_set_window (in the layout of
 * fxl_panel_pixel_format). Waits for the previous transfer, starts this one
 * and returns; `data` must stay unchanged until fxl_panel_wait_idle (or the
 * next panel call) returns. FXL_ERR_ARG on NULL/odd/zero bytes, and on
 * data at an odd address when the HAL sends 16-bit frames. */
fxl_status_t fxl_panel_write(fxl_panel_t *panel, const void *data, size_t bytes);
/* Wait until every started transfer has completed (calls hal->wait). */
fxl_status_t fxl_panel_wait_idle(fxl_panel_t *panel);
/* Wait until transfer number `seq` has completed: the value of
 * panel->started right after the fxl_panel_write that started it (for your
 * own double buffering). A number not in flight returns at once: one that
 * completed, however long ago, one not started yet, or 0 before the first
 * write. fxl_panel_init numbers transfers from 1 again, so a number kept
 * from before it names whichever transfer has that number since, and is
 * waited for while that one is in flight. */
fxl_status_t fxl_panel_wait_done(fxl_panel_t *panel, uint32_t seq);
/* 1 while a transfer started by fxl_panel_write has not completed, else 0
 * (also for NULL, and for a zeroed panel fxl_panel_init has not set up).
 * Never waits: for a wait hook that sleeps with interrupts masked, and for
 * work between transfers. */
int fxl_panel_busy(const fxl_panel_t *panel);
/* DISPON / DISPOFF. */
fxl_status_t fxl_panel_display(fxl_panel_t *panel, int on);

/* ---- band rendering (port/band.c) ----------------------------------------
 *
 * A frame is drawn as horizontal bands of `band_rows` rows into two band
 * buffers: band k is sent (DMA) while band k+1 is rendered into the other
 * buffer; a buffer is rendered into only after its transfer completed.
 * RAM for a W x H frame: 2 * W * band_rows * 2 bytes of band buffers, plus
 * W * band_rows * 2 bytes of depth (optional), plus the scene store:
 * FXL_BAND_TRI_BYTES per triangle and FXL_BAND_BIN_BYTES(bands, refs) of bins.
 *
 * Usage per frame: fxl_band_begin, fxl_band_add for every triangle (the
 * vertices are copied, the draw state is referenced and must live until
 * fxl_band_render returns), fxl_band_render.
 *
 * Binning: each triangle is listed in every band its y extent touches (one
 * bin entry per band touched), in submission order. When the bin memory
 * cannot hold a triangle's entries, it and every later triangle are instead
 * tested against each band by their stored band range (slower for large
 * scenes, the same image: submission order is kept in every band).
 */

typedef struct fxl_band_tri {
    fxl_vertex_t v[3];
    const fxl_draw_t *draw;
    uint16_t band0, band1;   /* bands touched, inclusive */
} fxl_band_tri_t;

typedef struct fxl_band_bin {
    uint16_t tri;            /* triangle index (list headers: first entry) */
    uint16_t next;           /* next entry (list headers: last entry) */
} fxl_band_bin_t;

#define FXL_BAND_NONE 0xFFFFu
#define FXL_BAND_MAX_TRIS 65535u
#define FXL_BAND_TRI_BYTES ((uint32_t)sizeof(fxl_band_tri_t))
/* Bin entries: one list header per band plus one entry per (triangle, band)
 * reference. Referencing every band of each triangle: refs = tris * bands. */
#define FXL_BAND_BIN_ENTRIES(bands, refs) ((uint32_t)(bands) + (uint32_t)(refs))
#define FXL_BAND_BIN_BYTES(bands, refs) (FXL_BAND_BIN_ENTRIES(bands, refs) * 4u)

typedef struct fxl_band {
    fxl_panel_t *panel;
    uint16_t *buf[2];
    uint16_t *depth;         /* one band, or NULL */
    int32_t width, height;   /* frame = panel's visible area at init */
    int32_t band_rows, band_count;
    fxl_band_tri_t *tris;
    uint32_t tri_cap, tri_count;
    fxl_band_bin_t *bins;
    uint32_t bin_cap, bin_used;
    uint32_t first_unbinned; /* triangles from here on use the fallback scan */
    const fxl_draw_t *checked; /* the draw fxl_band_add last found valid this frame */
    uint32_t seq[2];         /* transfer number that last sent buf[i]; one not in flight
                              * (0, completed) is not waited for. Bind again
                              * (fxl_band_init) after re-initialising the panel:
                              * its numbers restart at 1. */
} fxl_band_t;

/* Bind the band renderer to an initialised panel (frame = its current
 * visible size; after fxl_panel_set_rotation changes it, fxl_band_render
 * says FXL_ERR_ARG until fxl_band_init runs again). buf0/buf1 hold width *
 * band_rows pixels each; depth is NULL or width * band_rows entries.
 * tri_cap and bin_cap count entries of tris and bins (not bytes: see
 * FXL_BAND_TRI_BYTES, FXL_BAND_BIN_BYTES), and at most 65535 of each are
 * used (16-bit links). bins may be NULL with bin_cap 0 (fallback
 * only). Errors: FXL_ERR_ARG (NULL/zero, buf0 == buf1, buffers that share a
 * byte (buf0, buf1, depth, tris, bins over the sizes above), buf0, buf1 or
 * depth at an odd address, a panel whose init failed), FXL_ERR_RANGE (band_rows > height,
 * band_rows or width > FXL_TARGET_MAX_DIM, or a last band starting below frame row
 * FXL_TARGET_MAX_ORIGIN), FXL_ERR_NOMEM (bin_cap below one header per band
 * while non-zero), FXL_ERR_UNSUPPORTED (a depth band in a build without
 * FXL_HAVE_DEPTH). On an error *b is left unchanged. */
fxl_status_t fxl_band_init(fxl_band_t *b, fxl_panel_t *panel, uint16_t *buf0, uint16_t *buf1,
                           uint16_t *depth, int32_t band_rows, fxl_band_tri_t *tris,
                           uint32_t tri_cap, fxl_band_bin_t *bins, uint32_t bin_cap);
/* Start a new scene (forget the triangles of the last frame). */
fxl_status_t fxl_band_begin(fxl_band_t *b);
/* Add one triangle. Triangles entirely above or below the frame are dropped
 * (FXL_OK). Errors (the triangle is not added): FXL_ERR_ARG (NULL), what
 * fxl_draw_check says of the draw on a band of this frame (in
 * fxl_panel_pixel_format, with the depth band if any: bad settings, or a
 * draw this build left out), FXL_ERR_RANGE (an inv_w of 0), FXL_ERR_NOMEM (triangle store
 * full). The check is skipped for the draw this function last found valid
 * (the same address): a draw changed after its first add, which the frame
 * must not do, is checked again per band instead, when the frame is
 * already being sent (fxl_band_render). */
fxl_status_t fxl_band_add(fxl_band_t *b, const fxl_vertex_t v[3], const fxl_draw_t *draw);
/* Render and send the frame: full-frame window, RAMWR, then each band
 * cleared to `clear_rgb565` (native RGB565), its depth cleared, its
 * triangles drawn, and sent. Returns after the last transfer completed.
 * Every band is sent even when a triangle fails; the first draw error is
 * returned. stats (may be NULL) accumulates the core counters of all bands. */
fxl_status_t fxl_band_render(fxl_band_t *b, uint16_t clear_rgb565, fxl_stats_t *stats);
/* True when the last scene needed the fallback scan (bin memory too small). */
int fxl_band_overflowed(const fxl_band_t *b);

#ifdef __cplusplus
}
#endif
#endif

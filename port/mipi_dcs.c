/* port/mipi_dcs.c - what every MIPI DCS panel shares: commands, windows,
 * MADCTL rotation, the init flow, pixel transfers and DMA completion.
 * Controller differences (init steps, MADCTL per rotation, RAM offsets) are
 * data in the presets of st7789.c / ili9341.c. Contract: include/fixel/port.h.
 */
#include "fixel/port.h"

/* Datasheet timings (the SWRESET and SLPOUT command pages of the ST7789V
 * and ILI9341 datasheets agree): after a RESX pulse or SWRESET the controller needs 5 ms before it
 * takes commands and up to 120 ms before SLPOUT (its reset-cancel sequence
 * reloads the registers); after SLPOUT 5 ms before the next command, and
 * the boosters settle within 120 ms. We wait the 120 ms in both places. */
#define RESET_PULSE_MS 1u   /* RESX low >= 10 us */
#define CMD_GAP_MS 5u       /* after SWRESET or SLPOUT, before the next command */
#define RESET_WAIT_MS 120u
#define SLPOUT_WAIT_MS 120u

static fxl_status_t hal_cmd(const fxl_port_hal_t *hal, uint8_t cmd, const uint8_t *p, size_t n)
{
    return hal->cmd(hal->user, cmd, p, n) == FXL_OK ? FXL_OK : FXL_ERR_IO;
}

fxl_status_t fxl_dcs_cmd(const fxl_port_hal_t *hal, uint8_t cmd, const uint8_t *params, size_t n)
{
    if (hal == NULL || hal->cmd == NULL || (params == NULL && n > 0)) return FXL_ERR_ARG;
    return hal_cmd(hal, cmd, params, n);
}

/* Start and end address, each 16-bit big-endian as DCS specifies. */
static void put_range(uint8_t out[4], uint16_t a, uint16_t b)
{
    out[0] = (uint8_t)(a >> 8);
    out[1] = (uint8_t)(a & 0xFFu);
    out[2] = (uint8_t)(b >> 8);
    out[3] = (uint8_t)(b & 0xFFu);
}

fxl_status_t fxl_dcs_window(const fxl_port_hal_t *hal, uint16_t x0, uint16_t y0, uint16_t x1,
                            uint16_t y1)
{
    uint8_t p[4];
    fxl_status_t st;
    if (hal == NULL || hal->cmd == NULL) return FXL_ERR_ARG;
    if (x1 < x0 || y1 < y0) return FXL_ERR_RANGE;
    put_range(p, x0, x1);
    st = hal_cmd(hal, FXL_DCS_CASET, p, 4);
    if (st != FXL_OK) return st;
    put_range(p, y0, y1);
    st = hal_cmd(hal, FXL_DCS_RASET, p, 4);
    if (st != FXL_OK) return st;
    return hal_cmd(hal, FXL_DCS_RAMWR, NULL, 0);
}

fxl_status_t fxl_dcs_run(const fxl_port_hal_t *hal, const fxl_dcs_step_t *steps, size_t count)
{
    size_t i;
    if (hal == NULL || hal->cmd == NULL || (steps == NULL && count > 0)) return FXL_ERR_ARG;
    for (i = 0; i < count; i++) {
        fxl_status_t st;
        if (steps[i].n > sizeof(steps[i].params)) return FXL_ERR_ARG;
        st = hal_cmd(hal, steps[i].cmd, steps[i].params, steps[i].n);
        if (st != FXL_OK) return st;
        if (steps[i].delay_ms > 0) {
            st = fxl_port_delay_ms(hal, steps[i].delay_ms);
            if (st != FXL_OK) return st;
        }
    }
    return FXL_OK;
}

/* ---- completion ---------------------------------------------------------- */

void fxl_port_transfer_done(fxl_panel_t *panel)
{
    /* The only writer of `done` while transfers run (fxl_panel_init zeroes
     * it with the DMA stopped): a plain read-modify-write of a volatile
     * word is race-free because the thread side only reads it. */
    if (panel != NULL) panel->done = panel->done + 1u;
}

fxl_pixfmt_t fxl_port_wire_format(void)
{
    /* The wire wants the high byte first; on a little-endian CPU that is the
     * byte-swapped layout. Compilers fold this probe to a constant. */
    const uint16_t probe = 0x0102u;
    const unsigned char *first = (const unsigned char *)&probe;
    return first[0] == 0x02u ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
}

fxl_pixfmt_t fxl_panel_pixel_format(const fxl_panel_t *panel)
{
    /* 16-bit frames shift each halfword out MSB first whatever the CPU's
     * byte order, so the pixel values themselves are what go out. */
    if (panel != NULL && (panel->hal.flags & FXL_PORT_PIXELS_16BIT)) return FXL_PIXFMT_RGB565;
    return fxl_port_wire_format();
}

/* Is transfer number `seq` in flight, i.e. in (done, started]? Unsigned
 * differences, so the counters may wrap after 2^32 transfers and a number
 * from long ago (or from before fxl_panel_init zeroed the counters) is
 * simply not in flight: comparing seq with done alone would call anything
 * 2^31 or more behind `done` pending and wait forever. `done` ahead of
 * `started` (a completion with no transfer: a late interrupt after
 * fxl_panel_init, one reported twice) means nothing is in flight. */
static int in_flight(const fxl_panel_t *p, uint32_t seq)
{
    const uint32_t done = p->done;
    const uint32_t n = p->started - done; /* transfers in flight: 0 or 1 */
    const uint32_t age = seq - done;      /* 1..n: started, not completed */
    return n - 1u < 0x7FFFFFFFu && age != 0u && age <= n; /* n in [1, 2^31) */
}

static fxl_status_t wait_for(fxl_panel_t *p, uint32_t seq)
{
    while (in_flight(p, seq)) {
        if (p->hal.wait != NULL && fxl_port_wait_hook(&p->hal) != FXL_OK) return FXL_ERR_IO;
    }
    return FXL_OK;
}

/* ---- panel --------------------------------------------------------------- */

static int preset_ok(const fxl_panel_preset_t *pr)
{
    unsigned r;
    if (pr->width == 0 || pr->height == 0 || (pr->init == NULL && pr->init_count > 0)) return 0;
    /* Every step is checked before the first command goes out: one found
     * bad by fxl_dcs_run would leave the controller half-initialised. */
    for (r = 0; r < pr->init_count; r++)
        if (pr->init[r].n > sizeof(pr->init[r].params)) return 0;
    for (r = 0; r < 4; r++) {
        /* Keep every controller address inside 16 bits. */
        if ((uint32_t)pr->offset[r].x + pr->width > 65535u ||
            (uint32_t)pr->offset[r].y + pr->width > 65535u ||
            (uint32_t)pr->offset[r].x + pr->height > 65535u ||
            (uint32_t)pr->offset[r].y + pr->height > 65535u)
            return 0;
    }
    return 1;
}

static uint8_t madctl_of(const fxl_panel_preset_t *pr, unsigned rotation)
{
    uint8_t m = (uint8_t)(pr->madctl[rotation] & (uint8_t)~FXL_MADCTL_BGR);
    if (pr->flags & FXL_PANEL_BGR) m = (uint8_t)(m | FXL_MADCTL_BGR);
    return m;
}

static void apply_rotation(fxl_panel_t *p, unsigned rotation)
{
    p->rotation = (uint8_t)rotation;
    /* Odd rotations exchange rows and columns (MV). */
    if (rotation & 1u) {
        p->width = p->preset->height;
        p->height = p->preset->width;
    } else {
        p->width = p->preset->width;
        p->height = p->preset->height;
    }
}

fxl_status_t fxl_panel_init(fxl_panel_t *panel, const fxl_port_hal_t *hal,
                            const fxl_panel_preset_t *preset, unsigned rotation)
{
    fxl_status_t st;
    uint8_t b;
    if (panel == NULL || hal == NULL || preset == NULL || hal->cmd == NULL || hal->pixels == NULL)
        return FXL_ERR_ARG;
    if (rotation > 3u || !preset_ok(preset)) return FXL_ERR_ARG;
    if (hal->delay_ms == NULL) return FXL_ERR_UNSUPPORTED;
    /* COLMOD bits 2..0 are the MCU interface's pixel format: the drivers
     * and the band renderer send RGB565 (16 bits, 0x5) only */
    if ((preset->colmod & 0x07u) != (FXL_COLMOD_RGB565 & 0x07u)) return FXL_ERR_UNSUPPORTED;
    panel->hal = *hal;
    panel->preset = preset;
    panel->started = 0;
    panel->done = 0;
    apply_rotation(panel, rotation);
    hal = &panel->hal;

    if (hal->reset != NULL) {
        st = fxl_port_reset(hal, 1);
        if (st == FXL_OK) st = fxl_port_delay_ms(hal, RESET_PULSE_MS);
        if (st == FXL_OK) st = fxl_port_reset(hal, 0);
        if (st == FXL_OK) st = fxl_port_delay_ms(hal, RESET_PULSE_MS);
        if (st == FXL_OK) st = fxl_port_reset(hal, 1);
    } else {
        /* A command is the one reset that must keep the 5 ms gap: an init
         * that failed (a refused delay) right after its SWRESET or SLPOUT,
         * then retried at once, would send this SWRESET inside that gap,
         * where the controller may ignore it. A RESX pulse needs no gap. */
        st = fxl_port_delay_ms(hal, CMD_GAP_MS);
        if (st == FXL_OK) st = hal_cmd(hal, FXL_DCS_SWRESET, NULL, 0);
    }
    if (st == FXL_OK) st = fxl_port_delay_ms(hal, RESET_WAIT_MS);
    if (st == FXL_OK) st = hal_cmd(hal, FXL_DCS_SLPOUT, NULL, 0);
    if (st == FXL_OK) st = fxl_port_delay_ms(hal, SLPOUT_WAIT_MS);
    if (st == FXL_OK) st = fxl_dcs_run(hal, preset->init, preset->init_count);
    b = preset->colmod;
    if (st == FXL_OK) st = hal_cmd(hal, FXL_DCS_COLMOD, &b, 1);
    b = madctl_of(preset, rotation);
    if (st == FXL_OK) st = hal_cmd(hal, FXL_DCS_MADCTL, &b, 1);
    if (st == FXL_OK)
        st = hal_cmd(hal, (preset->flags & FXL_PANEL_INVERT) ? FXL_DCS_INVON : FXL_DCS_INVOFF, NULL, 0);
    if (st == FXL_OK) st = hal_cmd(hal, FXL_DCS_NORON, NULL, 0);
    if (st == FXL_OK) st = hal_cmd(hal, FXL_DCS_DISPON, NULL, 0);
    /* A panel whose init failed part-way is in no known state: every call
     * but fxl_panel_init refuses it (FXL_ERR_ARG) until an init succeeds. */
    if (st != FXL_OK) panel->preset = NULL;
    return st;
}

fxl_status_t fxl_panel_wait_idle(fxl_panel_t *panel)
{
    if (panel == NULL || panel->preset == NULL) return FXL_ERR_ARG;
    return wait_for(panel, panel->started);
}

int fxl_panel_busy(const fxl_panel_t *panel)
{
    if (panel == NULL || panel->preset == NULL) return 0;
    return in_flight(panel, panel->started);
}

fxl_status_t fxl_panel_wait_done(fxl_panel_t *panel, uint32_t seq)
{
    if (panel == NULL || panel->preset == NULL) return FXL_ERR_ARG;
    return wait_for(panel, seq);
}

fxl_status_t fxl_panel_set_rotation(fxl_panel_t *panel, unsigned rotation)
{
    fxl_status_t st;
    uint8_t b;
    if (panel == NULL || panel->preset == NULL || rotation > 3u) return FXL_ERR_ARG;
    st = fxl_panel_wait_idle(panel);
    if (st != FXL_OK) return st;
    b = madctl_of(panel->preset, rotation);
    st = hal_cmd(&panel->hal, FXL_DCS_MADCTL, &b, 1);
    if (st == FXL_OK) apply_rotation(panel, rotation);
    return st;
}

fxl_status_t fxl_panel_set_window(fxl_panel_t *panel, int32_t x, int32_t y, int32_t w, int32_t h)
{
    fxl_status_t st;
    const fxl_port_offset_t *off;
    if (panel == NULL || panel->preset == NULL) return FXL_ERR_ARG;
    /* Written so that no sum can overflow: w <= width - x with x >= 0. */
    if (x < 0 || y < 0 || w <= 0 || h <= 0 || x >= panel->width || y >= panel->height ||
        w > panel->width - x || h > panel->height - y)
        return FXL_ERR_RANGE;
    st = fxl_panel_wait_idle(panel);
    if (st != FXL_OK) return st;
    off = &panel->preset->offset[panel->rotation];
    /* preset_ok() keeps offset + side <= 65535. */
    return fxl_dcs_window(&panel->hal, (uint16_t)(off->x + x), (uint16_t)(off->y + y),
                          (uint16_t)(off->x + x + w - 1), (uint16_t)(off->y + y + h - 1));
}

fxl_status_t fxl_panel_write(fxl_panel_t *panel, const void *data, size_t bytes)
{
    fxl_status_t st;
    if (panel == NULL || panel->preset == NULL || data == NULL || bytes == 0 || (bytes & 1u))
        return FXL_ERR_ARG;
    /* A 16-bit HAL reads the data as uint16: port.h promises it 2-byte
     * alignment (misaligned, a Cortex-M0+ faults). (uintptr_t is optional
     * in C99; without it the check is the caller's.) */
#ifdef UINTPTR_MAX
    if ((panel->hal.flags & FXL_PORT_PIXELS_16BIT) && ((uintptr_t)data & 1u)) return FXL_ERR_ARG;
#endif
    /* One DMA channel, and D/C must not change under a running transfer. */
    st = fxl_panel_wait_idle(panel);
    if (st != FXL_OK) return st;
    {
        /* A completion with no transfer left `done` ahead: count from it,
         * or this transfer would look complete while on the wire and the
         * next write would start under it. */
        const uint32_t done = panel->done;
        if (panel->started - done > 0x7FFFFFFFu) panel->started = done;
    }
    panel->started++;
    if (panel->hal.pixels(panel->hal.user, data, bytes) != FXL_OK) {
        /* Nothing is in flight after a refused start: take the number back
         * so later waits do not hang on a completion that never comes. */
        panel->started--;
        return FXL_ERR_IO;
    }
    if (panel->hal.flags & FXL_PORT_PIXELS_SYNC) fxl_port_transfer_done(panel);
    return FXL_OK;
}

fxl_status_t fxl_panel_display(fxl_panel_t *panel, int on)
{
    fxl_status_t st;
    if (panel == NULL || panel->preset == NULL) return FXL_ERR_ARG;
    st = fxl_panel_wait_idle(panel);
    if (st != FXL_OK) return st;
    return hal_cmd(&panel->hal, on ? FXL_DCS_DISPON : FXL_DCS_DISPOFF, NULL, 0);
}

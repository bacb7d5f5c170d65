/* fw_app.c - see fw_app.h. */
#include "fw_app.h"

/* Scene list of the run: the rotating cube in three frames, the issue-7
 * front-end scenes, the benchmark floor, and the cube and floor once more
 * with the fast span loops (point sampling, no mips). */
const fw_frame_t fw_frames[] = {
    {FW_SCENE_CUBE, 0},  {FW_SCENE_CUBE, 1},       {FW_SCENE_CUBE, 2},
    {FW_SCENE_SPHERE, 0}, {FW_SCENE_SPHERE, 1},    {FW_SCENE_LIT, 0},
    {FW_SCENE_FLOOR, 0}, {FW_SCENE_CUBE_POINT, 0}, {FW_SCENE_FLOOR_POINT, 0},
};
const uint32_t fw_frame_count = (uint32_t)(sizeof(fw_frames) / sizeof(fw_frames[0]));

/* ---- markers ------------------------------------------------------------------
 * Kept out of line and non-empty so the compiler can neither inline nor
 * merge them: the measuring script needs their addresses in the trace. */
#if defined(__GNUC__)
#define FW_NOINLINE __attribute__((noinline))
#define FW_BARRIER() __asm__ volatile("" ::: "memory")
#else
#define FW_NOINLINE
#define FW_BARRIER() ((void)0)
#endif

FW_NOINLINE void fw_mark_frame(void)
{
    FW_BARRIER();
}

FW_NOINLINE void fw_mark_render(void)
{
    FW_BARRIER();
}

/* ---- mock SPI ----------------------------------------------------------------
 * Every function of the mock is named spi_mock_*: frame_time.py leaves their
 * instructions out of the render counts (on hardware the DMA does this work). */

static void spi_mock_table(fw_spi_t *m)
{
    uint32_t i, c;
    int k;
    for (i = 0; i < 256u; i++) {
        c = i;
        for (k = 0; k < 8; k++) c = (c >> 1) ^ (0xEDB88320u & (0u - (c & 1u)));
        m->table[i] = c;
    }
}

static uint32_t spi_mock_crc(const fw_spi_t *m, uint32_t crc, const uint8_t *p, uint32_t n)
{
    while (n--) crc = (crc >> 8) ^ m->table[(crc ^ *p++) & 0xFFu];
    return crc;
}

static void spi_mock_wire(fw_spi_t *m, const uint8_t *p, uint32_t n)
{
    m->wire_crc = spi_mock_crc(m, m->wire_crc, p, n);
    m->wire_bytes += n;
}

static fxl_status_t spi_mock_cmd(void *user, uint8_t cmd, const uint8_t *params, size_t n)
{
    fw_spi_t *m = (fw_spi_t *)user;
    if (m->dma_src != (const uint8_t *)0) return FXL_ERR_IO; /* the driver promised not to */
    spi_mock_wire(m, &cmd, 1);
    if (n > 0) spi_mock_wire(m, params, (uint32_t)n);
    return FXL_OK;
}

static fxl_status_t spi_mock_pixels(void *user, const void *data, size_t bytes)
{
    fw_spi_t *m = (fw_spi_t *)user;
    if (m->dma_src != (const uint8_t *)0) return FXL_ERR_IO;
    m->dma_src = (const uint8_t *)data; /* "start the DMA" */
    m->dma_len = (uint32_t)bytes;
    return FXL_OK;
}

static fxl_status_t spi_mock_wait(void *user)
{
    /* The "DMA interrupt": the bytes leave, completion is reported. */
    fw_spi_t *m = (fw_spi_t *)user;
    if (m->dma_src != (const uint8_t *)0) {
        spi_mock_wire(m, m->dma_src, m->dma_len);
        m->pixel_crc = spi_mock_crc(m, m->pixel_crc, m->dma_src, m->dma_len);
        if (m->capture != (uint8_t *)0) {
            uint32_t i;
            for (i = 0; i < m->dma_len && m->pixel_bytes + i < m->capture_cap; i++)
                m->capture[m->pixel_bytes + i] = m->dma_src[i];
        }
        m->pixel_bytes += m->dma_len;
        m->transfers++;
        m->dma_src = (const uint8_t *)0;
        fxl_port_transfer_done(m->panel);
    }
    return FXL_OK;
}

static fxl_status_t spi_mock_reset(void *user, int level)
{
    (void)user;
    (void)level;
    return FXL_OK;
}

static fxl_status_t spi_mock_delay(void *user, uint32_t ms)
{
    (void)user;
    (void)ms;
    return FXL_OK;
}

static void spi_mock_restart(fw_spi_t *m)
{
    m->wire_crc = m->pixel_crc = 0xFFFFFFFFu;
    m->wire_bytes = m->pixel_bytes = m->transfers = 0;
}

/* ---- application --------------------------------------------------------------- */

fxl_status_t fw_app_init(fw_app_t *a)
{
    fxl_status_t st;
    if (a == (fw_app_t *)0) return FXL_ERR_ARG;
    spi_mock_table(&a->spi);
    spi_mock_restart(&a->spi);
    a->spi.dma_src = (const uint8_t *)0;
    a->spi.dma_len = 0;
    a->spi.panel = &a->panel;
    a->spi.capture = (uint8_t *)0;
    a->spi.capture_cap = 0;
    a->hal.cmd = spi_mock_cmd;
    a->hal.pixels = spi_mock_pixels;
    a->hal.reset = spi_mock_reset;
    a->hal.delay_ms = spi_mock_delay;
    a->hal.wait = spi_mock_wait;
    a->hal.user = &a->spi;
    a->hal.flags = 0;
    /* Rotation 1 (90 degrees) turns the 240x320 module into a 320 x 240 frame. */
    st = fxl_panel_init(&a->panel, &a->hal, &fxl_st7789_240x320, 1);
    a->init_crc = ~a->spi.wire_crc;
    a->init_bytes = a->spi.wire_bytes;
    if (st != FXL_OK) return st;
    if (a->panel.width != FW_WIDTH || a->panel.height != FW_HEIGHT) return FXL_ERR_RANGE;
    /* Every scene is one convex mesh with back faces culled, or one quad:
     * the same image with or without depth, so a build without
     * FXL_HAVE_DEPTH draws them without a depth band. */
    st = fxl_band_init(&a->band, &a->panel, a->band_a, a->band_b, FW_DEPTH_BAND(a), FW_BAND_ROWS, a->tris,
                       FW_TRI_CAP, a->bins, FW_BIN_CAP);
    if (st != FXL_OK) return st;
    return fw_scenes_init(&a->scenes);
}

typedef struct emit_ctx {
    fxl_band_t *band;
    const fxl_draw_t *draw;
    uint32_t count;
} emit_ctx_t;

/* The front end's output goes to the band renderer's store, binned once. */
static fxl_status_t emit_to_band(void *user, const fxl_vertex_t tri[3])
{
    emit_ctx_t *c = (emit_ctx_t *)user;
    c->count++;
    return fxl_band_add(c->band, tri, c->draw);
}

fxl_status_t fw_app_frame(fw_app_t *a, int scene, uint32_t frame, fw_result_t *r)
{
    emit_ctx_t ctx;
    fxl_status_t st, st2;
    if (a == (fw_app_t *)0 || r == (fw_result_t *)0) return FXL_ERR_ARG;
    r->stats.triangles = r->stats.drawn = r->stats.culled_degenerate = 0;
    r->stats.culled_outside = r->stats.culled_backface = 0;
    r->stats.pixels = r->stats.spans = r->stats.divisions = r->stats.generic = 0;
    spi_mock_restart(&a->spi);
    fw_mark_frame();
    /* the band first: after a failed set-up the frame below renders
     * empty, not the previous frame's triangles with a half-set draw */
    st = fxl_band_begin(&a->band);
    if (st == FXL_OK) st = fw_scene_setup(&a->scenes, scene, frame, a->panel.width, a->panel.height, &a->view);
    if (st == FXL_OK) st = fxl_pipeline_set_vertex_cache(&a->view.pipe, a->vcache, FW_VCACHE_ENTRIES);
    ctx.band = &a->band;
    ctx.draw = &a->view.draw;
    ctx.count = 0;
    if (st == FXL_OK) st = fxl_pipeline_emit(&a->view.pipe, &a->view.mesh, emit_to_band, &ctx, &r->stats);
    fw_mark_render();
    /* Render and send even after an error: the panel never stays in a
     * half-written frame, and the CRC then shows that something differs. */
    st2 = fxl_band_render(&a->band, a->view.clear_rgb565, &r->stats);
    r->wire_crc = ~a->spi.wire_crc;
    r->pixel_crc = ~a->spi.pixel_crc;
    r->wire_bytes = a->spi.wire_bytes;
    r->pixel_bytes = a->spi.pixel_bytes;
    r->transfers = a->spi.transfers;
    r->screen_tris = ctx.count;
    r->bins_overflowed = fxl_band_overflowed(&a->band);
    return st != FXL_OK ? st : st2;
}

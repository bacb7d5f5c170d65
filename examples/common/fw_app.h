/* fw_app.h - the firmware example's application, shared by the Cortex-M4
 * firmware and the host test: an ST7789 (240x320 module, rotation 90 = a
 * 320 x 240 frame) behind a mock SPI, the band renderer of port.h with two
 * 320 x 24 band buffers and a depth band, and a frame runner that sends one
 * frame of a scene (fw_scenes.h) through the fixed-point front end into the
 * bands and returns the CRC-32 of the bytes that went over the wire.
 *
 * The mock SPI. cmd() is blocking; pixels() "starts a DMA" and returns; the
 * transfer leaves (its bytes are hashed) and fxl_port_transfer_done() is
 * called on the next call of the HAL's wait hook, i.e. while the driver
 * waits, the way a DMA interrupt arrives while the CPU idles. So the band
 * renderer's asynchronous path is the one exercised.
 * CRCs are the standard CRC-32 (zlib / PNG, "123456789" -> 0xCBF43926):
 * wire_crc over every byte in order (command bytes, parameters, pixels),
 * pixel_crc over the pixel bytes only (= the CRC of the whole frame as a
 * 320 x 240 byte-swapped RGB565 image, which the host test checks against
 * a full-frame fxl_mesh_draw render).
 *
 * Freestanding C99, no libc, no global mutable state: everything lives in
 * the caller's fw_app_t (about 115 KB; make it static).
 */
#ifndef FW_APP_H
#define FW_APP_H

#include "fixel/port.h"
#include "fw_scenes.h"

#define FW_WIDTH 320
#define FW_HEIGHT 240
#define FW_BAND_ROWS 24
#define FW_BANDS ((FW_HEIGHT + FW_BAND_ROWS - 1) / FW_BAND_ROWS)
#define FW_TRI_CAP FW_MAX_SCREEN_TRIS
/* Bins for three bands per triangle on average; beyond that the band
 * renderer's fallback scan keeps the image identical (port.h). */
#define FW_BIN_CAP FXL_BAND_BIN_ENTRIES(FW_BANDS, 3 * FW_TRI_CAP)
/* The front end's vertex cache: two of the sphere's rings (its triangles
 * are indexed ring by ring), 34 entries of 56 bytes. Each vertex is then
 * transformed, lit and texgen'd about once a frame instead of once per
 * corner (pipeline.md, "Vertex cache"); the output is bit-identical. */
#define FW_VCACHE_ENTRIES (2 * (FW_SPHERE_SLICES + 1))

typedef struct fw_spi {
    uint32_t table[256];          /* CRC-32 byte table, built at init */
    uint32_t wire_crc, pixel_crc; /* running, pre-inverted form */
    uint32_t wire_bytes, pixel_bytes, transfers;
    const uint8_t *dma_src;       /* transfer in flight, or NULL */
    uint32_t dma_len;
    fxl_panel_t *panel;
    uint8_t *capture;             /* optional (tests): the frame's pixel bytes */
    uint32_t capture_cap;         /* its size in bytes; bytes beyond are dropped */
} fw_spi_t;

typedef struct fw_app {
    fw_scenes_t scenes;
    fw_view_t view;
    fw_spi_t spi;
    fxl_port_hal_t hal;
    fxl_panel_t panel;
    fxl_band_t band;
    uint16_t band_a[FW_WIDTH * FW_BAND_ROWS], band_b[FW_WIDTH * FW_BAND_ROWS];
#if FXL_HAVE_DEPTH
    uint16_t depth[FW_WIDTH * FW_BAND_ROWS]; /* no scene needs it, but a game would */
#endif
    fxl_band_tri_t tris[FW_TRI_CAP];
    fxl_band_bin_t bins[FW_BIN_CAP];
    fxl_vcache_entry_t vcache[FW_VCACHE_ENTRIES];
    uint32_t init_crc, init_bytes; /* the panel init sequence on the wire */
} fw_app_t;

/* The app's depth band, or NULL in a build without FXL_HAVE_DEPTH. */
#if FXL_HAVE_DEPTH
#define FW_DEPTH_BAND(a) ((a)->depth)
#else
#define FW_DEPTH_BAND(a) ((uint16_t *)0)
#endif

/* One frame of the run: scene and frame number. */
typedef struct fw_frame {
    uint8_t scene, frame;
} fw_frame_t;

/* The frames the firmware renders and prints, in order (the expected-CRC
 * file lists them in the same order). */
extern const fw_frame_t fw_frames[];
extern const uint32_t fw_frame_count;

typedef struct fw_result {
    uint32_t wire_crc, pixel_crc; /* final CRC-32 values */
    uint32_t wire_bytes, pixel_bytes, transfers;
    fxl_stats_t stats;            /* front end and rasterizer counters */
    uint32_t screen_tris;         /* triangles handed to the band renderer */
    int bins_overflowed;          /* the band renderer used its fallback scan */
} fw_result_t;

/* Initialise the mock SPI (no capture), the panel (init sequence hashed
 * into init_crc), the band renderer and the scenes. */
fxl_status_t fw_app_init(fw_app_t *a);
/* Render and send one frame; r receives its CRCs and counters (the CRCs
 * cover this frame's window commands and pixels only). */
fxl_status_t fw_app_frame(fw_app_t *a, int scene, uint32_t frame, fw_result_t *r);

/* Empty functions called at the start of each frame and right before its
 * bands are rendered; examples/frame_time.py finds them in the instruction
 * trace (together with each pixels() call) to split the work per band. */
void fw_mark_frame(void);
void fw_mark_render(void);

#endif

/* fixel/target.h - where pixels go: a caller-owned RGB565 buffer that may be a
 * whole frame or one horizontal band of a larger frame.
 *
 * Coordinates. Triangles are given in *frame* coordinates. A target covers the
 * frame rectangle [origin_x, origin_x + width) x [origin_y, origin_y + height);
 * pixels[0] is frame pixel (origin_x, origin_y). For a band renderer, the band
 * k of height H is a target with origin_y = k * H: the same triangles then land
 * in the right rows, and the output is bit-identical to a full-frame render.
 *
 * Clipping. Nothing is ever written outside `clip` (frame coordinates,
 * half-open), which the setters keep inside the buffer. Which pixels are drawn
 * depends on the clip rectangle; the value of a drawn pixel never does.
 *
 * Memory. pixels (and the optional depth buffer) belong to the caller; the
 * target only points at them. Both use `stride` elements per row. The
 * struct is plain data: every call re-checks fields edited by hand (sizes,
 * origin, stride outside the limits, an odd pixel pointer), and the calls
 * that store through the depth pointer (fxl_target_clear_depth, the
 * draws) refuse an odd one; nothing is written then.
 * Limits: 1 <= width, height <= FXL_TARGET_MAX_DIM, width <= stride <=
 * 4 * FXL_TARGET_MAX_DIM, |origin| <= FXL_TARGET_MAX_ORIGIN.
 */
#ifndef FIXEL_TARGET_H
#define FIXEL_TARGET_H

#include <stdint.h>
#include "fixel/status.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FXL_TARGET_MAX_DIM 4096
#define FXL_TARGET_MAX_ORIGIN 16384

typedef enum fxl_pixfmt {
    FXL_PIXFMT_RGB565 = 0,      /* native-endian uint16_t: r5 g6 b5, r in bits 15..11 */
    FXL_PIXFMT_RGB565_SWAP = 1  /* byte-swapped: in memory big-endian, as MIPI DCS panels
                                   take it on the wire (little-endian CPUs) */
} fxl_pixfmt_t;

/* Half-open rectangle [x0, x1) x [y0, y1). */
typedef struct fxl_rect {
    int32_t x0, y0, x1, y1;
} fxl_rect_t;

typedef struct fxl_target {
    uint16_t *pixels;
    uint16_t *depth;        /* optional depth buffer (NULL: no depth test) */
    int32_t width, height;  /* buffer size in pixels */
    int32_t stride;         /* elements per row of pixels and depth, >= width */
    int32_t origin_x, origin_y;
    fxl_rect_t clip;        /* frame coordinates, always inside the buffer */
    fxl_pixfmt_t format;
} fxl_target_t;

/* Bytes of a pixel (or depth) buffer for w x h with stride w: use it to
 * size static arrays. With a stride s > w the buffer needs
 * FXL_TARGET_BYTES(s, h - 1) + FXL_TARGET_BYTES(w, 1), i.e. s * h * 2 is
 * enough: rows are s pixels apart. */
#define FXL_TARGET_BYTES(w, h) ((uint32_t)(w) * (uint32_t)(h) * 2u)

/* Initialise: origin (0, 0), clip = whole buffer, no depth buffer.
 * FXL_ERR_ARG for NULL or odd-address pixels (uint16_t stores there would
 * be misaligned: a HardFault on a Cortex-M0+) or an unknown format;
 * FXL_ERR_RANGE for sizes or a stride outside the limits above. */
fxl_status_t fxl_target_init(fxl_target_t *t, uint16_t *pixels, int32_t width,
                             int32_t height, int32_t stride, fxl_pixfmt_t format);
/* Move the buffer within the frame; resets clip to the whole buffer. */
fxl_status_t fxl_target_set_origin(fxl_target_t *t, int32_t origin_x, int32_t origin_y);
/* Set the clip rectangle (frame coordinates); it is intersected with the
 * buffer. An empty intersection is allowed (nothing is drawn). */
fxl_status_t fxl_target_set_clip(fxl_target_t *t, const fxl_rect_t *clip);
/* Attach (or with NULL detach) a depth buffer of the same size and stride.
 * FXL_ERR_ARG for one at an odd address; FXL_ERR_UNSUPPORTED for a
 * non-NULL one without FXL_HAVE_DEPTH (detaching is always FXL_OK). */
fxl_status_t fxl_target_set_depth(fxl_target_t *t, uint16_t *depth);
/* Fill the clip rectangle with an RGB565 colour (given native; swapped for
 * FXL_PIXFMT_RGB565_SWAP targets). */
fxl_status_t fxl_target_clear(fxl_target_t *t, uint16_t rgb565);
/* Fill the clip rectangle of the depth buffer with 0 (farthest).
 * FXL_ERR_ARG when no depth buffer is attached; FXL_ERR_UNSUPPORTED
 * without FXL_HAVE_DEPTH. */
fxl_status_t fxl_target_clear_depth(fxl_target_t *t);

/* Pack 8-bit channels into native RGB565 (truncating). */
#define FXL_RGB565(r, g, b) \
    ((uint16_t)((((uint32_t)(r) & 0xF8u) << 8) | (((uint32_t)(g) & 0xFCu) << 3) | ((uint32_t)(b) >> 3)))

#ifdef __cplusplus
}
#endif
#endif

/* metrics.h - accuracy metrics of a fixel render against the reference
 * renderer (reference.h), host side only.
 *
 * Images: a fixel target (RGB565 native or byte-swapped) and a ref_image of
 * the same size and origin. Colours are compared on the reference's 0..255
 * scale (each channel expanded linearly, c * 255 / 31 or / 63).
 *
 * Texture coordinates: the core cannot export u, v per pixel, so the scene is
 * rendered a second time with a *probe texture* whose RGB565 word is its own
 * texel index: word = (y_bits << 8) | x_bits, with x_bits, y_bits = 8 bits of
 * the texel's x, y. Rendered with FXL_FILTER_POINT, FXL_MIP_NONE,
 * FXL_TEXENV_REPLACE and no colour key, each pixel holds the stored word of
 * the level-0 texel the core fetched, so the fetched index is exact.
 * Limit: one pass encodes sides up to 256 texels; pass 1 (the high 8 bits)
 * extends that to 65536 (more than FXL_TEX_MAX_LOG2 allows). Every 16-bit
 * value is a valid probe colour, so the drawn mask must come from another
 * render (metrics_mask_from_target on a sentinel-cleared render, or
 * metrics_coverage_count).
 * Error of a pixel: the core's u lies somewhere inside the fetched texel
 * [f, f + 1) (modulo the wrap), so with exact u from the reference:
 * - lower bound: distance from (u, v) to the nearest fetched-texel square
 *   (0 when inside). A real error: the core was at least that far off.
 * - centre distance: distance from (u, v) to that square's centre; the true
 *   error is within +-sqrt(0.5) texel of it (useful for large errors only).
 * To resolve errors below one texel, multiply the scene's u, v by 2^k with
 * repeat wrap: one probe texel is then 2^-k of a scene texel (divide the
 * results by 2^k).
 * Percentiles use the nearest-rank definition: the p-th percentile of n
 * sorted values is x[ceil(p / 100 * n) - 1].
 */
#ifndef FXL_HOST_METRICS_H
#define FXL_HOST_METRICS_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/status.h"
#include "fixel/target.h"
#include "fixel/texture.h"
#include "fixel/raster.h"
#include "reference.h"

#define METRICS_PSNR_CAP 100.0 /* dB reported for identical images */
#define METRICS_PROBE_BITS 8   /* index bits per axis per pass */

typedef struct metrics_summary {
    size_t n;
    double max, mean, p99;     /* 0 when n == 0 */
} metrics_summary;

typedef struct metrics_coverage {
    uint32_t ref_pixels;       /* reference count >= 1 */
    uint32_t drawn_pixels;     /* fixel count >= 1 */
    uint32_t mismatches;       /* (ref >= 1) != (fixel >= 1): must be 0 */
    uint32_t holes;            /* ref >= 1, fixel == 0 */
    uint32_t extra;            /* ref == 0, fixel >= 1 */
    uint32_t twice;            /* fixel count >= 2 (drawn more than once) */
    uint32_t ref_twice;        /* reference count >= 2 (0 for a mesh) */
    uint32_t count_mismatches; /* ref count != fixel count */
} metrics_coverage;

typedef struct metrics_image {
    size_t pixels;             /* compared */
    double mse;                /* mean over pixels and 3 channels, 0..255 scale */
    double psnr;               /* dB, 10 log10(255^2 / mse), METRICS_PSNR_CAP at most */
    double max_diff;           /* largest |channel difference|, 0..255 scale */
    double max_diff_lsb;       /* the same in LSBs of that channel (5 or 6 bits) */
    int32_t max_x, max_y;      /* image pixel of max_diff (-1 if none) */
} metrics_image;

typedef struct metrics_texcoord {
    size_t pixels;             /* compared */
    size_t wrong_texel;        /* fetched texel != reference point texel */
    double wrong_share;        /* wrong_texel / pixels (0 if none) */
    metrics_summary lower;     /* lower bound of |(u, v) - exact|, level-0 texels */
    metrics_summary centre;    /* distance to the fetched texel centre */
} metrics_texcoord;

/* Summary of n values (nearest-rank p99). x is not modified. */
fxl_status_t metrics_summarize(const double *x, size_t n, metrics_summary *out);
/* Nearest-rank percentile (0 < p <= 100) of n >= 1 values; sorts x in place. */
double metrics_percentile(double *x, size_t n, double p);

/* Coverage counts (or 0/1 masks) of n pixels: reference vs fixel. */
fxl_status_t metrics_coverage_compare(const uint8_t *ref_counts, const uint8_t *fxl_counts,
                                      size_t n, metrics_coverage *out);
/* mask[y * width + x] = 1 where the target's pixel differs from `sentinel`
 * (native RGB565, byte-swapped here for swapped targets), over the whole
 * buffer width x height. */
fxl_status_t metrics_mask_from_target(const fxl_target_t *t, uint16_t sentinel, uint8_t *mask);
/* How many triangles the core draws at each pixel of the frame rectangle
 * [0, width) x [0, height): each triangle is drawn alone, untextured (with a
 * 1x1 texture without FXL_HAVE_GENERIC), without depth, into a scratch
 * target clipped to its bounding box (so the cost is the sum of the bounding
 * boxes). counts saturate at 255. Uses the core. */
fxl_status_t metrics_coverage_count(const fxl_vertex_t *tris, int ntri, int32_t width,
                                    int32_t height, uint8_t *counts);

/* Image error of target vs reference over pixels where mask != 0 (mask NULL:
 * all). Target and reference must have the same size and origin. */
fxl_status_t metrics_image_compare(const fxl_target_t *t, const ref_image *ref,
                                   const uint8_t *mask, metrics_image *out);

/* Probe texture: fill w x h texels (powers of two up to 65536 per side) of
 * pass 0 (low 8 bits of x, y) or pass 1 (bits 8..15). */
fxl_status_t metrics_probe_fill(uint16_t *texels, uint32_t w, uint32_t h, int pass);
/* Decode a probe render: pass 0 sets tx, ty (width * height, row-major) to
 * the low bits, pass 1 ORs in the high bits. */
fxl_status_t metrics_probe_decode(const fxl_target_t *t, int pass, int32_t *tx, int32_t *ty);
/* Texture-coordinate error of fetched texels (tx, ty: level-0 indices in
 * [0, tex_w) x [0, tex_h)) against the reference, over pixels where the
 * reference drew without a depth tie, mask != 0 (NULL: all) and the fetched
 * index is in range. Wraps: repeat, mirror, clamp (border: FXL_ERR_ARG). */
fxl_status_t metrics_texcoord_compare(const ref_image *ref, const int32_t *tx, const int32_t *ty,
                                      const uint8_t *mask, uint32_t tex_w, uint32_t tex_h,
                                      fxl_wrap_t wrap_u, fxl_wrap_t wrap_v,
                                      metrics_texcoord *out);
/* The per-axis part: distance from exact coordinate e (texels, unwrapped) to
 * the nearest texel interval that wraps to index f of n, and to its centre. */
void metrics_axis_error(double e, int32_t f, int32_t n, fxl_wrap_t wrap, double *lower,
                        double *centre);

#endif

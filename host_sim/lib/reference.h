/* reference.h - double-precision reference renderer, host side only.
 *
 * The ground truth for every accuracy metric: it draws the same triangles as
 * the core with the same conventions (include/fixel/raster.h), but exactly.
 * - Coverage: vertices snapped with the core's rule (nearest 1/16 px, ties
 *   toward +inf), then the top-left rule in exact int64 arithmetic on doubled
 *   grid coordinates (pixel centres are integers). Either winding; zero area
 *   draws nothing.
 * - u, v: exact perspective value at the pixel centre,
 *   u = sum(b_k u_k q_k) / sum(b_k q_k), b_k screen-space barycentrics w.r.t.
 *   the snapped vertices, q_k = inv_w_k (long double). Affine draws
 *   (persp == FXL_PERSP_AFFINE) use u = sum(b_k u_k) instead.
 * - Texel space: u_texel = u * width_of_level. Point: texel floor(u_texel).
 *   Bilinear: x0 = floor(u_texel - 0.5), fx = frac(u_texel - 0.5), exact
 *   weights (the core quantises them to 1/32, so compare with a tolerance).
 * - Colours are doubles on a 0..255 scale, each channel expanded linearly:
 *   c * 255 / 31 (red, blue) or c * 255 / 63 (green). Blending happens on
 *   these values (a linear blend of 5/6-bit channel values, scaled). L8 texels
 *   read as the RGB565 word FXL_RGB565(l, l, l) (what fxl_texture_fetch
 *   returns), I8 through the palette.
 * - LOD (level-0 texels): FXL_LOD_TRIANGLE: log4(texel area / pixel area) of
 *   the triangle (snapped screen area); FXL_LOD_SEGMENT: per pixel
 *   log2(max(|(du/dx, dv/dx)|, |(du/dy, dv/dy)|)) from the exact derivatives
 *   of the mapping being drawn (perspective, or the affine gradients); plus
 *   lod_bias_q8 / 256; clamped to [0, levels - 1]. FXL_MIP_NEAREST samples
 *   level floor(lod + 0.5); FXL_MIP_LINEAR blends levels floor(lod) and
 *   floor(lod) + 1 by frac(lod).
 * - Depth (FXL_DEPTH_TEST / _WRITE with ref_params.depth_enabled): the
 *   screen-linear exact inv_w, d = floor(inv_w / 65536) (the core's
 *   inv_w >> 16); the buffer starts at 0; a pixel passes when d > stored
 *   (strictly: on equal d the triangle drawn first stays). Because the core
 *   interpolates inv_w in fixed point, its d may differ by one; the reference
 *   flags every pixel where a depth comparison between two triangles was
 *   within `depth_tie_margin` (ref_image.depth_tie) so metrics can skip it.
 * - Colour key: a key texel is transparent (nothing drawn, no depth write).
 *   Bilinear: drawn only if the point-sampled (nearest) texel is opaque; key
 *   texels of the 2x2 footprint take that nearest texel's colour. Trilinear:
 *   the pixel is transparent when the finer level's sample is; a transparent
 *   coarser level drops out (the finer sample is used alone).
 *   Border texels are never transparent.
 * Supported: texenv REPLACE, flat or Gouraud shading when untextured.
 * MODULATE / DECAL and Gouraud with a texture return FXL_ERR_UNSUPPORTED.
 * Memory: ref_render mallocs the arrays of ref_image; ref_free releases them.
 */
#ifndef FXL_HOST_REFERENCE_H
#define FXL_HOST_REFERENCE_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/status.h"
#include "fixel/texture.h"
#include "fixel/raster.h"

#define REF_NO_TEXEL INT32_MIN /* tex_x / tex_y of a border texel or no pixel */

typedef struct ref_params {
    int32_t width, height;       /* image: frame pixels [origin, origin + size) */
    int32_t origin_x, origin_y;
    fxl_draw_t draw;             /* the same settings as the core's draw */
    int depth_enabled;           /* 1: apply draw.depth bits (the core needs a
                                    depth buffer for that) */
    int32_t depth_tie_margin;    /* |d_new - d_stored| <= margin flags a tie (1) */
    uint16_t clear_color;        /* native RGB565 of pixels nothing drew (0) */
} ref_params;

typedef struct ref_image {
    int32_t width, height, origin_x, origin_y;
    /* per pixel, row-major, index y * width + x: */
    uint8_t *covered;   /* triangles whose coverage includes it (saturates at 255) */
    uint8_t *drawn;     /* 1: a triangle's colour is there (covered, depth, key) */
    uint8_t *depth_tie; /* 1: a depth decision here was within the tie margin */
    int32_t *tri;       /* index of the triangle shown, -1 for none */
    double *u, *v;      /* exact coordinates of the shown triangle, level-0
                           texels, unwrapped (u_norm * width0; normalised
                           when untextured) */
    double *lod;        /* LOD used, bias added and clamped (0 if untextured) */
    int32_t *tex_x, *tex_y; /* point-sampled level-0 texel, wrapped
                               (REF_NO_TEXEL: border or nothing drawn) */
    double *rgb;        /* 3 per pixel, 0..255 scale (see top) */
    uint16_t *depth;    /* depth buffer after the draw (inv_w >> 16 values) */
} ref_image;

/* Defaults: the given size at origin (0, 0), fxl_draw_defaults(), depth off,
 * tie margin 1, clear colour 0. */
void ref_params_init(ref_params *p, int32_t width, int32_t height);

/* Render ntri triangles (3 vertices each, in order) like consecutive
 * fxl_draw_triangle calls. FXL_ERR_ARG: NULL pointers, bad size, ntri < 0;
 * FXL_ERR_UNSUPPORTED: invalid texture or unsupported mode; FXL_ERR_NOMEM.
 * On error *out holds no memory. */
fxl_status_t ref_render(const ref_params *p, const fxl_vertex_t *tri_list, int ntri,
                        ref_image *out);
void ref_free(ref_image *img);

/* ---- exact coverage ------------------------------------------------------ */

/* The core's snap (fxl_snap_subpx): x * 2^FXL_SUBPIXEL_BITS / 65536 rounded
 * to nearest, ties toward +inf, in grid units. */
int32_t ref_snap(fxl_q16_t x);
/* 1 if frame pixel (i, j) is covered by the top-left rule, else 0. */
int ref_pixel_covered(const fxl_vertex_t tri[3], int32_t i, int32_t j);
/* Coverage of frame pixels [x0, x0 + w) x [y0, y0 + h) into mask (w * h
 * bytes, row-major, 0/1). Returns the number of covered pixels, -1 on bad
 * arguments. */
long ref_coverage_mask(const fxl_vertex_t tri[3], int32_t x0, int32_t y0, int32_t w,
                       int32_t h, uint8_t *mask);

/* ---- pieces, exposed for tests and tools ---------------------------------- */

/* Exact normalised u, v (1.0 = one texture side) at frame point (px, py), in
 * pixels, of the snapped triangle; affine != 0 gives the screen-linear value.
 * du[0..1] = du/dx, du/dy and dv[0..1] likewise (normalised per pixel), may be
 * NULL. Returns 0, or -1 for a zero-area triangle. */
int ref_uv_at(const fxl_vertex_t tri[3], double px, double py, int affine, double *u,
              double *v, double du[2], double dv[2]);
/* Unclamped per-triangle LOD log4(level-0 texel area / snapped pixel area);
 * -HUGE_VAL for zero texel area, +HUGE_VAL for zero pixel area. */
double ref_lod_triangle(const fxl_texture_t *t, const fxl_vertex_t tri[3]);
/* Unclamped per-pixel LOD from normalised derivatives (as ref_uv_at gives). */
double ref_lod_pixel(const fxl_texture_t *t, const double du[2], const double dv[2]);
/* Wrap an integer texel coordinate into [0, n); -1 means border (FXL_WRAP_BORDER
 * outside [0, n)). n >= 1. */
int32_t ref_wrap(fxl_wrap_t mode, int64_t x, int32_t n);
/* Stored colour of texel (x, y) of `level` after wrapping, 0..255 scale;
 * returns 1 if transparent (key), else 0. */
int ref_texel(const fxl_texture_t *t, uint32_t level, int64_t x, int64_t y, double rgb[3]);
/* Filtered colour at texel-space point (ut, vt) of `level` (point or bilinear
 * as above, key handling included). Returns 1 if transparent, else 0. */
int ref_sample_level(const fxl_texture_t *t, uint32_t level, fxl_filter_t filter, double ut,
                     double vt, double rgb[3]);
/* The error that stepping u, v linearly over L pixels between exact points
 * adds to the perspective map of tri, in level-0 texels of a 2^log2_w x
 * 2^log2_h texture (both axes together): along a span u = s / q with s, q
 * linear, so a chord over L pixels errs by at most L^2 max |u' q'| / (4 q)
 * = L^2 |q_x| |N| / (4 q^3), N = s_x q - s q_x linear over the triangle
 * (bounded by its vertex values, q by its smallest), plus one q16 unit a
 * pixel of truncated steps. For the snapped vertices. */
double ref_chord_bound(const fxl_vertex_t tri[3], uint32_t log2_w, uint32_t log2_h, int L);
/* RGB565 word -> 0..255 channels (linear expansion). */
void ref_rgb565_to_rgb(uint16_t c, double rgb[3]);

#endif

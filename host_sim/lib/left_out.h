/* left_out.h - which draws this build of the core refuses, host side only.
 *
 * The tests expect FXL_ERR_UNSUPPORTED for a draw that needs a feature
 * config.h left out, and the default build's pixels for every other. This
 * predicate is written from config.h's documented rules, not from the
 * core's code (raster.c: check_draw, check_build), so the tests compare the
 * two. Header-only: the libFuzzer target compiles it without the host
 * library.
 */
#ifndef FIXEL_LEFT_OUT_H
#define FIXEL_LEFT_OUT_H

#include <stddef.h>
#include "fixel/fixel.h"

/* The first optional feature that a draw with settings d (texture tex, may
 * be NULL) onto a target of pixel format `format` with (depth_buffer != 0)
 * or without a depth buffer needs and this build left out, by its config.h
 * name ("FXL_HAVE_BILINEAR", "FXL_FAST_SWAPPED", ...), or NULL when the core
 * draws it. Every triangle of such a draw is refused, culled ones included.
 * Always NULL in the default configuration. */
static inline const char *left_out_feature(const fxl_draw_t *d, const fxl_texture_t *tex, int32_t format,
                                           int depth_buffer)
{
    const uint32_t both = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
    const int zmode = depth_buffer && (d->depth & both) != 0;
    (void)tex;
    (void)format;
    (void)both;
    (void)zmode;
#if !FXL_HAVE_BILINEAR
    if (d->filter == FXL_FILTER_BILINEAR)
        return "FXL_HAVE_BILINEAR";
#endif
#if !FXL_HAVE_AUTO
    if (d->persp == FXL_PERSP_AUTO)
        return "FXL_HAVE_AUTO";
#endif
#if !FXL_HAVE_MIPMAP
    if (d->mip != FXL_MIP_NONE && tex != NULL && tex->levels > 1u)
        return "FXL_HAVE_MIPMAP";
#endif
#if !FXL_HAVE_GENERIC
    if (tex == NULL || d->shade != FXL_SHADE_FLAT || d->texenv != FXL_TEXENV_REPLACE ||
        tex->format != FXL_TEXFMT_RGB565 || tex->wrap_u != FXL_WRAP_REPEAT || tex->wrap_v != FXL_WRAP_REPEAT ||
        (tex->flags & FXL_TEXF_KEY) != 0)
        return "FXL_HAVE_GENERIC";
#endif
#if !FXL_HAVE_DEPTH
    /* fxl_target_set_depth refuses a buffer; this one was put in the struct */
    if (zmode)
        return "FXL_HAVE_DEPTH";
#endif
#if !FXL_HAVE_GENERIC
    /* only the specialised walks: each kind of draw needs its own */
    if (d->filter == FXL_FILTER_BILINEAR ? !FXL_FAST_BILINEAR : !FXL_FAST_POINT)
        return d->filter == FXL_FILTER_BILINEAR ? "FXL_FAST_BILINEAR" : "FXL_FAST_POINT";
    if (zmode ? !FXL_FAST_DEPTH : !FXL_FAST_NO_DEPTH)
        return zmode ? "FXL_FAST_DEPTH" : "FXL_FAST_NO_DEPTH";
    if (format == FXL_PIXFMT_RGB565_SWAP ? !FXL_FAST_SWAPPED : !FXL_FAST_NATIVE)
        return format == FXL_PIXFMT_RGB565_SWAP ? "FXL_FAST_SWAPPED" : "FXL_FAST_NATIVE";
    if ((zmode && (d->depth & both) != both) || (uint32_t)tex->log2_w + tex->log2_h > 16u)
        return "FXL_HAVE_GENERIC";
#endif
    return NULL;
}

/* The texture of a flat white draw any build draws: NULL (untextured)
 * where it has the generic walk, else a 1x1 white RGB565 repeat texture,
 * which covers the same pixels in the same colour (coverage never depends
 * on the texture). */
static inline const fxl_texture_t *flat_white_texture(void)
{
#if FXL_HAVE_GENERIC
    return NULL;
#else
    static const uint16_t white[1] = {0xFFFFu};
    static fxl_texture_t tex;
    return fxl_texture_init(&tex, white, 1, 1, FXL_TEXFMT_RGB565, 1) == FXL_OK ? &tex : NULL;
#endif
}

/* The RGB565 byte order this build draws every kind of draw it keeps in:
 * native, except in a build with only the byte-swapped walks (an SPI
 * panel's: no generic walk, FXL_FAST_NATIVE 0). Host code that needs
 * native pixels but not a native target (coverage, texel and CRC checks)
 * draws in this order and converts with pixels_to_native: both orders draw
 * the same colours (test_fast_and_generic_walks_agree, test_span_modes). */
static inline fxl_pixfmt_t drawable_rgb565(void)
{
#if !FXL_HAVE_GENERIC && !FXL_FAST_NATIVE
    return FXL_PIXFMT_RGB565_SWAP;
#else
    return FXL_PIXFMT_RGB565;
#endif
}

/* 1 on a little-endian host (the probe fxl_port_wire_format makes; here
 * so this header needs no port library). */
static inline int host_little_endian(void)
{
    const uint16_t probe = 1u;
    return *(const unsigned char *)&probe == 1u;
}

/* Whether the emulated SPI panel's HAL sends pixels as 16-bit frames
 * (FXL_PORT_PIXELS_16BIT, port.h) rather than bytes: only where this build
 * cannot draw the byte stream's format, i.e. on a little-endian host
 * without the generic walk and the byte-swapped walks (configuration
 * min-native). Both send the same bytes to the panel. */
static inline int panel_spi16(void)
{
    return !FXL_HAVE_GENERIC && !FXL_FAST_SWAPPED && host_little_endian();
}

/* The format the band renderer draws in for that HAL
 * (fxl_panel_pixel_format): native RGB565 for 16-bit frames and on
 * big-endian hosts, else byte-swapped. */
static inline fxl_pixfmt_t panel_band_format(void)
{
    return host_little_endian() && !panel_spi16() ? FXL_PIXFMT_RGB565_SWAP : FXL_PIXFMT_RGB565;
}

/* n pixels drawn in format `format` as native RGB565, in place. */
static inline void pixels_to_native(uint16_t *px, size_t n, fxl_pixfmt_t format)
{
    size_t i;
    if (format != FXL_PIXFMT_RGB565_SWAP)
        return;
    for (i = 0; i < n; i++)
        px[i] = (uint16_t)((px[i] >> 8) | (px[i] << 8));
}

#endif

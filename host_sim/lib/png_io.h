/* png_io.h - RGB565 images to PNG files and PNG files to RGBA8, host side.
 *
 * This is the only place libpng is used. Functions return 0 on success and
 * -1 on failure with a one-line English reason in err[err_size] (err may be
 * NULL); they never exit() or print.
 *
 * Writing expands each RGB565 channel to 8 bits by bit replication
 * (r8 = r5 << 3 | r5 >> 2, g8 = g6 << 2 | g6 >> 4), so 0 -> 0 and full ->
 * 255 exactly, and stores an 8-bit RGB PNG. The image goes to a temporary
 * file next to `path` that is renamed over `path` only once complete: a
 * failed write leaves no partial file (and an older `path` untouched).
 *
 * Reading accepts every colour type and bit depth libpng decodes (palette,
 * grey, grey+alpha, RGB, RGBA, 1..16 bits, interlaced) and returns RGBA8
 * rows, tightly packed, in a malloc'd buffer the caller free()s. 16-bit
 * channels are scaled to 8 bits with rounding; no gamma conversion is done.
 */
#ifndef FXL_HOST_PNG_IO_H
#define FXL_HOST_PNG_IO_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/target.h"

/* Largest side accepted by pngio_read_rgba8 (protects against absurd headers). */
#define PNGIO_MAX_DIM 16384

/* Expand a native RGB565 value to 8-bit r, g, b by bit replication. */
void pngio_expand565(uint16_t native565, uint8_t rgb[3]);

/* Write width x height pixels (stride elements per row) of the given format. */
int pngio_write_rgb565(const char *path, const uint16_t *pixels, int32_t width, int32_t height,
                       int32_t stride, fxl_pixfmt_t format, char *err, size_t err_size);

/* Write a target's whole buffer (width x height, its stride and format). */
int pngio_write_target(const char *path, const fxl_target_t *t, char *err, size_t err_size);

/* Read any PNG as RGBA8: *rgba = malloc'd width*height*4 bytes. On failure
 * *rgba is NULL and *width = *height = 0. */
int pngio_read_rgba8(const char *path, uint8_t **rgba, uint32_t *width, uint32_t *height,
                     char *err, size_t err_size);

#endif

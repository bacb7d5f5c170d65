/* png_io.c - see png_io.h.
 *
 * libpng reports errors by calling an error function that must not return;
 * ours records the message and longjmp()s back to the setjmp() in the
 * caller. Locals changed after setjmp() are volatile, as C requires for
 * their values to be reliable after the jump.
 */
#ifndef _POSIX_C_SOURCE
#define _POSIX_C_SOURCE 200809L
#endif
#include "png_io.h"
#include "outfile.h"

#include <errno.h>
#include <png.h>
#include <setjmp.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

typedef struct png_ctx {
    char msg[200];
} png_ctx_t;

static void set_err(char *err, size_t err_size, const char *fmt, ...)
{
    va_list ap;
    if (err == NULL || err_size == 0) {
        return;
    }
    va_start(ap, fmt);
    vsnprintf(err, err_size, fmt, ap);
    va_end(ap);
}

static void on_png_error(png_structp png, png_const_charp msg)
{
    png_ctx_t *ctx = (png_ctx_t *)png_get_error_ptr(png);
    if (ctx != NULL) {
        snprintf(ctx->msg, sizeof(ctx->msg), "%s", msg != NULL ? msg : "unknown error");
    }
    png_longjmp(png, 1);
}

static void on_png_warning(png_structp png, png_const_charp msg)
{
    /* Warnings (e.g. a bad ancillary chunk) do not stop decoding; staying
     * silent keeps tools' output clean. */
    (void)png;
    (void)msg;
}

void pngio_expand565(uint16_t c, uint8_t rgb[3])
{
    unsigned r5 = (c >> 11) & 0x1Fu, g6 = (c >> 5) & 0x3Fu, b5 = c & 0x1Fu;
    rgb[0] = (uint8_t)((r5 << 3) | (r5 >> 2));
    rgb[1] = (uint8_t)((g6 << 2) | (g6 >> 4));
    rgb[2] = (uint8_t)((b5 << 3) | (b5 >> 2));
}

int pngio_write_rgb565(const char *path, const uint16_t *pixels, int32_t width, int32_t height,
                       int32_t stride, fxl_pixfmt_t format, char *err, size_t err_size)
{
    png_ctx_t ctx;
    png_structp png = NULL;
    png_infop info = NULL;
    outfile_t out;   /* not changed between setjmp() and a longjmp() */
    unsigned char *row = NULL;
    int32_t x, y;

    if (path == NULL || pixels == NULL || width <= 0 || height <= 0 || stride < width) {
        set_err(err, err_size, "png write: bad arguments (NULL or size %ldx%ld stride %ld)",
                (long)width, (long)height, (long)stride);
        return -1;
    }
    if (format != FXL_PIXFMT_RGB565 && format != FXL_PIXFMT_RGB565_SWAP) {
        set_err(err, err_size, "png write: unsupported pixel format %d", (int)format);
        return -1;
    }
    row = (unsigned char *)malloc((size_t)width * 3u);
    if (row == NULL) {
        set_err(err, err_size, "png write '%s': out of memory", path);
        return -1;
    }
    /* a temp file renamed into place, or a device written in place */
    if (outfile_open(&out, path) != 0) {
        set_err(err, err_size, "cannot create '%s': %s", path, strerror(errno));
        free(row);
        return -1;
    }
    ctx.msg[0] = '\0';
    png = png_create_write_struct(PNG_LIBPNG_VER_STRING, &ctx, on_png_error, on_png_warning);
    if (png != NULL) {
        info = png_create_info_struct(png);
    }
    if (png == NULL || info == NULL) {
        set_err(err, err_size, "png write '%s': libpng initialisation failed", path);
        goto fail;
    }
    if (setjmp(png_jmpbuf(png))) {
        set_err(err, err_size, "png write '%s': libpng: %s", path, ctx.msg);
        goto fail;
    }
    png_init_io(png, out.f);
    png_set_IHDR(png, info, (png_uint_32)width, (png_uint_32)height, 8, PNG_COLOR_TYPE_RGB,
                 PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (y = 0; y < height; y++) {
        const uint16_t *src = pixels + (size_t)y * (size_t)stride;
        for (x = 0; x < width; x++) {
            uint16_t c = src[x];
            if (format == FXL_PIXFMT_RGB565_SWAP) {
                c = (uint16_t)((c >> 8) | (c << 8));
            }
            pngio_expand565(c, row + (size_t)x * 3u);
        }
        png_write_row(png, row);
    }
    png_write_end(png, NULL);
    png_destroy_write_struct(&png, &info);
    png = NULL;
    if (outfile_close(&out, 0) != 0) {
        set_err(err, err_size, "png write '%s': %s", path, strerror(errno));
        goto fail;
    }
    if (outfile_commit(&out) != 0) {
        set_err(err, err_size, "cannot rename into '%s': %s", path, strerror(errno));
        goto fail;
    }
    free(row);
    return 0;

fail:
    if (png != NULL) {
        png_destroy_write_struct(&png, info != NULL ? &info : NULL);
    }
    outfile_abandon(&out);
    free(row);
    return -1;
}

int pngio_write_target(const char *path, const fxl_target_t *t, char *err, size_t err_size)
{
    if (t == NULL) {
        set_err(err, err_size, "png write: NULL target");
        return -1;
    }
    return pngio_write_rgb565(path, t->pixels, t->width, t->height, t->stride, t->format, err,
                              err_size);
}

int pngio_read_rgba8(const char *path, uint8_t **rgba, uint32_t *width, uint32_t *height,
                     char *err, size_t err_size)
{
    png_ctx_t ctx;
    png_structp png = NULL;
    png_infop info = NULL;
    FILE *fp;
    unsigned char sig[8];
    uint8_t *volatile out = NULL;
    png_bytep *volatile rows = NULL;
    png_uint_32 w, h, y;
    int color_type, bit_depth;

    if (rgba != NULL) {
        *rgba = NULL;
    }
    if (width != NULL) {
        *width = 0;
    }
    if (height != NULL) {
        *height = 0;
    }
    if (path == NULL || rgba == NULL || width == NULL || height == NULL) {
        set_err(err, err_size, "png read: NULL argument");
        return -1;
    }
    fp = fopen(path, "rb");
    if (fp == NULL) {
        set_err(err, err_size, "cannot open '%s': %s", path, strerror(errno));
        return -1;
    }
    if (fread(sig, 1, sizeof(sig), fp) != sizeof(sig) || png_sig_cmp(sig, 0, sizeof(sig)) != 0) {
        set_err(err, err_size, "'%s' is not a PNG file (bad signature)", path);
        fclose(fp);
        return -1;
    }
    ctx.msg[0] = '\0';
    png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &ctx, on_png_error, on_png_warning);
    if (png != NULL) {
        info = png_create_info_struct(png);
    }
    if (png == NULL || info == NULL) {
        set_err(err, err_size, "png read '%s': libpng initialisation failed", path);
        png_destroy_read_struct(&png, info != NULL ? &info : NULL, NULL);
        fclose(fp);
        return -1;
    }
    if (setjmp(png_jmpbuf(png))) {
        set_err(err, err_size, "png read '%s': libpng: %s", path, ctx.msg);
        png_destroy_read_struct(&png, &info, NULL);
        free(rows);
        free(out);
        fclose(fp);
        return -1;
    }
    png_init_io(png, fp);
    png_set_sig_bytes(png, (int)sizeof(sig));
    png_read_info(png, info);
    w = png_get_image_width(png, info);
    h = png_get_image_height(png, info);
    color_type = png_get_color_type(png, info);
    bit_depth = png_get_bit_depth(png, info);
    if (w == 0 || h == 0 || w > PNGIO_MAX_DIM || h > PNGIO_MAX_DIM) {
        png_error(png, "image size outside 1..16384");
    }
    /* Normalise every colour type to 8-bit RGBA. */
    if (color_type == PNG_COLOR_TYPE_PALETTE) {
        png_set_palette_to_rgb(png);
    }
    if (color_type == PNG_COLOR_TYPE_GRAY && bit_depth < 8) {
        png_set_expand_gray_1_2_4_to_8(png);
    }
    if (png_get_valid(png, info, PNG_INFO_tRNS)) {
        png_set_tRNS_to_alpha(png);
    }
    if (bit_depth == 16) {
#ifdef PNG_READ_SCALE_16_TO_8_SUPPORTED
        png_set_scale_16(png); /* rounds: v8 = (v16 * 255 + 32767) / 65535 */
#else
        png_set_strip_16(png);
#endif
    }
    if (color_type == PNG_COLOR_TYPE_GRAY || color_type == PNG_COLOR_TYPE_GRAY_ALPHA) {
        png_set_gray_to_rgb(png);
    }
    if (!(color_type & PNG_COLOR_MASK_ALPHA) && !png_get_valid(png, info, PNG_INFO_tRNS)) {
        png_set_add_alpha(png, 0xFF, PNG_FILLER_AFTER);
    }
    (void)png_set_interlace_handling(png);
    png_read_update_info(png, info);
    if (png_get_rowbytes(png, info) != (size_t)w * 4u) {
        png_error(png, "unexpected row size after conversion to RGBA8");
    }
    out = (uint8_t *)malloc((size_t)w * (size_t)h * 4u);
    rows = (png_bytep *)malloc((size_t)h * sizeof(png_bytep));
    if (out == NULL || rows == NULL) {
        png_error(png, "out of memory");
    }
    for (y = 0; y < h; y++) {
        rows[y] = out + (size_t)y * (size_t)w * 4u;
    }
    png_read_image(png, rows);
    png_read_end(png, NULL);
    png_destroy_read_struct(&png, &info, NULL);
    free(rows);
    fclose(fp);
    *rgba = out;
    *width = (uint32_t)w;
    *height = (uint32_t)h;
    return 0;
}

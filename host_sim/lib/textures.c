/* textures.c - see textures.h. */
#include "textures.h"

#include <stdlib.h>
#include <string.h>

#include "fixel/target.h"

/* 3x5 glyphs, one row per entry, bit 2 = left column. Digits 0-9, then F. */
static const uint8_t glyph3x5[11][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
    {7, 4, 6, 4, 4}};
#define GLYPH_F 10

static int is_pow2(uint32_t x)
{
    return x != 0 && (x & (x - 1u)) == 0;
}

static uint32_t log2u(uint32_t x)
{
    uint32_t n = 0;
    while (x > 1u) {
        x >>= 1;
        n++;
    }
    return n;
}

static uint32_t level_dim(uint32_t size, uint32_t level)
{
    uint32_t d = size >> level;
    return d == 0 ? 1u : d;
}

static int alloc_chain(host_texture_t *out, uint32_t w, uint32_t h)
{
    uint32_t lw = log2u(w), lh = log2u(h);
    uint32_t levels = 1u + (lw > lh ? lw : lh);
    uint32_t n = 0, l;
    memset(out, 0, sizeof(*out));
    if (!is_pow2(w) || !is_pow2(h) || lw > FXL_TEX_MAX_LOG2 || lh > FXL_TEX_MAX_LOG2) {
        return -1;
    }
    for (l = 0; l < levels; l++) {
        n += level_dim(w, l) * level_dim(h, l);
    }
    out->texels = (uint16_t *)calloc(n, sizeof(uint16_t));
    if (out->texels == NULL) {
        return -1;
    }
    out->width = w;
    out->height = h;
    out->texel_count = n;
    /* The descriptor is plain data (texture.h); fill it directly rather than
     * through fxl_texture_init so host tools need no core object for it. */
    out->tex.texels = out->texels;
    out->tex.palette = NULL;
    out->tex.log2_w = (uint8_t)lw;
    out->tex.log2_h = (uint8_t)lh;
    out->tex.levels = (uint8_t)levels;
    out->tex.format = FXL_TEXFMT_RGB565;
    out->tex.wrap_u = FXL_WRAP_REPEAT;
    out->tex.wrap_v = FXL_WRAP_REPEAT;
    out->tex.flags = 0;
    out->tex.reserved = 0;
    out->tex.key = 0;
    out->tex.border = 0;
    return 0;
}

static uint16_t avg565(const uint16_t *c, unsigned n)
{
    /* Per-channel mean of n = 2 or 4 texels rounded to nearest (half up). */
    unsigned r = 0, g = 0, b = 0, i, sh = (n == 4u) ? 2u : 1u;
    for (i = 0; i < n; i++) {
        r += (c[i] >> 11) & 0x1Fu;
        g += (c[i] >> 5) & 0x3Fu;
        b += c[i] & 0x1Fu;
    }
    r = (r + n / 2u) >> sh;
    g = (g + n / 2u) >> sh;
    b = (b + n / 2u) >> sh;
    return (uint16_t)((r << 11) | (g << 5) | b);
}

static void build_mips(host_texture_t *t)
{
    uint16_t *src = t->texels;
    uint32_t l, x, y;
    for (l = 1; l < t->tex.levels; l++) {
        uint32_t sw = level_dim(t->width, l - 1u), sh = level_dim(t->height, l - 1u);
        uint32_t dw = level_dim(t->width, l), dh = level_dim(t->height, l);
        uint16_t *dst = src + (size_t)sw * sh;
        for (y = 0; y < dh; y++) {
            for (x = 0; x < dw; x++) {
                uint16_t c[4];
                unsigned n = 0;
                uint32_t sx = (sw > 1u) ? 2u * x : x, sy = (sh > 1u) ? 2u * y : y;
                c[n++] = src[sy * sw + sx];
                if (sw > 1u) {
                    c[n++] = src[sy * sw + sx + 1u];
                }
                if (sh > 1u) {
                    c[n++] = src[(sy + 1u) * sw + sx];
                    if (sw > 1u) {
                        c[n++] = src[(sy + 1u) * sw + sx + 1u];
                    }
                }
                dst[y * dw + x] = (n == 1u) ? c[0] : avg565(c, n);
            }
        }
        src = dst;
    }
}

static void fill_rect(host_texture_t *t, uint32_t x0, uint32_t y0, uint32_t w, uint32_t h,
                      uint16_t c)
{
    uint32_t x, y;
    for (y = y0; y < y0 + h && y < t->height; y++) {
        for (x = x0; x < x0 + w && x < t->width; x++) {
            t->texels[y * t->width + x] = c;
        }
    }
}

static void draw_glyph(host_texture_t *t, unsigned g, uint32_t x0, uint32_t y0, uint32_t scale,
                       uint16_t c)
{
    uint32_t row, col;
    for (row = 0; row < 5u; row++) {
        for (col = 0; col < 3u; col++) {
            if (glyph3x5[g][row] & (4u >> col)) {
                fill_rect(t, x0 + col * scale, y0 + row * scale, scale, scale, c);
            }
        }
    }
}

int texture_make_checker(host_texture_t *out, uint32_t width, uint32_t height, uint32_t cell,
                         uint16_t c0, uint16_t c1)
{
    uint32_t x, y;
    if (out == NULL) {
        return -1;
    }
    if (cell == 0 || alloc_chain(out, width, height) != 0) {
        memset(out, 0, sizeof(*out));
        return -1;
    }
    for (y = 0; y < height; y++) {
        for (x = 0; x < width; x++) {
            out->texels[y * width + x] = (((x / cell) + (y / cell)) & 1u) ? c1 : c0;
        }
    }
    build_mips(out);
    return 0;
}

int texture_make_crate(host_texture_t *out, uint32_t size)
{
    uint32_t x, y, frame, mark, s;
    if (out == NULL) {
        return -1;
    }
    if (size < 16u || alloc_chain(out, size, size) != 0) {
        memset(out, 0, sizeof(*out));
        return -1;
    }
    frame = size / 16u;
    mark = size / 8u;
    for (y = 0; y < size; y++) {
        for (x = 0; x < size; x++) {
            /* Planks: horizontal boards size/4 high with a dark seam, and a
             * slight grain that varies along x so stretching is visible. */
            uint32_t grain = ((x * 7u + (y / (size / 4u)) * 13u) % 11u);
            uint16_t c = FXL_RGB565(150 + grain * 3u, 98 + grain * 2u, 48);
            if (y % (size / 4u) == 0) {
                c = FXL_RGB565(80, 50, 24);
            }
            out->texels[y * size + x] = c;
        }
    }
    /* Diagonal brace from the bottom-left to the top-right corner. */
    for (y = 0; y < size; y++) {
        for (x = 0; x < size; x++) {
            uint32_t d = x + y, target = size - 1u;
            if (d + frame / 2u + 1u >= target && d <= target + frame / 2u + 1u) {
                out->texels[y * size + x] = FXL_RGB565(110, 70, 30);
            }
        }
    }
    /* Frame. */
    fill_rect(out, 0, 0, size, frame, FXL_RGB565(70, 42, 20));
    fill_rect(out, 0, size - frame, size, frame, FXL_RGB565(70, 42, 20));
    fill_rect(out, 0, 0, frame, size, FXL_RGB565(70, 42, 20));
    fill_rect(out, size - frame, 0, frame, size, FXL_RGB565(70, 42, 20));
    /* Orientation marks (see textures.h). */
    fill_rect(out, 0, 0, mark, mark, FXL_RGB565(255, 0, 0));
    fill_rect(out, size - mark, 0, mark, mark, FXL_RGB565(0, 255, 0));
    fill_rect(out, 0, size - mark, mark, mark, FXL_RGB565(0, 0, 255));
    /* A large "F" in the upper-left quarter, away from the brace. */
    s = size / 16u;
    draw_glyph(out, GLYPH_F, mark + s, mark + s / 2u, s, FXL_RGB565(250, 240, 120));
    build_mips(out);
    return 0;
}

int texture_make_grid(host_texture_t *out, uint32_t size)
{
    uint32_t x, y;
    if (out == NULL) {
        return -1;
    }
    if (size < 32u || alloc_chain(out, size, size) != 0) {
        memset(out, 0, sizeof(*out));
        return -1;
    }
    for (y = 0; y < size; y++) {
        for (x = 0; x < size; x++) {
            uint32_t bx = x / 32u, by = y / 32u, nb = size / 32u;
            uint16_t c = FXL_RGB565(40u + (bx * 160u) / nb + (x % 32u), 40u + (by * 160u) / nb
                                    + (y % 32u), 150u - ((bx + by) * 100u) / (2u * nb));
            if (x % 32u == 0 || y % 32u == 0) {
                c = FXL_RGB565(255, 255, 255);
            } else if (x % 8u == 0 || y % 8u == 0) {
                c = FXL_RGB565(170, 170, 170);
            }
            out->texels[y * size + x] = c;
        }
    }
    /* Block numbers, two digits at scale 2 (6x10 each), centred in the block. */
    for (y = 0; y < size / 32u; y++) {
        for (x = 0; x < size / 32u; x++) {
            uint32_t n = (y * (size / 32u) + x) % 100u;
            uint32_t bx = x * 32u, by = y * 32u;
            draw_glyph(out, n / 10u, bx + 9u, by + 11u, 2u, FXL_RGB565(0, 0, 0));
            draw_glyph(out, n % 10u, bx + 17u, by + 11u, 2u, FXL_RGB565(0, 0, 0));
        }
    }
    build_mips(out);
    return 0;
}

int texture_make(host_texture_t *out, texture_id_t id)
{
    switch (id) {
    case TEXTURE_CHECKER:
        return texture_make_checker(out, 64, 64, 8, FXL_RGB565(235, 235, 235),
                                    FXL_RGB565(40, 40, 48));
    case TEXTURE_CRATE:
        return texture_make_crate(out, 64);
    case TEXTURE_GRID:
        return texture_make_grid(out, 128);
    default:
        if (out != NULL) {
            memset(out, 0, sizeof(*out));
        }
        return -1;
    }
}

const char *texture_name(texture_id_t id)
{
    switch (id) {
    case TEXTURE_CHECKER:
        return "checker";
    case TEXTURE_CRATE:
        return "crate";
    case TEXTURE_GRID:
        return "grid";
    default:
        return "?";
    }
}

uint16_t texture_texel(const host_texture_t *t, uint32_t x, uint32_t y)
{
    return t->texels[y * t->width + x];
}

void texture_free(host_texture_t *t)
{
    if (t != NULL) {
        free(t->texels);
        memset(t, 0, sizeof(*t));
    }
}

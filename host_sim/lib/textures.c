/* textures.c - see textures.h. */
#include "textures.h"

#include <stdlib.h>
#include <string.h>

#include "fixel/target.h"
#include "fixel/texture.h"

/* 3x5 glyphs, one row per entry, bit 2 = left column: digits 0-9, A-Z, then
 * the punctuation of font_chars. The digits and F are what the crate and grid
 * textures were first drawn with; changing them changes those textures. */
static const uint8_t glyph3x5[][5] = {
    {7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7}, {5, 5, 7, 1, 1},
    {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1}, {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7},
    {2, 5, 7, 5, 5}, {6, 5, 6, 5, 6}, {3, 4, 4, 4, 3}, {6, 5, 5, 5, 6}, {7, 4, 6, 4, 7}, /* A-E */
    {7, 4, 6, 4, 4}, {3, 4, 5, 5, 3}, {5, 5, 7, 5, 5}, {7, 2, 2, 2, 7}, {1, 1, 1, 5, 2}, /* F-J */
    {5, 5, 6, 5, 5}, {4, 4, 4, 4, 7}, {5, 7, 7, 5, 5}, {6, 5, 5, 5, 5}, {2, 5, 5, 5, 2}, /* K-O */
    {6, 5, 6, 4, 4}, {2, 5, 5, 6, 3}, {6, 5, 6, 5, 5}, {3, 4, 2, 1, 6}, {7, 2, 2, 2, 2}, /* P-T */
    {5, 5, 5, 5, 7}, {5, 5, 5, 5, 2}, {5, 5, 7, 7, 5}, {5, 5, 2, 5, 5}, {5, 5, 2, 2, 2}, /* U-Y */
    {7, 1, 2, 4, 7},                                                                     /* Z */
    {0, 2, 7, 2, 0}, {0, 0, 7, 0, 0}, {0, 0, 0, 0, 2}, {1, 1, 2, 4, 4}, {0, 2, 0, 2, 0}, /* +-./: */
    {1, 2, 2, 2, 1}, {4, 2, 2, 2, 4}, {0, 0, 0, 2, 4}, {0, 0, 0, 0, 0}};                 /* (), space */
static const char font_punct[] = "+-./:(), ";
#define GLYPH_A 10u
#define GLYPH_PUNCT 36u
#define GLYPH_F (GLYPH_A + 5u)
#define GLYPH_BLANK (GLYPH_PUNCT + 8u)

const uint8_t *texture_font_glyph(char c)
{
    const char *p;
    if (c >= '0' && c <= '9') {
        return glyph3x5[c - '0'];
    }
    if (c >= 'a' && c <= 'z') {
        c = (char)(c - 'a' + 'A');
    }
    if (c >= 'A' && c <= 'Z') {
        return glyph3x5[GLYPH_A + (unsigned)(c - 'A')];
    }
    for (p = font_punct; *p != '\0'; p++) {
        if (*p == c) {
            return glyph3x5[GLYPH_PUNCT + (unsigned)(p - font_punct)];
        }
    }
    return glyph3x5[GLYPH_BLANK];
}

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

/* Levels 1.. from level 0 by the core, as firmware would at start-up. */
static int build_mips(host_texture_t *t, fxl_mip_space_t space)
{
    uint32_t bytes = t->texel_count * (uint32_t)sizeof(uint16_t);
    if (fxl_mip_build(t->texels, bytes, t->width, t->height, FXL_TEXFMT_RGB565, t->tex.levels,
                      NULL, space) != FXL_OK) {
        texture_free(t);
        return -1;
    }
    return 0;
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
    return texture_make_checker_space(out, width, height, cell, c0, c1, FXL_MIP_SPACE_STORED);
}

int texture_make_checker_space(host_texture_t *out, uint32_t width, uint32_t height,
                               uint32_t cell, uint16_t c0, uint16_t c1, fxl_mip_space_t space)
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
    return build_mips(out, space);
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
    return build_mips(out, FXL_MIP_SPACE_STORED);
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
    return build_mips(out, FXL_MIP_SPACE_STORED);
}

int texture_make_cubemap(host_texture_t *out, uint32_t w)
{
    static const char *const names[6] = {"+X", "-X", "+Y", "-Y", "+Z", "-Z"};
    static const uint8_t rgb[6][3] = {{210, 70, 60},  {60, 190, 200}, {80, 200, 70},
                                      {190, 80, 200}, {70, 100, 220}, {225, 200, 60}};
    uint32_t x, y, tw = 2u * w;
    double tile_w = (double)tw / 3.0, tile_h = (double)w / 2.0;
    if (out == NULL) {
        return -1;
    }
    if (w < 32u || alloc_chain(out, tw, w) != 0) {
        memset(out, 0, sizeof(*out));
        return -1;
    }
    for (y = 0; y < w; y++) {
        for (x = 0; x < tw; x++) {
            /* Tile of the texel centre, and the centre's position in it. */
            double cx = ((double)x + 0.5) / tile_w, cy = ((double)y + 0.5) / tile_h;
            int col = (int)cx, row = (int)cy, f = row * 3 + col;
            double lx = (cx - col) * tile_w, ly = (cy - row) * tile_h; /* texels */
            double scale = tile_h / 8.0, gx0 = (tile_w - 7.0 * scale) / 2.0, gy0 = 1.5 * scale;
            const uint8_t *c = rgb[f];
            uint16_t v = FXL_RGB565(c[0], c[1], c[2]);
            int line_x = (int)(lx * 8.0 / tile_w) != (int)((lx + 1.0) * 8.0 / tile_w);
            int line_y = (int)(ly * 8.0 / tile_h) != (int)((ly + 1.0) * 8.0 / tile_h);
            if (line_x || line_y) {
                v = FXL_RGB565(c[0] / 2u + 100u, c[1] / 2u + 100u, c[2] / 2u + 100u);
            }
            /* Label: two glyphs at `scale` texels per font pixel, one blank
             * column between them, centred across and high in the tile. */
            if (lx >= gx0 && ly >= gy0 && ly < gy0 + 5.0 * scale && lx < gx0 + 7.0 * scale) {
                int fx = (int)((lx - gx0) / scale), fy = (int)((ly - gy0) / scale);
                if (fx != 3) {
                    const uint8_t *g = texture_font_glyph(names[f][fx / 4]);
                    if (g[fy] & (4u >> (fx % 4))) {
                        v = FXL_RGB565(250, 250, 250);
                    }
                }
            }
            if (lx < 2.0 || ly < 2.0 || lx > tile_w - 2.0 || ly > tile_h - 2.0) {
                v = FXL_RGB565(24, 24, 28);
            }
            out->texels[y * tw + x] = v;
        }
    }
    return build_mips(out, FXL_MIP_SPACE_SRGB);
}

uint16_t texture_level_tint(uint32_t level)
{
    static const uint8_t rgb[8][3] = {{255, 0, 0},   {255, 128, 0}, {255, 255, 0},
                                      {0, 255, 0},   {0, 255, 255}, {0, 64, 255},
                                      {255, 0, 255}, {128, 128, 128}};
    const uint8_t *c = rgb[level < 7u ? level : 7u];
    return FXL_RGB565(c[0], c[1], c[2]);
}

static int make_level_tinted(host_texture_t *out)
{
    uint32_t l, i, off = 0;
    if (texture_make_checker_space(out, 256, 256, 16, FXL_RGB565(255, 255, 255),
                                   FXL_RGB565(0, 0, 0), FXL_MIP_SPACE_SRGB) != 0) {
        return -1;
    }
    for (l = 0; l < out->tex.levels; l++) {
        uint32_t n = level_dim(out->width, l) * level_dim(out->height, l);
        uint16_t t = texture_level_tint(l);
        for (i = 0; i < n; i++) {
            uint16_t c = out->texels[off + i];
            /* per channel (c + t + 1) / 2: the checker stays visible */
            uint16_t r = (uint16_t)((((c >> 11) & 31u) + ((t >> 11) & 31u) + 1u) >> 1);
            uint16_t g = (uint16_t)((((c >> 5) & 63u) + ((t >> 5) & 63u) + 1u) >> 1);
            uint16_t b = (uint16_t)(((c & 31u) + (t & 31u) + 1u) >> 1);
            out->texels[off + i] = (uint16_t)((r << 11) | (g << 5) | b);
        }
        off += n;
    }
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
    case TEXTURE_CHECKER_HC:
        return texture_make_checker_space(out, 256, 256, 16, FXL_RGB565(255, 255, 255),
                                          FXL_RGB565(0, 0, 0), FXL_MIP_SPACE_SRGB);
    case TEXTURE_CUBEMAP:
        return texture_make_cubemap(out, 128);
    case TEXTURE_CHECKER_HC_LEVELS:
        return make_level_tinted(out);
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
    case TEXTURE_CHECKER_HC:
        return "checker_hc";
    case TEXTURE_CUBEMAP:
        return "cubemap";
    case TEXTURE_CHECKER_HC_LEVELS:
        return "checker_hc_levels";
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

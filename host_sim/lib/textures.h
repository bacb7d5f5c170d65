/* textures.h - procedural RGB565 textures for the simulator scenes, host side.
 *
 * Each maker fills a host_texture_t: malloc'd texel storage holding the full
 * mip chain and a ready fxl_texture_t describing it (RGB565, repeat wrap on
 * both axes, no key, levels = the whole chain). Free with texture_free().
 * The makers draw level 0; levels 1.. are built by the core's fxl_mip_build
 * (texture.h: each level the 2x2 box average of the previous one, per channel
 * rounded to nearest, (a + b + c + d + 2) >> 2 for FXL_MIP_SPACE_STORED; 1x2 /
 * 2x1 once a side is 1), exactly as firmware would build them at start-up.
 *
 * All makers return 0, or -1 on bad arguments / out of memory (out is then
 * zeroed). Colours are native RGB565.
 */
#ifndef FXL_HOST_TEXTURES_H
#define FXL_HOST_TEXTURES_H

#include <stdint.h>
#include "fixel/texture.h"

typedef struct host_texture {
    uint16_t *texels;     /* malloc'd: whole chain, level 0 first */
    uint32_t width, height;
    uint32_t texel_count; /* texels in the whole chain */
    fxl_texture_t tex;    /* points into texels */
} host_texture_t;

/* The textures the scenes use (scene_t.texture). */
typedef enum texture_id {
    TEXTURE_CHECKER = 0,  /* 64x64, 8x8-texel cells, white / dark grey */
    TEXTURE_CRATE = 1,    /* 64x64 wooden crate with orientation marks */
    TEXTURE_GRID = 2,     /* 128x128, thin lines every 8 texels, numbered blocks */
    TEXTURE_CHECKER_HC = 3, /* 256x256, 16x16-texel cells, black / white; mips
                               averaged in linear light (FXL_MIP_SPACE_SRGB) */
    TEXTURE_CUBEMAP = 4,  /* 256x128 atlas of the six cube-map faces (below) */
    TEXTURE_CHECKER_HC_LEVELS = 5, /* TEXTURE_CHECKER_HC with every level n mixed
                               50:50 with a colour of its own (texture_level_tint)
                               after fxl_mip_build: shows which level is sampled */
    TEXTURE_COUNT
} texture_id_t;

/* Checkerboard: width x height (powers of two), square cells of `cell`
 * texels (>= 1), colour c0 where (x / cell + y / cell) is even, else c1. */
int texture_make_checker(host_texture_t *out, uint32_t width, uint32_t height, uint32_t cell,
                         uint16_t c0, uint16_t c1);
/* The same with the mip levels averaged in `space` (fxl_mip_space_t). */
int texture_make_checker_space(host_texture_t *out, uint32_t width, uint32_t height,
                               uint32_t cell, uint16_t c0, uint16_t c1, fxl_mip_space_t space);

/* Cube-map atlas for FXL_TEXGEN_CUBE (pipeline.h): 2w x w texels (w a power
 * of two >= 32), face f is the tile u in [(f % 3) / 3, (f % 3 + 1) / 3),
 * v in [(f / 3) / 2, (f / 3 + 1) / 2) (tile edges fall between texels when
 * 2w is not a multiple of 3; a texel belongs to the tile of its centre).
 * Each tile: its own colour, a dark frame (so bilinear reads across a tile
 * edge blend dark with dark), thin lines every 1/8 tile, and its name
 * ("+X", "-X", "+Y", "-Y", "+Z", "-Z") upright in the tile's (s, t) frame,
 * i.e. left to right along s, top to bottom along t. */
int texture_make_cubemap(host_texture_t *out, uint32_t w);

/* Crate: size x size (power of two >= 16). Planks with a dark frame and a
 * diagonal brace, plus marks that reveal any flip, rotation or swap of u/v:
 * a red square at texel (0, 0) (u = 0, v = 0 corner), a green one at the
 * u = 1, v = 0 corner, a blue one at the u = 0, v = 1 corner (the u = 1,
 * v = 1 corner has none), and a large letter "F" (no symmetry). */
int texture_make_crate(host_texture_t *out, uint32_t size);

/* Grid: size x size (power of two >= 32). One-texel grey lines at every
 * multiple of 8 texels (so subdivision and wrap errors show as broken or
 * bent lines), cell colours that change with position, and each 32x32
 * block carries its number (row-major, 0 = top left) in a small font. */
int texture_make_grid(host_texture_t *out, uint32_t size);

/* The default texture for an id, with the sizes documented above. */
int texture_make(host_texture_t *out, texture_id_t id);

/* Name of an id ("checker", "crate", "grid"), or "?" */
const char *texture_name(texture_id_t id);

/* Tint of mip level n in TEXTURE_CHECKER_HC_LEVELS: 0 red, 1 orange,
 * 2 yellow, 3 green, 4 cyan, 5 blue, 6 magenta, 7 and above grey. */
uint16_t texture_level_tint(uint32_t level);

/* A 3x5 pixel font for labels: rows of glyph `c` (bit 2 = left column) for
 * digits, A-Z (either case), '+', '-', '.', '/', ':', '(', ')', ',' and ' '
 * (anything else draws as a blank). */
const uint8_t *texture_font_glyph(char c);

/* Native RGB565 texel of level 0 at (x, y), no wrap (caller keeps in range). */
uint16_t texture_texel(const host_texture_t *t, uint32_t x, uint32_t y);

void texture_free(host_texture_t *t);

#endif

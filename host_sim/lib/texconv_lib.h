/* host_sim/lib/texconv_lib.h - PNG -> fixel texture chain (the fixel-texconv tool).
 *
 * Host only (libpng, malloc, stdio). The tool's main is texconv_main(); the
 * steps are exposed so tests can check each one in memory:
 *   texconv_read_png   any PNG colour type -> 8-bit RGBA
 *   texconv_convert    RGBA -> texel format, colour key, I8 palette, mip chain
 *   texconv_write_c    C source: static texel (+ palette) arrays + descriptor
 *   texconv_write_bin  raw little-endian blob for external flash (layout below)
 *
 * Conversions (documented in docs/textures.md):
 *   RGB565  r5 = (r * 31 + 127) / 255, g6 = (g * 63 + 127) / 255, b5 like r5
 *   L8      l = (77 r + 150 g + 29 b + 128) >> 8   (BT.601 weights, grey exact)
 *   I8      exact palette when the opaque pixels have <= 256 distinct RGB565
 *           colours (255 with a key), else median cut; nearest entry by squared
 *           distance of 8-bit expanded RGB, ties to the lowest index.
 * Colour key (--key RRGGBB): a pixel is transparent when its alpha < 128 or
 * its RGB equals RRGGBB exactly; it is stored as the key value (RGB565 of the
 * key, L8 luminance of the key, or I8 index 0). An opaque pixel that would
 * convert to the key value is moved off it (RGB565 blue LSB flipped, L8 one
 * step up / 254 for 255, I8 never maps to index 0). Without --key, alpha is
 * ignored. Mip levels use the keyed rule of src/mip.c.
 *
 * Blob (--bin), little-endian, 24-byte header:
 *   0 "FXLT"  4 u16 version (1)  6 u8 log2_w  7 u8 log2_h  8 u8 levels
 *   9 u8 format  10 u8 wrap_u  11 u8 wrap_v  12 u8 flags  13 u8 0
 *   14 u16 key  16 u16 border  18 u16 0  20 u32 texel count of the chain
 *   24: I8 only: 256 x u16 palette; then the chain (u16 per RGB565 texel,
 *   u8 per L8/I8 texel).
 */
#ifndef FIXEL_HOST_TEXCONV_LIB_H
#define FIXEL_HOST_TEXCONV_LIB_H

#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "fixel/texture.h"

#define TEXCONV_BLOB_VERSION 1u
#define TEXCONV_BLOB_HEADER_BYTES 24u

typedef enum texconv_mips {
    TEXCONV_MIPS_NONE = 0,    /* level 0 only */
    TEXCONV_MIPS_BOX = 1,     /* full chain, FXL_MIP_SPACE_STORED */
    TEXCONV_MIPS_GAMMA22 = 2, /* full chain, FXL_MIP_SPACE_GAMMA22 */
    TEXCONV_MIPS_SRGB = 3     /* full chain, FXL_MIP_SPACE_SRGB */
} texconv_mips_t;

typedef struct texconv_opts {
    fxl_texfmt_t format;      /* default RGB565 */
    texconv_mips_t mips;      /* default BOX */
    int has_key;              /* colour key on */
    uint32_t key_rgb;         /* 0xRRGGBB */
    fxl_wrap_t wrap_u, wrap_v;/* default repeat */
    uint32_t border_rgb;      /* 0xRRGGBB, for FXL_WRAP_BORDER (default black) */
} texconv_opts_t;

typedef struct texconv_image {
    uint32_t width, height;
    uint8_t *rgba;            /* width * height * 4 bytes, malloc'd */
} texconv_image_t;

typedef struct texconv_chain {
    fxl_texture_t tex;        /* .texels / .palette point at the buffers below */
    void *texels;             /* the whole chain, malloc'd */
    uint32_t texel_count;     /* texels in the chain */
    uint32_t bytes;           /* bytes of the chain */
    uint16_t *palette;        /* I8: 256 entries, malloc'd; else NULL */
    uint32_t palette_used;    /* I8: distinct entries produced (incl. the key) */
} texconv_chain_t;

void texconv_opts_default(texconv_opts_t *o);

/* The converter's colour conversions (see the top of this file). */
uint16_t texconv_rgb565(uint32_t r, uint32_t g, uint32_t b);
uint8_t texconv_luma(uint32_t r, uint32_t g, uint32_t b);

/* 0 on success; else -1 with a message naming `path` in err. */
int texconv_read_png(const char *path, texconv_image_t *img, char *err, size_t err_size);
void texconv_image_free(texconv_image_t *img);

/* 0 on success (chain filled, fxl_texture_validate passes); else -1 + err. */
int texconv_convert(const texconv_image_t *img, const texconv_opts_t *o, texconv_chain_t *out,
                    char *err, size_t err_size);
void texconv_chain_free(texconv_chain_t *c);

/* Writers: 0 on success, -1 on a write error. `command` goes into the header
 * comment ("*" "/" sequences are defused); `name` must be a C identifier. */
int texconv_write_c(FILE *f, const texconv_chain_t *c, const char *name, const char *command,
                    const texconv_opts_t *o);
int texconv_write_bin(FILE *f, const texconv_chain_t *c);

/* The whole tool: argument parsing, conversion, atomic writes (temp file +
 * rename; nothing is left behind on error). Returns the exit status. */
int texconv_main(int argc, char **argv);

#endif

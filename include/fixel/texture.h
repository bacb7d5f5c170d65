/* fixel/texture.h - texture descriptors, texel formats, wrap modes, mip chains.
 *
 * A texture is a chain of `levels` power-of-two levels stored contiguously:
 * level 0 (2^log2_w x 2^log2_h texels, rows tightly packed), then level 1
 * (each side halved, never below 1), ... down to at most 1x1. The descriptor
 * holds no derived data, so it can be a `const` initialiser in flash (the
 * converter fixel-texconv writes one); every draw validates it.
 *
 * Formats: RGB565 (native-endian uint16_t), L8 (8-bit luminance, grey),
 * I8 (8-bit index into `palette`, 256 native RGB565 entries).
 * Colour key: with FXL_TEXF_KEY set, a texel whose *stored* value equals `key`
 * (the RGB565 word, the L8 byte or the I8 index) is transparent: the pixel is
 * not drawn and its depth is not written (except with FXL_TEXENV_DECAL, which
 * draws the draw's colour there: raster.h). Filtering never blends a key texel
 * into its neighbours: with bilinear filtering the pixel is drawn only if the
 * nearest texel is opaque, and any key texel of the 2x2 footprint takes that
 * nearest texel's colour (weights unchanged, no division).
 * Sizes: power-of-two sides 1 .. 2^FXL_TEX_MAX_LOG2 only; other sizes get
 * FXL_ERR_UNSUPPORTED (pad or resample the image first: fixel-texconv
 * refuses other sizes too).
 * Texture coordinates are normalised: 1.0 (q16 65536) is one texture width.
 */
#ifndef FIXEL_TEXTURE_H
#define FIXEL_TEXTURE_H

#include <stdint.h>
#include "fixel/config.h"
#include "fixel/status.h"
#include "fixel/fixed.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef enum fxl_texfmt {
    FXL_TEXFMT_RGB565 = 0,
    FXL_TEXFMT_L8 = 1,
    FXL_TEXFMT_I8 = 2
} fxl_texfmt_t;

typedef enum fxl_wrap {
    FXL_WRAP_REPEAT = 0,      /* coordinate modulo size */
    FXL_WRAP_MIRROR = 1,      /* mirrored repeat: 0..n-1, n-1..0, ... */
    FXL_WRAP_CLAMP = 2,       /* clamp to edge texel */
    FXL_WRAP_BORDER = 3       /* outside [0, n) reads `border` */
} fxl_wrap_t;

#define FXL_TEXF_KEY 0x01u    /* colour key enabled */

#define FXL_TEX_MAX_LEVELS (FXL_TEX_MAX_LOG2 + 1)

typedef struct fxl_texture {
    const void *texels;        /* the whole chain, level 0 first; RGB565: 2-byte aligned */
    const uint16_t *palette;   /* I8 only: 256 native RGB565 colours, 2-byte aligned; the
                                * caller sets it after fxl_texture_init (which leaves it
                                * NULL: validate and draws say FXL_ERR_ARG until then) */
    uint8_t log2_w, log2_h;    /* level 0 is (1 << log2_w) x (1 << log2_h) */
    uint8_t levels;            /* 1 .. 1 + max(log2_w, log2_h) */
    uint8_t format;            /* fxl_texfmt_t */
    uint8_t wrap_u, wrap_v;    /* fxl_wrap_t, per axis */
    uint8_t flags;             /* FXL_TEXF_* */
    uint8_t reserved;          /* 0 */
    uint16_t key;              /* stored texel value that is transparent */
    uint16_t border;           /* native RGB565 colour for FXL_WRAP_BORDER */
} fxl_texture_t;

/* Describe existing texel data: repeat wrap on both axes, no key.
 * width and height must be powers of two (else FXL_ERR_UNSUPPORTED, as
 * sides beyond 1 << FXL_TEX_MAX_LOG2); levels in 1 .. fxl_mip_levels()
 * (else FXL_ERR_RANGE); NULL, a zero side, an unknown format or RGB565
 * texels at an odd address: FXL_ERR_ARG. */
fxl_status_t fxl_texture_init(fxl_texture_t *t, const void *texels, uint32_t width,
                              uint32_t height, fxl_texfmt_t format, uint32_t levels);
/* FXL_OK when the descriptor is usable (draws call this too): the checks
 * of fxl_texture_init, plus wrap modes, the I8 palette (set, aligned), the
 * reserved byte and flags, and a key an 8-bit format can hold. */
fxl_status_t fxl_texture_validate(const fxl_texture_t *t);
/* Bytes per texel of a format (0 for an unknown format). */
uint32_t fxl_texfmt_bytes(fxl_texfmt_t format);
/* Offset of the first texel of `level` from `texels`, in texels. A level
 * past the chain gives the chain's length (the offset just after it); NULL
 * or an invalid size gives 0. */
uint32_t fxl_texture_level_offset(const fxl_texture_t *t, uint32_t level);

/* Wrap-aware texel read at integer texel (x, y) of `level`, as native RGB565.
 * *transparent (may be NULL) is set to 1 for a key texel, else 0. Any x, y.
 * An invalid descriptor (fxl_texture_validate) or a level >= t->levels reads
 * opaque black (0) and touches no texel. */
uint16_t fxl_texture_fetch(const fxl_texture_t *t, uint32_t level, int32_t x, int32_t y,
                           int *transparent);

/* ---- mip chains (src/mip.c) ---------------------------------------------- */

typedef enum fxl_mip_space {
    FXL_MIP_SPACE_STORED = 0,  /* average the stored values */
    FXL_MIP_SPACE_GAMMA22 = 1, /* decode with gamma 2.2, average in linear light, encode */
    FXL_MIP_SPACE_SRGB = 2     /* the same with the sRGB transfer function */
} fxl_mip_space_t;

/* Number of levels of a full chain for width x height: 1 + log2(max side).
 * 0 when a side is 0, not a power of two, or too large. */
uint32_t fxl_mip_levels(uint32_t width, uint32_t height);
/* Bytes needed for `levels` levels (0 on bad input). */
uint32_t fxl_mip_size(uint32_t width, uint32_t height, fxl_texfmt_t format, uint32_t levels);
/* Build levels 1 .. levels-1 in place: `storage` already holds level 0 and has
 * room for fxl_mip_size() bytes. Level n is the 2x2 box average of level n-1
 * (1x2 / 2x1 once a side reaches 1), each channel rounded to nearest. I8
 * levels average palette colours and store the nearest palette entry.
 * FXL_ERR_ARG for NULL storage, a zero side, an unknown format or space, an
 * I8 palette that is NULL or at an odd address, or (RGB565) odd storage;
 * FXL_ERR_UNSUPPORTED for a side that is not a power of two or is above
 * 1 << FXL_TEX_MAX_LOG2; FXL_ERR_RANGE for levels outside
 * 1 .. fxl_mip_levels(); FXL_ERR_NOMEM when storage_bytes is below
 * fxl_mip_size(). */
fxl_status_t fxl_mip_build(void *storage, uint32_t storage_bytes, uint32_t width, uint32_t height,
                           fxl_texfmt_t format, uint32_t levels, const uint16_t *palette,
                           fxl_mip_space_t space);
/* The same with a colour key (*key: the stored value that is transparent;
 * NULL is fxl_mip_build): a level-n texel is transparent when at least half
 * of its sources are (2 of 4, 1 of 2), otherwise the average of its opaque
 * sources, nudged off the key value (RGB565: blue LSB flipped, L8: one code,
 * I8: the key index is never chosen). A key at an odd address is
 * FXL_ERR_ARG; a key above 255 for L8 or I8 is FXL_ERR_RANGE (as in
 * fxl_texture_validate). */
fxl_status_t fxl_mip_build_keyed(void *storage, uint32_t storage_bytes, uint32_t width, uint32_t height,
                                 fxl_texfmt_t format, uint32_t levels, const uint16_t *palette,
                                 fxl_mip_space_t space, const uint16_t *key);

#ifdef __cplusplus
}
#endif
#endif

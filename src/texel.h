/* src/texel.h - per-texel helpers shared by the core (internal, not installed).
 *
 * One source of truth for wrap addressing and texel decoding: fxl_texture_fetch
 * (texture.c) and the span loops call these inline helpers, so the reference
 * fetch and the hot loops cannot disagree. The descriptor is assumed valid
 * (fxl_texture_validate passed): no checks are repeated per texel.
 *
 * Indices are texel indices inside one level; a level is (1 << log2_w) x
 * (1 << log2_h) texels, rows tightly packed: index = (y << log2_w) + x.
 */
#ifndef FIXEL_TEXEL_H
#define FIXEL_TEXEL_H

#include <stddef.h>
#include <stdint.h>
#include "fixel/texture.h"
#include "align.h"

/* Power-of-two sizes (texture.c, mip.c). */
static inline int fxl__is_pow2(uint32_t v)
{
    return v != 0u && (v & (v - 1u)) == 0u;
}

/* log2 of a power of two (v >= 1). */
static inline uint32_t fxl__log2_pow2(uint32_t v)
{
    uint32_t n = 0;
    while (v > 1u) {
        v >>= 1;
        n++;
    }
    return n;
}

/* Side (log2) of mip level `level` of a side of 2^log2_size: halved per
 * level, never below 1 texel. */
static inline uint32_t fxl__level_log2(uint32_t log2_size, uint32_t level)
{
    return log2_size > level ? log2_size - level : 0u;
}

/* Wrap integer texel coordinate `coord` (any int32, INT32_MIN..INT32_MAX) into
 * a side of n = 2^log2_size texels (log2_size <= 14):
 *   REPEAT  coord mod n                     (-1 -> n-1)
 *   MIRROR  m = coord mod 2n; m < n ? m : 2n-1-m   (-1 -> 0, -n -> n-1)
 *   CLAMP   min(max(coord, 0), n-1)
 *   BORDER  coord if 0 <= coord < n, else -1 (read the border colour)
 * The result is always in [0, n) or exactly -1. The modulo uses the
 * two's-complement bit pattern: (uint32_t)coord is coord mod 2^32 (defined
 * by C99 6.3.1.3), and 2^32 is a multiple of n and 2n, so masking the low
 * bits gives the true mathematical remainder for negative coord too.
 * An unknown mode behaves like CLAMP (validated descriptors never have one). */
static inline int32_t fxl__wrap(int32_t coord, uint32_t log2_size, fxl_wrap_t mode)
{
    const uint32_t n = 1u << log2_size;
    uint32_t m;

    switch (mode) {
    case FXL_WRAP_REPEAT:
        return (int32_t)((uint32_t)coord & (n - 1u));
    case FXL_WRAP_MIRROR:
        m = (uint32_t)coord & (2u * n - 1u);
        return (int32_t)(m < n ? m : 2u * n - 1u - m);
    case FXL_WRAP_BORDER:
        return (coord >= 0 && (uint32_t)coord < n) ? coord : -1;
    case FXL_WRAP_CLAMP:
    default:
        if (coord < 0)
            return 0;
        return (uint32_t)coord >= n ? (int32_t)(n - 1u) : coord;
    }
}

/* L8 luminance -> native RGB565 grey: r5 = l >> 3, g6 = l >> 2, b5 = l >> 3. */
static inline uint16_t fxl__l8_rgb565(uint32_t l)
{
    return (uint16_t)(((l >> 3) << 11) | ((l >> 2) << 5) | (l >> 3));
}

/* Texel `index` of the level starting at `level_base`, as native RGB565.
 * *transparent (must not be NULL) is set to 1 when FXL_TEXF_KEY is set and
 * the stored value (RGB565 word, L8 byte or I8 index) equals t->key, else 0. */
static inline uint16_t fxl__texel_rgb565(const fxl_texture_t *t, const void *level_base,
                                         uint32_t index, int *transparent)
{
    uint32_t stored;
    uint16_t rgb;

    switch (t->format) {
    case FXL_TEXFMT_L8:
        stored = ((const uint8_t *)level_base)[index];
        rgb = fxl__l8_rgb565(stored);
        break;
    case FXL_TEXFMT_I8:
        stored = ((const uint8_t *)level_base)[index];
        rgb = t->palette[stored];
        break;
    case FXL_TEXFMT_RGB565:
    default:
        stored = ((const uint16_t *)level_base)[index];
        rgb = (uint16_t)stored;
        break;
    }
    *transparent = (t->flags & FXL_TEXF_KEY) != 0u && stored == t->key;
    return rgb;
}

#endif

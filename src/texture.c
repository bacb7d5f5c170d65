/* src/texture.c - texture descriptors: validation, level layout, reference fetch.
 *
 * The per-texel work (wrap, decode, key) lives in texel.h so that the span
 * loops and fxl_texture_fetch share it; this file is the API boundary.
 */
#include "fixel/texture.h"
#include "texel.h"

uint32_t fxl_texfmt_bytes(fxl_texfmt_t format)
{
    switch (format) {
    case FXL_TEXFMT_RGB565:
        return 2u;
    case FXL_TEXFMT_L8:
    case FXL_TEXFMT_I8:
        return 1u;
    default:
        return 0u;
    }
}

fxl_status_t fxl_texture_init(fxl_texture_t *t, const void *texels, uint32_t width,
                              uint32_t height, fxl_texfmt_t format, uint32_t levels)
{
    uint32_t lw, lh, max_levels;

    if (t == NULL || texels == NULL || width == 0u || height == 0u)
        return FXL_ERR_ARG;
    if (fxl_texfmt_bytes(format) == 0u || !fxl__aligned(texels, fxl_texfmt_bytes(format)))
        return FXL_ERR_ARG;
    if (!fxl__is_pow2(width) || !fxl__is_pow2(height))
        return FXL_ERR_UNSUPPORTED;
    lw = fxl__log2_pow2(width);
    lh = fxl__log2_pow2(height);
    if (lw > FXL_TEX_MAX_LOG2 || lh > FXL_TEX_MAX_LOG2)
        return FXL_ERR_UNSUPPORTED;
    max_levels = 1u + (lw > lh ? lw : lh);
    if (levels == 0u || levels > max_levels)
        return FXL_ERR_RANGE;

    /* An I8 descriptor is complete only once the caller sets t->palette;
     * validate (and every draw) reports FXL_ERR_ARG until then. */
    t->texels = texels;
    t->palette = NULL;
    t->log2_w = (uint8_t)lw;
    t->log2_h = (uint8_t)lh;
    t->levels = (uint8_t)levels;
    t->format = (uint8_t)format;
    t->wrap_u = (uint8_t)FXL_WRAP_REPEAT;
    t->wrap_v = (uint8_t)FXL_WRAP_REPEAT;
    t->flags = 0u;
    t->reserved = 0u;
    t->key = 0u;
    t->border = 0u;
    return FXL_OK;
}

fxl_status_t fxl_texture_validate(const fxl_texture_t *t)
{
    uint32_t max_log2;

    if (t == NULL || t->texels == NULL)
        return FXL_ERR_ARG;
    if (t->log2_w > FXL_TEX_MAX_LOG2 || t->log2_h > FXL_TEX_MAX_LOG2)
        return FXL_ERR_UNSUPPORTED;
    if (fxl_texfmt_bytes((fxl_texfmt_t)t->format) == 0u ||
        !fxl__aligned(t->texels, fxl_texfmt_bytes((fxl_texfmt_t)t->format)))
        return FXL_ERR_ARG;
    if (t->wrap_u > FXL_WRAP_BORDER || t->wrap_v > FXL_WRAP_BORDER)
        return FXL_ERR_ARG;
    if (t->format == FXL_TEXFMT_I8 && (t->palette == NULL || !fxl__aligned(t->palette, 2u)))
        return FXL_ERR_ARG;
    /* Unknown flag bits and a non-zero reserved byte are refused so that
     * future meanings cannot be silently ignored by this version. */
    if (t->reserved != 0u || (t->flags & ~FXL_TEXF_KEY) != 0u)
        return FXL_ERR_ARG;
    max_log2 = t->log2_w > t->log2_h ? t->log2_w : t->log2_h;
    if (t->levels == 0u || t->levels > 1u + max_log2)
        return FXL_ERR_RANGE;
    /* An 8-bit format stores values 0..255: a larger key could never match,
     * which is almost certainly a mistake (e.g. an RGB565 key on L8 data). */
    if ((t->flags & FXL_TEXF_KEY) != 0u && t->format != FXL_TEXFMT_RGB565 && t->key > 255u)
        return FXL_ERR_RANGE;
    return FXL_OK;
}

/* Level n is max(1, w >> n) x max(1, h >> n); offsets sum the earlier levels.
 * Range: at most 1 + FXL_TEX_MAX_LOG2 (<= 15) levels of at most 2^28 texels,
 * a sum below 2^30, so uint32_t cannot overflow. */
uint32_t fxl_texture_level_offset(const fxl_texture_t *t, uint32_t level)
{
    uint32_t n, off = 0;

    if (t == NULL || t->log2_w > FXL_TEX_MAX_LOG2 || t->log2_h > FXL_TEX_MAX_LOG2)
        return 0u;
    if (level > t->levels)
        level = t->levels;
    for (n = 0; n < level; n++)
        off += 1u << (fxl__level_log2(t->log2_w, n) + fxl__level_log2(t->log2_h, n));
    return off;
}

uint16_t fxl_texture_fetch(const fxl_texture_t *t, uint32_t level, int32_t x, int32_t y,
                           int *transparent)
{
    int key_hit = 0;
    uint16_t rgb = 0u;
    uint32_t lw, lh;
    int32_t ix, iy;
    const uint8_t *base;

    /* An invalid descriptor or level reads as opaque black: there is no
     * status channel here and nothing outside the chain may be touched. */
    if (fxl_texture_validate(t) == FXL_OK && level < t->levels) {
        lw = fxl__level_log2(t->log2_w, level);
        lh = fxl__level_log2(t->log2_h, level);
        ix = fxl__wrap(x, lw, (fxl_wrap_t)t->wrap_u);
        iy = fxl__wrap(y, lh, (fxl_wrap_t)t->wrap_v);
        if (ix < 0 || iy < 0) {
            rgb = t->border; /* border texels are never transparent */
        } else {
            base = (const uint8_t *)t->texels +
                   fxl_texture_level_offset(t, level) * fxl_texfmt_bytes((fxl_texfmt_t)t->format);
            rgb = fxl__texel_rgb565(t, base, ((uint32_t)iy << lw) + (uint32_t)ix, &key_hit);
        }
    }
    if (transparent != NULL)
        *transparent = key_hit;
    return rgb;
}

/* src/mip.c - building a mip chain in place (once, at start-up or on the host).
 *
 * Level n is the box average of level n-1: 2x2 sources per texel, or 2x1 /
 * 1x2 once one side is 1. Each channel is averaged separately with round half
 * up: (a+b+c+d+2)>>2, (a+b+1)>>1, and (sum + cnt/2) / cnt when the colour key
 * leaves 3 opaque sources.
 *
 * Averaging space: STORED averages the codes themselves (RGB565 as 5/6/5-bit
 * channels, L8 bytes, I8 palette colours expanded to 8 bits per channel).
 * GAMMA22 / SRGB decode each code to 16-bit linear light with the tables of
 * mip_tables.h, average there and encode back to the code whose linear value
 * is nearest (a tie between two codes takes the higher one). The tables are
 * strictly increasing, so a uniform area keeps its exact code.
 * I8: the average colour (8 bits per channel) is matched to the nearest
 * palette entry by squared distance, ties to the lowest index; when all
 * sources share one index it is kept as is.
 */
#include "fixel/texture.h"
#include "texel.h"
#include "mip_tables.h"

/* Lookup tables and parameters for one build. */
typedef struct mipctx {
    fxl_texfmt_t format;
    const uint16_t *palette;
    const uint16_t *lin5, *lin6, *lin8; /* NULL in STORED space */
    int keyed;
    uint32_t key;
} mipctx_t;

uint32_t fxl_mip_levels(uint32_t width, uint32_t height)
{
    uint32_t lw, lh;

    if (!fxl__is_pow2(width) || !fxl__is_pow2(height))
        return 0u;
    lw = fxl__log2_pow2(width);
    lh = fxl__log2_pow2(height);
    if (lw > FXL_TEX_MAX_LOG2 || lh > FXL_TEX_MAX_LOG2)
        return 0u;
    return 1u + (lw > lh ? lw : lh);
}

/* Texels of the first `levels` levels. Sides <= 2^14, so the chain holds
 * fewer than 4/3 * 2^28 + 2^15 texels and the sum fits in 32 bits. */
static uint32_t chain_texels(uint32_t width, uint32_t height, uint32_t levels)
{
    uint32_t n, sum = 0;

    for (n = 0; n < levels; n++) {
        sum += width * height;
        if (width > 1u)
            width >>= 1;
        if (height > 1u)
            height >>= 1;
    }
    return sum;
}

uint32_t fxl_mip_size(uint32_t width, uint32_t height, fxl_texfmt_t format, uint32_t levels)
{
    uint32_t max_levels = fxl_mip_levels(width, height);
    uint32_t bytes = fxl_texfmt_bytes(format);

    if (max_levels == 0u || bytes == 0u || levels == 0u || levels > max_levels)
        return 0u;
    /* At most 2 * (4/3 * 2^28 + 2^15) < 2^30 bytes: no overflow. */
    return chain_texels(width, height, levels) * bytes;
}

static uint32_t expand5(uint32_t c) { return (c << 3) | (c >> 2); }
static uint32_t expand6(uint32_t c) { return (c << 2) | (c >> 4); }

/* Nearest code for the linear value sum / n (n = 1..4 sources) in a
 * strictly increasing table of `count` entries: binary search for the first
 * entry >= sum / n, then compare with the one below; an exact tie goes to
 * the higher code. Compared as n t against sum (<= 4 * 65535), so the mean
 * is never rounded first: rounding it to an integer picks the farther
 * code when the exact mean lies within half a unit of the midpoint (L8
 * {140, 28} in gamma 2.2: 104 for a mean nearer 103; 71 of 268,920 texels
 * in a review's sweep). */
static uint32_t encode_lin(const uint16_t *table, uint32_t count, uint32_t sum, uint32_t n)
{
    uint32_t lo = 0, hi = count - 1u, mid;

    if (sum >= n * table[hi])
        return hi;
    while (lo < hi) { /* invariant: n table[hi] >= sum; answer in [lo, hi] */
        mid = lo + ((hi - lo) >> 1);
        if (n * table[mid] >= sum)
            hi = mid;
        else
            lo = mid + 1u;
    }
    if (lo > 0u && sum - n * table[lo - 1u] < n * table[lo] - sum)
        return lo - 1u;
    return lo;
}

/* Stored texel -> 3 channels in the averaging space (L8 uses channel 0). */
static void decode(const mipctx_t *m, uint32_t stored, uint32_t ch[3])
{
    uint32_t c;

    switch (m->format) {
    case FXL_TEXFMT_L8:
        ch[0] = m->lin8 != NULL ? m->lin8[stored] : stored;
        ch[1] = ch[2] = 0u;
        return;
    case FXL_TEXFMT_I8:
        c = m->palette[stored];
        if (m->lin8 != NULL) {
            ch[0] = m->lin5[c >> 11];
            ch[1] = m->lin6[(c >> 5) & 63u];
            ch[2] = m->lin5[c & 31u];
        } else {
            ch[0] = expand5(c >> 11);
            ch[1] = expand6((c >> 5) & 63u);
            ch[2] = expand5(c & 31u);
        }
        return;
    case FXL_TEXFMT_RGB565:
    default:
        if (m->lin8 != NULL) {
            ch[0] = m->lin5[stored >> 11];
            ch[1] = m->lin6[(stored >> 5) & 63u];
            ch[2] = m->lin5[stored & 31u];
        } else {
            ch[0] = stored >> 11;
            ch[1] = (stored >> 5) & 63u;
            ch[2] = stored & 31u;
        }
        return;
    }
}

/* Nearest palette entry to an 8-bit colour; the key index is skipped when
 * keyed (an opaque average must stay opaque). Ties go to the lowest index. */
static uint32_t nearest_index(const mipctx_t *m, const uint32_t rgb8[3])
{
    uint32_t i, best = 0, best_d = UINT32_MAX;

    for (i = 0; i < 256u; i++) {
        uint32_t c = m->palette[i];
        int32_t dr, dg, db;
        uint32_t d;
        if (m->keyed && i == m->key)
            continue;
        dr = (int32_t)expand5(c >> 11) - (int32_t)rgb8[0];
        dg = (int32_t)expand6((c >> 5) & 63u) - (int32_t)rgb8[1];
        db = (int32_t)expand5(c & 31u) - (int32_t)rgb8[2];
        d = (uint32_t)(dr * dr + dg * dg + db * db); /* <= 3 * 255^2 */
        if (d < best_d) {
            best_d = d;
            best = i;
        }
    }
    return best;
}

/* One channel's sum over n sources -> its code: the nearest to the mean in
 * a linear space (its table), the mean rounded to nearest in stored codes
 * (table NULL). */
static uint32_t channel(const uint16_t *table, uint32_t count, uint32_t sum, uint32_t n)
{
    return table != NULL ? encode_lin(table, count, sum, n) : (sum + n / 2u) / n;
}

/* The channels' sums over n opaque sources -> stored value: the nearest
 * code to each mean (linear spaces) or the mean rounded to nearest (stored
 * codes); never returns the key when keyed. */
static uint32_t encode(const mipctx_t *m, const uint32_t sum[3], uint32_t n)
{
    uint32_t v, rgb8[3], i;

    switch (m->format) {
    case FXL_TEXFMT_L8:
        v = channel(m->lin8, 256u, sum[0], n);
        /* One grey step up (down at 255): invisible, and keeps it opaque. */
        if (m->keyed && v == m->key)
            v = v == 255u ? 254u : v + 1u;
        return v;
    case FXL_TEXFMT_I8:
        for (i = 0; i < 3u; i++)
            rgb8[i] = channel(m->lin8, 256u, sum[i], n);
        return nearest_index(m, rgb8);
    case FXL_TEXFMT_RGB565:
    default:
        v = (channel(m->lin5, 32u, sum[0], n) << 11) | (channel(m->lin6, 64u, sum[1], n) << 5) |
            channel(m->lin5, 32u, sum[2], n);
        /* The blue LSB is the least visible bit of an RGB565 word. */
        if (m->keyed && v == m->key)
            v ^= 1u;
        return v;
    }
}

static uint32_t load(const void *base, uint32_t bytes, uint32_t index)
{
    return bytes == 2u ? ((const uint16_t *)base)[index] : ((const uint8_t *)base)[index];
}

static void store(void *base, uint32_t bytes, uint32_t index, uint32_t v)
{
    if (bytes == 2u)
        ((uint16_t *)base)[index] = (uint16_t)v;
    else
        ((uint8_t *)base)[index] = (uint8_t)v;
}

/* One destination texel from its 2 or 4 sources. */
static uint32_t reduce(const mipctx_t *m, const uint32_t *src, uint32_t count)
{
    uint32_t sum[3] = {0u, 0u, 0u}, ch[3];
    uint32_t i, k, opaque = 0, same = 1;

    for (i = 1; i < count; i++)
        same &= src[i] == src[0];
    /* Uniform sources: the exact average is the value itself (for I8 this
     * keeps the index even when an equal colour has a lower index). */
    if (same)
        return src[0];
    for (i = 0; i < count; i++) {
        if (m->keyed && src[i] == m->key)
            continue;
        decode(m, src[i], ch);
        for (k = 0; k < 3u; k++)
            sum[k] += ch[k]; /* <= 4 * 65535 */
        opaque++;
    }
    /* Transparent when at least half the sources are: 2 of 4, 1 of 2. */
    if (2u * (count - opaque) >= count)
        return m->key;
    return encode(m, sum, opaque);
}

fxl_status_t fxl_mip_build_keyed(void *storage, uint32_t storage_bytes, uint32_t width,
                                  uint32_t height, fxl_texfmt_t format, uint32_t levels,
                                  const uint16_t *palette, fxl_mip_space_t space,
                                  const uint16_t *key)
{
    mipctx_t m;
    uint32_t bytes = fxl_texfmt_bytes(format), max_levels, n, x, y;
    uint32_t sw = width, sh = height, dw, dh;
    uint8_t *src, *dst;

    if (storage == NULL || bytes == 0u || width == 0u || height == 0u)
        return FXL_ERR_ARG;
    /* The palette and the key are read as uint16_t: misaligned, that is
     * undefined behaviour and a HardFault on a Cortex-M0+ (as in
     * fxl_texture_validate). */
    if (format == FXL_TEXFMT_I8 && (palette == NULL || !fxl__aligned(palette, 2u)))
        return FXL_ERR_ARG;
    if (key != NULL && !fxl__aligned(key, 2u))
        return FXL_ERR_ARG;
    if (space != FXL_MIP_SPACE_STORED && space != FXL_MIP_SPACE_GAMMA22 &&
        space != FXL_MIP_SPACE_SRGB)
        return FXL_ERR_ARG;
    /* RGB565 texels are read as uint16_t: the storage must be aligned. */
    if (!fxl__aligned(storage, bytes))
        return FXL_ERR_ARG;
    max_levels = fxl_mip_levels(width, height);
    if (max_levels == 0u)
        return FXL_ERR_UNSUPPORTED;
    if (levels == 0u || levels > max_levels)
        return FXL_ERR_RANGE;
    if (storage_bytes < fxl_mip_size(width, height, format, levels))
        return FXL_ERR_NOMEM;
    if (key != NULL && format != FXL_TEXFMT_RGB565 && *key > 255u)
        return FXL_ERR_RANGE;

    m.format = format;
    m.palette = palette;
    m.keyed = key != NULL;
    m.key = key != NULL ? *key : 0u;
    if (space == FXL_MIP_SPACE_GAMMA22) {
        m.lin5 = fxl__lin5_g22;
        m.lin6 = fxl__lin6_g22;
        m.lin8 = fxl__lin8_g22;
    } else if (space == FXL_MIP_SPACE_SRGB) {
        m.lin5 = fxl__lin5_srgb;
        m.lin6 = fxl__lin6_srgb;
        m.lin8 = fxl__lin8_srgb;
    } else {
        m.lin5 = m.lin6 = m.lin8 = NULL;
    }

    src = (uint8_t *)storage;
    for (n = 1; n < levels; n++) {
        dw = sw > 1u ? sw >> 1 : 1u;
        dh = sh > 1u ? sh >> 1 : 1u;
        dst = src + sw * sh * bytes; /* levels are contiguous */
        for (y = 0; y < dh; y++) {
            for (x = 0; x < dw; x++) {
                /* Source columns 2x, 2x+1 (only 2x when the source is one
                 * texel wide); rows likewise. */
                uint32_t s[4], cnt = 0, sx, sy;
                uint32_t nx = sw > 1u ? 2u : 1u, ny = sh > 1u ? 2u : 1u;
                for (sy = 0; sy < ny; sy++)
                    for (sx = 0; sx < nx; sx++)
                        s[cnt++] = load(src, bytes, (y * ny + sy) * sw + x * nx + sx);
                store(dst, bytes, y * dw + x, reduce(&m, s, cnt));
            }
        }
        src = dst;
        sw = dw;
        sh = dh;
    }
    return FXL_OK;
}

fxl_status_t fxl_mip_build(void *storage, uint32_t storage_bytes, uint32_t width, uint32_t height,
                           fxl_texfmt_t format, uint32_t levels, const uint16_t *palette,
                           fxl_mip_space_t space)
{
    return fxl_mip_build_keyed(storage, storage_bytes, width, height, format, levels, palette,
                                space, NULL);
}

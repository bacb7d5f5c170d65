/* span_fast.h - template for the specialised span loops (included by span.c).
 *
 * Macro contract, all defined by the includer and undefined here:
 *   FXL_T_NAME      name of the generated function (fxl__seg_fn signature)
 *   FXL_T_BILINEAR  0: nearest texel, 1: 2x2 texels with 5-bit weights
 *   FXL_T_DEPTH     0: no depth buffer, 1: test (greater is nearer) and write
 *   FXL_T_SWAP      0: native RGB565 stores, 1: byte-swapped stores
 * Preconditions (fxl__pick_seg_fn checks them): RGB565 texels, repeat wrap on
 * both axes, no colour key, REPLACE, one level per segment, and level-0
 * log2_w + log2_h <= 16 (the scaled v below must keep its row bits).
 * Why a template: this loop is the cost of every pixel; one source of truth
 * for eight variants keeps branches out of it without eight copies.
 * Repeat wrap is free: u, v are uint32 q16 texel coordinates stepped modulo
 * 2^32, and the texture side divides 2^16, so masking the integer part is
 * the exact remainder even after wrap-around.
 */
static uint32_t FXL_T_NAME(const fxl__tri_t *tri, const fxl__seg_t *s)
{
    const uint16_t *tex = (const uint16_t *)s->lvl->texels;
    const uint32_t lw = s->lvl->log2_w;
    /* Texel index in one shift: v is carried scaled by the level width, so
     * the row offset and the column sit in disjoint bit fields above bit 16
     * (lw + lh <= 16, checked by fxl__pick_seg_fn) and (v & MV) | (u & MU)
     * >> 16 is (row << lw) + column, wrap included. */
    const uint32_t mu16 = s->lvl->mask_u << 16, mv16 = (s->lvl->mask_v << lw) << 16;
    const uint32_t du = (uint32_t)s->du, dv = (uint32_t)s->dv << lw;
    uint32_t u = s->u, v = s->v << lw;
    uint16_t *dst = s->dst;
    const int32_t n = s->n;
    int32_t i;
#if FXL_T_DEPTH
    uint16_t *zb = s->zb;
    uint32_t z = s->z, rejected = 0;
    const uint32_t dz = (uint32_t)s->dz;
#endif
    (void)tri;

    for (i = 0; i < n; i++) {
        uint32_t c;
#if FXL_T_DEPTH
        uint32_t zz = z >> 16;
        z += dz;
        if (zz <= zb[i]) {
            /* counted on the rare path so the common one stays short */
            rejected++;
            u += du;
            v += dv;
            continue;
        }
        zb[i] = (uint16_t)zz;
#endif
#if FXL_T_BILINEAR
        {
            /* texel centres at +0.5; the 2x2 footprint wraps per axis */
            uint32_t uu = u - 0x8000u, vv = v - (0x8000u << lw);
            uint32_t c0 = (uu & mu16) >> 16, c1 = ((uu + 0x10000u) & mu16) >> 16;
            uint32_t r0 = (vv & mv16) >> 16, r1 = ((vv + (0x10000u << lw)) & mv16) >> 16;
            c = fxl__bilerp565(tex[r0 + c0], tex[r0 + c1], tex[r1 + c0], tex[r1 + c1], (uu >> 11) & 31u,
                               (vv >> (11 + lw)) & 31u);
        }
#else
        c = tex[((v & mv16) | (u & mu16)) >> 16];
#endif
#if FXL_T_SWAP
        dst[i] = (uint16_t)((c >> 8) | (c << 8));
#else
        dst[i] = (uint16_t)c;
#endif
        u += du;
        v += dv;
    }
#if FXL_T_DEPTH
    return (uint32_t)n - rejected;
#else
    return (uint32_t)n;
#endif
}

#undef FXL_T_NAME
#undef FXL_T_BILINEAR
#undef FXL_T_DEPTH
#undef FXL_T_SWAP

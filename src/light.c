/* src/light.c - per-vertex diffuse lighting: one directional light plus
 * ambient, producing the RGB565 vertex colour for FXL_SHADE_GOURAUD.
 *
 *   I_c = min(1, (ambient_c + diffuse_c * max(0, n . L)) / 255)
 *   out_c = round(base_c * I_c)    (base_c: 5, 6, 5-bit channels)
 *
 * n . L is formed in q32 and rounded to q16 (error <= 2^-17 for unit
 * vectors given in q16, plus their own 2^-17 rounding per component), so
 * base_c * I_c is within 63 * 2^-14 < 0.004 of the exact value: the result
 * equals round(exact) except within 0.004 of a rounding tie.
 */
#include "pipeline_int.h"
#include "div64.h"

uint16_t fxl_light_shade(const fxl_light_t *l, const fxl_vec3_t *n, uint16_t base)
{
    static const uint8_t shift[3] = {11, 5, 0};
    static const uint8_t maxc[3] = {31, 63, 31};
    int64_t ndotl;
    uint32_t out = 0;
    int c;
    if (!l || !n) return base;
    /* each product |.| <= 2^62; the saturating sum cannot overflow */
    ndotl = fxl__add_sat((int64_t)n->x * l->dir.x, (int64_t)n->y * l->dir.y, NULL);
    ndotl = fxl__add_sat(ndotl, (int64_t)n->z * l->dir.z, NULL);
    ndotl = fxl__shr_round(ndotl, 16);
    if (ndotl < 0) ndotl = 0;
    if (ndotl > 65536) ndotl = 65536;
    for (c = 0; c < 3; c++) {
        uint32_t bc = ((uint32_t)base >> shift[c]) & maxc[c];
        int64_t i_q16 = fxl__fe_sdiv64((int64_t)l->ambient[c] * 65536 + (int64_t)l->diffuse[c] * ndotl + 127, 255);
        uint32_t oc;
        if (i_q16 > 65536) i_q16 = 65536;
        oc = (uint32_t)(((int64_t)bc * i_q16 + 32768) >> 16);
        if (oc > maxc[c]) oc = maxc[c];
        out |= oc << shift[c];
    }
    return (uint16_t)out;
}

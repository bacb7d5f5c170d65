/* det_entries.h - what the determinism check renders (shared by the host
 * generator gen_data.c, the bare-metal/host harness det_main.c and
 * tests/test_determinism.c, so every build renders exactly the same list).
 *
 * Every scene of the gallery (the host's scene list) at 320x240, native
 * RGB565, with each draw variant below: the gallery's own four (subdiv16 and
 * affine, point and bilinear, no mips) plus variants that reach the other
 * span paths (exact and auto with and without mips, subdiv32, mip nearest
 * and linear, per-triangle LOD). Size-optimised builds draw every one of
 * them with the generic walk, the others with the specialised ones. Frame procedure: pixels and depth cleared to 0, every triangle drawn
 * in order with depth test + write, CRC-32 (crc32.h) of the pixel rows.
 */
#ifndef FXL_DET_ENTRIES_H
#define FXL_DET_ENTRIES_H

#include "fixel/raster.h"

#define DET_W 320
#define DET_H 240

typedef struct det_variant {
    const char *name;
    int16_t persp;
    uint8_t filter, mip, lod;
} det_variant_t;

static const det_variant_t det_variants[] = {
    {"subdiv16_point", 16, FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"affine_point", FXL_PERSP_AFFINE, FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"subdiv16_bilinear", 16, FXL_FILTER_BILINEAR, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"affine_bilinear", FXL_PERSP_AFFINE, FXL_FILTER_BILINEAR, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"exact_trilinear", FXL_PERSP_EXACT, FXL_FILTER_BILINEAR, FXL_MIP_LINEAR, FXL_LOD_SEGMENT},
    {"auto_bilinear_mip", FXL_PERSP_AUTO, FXL_FILTER_BILINEAR, FXL_MIP_NEAREST, FXL_LOD_SEGMENT},
    {"subdiv32_point_mip_tri", 32, FXL_FILTER_POINT, FXL_MIP_NEAREST, FXL_LOD_TRIANGLE},
    {"exact_bilinear", FXL_PERSP_EXACT, FXL_FILTER_BILINEAR, FXL_MIP_NONE, FXL_LOD_SEGMENT},
    {"auto_point", FXL_PERSP_AUTO, FXL_FILTER_POINT, FXL_MIP_NONE, FXL_LOD_SEGMENT},
};
#define DET_NVARIANTS ((int)(sizeof det_variants / sizeof det_variants[0]))

static void det_draw_settings(const det_variant_t *v, fxl_draw_t *d)
{
    fxl_draw_defaults(d);
    d->persp = v->persp;
    d->filter = v->filter;
    d->mip = v->mip;
    d->lod = v->lod;
    d->depth = FXL_DEPTH_TEST | FXL_DEPTH_WRITE;
}

#endif

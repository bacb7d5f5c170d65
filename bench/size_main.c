/* size_main.c - the smallest program that draws a textured triangle: linked
 * with --gc-sections it keeps exactly the core code a draw call needs, which
 * is what the footprint table reports (the archive also holds the 3D front
 * end, mip building and the other modules an application may not use). */
#include "fixel/fixel.h"

static uint16_t fb[16 * 16];
static const uint16_t texels[4] = {0xFFFFu, 0, 0, 0xFFFFu};

int main(void)
{
    fxl_target_t t;
    fxl_texture_t tex;
    fxl_draw_t d;
    fxl_vertex_t v[3] = {{0, 0, 1u << 31, 0, 0, 0}, {16 << 16, 0, 1u << 30, 1 << 16, 0, 0},
                         {0, 16 << 16, 1u << 31, 0, 1 << 16, 0}};
    if (fxl_target_init(&t, fb, 16, 16, 16, FXL_PIXFMT_RGB565) != FXL_OK ||
        fxl_texture_init(&tex, texels, 2, 2, FXL_TEXFMT_RGB565, 1) != FXL_OK)
        return 1;
    fxl_draw_defaults(&d);
    d.texture = &tex;
    d.mip = FXL_MIP_NONE;
    d.depth = 0;
    return fxl_draw_triangle(&t, &d, v, 0) != FXL_OK;
}

/* fixel/fixel.h - umbrella header.
 *
 * fixel draws perspective-textured triangles into RGB565 framebuffers, or into
 * horizontal bands of a frame, with fixed-point arithmetic only. Freestanding
 * C99: no libc, no allocation, no floating point, no global state.
 *
 *   static uint16_t pixels[240 * 320], depth[240 * 320];
 *   fxl_target_t fb;   fxl_target_init(&fb, pixels, 320, 240, 320, FXL_PIXFMT_RGB565);
 *   fxl_target_set_depth(&fb, depth);
 *   fxl_texture_t tex; fxl_texture_init(&tex, texels, 64, 64, FXL_TEXFMT_RGB565, 1);
 *   fxl_draw_t d;      fxl_draw_defaults(&d); d.texture = &tex;
 *   fxl_target_clear(&fb, 0); fxl_target_clear_depth(&fb);
 *   fxl_draw_triangle(&fb, &d, verts, NULL);   // verts: fxl_vertex_t[3]
 *
 * Modules, all included here: fixed.h (q16 math), target.h (buffers, bands,
 * clipping), texture.h (texels, mips, wrap), raster.h (triangles),
 * pipeline.h (3D front end). port.h (SPI panels, band rendering) belongs to
 * the separate fixel_port library and is included on its own. Every call that can fail returns
 * fxl_status_t; the few that cannot return their value or nothing
 * (fxl_draw_defaults, fxl_q16_round, fxl_texture_fetch, ...).
 */
#ifndef FIXEL_FIXEL_H
#define FIXEL_FIXEL_H

#include "fixel/config.h"
#include "fixel/status.h"
#include "fixel/fixed.h"
#include "fixel/target.h"
#include "fixel/texture.h"
#include "fixel/raster.h"
#include "fixel/pipeline.h"

#endif
